// symrep/algebra/walsh_complex.h -- the complex extension W* of the Walsh algebra
// (III.3.45-67), in its real form of order 2^{n+1}.
//
// W* is the C-algebra with basis w_p, w_p w_q = w_{p xor q} (III.3.45); its real form has
// basis B = {w_p, i0 w_p} with i0^2 = -1 (III.3.51). Coordinates follow (III.3.53):
//     w = sum_p (a_p w_p + b_p i0 w_p)  is stored as  [a_0..a_{2^n-1}, b_0..b_{2^n-1}],
// with the bit order of walsh.h (p_0 most significant, u_k = w_{2^{n-1-k}}).
// Idempotent components y_p = c_p + i0 d_p, c = H a, d = H b (III.3.62-63), computed by
// fwht on complex pairs; idempotent_components() returns them as c_p + I d_p.
// Fast paths: product, inverse, exp, log of every non-zero-divisor (III.3.64-67),
// determinant prod (c_p^2 + d_p^2), charpoly prod (X^2 - 2 c_p X + c_p^2 + d_p^2) (each
// component contributes the conjugate pair y_p, conj y_p of the real form), minpoly (the
// distinct real irreducible factors: X - c_p if d_p = 0, the quadratic otherwise), zero
// divisors of rank p (y_p = 0).
#pragma once

#include "symrep/algebra/algebra.h"

namespace symrep {

// The interface of algebra (algebra/algebra.h), declared as every family declares it: the
// declarations look alike, the fast paths behind them differ.
class walsh_complex : public algebra {
public:
    /// Largest n accepted for the exact algebra (real order 2^{n+1}).
    static constexpr unsigned max_n = 15;

    /// W* of real order 2^{n+1}; throws size_error for n > walsh_complex_d::max_n.
    /// Float elements take the double path (walsh_complex_d; algebra/double_path.h),
    /// and above max_n the algebra is double-precision only.
    static algebra_ptr make(long n);
    explicit walsh_complex(unsigned n);
    /// n <= max_n: exact coordinates are allowed.
    bool exact() const override { return n_ <= max_n; }

    unsigned n() const { return n_; }
    /// Number of components 2^n (the complex order of W*).
    std::size_t size() const { return std::size_t(1) << n_; }
    std::string name() const override;  // "walsh_complex(n)"
    std::size_t dim() const override { return std::size_t(2) << n_; }
    /// "1", "u0", "u0*u1", ..., "i0", "i0*u0", ...
    std::string basis_name(std::size_t k) const override;

    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    GiNaC::ex determinant(const coeffs& w) const override;
    GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    bool is_zero_divisor(const coeffs& w) const override;
    coeffs inverse(const coeffs& w) const override;
    coeffs exp(const coeffs& w, const GiNaC::ex& t) const override;
    /// (III.3.64-67) sum_p (ln rho_p e_p + theta_p i0 e_p), theta_p = atan2(d_p, c_p).
    coeffs log(const coeffs& w) const override;

    std::size_t idempotent_count() const override { return size(); }
    coeffs idempotent(std::size_t p) const override;
    /// Complex components c_p + I d_p (III.3.61-63).
    std::vector<GiNaC::ex> idempotent_components(const coeffs& w) const override;
    /// From components y_p (complex expressions; real and imaginary parts are taken).
    coeffs from_idempotent_components(const std::vector<GiNaC::ex>& y) const override;
    std::vector<std::size_t> zero_divisor_ranks(const coeffs& w) const override;
    /// Not in the thesis (III.4.2c treats W only): d = sum_k alpha_k u_k + beta i0, with
    /// components Omega_p + i beta. params {} gives alpha_k = 2^k, beta = 1: the 2^n
    /// quadratics (X - Omega_p)^2 + 1 are distinct, so the characteristic polynomial is
    /// minimal. params {alpha_0..alpha_{n-1}} (beta = 1) or {alpha_0..alpha_{n-1}, beta}.
    coeffs generating_element(const std::vector<GiNaC::ex>& params) const override;

    /// Coordinates of the generator u_k and of i0 (III.3.51).
    coeffs generator(std::size_t k) const;
    coeffs i0() const;

private:
    unsigned exact_limit() const override { return max_n; }
    unsigned n_;
};

}  // namespace symrep
