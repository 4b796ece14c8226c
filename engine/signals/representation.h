// symrep/signals/representation.h -- signals represented by algebra elements
// (thesis II.1-II.3, Thm II.1.1, Thm II.2.3, Thm II.3.1-II.3.4, Cor. II.3.5).
//
// The solutions of a linear constant-coefficient ODE p(D) f = 0 of order n form an
// n-dimensional space V. An algebra A_n with an element d whose minimal polynomial is
// p represents V: a linear bijection Psi: V -> A_n with Psi(f') = d Psi(f) (II.1.7-8),
// so differentiation becomes multiplication by d and the ODE becomes algebra.
//
// The map. The thesis fixes Psi by Psi(f_k) = e_k, where exp(d t) = sum_k f_k(t) e_k
// (Thm II.2.3); that map satisfies Psi(f') = d Psi(f) only when the canonical matrix
// [d] is symmetric (the coordinates of exp(d t) obey [f'] = [d]^T [f], II.2.18, not
// [d] [f], II.1.17; ../shared/thesis/FORMULAS.md). symrep derives the map instead:
//     Psi^-1(w)(t) = lambda(w exp(d t)),
// lambda the last coordinate in the power basis 1, d, ..., d^(n-1) (on a polynomial
// algebra P_n: the coordinate of v^(n-1), for every operator d; on the multicomplex
// algebra: the coordinate of 1, IV.1, signals/multicomplex_signals.h). Then
// Psi^-1(d w) = Psi^-1(w)' exactly, Psi^-1 is one-to-one when d generates A (the
// form (x, y) -> lambda(x y) is nondegenerate on R[d] = R[X]/(p)), and on the
// polynomial algebra P_n with d = v, Psi^-1(v^j) = g^(j), g the impulse response
// (g(0) = ... = g^(n-2)(0) = 0, g^(n-1)(0) = 1). Psi(f) solves
// lambda(w d^k) = f^(k)(0), k < n (a triangular Hankel system on P_n).
//
// Discrete signals (II.3): with the shift as d, Psi_d^-1(w)(k) = lambda(w d^k).
// Sampling (Thm II.3.4, step h): f(k h) = lambda(w exp(h d)^k), so the samples are
// represented by the same w with the operator exp(h d), whose characteristic
// polynomial is q(l) = det(l I - exp(h [d])) (II.3.26, Cor. II.3.5).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/equality.h"

