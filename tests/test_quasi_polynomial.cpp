// Tests of quasi-polynomials (engine/mechanics/quasi_polynomial.h): recognition,
// closed-form antiderivative and convolution (thesis VI.1.22-25, 37).
#include <cmath>
#include <functional>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "core/error.h"
#include "mechanics/quasi_polynomial.h"

using namespace symrep;
using namespace symrep::mechanics;
using GiNaC::ex;

namespace {

const GiNaC::realsymbol t("t");

bool same_function(const ex& a, const ex& b) {
    return quasi_polynomial::from_ex(a - b, t).is_zero();
}

double num(const ex& e) {
    const ex v = GiNaC::evalf(e);
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(v)) << e;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

}  // namespace

TEST(QuasiPolynomial, RecognizesAndRoundTrips) {
    const GiNaC::possymbol W("W");
    const GiNaC::realsymbol a("a");
    const ex e = 3 * t * t * GiNaC::exp(-2 * t) * GiNaC::cos(5 * t) + t * GiNaC::sin(W * t) + 7 +
                 GiNaC::exp(a * t + 1) * GiNaC::cos(W * t + ex(1) / 3) + GiNaC::cosh(2 * t) -
                 GiNaC::pow(GiNaC::sin(t), 2);
    const quasi_polynomial q = quasi_polynomial::from_ex(e, t);
    EXPECT_TRUE(q.is_real());
    EXPECT_TRUE(same_function(q.to_ex(), e));
    // sin^2 t = 1/2 - cos(2t)/2 is recognized through the product
    const quasi_polynomial s2 = quasi_polynomial::from_ex(GiNaC::pow(GiNaC::sin(t), 2), t);
    EXPECT_TRUE((s2 - quasi_polynomial::from_ex(ex(1) / 2 - GiNaC::cos(2 * t) / 2, t)).is_zero());
    // cos(-W t) and cos(W t) combine
    EXPECT_TRUE(quasi_polynomial::from_ex(GiNaC::cos(-W * t) - GiNaC::cos(W * t), t).is_zero());
    EXPECT_EQ(quasi_polynomial::from_ex(GiNaC::cos(W * t), t).to_ex(), GiNaC::cos(W * t));
}

TEST(QuasiPolynomial, RejectsNonQuasiPolynomials) {
    for (const ex& e : std::vector<ex>{ex(1 / t), GiNaC::sqrt(t), GiNaC::exp(t * t), GiNaC::log(1 + t),
                        GiNaC::cos(t) / t, GiNaC::pow(2, t * t)}) {
        try {
            quasi_polynomial::from_ex(e, t);
            ADD_FAILURE() << "accepted " << e;
        } catch (const domain_error& err) {
            EXPECT_NE(std::string(err.what()).find("not a quasi-polynomial"), std::string::npos)
                << err.what();
        }
    }
}

TEST(QuasiPolynomial, AntiderivativeDifferentiatesBack) {
    const GiNaC::possymbol W("W");
    const GiNaC::realsymbol a("a"), b("b");
    const std::vector<ex> cases{
        ex(5), t, GiNaC::pow(t, 3),                                  // a = b = 0
        GiNaC::exp(-2 * t), t * t * GiNaC::exp(3 * t),              // real exponent
        GiNaC::cos(W * t), t * GiNaC::sin(W * t), GiNaC::pow(t, 3) * GiNaC::cos(W * t),
        GiNaC::exp(a * t) * GiNaC::sin(b * t) * t,                  // generic symbolic
        GiNaC::exp(-t) * GiNaC::cos(2 * t) * t * t + 4 * t - 1,
        GiNaC::cos(W * t) * GiNaC::sin(W * t)};
    for (const ex& e : cases) {
        const quasi_polynomial f = quasi_polynomial::from_ex(e, t);
        const quasi_polynomial F = f.antiderivative();
        // exact: d/dt F == f, canonically and through GiNaC's own diff
        EXPECT_TRUE((F.derivative() - f).is_zero()) << e;
        EXPECT_TRUE(same_function(GiNaC::diff(F.to_ex(), t), e)) << e << " -> " << F.to_ex();
        EXPECT_TRUE(is_zero_cex(F.at_zero())) << e;
        EXPECT_TRUE(F.is_real()) << e;
    }
    // printed closed forms
    EXPECT_TRUE(same_function(quasi_polynomial::from_ex(GiNaC::sin(W * t), t).antiderivative().to_ex(),
                              (1 - GiNaC::cos(W * t)) / W));
    EXPECT_TRUE(same_function(quasi_polynomial::from_ex(t * t, t).antiderivative().to_ex(),
                              GiNaC::pow(t, 3) / 3));
}

TEST(QuasiPolynomial, AntiderivativeNumericallyAt30Digits) {
    const ex e = GiNaC::pow(t, 2) * GiNaC::exp(-t / 3) * GiNaC::sin(ex(7) / 5 * t);
    const ex F = quasi_polynomial::from_ex(e, t).antiderivative().to_ex();
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 40;
    for (const ex& tv : std::vector<ex>{ex(3) / 10, ex(17) / 10, ex(5)}) {
        // d/dt by a central difference of width 1e-12 is accurate to ~1e-24
        const ex h = GiNaC::numeric(1, 1000000000000LL);
        const ex d = GiNaC::evalf((F.subs(t == tv + h) - F.subs(t == tv - h)) / (2 * h));
        const ex v = GiNaC::evalf(e.subs(t == tv));
        EXPECT_LT(std::abs(num(d - v)), 1e-20) << tv;
    }
    GiNaC::Digits = saved;
}

