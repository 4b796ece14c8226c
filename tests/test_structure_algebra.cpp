// Tests of structure-constant algebras (II.1.2) and the general methods of II.1.
#include <gtest/gtest.h>

#include "algebra/element.h"
#include "algebra/polynomial_algebra.h"
#include "scalar/scalar.h"
#include "algebra/structure_algebra.h"
#include "gen_tables.h"
#include "core/error.h"

using namespace symrep;
using namespace symrep::test;
using GiNaC::ex;

namespace {

bool is_zero_vec(const coeffs& c) {
    for (const auto& x : c)
        if (!is_zero_scalar(x)) return false;
    return true;
}

template <class E> std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    return "<no exception>";
}

std::vector<algebra_ptr> sample_algebras() {
    GiNaC::realsymbol a("a"), b("b");
    return {complex_numbers(), dual_numbers(), split_complex(), truncated_cubic(), c_r_r(),
            symbolic_quadratic(a, b)};
}

// a generic-looking element of each algebra
coeffs sample_element(const algebra& A) {
    coeffs w(A.dim());
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = ex(int(2 * k + 1)) / ex(int(k + 2)) - (k % 2);
    return w;
}

}  // namespace

TEST(StructureAlgebra, NonCommutativeNamesThePair) {
    table g = unital_table(2, [](std::size_t, std::size_t) { return coeffs{-1, 0}; });
    g[0][1] = {0, 2};  // e0 e1 != e1 e0
    const std::string m = message_of<algebra_error>([&] { structure_algebra::make(g); });
    EXPECT_NE(m.find("not commutative"), std::string::npos) << m;
    EXPECT_NE(m.find("(0,1)"), std::string::npos) << m;
}

TEST(StructureAlgebra, NonAssociativeNamesTheTriple) {
    // e0 unit, e1^2 = e2, e2^2 = e2, e1 e2 = 0: (e1 e1) e2 = e2 but e1 (e1 e2) = 0
    table g = unital_table(3, [](std::size_t i, std::size_t j) {
        if (i == 1 && j == 1) return coeffs{0, 0, 1};
        if (i == 2 && j == 2) return coeffs{0, 0, 1};
        return coeffs{0, 0, 0};
    });
    const std::string m = message_of<algebra_error>([&] { structure_algebra::make(g); });
    EXPECT_NE(m.find("not associative"), std::string::npos) << m;
    EXPECT_NE(m.find("basis triple (1,1,2)"), std::string::npos) << m;
}

TEST(StructureAlgebra, NoUnit) {
    table g = zero_table(2);
    set(g, 0, 0, {1, 0});  // e1 annihilates everything
    const std::string m = message_of<algebra_error>([&] { structure_algebra::make(g); });
    EXPECT_NE(m.find("no unit element"), std::string::npos) << m;
}

TEST(StructureAlgebra, MalformedTable) {
    table g = zero_table(2);
    g[1][0] = {1};
    const std::string m = message_of<algebra_error>([&] { structure_algebra::make(g); });
    EXPECT_NE(m.find("e1*e0 has 1 coordinates, expected 2"), std::string::npos) << m;
    EXPECT_THROW(structure_algebra::make({}), algebra_error);
    EXPECT_THROW(structure_algebra::make(zero_table(2), {"only-one"}), algebra_error);
}

TEST(StructureAlgebra, UnitFoundByLinearSystem) {
    auto A = c_r_r();
    EXPECT_TRUE(algebra::equal(A->unit(), coeffs{1, 0, 1, 1}));
    const coeffs w = sample_element(*A);
    EXPECT_TRUE(algebra::equal(A->multiply(A->unit(), w), w));
}

TEST(StructureAlgebra, NameIsDeterministic) {
    auto A = dual_numbers(), B = dual_numbers();
    EXPECT_EQ(A->name(), B->name());
    EXPECT_EQ(A->name().rfind("algebra(2, #", 0), 0u) << A->name();
    EXPECT_NE(A->name(), split_complex()->name());
    EXPECT_EQ(complex_numbers()->name(), "complex-table");
    EXPECT_EQ(A->basis_name(1), "eps");
}

TEST(StructureAlgebra, ComplexProduct) {
    auto C = complex_numbers();
    // (1 + 2i)(3 - i) = 5 + 5i
    EXPECT_TRUE(algebra::equal(C->multiply({1, 2}, {3, -1}), coeffs{5, 5}));
}

TEST(StructureAlgebra, FromReproducesTable) {
    GiNaC::symbol X("X");
    auto P = polynomial_algebra::make(GiNaC::pow(X, 3) - 2 * X + 5, X);
    auto S = structure_algebra::from(*P);
    const coeffs a{1, -2, 3}, b{ex(1) / 2, 4, -1};
    EXPECT_TRUE(algebra::equal(P->multiply(a, b), S->multiply(a, b)));
    EXPECT_EQ(S->basis_name(2), "v^2");
    const GiNaC::symbol Y("Y");
    EXPECT_TRUE(is_zero_scalar(P->minpoly(a, Y) - S->minpoly(a, Y)));
}

// (II.1.3-4) row j of [w] = coordinates of w e_j.
TEST(GeneralMethods, CanonicalMatrixRows) {
    for (const auto& A : sample_algebras()) {
        const coeffs w = sample_element(*A);
        const GiNaC::matrix M = A->canonical_matrix(w);
        for (std::size_t j = 0; j < A->dim(); ++j) {
            const coeffs row = A->multiply(w, A->basis_vector(j));
            for (std::size_t k = 0; k < A->dim(); ++k)
                EXPECT_TRUE(is_zero_scalar(M(j, k) - row[k])) << A->name();
        }
    }
    // complex numbers: [a + b i] = [[a, b], [-b, a]]
    const GiNaC::matrix M = complex_numbers()->canonical_matrix({2, 3});
    EXPECT_EQ(M(0, 0), 2);
    EXPECT_EQ(M(0, 1), 3);
    EXPECT_EQ(M(1, 0), -3);
    EXPECT_EQ(M(1, 1), 2);
}

