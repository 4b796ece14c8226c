// tests/test_limit.cpp -- the limit at a removable singularity (scalar/limit.h).
#include <gtest/gtest.h>

#include <cmath>

#include <ginac/ginac.h>

#include "core/error.h"
#include "scalar/limit.h"
#include "test_util.h"

using namespace symrep;
using GiNaC::ex;

namespace {

/// The limit of e at x = x0, y = y0 (two parameters).
ex limit2(const ex& e, const GiNaC::symbol& x, const ex& x0, const GiNaC::symbol& y, const ex& y0) {
    return limit_at_point(2, [&](const std::vector<ex>& o) {
        return e.subs(GiNaC::lst{x == x0 + o[0], y == y0 + o[1]});
    });
}

}  // namespace

TEST(Limit, RemovableSingularitiesAreTheirExactLimit) {
    const GiNaC::symbol c("c"), k("k");
    // the double root of y'' + c y' + k y: the impulse response's sin(s t/2)/s with
    // s = sqrt(4 k - c^2) at t = 3 is 3/2 at c = 2, k = 1 (exact; both sides of c^2 = 4 k)
    const ex s = GiNaC::sqrt(4 * k - c * c);
    EXPECT_TRUE(limit2(GiNaC::sin(s * 3 / 2) / s, c, 2, k, 1).is_equal(GiNaC::numeric(3, 2)));
    // a resonance: (cos(w t) - cos(2 t))/(4 - w^2) at w = 2, t = 1 is sin(2)/4
    const GiNaC::symbol w("w"), t("t");
    const ex f = (GiNaC::cos(w * t) - GiNaC::cos(2 * t)) / (4 - w * w);
    const ex L = limit2(f, w, 2, t, 1);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(L.evalf()).to_double(), std::sin(2.0) / 4, 1e-15);
    // a matrix: entrywise
    const ex m = limit2(GiNaC::matrix{{GiNaC::sin(c) / c}, {(1 - GiNaC::cos(c)) / (c * c)}}, c, 0, k, 0);
    ASSERT_TRUE(GiNaC::is_a<GiNaC::matrix>(m));
    EXPECT_TRUE(m.op(0).is_equal(1));
    EXPECT_TRUE(m.op(1).is_equal(GiNaC::numeric(1, 2)));
}

TEST(Limit, NoLimitIsRefusedWithItsReason) {
    const GiNaC::symbol x("x"), y("y");
    const std::string dir = test::what_of([&] { limit2(x * y / (x * x + y * y), x, 0, y, 0); });
    EXPECT_NE(dir.find("depends on the direction"), std::string::npos) << dir;
    const std::string side = test::what_of([&] { limit2(GiNaC::abs(x) / x, x, 0, y, 1); });
    EXPECT_NE(side.find("depends on the direction"), std::string::npos) << side;
    const std::string pole = test::what_of([&] { limit2((x + 1) / (x * y), x, 0, y, 1); });
    EXPECT_NE(pole.find("pole"), std::string::npos) << pole;
    // sqrt(|x|)-like branches: sqrt(x^2 + y^2)/ (x^2 + y^2)^(1/2) is 1, sqrt(x)/x has no limit
    const std::string branch = test::what_of([&] { limit2(GiNaC::sqrt(x) / x, x, 0, y, 1); });
    EXPECT_NE(branch.find("limit"), std::string::npos) << branch;
}

// With several parameters approaching the point, agreement along lines is not a
// proof: each of these is the same number on every line through the point, and
// has no limit (x^2 y/(x^4 + y^2) is 1/2 on y = x^2). Refused, never that number.
TEST(Limit, LinesAloneAreNoProofInSeveralParameters) {
    const GiNaC::symbol x("x"), y("y");
    const ex q = GiNaC::pow(x, 4) + y * y;
    for (const ex& e : {x * x * y / q, (x * x * y + q) / q, x * y * GiNaC::sin(x) / q}) {
        const std::string m = test::what_of([&] { limit2(e, x, 0, y, 0); });
        EXPECT_NE(m.find("not a proof"), std::string::npos) << e << ": " << m;
    }
}

// ... and where the expression is a regular function of the one quantity that
// vanishes, the limit is proved: a common factor (x^2 - y^2)/(x - y) at x = y = 1,
// a resonance where both frequencies move (w^2 - u^2 = (w - u)(w + u); w
// eliminated by w = u + q), the k = 0 limit of a damped oscillator's static term.
TEST(Limit, OneVanishingQuantityIsAProof) {
    const GiNaC::symbol x("x"), y("y"), w("w"), u("u"), k("k"), c("c");
    EXPECT_TRUE(limit2((x * x - y * y) / (x - y), x, 1, y, 1).is_equal(2));
    const ex f = (GiNaC::cos(w) - GiNaC::cos(u)) / (w * w - u * u);
    const ex L = limit2(f, w, 2, u, 2);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(L.evalf()).to_double(), -std::sin(2.0) / 4, 1e-15);
    // (1 - e^(-c t) (cosh + c sinh/s)(s t))/k with s = sqrt(c^2 - 4 k)... at t = 1: the
    // static deflection's k -> 0 limit t/c - (1 - e^(-c t))/c^2 of the overdamped form
    const ex s = GiNaC::sqrt(c * c - 4 * k);
    const ex g = (1 - GiNaC::exp(-c / 2) * (GiNaC::cosh(s / 2) + c * GiNaC::sinh(s / 2) / s)) / k;
    const ex G = limit2(g, k, 0, c, 3);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(G.evalf()).to_double(), 1.0 / 3 - (1 - std::exp(-3.0)) / 9, 1e-15);
}
