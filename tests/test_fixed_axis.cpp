// tests/test_fixed_axis.cpp -- rotating frames with w(t) = s(t) u (thesis VI.2,
// mechanics/fixed_axis.h): read from the equation as a user writes it, reduced to
// the inertial problem, checked exactly (residual 0, initial values) and against
// Boost.Odeint on the equation as stated.
//
// Tolerance of the numeric comparisons: verify() integrates the rotating-frame
// equation with rkf78 at 1e-12 absolute and relative tolerance; over 20-200 time
// units its global error measured here is 1e-11 .. 1e-10 relative, so 1e-8 leaves
// two orders for other machines while a wrong sign of the angle gives O(1).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/error.h"
#include "lang/print_value.h"
#include "mechanics/solution_witness.h"
#include "test_support.h"

using symrep::test::test_session;

namespace {
double number(test_session& t, const std::string& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(t.ex(e))).to_double();
}
}  // namespace

// VI.2.70: the Foucault pendulum with a rate a + b sin(c t) that changes sign.
TEST(FixedAxis, FoucaultWithAVaryingRateIsSolvedByReduction) {
    test_session t;
    ASSERT_EQ(t.run("vector u, r0, v0\npositive w0\nw := (a + b*sin(c*t))*u\n"
                    "P := ode(r'' + 2*w x r' + w' x r + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)\n"
                    "s := solve(P)"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(P, s)").as_bool());  // symbolic residual and initial values 0
    // the angle a(t) = |u| (a t + b/c (1 - cos(c t))) and psi' (0) = v0 + w(0) x r0
    EXPECT_TRUE(t.val("s == cos(norm(u)*(a*t + b/c*(1 - cos(c*t))))*(r0*cos(w0*t) + (v0 + a*(u x r0))/w0*sin(w0*t)) "
                      "- sin(norm(u)*(a*t + b/c*(1 - cos(c*t))))/norm(u)*(u x (r0*cos(w0*t) + (v0 + a*(u x r0))/w0*sin(w0*t))) "
                      "+ (1 - cos(norm(u)*(a*t + b/c*(1 - cos(c*t)))))/norm(u)^2*(u . (r0*cos(w0*t) + (v0 + a*(u x r0))/w0*sin(w0*t)))*u")
                    .as_bool());
    ASSERT_EQ(t.run("vals := [u = [0, 0.6, 0.8], a = 0.3, b = 1.2, c = 2, w0 = 1.5, r0 = [1, 0.5, -0.2], "
                    "v0 = [0.1, 0.3, 0.7]]"),
              0);
    EXPECT_LT(number(t, "verify(P, s, vals, 20)"), 1e-8);
    EXPECT_LT(number(t, "verify(P, s, vals, 200)"), 1e-8);
    // free motion (k = 0) with a skew axis of length 3
    ASSERT_EQ(t.run("F := ode(r'' + 2*w x r' + w' x r + w x (w x r) = 0, r(0) = r0, r'(0) = v0)\nf := solve(F)"), 0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(F, f)").as_bool());
    EXPECT_LT(number(t, "verify(F, f, [u = [1, 2, 2], a = -0.2, b = 0.5, c = 3, r0 = [1, 0, 0], v0 = [0, 1, 0]], 20)"),
              1e-8);
}

// A literal axis with the rate inside it, w' as the derivative of the given w, and a
// free term along the axis (gravity): the inertial problem keeps it (Q^T g = g).
TEST(FixedAxis, LiteralAxisGravityAndTheDerivativeOfAGivenW) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nW := [0, 0, 2*cos(t) - 1/2]\n"
                    "G := ode(r'' + 2*W x r' + W' x r + W x (W x r) = [0, 0, -g], r(0) = r0, r'(0) = v0)\n"
                    "h := solve(G)"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("W' == [0, 0, -2*sin(t)]").as_bool());
    EXPECT_TRUE(t.val("check(G, h)").as_bool());
    EXPECT_LT(number(t, "verify(G, h, [g = 9.81, r0 = [1, 2, 3], v0 = [0, 1, 0]], 30)"), 1e-8);
    // the vertical motion is free fall, untouched by the rotation
    EXPECT_TRUE(t.val("h . [0, 0, 1] == (r0 . [0, 0, 1]) + (v0 . [0, 0, 1])*t - g*t^2/2").as_bool());
}

// Problems that have the cross terms of a varying w but not Thm VI.2.2's form are
// refused with the reason, not "the coefficient depends on t" nor a wrong answer.
TEST(FixedAxis, OtherFormsAreRefusedWithTheReason) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nw := (2*cos(t) - 1/2)*[0, 0, 1]"), 0);
    struct bad {
        const char* equation;
        const char* reason;
    };
    for (const bad& b : {bad{"r'' + 2*w x r' + w x (w x r) = 0", "not the rotating-frame operator"},
                         bad{"r'' + 2*w x r' + w' x r + w x (w x r) + r'/10 = 0", "undamped form only"},
                         bad{"r'' + 2*[sin(t), 0, cos(t)] x r' + r = 0", "not the rotating-frame operator"}}) {
        const std::size_t before = t.err.str().size();
        EXPECT_NE(t.run(std::string("ode(") + b.equation + ", r(0) = r0, r'(0) = v0)"), 0) << b.equation;
        const std::string msg = t.err.str().substr(before);
        EXPECT_NE(msg.find(b.reason), std::string::npos) << b.equation << ": " << msg;
    }
}

