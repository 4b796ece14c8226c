// symrep/algebra/multicomplex.h -- the multicomplex algebra (x)C^{n+1} with
// exact (GiNaC) coefficients (thesis III.1, III.4.2a).
//
// (x)C^{n+1} = C_0 (x) C_1 (x) ... (x) C_n, order 2^{n+1}, commutative,
// associative, unital (III.1.1-2). Basis: the natural binary basis
//     e_p = i0^{p_0} i1^{p_1} ... in^{p_n},  p = (p_0 p_1 ... p_n)_2, p_0 MSB,
// so that coordinate p of a coeffs vector is the coefficient of e_p, i0 = e_{2^n}
// and i_k = e_{2^{n-k}} (III.1.4, corrected). Product (III.1.7):
//     e_p e_q = (-1)^{<p,q>} e_{p xor q}.
//
// Everything fast goes through the 2^n orthogonal idempotents e_p (III.1.15):
// w = sum_p (a_p + i0 b_p) e_p (III.1.39), computed by one fast Walsh-Hadamard
// transform (multicomplex_transform.h) in O(n 2^n). Products, inverses (III.1.57),
// exp (III.1.45-52), log (III.1.53), zero divisors (III.1.54-56), determinant,
// characteristic and minimal polynomials (III.1.59-60, corrected) and the
// semiexponential / special-type forms (III.1.72-95) are componentwise.
//
// Coefficients may be symbolic: declare symbols as GiNaC::realsymbol so that the
// real and imaginary parts of the components separate. Where a test on a
// symbolic coefficient is needed (b_p = 0? two factors equal?), the answer is the
// generic one: an expression is zero only when it normalizes to 0.
//
// Size: n <= max_order = 10 (dimension 2^11 = 2048). Exact coordinates are
// GiNaC trees; at n = 10 one product already handles 3 * 10 * 2^10 complex
// exact additions plus 2^11 normalizations, and the general methods of the base
// class (canonical matrix, 4^{n+1} entries) are far out of reach. For larger n
// use the double path (multicomplex_double.h), which reaches n = 24 and beyond.
//
// Floating-point elements take the double path (issue 13, 4.6): when every
// coordinate of the operands is a number and one is a float (1.5, not 3/2),
// multiply, inverse, exp, log and the zero-divisor ranks run in
// multicomplex_d (one FWHT, O(n 2^n)) and give float coordinates. For
// max_order < n <= multicomplex_d::max_order() the algebra is float-only:
// numeric elements (exact numbers too) take the double path, and the exact-only
// operations (characteristic and minimal polynomials, determinant, canonical
// matrix, semiexponential and special-type forms, symbolic coordinates) are
// refused with a size_error naming the limit.
#pragma once

#include <memory>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/cplx.h"

namespace symrep {

// The interface of algebra (algebra/algebra.h), declared as every family declares it: the
// declarations look alike, the fast paths behind them differ.
class multicomplex final : public algebra {
public:
    /// Largest n of the exact path (see the header comment for the reason).
    static constexpr unsigned max_order = 10;

    /// The algebra (x)C^{n+1}; throws size_error for n > multicomplex_d::max_order()
    /// (and float-only above max_order, see above).
    static std::shared_ptr<const multicomplex> make(unsigned n);
    /// n <= max_order: exact coordinates are allowed.
    bool exact() const override { return n_ <= max_order; }

    /// n (the algebra has n+1 imaginary units i0..in).
    unsigned order() const { return n_; }
    /// 2^n, the number of orthogonal idempotents.
    std::size_t half_dim() const { return std::size_t{1} << n_; }

    // --- identity and product ------------------------------------------------
    /// "multicomplex(n)".
    std::string name() const override;
    /// 2^{n+1}.
    std::size_t dim() const override { return std::size_t{2} << n_; }
    /// "1", "i0", "i1*i3", ... (III.1.4).
    std::string basis_name(std::size_t k) const override;
    /// Product through the idempotent components, then tidy (III.1.39, III.1.16).
    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    /// (III.1.7) e_i e_j = (-1)^{<i,j>} e_{i xor j}.
    coeffs basis_product(std::size_t i, std::size_t j) const override;

    // --- bases (III.1.4, III.1.10-14) ------------------------------------------
    /// i_k, k = 0..n (III.1.4).
    coeffs imag_unit(unsigned k) const;
    /// v_k = e_{g(k)}, k = 0..2^{n+1}-1 (III.1.13); u_k = v_k, j_k = v_{2^n+k}.
    coeffs gray_basis(std::size_t k) const;
    /// Coordinates in the basis {v_k} (III.1.37): (w^v)_k = w_{g(k)}.
    coeffs to_gray_coordinates(const coeffs& w) const;
    /// Inverse of to_gray_coordinates.
    coeffs from_gray_coordinates(const coeffs& wv) const;

