// tests/test_quadrature.cpp -- integral objects, nested ones included, by one march of Chebyshev
// panels (numeric/quadrature.h, numeric/quadrature_chain.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "numeric/quadrature.h"
#include "numeric/reference.h"

using namespace symrep;

// Against closed forms: a smooth integrand is integrated to a few ulps (bound 1e-14
// relative), including a phase that is not linear (int_0^t cos(a + b sin(c tau)) has no
// elementary form; its derivative in t, the integrand, is compared instead by
// differencing the quadrature: 1e-8, the central difference's own error).
TEST(Quadrature, SmoothIntegrandsToAFewUlps) {
    const GiNaC::realsymbol tau("tau");
    EXPECT_NEAR(num::integrate_numerically(tau, 0, 2, GiNaC::cos(3 * tau)), std::sin(6.0) / 3, 1e-14);
    EXPECT_NEAR(num::integrate_numerically(tau, 0, 50, GiNaC::exp(-tau) * tau), 1 - 51 * std::exp(-50.0), 1e-14);
    const GiNaC::ex f = GiNaC::cos(GiNaC::numeric(3, 10) * tau + GiNaC::numeric(6, 5) * GiNaC::sin(2 * tau));
    const double h = 1e-4, t = 7.3;
    const double d = (num::integrate_numerically(tau, 0, t + h, f) - num::integrate_numerically(tau, 0, t - h, f)) / (2 * h);
    EXPECT_NEAR(d, std::cos(0.3 * t + 1.2 * std::sin(2 * t)), 1e-8);
}

// Integral objects in an expression are replaced by their values when their limits are
// numbers, and kept otherwise; accurate_double evaluates through them.
TEST(Quadrature, IntegralObjectsInExpressions) {
    const GiNaC::realsymbol tau("tau"), t("t");
    const GiNaC::ex I = GiNaC::integral(tau, 0, t, GiNaC::cos(tau * tau));
    EXPECT_TRUE(num::has_integral(num::integrals_as_numbers(I)));  // t has no value
    const GiNaC::ex at2 = 3 * I.subs(t == 2) + 1;
    EXPECT_FALSE(num::has_integral(num::integrals_as_numbers(at2)));
    // int_0^2 cos(tau^2) = 0.461461...: Fresnel C, here checked by its series to 1e-13
    double series = 0, term = 2;  // sum (-1)^k 2^(4k+1)/((4k+1)(2k)!)
    for (int k = 0; k < 40; ++k) {
        series += term / (4 * k + 1);
        term *= -16.0 / ((2 * k + 1) * (2 * k + 2));
    }
    EXPECT_NEAR(num::accurate_double(at2), 3 * series + 1, 1e-13);
    EXPECT_THROW(num::integrate_numerically(tau, 0, 1, 1 / (tau - GiNaC::numeric(1, 2))), domain_error);
}

// A short interval (Gauss-Kronrod's estimate was above its bound there, though the value was
// right). Nested integrals (a position from a velocity with integral objects) against closed
// forms: int_0^t cos(tau) int_0^tau cos(s) ds dtau = sin(t)^2/2; bound 1e-12.
TEST(Quadrature, ShortIntervalsAndNestedIntegrals) {
    const GiNaC::realsymbol tau("tau"), s("s"), t("t");
    const double b = 0.0020397;
    const double exact = 2 * std::sin(b / 2) * std::sin(b / 2);  // int_0^b sin = 1 - cos b, without cancellation
    EXPECT_NEAR(num::integrate_numerically(tau, 0, b, GiNaC::sin(tau)), exact, 1e-14 * exact);
    EXPECT_NEAR(num::integrate_numerically(tau, 0, b, tau), b * b / 2, 1e-15 * b * b);
    const GiNaC::ex nested =
        GiNaC::integral(tau, 0, t, GiNaC::cos(tau) * GiNaC::integral(s, 0, tau, GiNaC::cos(s)));
    for (double T : {0.001, 1.0, 7.5}) {
        const double v = num::accurate_double(nested.subs(t == GiNaC::numeric(T)));
        EXPECT_NEAR(v, std::sin(T) * std::sin(T) / 2, 1e-12 * std::max(1e-6, std::sin(T) * std::sin(T))) << T;
    }
    // an inner integral starting elsewhere: int_0^2 tau int_1^tau s ds dtau = int_0^2 tau (tau^2 - 1)/2 = 1
    EXPECT_NEAR(num::accurate_double(GiNaC::integral(tau, 0, 2, tau * GiNaC::integral(s, 1, tau, s))), 1.0, 1e-12);
    // deeper or foreign nesting is refused
    EXPECT_THROW(num::integrate_nested(tau, 0, 1, GiNaC::integral(s, 0, tau + 1, s)), domain_error);
}

