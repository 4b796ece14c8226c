// Tests of signals/representation.h (thesis II.1-II.3): Psi and Psi^-1, the least
// equation of a quasi-polynomial, discrete signals, sampling and aliasing. All exact:
// every identity is checked by the exact zero test (no tolerance).
#include <gtest/gtest.h>

#include "test_util.h"

#include "algebra/polynomial_algebra.h"
#include "algebra/structure_algebra.h"
#include "core/error.h"
#include "scalar/scalar.h"
#include "signals/product.h"
#include "signals/representation.h"

using namespace symrep;
using namespace symrep::signals;
using GiNaC::ex;

namespace {

const GiNaC::symbol t("t"), X("X"), l("l"), h("h"), k("k");
const GiNaC::possymbol w("w");  // positive: sqrt(w^2) = w

using symrep::test::same;

// a reference value parsed with 50 digits (a numeric read from a string has the current Digits)
GiNaC::numeric ref(const char* text) {
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 50;
    const GiNaC::numeric x(text);
    GiNaC::Digits = saved;
    return x;
}

}  // namespace

// P_3, p = (X + 1)(X + 2)(X + 3): Psi^-1(v^j) = g^(j), g the impulse response
// (g(0) = g'(0) = 0, g''(0) = 1), and Psi^-1(v w) = Psi^-1(w)' for every w.
TEST(Signals, PolynomialAlgebraImpulseResponseAndDerivative) {
    const auto R = polynomial_representation(GiNaC::pow(X, 3) + 6 * GiNaC::pow(X, 2) + 11 * X + 6, X);
    const ex g = (GiNaC::exp(-t) - 2 * GiNaC::exp(-2 * t) + GiNaC::exp(-3 * t)) / 2;
    for (int j = 0; j < 3; ++j)
        EXPECT_TRUE(same(signal_of(R, R.A->basis_vector(std::size_t(j)), t), g.diff(t, j))) << j;
    const coeffs u{ex(3), ex(-1) / 2, ex(7)};
    const ex f = signal_of(R, u, t);
    EXPECT_TRUE(same(signal_of(R, R.A->multiply(R.d, u), t), f.diff(t)));
    // Psi(Psi^-1(u)) = u
    const coeffs back = element_of(R, f, t);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(same(back[i], u[i])) << i;
}

// On P_n every generator d works with the same lambda (the coordinate of v^(n-1)):
// d = v^2 + v on P_3, p = (X + 1)(X + 2)(X + 3) (d has the distinct eigenvalues 0, 2, 6),
// Psi^-1(d w) = Psi^-1(w)'.
TEST(Signals, PolynomialAlgebraOtherOperator) {
    const auto P = polynomial_algebra::make(GiNaC::pow(X, 3) + 6 * GiNaC::pow(X, 2) + 11 * X + 6, X);
    const coeffs v = P->generator();
    const coeffs d = P->add(P->multiply(v, v), v);
    const auto R = represent_on(P, d);
    EXPECT_EQ(R.lambda, (coeffs{ex(0), ex(0), ex(1)}));
    const coeffs u{ex(1), ex(-2), ex(3)};
    const ex f = signal_of(R, u, t);
    EXPECT_TRUE(same(signal_of(R, P->multiply(d, u), t), f.diff(t)));
    const coeffs back = element_of(R, f, t);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(same(back[i], u[i])) << i;
}

