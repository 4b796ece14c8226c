// Tests of the polynomial algebras P_n (II.1 completion of Thm II.1.2) and of
// Theorem III.4.1 (generators, power basis III.4.4, Wronskian form III.4.2-4).
#include <gtest/gtest.h>

#include <array>
#include <complex>

#include "test_util.h"

#include "algebra/polynomial_algebra.h"
#include "algebra/polynomial_structure.h"
#include "scalar/scalar.h"
#include "gen_tables.h"
#include "core/error.h"

using namespace symrep;
using namespace symrep::test;
using GiNaC::ex;

namespace {

using symrep::test::same;

using symrep::test::what_of;

}  // namespace

TEST(PolynomialAlgebra, ProductIsMultiplicationModP) {
    const GiNaC::symbol X("X");
    const ex p = GiNaC::pow(X, 3) - 2 * X + 5;
    auto P = polynomial_algebra::make(p, X);
    EXPECT_EQ(P->dim(), 3u);
    EXPECT_EQ(P->name(), "polynomial(X^3 - 2*X + 5)");
    const coeffs a{1, -2, 3}, b{ex(1) / 2, 4, -1};
    const ex pa = 1 - 2 * X + 3 * X * X, pb = ex(1) / 2 + 4 * X - X * X;
    const ex r = GiNaC::rem(GiNaC::expand(pa * pb), p, X);
    const coeffs c = P->multiply(a, b);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(is_zero_scalar(c[k] - r.coeff(X, k))) << k;
    // p(v) = 0
    EXPECT_TRUE(same(P->evaluate_polynomial(p, X, P->generator()), P->zero()));
    EXPECT_EQ(P->basis_name(2), "v^2");
}

TEST(PolynomialAlgebra, FrobeniusIsCanonicalMatrixOfV) {
    const GiNaC::symbol X("X");
    const GiNaC::realsymbol a("a");
    for (const ex& p : {ex(GiNaC::pow(X, 4) + 3 * GiNaC::pow(X, 2) - X + 7),
                        ex(GiNaC::pow(X, 2) + a * a), ex(X - 3)}) {
        auto P = polynomial_algebra::make(p, X);
        const GiNaC::matrix F = P->frobenius_matrix();
        EXPECT_TRUE(same(F, P->canonical_matrix(P->generator()))) << P->name();
        // the charpoly of the Frobenius matrix (general method) is p
        EXPECT_TRUE(is_zero_scalar(P->algebra::charpoly(P->generator(), X) - p)) << P->name();
        EXPECT_TRUE(is_zero_scalar(P->charpoly(P->generator(), X) - p));
        EXPECT_TRUE(is_zero_scalar(P->algebra::minpoly(P->generator(), X) - GiNaC::expand(p)));
    }
    auto P = polynomial_algebra::make(GiNaC::pow(X, 3) + 2 * X * X - 5 * X + 7, X);
    const GiNaC::matrix F = P->frobenius_matrix();
    EXPECT_EQ(F(0, 1), 1);
    EXPECT_EQ(F(1, 2), 1);
    EXPECT_EQ(F(2, 0), -7);  // -a_n
    EXPECT_EQ(F(2, 1), 5);
    EXPECT_EQ(F(2, 2), -2);  // -a_1
}

TEST(PolynomialAlgebra, InvalidPolynomials) {
    const GiNaC::symbol X("X"), Y("Y");
    EXPECT_NE(what_of([&] { polynomial_algebra::make(2 * X * X + 1, X); }).find("not monic"),
              std::string::npos);
    EXPECT_NE(what_of([&] { polynomial_algebra::make(1 / X + X, X); }).find("not a polynomial"),
              std::string::npos);
    EXPECT_NE(what_of([&] { polynomial_algebra::make(GiNaC::sin(X), X); }).find("not a polynomial"),
              std::string::npos);
    EXPECT_NE(what_of([&] { polynomial_algebra::make(Y + 1, X); }).find("degree 0"), std::string::npos);
    EXPECT_THROW(polynomial_algebra::make(2 * X * X + 1, X), algebra_error);
}

