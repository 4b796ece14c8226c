// symrep/algebra/walsh.h -- the Walsh algebra W = U_0 (x) ... (x) U_{n-1} (III.3),
// the group algebra of the dyadic group of order 2^n.
//
// Basis w_p = u_0^{p_0} u_1^{p_1} ... u_{n-1}^{p_{n-1}} (III.3.3), with product
// w_p w_q = w_{p xor q} (III.3.6). Bit order: as in the thesis's p = (p_0 p_1 ... p_{n-1})_2,
// p_0 is the MOST significant bit, so the generator u_k is basis element w_{2^{n-1-k}}
// (u_0 = w_{2^{n-1}}, u_{n-1} = w_1). <p,q> and xor do not depend on the bit order.
// Coordinates: f = sum_p f_p w_p is stored as [f_0, ..., f_{2^n-1}]; index 0 is the identity.
//
// Hadamard idempotents e_p = 2^{-n} prod_k (1 + (-1)^{p_k} u_k) (III.3.7, prefactor 1/4^n
// in (III.3.8) corrected per FORMULAS.md), e_p = 2^{-n} sum_q (-1)^{<p,q>} w_q (III.3.22).
// Components a = H f (III.3.25) by fwht in O(n 2^n); every fast path works on them:
// product, inverse, determinant (III.3.28), charpoly (III.3.33-34), minpoly (product over
// distinct a_p), zero divisors of rank p (III.3.31-32), exp (III.3.44), log when every
// a_p > 0 (Thm III.3.3.1, III.3.40; otherwise domain_error pointing to walsh_complex).
#pragma once

#include "symrep/algebra/algebra.h"

namespace symrep {

// The interface of algebra (algebra/algebra.h), declared as every family declares it: the
// declarations look alike, the fast paths behind them differ.
class walsh : public algebra {
public:
    /// Largest n accepted for the exact algebra (order 2^n).
    static constexpr unsigned max_n = 16;

    /// The algebra W of order 2^n; throws size_error for n > walsh_d::max_n. Float
    /// elements take the double path (walsh_d; algebra/double_path.h), and above
    /// max_n the algebra is double-precision only (exact-only operations refused).
    static algebra_ptr make(long n);
    explicit walsh(unsigned n);
    /// n <= max_n: exact coordinates are allowed.
    bool exact() const override { return n_ <= max_n; }

    unsigned n() const { return n_; }
    std::string name() const override;  // "walsh(n)"
    std::size_t dim() const override { return std::size_t(1) << n_; }
    /// "1", "u0", "u1", "u0*u1", ... (the factors u_k with p_k = 1).
    std::string basis_name(std::size_t k) const override;

    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    coeffs basis_product(std::size_t i, std::size_t j) const override;
    GiNaC::ex determinant(const coeffs& w) const override;
    GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    bool is_zero_divisor(const coeffs& w) const override;
    coeffs inverse(const coeffs& w) const override;
    coeffs exp(const coeffs& w, const GiNaC::ex& t) const override;
    coeffs log(const coeffs& w) const override;

    std::size_t idempotent_count() const override { return dim(); }
    coeffs idempotent(std::size_t p) const override;
    /// Real components a_p (III.3.25).
    std::vector<GiNaC::ex> idempotent_components(const coeffs& w) const override;
    coeffs from_idempotent_components(const std::vector<GiNaC::ex>& a) const override;
    std::vector<std::size_t> zero_divisor_ranks(const coeffs& w) const override;
    /// (III.4.15) d = sum_k alpha_k u_k; params {} gives alpha_k = 2^k, whose
    /// Omega_p = sum_k (-1)^{p_k} 2^k (III.4.17) are distinct odd integers.
    coeffs generating_element(const std::vector<GiNaC::ex>& params) const override;

    /// Coordinates of the generator u_k (k = 0..n-1).
    coeffs generator(std::size_t k) const;
    /// Index of u_k in the basis: 2^{n-1-k}.
    std::size_t generator_index(std::size_t k) const;

private:
    unsigned exact_limit() const override { return max_n; }
    unsigned n_;
};

}  // namespace symrep