// The printed Psi(f_k) = e_k of Thm II.2.3 fails Psi(f') = d Psi(f) for a non-symmetric
// [d]; the derived map holds it on a general algebra too (C as a structure-constant
// algebra with d = i w: cos' = -w sin).
TEST(Signals, GeneralAlgebraOperator) {
    std::vector<std::vector<coeffs>> gamma{{{1, 0}, {0, 1}}, {{0, 1}, {-1, 0}}};
    const auto C = structure_algebra::make(gamma);
    const auto R = represent_on(C, coeffs{ex(0), ex(w)});
    const coeffs a = element_of(R, GiNaC::cos(w * t), t);
    const coeffs da = C->multiply(R.d, a);
    EXPECT_TRUE(same(signal_of(R, da, t), -w * GiNaC::sin(w * t)));
    // d = 1 does not generate C: refused by name
    EXPECT_THROW(represent_on(C, coeffs{ex(1), ex(0)}), algebra_error);
    // a signal outside the solution space is refused, with the residual seen nonzero
    try {
        element_of(R, GiNaC::exp(-t), t);
        FAIL() << "exp(-t) is not a solution of f'' + w^2 f = 0";
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("not a solution"), std::string::npos) << e.what();
    }
}

TEST(Signals, LeastEquationOfAQuasiPolynomial) {
    EXPECT_TRUE(same(annihilator(t * GiNaC::exp(-t), t, X), GiNaC::pow(X + 1, 2)));
    EXPECT_TRUE(same(annihilator(GiNaC::cos(2 * t) + 3, t, X), X * (X * X + 4)));
    EXPECT_TRUE(same(annihilator(t * GiNaC::exp(-t) * GiNaC::sin(2 * t), t, X),
                     GiNaC::pow(GiNaC::pow(X + 1, 2) + 4, 2)));
    // products of signals: cos t cos 2t = (cos t + cos 3t)/2
    EXPECT_TRUE(same(annihilator(GiNaC::cos(t) * GiNaC::cos(2 * t), t, X), (X * X + 1) * (X * X + 9)));
    EXPECT_TRUE(same(annihilator(GiNaC::cosh(w * t), t, X), X * X - w * w));
    // cos^2 + sin^2 - 1 = 0 and parts of no quasi-polynomial are refused
    EXPECT_THROW(annihilator(GiNaC::pow(GiNaC::cos(t), 2) + GiNaC::pow(GiNaC::sin(t), 2) - 1, t, X), domain_error);
    EXPECT_THROW(annihilator(GiNaC::log(1 + t), t, X), domain_error);
    EXPECT_THROW(annihilator(GiNaC::exp(t * t), t, X), domain_error);
    // the least equation represents the signal, and back
    const ex f = t * t * GiNaC::exp(2 * t) - GiNaC::sin(t);
    const auto R = polynomial_representation(annihilator(f, t, X), X);
    EXPECT_EQ(R.A->dim(), 5u);
    EXPECT_TRUE(same(signal_of(R, element_of(R, f, t), t), f));
}

// Thm II.3.3: with the shift as multiplication by v in P_2, p = X^2 - X - 1, the
// sequence of v is Fibonacci's; negative k through v^-1.
TEST(Signals, DiscreteSignals) {
    const auto R = polynomial_representation(X * X - X - 1, X);
    const auto s = sequence_of(R, R.d, -3, 8);
    const std::vector<int> expected{-1, 1, 0, 1, 1, 2, 3, 5};  // F(k+1), k = -3..4
    ASSERT_EQ(s.size(), expected.size());
    for (std::size_t i = 0; i < s.size(); ++i) EXPECT_TRUE(same(s[i], expected[i])) << i;
}

