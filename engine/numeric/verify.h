// symrep/numeric/verify.h -- check a closed form against numerical integration.
//
// verify() compiles a closed-form solution y(t) and a first-order system
// y' = F(t, y; p), integrates the system from the closed form's initial state
// with Boost.Odeint (numeric/integrate.h), and compares both at n_points
// equally spaced sample times of [t0, t1].
//
// Difference measure, per component i of the closed form:
//     rel_i = max_k |cf_i(t_k) - y_i(t_k)| / max_k |y_i(t_k)|
// (the error relative to the component's scale over the whole trajectory, so
// a zero crossing does not inflate it; a component that is zero at every
// sample is measured absolutely). max_relative_difference = max_i rel_i.
// A correct closed form gives about the integrator's global error (1e-9 ..
// 1e-12 at the default tolerances 1e-10 over a few periods); a wrong one
// gives O(1).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/integrate.h"
#include "symrep/numeric/stable_evaluator.h"

namespace symrep::num {

struct verify_result {
    double max_relative_difference = 0.0;  ///< max_i rel_i, see above
    double max_absolute_difference = 0.0;  ///< max_{i,k} |cf_i(t_k) - y_i(t_k)|
    double time_of_max = 0.0;              ///< sample time of the largest rel_i's worst sample
    std::size_t component_of_max = 0;      ///< the component i with the largest rel_i
    std::size_t n_points = 0;
    double compile_seconds = 0.0;          ///< compiling closed form and right-hand sides
    double closed_form_seconds = 0.0;      ///< evaluating the compiled closed form at all samples
    /// With a stable_function: how many samples each precision tier evaluated
    /// (binary64, binary128, multiprecision; see stable_evaluator.h).
    std::array<std::size_t, 3> closed_form_tiers{};
    double integration_seconds = 0.0;      ///< odeint, all samples
    std::size_t rhs_evaluations = 0;
    std::size_t steps = 0;
    std::vector<double> times;             ///< the sample times
    Eigen::MatrixXd closed_form;           ///< row k: closed form at times[k]
    Eigen::MatrixXd integrated;            ///< row k: integrated state at times[k] (all state components)
};

/// Symbolic front end.
///   closed_form:   m scalar expressions in t and the parameters, m <= state.size();
///                  they are compared with the first m state components
///                  (so a closed form for r may be checked against a state (r, v)).
///   t:             the time symbol.
///   ode_rhs:       right-hand sides F_i, one per state symbol, in t, state, parameters.
///   state:         the state symbols.
///   initial_state: y(t0); if empty, the closed form's value at t0 is used (requires m == state.size()).
///   params:        values of every other symbol in closed_form and ode_rhs.
///   t0, t1, n_points: sample times linspace(t0, t1, n_points), n_points >= 2, t1 > t0.
/// Errors: symrep::type_error for sizes that do not fit or symbols without value
/// (named), symrep::error when the integration fails.
verify_result verify(const std::vector<GiNaC::ex>& closed_form, const GiNaC::symbol& t,
                     const std::vector<GiNaC::ex>& ode_rhs, const std::vector<GiNaC::ex>& state,
                     const std::vector<double>& initial_state, const parameter_values& params, double t0,
                     double t1, std::size_t n_points, const integration_options& options = {});

/// Numeric back end: closed_form is a function of the single input t with m outputs.
/// The symbolic front end uses a stable_function, so that the difference
/// measures the integrator and not the rounding of the closed form (at the
/// Earth's rotation rate the solver's form cancels by 1e8 in double).
verify_result verify(const stable_function& closed_form, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options = {});
verify_result verify(const compiled_function& closed_form, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options = {});

/// Numeric back end for a closed form evaluated at all sample times at once (a
/// solution by reduction, whose rotation tensor is integrated along the samples):
/// all(times, values) fills times.size() rows of m values (row-major).
using sampled_function = std::function<void(const std::vector<double>& times, double* values)>;
verify_result verify(const sampled_function& closed_form, std::size_t m, const rhs_function& rhs,
                     const std::vector<double>& initial_state, double t0, double t1, std::size_t n_points,
                     const integration_options& options = {});

}  // namespace symrep::num
