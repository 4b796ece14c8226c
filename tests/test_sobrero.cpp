// Tests of the generalized Sobrero algebra S (III.2, III.4.2b): exact with
// symbolic and rational coefficients, fast paths against the general
// (product-derived) methods of the base class, and the double path.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "algebra/element.h"
#include "algebra/sobrero.h"
#include "algebra/walsh_double.h"
#include "core/error.h"

using namespace symrep;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

std::shared_ptr<const sobrero> S(unsigned n) {
    return std::static_pointer_cast<const sobrero>(sobrero::make(n));
}

/// Coordinates [a_0..a_n, b_0..b_n] from the complex coefficients xi_k = a[k] + j b[k].
coeffs xi(const std::vector<ex>& a, const std::vector<ex>& b) {
    coeffs c(a);
    c.insert(c.end(), b.begin(), b.end());
    return c;
}

/// A generic symbolic element of S(n): a_k, b_k real symbols.
coeffs symbolic(unsigned n, std::vector<GiNaC::realsymbol>& keep, const std::string& p = "") {
    coeffs c(2 * (n + 1));
    for (unsigned k = 0; k <= n; ++k) {
        keep.emplace_back(p + "a" + std::to_string(k));
        c[k] = keep.back();
    }
    for (unsigned k = 0; k <= n; ++k) {
        keep.emplace_back(p + "b" + std::to_string(k));
        c[n + 1 + k] = keep.back();
    }
    return c;
}

bool same_poly(const ex& p, const ex& q) { return GiNaC::normal(GiNaC::expand(p - q)).is_zero(); }

bool close(const coeffs& a, const coeffs& b, double tol = 1e-12) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const ex d = GiNaC::evalf(a[k] - b[k]);
        if (!GiNaC::is_a<numeric>(d) || GiNaC::abs(GiNaC::ex_to<numeric>(d)).to_double() > tol)
            return false;
    }
    return true;
}

}  // namespace

// (III.2.4) with (III.2.3): the multiplication table of the basis {eps^k, j eps^k}.
TEST(Sobrero, MultiplicationTable) {
    const unsigned n = 3;
    auto A = S(n);
    const std::size_t m = n + 1;
    for (std::size_t k = 0; k < m; ++k)
        for (std::size_t p = 0; p < m; ++p) {
            coeffs e = A->zero(), je = A->zero(), mine = A->zero();
            if (k + p < m) {
                e[k + p] = 1;
                je[m + k + p] = 1;
                mine[k + p] = -1;
            }
            EXPECT_TRUE(algebra::equal(A->multiply(A->basis_vector(k), A->basis_vector(p)), e));
            EXPECT_TRUE(algebra::equal(A->multiply(A->basis_vector(k), A->basis_vector(m + p)), je));
            EXPECT_TRUE(algebra::equal(A->multiply(A->basis_vector(m + k), A->basis_vector(m + p)), mine));
        }
    EXPECT_EQ(A->name(), "sobrero(3)");
    EXPECT_EQ(A->dim(), 8u);
    EXPECT_EQ(A->basis_name(0), "1");
    EXPECT_EQ(A->basis_name(2), "eps^2");
    EXPECT_EQ(A->basis_name(4), "j");
    EXPECT_EQ(A->basis_name(5), "j*eps");
    EXPECT_TRUE(algebra::equal(A->multiply(A->j(), A->j()), algebra::scale(-1, A->unit())));
    EXPECT_TRUE(algebra::equal(A->power(A->eps(), n + 1), A->zero()));  // (III.2.3)
    EXPECT_FALSE(algebra::equal(A->power(A->eps(), n), A->zero()));
}

// (III.2.8) eps^k w = xi_0 eps^k + ... + xi_{n-k} eps^n, which is row k of the matrix (III.2.9).
TEST(Sobrero, ShiftRowsOfCanonicalMatrix) {
    const unsigned n = 3;
    auto A = S(n);
    std::vector<GiNaC::realsymbol> s;
    const coeffs w = symbolic(n, s);
    const GiNaC::matrix M = A->canonical_matrix(w);
    for (unsigned k = 0; k <= n; ++k) {
        for (unsigned l = 0; l <= n; ++l) {
            const ex a = l >= k ? w[l - k] : ex(0), b = l >= k ? w[n + 1 + l - k] : ex(0);
            EXPECT_TRUE(same_poly(M(k, l), a));
            EXPECT_TRUE(same_poly(M(k, n + 1 + l), b));
        }
    }
}