// VI.2.42-52: a charge in B(t) = (B0 + B1 cos(f t)) n of fixed direction, first order
// m v' = q (v x B): w = q B/m, v = Q v0; with a uniform E along n the inertial problem
// has the force q E (Q^T E = E). Same tolerance as above.
TEST(FixedAxis, ChargeInAFieldOfFixedDirectionVaryingInTime) {
    test_session t;
    ASSERT_EQ(t.run("vector n, v0\npositive m\nB := (B0 + B1*cos(f*t))*n\n"
                    "C := ode(m*v' = q*(v x B), v(0) = v0)\ns := solve(C)\n"
                    "E := ode(m*v' = q*(v x B + E0*n), v(0) = v0)\ne := solve(E)"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(C, s)").as_bool());
    EXPECT_TRUE(t.val("check(E, e)").as_bool());
    // |v| is conserved without E (a rotation of v0): at t = 7.3, 1e-12 for a closed form in doubles
    // (the exact s . s == v0 . v0 is undecided by the zero test: it says so, never false)
    EXPECT_NEAR(number(t, "eval(s . s, [n = [0, 0, 1], B0 = 0.5, B1 = 2, f = 3, q = -1.5, m = 2, v0 = [1, 0.5, 0.3]], "
                          "t = 7.3)"),
                1.34, 1e-12);
    EXPECT_LT(number(t, "verify(C, s, [n = [0, 0, 1], B0 = 0.5, B1 = 2, f = 3, q = -1.5, m = 2, v0 = [1, 0.5, 0.3]], 50)"),
              1e-8);
    EXPECT_LT(number(t, "verify(E, e, [n = [0, 1, 1], B0 = 0.5, B1 = 2, f = 3, q = -1.5, m = 2, E0 = 0.7, "
                        "v0 = [1, 0.5, 0.3]], 50)"),
              1e-8);
}

// (VI.2.53-63) a uniform E across B(t) of fixed direction: the inertial problem has the
// rotated force Q^T E, and psi = v0 + (q/m) int_0^t Q^T E holds the integrals I_c, I_s of
// cos and sin of the phase (VI.2.62), kept as integral objects; check proves the residual
// 0 with them (merged under one integral), verify evaluates them by Gauss-Kronrod.
// Measured 7e-12 against rkf78 at 1e-12 over 20 time units; bound as above.
TEST(FixedAxis, ChargeWithAnElectricFieldAcrossAVaryingMagneticField) {
    test_session t;
    ASSERT_EQ(t.run("vector n, v0, E\npositive m\nB := (B0 + B1*cos(f*t))*n\n"
                    "C := ode(m*v' = q*(v x B + E), v(0) = v0)\nv := solve(C)\n"
                    "vals := [n = [0, 0.6, 0.8], B0 = 0.5, B1 = 2, f = 3, q = -1.5, m = 2, E = [0.7, -0.2, 0.4], "
                    "v0 = [1, 0.5, 0.3]]"),
              0)
        << t.err.str();
    const std::string shown = symrep::lang::print_value(t.val("v"));
    EXPECT_NE(shown.find("int_0^t cos("), std::string::npos) << shown;  // I_c
    EXPECT_NE(shown.find("int_0^t sin("), std::string::npos) << shown;  // I_s
    EXPECT_TRUE(t.val("check(C, v)").as_bool());
    EXPECT_LT(number(t, "verify(C, v, vals, 20)"), 1e-9);
    // E along B: no integral, the closed form of before
    ASSERT_EQ(t.run("D := ode(m*v' = q*(v x B + E0*n), v(0) = v0)\nd := solve(D)"), 0) << t.err.str();
    EXPECT_EQ(symrep::lang::print_value(t.val("d")).find("int_"), std::string::npos);
}

// (VI.2.38-41) gravity across an axis turning at the rate a + b sin(c t), free and with
// the pendulum's w0^2 r: the nested integral int_0^t (t - tau) Q^T(tau) g dtau (and its
// Duhamel form with sin(w0 (t - tau))) split into integrals of functions of tau times
// functions of t; check exact, verify as above (measured 1.3e-11 and 1.6e-12).
TEST(FixedAxis, GravityAcrossAVaryingAxis) {
    test_session t;
    ASSERT_EQ(t.run("vector u, r0, v0, g\nw := (a + b*sin(c*t))*u\n"
                    "P := ode(r'' + 2*w x r' + w' x r + w x (w x r) = g, r(0) = r0, r'(0) = v0)\ns := solve(P)\n"
                    "F := ode(r'' + 2*w x r' + w' x r + w x (w x r) + w0^2*r = g, r(0) = r0, r'(0) = v0)\n"
                    "f := solve(F)\nvals := [u = [0, 0.6, 0.8], a = 0.3, b = 1.2, c = 2, w0 = 2, g = [0, 0, -9.81], "
                    "r0 = [1, 0.5, -0.2], v0 = [0.1, 0.3, 0.7]]"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
    EXPECT_TRUE(t.val("check(F, f)").as_bool());
    EXPECT_LT(number(t, "verify(P, s, vals, 20, 50)"), 1e-9);
    EXPECT_LT(number(t, "verify(F, f, vals, 20, 50)"), 1e-9);
}

// Scenes of a fixed-axis problem: solve(P, values) is the general reduction with the
// values put in (exact values exact, checked exactly; floats evaluated once at the
// end, checked up to rounding), and eval agrees with the general path (1e-15: both
// are the same closed form evaluated with the stable evaluator).
TEST(FixedAxis, ScenesAreTheGeneralSolutionWithTheValuesPutIn) {
    test_session t;
    ASSERT_EQ(t.run("vector u, r0, v0\nw := (a + b*sin(c*t))*u\n"
                    "P := ode(r'' + 2*w x r' + w' x r + w x (w x r) + k^2*r = 0, r(0) = r0, r'(0) = v0)\n"
                    "vals := [u = [0, 0, 1], a = 1/3, b = 2, c = 3, k = 2, r0 = [1, 0, 0], v0 = [0, 1, 0]]\n"
                    "s := solve(P, vals)\nfv := [u = [0, 0, 1], a = 0.3, b = 2, c = 3, k = 2, r0 = [1, 0, 0], "
                    "v0 = [0, 1, 0]]\nsf := solve(P, fv)"),
              0)
        << t.err.str();
    EXPECT_NE(t.out.str().find("reduction to the inertial problem"), std::string::npos) << t.out.str();
    EXPECT_TRUE(t.val("check(P, s, vals)").as_bool());
    EXPECT_TRUE(t.val("check(P, sf, fv)").as_bool());
    for (const char* k : {"0", "1"}) {
        EXPECT_NEAR(number(t, std::string("eval(s, vals, t = 1)[") + k + "]"),
                    number(t, std::string("eval(solve(P), vals, t = 1)[") + k + "]"), 1e-15)
            << k;
        EXPECT_NEAR(number(t, std::string("eval(sf, fv, t = 1)[") + k + "]"),
                    number(t, std::string("eval(solve(P), fv, t = 1)[") + k + "]"), 1e-15)
            << k;
    }
}

// first_integrals(P) (Thm VI.2.2.3.3, VI.3.140-141): each derivative along the equation
// (r'' replaced by what the equation gives) is exactly 0, for a varying and for a
// constant rate; a free term is refused (it does work).
TEST(FixedAxis, FirstIntegralsHaveZeroDerivativeAlongTheEquation) {
    using namespace symrep;
    for (const char* rate : {"(a + b*sin(c*t))", "a"}) {
        test_session t;
        ASSERT_EQ(t.run(std::string("vector u, r0, v0\nw := ") + rate +
                        "*u\nP := ode(m*(r'' + 2*w x r' + w' x r + w x (w x r)) + k*r = 0, r(0) = r0, r'(0) = v0)\n"
                        "I := first_integrals(P)"),
                  0)
            << t.err.str();
        const auto& P = t.val("P").as_problem();
        const GiNaC::ex w = t.ex("w"), k = t.ex("k"), m = t.ex("m");
        const GiNaC::ex &r = P.unknowns[0], &r1 = P.unknowns[1], &r2 = P.unknowns[2];
        const GiNaC::ex acc =
            -(2 * cross(w, r1) + cross(diff_t(w, P.t), r) + cross(w, cross(w, r)) + k / m * r);
        const lang::list I = t.val("I").as_list();
        ASSERT_EQ(I.size(), 3u);
        for (const lang::value& v : I) {
            const GiNaC::ex dI = subs_vectors(diff_t(v.as_ex(), P.t), {{r2, acc}});
            EXPECT_TRUE(equal(dI, 0)) << rate << ": " << v.as_ex();
        }
    }
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nw := (1 + t)*[0, 0, 1]\n"
                    "G := ode(r'' + 2*w x r' + w' x r + w x (w x r) = [0, 0, -1], r(0) = r0, r'(0) = v0)"),
              0)
        << t.err.str();
    EXPECT_NE(t.run("first_integrals(G)"), 0);
    EXPECT_NE(t.err.str().find("does work"), std::string::npos) << t.err.str();
}

// A rate whose integral is not a quasi-polynomial (tanh(t - 2), changing sign at t = 2;
// 1/(1 + t^2)): the angle a(t) = |u| int_0^t s is an integral object, VI.2.12 holds as it
// is, check proves the residual 0 (d/dt of the integral is s), eval and verify evaluate
// the angle by quadrature (measured 5e-12 and 6e-13 against rkf78 at 1e-12 over 20).
TEST(FixedAxis, ARateWithoutAnElementaryIntegral) {
    test_session t;
    ASSERT_EQ(t.run("vector u, r0, v0\nw := tanh(t - 2)*u\n"
                    "P := ode(r'' + 2*w x r' + w' x r + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)\n"
                    "s := solve(P)\nW := 1/(1 + t^2)*[0, 0, 1]\n"
                    "G := ode(r'' + 2*W x r' + W' x r + W x (W x r) = [0, 0, -1], r(0) = r0, r'(0) = v0)\n"
                    "g := solve(G)\nvals := [u = [0, 0.6, 0.8], w0 = 1.5, r0 = [1, 0.5, -0.2], v0 = [0.1, 0.3, 0.7]]"),
              0)
        << t.err.str();
    EXPECT_NE(symrep::lang::print_value(t.val("s")).find("int_0^t tanh(-2 + tau) dtau"), std::string::npos);
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
    EXPECT_TRUE(t.val("check(G, g)").as_bool());
    EXPECT_LT(number(t, "verify(P, s, vals, 20, 50)"), 1e-9);
    EXPECT_LT(number(t, "verify(G, g, vals, 20, 50)"), 1e-9);
    // the vertical motion is free fall: z(3) = -0.2 + 0.7*3 - 9/2
    EXPECT_NEAR(number(t, "eval(g . [0, 0, 1], vals, t = 3)"), -0.2 + 2.1 - 4.5, 1e-13);
    // a force across the axis with that angle: Duhamel's integrals hold the angle's integral,
    // nested integrals; check exact (the bound variables renamed by depth, so that the two
    // spellings of int_0^t exp(-tau^2) meet), verify (measured 1.3e-13 over 5 time units) and
    // eval against mpmath (50 digits: x = 4.90965540998021, y = -0.832088763119690 at t = 5)
    ASSERT_EQ(t.run("C := ode(v' = v x (exp(-t^2)*[0, 0, 1]) + [1, 0, 0], v(0) = v0)\nc := solve(C)"), 0)
        << t.err.str();
    EXPECT_NE(symrep::lang::print_value(t.val("c")).find("int_0^tau exp(-sigma^2) dsigma"), std::string::npos);
    EXPECT_TRUE(t.val("check(C, c)").as_bool());
    EXPECT_LT(number(t, "verify(C, c, [v0 = [0.3, -0.2, 0.5]], 5, 40)"), 1e-11);
    EXPECT_NEAR(number(t, "eval(c, [v0 = [0.3, -0.2, 0.5]], t = 5)[0]"), 4.9096554099802100396, 1e-14);
    EXPECT_NEAR(number(t, "eval(c, [v0 = [0.3, -0.2, 0.5]], t = 5)[1]"), -0.83208876311969043787, 1e-14);
}

// (VI.2.50-52) the law of motion of a charge in B(t) of fixed direction: x itself is absent
// from m r'' = q (r' x B + E), so the velocity problem is solved by reduction and
// r = r0 + int_0^t r' (VI.2.51). Without E (and with E along B) r holds the single integrals
// int_0^t cos(phi), int_0^t sin(phi) of VI.2.52; with E across B the nested ones
// int_0^t cos(phi(tau)) I_c(tau) dtau ... Check exact; verify as above (measured 8e-13 and
// 3.7e-13 over 5-10 time units; the nested integrals as one system of quadratures).
TEST(FixedAxis, ThePositionOfAChargeInAVaryingMagneticField) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0, E\npositive m\nB := (1 + t)*[0, 0, 1]\n"
                    "P := ode(m*r'' = q*(r' x B), r(0) = r0, r'(0) = v0)\ns := solve(P)\n"
                    "vals := [m = 2, q = 3, r0 = [1, 2, 3], v0 = [0.3, -0.2, 0.5], E = [0.2, 0.1, 0.4]]"),
              0)
        << t.err.str();
    const std::string shown = symrep::lang::print_value(t.val("s"));
    EXPECT_NE(shown.find("int_0^t cos("), std::string::npos) << shown;
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
    EXPECT_LT(number(t, "verify(P, s, vals, 10)"), 1e-9);
    // the velocity of the position is the thesis's (VI.2.49): diff(s, t) at t = 0 is v0
    EXPECT_NEAR(number(t, "eval(diff(s, t), vals, t = 0)[1]"), -0.2, 1e-15);
    ASSERT_EQ(t.run("P3 := ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)\ns3 := solve(P3)"), 0) << t.err.str();
    EXPECT_NE(symrep::lang::print_value(t.val("s3")).find("int_0^tau"), std::string::npos);
    EXPECT_TRUE(t.val("check(P3, s3)").as_bool());
    EXPECT_LT(number(t, "verify(P3, s3, vals, 5, 50)"), 1e-9);
    // a scene: the values put in, the method said
    ASSERT_EQ(t.run("sc := solve(P, vals)"), 0) << t.err.str();
    EXPECT_NE(t.out.str().find("r = r(0) + int_0^t r'"), std::string::npos) << t.out.str();
    // a turning B: the velocity is the reduction object, the position is refused with the reason
    EXPECT_NE(t.run("solve(ode(r'' = r' x [sin(t), cos(2*t), 1], r(0) = r0, r'(0) = v0))"), 0);
    EXPECT_NE(t.err.str().find("no closed form"), std::string::npos) << t.err.str();
}

