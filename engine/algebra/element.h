// symrep/algebra/element.h -- an element of an algebra, as a value.
//
// element = (algebra, coordinates). Arithmetic between elements of different
// algebras throws algebra_error. Scalars (GiNaC::ex, exact or symbolic) multiply
// from either side. Everything delegates to the algebra, so fast paths of the
// families are used automatically.
#pragma once

#include "symrep/algebra/algebra.h"

namespace symrep {

class element {
public:
    /// Throws algebra_error if c.size() != A->dim().
    element(algebra_ptr A, coeffs c);
    /// The identity of A.
    static element one(algebra_ptr A);
    /// Basis element k of A.
    static element basis(algebra_ptr A, std::size_t k);
    /// A scalar s times the identity of A.
    static element scalar(algebra_ptr A, const GiNaC::ex& s);

    const algebra& parent() const { return *A_; }
    const algebra_ptr& parent_ptr() const { return A_; }
    const coeffs& coefficients() const { return c_; }
    const GiNaC::ex& operator[](std::size_t k) const { return c_[k]; }
    std::size_t dim() const { return c_.size(); }

    element operator-() const;
    friend element operator+(const element& a, const element& b);
    friend element operator-(const element& a, const element& b);
    friend element operator*(const element& a, const element& b);
    friend element operator*(const GiNaC::ex& s, const element& a);
    friend element operator*(const element& a, const GiNaC::ex& s) { return s * a; }
    /// a / b = a * b^{-1}; b must not be a zero divisor.
    friend element operator/(const element& a, const element& b);
    friend element operator/(const element& a, const GiNaC::ex& s);
    /// w^k; negative k uses the inverse.
    element pow(long k) const;
    /// Exact equality (coordinate differences normalize to 0).
    friend bool operator==(const element& a, const element& b);

    element inverse() const { return {A_, A_->inverse(c_)}; }
    element exp(const GiNaC::ex& t = 1) const { return {A_, A_->exp(c_, t)}; }
    element log() const { return {A_, A_->log(c_)}; }
    GiNaC::ex charpoly(const GiNaC::symbol& X) const { return A_->charpoly(c_, X); }
    GiNaC::ex minpoly(const GiNaC::symbol& X) const { return A_->minpoly(c_, X); }
    GiNaC::ex determinant() const { return A_->determinant(c_); }
    bool is_zero_divisor() const { return A_->is_zero_divisor(c_); }
    GiNaC::matrix canonical_matrix() const { return A_->canonical_matrix(c_); }
    /// p(w) for a polynomial p in X.
    element evaluate(const GiNaC::ex& p, const GiNaC::symbol& X) const;
    /// Map f over the coordinates (e.g. subs, normal, expand, diff by t).
    template <class F> element map_coeffs(F&& f) const {
        coeffs d; d.reserve(c_.size());
        for (const auto& x : c_) d.push_back(f(x));
        return {A_, std::move(d)};
    }

private:
    algebra_ptr A_;
    coeffs c_;
};

/// Throws algebra_error unless a and b belong to the same algebra (same name()).
void require_same_algebra(const element& a, const element& b, const char* op);

}  // namespace symrep
