// symrep/algebra/polynomial_algebra.h -- the polynomial algebra P_n = R[X]/(p)
// (thesis II.1.2, completion of the proof of Thm II.1.2).
//
// For a monic p(X) = X^n + a_1 X^{n-1} + ... + a_n (rational or symbolic
// coefficients) P_n has the cyclic basis {v^0, v, ..., v^{n-1}} with p(v) = 0;
// the product is polynomial multiplication reduced mod p.
//
// Convention of the Frobenius matrix: with the canonical matrix of algebra.h
// (row j of [w] = coordinates of w eps_j, II.1.4) and eps_j = v^j, row j of [v]
// holds v^{j+1}: ones on the superdiagonal and last row (-a_n, ..., -a_1). This
// is exactly the thesis's Frobenius matrix, so frobenius_matrix() ==
// canonical_matrix(generator()) with no transpose (tested).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "symrep/algebra/algebra.h"

namespace symrep {

class polynomial_algebra : public algebra {
public:
    /// P_n for a monic polynomial p in X of degree n >= 1. Throws algebra_error
    /// when p is not a polynomial in X, has degree 0, or is not monic.
    /// Largest degree accepted (larger ones throw size_error).
    static constexpr std::size_t max_degree = 4096;
    static std::shared_ptr<const polynomial_algebra> make(const GiNaC::ex& p, const GiNaC::symbol& X);

    std::string name() const override { return name_; }
    std::size_t dim() const override { return n_; }
    /// "1", "v", "v^2", ...
    std::string basis_name(std::size_t k) const override;
    /// Product of polynomials in v reduced mod p(v) = 0.
    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    coeffs unit() const override { return basis_vector(0); }
    /// charpoly(v) = p (Thm II.1.2); other elements use the general method.
    GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const override;
    /// minpoly(v) = p; other elements use the general method.
    GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const override;

    /// The generating polynomial p(X) (in the symbol given to make()).
    const GiNaC::ex& polynomial() const { return p_; }
    const GiNaC::ex& variable() const { return X_; }
    /// Coordinates of v (for n = 1, v = -a_1 times the unit).
    coeffs generator() const;
    /// w == generator(): the basis 1, v, ..., v^(n-1) is the power basis of v.
    bool is_power_basis_generator(const coeffs& w) const override;
    /// (II.1 completion) the Frobenius matrix of p.
    GiNaC::matrix frobenius_matrix() const;

    polynomial_algebra(const GiNaC::ex& p, const GiNaC::symbol& X);  // use make()

private:
    std::size_t n_;
    GiNaC::ex p_;
    GiNaC::ex X_;  // an ex, not a symbol: a copy would slice a realsymbol (other hash)
    std::vector<GiNaC::ex> low_;  // p = X^n + sum_{k<n} low_[k] X^k
    std::string name_;
};

}  // namespace symrep
