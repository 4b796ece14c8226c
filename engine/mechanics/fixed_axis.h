// symrep/mechanics/fixed_axis.h -- problems in a frame that rotates about a fixed
// axis at a varying rate, w(t) = s(t) u (thesis VI.2), solved by reduction to the
// inertial problem.
//
// The problem, as a user writes it (m a constant, s(t) a quasi-polynomial, u a
// constant vector: a vector symbol, a literal, or a combination of them):
//     m (r'' + 2 w x r' + w' x r + w x (w x r)) + k r + F(t) = 0,
//     r(0) = r0,  r'(0) = v0,
// with k a constant (0: free motion; w0^2: the Foucault pendulum VI.2.70) and a
// free part F(t) along u (a quasi-polynomial times u: gravity along the axis).
// read_fixed_axis() reads w from the cross terms acting on r' (their sum over
// 2 m), checks that w keeps its direction, that the rest of the equation is
// exactly the rotating-frame operator above, and that what remains is the
// isotropic k r + F(t). By Thm VI.2.1.1 / VI.2.2 (Q' = -W Q, Q(0) = I)
//     r = Q psi,   Q x = cos(a) x - sin(a) n x x + (1 - cos(a)) (n . x) n,
// n = u/|u|, a(t) = |u| int_0^t s (closed form: s is a quasi-polynomial), where
// psi solves the inertial problem m psi'' + k psi + F(t) = 0 (Q^T F = F as F is
// along u) with psi(0) = r0, psi'(0) = v0 + w(0) x r0; psi comes from the
// constant-coefficient solver (cauchy_problem.h). w(t) may change sign.
//
// Not read here (the reading returns nothing and the caller keeps its error):
// a w whose direction turns (VI.3: Q has no closed form), damping c r', a
// nonlinear central force f(|r|) r/|r|, a free part not along u.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "mechanics/cauchy_problem.h"

namespace symrep::mechanics {

struct fixed_axis_form {
    GiNaC::ex s;       ///< the signed rate s(t)
    GiNaC::ex u;       ///< the constant direction (not normalized)
    GiNaC::ex angle;   ///< a(t) = |u| int_0^t s(tau) dtau, closed form
    GiNaC::ex m, k;    ///< the leading coefficient and the constant k of k r
    GiNaC::ex free;    ///< F(t), along u (0 for none)
    std::shared_ptr<const cauchy_problem> inertial;  ///< m psi'' + k psi + F = 0 with psi's initial values
};

/// The reading above, or nothing when P is not of that form; `why` (if given)
/// receives the reason when P has the cross terms of a varying w but the rest
/// is not of the form (damping, a turning axis, a force across the axis).
std::optional<fixed_axis_form> read_fixed_axis(const cauchy_problem& P, std::string* why = nullptr);

/// r(t) = Q psi(t), coordinate-free. Errors as solve(cauchy_problem).
GiNaC::ex solve_fixed_axis(const cauchy_problem& P, const fixed_axis_form& F);

/// (Thm VI.2.2.3.3, VI.3.140-141) First integrals of a second-order problem without a
/// free term, in the unknowns r, r' of P: with p = r' + w x r (= Q psi'),
///   the energy (m |p|^2 + k |r|^2)/2,  u . (r x p),  |r x p|^2
/// (psi x psi' = Q^T (r x p) is constant, and Q turns about u). Throws domain_error
/// for a first-order problem or one with a free term F(t).
std::vector<GiNaC::ex> first_integrals(const cauchy_problem& P, const fixed_axis_form& F);

}  // namespace symrep::mechanics
