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
