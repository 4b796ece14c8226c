// symrep/numeric/integrate.h -- reference numerical integration with Boost.Odeint.
//
// integrate() solves a first-order system y' = F(t, y) from (t0, y0) and
// reports the state at requested output times (odeint's integrate_times: the
// steppers hit every output time exactly, or interpolate with dense output),
// how many times F was evaluated, how many steps were taken, and the wall time.
//
// Steppers (adaptive, with absolute and relative tolerances, odeint's error
// norm  max_i |err_i| / (abs_tol + rel_tol |y_i|)  per step):
//   - rkf78:          controlled runge_kutta_fehlberg78 (order 7/8, 13 stages),
//   - bulirsch_stoer: odeint's bulirsch_stoer (extrapolation, variable order),
//   - dopri5:         dense-output runge_kutta_dopri5 (order 5/4 with FSAL,
//                     output times by 4th-order continuous interpolation);
// and one with a fixed step and no error control (the tolerances are ignored):
//   - rk4:            the classical runge_kutta4 (order 4, 4 stages) with step
//                     integration_options::fixed_step, shortened where needed
//                     to land on each output time.
// The tolerances bound the local error per step; the global error at time t is
// roughly the tolerance times the growth of perturbations (the norm of the
// propagator) times the number of steps, so for a stable or oscillating system
// it stays within a few orders of magnitude of the tolerance.
//
// symbolic_system builds F from symbolic right-hand sides compiled with the
// evaluator (numeric/evaluator.h).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <ginac/ginac.h>

#include "symrep/numeric/evaluator.h"

namespace symrep::num {

/// Right-hand side: write F(t, y) to dydt (both arrays have the system's dimension).
using rhs_function = std::function<void(double t, const double* y, double* dydt)>;

enum class stepper_kind { rkf78, bulirsch_stoer, dopri5, rk4 };

/// "rkf78", "bulirsch_stoer", "dopri5", "rk4".
const char* stepper_name(stepper_kind k);
/// Inverse of stepper_name (also accepts "bs", "rk78"); symrep::type_error on an unknown name.
stepper_kind stepper_from_name(const std::string& name);

struct integration_options {
    stepper_kind stepper = stepper_kind::rkf78;
    double abs_tol = 1e-10;
    double rel_tol = 1e-10;
    /// First trial step; the controllers adapt it at once. 0: 1e-3 times the span.
    double initial_step = 0.0;
    /// The step of rk4 (required, > 0, for rk4; unused by the adaptive steppers).
    double fixed_step = 0.0;
    /// Error (symrep::error) when more steps than this are needed between two
    /// consecutive output times (guards against stiff or singular systems).
    std::size_t max_steps_between_outputs = 1'000'000;
    /// Error (symrep::error) when F has been evaluated more often than this in total.
    std::size_t max_rhs_evaluations = 100'000'000;
};

struct integration_result {
    std::vector<double> times;   ///< the output times (as requested)
    Eigen::MatrixXd states;      ///< row k = state at times[k]
    std::size_t rhs_evaluations = 0;
    std::size_t steps = 0;       ///< steps reported by odeint's integrate_times
    double wall_seconds = 0.0;   ///< integration only (no setup)
    stepper_kind stepper = stepper_kind::rkf78;

    /// The state at times[k] as a vector.
    Eigen::VectorXd state(std::size_t k) const { return states.row(static_cast<Eigen::Index>(k)).transpose(); }
};

/// Integrate y' = f(t, y), y(t0) = y0, and record the state at each of
/// `output_times` (non-empty, strictly increasing, all >= t0; t0 itself may be
/// among them; forward integration only). Throws symrep::type_error on bad arguments
/// (empty state, unsorted times, non-positive tolerances) and symrep::error
/// when the integration fails (non-finite state, step limit, evaluation limit).
integration_result integrate(const rhs_function& f, double t0, const std::vector<double>& y0,
                             const std::vector<double>& output_times, const integration_options& options = {});

/// Eigen overload (same semantics; a template so that a braced list {a, b}
/// picks the std::vector overload unambiguously).
template <class Derived>
integration_result integrate(const rhs_function& f, double t0, const Eigen::MatrixBase<Derived>& y0,
                             const std::vector<double>& output_times, const integration_options& options = {}) {
    const Eigen::VectorXd y = y0;
    return integrate(f, t0, std::vector<double>(y.data(), y.data() + y.size()), output_times, options);
}

/// n_points equally spaced times t0, ..., t1 (n_points >= 2; n_points == 1 gives {t1}).
std::vector<double> linspace(double t0, double t1, std::size_t n_points);

/// Numeric values of parameter symbols.
using parameter_values = std::vector<std::pair<GiNaC::ex, double>>;

/// A first-order system y' = F(t, y; p) given by symbolic right-hand sides.
/// rhs[i] is the derivative of state[i]; it may contain t, the state symbols
/// and the parameter symbols (any other symbol: symrep::type_error naming it).
/// The right-hand sides are compiled once with inputs (t, state..., params...).
class symbolic_system {
public:
    symbolic_system(const std::vector<GiNaC::ex>& rhs, const GiNaC::symbol& t,
                    const std::vector<GiNaC::ex>& state, const parameter_values& params = {});

    std::size_t dimension() const { return dim_; }
    const compiled_function& compiled() const { return f_; }

    /// Change the value of parameter `p` (symrep::type_error if it is not a parameter).
    void set_parameter(const GiNaC::ex& p, double value);

    /// F as an rhs_function. The function holds a copy of the compiled program
    /// and of the current parameter values; it is not safe to call one returned
    /// function from two threads at once (it owns one input buffer).
    rhs_function function() const;

private:
    std::size_t dim_ = 0;
    std::vector<GiNaC::ex> params_;  // symbols kept as ex: a copy would slice a realsymbol
    std::vector<double> param_values_;
    compiled_function f_;
};

}  // namespace symrep::num