// exp(v t) = sum f_j v^j: the f_j are a fundamental system of p(D) f = 0 (Thm II.2.3).
TEST(PolynomialAlgebra, ExpOfGeneratorSolvesTheEquation) {
    const GiNaC::symbol X("X"), t("t");
    const GiNaC::realsymbol a("a");
    const std::vector<ex> ps = {
        GiNaC::expand(GiNaC::pow(X - 1, 2) * (X + 2)),          // repeated real root
        GiNaC::expand((X * X + 1) * (X * X - 2 * X + 5)),       // two complex pairs
        GiNaC::expand(GiNaC::pow(X * X + 1, 2)),                // Sobrero n = 1 (III.4.14)
        GiNaC::expand(X * X + a * a),                           // symbolic
        GiNaC::expand(X * X - 2),                               // irrational real roots
    };
    for (const ex& p : ps) {
        auto P = polynomial_algebra::make(p, X);
        const std::vector<ex> f = fundamental_system(*P, P->generator(), t);
        const int n = int(P->dim());
        for (const ex& fj : f) {
            ex acc = 0, g = fj;
            for (int k = 0; k <= n; ++k, g = g.diff(t)) acc += p.coeff(X, k) * g;
            EXPECT_TRUE(is_zero_scalar(acc)) << P->name() << ": " << fj;
        }
        // in the power basis, f_j^{(k)}(0) = delta_jk: the Wronskian at 0 is the identity
        EXPECT_TRUE(same(wronskian_at_zero(*P, P->generator()), GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(n)))) << P->name();
    }
}

TEST(PolynomialAlgebra, AgreesWithStructureAlgebra) {
    const GiNaC::symbol X("X"), t("t");
    auto P = polynomial_algebra::make(GiNaC::expand(GiNaC::pow(X - 1, 2) * (X * X + 4)), X);
    auto S = structure_algebra::from(*P);
    const coeffs w{1, 2, 0, -1};
    EXPECT_TRUE(same(P->exp(w, t), S->exp(w, t)));
    EXPECT_TRUE(same(P->inverse(w), S->inverse(w)));
    EXPECT_TRUE(is_zero_scalar(P->charpoly(w, X) - S->charpoly(w, X)));
}

// Thm III.4.1, positive cases.
TEST(TheoremIII41, GeneratorsOfPolynomialAlgebras) {
    const GiNaC::symbol X("X");
    std::vector<algebra_ptr> algebras = {complex_numbers(), dual_numbers(), split_complex(),
                                         truncated_cubic(), c_r_r(),
                                         polynomial_algebra::make(GiNaC::pow(X, 4) - 1, X)};
    for (const auto& A : algebras) {
        const generator_search s = find_generator(*A);
        ASSERT_EQ(s.status, generator_search::verdict::polynomial) << A->name() << ": " << s.reason;
        EXPECT_TRUE(is_polynomial(*A));
        EXPECT_TRUE(is_generator(*A, s.generator));
        EXPECT_EQ(A->minpoly(s.generator, X).degree(X), int(A->dim())) << A->name();
        // (III.4.4): rows of M are the powers of d; M is invertible
        const GiNaC::matrix M = change_of_basis_to_power_basis(*A, s.generator);
        EXPECT_FALSE(is_zero_scalar(M.determinant()));
        coeffs pw = A->unit();
        for (unsigned k = 0; k < A->dim(); ++k) {
            for (unsigned j = 0; j < A->dim(); ++j) EXPECT_TRUE(is_zero_scalar(M(k, j) - pw[j]));
            pw = A->multiply(pw, s.generator);
        }
        // (III.4.2-4): the same matrix from the Wronskian of exp(d t) at 0
        EXPECT_TRUE(same(M, wronskian_at_zero(*A, s.generator))) << A->name();
    }
    // C x R x R needs a combination: no basis element generates it
    auto A = c_r_r();
    for (std::size_t k = 0; k < 4; ++k) EXPECT_FALSE(is_generator(*A, A->basis_vector(k)));
    EXPECT_GT(find_generator(*A).candidates, 4u);
}