    // --- idempotent structure (III.1.15-43) -------------------------------------
    /// Components (a_p, b_p), p = 0..2^n-1, of w = sum_p (a_p + i0 b_p) e_p (III.1.39).
    std::vector<cplx<GiNaC::ex>> component_pairs(const coeffs& w) const;
    /// Inverse of component_pairs (III.1.42-43, corrected).
    coeffs from_component_pairs(const std::vector<cplx<GiNaC::ex>>& c) const;

    /// 2^n.
    std::size_t idempotent_count() const override { return half_dim(); }
    /// (III.1.15) e_p = 2^{-n} prod_{k=1}^n [1 - (-1)^{p_k} i0 i_k].
    coeffs idempotent(std::size_t p) const override;
    /// (III.1.39) c_p = a_p + I b_p as GiNaC expressions.
    std::vector<GiNaC::ex> idempotent_components(const coeffs& w) const override;
    /// Inverse of idempotent_components (real_part / imag_part of each c_p).
    coeffs from_idempotent_components(const std::vector<GiNaC::ex>& c) const override;

    // --- fast overrides of the general methods ---------------------------------
    /// det [w] = prod_p (a_p^2 + b_p^2) (III.1.54).
    GiNaC::ex determinant(const coeffs& w) const override;
    /// (III.1.59) prod_p (X^2 - 2 a_p X + a_p^2 + b_p^2), expanded.
    GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    /// The true minimal polynomial (III.1.59-60 corrected, FORMULAS.md): the
    /// product of the DISTINCT factors (X - a_p) for b_p = 0 (X itself for a
    /// vanishing component) and (X^2 - 2 a_p X + a_p^2 + b_p^2) for b_p != 0.
    GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    /// (III.1.54-55) some component vanishes.
    bool is_zero_divisor(const coeffs& w) const override;
    /// (III.1.55) the ranks p with a_p = b_p = 0.
    std::vector<std::size_t> zero_divisor_ranks(const coeffs& w) const override;
    /// (III.1.57); zero_divisor_error naming the ranks for a zero divisor.
    coeffs inverse(const coeffs& w) const override;
    /// (III.1.45-52) exp(w t), componentwise e^{a_p t}(cos b_p t + i0 sin b_p t).
    coeffs exp(const coeffs& w, const GiNaC::ex& t) const override;
    /// (III.1.53) principal logarithm: log r_p + i0 atan2(b_p, a_p), atan2 in
    /// (-pi, pi]. The thesis takes phi_p in [0, 2pi); the two differ by 2 pi i0 e_p
    /// multiples, and exp of both is w. Zero divisor: zero_divisor_error with ranks.
    coeffs log(const coeffs& w) const override;

    // --- special forms (III.1.72-95, Thm III.1.3.1, III.4.2a) -------------------
    /// (III.1.72-76) w = rho exp(theta): rho has components r_p (in span{u_k}),
    /// theta has components i0 phi_p (in span{j_k}); phi_p = 0 where r_p = 0, so
    /// zero divisors have a semiexponential form too.
    std::pair<coeffs, coeffs> semiexponential(const coeffs& w) const override;
    /// (III.1.93, III.1.95) all r_p equal and nonzero; `strict` is not used here.
    bool is_special_type(const coeffs& w, bool strict = true) const override;
    /// Thm III.1.3.1, (III.1.90-92): w = sum_k rho_k exp(alpha_k), one term per
    /// nonzero rho_k (at most 2^n terms), each of special type; the terms are
    /// rho_k u_k exp(theta) since exp(sum_p i_p kb_p pi/2) = u_k (III.1.89).
    std::vector<coeffs> special_type_decomposition(const coeffs& w) const override;
    /// (III.4.5) d = sum_k omega_k i_k; params = {omega_0..omega_n}. Empty params:
    /// omega_0 = 2^n, omega_k = 2^{k-1}: sum_k (-1)^{p_k} 2^{k-1} runs over the 2^n
    /// distinct odd numbers of (-2^n, 2^n), so the Omega_p (III.4.8) are distinct
    /// and positive and the characteristic polynomial (III.4.9) is minimal. (The
    /// thesis asks only Omega_p != 0; that is not enough: equal |Omega_p| repeat
    /// a factor of (III.4.9), e.g. d = i0 in multicomplex(1).)
    coeffs generating_element(const std::vector<GiNaC::ex>& params) const override;

    /// (III.4.8) Omega_p = omega_0 + sum_{k=1}^n (-1)^{p_k} omega_k.
    std::vector<GiNaC::ex> generating_frequencies(const std::vector<GiNaC::ex>& omega) const;


private:
    explicit multicomplex(unsigned n) : n_(n) {}
    coeffs tidy_all(coeffs c) const;
    unsigned exact_limit() const override { return max_order; }
    unsigned n_;
};

}  // namespace symrep
