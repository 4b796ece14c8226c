// symrep/algebra/sobrero.h -- the generalized Sobrero algebra S = C (x) P (III.2).
//
// P = R[eps]/(eps^{n+1}) is the nilpotent algebra of order n+1 (III.2.2-3) and
// S = C (x) P is commutative, associative, unital, of order 2(n+1) over R, with
// basis {eps^k, j eps^k}, k = 0..n, and table (III.2.4):
//     eps^k eps^p = eps^{k+p},  eps^k (j eps^p) = j eps^{k+p},  (j eps^k)(j eps^p) = -eps^{k+p},
// where eps^{k+p} = 0 for k+p > n.
//
// Coordinate order: w = sum_k (a_k + j b_k) eps^k (III.2.6) is stored as
//     [a_0, a_1, ..., a_n, b_0, b_1, ..., b_n],
// so index k is eps^k and index n+1+k is j eps^k; index 0 is the identity.
//
// Fast paths (all exact, derived from w = xi_0 + N with N nilpotent):
//   multiply          truncated complex convolution (III.2.4, III.2.8)
//   charpoly          (X^2 - 2 a_0 X + a_0^2 + b_0^2)^{n+1} (III.2.12), expanded
//   minpoly           ((X - xi_0)(X - conj xi_0))^m, or (X - a_0)^m when b_0 = 0,
//                     m = nilpotency index of N = 1 + floor(n / k_0), k_0 the first
//                     k >= 1 with xi_k != 0 (m = 1 when N = 0)
//   determinant       (a_0^2 + b_0^2)^{n+1}
//   is_zero_divisor   a_0 = b_0 = 0 (III.2.13); zero divisors are nilpotent (III.2.15);
//                     zero_divisor_ranks gives {0} for them (the single idempotent 1)
//   inverse, exp(w t), log   nilpotent series around xi_0 (sobrero_kernel.h)
//   semiexponential   (III.2.16-18)
//   is_special_type   corrected (III.2.20): all xi_k on one ray (strict) or one line
//   special_type_decomposition  (III.2.24): real part + j part
//   generating_element (III.4.10): alpha j + beta eps, default alpha = beta = 1
#pragma once

#include "symrep/algebra/algebra.h"

namespace symrep {

// The interface of algebra (algebra/algebra.h), declared as every family declares it: the
// declarations look alike, the fast paths behind them differ.
class sobrero : public algebra {
public:
    /// Largest n accepted by make() for the exact algebra.
    static constexpr unsigned max_n = 512;

    /// The algebra S of order 2(n+1); throws size_error for n > sobrero_d::max_n.
    /// Float elements take the double path (sobrero_d: products, inverse, exp, zero
    /// divisors; algebra/double_path.h), and above max_n the algebra is
    /// double-precision only (exact-only operations, log among them, refused).
    static algebra_ptr make(long n);
    explicit sobrero(unsigned n);
    /// n <= max_n: exact coordinates are allowed.
    bool exact() const override { return n_ <= max_n; }

    /// Nilpotency order parameter n (eps^{n+1} = 0).
    unsigned n() const { return n_; }

    std::string name() const override;  // "sobrero(n)"
    std::size_t dim() const override { return 2 * (std::size_t(n_) + 1); }
    /// "1", "eps", "eps^2", ..., "j", "j*eps", "j*eps^2", ...
    std::string basis_name(std::size_t k) const override;

    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    GiNaC::ex determinant(const coeffs& w) const override;
    GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    bool is_zero_divisor(const coeffs& w) const override;
    /// S is local: its only idempotent is 1 and the zero divisors are the elements with
    /// xi_0 = 0 (III.2.13). Returns {0} for a zero divisor, {} otherwise.
    std::vector<std::size_t> zero_divisor_ranks(const coeffs& w) const override;
    coeffs inverse(const coeffs& w) const override;
    coeffs exp(const coeffs& w, const GiNaC::ex& t) const override;
    coeffs log(const coeffs& w) const override;

    /// (III.2.16-18): rho = [A_0..A_n, 0..0] and theta = [0..0, phi_0..phi_n], i.e.
    /// rho = sum A_k eps^k, theta = sum phi_k j eps^k with A_k = sqrt(a_k^2+b_k^2) and
    /// phi_k = atan2(b_k, a_k) in [0, 2 pi). The pair encodes w = sum_k A_k e^{j phi_k} eps^k
    /// coefficient by coefficient (it is not the algebra product rho * exp(theta)).
    /// phi_k = 0 where A_k = 0.
    std::pair<coeffs, coeffs> semiexponential(const coeffs& w) const override;
    /// Corrected (III.2.20), see FORMULAS.md. strict: all xi_k on one ray from 0,
    /// a_k b_l = a_l b_k and a_k a_l + b_k b_l >= 0 for all k, l. Non-strict: all xi_k on
    /// one line through 0 (a_k b_l = a_l b_k), i.e. w = (sum x_k eps^k) e^{j alpha} with
    /// real x_k of either sign. Throws domain_error when a sign cannot be decided.
    bool is_special_type(const coeffs& w, bool strict = true) const override;
    /// (III.2.24): {sum a_k eps^k, sum b_k j eps^k}, two special-type elements in the
    /// non-strict sense (real x_k of either sign, as the corrected Thm III.2.2.1 states).
    std::vector<coeffs> special_type_decomposition(const coeffs& w) const override;
    /// (III.4.10): alpha j + beta eps; params {} (alpha = beta = 1, III.4.13) or
    /// {alpha, beta}. Its minimal polynomial is (X^2 + alpha^2)^{n+1} when alpha, beta != 0.
    coeffs generating_element(const std::vector<GiNaC::ex>& params) const override;

    /// Coordinates of j (III.2.1) and eps (the generator of P; zero when n = 0).
    coeffs j() const;
    coeffs eps() const;

private:
    unsigned exact_limit() const override { return max_n; }
    unsigned n_;
};

}  // namespace symrep