// Thm III.4.1, negative cases: local algebras with dim m/m^2 = 2.
TEST(TheoremIII41, NonPolynomialAlgebras) {
    for (const auto& A : {square_zero_plane(), dual_square()}) {
        const generator_search s = find_generator(*A);
        EXPECT_EQ(s.status, generator_search::verdict::not_polynomial) << A->name();
        EXPECT_NE(s.reason.find("not polynomial"), std::string::npos) << s.reason;
        EXPECT_FALSE(is_polynomial(*A));
    }
    auto A = square_zero_plane();
    const std::string m = what_of([&] { change_of_basis_to_power_basis(*A, {0, 1, 1}); });
    EXPECT_NE(m.find("does not generate"), std::string::npos) << m;
    // a search without the structural test stays honest
    const generator_search s = find_generator(*A, 5, false);
    EXPECT_EQ(s.status, generator_search::verdict::unknown);
    EXPECT_NE(s.reason.find("after 5 candidates"), std::string::npos) << s.reason;
}

TEST(PolynomialAlgebra, NamesWithSymbolicCoefficients) {
    const GiNaC::symbol X("X");
    const GiNaC::realsymbol a("a");
    EXPECT_EQ(polynomial_algebra::make(X * X - 2 * a * X + 1, X)->name(), "polynomial(X^2 - 2*a*X + 1)");
    EXPECT_EQ(polynomial_algebra::make(X - 3, X)->name(), "polynomial(X - 3)");
    // symbolic coefficient: P_2 with v^2 = -a^2 has exp(v t) solving f'' + a^2 f = 0
    auto P = polynomial_algebra::make(X * X + a * a, X);
    const GiNaC::symbol t("t");
    const coeffs E = P->exp(P->generator(), t);
    for (const auto& f : E) EXPECT_TRUE(is_zero_scalar(f.diff(t, 2) + a * a * f)) << f;
}

TEST(TheoremIII41, Nilradical) {
    EXPECT_TRUE(nilradical(*c_r_r()).empty());       // semisimple: C x R x R
    EXPECT_TRUE(nilradical(*complex_numbers()).empty());
    const std::vector<coeffs> N = nilradical(*truncated_cubic());  // span(x, x^2)
    ASSERT_EQ(N.size(), 2u);
    for (const auto& v : N) EXPECT_TRUE(is_zero_scalar(v[0]));
    EXPECT_EQ(nilradical(*dual_square()).size(), 3u);  // span(x, y, xy)
}

// With no candidates at all, the structural test decides and the box search finds a generator.
TEST(TheoremIII41, StructuralTestThenBoxSearch) {
    auto A = c_r_r();
    const generator_search s = find_generator(*A, 0);
    ASSERT_EQ(s.status, generator_search::verdict::polynomial) << s.reason;
    EXPECT_TRUE(is_generator(*A, s.generator));
    EXPECT_NE(s.reason.find("box search"), std::string::npos) << s.reason;
}

// C x R[x,y]/(x,y)^2 x R in a dense basis: no basis element is special, and the
// structural test still proves that the algebra is not polynomial.
TEST(TheoremIII41, DenseNonPolynomial) {
    const int n = 6;
    table g = zero_table(n);
    auto e = [&](int k, int s = 1) { coeffs c(n, ex(0)); c[k] = s; return c; };
    set(g, 0, 0, e(0)); set(g, 0, 1, e(1)); set(g, 1, 1, e(0, -1));
    set(g, 2, 2, e(2)); set(g, 2, 3, e(3)); set(g, 2, 4, e(4)); set(g, 5, 5, e(5));
    auto S = structure_algebra::make(g);
    GiNaC::matrix M(n, n);  // new basis b_k = sum_l M(k, l) s_l
    for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l) M(k, l) = (k == l) ? 1 : ((k * 3 + l * 5) % 4) - 1;
    const GiNaC::matrix Mi = M.inverse();
    table h = zero_table(n);
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            coeffs va(n), vb(n);
            for (int l = 0; l < n; ++l) { va[l] = M(a, l); vb[l] = M(b, l); }
            const coeffs p = S->multiply(va, vb);
            for (int k = 0; k < n; ++k) {
                ex s = 0;
                for (int l = 0; l < n; ++l) s += p[l] * Mi(l, k);
                h[a][b][k] = GiNaC::normal(s);
            }
        }
    auto A = structure_algebra::make(h);
    const generator_search s = find_generator(*A);
    EXPECT_EQ(s.status, generator_search::verdict::not_polynomial) << s.reason;
    EXPECT_NE(s.reason.find("N/N^2 is not a cyclic"), std::string::npos) << s.reason;
    EXPECT_EQ(nilradical(*A).size(), 2u);
}

