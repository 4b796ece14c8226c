// symrep/mechanics/reduced_solution.h -- the solution of a rotating-frame problem
// by reduction to the inertial one (Thm VI.3.2.1) when it has no closed form:
// r = F_(-w)(psi) = Q psi with Q numeric for a turning w (Magnus on SO(3)) and
// psi numeric for a nonlinear central field (Kepler by universal variables).
//
// The object keeps the problem (with its turning_frame_form) and the values bound
// by solve(P, values); evaluate() puts in every value and returns r and r' at the
// requested times, each to about 1e-13 relative (the Magnus tolerance and Kepler's
// equation solved to the last digit; a general f by Boost.Odeint at 1e-13). A free term F(t)
// (Thm VI.3.2.1 with a force, constant k): psi's part -int_0^t G(t - tau) Q^T F/m dtau
// integrated with Q^T by Boost.Odeint at 1e-13 (add_forced_part in the .cpp).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/rotating_frame.h"
#include "symrep/mechanics/scene.h"
#include "symrep/mechanics/turning_frame.h"

namespace symrep::mechanics {

struct reduced_solution {
    std::shared_ptr<const cauchy_problem> problem;  ///< with problem->turning set
    parameter_values values;                        ///< bound by solve(P, values); may be empty
    /// The rotation operator F_w(x0) itself (rotation_problem(), turning_frame.h): printed as such.
    bool rotation_operator = false;

    const turning_frame_form& form() const { return *problem->turning; }
    /// The derivation, as describe_reduction() (with the bound values listed).
    std::string to_string() const;
};

/// A vector expression with its values in (no vector symbol left) as one literal [x, y, z] of
/// numbers or functions of t; type_error naming `what` when a vector symbol is left or it is no
/// vector.
GiNaC::ex numeric_vector_literal(const GiNaC::ex& e, const std::string& what);

/// Turns a symbolic value into a number: the caller's way of putting in its values
/// (exact, with limits) and evaluating; scalars give 1x1, vectors 3x1.
using value_map = std::function<GiNaC::ex(const GiNaC::ex&)>;

/// The numeric problem (VI.3.132) for order 2, with every value put in by `put`.
/// type_error naming a symbol left without a value; domain_error for a field
/// singular at |r0| or non-finite data.
rotating_frame_problem numeric_problem(const reduced_solution& s, const value_map& put);

/// x and x' (r and r') at each of `times` (sorted, >= 0).
std::vector<rotating_frame_state> evaluate(const reduced_solution& s, const value_map& put,
                                           const std::vector<double>& times);

}  // namespace symrep::mechanics
