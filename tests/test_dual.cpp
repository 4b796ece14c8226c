// Dual numbers and dual vectors (engine/dual/dual.h, issue 31 item 1).
#include <gtest/gtest.h>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/vector/vector.h"

using namespace symrep;
using GiNaC::ex;

namespace {
const ex& eps = dual::dual_unit();
}

TEST(Dual, UnitSquaresToZero) {
    EXPECT_TRUE(dual::reduce(eps * eps).is_zero());
    EXPECT_TRUE(dual::reduce(GiNaC::pow(1 + eps, 2) - (1 + 2 * eps)).is_zero());
}

TEST(Dual, FunctionsExtendByTheirDerivative) {
    GiNaC::realsymbol a("a"), b("b");
    // f(a + eps b) = f(a) + eps b f'(a)
    const dual::dual_parts s = dual::parts(GiNaC::sin(a + eps * b));
    EXPECT_TRUE((s.primal - GiNaC::sin(a)).is_zero());
    EXPECT_TRUE((s.dual - b * GiNaC::cos(a)).expand().is_zero());
    const dual::dual_parts q = dual::parts(1 / (a + eps * b));
    EXPECT_TRUE((q.dual + b / (a * a)).normal().is_zero());
    const dual::dual_parts r = dual::parts(GiNaC::sqrt(a + eps * b));
    EXPECT_TRUE((r.dual - b / (2 * GiNaC::sqrt(a))).normal().is_zero());
}

TEST(Dual, PureDualIsAZeroDivisor) {
    GiNaC::realsymbol b("b");
    EXPECT_THROW(dual::reduce(1 / (eps * b)), zero_divisor_error);
    EXPECT_THROW(dual::reduce(GiNaC::log(eps * b)), zero_divisor_error);
}

TEST(Dual, TransferenceOfTheDoubleCrossProduct) {
    // a x (b x c) = (a . c) b - (a . b) c holds for dual vectors (transference principle)
    const ex a = dual::make_dual(vector_symbol("a"), vector_symbol("a1"));
    const ex b = dual::make_dual(vector_symbol("b"), vector_symbol("b1"));
    const ex c = dual::make_dual(vector_symbol("c"), vector_symbol("c1"));
    const ex lhs = dual::dual_cross(a, dual::dual_cross(b, c));
    const ex rhs = dual::reduce(dual::dual_dot(a, c) * b - dual::dual_dot(a, b) * c);
    EXPECT_TRUE(dual::dual_equal(lhs, rhs));
    EXPECT_FALSE(dual::dual_equal(lhs, dual::reduce(dual::dual_dot(a, b) * c - dual::dual_dot(a, c) * b)));
}