// Issue 13 (4.4): exp and log of an element whose minimal polynomial is an
// irreducible cubic (main: "degree 3 > 2 has no closed form"). Cardano's roots,
// one real and a complex pair, or three real ones (casus irreducibilis, in
// cosines), with Lagrange's interpolation. exp is checked against the
// exponential series summed exactly in the algebra: 60 terms of exp(v/2) with
// |v| <= 2 leave a tail below 1e-60, so the two agree to the 40 digits
// evaluated (tolerance 1e-30 leaves ten for rounding in evalf).
TEST(PolynomialAlgebra, ExpWithAnIrreducibleCubicMinimalPolynomial) {
    const GiNaC::symbol X("X");
    const long digits = GiNaC::Digits;
    GiNaC::Digits = 40;
    for (const ex& p : {GiNaC::pow(X, 3) - 2, GiNaC::pow(X, 3) - 3 * X + 1, GiNaC::pow(X, 3) + X + 1,
                        GiNaC::pow(X, 3) - X * X / 2 + 3 * X - ex(1) / 3}) {
        auto P = polynomial_algebra::make(p, X);
        const coeffs half{0, ex(1) / 2, 0};  // v/2, v the class of X
        const coeffs e = P->exp(half, 1);
        coeffs series{0, 0, 0}, term{1, 0, 0};
        for (int k = 0; k < 60; ++k) {
            for (int i = 0; i < 3; ++i) series[i] += term[i];
            term = P->multiply(term, half);
            for (auto& x : term) x = x / (k + 1);
        }
        for (int i = 0; i < 3; ++i) {
            const ex d = GiNaC::evalf(e[i] - series[i]);
            ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(d)) << P->name() << " " << i << ": " << e[i];
            EXPECT_LT(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(d)), GiNaC::pow(GiNaC::numeric(10), -30))
                << P->name() << " " << i << ": " << e[i];
        }
    }
    GiNaC::Digits = digits;
}

// log(v) for the cubics whose real roots are positive: the interpolating
// polynomial L = c0 + c1 X + c2 X^2 takes the principal log at every root z of p
// (II.1.12). The roots from Eigen's eigenvalues of the companion matrix (double:
// 1e-12 absolute leaves three orders for their conditioning).
TEST(PolynomialAlgebra, LogWithAnIrreducibleCubicMinimalPolynomial) {
    const GiNaC::symbol X("X");
    for (const ex& p : {GiNaC::pow(X, 3) - 2, GiNaC::pow(X, 3) - X * X / 2 + 3 * X - ex(1) / 3}) {
        auto P = polynomial_algebra::make(p, X);
        const coeffs l = P->log({0, 1, 0});
        std::array<double, 3> c{}, q{};
        for (int i = 0; i < 3; ++i) {
            c[i] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(l[i])).to_double();
            q[i] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::expand(p).coeff(X, i)).to_double();
        }
        // the roots of X^3 + q2 X^2 + q1 X + q0 (Durand-Kerner in long double)
        std::array<std::complex<long double>, 3> z{std::complex<long double>(0.4L, 0.9L)};
        for (int i = 1; i < 3; ++i) z[i] = z[i - 1] * z[0];
        for (int it = 0; it < 500; ++it)
            for (int i = 0; i < 3; ++i) {
                std::complex<long double> num = ((z[i] + (long double)q[2]) * z[i] + (long double)q[1]) * z[i] + (long double)q[0],
                                          den = 1;
                for (int j = 0; j < 3; ++j)
                    if (j != i) den *= z[i] - z[j];
                z[i] -= num / den;
            }
        for (const auto& zi : z) {
            const std::complex<long double> Lz = (long double)c[0] + ((long double)c[1] + (long double)c[2] * zi) * zi;
            EXPECT_NEAR(double(Lz.real()), double(std::log(zi).real()), 1e-12) << P->name() << " at " << double(zi.real());
            EXPECT_NEAR(double(Lz.imag()), double(std::log(zi).imag()), 1e-12) << P->name() << " at " << double(zi.real());
        }
    }
}