// (VI.2.50-52) the position of a charge in B(t) with E across B, at long times and in a field
// that changes sign: r holds nested integral objects int_0^t c(tau) int_0^tau g(sigma) dsigma
// dtau, evaluated as one system of quadratures marched once (numeric/quadrature.h), so
// t = 30 (phase t + t^3/30 = 930) takes a fraction of a second (a quadrature at each node of
// another one took > 300 s). The references are scipy's DOP853 on the equation as written
// (m r'' = q (r' x B + E)) at rtol 1e-13, atol 1e-15; at rtol 1e-12 they move by 4e-13 of
// the largest component, and the engine's values lie within 5e-14 of them: bound 1e-10 of
// the largest component (a wrong term or a lost inner integral gives O(1)).
TEST(FixedAxis, ThePositionOfAChargeAtLongTimesAndInAFieldThatChangesSign) {
    struct point {
        const char* at;
        double x, y, z;
    };
    auto agree = [](test_session& t, const std::string& what, const point& p) {
        const double scale = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        const std::string e = "eval(s, vals, t = " + std::string(p.at) + ")";
        EXPECT_NEAR(number(t, e + "[0]"), p.x, 1e-10 * scale) << what << " at t = " << p.at;
        EXPECT_NEAR(number(t, e + "[1]"), p.y, 1e-10 * scale) << what << " at t = " << p.at;
        EXPECT_NEAR(number(t, e + "[2]"), p.z, 1e-10 * scale) << what << " at t = " << p.at;
    };
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nB := (1 + t^2/10)*[0, 0, 1]\nE := [1, 0, 0]\n"
                    "P := ode(r'' = r' x B + E, r(0) = r0, r'(0) = v0)\ns := solve(P)\n"
                    "vals := [r0 = [0, 0, 0], v0 = [0, 0, 0]]"),
              0)
        << t.err.str();
    const auto start = std::chrono::steady_clock::now();
    agree(t, "B = 1 + t^2/10", {"15", 0.6154247254800357, -4.164795524554531, 0});
    agree(t, "B = 1 + t^2/10", {"30", 0.5835726863240753, -4.528816119743718, 0});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 20.0);  // measured 0.2 s for the six evaluations
    // and against Boost.Odeint (rkf78 at 1e-12) on the equation over [0, 30]: measured 2.8e-12
    EXPECT_LT(number(t, "verify(P, s, vals, 30, 30)"), 1e-9);
    // a sign-changing B = 1/2 + sin(3 t) (was refused at t = 0.01: a piece of the inner
    // quadrature judged by its own size), at short and long times
    ASSERT_EQ(t.run("B := (1/2 + sin(3*t))*[0, 0, 1]\nP := ode(r'' = r' x B + E, r(0) = r0, r'(0) = v0)\n"
                    "s := solve(P)"),
              0)
        << t.err.str();
    agree(t, "B = 1/2 + sin(3 t)", {"0.006", 1.7999986009349372e-05, -1.8323984455973811e-08, 0});
    agree(t, "B = 1/2 + sin(3 t)", {"1", 0.43392799792535519, -0.19789904122954494, 0});
    agree(t, "B = 1/2 + sin(3 t)", {"5", 7.0391503723900515, -7.1205952624557716, 0});
    agree(t, "B = 1/2 + sin(3 t)", {"20", 6.8780478146160586, -39.787317322235587, 0});
    // another sign-changing B along a literal axis, with m, q, E of every direction, r0, v0
    ASSERT_EQ(t.run("vector E0\npositive m\nB := (-3/10 + 2*sin(7/10*t))*[0, 3/5, 4/5]\n"
                    "P := ode(m*r'' = q*(r' x B + E0), r(0) = r0, r'(0) = v0)\ns := solve(P)\n"
                    "vals := [m = 2, q = -3/2, E0 = [0.7, -0.2, 0.4], r0 = [1, 2, 3], v0 = [1/5, -1/10, 2/5]]"),
              0)
        << t.err.str();
    agree(t, "B = -3/10 + 2 sin(7 t/10)", {"0.006", 1.0011892681366665, 1.9994020618586408, 3.0023950786060194});
    agree(t, "B = -3/10 + 2 sin(7 t/10)", {"2", 0.43779474916155875, 1.8697496297542389, 3.372687777684321});
    agree(t, "B = -3/10 + 2 sin(7 t/10)", {"12", -0.7154632733511337, -4.9843543852141785, -1.3617342110893615});
}