// The nested integrals of the charge in B = 1 + t^2/10 (phase phi = t + t^3/30): by the chain
// rule int_0^T cos(phi) I_c = I_c(T)^2/2 and int_0^T (cos(phi) I_s + sin(phi) I_c) = I_c(T) I_s(T)
// with I_c = int_0^t cos(phi), I_s = int_0^t sin(phi); references by mpmath (30 digits, 3000
// pieces). Bound 1e-11 absolute: the phase 930 at t = 30 is rounded in double (1e-13 per value
// of the integrand), and the estimate must cover the actual error. The work is linear in T.
TEST(Quadrature, NestedIntegralsInLinearTimeWithAnHonestEstimate) {
    const GiNaC::realsymbol tau("tau"), s("s");
    auto phi = [](const GiNaC::ex& x) { return x + GiNaC::pow(x, 3) / 30; };
    const GiNaC::ex Ic = GiNaC::integral(s, 0, tau, GiNaC::cos(phi(s))), Is = GiNaC::integral(s, 0, tau, GiNaC::sin(phi(s)));
    struct reference {
        double T, square, product;
    };
    for (const reference& r : {reference{15, 0.02584454399510579837, 0.2468799784432203577},
                               reference{30, 0.01752128970507181204, 0.1991778151112464415}}) {
        const num::integral_value a = num::evaluate_integral(tau, 0, r.T, GiNaC::cos(phi(tau)) * Ic);
        const num::integral_value b =
            num::evaluate_integral(tau, 0, r.T, GiNaC::cos(phi(tau)) * Is + GiNaC::sin(phi(tau)) * Ic);
        EXPECT_NEAR(a.value, r.square, 1e-11) << r.T;
        EXPECT_NEAR(b.value, r.product, 1e-11) << r.T;
        // the estimate: small against the scale, and not below the actual error
        EXPECT_LT(a.error, 1e-11 * a.scale) << r.T;
        EXPECT_GE(std::max(a.error, 1e-15 * a.scale), std::fabs(a.value - r.square)) << r.T;
        EXPECT_GE(std::max(b.error, 1e-15 * b.scale), std::fabs(b.value - r.product)) << r.T;
    }
    // linear work: ten times the interval, about ten times the evaluations (quadratic: 100)
    const GiNaC::ex f = GiNaC::cos(tau) * GiNaC::integral(s, 0, tau, GiNaC::cos(s));
    const num::integral_value at100 = num::evaluate_integral(tau, 0, 100, f);
    const num::integral_value at1000 = num::evaluate_integral(tau, 0, 1000, f);
    EXPECT_NEAR(at1000.value, std::sin(1000.0) * std::sin(1000.0) / 2, 1e-12 * at1000.scale);
    EXPECT_LT(double(at1000.evaluations), 15.0 * double(at100.evaluations));
    // three levels: int_0^2 int_0^tau int_0^s x dx ds dtau = 2^4/24
    const GiNaC::realsymbol x("x");
    EXPECT_NEAR(num::integrate_nested(tau, 0, 2, GiNaC::integral(s, 0, tau, GiNaC::integral(x, 0, s, x))), 16.0 / 24,
                1e-15);
}

// Failing loudly: an integrand that oscillates too fast for the panel budget, one that is not
// integrable, and one that is rounding noise (3/4 - 3 cos(tau)/4 near 0: 2e-4 of its size at
// tau = 1e-6) are refused; the same noisy integral inside an expression whose value dwarfs its
// estimate is a value (judged against the whole, not the piece).
TEST(Quadrature, AnEstimateThatFailsLoudly) {
    const GiNaC::realsymbol tau("tau"), t("t");
    EXPECT_THROW(num::integrate_numerically(tau, 0, 200, GiNaC::cos(GiNaC::pow(tau, 3))), domain_error);
    EXPECT_THROW(num::integrate_numerically(tau, 0, 1, 1 / (tau - GiNaC::numeric(1, 3))), domain_error);
    const GiNaC::ex noisy = GiNaC::sin(GiNaC::numeric(3, 4) - 3 * GiNaC::cos(tau) / 4);
    const GiNaC::numeric T(1, 1000000);
    EXPECT_THROW(num::integrate_numerically(tau, 0, T.to_double(), noisy), domain_error);
    EXPECT_THROW(num::accurate_double(GiNaC::integral(tau, 0, T, noisy)), domain_error);
    // int_0^T 3 tau^2/8 = T^3/8 = 1.25e-19, far below 1 + ...: the value 1 to the last digit
    EXPECT_EQ(num::accurate_double(1 + GiNaC::integral(tau, 0, T, noisy)), 1.0);
    // a smooth integrand over a short interval and a long one: a few ulps, estimate below 1e-13
    for (const double b : {1e-7, 0.006, 50.0}) {
        const num::integral_value v = num::evaluate_integral(tau, 0, b, GiNaC::exp(-tau) * GiNaC::cos(3 * tau));
        // the antiderivative at b, (1 - e^-b (cos 3b - 3 sin 3b))/10: in long double, and by its
        // series b - b^2/2 - 4 b^3/3 + 13 b^4/12 where that cancels
        const long double B = b;
        const double exact = b < 1e-3 ? double(B - B * B / 2 - 4 * B * B * B / 3 + 13 * B * B * B * B / 12)
                                      : double((1 - std::exp(-B) * (std::cos(3 * B) - 3 * std::sin(3 * B))) / 10);
        EXPECT_NEAR(v.value, exact, 1e-15 * v.scale) << b;
        EXPECT_LT(v.error, 1e-13 * v.scale) << b;
    }
}