namespace symrep::signals {

/// A solution space represented on an algebra: A, the operator d (a generator of A:
/// its minimal polynomial has degree dim A) and the polynomial p (its minimal
/// polynomial, monic, in the symbol X).
struct representation {
    algebra_ptr A;
    coeffs d;
    GiNaC::ex p;
    GiNaC::symbol X{"X"};  ///< the variable of p (named X in messages)
    coeffs lambda;  ///< the functional: lambda(x) = sum_i lambda[i] x_i
};

/// lambda(x) = sum_i lambda[i] x_i (the functional of a representation applied to an element).
GiNaC::ex functional(const coeffs& lambda, const coeffs& x);

/// (Thm II.1.1) The representation with operator d on A. Throws algebra_error when d
/// does not generate A (its minimal polynomial has lower degree: Cor. II.1.1, the
/// signals would satisfy a lower-order equation and Psi would not be one-to-one).
representation represent_on(algebra_ptr A, const coeffs& d);

/// (Thm II.1.2 completion, II.3.29) P_n = R[X]/(p) with d = v: the representation of
/// p(D) f = 0 for a monic p of degree n >= 1 in X.
representation polynomial_representation(const GiNaC::ex& p, const GiNaC::symbol& X);

/// Psi^-1(w): the signal lambda(w exp(d t)) as a closed form in t.
GiNaC::ex signal_of(const representation& R, const coeffs& w, const GiNaC::ex& t);

/// Psi(f): the element w with lambda(w d^k) = f^(k)(0), k < n. Throws domain_error
/// when f is not a solution of p(D) f = 0 (the residual p(D) f is not proved 0), naming
/// the residual.
coeffs element_of(const representation& R, const GiNaC::ex& f, const GiNaC::symbol& t);

/// The monic real polynomial of least degree with q(D) f = 0, for a quasi-polynomial f
/// in t (sums and products of c t^k, exp(a t), cos(b t), sin(b t), cosh, sinh, with
/// a, b, c free of t): f is written with exponentials e^(lambda t), and each distinct
/// lambda with largest power t^k and a coefficient not 0 gives (X - lambda)^(k+1)
/// (with its conjugate: ((X - a)^2 + b^2)^(k+1)). Throws domain_error naming the part
/// of f that is not of this kind, and for f = 0 (represented by 0 in every algebra).
GiNaC::ex annihilator(const GiNaC::ex& f, const GiNaC::symbol& t, const GiNaC::symbol& X);

/// The distinct roots lambda of annihilator(f) with their multiplicities.
struct exponent {
    GiNaC::ex lambda;  ///< a + I b
    unsigned multiplicity;
};
/// A polynomial in X as text for messages, by descending powers ("X^2 + 4*X + 1"):
/// the same text whatever order GiNaC keeps the terms in.
std::string polynomial_text(const GiNaC::ex& p, const GiNaC::symbol& X);

std::vector<exponent> exponents_of(const GiNaC::ex& f, const GiNaC::symbol& t);

/// Psi^-1_d(w)(k) = lambda(w d^k) for k = first .. first + count - 1 (Thm II.3.3; the
/// shift is multiplication by d). Negative k need d invertible (zero_divisor_error).
std::vector<GiNaC::ex> sequence_of(const representation& R, const coeffs& w, long first, std::size_t count);

/// d^k for a symbolic integer k (Hermite interpolation of z^k on the roots of d's minimal
/// polynomial, as exp): the closed form of the shift's powers.
coeffs power(const representation& R, const GiNaC::ex& k);

/// Psi_d^-1(w) in closed form: lambda(w d^k) as an expression in the symbol k (Thm II.3.3).
GiNaC::ex sequence_formula(const representation& R, const coeffs& w, const GiNaC::symbol& k);

/// The monic real polynomial of least degree with q(E) f = 0, E the shift f(k) -> f(k+1), for
/// a sequence f(k) given in closed form: sums and products of c k^j, a^k, exp(b k),
/// cos(c k), sin(c k) (a, b, c free of k; parameters real). Each distinct ratio
/// rho = a e^b (cos c +- i sin c) with highest power k^j and a coefficient not 0 gives
/// (X - rho)^(j+1) (with its conjugate: (X^2 - 2 Re(rho) X + |rho|^2)^(j+1)). Throws
/// domain_error naming what is not of this kind, and for f = 0.
GiNaC::ex sequence_annihilator(const GiNaC::ex& f, const GiNaC::symbol& k, const GiNaC::symbol& X);

/// Psi_d(f) for a sequence: the element w with lambda(w d^j) = f(j), j < n, after q(E) f = 0
/// is proved for q the minimal polynomial of d.
coeffs sequence_element(const representation& R, const GiNaC::ex& f, const GiNaC::symbol& k);

/// (Thm II.3.4, Cor. II.3.5) Sampling with step h: the operator exp(h d), the
/// characteristic polynomial q(l) = det(l I - exp(h [d])), and the aliasing: the
/// sampled signals span fewer than n dimensions exactly when two distinct roots r, s of
/// p have e^(h r) = e^(h s), i.e. h (r - s) = 2 pi i m for a nonzero integer m. Decided
/// from the roots of p: yes or no for a numeric step;
/// for a symbolic h the report states the condition (generically: no). The roots come from
/// p's rational factors of degree <= 3 (Cardano for 3: scalar/polynomial_roots.h), and q from
/// them. With a factor of higher degree (roots not in radicals) and numeric p and h, the
/// numeric form (signals/sampling_numeric.h): floats marked as numeric, with an error bound
/// on q's coefficients; with symbols there, refused.
struct sampling {
    coeffs shift;        ///< exp(h d): the shift of the sampled signals
    GiNaC::ex q;         ///< det(l I - exp(h [d])), monic in l
    truth aliasing = truth::unknown;
    std::string report;  ///< one sentence: which roots meet and when, or that none do
    bool numeric = false;    ///< shift and q are floats (p has a factor without roots in radicals)
    GiNaC::ex error_bound;   ///< numeric: every coefficient of q is within it of the exact one
};
sampling sample(const representation& R, const GiNaC::ex& h, const GiNaC::symbol& l);

}  // namespace symrep::signals
