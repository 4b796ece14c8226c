// symrep/transforms/signal_transform.h -- T f(d) = int f(t) e^(-d t) dt over an algebra for
// signals that are not quasi-polynomials (thesis V.1.5, V.2.11, V.3.8): impulses, windows
// and pieces cut by step(), Gaussians; exact where the integral is elementary, else by
// quadrature with an error estimate.
//
// The signal is cut into pieces h on intervals [lo, hi] (the half-line t >= 0 for a causal
// signal, the whole line for a two-sided one; every step(alpha t + beta) factor, alpha a
// nonzero number, bounds its term's interval at -beta/alpha). On each piece:
//  - h a quasi-polynomial (least equation p, h = Psi^-1(w) on P_p): the tail integral
//        E_a(d) = int_a^oo h(t) e^(-d t) dt = e^(-a d) q_a(d) p(d)^-1,   q_a(X) = sum_j (w e^(v a))_j X^j
//    (h(t + a) = Psi^-1(w e^(v a)), the shift of Thm II.3.3 in continuous time), and
//    int_lo^hi = E_lo - E_hi: exact, for every d with p(d) invertible (both sides analytic in
//    d); an infinite end needs convergence, decided as transform() decides it (refused
//    when the integral diverges); a lower end -oo mirrors (t -> -t, d -> -d).
//  - on the whole line, h = sum c t^k e^(Q(t)) (cos, sin, cosh, sinh written with exp) with
//    Q(t) = -alpha t^2 + B t + C, alpha > 0: the Gaussian integral
//        int_R t^k e^(Q(t)) e^(-z t) dt = e^C (d/dB)^k sqrt(pi/alpha) e^((B - z)^2 / (4 alpha)),
//    an entire function G(z), applied to d on its algebra (algebra::apply_function, Hermite
//    interpolation on the roots of d's minimal polynomial): exact; over multicomplex(n) its
//    idempotent components are the Fourier transforms G(i Omega_p).
//  - otherwise (a half-line Gaussian, whose integral is erfc; any other closed form), by
//    quadrature (numeric/quadrature.h, Chebyshev panels) of h(t) times each coordinate of
//    e^(-d t), for d with numeric coordinates: a finite interval as is; an infinite end only
//    when h decays like e^(P(t)) with P a polynomial of even degree >= 2 and negative leading
//    coefficient (then the integral converges for every d, and the range is cut at a T where
//    the integrand's envelope and its tail are below 1e-20); any other infinite end: "cannot
//    decide whether the integral converges". The report gives the error estimate (quadrature
//    plus tail).
// Impulses c delta^(k)(t - a) (distribution.h) add c d^k e^(-a d).
#pragma once

#include "symrep/transforms/laplace.h"

namespace symrep::transforms {

/// T f(d) = int_0^oo f(t) e^(-d t) dt (g empty) or, with g, int_-oo^oo of the signal that is f
/// for t >= 0 and g for t < 0 (f and g the same expression: the whole line at once, as a
/// Gaussian needs). Quasi-polynomials without impulses or steps take transform() /
/// transform_two_sided() unchanged. domain_error for a divergent integral (named), an
/// undecided convergence ("cannot decide"), a quadrature that misses its tolerance, or a
/// signal that cannot be cut into pieces (a step of a non-linear argument).
algebra_transform transform_signal(const algebra_ptr& A, const coeffs& d, const GiNaC::ex& f,
                                   const GiNaC::symbol& t, const GiNaC::ex* g = nullptr);

/// True when f is a quasi-polynomial in t (signals::annihilator accepts it; 0 included).
bool is_quasi_polynomial(const GiNaC::ex& f, const GiNaC::symbol& t);

}  // namespace symrep::transforms
