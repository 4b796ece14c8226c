// Tests of numeric/reference.h: exact binary inputs, extended-precision values.
#include <gtest/gtest.h>

#include <cln/real.h>
#include <cmath>

#include "core/error.h"
#include "numeric/reference.h"

using namespace symrep;

TEST(Reference, DoublesAreTakenAsTheirExactBinaryValue) {
    // 0.1 is not 1/10: its binary value is 3602879701896397/2^55.
    const GiNaC::numeric q = num::exact_rational(0.1);
    EXPECT_EQ(q, GiNaC::numeric(3602879701896397LL) / GiNaC::numeric(36028797018963968LL));
    EXPECT_EQ(num::exact_rational(-0.5), GiNaC::numeric(-1, 2));
    EXPECT_THROW(num::exact_rational(INFINITY), domain_error);
}

TEST(Reference, ResolvesCancellationThatDoubleArithmeticLoses) {
    // (1 - cos(w t))/w^2 at w t = 1e-9: double arithmetic returns 0 (cos rounds to 1),
    // the exact value is t^2/2 (1 - (w t)^2/12 + ...) = 0.5 to 1e-19.
    const GiNaC::symbol w("w"), t("t");
    const GiNaC::ex e = (1 - GiNaC::cos(w * t)) / GiNaC::pow(w, 2);
    const auto v = num::reference_eval({e}, {w, t}, {1e-9, 1.0});
    ASSERT_EQ(v.size(), 1u);
    EXPECT_NEAR(static_cast<double>(v[0]), 0.5, 1e-17);
    const double naive = (1 - std::cos(1e-9 * 1.0)) / (1e-9 * 1e-9);
    EXPECT_GT(std::fabs(naive - 0.5), 0.1);  // what the reference is for
}

TEST(Reference, MeasuresTheSameBinaryInputs) {
    // sin(x) at the double nearest 1e6*pi: not 0 but sin of the rounding error.
    const GiNaC::symbol x("x");
    const double X = 1e6 * M_PI;
    const auto v = num::reference_eval({GiNaC::sin(x)}, {x}, {X}, 50);
    EXPECT_NEAR(static_cast<double>(v[0]), std::sin(X), 1e-15);  // glibc reduces arguments exactly
    EXPECT_NE(static_cast<double>(v[0]), 0.0);
}

TEST(Reference, NamesWhatIsWrong) {
    const GiNaC::symbol x("x"), y("y");
    EXPECT_THROW(num::reference_eval({x + y}, {x}, {1.0}), domain_error);
    EXPECT_THROW(num::reference_eval({x}, {x}, {1.0, 2.0}), type_error);
    EXPECT_THROW(num::reference_eval({GiNaC::sqrt(x)}, {x}, {-1.0}), domain_error);
    EXPECT_THROW(num::reference_eval({x}, {x}, {1.0}, 5), domain_error);
}

TEST(Reference, FloatsInTheExpressionAreExact) {
    // A float read from a script has ~20 digits; CLN computes an operation with
    // a float to that float's precision only, and GiNaC rounds float * number
    // at substitution. The reference takes the float's exact binary value, so
    // a phase 0.38... * t at t = 1e6 is not rounded to 20 digits (which would
    // move sin by ~1e-14).
    const GiNaC::symbol t("t");
    const GiNaC::numeric c("0.3826459335309356114");
    const auto v = num::reference_eval({GiNaC::sin(c * t)}, {t}, {1e6}, 60);
    const GiNaC::ex exact_phase = GiNaC::numeric(cln::rational(cln::the<cln::cl_R>(c.to_cl_N()))) * 1000000;
    const double want = num::evaluate_real(GiNaC::sin(exact_phase), 60).to_double();
    const double rounded = num::evaluate_real(GiNaC::sin(c * 1000000), 60).to_double();  // the 20-digit phase
    EXPECT_EQ(static_cast<double>(v[0]), want);
    EXPECT_GT(std::fabs(rounded - want), 1e-15);  // what the exactness saves
    EXPECT_EQ(num::exact_floats_of(GiNaC::ex(c)), GiNaC::ex(exact_phase / 1000000));
}