// (II.1.12) Cayley-Hamilton: p(w) = 0, and the minimal polynomial divides it.
TEST(GeneralMethods, CayleyHamiltonAndMinimalDivides) {
    const GiNaC::symbol X("X");
    for (const auto& A : sample_algebras()) {
        const coeffs w = sample_element(*A);
        const ex p = A->charpoly(w, X), q = A->minpoly(w, X);
        EXPECT_EQ(p.degree(X), int(A->dim())) << A->name();
        EXPECT_TRUE(is_zero_vec(A->evaluate_polynomial(p, X, w))) << A->name();
        EXPECT_TRUE(is_zero_vec(A->evaluate_polynomial(q, X, w))) << A->name();
        EXPECT_TRUE(is_zero_scalar(GiNaC::rem(p, q, X))) << A->name() << ": " << q << " / " << p;
        EXPECT_TRUE(is_zero_scalar(q.coeff(X, q.degree(X)) - 1));
    }
}

// (II.1.21) a_n = det [w] (up to (-1)^n for the monic form); (II.1.22) zero divisors.
TEST(GeneralMethods, DeterminantIsConstantTermAndZeroDivisors) {
    const GiNaC::symbol X("X");
    for (const auto& A : sample_algebras()) {
        const coeffs w = sample_element(*A);
        const ex p = A->charpoly(w, X);
        const int sgn = A->dim() % 2 ? -1 : 1;
        EXPECT_TRUE(is_zero_scalar(p.subs(X == 0) - sgn * A->determinant(w))) << A->name();
    }
    // dual numbers: eps * eps = 0, det [eps] = 0; 2 + eps is invertible
    auto D = dual_numbers();
    EXPECT_TRUE(D->is_zero_divisor({0, 1}));
    EXPECT_FALSE(D->is_zero_divisor({2, 1}));
    EXPECT_TRUE(algebra::equal(D->inverse({2, 1}), coeffs{ex(1) / 2, ex(-1) / 4}));
    const std::string m = message_of<zero_divisor_error>([&] { D->inverse({0, 3}); });
    EXPECT_NE(m.find("zero divisor"), std::string::npos) << m;
    // (II.1.22): d [(-1)^n d^{n-1} + a_1 d^{n-2} + ... + a_{n-1} e] = 0 when det = 0:
    // in monic form d * (p(d) - p(0)) / d = 0 with p(0) = 0.
    auto T = truncated_cubic();
    const coeffs z{0, 2, 5};  // 2x + 5x^2 is a zero divisor
    const ex p = T->charpoly(z, X);
    EXPECT_TRUE(is_zero_scalar(p.subs(X == 0)));
    const ex cofactor = GiNaC::quo(p, X, X);
    const coeffs c = T->evaluate_polynomial(cofactor, X, z);
    EXPECT_TRUE(is_zero_vec(T->multiply(z, c)));
    EXPECT_FALSE(is_zero_vec(c));
    // inverse round trip in C x R x R
    auto A = c_r_r();
    const coeffs w{1, 2, 3, -4};
    EXPECT_TRUE(algebra::equal(A->multiply(w, A->inverse(w)), A->unit()));
}

// Cor. II.1.1: minimal polynomial of lower degree than the characteristic one.
TEST(GeneralMethods, MinimalBelowCharacteristic) {
    const GiNaC::symbol X("X");
    auto A = c_r_r();
    // w = 2 u1 + 2 u2 + 2 u3 = 2: min X - 2, char (X - 2)^4
    EXPECT_TRUE(is_zero_scalar(A->minpoly({2, 0, 2, 2}, X) - (X - 2)));
    EXPECT_TRUE(is_zero_scalar(A->charpoly({2, 0, 2, 2}, X) - GiNaC::pow(X - 2, 4)));
    // w = i1 + u2 + u3: min (X^2 + 1)(X - 1), char (X^2 + 1)(X - 1)^2
    EXPECT_TRUE(is_zero_scalar(A->minpoly({0, 1, 1, 1}, X) - GiNaC::expand((X * X + 1) * (X - 1))));
    EXPECT_TRUE(is_zero_scalar(A->charpoly({0, 1, 1, 1}, X) -
                               GiNaC::expand((X * X + 1) * GiNaC::pow(X - 1, 2))));
    // x^2 in R[x]/(x^3): min X^2, char X^3
    auto T = truncated_cubic();
    EXPECT_TRUE(is_zero_scalar(T->minpoly({0, 0, 1}, X) - X * X));
    EXPECT_TRUE(is_zero_scalar(T->charpoly({0, 0, 1}, X) - GiNaC::pow(X, 3)));
}

TEST(GeneralMethods, SymbolicTable) {
    const GiNaC::realsymbol a("a"), b("b");
    const GiNaC::symbol X("X");
    auto A = symbolic_quadratic(a, b);
    EXPECT_TRUE(is_zero_scalar(A->minpoly({0, 1}, X) - (X * X - b * X - a)));
    EXPECT_TRUE(is_zero_scalar(A->determinant({0, 1}) + a));
    const coeffs w{1, 1};
    EXPECT_TRUE(algebra::equal(A->multiply(w, A->inverse(w)), A->unit()));
}