// (III.2.10-12) charpoly = (X^2 - 2 a_0 X + a_0^2 + b_0^2)^{n+1}, equal to the general
// det(X I - [w]); p(w) = 0.
TEST(Sobrero, CharpolySymbolicMatchesGeneral) {
    GiNaC::symbol X("X");
    for (unsigned n : {1u, 2u}) {
        auto A = S(n);
        std::vector<GiNaC::realsymbol> s;
        const coeffs w = symbolic(n, s);
        const ex p = A->charpoly(w, X);
        EXPECT_TRUE(same_poly(p, A->algebra::charpoly(w, X))) << n;
        EXPECT_TRUE(same_poly(p, GiNaC::pow(X * X - 2 * w[0] * X + w[0] * w[0] + w[n + 1] * w[n + 1], n + 1)));
        EXPECT_TRUE(algebra::equal(A->evaluate_polynomial(p, X, w), A->zero())) << n;
        EXPECT_TRUE(same_poly(A->determinant(w), A->algebra::determinant(w)));
    }
}

TEST(Sobrero, CharpolyRationalN4) {
    GiNaC::symbol X("X");
    auto A = S(4);
    const coeffs w = xi({numeric(1, 2), 3, -1, 0, 2}, {-2, 1, 0, numeric(5, 3), 1});
    EXPECT_TRUE(same_poly(A->charpoly(w, X), A->algebra::charpoly(w, X)));
    EXPECT_TRUE(algebra::equal(A->evaluate_polynomial(A->charpoly(w, X), X, w), A->zero()));
    EXPECT_TRUE(same_poly(A->determinant(w), A->algebra::determinant(w)));
}

// Minimal polynomial: ((X - xi_0)(X - conj xi_0))^m or (X - a_0)^m, m = 1 + floor(n/k_0).
TEST(Sobrero, MinpolyMatchesGeneral) {
    GiNaC::symbol X("X");
    auto A = S(4);
    const std::vector<coeffs> cases = {
        xi({1, 2, 0, 0, 0}, {3, 0, 0, 0, 0}),    // b_0 != 0, k_0 = 1: m = 5
        xi({1, 0, 2, 0, 0}, {3, 0, 0, 0, 0}),    // k_0 = 2: m = 3
        xi({1, 0, 0, 0, 1}, {3, 0, 0, 0, 0}),    // k_0 = 4: m = 2
        xi({2, 0, 0, 0, 0}, {3, 0, 0, 0, 0}),    // N = 0: m = 1
        xi({2, 0, 0, 0, 0}, {0, 0, 0, 0, 0}),    // real scalar: X - 2
        xi({2, 0, 1, 0, 0}, {0, 0, 0, 0, 0}),    // real root, k_0 = 2: (X - 2)^3
        xi({-1, 0, 0, 1, 0}, {0, 0, 0, 5, 0}),   // real root, k_0 = 3: (X + 1)^2
        xi({0, 1, 0, 0, 0}, {0, 1, 0, 0, 0}),    // nilpotent: X^5
        xi({0, 0, 0, 1, 0}, {0, 0, 0, 0, 0}),    // nilpotent eps^3: X^2
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const ex p = A->minpoly(cases[i], X);
        EXPECT_TRUE(same_poly(p, A->algebra::minpoly(cases[i], X))) << i << ": " << p;
        EXPECT_TRUE(algebra::equal(A->evaluate_polynomial(p, X, cases[i]), A->zero())) << i;
    }
    EXPECT_TRUE(same_poly(A->minpoly(cases[5], X), GiNaC::pow(X - 2, 3)));
    EXPECT_TRUE(same_poly(A->minpoly(cases[7], X), GiNaC::pow(X, 5)));
}

// (III.2.13-15) zero divisors: a_0 = b_0 = 0, they are nilpotent, w^{n+1} = 0.
TEST(Sobrero, ZeroDivisorsAreNilpotent) {
    for (unsigned n : {1u, 2u, 3u, 4u}) {
        auto A = S(n);
        std::vector<GiNaC::realsymbol> s;
        coeffs w = symbolic(n, s);
        EXPECT_FALSE(A->is_zero_divisor(w));
        w[0] = 0;
        w[n + 1] = 0;  // (III.2.14)
        EXPECT_TRUE(A->is_zero_divisor(w));
        EXPECT_TRUE(algebra::equal(A->power(w, n + 1), A->zero())) << n;  // (III.2.15)
        EXPECT_FALSE(algebra::equal(A->power(w, n), A->zero())) << n;
        if (n <= 2) {
            EXPECT_TRUE(A->algebra::is_zero_divisor(w));
        }
    }
}