// Thm II.3.4, Cor. II.3.5: the samples f(k h) are the discrete signal of the same w
// with the shift exp(h d); q(l) = prod (l - e^(h r)); aliasing decided from the roots.
TEST(Signals, SamplingAndAliasing) {
    const auto R = polynomial_representation(GiNaC::pow(X, 3) + 6 * GiNaC::pow(X, 2) + 11 * X + 6, X);
    const sampling s = sample(R, h, l);
    EXPECT_TRUE(same(s.q, (l - GiNaC::exp(-h)) * (l - GiNaC::exp(-2 * h)) * (l - GiNaC::exp(-3 * h))));
    EXPECT_EQ(s.aliasing, truth::no);
    // the samples of Psi^-1(w) at k h are lambda(w exp(h d)^k)
    const coeffs u{ex(1), ex(2), ex(-1)};
    const ex f = signal_of(R, u, t);
    representation Rh = R;
    Rh.d = s.shift;
    const auto seq = sequence_of(Rh, u, 0, 4);
    for (int j = 0; j < 4; ++j) EXPECT_TRUE(same(seq[std::size_t(j)], f.subs(t == j * h))) << j;

    // q from the factors of p equals det(l I - exp(h [d])) (a complex pair, a repeated
    // real root, real roots of a quadratic): compared at l = 7/10, 2 and 5 with 30 digits
    // (the determinant needs cos^2 + sin^2 = 1 to be seen equal), tolerance 1e-25
    for (const ex& p : {ex(GiNaC::pow(X + 1, 2) * (X * X + 2 * X + 5)), ex(X * X - 3 * X + 1)}) {
        const auto Rp = polynomial_representation(p.expand(), X);
        const sampling sp = sample(Rp, ex(1) / 3, l);
        const ex det = Rp.A->charpoly(sp.shift, l);
        for (const GiNaC::numeric& at : {GiNaC::numeric(7, 10), GiNaC::numeric(2), GiNaC::numeric(5)}) {
            GiNaC::numeric v;
            ASSERT_TRUE(evaluate_numeric((sp.q - det).subs(l == at), 30, v));
            EXPECT_LT(GiNaC::abs(v), GiNaC::numeric("1e-25")) << p << " at l = " << at;
        }
    }

    // x'' + pi^2 x = 0 at step 1: e^(i pi) = e^(-i pi) = -1, q = (l + 1)^2, aliasing
    const auto P = polynomial_representation(X * X + GiNaC::pow(GiNaC::Pi, 2), X);
    const sampling a = sample(P, 1, l);
    EXPECT_TRUE(same(a.q, GiNaC::pow(l + 1, 2)));
    EXPECT_EQ(a.aliasing, truth::yes) << a.report;
    EXPECT_EQ(sample(P, ex(1) / 2, l).aliasing, truth::no);
    // a symbolic step: generically no aliasing, and the report states when
    const sampling g = sample(polynomial_representation(X * X + w * w, X), h, l);
    EXPECT_EQ(g.aliasing, truth::no);
    EXPECT_NE(g.report.find("nonzero integer"), std::string::npos) << g.report;
    // a cubic factor: its roots by Cardano (2^(1/3) and a pair whose imaginary parts differ by
    // 3^(1/2) 2^(1/3), not a multiple of 2 pi): decided
    EXPECT_EQ(sample(polynomial_representation(GiNaC::pow(X, 3) - 2, X), 1, l).aliasing, truth::no);
    EXPECT_THROW(sample(R, 0, l), domain_error);
}

// q(l) of a cubic p from Cardano's roots, exactly (the characteristic polynomial of the
// radical matrix exp(h [d]) was refused by the size guard). Against mpmath's prod (l - e^(h r))
// over mp.polyroots at 50 digits, printed to 30: coefficients to 1e-25 at 40 digits.
TEST(Signals, SamplingACubicByItsRoots) {
    const auto R = polynomial_representation(GiNaC::pow(X, 3) - 2 * X * X - ex(8) / 3 * X + 2, X);
    const sampling sp = sample(R, ex(3) / 4, l);
    EXPECT_FALSE(sp.numeric);
    const char* expected[] = {"-4.48168907033806482260205546012", "15.2523201452284160752138871989",
                              "-9.56068692569413049076488665575"};
    const ex q = sp.q.expand();
    for (int k = 0; k < 3; ++k) {
        GiNaC::numeric v;
        ASSERT_TRUE(evaluate_numeric(q.coeff(l, k), 40, v)) << q;
        EXPECT_LT(GiNaC::abs(v - ref(expected[k])), GiNaC::numeric("1e-25")) << k;
    }
    EXPECT_TRUE(is_zero_scalar(q.coeff(l, 3) - 1));
    EXPECT_EQ(sp.aliasing, truth::no) << sp.report;
}

