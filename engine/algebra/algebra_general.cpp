// symrep/algebra/algebra_general.cpp -- the general methods of II.1-II.2 that
// every algebra gets from its product alone: the canonical matrix, determinant,
// characteristic and minimal polynomials, zero-divisor test and inverse.
#include "algebra/algebra.h"

#include "algebra/scalar.h"
#include "io/error.h"

namespace symrep {

using GiNaC::ex;
using GiNaC::matrix;

// (II.1.3-4) row j of [w] holds the coordinates of w eps_j: a_jk = sum_i w_i gamma_ijk.
matrix algebra::canonical_matrix(const coeffs& w) const {
    check_size(w, "canonical matrix");
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
    return tidy(canonical_matrix(w).determinant());
}

// (II.1.20) made monic: det(X I - [w]) = (-1)^n det([w] - X I); GiNaC's
// charpoly(l) is det(M - l I).
ex algebra::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    const ex p = canonical_matrix(w).charpoly(X);
    return GiNaC::expand((dim() % 2 ? -1 : 1) * p);
}

// Cor. II.1.1: the minimal polynomial is the first linear relation among
// w^0, w^1, w^2, ... (Krylov sequence); its degree is at most n.
ex algebra::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "minimal polynomial");
    const std::size_t n = dim();
    std::vector<coeffs> powers{unit()};
    for (std::size_t k = 1; k <= n; ++k) {
        powers.push_back(multiply(powers.back(), w));
        matrix K(n, k);  // columns w^0 .. w^{k-1}
        for (std::size_t c = 0; c < k; ++c)
            for (std::size_t r = 0; r < n; ++r) K(r, c) = powers[c][r];
        matrix rhs(n, 1);
        for (std::size_t r = 0; r < n; ++r) rhs(r, 0) = powers[k][r];
        matrix Kb(n, k + 1);
        for (std::size_t r = 0; r < n; ++r) {
            for (std::size_t c = 0; c < k; ++c) Kb(r, c) = K(r, c);
            Kb(r, k) = rhs(r, 0);
        }
        if (Kb.rank() > k) continue;  // w^k independent of the lower powers
        matrix vars(k, 1);
        std::vector<GiNaC::symbol> cs;
        for (std::size_t c = 0; c < k; ++c) {
            cs.emplace_back("c" + std::to_string(c));
            vars(c, 0) = cs.back();
        }
        const matrix sol = K.solve(vars, rhs);
        ex p = GiNaC::pow(X, static_cast<int>(k));
        for (std::size_t c = 0; c < k; ++c) p -= tidy(sol(c, 0)) * GiNaC::pow(X, static_cast<int>(c));
        return GiNaC::expand(p);
    }
    return charpoly(w, X);  // unreachable by Cayley-Hamilton, kept for safety
}

// (II.1.22) w is a zero divisor iff det [w] = 0.
bool algebra::is_zero_divisor(const coeffs& w) const { return is_zero_scalar(determinant(w)); }

// w x = 1: coordinates of w x are [w]^T x.
coeffs algebra::inverse(const coeffs& w) const {
    const matrix M = canonical_matrix(w);
    const ex det = tidy(M.determinant());
    if (is_zero_scalar(det))
        throw zero_divisor_error("inverse of a zero divisor in " + name() +
                                     ": det [w] = 0, so w v = 0 for some v != 0 (II.1.22)",
                                 {});
    const std::size_t n = dim();
    matrix vars(n, 1), rhs(n, 1);
    const coeffs u = unit();
    for (std::size_t k = 0; k < n; ++k) {
        vars(k, 0) = GiNaC::symbol("x" + std::to_string(k));
        rhs(k, 0) = u[k];
    }
    const matrix x = M.transpose().solve(vars, rhs);
    coeffs r(n);
    for (std::size_t k = 0; k < n; ++k) r[k] = tidy(x(k, 0));
    return r;
}

}  // namespace symrep
