// tests/gen_tables.h -- structure-constant tables shared by the tests of the
// general methods (II.1-II.2) and of Thm III.4.1.
#pragma once

#include <string>
#include <vector>

#include "algebra/structure_algebra.h"

namespace symrep::test {

using table = std::vector<std::vector<coeffs>>;

/// n x n table of zero products.
inline table zero_table(std::size_t n) {
    return table(n, std::vector<coeffs>(n, coeffs(n, GiNaC::ex(0))));
}

/// Sets e_i e_j = e_j e_i = c.
inline void set(table& g, std::size_t i, std::size_t j, coeffs c) {
    g[i][j] = c;
    g[j][i] = std::move(c);
}

/// Table with e_0 the unit and e_i e_j (i, j >= 1) given by f(i, j).
template <class F> table unital_table(std::size_t n, F f) {
    table g = zero_table(n);
    for (std::size_t j = 0; j < n; ++j) {
        coeffs c(n, GiNaC::ex(0));
        c[j] = 1;
        set(g, 0, j, c);
    }
    for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = i; j < n; ++j) set(g, i, j, f(i, j));
    return g;
}

/// C as {1, i}: i^2 = -1.
inline algebra_ptr complex_numbers() {
    return structure_algebra::make(unital_table(2, [](std::size_t, std::size_t) { return coeffs{-1, 0}; }),
                                   {"1", "i"}, "complex-table");
}
/// Dual numbers R[eps]/eps^2.
inline algebra_ptr dual_numbers() {
    return structure_algebra::make(unital_table(2, [](std::size_t, std::size_t) { return coeffs{0, 0}; }),
                                   {"1", "eps"});
}
/// Split-complex numbers: j^2 = 1.
inline algebra_ptr split_complex() {
    return structure_algebra::make(unital_table(2, [](std::size_t, std::size_t) { return coeffs{1, 0}; }),
                                   {"1", "j"});
}
/// R[x]/(x^3) in the basis {1, x, x^2}.
inline algebra_ptr truncated_cubic() {
    return structure_algebra::make(unital_table(3, [](std::size_t i, std::size_t j) {
        coeffs c(3, GiNaC::ex(0));
        if (i + j < 3) c[i + j] = 1;
        return c;
    }), {"1", "x", "x^2"});
}
/// C x R x R in the basis {u1, i1, u2, u3} (u1 = (1,0,0), i1 = (i,0,0), ...):
/// the unit is u1 + u2 + u3, not a basis element.
inline algebra_ptr c_r_r() {
    table g = zero_table(4);
    set(g, 0, 0, {1, 0, 0, 0});
    set(g, 0, 1, {0, 1, 0, 0});
    set(g, 1, 1, {-1, 0, 0, 0});
    set(g, 2, 2, {0, 0, 1, 0});
    set(g, 3, 3, {0, 0, 0, 1});
    return structure_algebra::make(g, {"u1", "i1", "u2", "u3"});
}
/// R[x,y]/(x,y)^2, basis {1, x, y}: not polynomial.
inline algebra_ptr square_zero_plane() {
    return structure_algebra::make(unital_table(3, [](std::size_t, std::size_t) { return coeffs{0, 0, 0}; }),
                                   {"1", "x", "y"});
}
/// R[x,y]/(x^2, y^2), basis {1, x, y, xy}: not polynomial.
inline algebra_ptr dual_square() {
    return structure_algebra::make(unital_table(4, [](std::size_t i, std::size_t j) {
        coeffs c(4, GiNaC::ex(0));
        if (i == 1 && j == 2) c[3] = 1;
        return c;
    }), {"1", "x", "y", "xy"});
}
/// e1^2 = a e0 + b e1 with symbols a, b (R[X]/(X^2 - b X - a)).
inline algebra_ptr symbolic_quadratic(const GiNaC::ex& a, const GiNaC::ex& b) {
    return structure_algebra::make(unital_table(2, [&](std::size_t, std::size_t) { return coeffs{a, b}; }));
}

}  // namespace symrep::test
