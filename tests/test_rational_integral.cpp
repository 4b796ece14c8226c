// tests/test_rational_integral.cpp -- int_0^t of rational functions in closed form
// (scalar/rational_integral.h), used by the Duhamel integrals of Thm VI.1.2.2-4.
#include <gtest/gtest.h>

#include <vector>

#include "scalar/rational_integral.h"
#include "test_util.h"

namespace {

using GiNaC::ex;
using symrep::test::same;

const GiNaC::realsymbol x("x"), t("t");

double at(const ex& e, double v) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(t == v))).to_double(); }

TEST(RationalIntegral, ClosedFormsAreTheAntiderivativesFromZero) {
    // exact forms: int_0^t dx/(1 + x^2) = atan t; int_0^t dx/(x + 2)^2 = 1/2 - 1/(t + 2)
    const auto a = symrep::definite_rational_integral(1 / (1 + x * x), x, t);
    ASSERT_TRUE(a);
    EXPECT_TRUE(same(*a, GiNaC::atan(t)));
    const auto b = symrep::definite_rational_integral(GiNaC::pow(x + 2, -2), x, t);
    ASSERT_TRUE(b);
    EXPECT_TRUE(GiNaC::normal(*b - (ex(1) / 2 - 1 / (t + 2))).is_zero());
    // symbols in the numerator stay: a b/(1 + x^2) -> a b atan t
    const GiNaC::symbol p("p");
    const auto c = symrep::definite_rational_integral(p / (4 + x * x), x, t);
    ASSERT_TRUE(c);
    EXPECT_TRUE(same(*c, p * GiNaC::atan(t / 2) / 2));
    // against mpmath's quadrature at 30 digits on [0, 2] (tolerance 1e-14: the double evaluation)
    const std::pair<ex, double> cases[] = {
        {1 / (1 + GiNaC::pow(x, 3)), 1.09000173022846054052958000164},  // (x + 1)(x^2 - x + 1)
        {(3 * x + 1) / (x * x + x + 1), 2.50679626127201105355701210988},
        {(GiNaC::pow(x, 3) + 5) / (GiNaC::pow(x + 1, 2) * (x + 3)), 1.07309854695443942140062842212}};
    for (const auto& [f, value] : cases) {
        const auto R = symrep::definite_rational_integral(f, x, t);
        ASSERT_TRUE(R) << f;
        EXPECT_NEAR(at(*R, 2), value, 1e-14) << f;
        EXPECT_TRUE(GiNaC::normal(R->diff(t) - f.subs(x == t)).is_zero()) << f;
    }
}

TEST(RationalIntegral, NothingWhereTheMethodDoesNotApply) {
    // a pole in [0, inf) (1/(x - 1), 1/x, 1/(x^2 - 2)), a repeated quadratic, an irreducible cubic,
    // symbols in the denominator, a non-rational integrand: no closed form is claimed
    const GiNaC::symbol e("e");
    for (const ex& f : std::vector<ex>{1 / (x - 1), 1 / x, 1 / (x * x - 2), GiNaC::pow(1 + x * x, -2), 1 / (GiNaC::pow(x, 3) + x + 1),
                        1 / (x + e), GiNaC::exp(-x * x), GiNaC::cos(x) / (1 + x * x)})
        EXPECT_FALSE(symrep::definite_rational_integral(f, x, t)) << f;
}

}  // namespace
