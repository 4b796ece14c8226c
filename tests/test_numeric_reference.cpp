// Tests of numeric/reference.h: exact binary inputs, extended-precision values.
#include <gtest/gtest.h>

#include <cmath>

#include "io/error.h"
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