// (issue 27) A force across the axis whose dependence on t sits inside a literal,
// cos(t) [1, 0, 0] read as [cos(t), 0, 0]: the t of the literal goes into Duhamel's integral
// (terms_in_time), it is not a constant vector left outside (which gave [0.49998, 0.47423, 0]
// for the first problem). Each result is compared at t = 2 (r0 = v0 = 0) with an independent
// integration (mpmath's Taylor odefun at 20 digits, printed to 13: the bound 1e-11 is the
// printed digits; the closed forms are evaluated exactly, the integral objects by
// Gauss-Kronrod to ~1e-13), with Boost.Odeint (verify, same bound as the tests above) and
// proved exactly by check.
TEST(FixedAxis, ForceWithTimeInsideALiteralAcrossTheAxis) {
    struct variant {
        const char* axis;
        const char* left;   // what is added to the rotating-frame operator
        const char* force;
        double x, y, z;     // r(2) from r0 = v0 = 0 (mpmath)
    };
    for (const variant& c :
         {variant{"[0, 0, 1]", "", "cos(t)*[1, 0, 0]", -1.157846573629, -0.6739508842326, 0},
          variant{"[0, 0, 1]", "", "t*[1, 0, 0]", -0.3688611565375, -0.986064465171, 0},
          variant{"[0, 0, 1]", " + 9*r", "cos(t)*[1, 0, 0]", 0.1580956130641, 0.05742946613099, 0},
          variant{"[0, 0, 1]", "", "cos(3*t)*[1, 0, 0]", -0.3065135148444, 0.3782707213432, 0},
          variant{"[1, 1, 0]", "", "cos(t)*[1, 0, 0]", 0.175390335176, 1.240756501371, -0.4744065668966}}) {
        test_session t;
        const std::string what = std::string("w = (1/2 + t) ") + c.axis + c.left + ", F = " + c.force;
        ASSERT_EQ(t.run(std::string("vector r0, v0\nw := (1/2 + t)*") + c.axis +
                        "\nB := ode(r'' + 2*w x r' + w' x r + w x (w x r)" + c.left + " = " + c.force +
                        ", r(0) = r0, r'(0) = v0)\nb := solve(B)\nzero := [r0 = [0, 0, 0], v0 = [0, 0, 0]]"),
                  0)
            << what << ": " << t.err.str();
        EXPECT_NEAR(number(t, "eval(b, zero, t = 2)[0]"), c.x, 1e-11) << what;
        EXPECT_NEAR(number(t, "eval(b, zero, t = 2)[1]"), c.y, 1e-11) << what;
        EXPECT_NEAR(number(t, "eval(b, zero, t = 2)[2]"), c.z, 1e-11) << what;
        EXPECT_LT(number(t, "verify(B, b, [r0 = [1, 0.5, -0.2], v0 = [0.1, 0.3, 0.7]], 5)"), 1e-8) << what;
        EXPECT_TRUE(t.val("check(B, b)").as_bool()) << what;
    }
}