// Inverse: nilpotent series, against w w^{-1} = 1 and the general linear solve.
TEST(Sobrero, Inverse) {
    {
        auto A = S(2);
        std::vector<GiNaC::realsymbol> s;
        const coeffs w = symbolic(2, s);
        EXPECT_TRUE(algebra::equal(A->multiply(w, A->inverse(w)), A->unit()));
    }
    auto A = S(4);
    const coeffs w = xi({numeric(1, 2), 3, -1, 0, 2}, {-2, 1, 0, numeric(5, 3), 1});
    EXPECT_TRUE(algebra::equal(A->inverse(w), A->algebra::inverse(w)));
    const coeffs nil = xi({0, 1, 0, 0, 0}, {0, 0, 2, 0, 0});
    try {
        A->inverse(nil);
        FAIL() << "no throw";
    } catch (const zero_divisor_error& e) {
        EXPECT_NE(std::string(e.what()).find("a_0 = b_0 = 0"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("sobrero(4)"), std::string::npos);
        EXPECT_EQ(e.ranks, (std::vector<std::size_t>{0}));
    }
    EXPECT_EQ(A->zero_divisor_ranks(nil), (std::vector<std::size_t>{0}));
    EXPECT_TRUE(A->zero_divisor_ranks(w).empty());
    EXPECT_THROW(A->log(nil), zero_divisor_error);
}

// exp(w t) = e^{xi_0 t} sum N^k t^k / k!: solves d/dt E = w E, E(0) = 1 (symbolic).
TEST(Sobrero, ExpSolvesItsDifferentialEquation) {
    GiNaC::realsymbol t("t");
    for (unsigned n : {1u, 2u, 3u}) {
        auto A = S(n);
        std::vector<GiNaC::realsymbol> s;
        const coeffs w = symbolic(n, s);
        const coeffs E = A->exp(w, t);
        coeffs dE(E.size());
        for (std::size_t k = 0; k < E.size(); ++k) dE[k] = E[k].diff(t);
        EXPECT_TRUE(algebra::equal(dE, A->multiply(w, E))) << n;
        coeffs E0(E.size());
        for (std::size_t k = 0; k < E.size(); ++k) E0[k] = E[k].subs(t == 0);
        EXPECT_TRUE(algebra::equal(E0, A->unit()));
    }
    // the generating element: exp(d t) has the closed form e^{j t} sum eps^k t^k / k!
    auto A = S(2);
    const coeffs E = A->exp(A->generating_element({}), t);
    EXPECT_TRUE(same_poly(E[2], GiNaC::cos(t) * t * t / 2));
    EXPECT_TRUE(same_poly(E[3 + 1], GiNaC::sin(t) * t));
}

// log: exp(log w) = w exactly where the angles are exact; log(exp N) = N symbolically.
TEST(Sobrero, LogInvertsExp) {
    auto A = S(3);
    const std::vector<coeffs> cases = {
        xi({2, 1, numeric(-1, 3), 4}, {0, 2, 0, 1}),  // xi_0 = 2
        xi({-1, 1, 0, 2}, {0, 0, 3, 0}),              // xi_0 = -1: log = j pi + ...
        xi({0, 1, 2, 3}, {1, 0, 0, -1}),              // xi_0 = j
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const coeffs L = A->log(cases[i]);
        EXPECT_TRUE(algebra::equal(A->exp(L, 1), cases[i])) << i;
    }
    const coeffs w = xi({3, 1, 0, 2}, {4, 0, -1, 0});  // xi_0 = 3 + 4j: exact angle atan2(4, 3)
    EXPECT_TRUE(close(A->exp(A->log(w), 1), w));
    std::vector<GiNaC::realsymbol> s;
    coeffs N = symbolic(3, s);
    N[0] = 0;
    N[4] = 0;
    EXPECT_TRUE(algebra::equal(A->log(A->exp(N, 1)), N));
}

// (III.2.16-18, 21-22) semiexponential form; phi_k in [0, 2 pi).
TEST(Sobrero, Semiexponential) {
    auto A = S(2);
    const coeffs w = xi({3, 1, 0}, {4, -1, 0});
    const auto [rho, theta] = A->semiexponential(w);
    EXPECT_TRUE(same_poly(rho[0], 5));
    EXPECT_TRUE(same_poly(rho[1], GiNaC::sqrt(ex(2))));
    EXPECT_TRUE(same_poly(rho[2], 0));
    EXPECT_TRUE(same_poly(theta[3 + 1], 7 * GiNaC::Pi / 4));  // 1 - j
    EXPECT_TRUE(same_poly(theta[3 + 2], 0));
    for (std::size_t k = 0; k < 3; ++k) {  // (III.2.17) a_k = A_k cos phi_k, b_k = A_k sin phi_k
        EXPECT_TRUE(close({rho[k] * GiNaC::cos(theta[3 + k])}, {w[k]}));
        EXPECT_TRUE(close({rho[k] * GiNaC::sin(theta[3 + k])}, {w[3 + k]}));
        const double phi = GiNaC::ex_to<numeric>(GiNaC::evalf(theta[3 + k])).to_double();
        EXPECT_GE(phi, 0.0);
        EXPECT_LT(phi, 2 * M_PI);
    }
    // (III.2.22) the charpoly in terms of A_0, phi_0
    GiNaC::symbol X("X");
    const ex p22 = GiNaC::pow(X * X - 2 * X * rho[0] * GiNaC::cos(theta[3]) + rho[0] * rho[0], 3);
    for (const ex& x0 : {ex(numeric(13, 10)), ex(-2), ex(7)})
        EXPECT_TRUE(close({p22.subs(X == x0)}, {A->charpoly(w, X).subs(X == x0)}, 1e-6));
    // (III.2.21) zero divisor iff A_0 = 0
    const coeffs z = xi({0, 1, 0}, {0, 1, 1});
    EXPECT_TRUE(same_poly(A->semiexponential(z).first[0], 0));
    EXPECT_TRUE(A->is_zero_divisor(z));
}

// Corrected (III.2.20): all xi_k on one ray (strict) or one line through 0.
TEST(Sobrero, SpecialTypeCorrectedTest) {
    auto A = S(2);
    EXPECT_TRUE(A->is_special_type(xi({1, 2, 0}, {1, 2, 0})));          // one ray
    EXPECT_FALSE(A->is_special_type(xi({1, -2, 0}, {1, -2, 0})));       // opposite rays
    EXPECT_TRUE(A->is_special_type(xi({1, -2, 0}, {1, -2, 0}), false));  // but one line
    EXPECT_FALSE(A->is_special_type(xi({1, 0, 0}, {0, 1, 0}), false));  // 1 and j
    // Real elements (b = 0) are special type (phi_k = 0), though the printed (III.2.20)
    // a_k = c b_k fails for them: that printed test is wrong.
    const coeffs real = xi({1, 2, 3}, {0, 0, 0});
    EXPECT_TRUE(A->is_special_type(real));
    // symbolic: x_k = s_k^2 >= 0 on the ray of 3 + 4 j
    GiNaC::realsymbol s0("s0"), s1("s1"), s2("s2");
    EXPECT_TRUE(A->is_special_type(
        xi({3 * s0 * s0, 3 * s1 * s1, 3 * s2 * s2}, {4 * s0 * s0, 4 * s1 * s1, 4 * s2 * s2})));
    GiNaC::realsymbol x("x"), y("y");
    EXPECT_TRUE(A->is_special_type(xi({x, y, 0}, {x, y, 0}), false));
    try {
        A->is_special_type(xi({x, y, 0}, {x, y, 0}), true);
        FAIL() << "sign of x y decided";
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot decide"), std::string::npos);
    }
}

// FORMULAS.md: xi = (1, j, -1 - j) is not a sum of two strict special-type elements.
// A sum x e^{j alpha} + y e^{j beta} with x_k, y_k >= 0 puts every xi_k in the cone
// spanned by two rays (an arc of at most pi, or a line); the arguments 0, pi/2, 5pi/4
// of xi_k need an arc of 5pi/4 > pi and are not collinear.
TEST(Sobrero, CounterexampleToStrictTheorem) {
    auto A = S(2);
    const coeffs w = xi({1, 0, -1}, {0, 1, -1});
    EXPECT_FALSE(A->is_special_type(w));
    EXPECT_FALSE(A->is_special_type(w, false));
    std::vector<double> ang = {0.0, M_PI / 2, 5 * M_PI / 4};
    double max_gap = 2 * M_PI - (ang[2] - ang[0]);
    for (std::size_t i = 1; i < ang.size(); ++i) max_gap = std::max(max_gap, ang[i] - ang[i - 1]);
    EXPECT_GT(2 * M_PI - max_gap, M_PI);  // smallest arc holding all xi_k
    const auto parts = A->special_type_decomposition(w);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_TRUE(algebra::equal(algebra::add(parts[0], parts[1]), w));  // (III.2.24)
    EXPECT_FALSE(A->is_special_type(parts[0]));        // (1, 0, -1): real of both signs
    EXPECT_TRUE(A->is_special_type(parts[0], false));  // special type in the corrected sense
    EXPECT_TRUE(A->is_special_type(parts[1], false));
}

// Thm III.2.2.1 first part as corrected: the two parts of (III.2.24) are special type with
// real coefficients of either sign, for a symbolic element.
TEST(Sobrero, DecompositionIntoTwoSpecialType) {
    auto A = S(3);
    std::vector<GiNaC::realsymbol> s;
    const coeffs w = symbolic(3, s);
    const auto parts = A->special_type_decomposition(w);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_TRUE(algebra::equal(algebra::add(parts[0], parts[1]), w));
    EXPECT_TRUE(A->is_special_type(parts[0], false));
    EXPECT_TRUE(A->is_special_type(parts[1], false));
}

// Thm III.2.2.1 second part, (III.2.27-29): (sum x eps^k) e^{j alpha} (sum y eps^k) e^{j beta}
// = (sum zeta_k eps^k) e^{j(alpha + beta)}, zeta the Cauchy product.
TEST(Sobrero, ProductOfSpecialType) {
    const unsigned n = 3;
    auto A = S(n);
    std::vector<GiNaC::realsymbol> xs, ys;
    for (unsigned k = 0; k <= n; ++k) {
        xs.emplace_back("x" + std::to_string(k));
        ys.emplace_back("y" + std::to_string(k));
    }
    GiNaC::realsymbol al("alpha"), be("beta");
    auto special = [&](const std::vector<GiNaC::realsymbol>& v, const ex& c, const ex& s) {
        coeffs w = A->zero();
        for (unsigned k = 0; k <= n; ++k) {
            w[k] = v[k] * c;
            w[n + 1 + k] = v[k] * s;
        }
        return w;
    };
    const coeffs w1 = special(xs, GiNaC::cos(al), GiNaC::sin(al));
    const coeffs w2 = special(ys, GiNaC::cos(be), GiNaC::sin(be));
    const coeffs prod = A->multiply(w1, w2);
    const ex cg = GiNaC::cos(al) * GiNaC::cos(be) - GiNaC::sin(al) * GiNaC::sin(be);  // cos(alpha+beta)
    const ex sg = GiNaC::sin(al) * GiNaC::cos(be) + GiNaC::cos(al) * GiNaC::sin(be);
    for (unsigned k = 0; k <= n; ++k) {
        ex zeta = 0;
        for (unsigned l = 0; l <= k; ++l) zeta += xs[l] * ys[k - l];  // (III.2.29)
        EXPECT_TRUE(same_poly(prod[k], zeta * cg)) << k;
        EXPECT_TRUE(same_poly(prod[n + 1 + k], zeta * sg)) << k;
    }
    // strict test on rational points of the unit circle: the product stays special type
    const coeffs u = xi({numeric(3, 5), numeric(6, 5), 0, numeric(9, 5)},
                        {numeric(4, 5), numeric(8, 5), 0, numeric(12, 5)});
    const coeffs v = xi({numeric(10, 13), 0, numeric(5, 13), numeric(15, 13)},
                        {numeric(24, 13), 0, numeric(12, 13), numeric(36, 13)});
    ASSERT_TRUE(A->is_special_type(u));
    ASSERT_TRUE(A->is_special_type(v));
    EXPECT_TRUE(A->is_special_type(A->multiply(u, v)));
}

// (III.4.10-14) the generating element alpha j + beta eps: charpoly (X^2 + alpha^2)^{n+1} is minimal.
TEST(Sobrero, GeneratingElement) {
    GiNaC::symbol X("X");
    for (unsigned n = 1; n <= 4; ++n) {
        auto A = S(n);
        const coeffs d = A->generating_element({});
        const ex p = A->charpoly(d, X);
        EXPECT_TRUE(same_poly(p, GiNaC::pow(X * X + 1, n + 1)));
        EXPECT_TRUE(same_poly(A->minpoly(d, X), p));
        EXPECT_TRUE(same_poly(A->algebra::minpoly(d, X), p)) << n;  // minimal by the general method
    }
    auto A = S(3);
    const coeffs d = A->generating_element({2, -3});
    EXPECT_TRUE(same_poly(A->algebra::minpoly(d, X), GiNaC::pow(X * X + 4, 4)));
    const coeffs d0 = A->generating_element({2, 0});  // beta = 0: not generating
    EXPECT_TRUE(same_poly(A->minpoly(d0, X), X * X + 4));
    EXPECT_TRUE(same_poly(A->algebra::minpoly(d0, X), X * X + 4));
    EXPECT_THROW(A->generating_element({1}), type_error);
}

TEST(Sobrero, BadSizes) {
    EXPECT_THROW(sobrero::make(-1), domain_error);
    try {
        sobrero::make(100000);
        FAIL();
    } catch (const size_error& e) {
        EXPECT_NE(std::string(e.what()).find("512"), std::string::npos);
    }
    auto A = S(2);
    EXPECT_THROW(A->multiply(A->unit(), coeffs(3, ex(0))), algebra_error);
    EXPECT_THROW(sobrero_d(5000), size_error);
}

// Double path: random elements up to n = 12 (fixed seed). Tolerance 1e-9: the series have
// at most 13 terms with coefficients O(1) and |xi_0| >= 1/2, so rounding stays far below.
TEST(SobreroDouble, RandomIdentities) {
    std::mt19937 gen(1995);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (unsigned n : {1u, 4u, 8u, 12u}) {
        sobrero_d A(n);
        std::vector<double> w(A.dim());
        for (auto& x : w) x = U(gen);
        w[0] = 1.5;  // |xi_0| >= 1/2
        const auto one = A.multiply(w, A.inverse(w));
        const auto back = A.exp(A.log(w));
        const auto e = A.multiply(A.exp(w, 0.7), A.exp(w, -0.7));
        for (std::size_t k = 0; k < w.size(); ++k) {
            EXPECT_NEAR(one[k], k == 0 ? 1.0 : 0.0, 1e-9) << n;
            EXPECT_NEAR(back[k], w[k], 1e-9) << n;
            EXPECT_NEAR(e[k], k == 0 ? 1.0 : 0.0, 1e-9) << n;
        }
    }
    sobrero_d A(3);
    EXPECT_THROW(A.inverse({0, 1, 0, 0, 0, 2, 0, 0}), zero_divisor_error);
}

// Double vs exact on a small rational element (tolerance 1e-12: a handful of operations).
TEST(SobreroDouble, MatchesExact) {
    auto A = S(3);
    sobrero_d D(3);
    const coeffs w = xi({2, 1, numeric(-1, 3), 4}, {1, 2, 0, 1});
    std::vector<double> wd;
    for (const auto& x : w) wd.push_back(GiNaC::ex_to<numeric>(x).to_double());
    const auto check = [](const coeffs& e, const std::vector<double>& d) {
        for (std::size_t k = 0; k < d.size(); ++k)
            EXPECT_NEAR(GiNaC::ex_to<numeric>(GiNaC::evalf(e[k])).to_double(), d[k], 1e-12) << k;
    };
    check(A->inverse(w), D.inverse(wd));
    check(A->exp(w, numeric(1, 2)), D.exp(wd, 0.5));
    check(A->log(w), D.log(wd));
    check(A->multiply(w, w), D.multiply(wd, wd));
}

// n = 3 with symbolic coefficients: fast charpoly and determinant against det(X I - [w]) of
// the 8 x 8 canonical matrix; and the element API dispatches to the overrides.
TEST(Sobrero, SymbolicN3AndElementApi) {
    GiNaC::symbol X("X");
    auto A = S(3);
    std::vector<GiNaC::realsymbol> s;
    const coeffs w = symbolic(3, s);
    EXPECT_TRUE(same_poly(A->charpoly(w, X), A->algebra::charpoly(w, X)));
    EXPECT_TRUE(same_poly(A->determinant(w), A->algebra::determinant(w)));
    const element e(A, w);
    EXPECT_TRUE(e * e.inverse() == element::one(A));
    EXPECT_TRUE(e.exp(0) == element::one(A));
    const element g(A, A->generating_element({}));
    EXPECT_TRUE(same_poly(g.minpoly(X), GiNaC::pow(X * X + 1, 4)));
    EXPECT_TRUE(close(g.exp(1).log().coefficients(), g.coefficients()));  // principal log inverts exp
}
