// Tests of the exact linear solvers (algebra/exact_linear.h) and of the sign of a quadratic's
// discriminant (scalar/polynomial_roots.h), each answer checked by substitution or by hand.
#include <gtest/gtest.h>

#include "algebra/exact_linear.h"
#include "scalar/equality.h"
#include "scalar/polynomial_roots.h"
#include "scalar/scalar.h"

using namespace symrep;
using GiNaC::ex;

namespace {

// M x - y, entry by entry, proved 0.
bool solves(const GiNaC::matrix& M, const coeffs& x, const std::vector<ex>& y) {
    for (unsigned i = 0; i < M.rows(); ++i) {
        ex row = 0;
        for (unsigned j = 0; j < M.cols(); ++j) row += M(i, j) * x[j];
        if (!is_zero_scalar(GiNaC::expand(row - y[i]))) return false;
    }
    return true;
}

}  // namespace

// solve_any: a rank-deficient but consistent system (the multiplication matrix of a zero
// divisor) has a solution, the free unknown 0; an inconsistent one has none.
TEST(ExactLinear, SolveAnyRankDeficient) {
    const GiNaC::symbol a("a");
    // rows (1, 1), (2, 2), (0, 0): x0 + x1 = a, 2 x0 + 2 x1 = 2 a
    const GiNaC::matrix M = {{1, 1}, {2, 2}, {0, 0}};
    coeffs x;
    ASSERT_TRUE(solve_any(M, {a, 2 * a, 0}, x));
    ASSERT_EQ(x.size(), 2u);
    EXPECT_TRUE(solves(M, x, {a, 2 * a, 0}));
    EXPECT_TRUE(x[0].is_zero() || x[1].is_zero()) << x[0] << ", " << x[1];  // the free unknown is 0
    EXPECT_FALSE(solve_any(M, {a, 2 * a + 1, 0}, x));                        // inconsistent
    // full rank: the one solution, as solve_linear gives it
    const GiNaC::matrix F = {{2, 1}, {1, 3}};
    ASSERT_TRUE(solve_any(F, {5, 10}, x));
    const auto y = solve_linear({{2, 1}, {1, 3}}, {5, 10});
    ASSERT_TRUE(y.has_value());
    EXPECT_TRUE(is_zero_scalar(x[0] - 1) && is_zero_scalar(x[1] - 3)) << x[0] << ", " << x[1];
    EXPECT_TRUE(is_zero_scalar((*y)[0] - 1) && is_zero_scalar((*y)[1] - 3));
    EXPECT_FALSE(solve_linear({{1, 1}, {2, 2}}, {1, 2}).has_value());  // rank deficient: refused
}

// discriminant_sign: numbers decided; -4 (w0 - W)^2 read as negative, 4 (w0 - W)^2 as positive
// (the generic reading); c^2 - 4 w0^2 undecided (2).
TEST(ExactLinear, DiscriminantSign) {
    const GiNaC::symbol w0("w0"), W("W"), c("c");
    EXPECT_EQ(discriminant_sign(ex(-3)), -1);
    EXPECT_EQ(discriminant_sign(ex(0)), 0);
    EXPECT_EQ(discriminant_sign(GiNaC::sqrt(ex(2)) - 1), 1);
    EXPECT_EQ(discriminant_sign(-4 * GiNaC::pow(w0 - W, 2)), -1);
    EXPECT_EQ(discriminant_sign(GiNaC::expand(4 * GiNaC::pow(w0 - W, 2))), 1);
    EXPECT_EQ(discriminant_sign(c * c - 4 * w0 * w0), 2);
}