// The same class held out from the reproducer: t inside literals along and across a skew
// axis with a symbolic rate and k, a component with t and one without, a literal force that
// is not a multiple of one vector, the same force written as a literal and as c(t) V.
TEST(FixedAxis, ForcesWithTimeInLiteralsAlongAndAcrossAnyAxis) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nw := (1/2 + 7/10*t)*[3, -4, 12]\n"
                    "P := ode(r'' + 2*w x r' + w' x r + w x (w x r) + 2*r = [t*exp(-t), 2, sin(2*t)], r(0) = r0, "
                    "r'(0) = v0)\np := solve(P)\n"
                    "W := (1 + t)*[0, 0, 1]\n"
                    "Q := ode(r'' + 2*W x r' + W' x r + W x (W x r) = [cos(t), t^2, exp(-t)], r(0) = r0, "
                    "r'(0) = v0)\nq := solve(Q)\n"
                    "Q2 := ode(r'' + 2*W x r' + W' x r + W x (W x r) = cos(t)*[1, 0, 0] + t^2*[0, 1, 0] + "
                    "exp(-t)*[0, 0, 1], r(0) = r0, r'(0) = v0)\nq2 := solve(Q2)\n"
                    "vals := [r0 = [1, 0.5, -0.2], "
                    "v0 = [0.1, 0.3, 0.7]]"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(P, p)").as_bool());
    EXPECT_TRUE(t.val("check(Q, q)").as_bool());
    EXPECT_TRUE(t.val("check(Q2, q2)").as_bool());
    EXPECT_LT(number(t, "verify(P, p, vals, 3, 6)"), 1e-8);
    EXPECT_LT(number(t, "verify(Q, q, vals, 3, 6)"), 1e-8);
    // the vertical motion of Q is z'' = exp(-t): z = z0 + (vz0 + 1) t - 1 + exp(-t)
    EXPECT_NEAR(number(t, "eval(q . [0, 0, 1], vals, t = 3)"), -0.2 + 1.7 * 3 - 1 + std::exp(-3.0), 1e-13);
    for (const char* k : {"0", "1", "2"})
        EXPECT_NEAR(number(t, std::string("eval(q, vals, t = 2)[") + k + "]"),
                    number(t, std::string("eval(q2, vals, t = 2)[") + k + "]"), 1e-13)
            << k;
}

