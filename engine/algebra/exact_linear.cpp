// symrep/algebra/exact_linear.cpp -- exact Gaussian elimination (see exact_linear.h).
#include "symrep/algebra/exact_linear.h"

#include <stdexcept>
#include <string>

#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"

namespace symrep {

using GiNaC::ex;

std::optional<std::vector<ex>> krylov_basis::add(const coeffs& v_in) {
    if (v_in.size() != length_)
        throw std::logic_error("krylov_basis: vector of length " + std::to_string(v_in.size()) +
                               ", expected " + std::to_string(length_));
    const std::size_t m = rows_.size();
    coeffs v(v_in.size());
    for (std::size_t k = 0; k < v.size(); ++k) v[k] = tidy(v_in[k]);
    std::vector<ex> comb(m + 1, ex(0));
    comb[m] = 1;  // v = 1 * v_m
    for (const row& r : rows_) {
        if (is_zero_scalar(v[r.pivot])) continue;
        const ex f = tidy(v[r.pivot] / r.v[r.pivot]);
        for (std::size_t k = 0; k < v.size(); ++k)
            if (!r.v[k].is_zero()) v[k] = tidy(v[k] - f * r.v[k]);
        v[r.pivot] = 0;
        for (std::size_t i = 0; i < r.comb.size(); ++i)
            if (!r.comb[i].is_zero()) comb[i] = tidy(comb[i] - f * r.comb[i]);
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
        // an unproved zero taken as a pivot would add a direction (a minimal polynomial
        // of too high a degree): constants are decided or refused
        if (!is_nonzero_generic(v[k], "linear independence")) continue;
        rows_.push_back({std::move(v), k, std::move(comb)});
        return std::nullopt;
    }
    // 0 = v_m + sum_{i<m} comb[i] v_i  =>  v_m = -sum comb[i] v_i
    std::vector<ex> c(m);
    for (std::size_t i = 0; i < m; ++i) c[i] = tidy(-comb[i]);
    return c;
}

std::optional<std::vector<ex>> solve_linear(std::vector<std::vector<ex>> A, std::vector<ex> b) {
    const std::size_t rows = A.size();
    if (rows == 0) return std::vector<ex>{};
    const std::size_t cols = A[0].size();
    std::vector<std::size_t> pivot_row(cols);
    std::size_t r = 0;
    for (std::size_t c = 0; c < cols; ++c) {
        std::size_t p = r;
        while (p < rows && !is_nonzero_generic(A[p][c], "a pivot of a linear system")) ++p;
        if (p == rows) return std::nullopt;  // rank deficient
        std::swap(A[p], A[r]);
        std::swap(b[p], b[r]);
        const ex piv = tidy(A[r][c]);
        for (std::size_t i = 0; i < rows; ++i) {
            if (i == r || is_zero_scalar(A[i][c])) continue;
            const ex f = tidy(A[i][c] / piv);
            for (std::size_t k = c; k < cols; ++k) A[i][k] = tidy(A[i][k] - f * A[r][k]);
            b[i] = b[i] - f * b[r];
        }
        pivot_row[c] = r++;
    }
    for (std::size_t i = r; i < rows; ++i)
        if (!is_zero_scalar(b[i])) return std::nullopt;  // inconsistent
    std::vector<ex> x(cols);
    for (std::size_t c = 0; c < cols; ++c) x[c] = tidy(b[pivot_row[c]] / A[pivot_row[c]][c]);
    return x;
}

bool solve_any(const GiNaC::matrix& M, const std::vector<ex>& y, coeffs& x) {
    const unsigned n = M.cols();
    GiNaC::matrix vars(n, 1), rhs(M.rows(), 1);
    std::vector<GiNaC::symbol> unknowns(n);
    for (unsigned j = 0; j < n; ++j) vars(j, 0) = unknowns[j];
    for (unsigned i = 0; i < M.rows(); ++i) rhs(i, 0) = y[i];
    GiNaC::matrix s;
    try {
        s = M.solve(vars, rhs, GiNaC::solve_algo::gauss);
    } catch (const std::runtime_error&) {
        return false;  // "inconsistent linear system"
    }
    GiNaC::exmap free;
    for (unsigned j = 0; j < n; ++j) free[unknowns[j]] = 0;
    x.assign(n, ex(0));
    for (unsigned j = 0; j < n; ++j) x[j] = tidy(s(j, 0).subs(free));
    return true;
}

std::vector<coeffs> null_space(std::vector<std::vector<ex>> A) {
    const std::size_t rows = A.size();
    if (rows == 0) return {};
    const std::size_t cols = A[0].size();
    std::vector<std::size_t> pivots;  // pivot column of row r
    std::size_t r = 0;
    for (std::size_t c = 0; c < cols && r < rows; ++c) {
        std::size_t p = r;
        while (p < rows && !is_nonzero_generic(A[p][c], "a pivot of a linear system")) ++p;
        if (p == rows) continue;
        std::swap(A[p], A[r]);
        const ex piv = tidy(A[r][c]);
        for (std::size_t k = c; k < cols; ++k) A[r][k] = tidy(A[r][k] / piv);
        for (std::size_t i = 0; i < rows; ++i) {
            if (i == r || is_zero_scalar(A[i][c])) continue;
            const ex f = A[i][c];
            for (std::size_t k = c; k < cols; ++k) A[i][k] = tidy(A[i][k] - f * A[r][k]);
        }
        pivots.push_back(c);
        ++r;
    }
    std::vector<coeffs> basis;
    std::vector<bool> is_pivot(cols, false);
    for (std::size_t c : pivots) is_pivot[c] = true;
    for (std::size_t f = 0; f < cols; ++f) {
        if (is_pivot[f]) continue;
        coeffs x(cols, ex(0));
        x[f] = 1;
        for (std::size_t i = 0; i < pivots.size(); ++i) x[pivots[i]] = tidy(-A[i][f]);
        basis.push_back(std::move(x));
    }
    return basis;
}

}  // namespace symrep
