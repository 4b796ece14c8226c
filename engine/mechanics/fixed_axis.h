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
// A free part across u (a charge in B(t) with E across B, VI.2.53-64; gravity
// across a turning axis, VI.2.38) enters the inertial problem rotated: with
// F = F_par + F_perp (along and across u), Q^T F_perp = cos(a) F_perp + sin(a) n x F_perp,
// so that psi = psi_par - sum_j (C_j(t) V_j + S_j(t) n x V_j) over the terms c_j(t) V_j
// of F_perp with every V_j constant (terms_in_time, turning_frame.h: a literal holding t,
// [cos(t), 0, 0], is split by components, its t goes into c_j), where (Duhamel, G the impulse response of m y^(M) + k y)
//     C_j(t) = int_0^t G(t - tau) c_j(tau) cos a(tau) dtau,  S_j likewise with sin,
// in closed form when the integrand is a quasi-polynomial (convolution, VI.1.25)
// and otherwise kept as an integral object (GiNaC::integral in tau; the nested
// integrals I_c, I_s of VI.2.62-63), evaluated by quadrature (numeric/quadrature.h).
//
// Not read here (the reading returns nothing and the caller keeps its error):
// a w whose direction turns (VI.3: turning_frame.h), damping c r', a nonlinear
// central force f(|r|) r/|r| (turning_frame.h).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

struct fixed_axis_form {
    GiNaC::ex s;       ///< the signed rate s(t)
    GiNaC::ex u;       ///< the constant direction (not normalized)
    GiNaC::ex angle;   ///< a(t) = |u| int_0^t s(tau) dtau, closed form
    GiNaC::ex m, k;    ///< the leading coefficient and the constant k of k r
    GiNaC::ex free;    ///< the part of F(t) along u (0 for none): the inertial problem's own free term
    GiNaC::ex across;  ///< the part of F(t) across u (0 for none): rotated, Q^T F, see below
    std::shared_ptr<const cauchy_problem> inertial;  ///< m psi'' + k psi + F = 0 with psi's initial values
};

/// The reading above, or nothing when P is not of that form; `why` (if given)
/// receives the reason when P has the cross terms of a varying w but the rest
/// is not of the form (damping, a turning axis, a force across the axis).
std::optional<fixed_axis_form> read_fixed_axis(const cauchy_problem& P, std::string* why = nullptr);

/// The variable tau of the integral objects int_0^t ... dtau in solutions.
const GiNaC::ex& integration_variable();

/// int_0^t v(tau) dtau of a vector (or scalar) expression v, term by term over its canonical
/// terms c(t) V: elementary when c is a quasi-polynomial, otherwise the integral object
/// int_0^t c dtau; a c that holds integral objects int_0^t g(tau) dtau gives the nested
/// int_0^t c(tau) (int_0^tau g(sigma) dsigma) dtau (numeric/quadrature.h evaluates it).
/// domain_error for deeper nesting.
GiNaC::ex integral_in_t(const GiNaC::ex& v, const GiNaC::ex& t);

/// (Duhamel, VI.1.25-38) int_0^t G(t - tau) c(tau) dtau of scalar functions G, c of t: in closed
/// form by convolution when both are quasi-polynomials; otherwise G(t - tau) separated by the
/// addition theorems and the result a sum k_i(t) int_0^t f_i(tau) dtau of integral objects in
/// tau (integration_variable()), the factors free of tau outside (c's own integral objects
/// int_0^t g become int_0^tau g(sigma) dsigma). The caller has made sure c is finite on [0, t].
GiNaC::ex duhamel(const GiNaC::ex& G, const GiNaC::ex& c, const GiNaC::ex& t);

/// r(t) = Q psi(t), coordinate-free. Errors as solve(cauchy_problem).
GiNaC::ex solve_fixed_axis(const cauchy_problem& P, const fixed_axis_form& F);

/// (Thm VI.2.2.3.3, VI.3.140-141) First integrals of a second-order problem without a
/// free term, in the unknowns r, r' of P: with p = r' + w x r (= Q psi'),
///   the energy (m |p|^2 + k |r|^2)/2,  u . (r x p),  |r x p|^2
/// (psi x psi' = Q^T (r x p) is constant, and Q turns about u). Throws domain_error
/// for a first-order problem or one with a free term F(t).
std::vector<GiNaC::ex> first_integrals(const cauchy_problem& P, const fixed_axis_form& F);

}  // namespace symrep::mechanics