// (issue 27) solve never returns what its residual at one point sees as nonzero: the witness
// (mechanics/solution_witness.h) sees a wrong candidate, with and without integral objects
// and with floats, and require_witness throws internal_error naming the problem; it sees
// nothing in the right solutions (exact, with floats, with integral objects).
TEST(FixedAxis, TheWitnessSeesAWrongSolution) {
    using namespace symrep;
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0, u\nw := (1/2 + t)*[0, 0, 1]\n"
                    "B := ode(r'' + 2*w x r' + w' x r + w x (w x r) = cos(t)*[1, 0, 0], r(0) = r0, r'(0) = v0)\n"
                    "b := solve(B)\n"
                    "C := ode(v' = v x (exp(-t^2)*[0, 0, 1]) + [1, 0, 0], v(0) = v0)\nc := solve(C)\n"
                    "F := ode(r'' + 2*u x r' + 0.25*r = [0, 0, -9.81], r(0) = r0, r'(0) = v0)\nf := solve(F)"),
              0)
        << t.err.str();
    const auto& B = t.val("B").as_problem();
    const auto& C = t.val("C").as_problem();
    const auto& F = t.val("F").as_problem();
    const GiNaC::ex b = t.ex("b"), c = t.ex("c"), f = t.ex("f"), e1 = vector_literal(1, 0, 0), T = B.t;
    EXPECT_FALSE(mechanics::witness(B, b).seen_nonzero);
    EXPECT_FALSE(mechanics::witness(C, c).seen_nonzero);
    EXPECT_FALSE(mechanics::witness(F, f).seen_nonzero);
    // wrong by t^3/1000 e1: residual component 1 is 6 t/1000 - (1/2 + t)^2 t^3/1000 (r'' and
    // w x (w x r)) at t = 7/10
    const mechanics::witness_report w = mechanics::witness(B, b + GiNaC::pow(T, 3) / 1000 * e1);
    EXPECT_TRUE(w.seen_nonzero);
    EXPECT_NE(w.what.find("residual"), std::string::npos) << w.what;
    EXPECT_NEAR(w.value, 6 * 0.7 / 1000 - 1.2 * 1.2 * 0.343 / 1000, 1e-12);
    EXPECT_TRUE(mechanics::witness(C, c + GiNaC::pow(T, 3) / 1000 * e1).seen_nonzero);  // integral objects
    EXPECT_TRUE(mechanics::witness(B, b + e1 / 1000).seen_nonzero);
    // with floats: 1e-3 relative is seen (rounding is bounded by 1e-12 of the terms' magnitude)
    EXPECT_TRUE(mechanics::witness(F, f * GiNaC::numeric(1.001)).seen_nonzero);
    // the initial value alone: 2 e^-t solves x' + x = 0 but not x(0) = 1
    ASSERT_EQ(t.run("X := ode(x' + x = 0, x(0) = 1)"), 0) << t.err.str();
    const auto& X = t.val("X").as_problem();
    const mechanics::witness_report wx = mechanics::witness(X, 2 * GiNaC::exp(-X.t));
    EXPECT_TRUE(wx.seen_nonzero);
    EXPECT_NE(wx.what.find("initial value x(0)"), std::string::npos) << wx.what;
    EXPECT_FALSE(mechanics::witness(X, GiNaC::exp(-X.t)).seen_nonzero);
    try {
        mechanics::require_witness(B, b + GiNaC::pow(T, 3) / 1000 * e1);
        ADD_FAILURE() << "no error";
    } catch (const internal_error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("internal error"), std::string::npos) << msg;
        EXPECT_NE(msg.find("r(0) = r0"), std::string::npos) << msg;  // names the problem
        EXPECT_NE(msg.find("withheld"), std::string::npos) << msg;
    }
    EXPECT_NO_THROW(mechanics::require_witness(B, b));
}

