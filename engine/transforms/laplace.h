// symrep/transforms/laplace.h -- integral transforms over algebras (thesis Ch. V),
// derived from the representation of signals (signals/representation.h).
//
// A causal quasi-polynomial f (f(t) for t >= 0, 0 before) is Psi^-1(w) on the
// polynomial algebra P_n = R[X]/(p), p its least equation (annihilator), with the
// functional lambda = the coordinate of v^(n-1). Then Psi^-1(v^j) = g^(j), g the impulse
// response (g(0) = ... = g^(n-2)(0) = 0, g^(n-1)(0) = 1), whose Laplace transform is
// 1/p(s), and L[g^(j)] = s^j / p(s) for j < n. So, with w = sum_j w_j v^j,
//     Lf(s) = q(s) / p(s),   q(s) = sum_j w_j s^j           (no integral is computed)
// and, conversely, a proper rational function q/p is the transform of Psi^-1(q(v)) on
// P_p: the inverse transform is a signal of the representation. Every pair is checked
// both ways before it is returned.
//
// Over an algebra (V.1.5): T f(d) = int_0^oo f(t) e^(-d t) dt = q(d) p(d)^-1, the same
// rational function of the algebra element, defined when p(d) is invertible (no
// eigenvalue of d is a root of p) and convergent when Re r < Re mu for every root r of p
// and eigenvalue mu of d. Over the multicomplex algebra with d = omega_0 i0 + ... +
// omega_n in this is the Fourier-type transform of V.2 for causal f: its idempotent
// components are the complex transforms F(i Omega_p) (V.2.27); over the Sobrero algebra
// with d = s + eps (+ j omega) it is the Laplace-type transform of V.3,
// sum_k eps^k/k! d^k/ds^k Lf(s) (the Taylor expansion of a function of s + eps,
// eps nilpotent). T(f') = d T f - f(0) (V.2.28 for causal f, the jump at 0 being the
// delta term of the distributional version) and T(f * g) = T f T g (V.2.29).
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/equality.h"

namespace symrep::transforms {

/// Lf(s) of a causal quasi-polynomial f (see above), in lowest terms; checked by the
/// inverse. Throws domain_error (from the signals layer) when f is not a quasi-polynomial.
GiNaC::ex laplace(const GiNaC::ex& f, const GiNaC::symbol& t, const GiNaC::ex& s);

/// The causal signal f(t) with Lf = F, for F a proper rational function of s (degree of
/// the numerator below the denominator's, coefficients free of s and t); checked by
/// laplace(f) = F. The roots of the denominator come from its factors over the rationals
/// (scalar/polynomial_roots.h): degree 1 and 2, and 3 by Cardano, where the check is
/// numeric (50 digits: f^(k)(0) and p(D) f = 0 at two points; laplace(f) would have to
/// simplify nested cube roots). Throws domain_error for an improper or non-rational F,
/// closed_form_error at once for a factor of degree > 3 (naming it and its degree).
GiNaC::ex inverse_laplace(const GiNaC::ex& F, const GiNaC::symbol& s, const GiNaC::symbol& t);

/// (V.2.42, Thm V.2.4) The energy int_0^oo f(t)^2 dt of a causal quasi-polynomial: L[f^2](0), exact.
/// domain_error when the integral diverges (an exponent of f^2 with real part >= 0) or when a real
/// part is not shown negative (symbolic parameters not declared positive): said, not assumed.
GiNaC::ex energy(const GiNaC::ex& f, const GiNaC::symbol& t);

/// (V.2.43-44) The inner product int_0^oo f(t) g(t) dt of two causal quasi-polynomials: L[f g](0),
/// exact; refused as energy() is (divergent, or convergence not decided), naming f*g.
GiNaC::ex inner_product(const GiNaC::ex& f, const GiNaC::ex& g, const GiNaC::symbol& t);

/// T f(d) on d's algebra with the convergence decided: yes (every Re(r - mu) < 0 shown),
/// no (some Re(r - mu) >= 0 shown: the integral diverges, the value is the analytic
/// continuation), or unknown (symbolic parameters: the report states the condition).
struct algebra_transform {
    coeffs value;
    truth converges = truth::unknown;
    std::string report;
};
algebra_transform transform(const algebra_ptr& A, const coeffs& d, const GiNaC::ex& f, const GiNaC::symbol& t);

/// The convergence decision of transform() alone (value left empty): Re r < Re mu for the
/// exponents r of the quasi-polynomial f and the eigenvalues mu of d.
algebra_transform convergence_of(const algebra_ptr& A, const coeffs& d, const GiNaC::ex& f, const GiNaC::symbol& t);

/// (V.2.11 over the whole line) int_-oo^oo F(t) e^(-d t) dt for F = f on t >= 0 and g on t < 0
/// (both quasi-polynomials): T f(d) + T[g(-u)](-d), the second part the causal transform of the
/// mirrored signal at -d. Converges when both parts do (the reports are joined). e^(-|t|) is
/// f = e^(-t), g = e^(t); its Fourier-type transform over the multicomplex algebra has the
/// idempotent components 2/(1 + Omega_p^2).
algebra_transform transform_two_sided(const algebra_ptr& A, const coeffs& d, const GiNaC::ex& f, const GiNaC::ex& g,
                                      const GiNaC::symbol& t);

}  // namespace symrep::transforms
