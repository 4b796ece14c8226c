// symrep/algebra/algebra_general.cpp -- the general methods of II.1-II.2 that
// every algebra gets from its product alone: the canonical matrix, determinant,
// characteristic and minimal polynomials, zero-divisor test and inverse.
#include "symrep/algebra/algebra.h"

#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

using GiNaC::ex;
using GiNaC::matrix;

// (II.1.3-4) row j of [w] holds the coordinates of w eps_j: a_jk = sum_i w_i gamma_ijk.
matrix algebra::canonical_matrix(const coeffs& w) const {
    check_size(w, "canonical matrix");
    check_dense("canonical matrix");
    const std::size_t n = dim();
    matrix M(n, n);
    for (std::size_t j = 0; j < n; ++j) {
        const coeffs row = multiply(w, basis_vector(j));
        for (std::size_t k = 0; k < n; ++k) M(j, k) = row[k];
    }
    return M;
}

// (II.1.21) a_n = det [w].
ex algebra::determinant(const coeffs& w) const {
    const GiNaC::matrix M = canonical_matrix(w);
    guard_terms(determinant_terms(M, false), "determinant");
    return tidy(M.determinant());
}

// (II.1.20) made monic: det(X I - [w]) = (-1)^n det([w] - X I); GiNaC's
// charpoly(l) is det(M - l I).
ex algebra::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    const GiNaC::matrix M = canonical_matrix(w);
    guard_terms(determinant_terms(M, true), "characteristic polynomial");
    const ex p = M.charpoly(X);
    return GiNaC::expand((dim() % 2 ? -1 : 1) * p);
}

// Cor. II.1.1: the minimal polynomial is the first linear relation among
// w^0, w^1, w^2, ... (Krylov sequence); its degree is at most n. Incremental
// Gaussian elimination: each new power is reduced once against the echelon
// rows of the lower ones.
ex algebra::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "minimal polynomial");
    check_dense("minimal polynomial");
    const std::size_t n = dim();
    krylov_basis K(n);
    coeffs pw = unit();
    for (std::size_t k = 0; k <= n; ++k) {
        if (auto rel = K.add(pw)) {  // w^k = sum_{c<k} rel[c] w^c
            ex p = GiNaC::pow(X, static_cast<int>(k));
            for (std::size_t c = 0; c < k; ++c) p -= (*rel)[c] * GiNaC::pow(X, static_cast<int>(c));
            return guarded_expand(p, "minimal polynomial");
        }
        pw = multiply(pw, w);
    }
    return charpoly(w, X);  // unreachable by Cayley-Hamilton (II.1.12)
}

// (II.1.22) w is a zero divisor iff det [w] = 0.
bool algebra::is_zero_divisor(const coeffs& w) const {
    return !is_nonzero_generic(determinant(w), "zero divisor test in " + name());
}

// w x = 1: the coordinates of w x are [w]^T x (II.1.4), so x solves [w]^T x = e.
coeffs algebra::inverse(const coeffs& w) const {
    const matrix M = canonical_matrix(w);
    const std::size_t n = dim();
    std::vector<std::vector<ex>> A(n, std::vector<ex>(n));
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c) A[r][c] = M(c, r);
    auto x = solve_linear(std::move(A), unit());
    if (!x)
        throw zero_divisor_error("inverse of a zero divisor in " + name() +
                                     ": det [w] = 0, so w v = 0 for some v != 0 (II.1.22)",
                                 {});
    return *x;
}

}  // namespace symrep