// B = b(t) N with N a literal of decimals: the rate is multiplied into the floats at the
// assignment, each product rounded to the working precision, so the components are one
// direction only up to their last digits (turning_frame.cpp, float_direction). Read as
// the fixed axis N, solved, and compared with the integration of the equation as stated
// (rkf78 at 1e-12: 1e-9 as above). check cannot prove a residual with integral objects
// and float roundings in it: it says so, never false.
TEST(FixedAxis, AFieldOfDecimalsTimesARateIsAFixedAxis) {
    test_session t;
    ASSERT_EQ(t.run("vector E, r0, v0\nB := (3/4 + 2/3*t)*[0.1, 0.2, 0.3]\n"
                    "P := ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)\ns := solve(P)\n"
                    "vals := [m = 1, q = 1, E = [1, 0, 0], r0 = [0, 0, 0], v0 = [0, 1, 0]]"),
              0)
        << t.err.str();
    EXPECT_LT(number(t, "verify(P, s, vals, 2)"), 1e-9);
    EXPECT_NE(t.run("check(P, s)"), 0);
    EXPECT_NE(t.err.str().find("cannot decide"), std::string::npos) << t.err.str();
    // digits that differ beyond rounding are a turning direction: not read as an axis
    ASSERT_EQ(t.run("C := (3/4 + 2/3*t)*[0.1, 0.2, 0.3] + t*[0, 0, 1e-12]\n"
                    "Q := ode(m*v' = q*(v x C), v(0) = v0)"),
              0)
        << t.err.str();
    EXPECT_EQ(t.run("solve(Q)"), 0) << t.err.str();  // the turning frame's reduction
    EXPECT_NE(t.out.str().find("Magnus"), std::string::npos) << t.out.str();
}