// A quintic without roots in radicals: q(l) numeric, marked as such, with its error bound.
// Against mpmath (as above): X^5 - X - 1 at step 1/2.
TEST(Signals, SamplingANumericQuintic) {
    const auto R = polynomial_representation(GiNaC::pow(X, 5) - X - 1, X);
    const sampling sp = sample(R, ex(1) / 2, l);
    EXPECT_TRUE(sp.numeric);
    EXPECT_NE(sp.report.find("numeric"), std::string::npos) << sp.report;
    EXPECT_NE(sp.report.find("degree 5"), std::string::npos) << sp.report;
    GiNaC::numeric bound;
    ASSERT_TRUE(evaluate_numeric(sp.error_bound, 20, bound));
    EXPECT_GT(bound, 0);
    EXPECT_LT(bound, GiNaC::numeric("1e-25"));
    const char* expected[] = {"-1.0", "5.00911492376490054007490396266", "-9.98307826521821899334175845106",
                              "9.95443524137261029568555638795", "-5.01171918731327752411966978102"};
    for (int k = 0; k < 5; ++k) {
        GiNaC::numeric v;
        ASSERT_TRUE(evaluate_numeric(sp.q.coeff(l, k), 40, v));
        // the reference's 30 printed digits, and the bound claimed
        EXPECT_LT(GiNaC::abs(v - ref(expected[k])), GiNaC::numeric("1e-28") + bound) << k;
    }
    EXPECT_EQ(sp.aliasing, truth::no) << sp.report;
    // the shift's samples agree with the signal's: f(k h) = lambda(w exp(h d)^k), the impulse
    // response at t = 1 against mpmath's residue sum at 40 digits
    representation Rh = R;
    Rh.d = sp.shift;
    const coeffs u{ex(1), ex(0), ex(0), ex(0), ex(0)};
    const auto seq = sequence_of(Rh, u, 0, 3);
    GiNaC::numeric v;
    ASSERT_TRUE(evaluate_numeric(seq[2], 30, v));
    EXPECT_LT(GiNaC::abs(v - ref("0.0416942264062746801150422530196")), GiNaC::numeric("1e-25"));
    // a symbolic step: the numeric form is refused
    EXPECT_THROW(sample(R, h, l), domain_error);
}

// Products of signals (signals/product.h): Psi(f g) = Psi(f) (x) Psi(g) on A (x) B with
// d = d_A (x) 1 + 1 (x) d_B and lambda_A (x) lambda_B; the derivative is the product by d
// (Leibniz), also where d does not generate A (x) B (cos t cos t).
TEST(Signals, ProductsOnTheTensorProduct) {
    const std::vector<std::pair<ex, ex>> pairs{{t * GiNaC::exp(-t), GiNaC::sin(2 * t)},
                                               {GiNaC::cos(t), GiNaC::cos(t)},
                                               {GiNaC::exp(-2 * t) + 1, t * t}};
    for (const auto& [f, g] : pairs) {
        const auto RA = polynomial_representation(annihilator(f, t, X), X);
        const auto RB = polynomial_representation(annihilator(g, t, X), X);
        const auto R = product_representation(RA, RB);
        EXPECT_EQ(R.A->dim(), RA.A->dim() * RB.A->dim());
        const coeffs w = tensor(element_of(RA, f, t), element_of(RB, g, t));
        EXPECT_TRUE(same(signal_of(R, w, t), f * g)) << f << " * " << g;
        EXPECT_TRUE(same(signal_of(R, R.A->multiply(R.d, w), t), (f * g).diff(t))) << f << " * " << g;
        // the same through represent_on (the language's signal(w, t, d))
        EXPECT_TRUE(same(signal_of(represent_on(R.A, R.d), w, t), f * g));
    }
    const auto C = polynomial_representation(X * X + 1, X);
    const auto CC = product_representation(C, C);
    EXPECT_EQ(CC.p.degree(CC.X), 3);  // exponents 2i, 0, -2i: d does not generate
}