TEST(QuasiPolynomial, ConvolutionMatchesQuadrature) {
    // tolerance: 1e-10 relative to max(1, |value|); 61-point Gauss-Kronrod,
    // adaptive to 1e-14, on smooth integrands
    const std::vector<std::pair<ex, ex>> pairs{
        {GiNaC::exp(-t), GiNaC::cos(2 * t)},
        {t * GiNaC::sin(3 * t), GiNaC::exp(-t / 2) * GiNaC::cos(3 * t)},
        {GiNaC::cos(t), GiNaC::sin(t)},                      // resonance
        {t * t + 1, GiNaC::exp(t / 4) * t},
        {GiNaC::exp(-t) * GiNaC::sin(t) * t, GiNaC::exp(-t) * GiNaC::cos(t)}};  // resonance, k > 0
    for (const auto& [fe, ge] : pairs) {
        const quasi_polynomial f = quasi_polynomial::from_ex(fe, t), g = quasi_polynomial::from_ex(ge, t);
        const ex c = convolution(f, g).to_ex();
        for (double tv : {0.3, 1.7, 5.0}) {
            auto integrand = [&](double tau) {
                return num(fe.subs(t == tau)) * num(ge.subs(t == tv - tau));
            };
            const double q = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                integrand, 0.0, tv, 10, 1e-14);
            const double v = num(c.subs(t == tv));
            EXPECT_LT(std::abs(v - q), 1e-10 * std::max(1.0, std::abs(q)))
                << fe << " * " << ge << " at " << tv;
        }
    }
}

TEST(QuasiPolynomial, ConvolutionIsCommutativeAndResonant) {
    const GiNaC::possymbol W("W");
    const GiNaC::realsymbol a("a"), b("b");
    const quasi_polynomial f = quasi_polynomial::from_ex(t * GiNaC::cos(W * t) + GiNaC::exp(a * t), t);
    const quasi_polynomial g =
        quasi_polynomial::from_ex(GiNaC::sin(W * t) + t * t * GiNaC::exp(b * t) * GiNaC::cos(W * t), t);
    EXPECT_TRUE((convolution(f, g) - convolution(g, f)).is_zero());
    // cos(W t) * sin(W t) = t sin(W t) / 2: a secular term from the exact resonance
    const quasi_polynomial cs = convolution(quasi_polynomial::from_ex(GiNaC::cos(W * t), t),
                                            quasi_polynomial::from_ex(GiNaC::sin(W * t), t));
    EXPECT_TRUE(same_function(cs.to_ex(), t * GiNaC::sin(W * t) / 2)) << cs.to_ex();
    // convolution with the constant 1 is the antiderivative
    EXPECT_TRUE((convolution(quasi_polynomial::constant(1, t), g) - g.antiderivative()).is_zero());
}

TEST(QuasiPolynomial, ExpConvolvedWithItselfVI_1_37) {
    // scalar form of e^{-W t} * e^{-W t} = t e^{-W t} (VI.1.37), for a real symbol,
    // for W = 0 and on the complex eigenvalue i|w| of the operator w x
    const GiNaC::realsymbol a("a");
    const GiNaC::possymbol W("W");
    for (const cex& lam : {cex(-a, 0), cex(0, 0), cex(0, -W), cex(-a, W)}) {
        const quasi_polynomial e = quasi_polynomial::monomial({1, 0}, 0, lam, t);
        const quasi_polynomial te = quasi_polynomial::monomial({1, 0}, 1, lam, t);
        EXPECT_TRUE((convolution(e, e) - te).is_zero()) << lam.re << " + i " << lam.im;
    }
}

TEST(QuasiPolynomial, GenericReadingAndItsExactSpecialCase) {
    // int_0^t e^{a t} cos(b t) has 1/(a^2 + b^2): generic in a, b
    const GiNaC::realsymbol a("a"), b("b");
    const quasi_polynomial F =
        quasi_polynomial::from_ex(GiNaC::exp(a * t) * GiNaC::cos(b * t), t).antiderivative();
    // a = 0 alone is fine (b generic)
    const quasi_polynomial F0 = F.subs(a, 0);
    EXPECT_TRUE(same_function(F0.to_ex(), GiNaC::sin(b * t) / b));
    // a = b = 0 is excluded by the generic reading: a typed error, not a crash
    EXPECT_THROW(F0.subs(b, 0), domain_error);
    // the specialized integrand takes the exact branch lambda = 0
    EXPECT_TRUE(same_function(quasi_polynomial::from_ex(ex(1), t).antiderivative().to_ex(), t));
    EXPECT_THROW(quasi_polynomial::from_ex(GiNaC::pow(1 + t, 100000), t), size_error);
    EXPECT_THROW(quasi_polynomial::from_ex(t, GiNaC::ex(2)), domain_error);
}
