// Tests of the builtins of "General and polynomial algebras", called through the
// registry with a small mock context.
#include <gtest/gtest.h>

#include "test_util.h"

#include "mock_context.h"

#include <map>
#include <sstream>

#include "algebra/polynomial_algebra.h"
#include "scalar/scalar.h"
#include "lang/builtins.h"

using namespace symrep;
using namespace symrep::lang;
using GiNaC::ex;

namespace {

using symrep::test::mock_context;

struct BuiltinsPolynomial : ::testing::Test {
    registry r;
    mock_context ctx;
    BuiltinsPolynomial() { register_polynomial_builtins(r); }
    value call(const std::string& name, const std::vector<value>& args) {
        const builtin* b = r.find(name);
        if (!b) throw std::logic_error("no builtin " + name);
        return b->fn(args, ctx);
    }
};

value vec(std::initializer_list<int> xs) {
    list l;
    for (int x : xs) l.push_back(value(x));
    return value(std::move(l));
}

// the complex numbers as a table
value complex_table() {
    return value(list{value(list{vec({1, 0}), vec({0, 1})}), value(list{vec({0, 1}), vec({-1, 0})})});
}

using symrep::test::what_of;

}  // namespace

TEST_F(BuiltinsPolynomial, AllDocumented) {
    for (const char* n : {"algebra_from_table", "polynomial_algebra", "frobenius_matrix", "find_generator",
                          "is_polynomial", "power_basis_change", "fundamental_system"}) {
        const builtin* b = r.find(n);
        ASSERT_NE(b, nullptr) << n;
        EXPECT_FALSE(b->signature.empty());
        EXPECT_FALSE(b->summary.empty());
        EXPECT_FALSE(b->equation.empty()) << n;
        EXPECT_NE(b->example.find(n), std::string::npos) << n;
        EXPECT_EQ(b->section, "General and polynomial algebras");
    }
    EXPECT_EQ(r.all().size(), 7u);
}

TEST_F(BuiltinsPolynomial, AlgebraFromTable) {
    const value A = call("algebra_from_table", {complex_table(), value(list{"1", "i"}), "C"});
    ASSERT_TRUE(A.is_algebra());
    EXPECT_EQ(A.as_algebra()->name(), "C");
    EXPECT_EQ(A.as_algebra()->basis_name(1), "i");
    EXPECT_TRUE(call("is_polynomial", {A}).as_bool());
    // malformed: second row too short
    const value bad = value(list{value(list{vec({1, 0}), vec({0, 1})}), value(list{vec({0, 1})})});
    const std::string m = what_of([&] { call("algebra_from_table", {bad}); });
    EXPECT_NE(m.find("gamma[1] must be a list of 2"), std::string::npos) << m;
    EXPECT_THROW(call("algebra_from_table", {bad}), type_error);
    // non-commutative table: the engine's message comes through
    const value nc = value(list{value(list{vec({1, 0}), vec({0, 1})}), value(list{vec({0, 2}), vec({-1, 0})})});
    EXPECT_THROW(call("algebra_from_table", {nc}), algebra_error);
    EXPECT_THROW(call("algebra_from_table", {value(3)}), type_error);
}

TEST_F(BuiltinsPolynomial, PolynomialAlgebraAndFrobenius) {
    const GiNaC::ex X = ctx.symbol("X");
    const value P = call("polynomial_algebra", {ex(GiNaC::pow(X, 2) + 1), X});
    ASSERT_TRUE(P.is_algebra());
    EXPECT_EQ(P.as_algebra()->name(), "polynomial(X^2 + 1)");
    const value F = call("frobenius_matrix", {P});
    ASSERT_TRUE(F.is_ex());
    ASSERT_TRUE(GiNaC::is_a<GiNaC::matrix>(F.as_ex()));
    const GiNaC::matrix M = GiNaC::ex_to<GiNaC::matrix>(F.as_ex());
    EXPECT_EQ(M(0, 1), 1);
    EXPECT_EQ(M(1, 0), -1);
    const value C = call("algebra_from_table", {complex_table()});
    const std::string m = what_of([&] { call("frobenius_matrix", {C}); });
    EXPECT_NE(m.find("must be a polynomial algebra"), std::string::npos) << m;
    EXPECT_THROW(call("polynomial_algebra", {ex(2 * X * X + 1), X}), algebra_error);
    EXPECT_THROW(call("polynomial_algebra", {ex(X * X + 1), ex(3)}), type_error);
}

TEST_F(BuiltinsPolynomial, GeneratorPowerBasisAndFundamentalSystem) {
    const GiNaC::ex X = ctx.symbol("X"), t = ctx.symbol("t");
    const value P = call("polynomial_algebra", {ex(GiNaC::pow(X, 2) + 1), X});
    const value d = call("find_generator", {P});
    ASSERT_TRUE(d.is_element());
    EXPECT_EQ(d.as_element().minpoly(GiNaC::ex_to<GiNaC::symbol>(X)).degree(X), 2);
    const value M = call("power_basis_change", {P, d});
    ASSERT_TRUE(GiNaC::is_a<GiNaC::matrix>(M.as_ex()));
    EXPECT_FALSE(is_zero_scalar(GiNaC::ex_to<GiNaC::matrix>(M.as_ex()).determinant()));
    EXPECT_TRUE(call("power_basis_change", {P}).is_ex());
    const value f = call("fundamental_system", {d, t});
    ASSERT_TRUE(f.is_list());
    ASSERT_EQ(f.as_list().size(), 2u);
    for (const value& fj : f.as_list())  // f'' + f = 0
        EXPECT_TRUE(is_zero_scalar(fj.as_ex().diff(GiNaC::ex_to<GiNaC::symbol>(t), 2) + fj.as_ex()));
    // R[x,y]/(x,y)^2 is not polynomial
    const value N = call("algebra_from_table",
                         {value(list{value(list{vec({1, 0, 0}), vec({0, 1, 0}), vec({0, 0, 1})}),
                                     value(list{vec({0, 1, 0}), vec({0, 0, 0}), vec({0, 0, 0})}),
                                     value(list{vec({0, 0, 1}), vec({0, 0, 0}), vec({0, 0, 0})})})});
    EXPECT_FALSE(call("is_polynomial", {N}).as_bool());
    const std::string m = what_of([&] { call("find_generator", {N}); });
    EXPECT_NE(m.find("not polynomial"), std::string::npos) << m;
    EXPECT_THROW(call("power_basis_change", {N}), algebra_error);
    EXPECT_THROW(call("power_basis_change", {P, call("find_generator", {call("algebra_from_table", {complex_table()})})}),
                 algebra_error);
}
