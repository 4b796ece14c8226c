// tests/test_moving_frame.cpp -- motion seen from a frame that rotates and translates ([CS21]
// Thms 11-12; mechanics/moving_frame.h): the inertial problem carried into the frame by
// moving_frame(P0, w, o), solved as r = R (psi - o), proved by check(P, s) and compared with
//   (a) verify(P, s, values, T): Boost.Odeint on the frame's equation as moving_frame wrote it, and
//   (b) an integration written here, independently of moving_frame: Newton's law in the inertial
//       frame carried into the frame by its kinematics, r'' = -2 w x r' - w' x r - w x (w x r)
//       - R o'' + R f(X, X', t), X = R^T r + o, X' = R^T (r' + w x r) + o', with R' = -W R
//       integrated beside r (18 states, Boost.Odeint dopri5 at 1e-13).
// Tolerance 1e-8 relative to the largest component: the integrations at 1e-12 .. 1e-13 leave
// 1e-11 .. 1e-10 over these spans (measured), so 1e-8 leaves two orders while a wrong sign of a
// term (Coriolis, the origin's acceleration, R for R^T) gives O(1e-2) or more.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>

#include "core/error.h"
#include "dual/dual.h"
#include "mechanics/moving_frame.h"
#include "vector/vector.h"
#include "lang/print_value.h"
#include "test_support.h"

using symrep::test::test_session;
using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

namespace {

double number(test_session& t, const std::string& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(t.ex(e))).to_double();
}

// The value of a script expression that is a list of three numbers.
V3 vec(test_session& t, const std::string& e) {
    const symrep::lang::value v = t.val(e);
    EXPECT_TRUE(v.is_list()) << e;
    V3 x = V3::Zero();
    if (!v.is_list() || v.as_list().size() != 3) return x;
    for (int i = 0; i < 3; ++i)
        x[i] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(v.as_list()[std::size_t(i)].as_ex())).to_double();
    return x;
}

M3 skew(const V3& w) {
    M3 W;
    W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return W;
}

// The frame (w, w', o, o', o'') and the inertial acceleration f(X, X', t).
struct frame_data {
    std::function<V3(double)> w, dw, o, o1, o2;
    std::function<V3(const V3&, const V3&, double)> f;
};

// (b) above: r and r' at time T from the frame's initial values.
std::array<V3, 2> integrate_in_frame(const frame_data& F, const V3& r0, const V3& v0, double T) {
    using state = std::array<double, 15>;
    state y{};
    for (int i = 0; i < 3; ++i) {
        y[std::size_t(4 * i)] = 1;  // R = I
        y[std::size_t(9 + i)] = r0[i];
        y[std::size_t(12 + i)] = v0[i];
    }
    auto rhs = [&](const state& s, state& ds, double t) {
        M3 R;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) R(i, j) = s[std::size_t(3 * i + j)];
        const V3 r(s[9], s[10], s[11]), v(s[12], s[13], s[14]), w = F.w(t);
        const M3 dR = -skew(w) * R;
        const V3 X = R.transpose() * r + F.o(t), X1 = R.transpose() * (v + w.cross(r)) + F.o1(t);
        const V3 a = -2 * w.cross(v) - F.dw(t).cross(r) - w.cross(w.cross(r)) - R * F.o2(t) + R * F.f(X, X1, t);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) ds[std::size_t(3 * i + j)] = dR(i, j);
        for (int i = 0; i < 3; ++i) {
            ds[std::size_t(9 + i)] = v[i];
            ds[std::size_t(12 + i)] = a[i];
        }
    };
    namespace odeint = boost::numeric::odeint;
    odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_dopri5<state>>(1e-13, 1e-13), rhs, y, 0.0,
                               T, 1e-3);
    return {V3(y[9], y[10], y[11]), V3(y[12], y[13], y[14])};
}

double relative(const V3& a, const V3& b) { return (a - b).norm() / std::max(1.0, b.norm()); }

}  // namespace

// Gravity seen from a frame turning at a constant rate whose origin accelerates: the closed form
// r = R (x0 + u0 t + (g - a) t^2/2) (Thm 12), proved by check and equal to the rotation operator's form.
TEST(MovingFrame, GravityInAnAcceleratingRotatingFrame) {
    test_session t;
    ASSERT_EQ(t.run("vector g, x0, u0, w, a\nP0 := ode(x'' = g, x(0) = x0, x'(0) = u0)\n"
                    "P := moving_frame(P0, w, a*t^2/2 + [0, 1, 0]*t)\ns := solve(P)"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
    EXPECT_TRUE(t.val("s == F(-w, x0 + u0*t + g*t^2/2 - a*t^2/2 - [0, 1, 0]*t)").as_bool());
    // the frame's initial values: r(0) = x0 - o(0), r'(0) = u0 - o'(0) - w x r(0)
    ASSERT_EQ(t.run("vals := [w = [0.3, -0.2, 0.5], g = [0, 0, -9.81], a = [1, 0.5, 0], x0 = [1, 2, 3], "
                    "u0 = [0.5, -1, 2]]"),
              0);
    EXPECT_LT(number(t, "verify(P, s, vals, 10)"), 1e-8);
    frame_data F;
    const V3 w(0.3, -0.2, 0.5), g(0, 0, -9.81), a(1, 0.5, 0), e2(0, 1, 0);
    F.w = [w](double) { return w; };
    F.dw = [](double) { return V3::Zero(); };
    F.o = [a, e2](double x) { return V3(a * x * x / 2 + e2 * x); };
    F.o1 = [a, e2](double x) { return V3(a * x + e2); };
    F.o2 = [a](double) { return a; };
    F.f = [g](const V3&, const V3&, double) { return g; };
    const V3 x0(1, 2, 3), u0(0.5, -1, 2);
    const auto ref = integrate_in_frame(F, x0, u0 - e2 - w.cross(x0), 7);
    EXPECT_LT(relative(vec(t, "eval(s, vals, t = 7)"), ref[0]), 1e-9);
    EXPECT_LT(relative(vec(t, "eval(s', vals, t = 7)"), ref[1]), 1e-9);
}

// A charge in uniform inertial fields E, B seen from a frame turning about a fixed axis at a
// varying rate, its origin on a circle: closed form, check, and both integrations.
TEST(MovingFrame, ChargeInElectricAndMagneticFieldsFromAFixedAxisFrame) {
    test_session t;
    ASSERT_EQ(t.run("P0 := ode(x'' = k*(x' x [0, 0, b] + [e0, 0, 0]), x(0) = [1, 0, 0], x'(0) = [0, 1, 1/2])\n"
                    "W := (1/2 + sin(t))*[0, 3/5, 4/5]\nP := moving_frame(P0, W, [cos(t) - 1, sin(t), 0])\n"
                    "s := solve(P)"),
              0)
        << t.err.str();
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
    ASSERT_EQ(t.run("vals := [k = 3/2, b = 2, e0 = 7/10]"), 0);
    EXPECT_LT(number(t, "verify(P, s, vals, 12)"), 1e-8);
    frame_data F;
    const V3 u(0, 0.6, 0.8), B(0, 0, 2), E(0.7, 0, 0);
    F.w = [u](double x) { return V3((0.5 + std::sin(x)) * u); };
    F.dw = [u](double x) { return V3(std::cos(x) * u); };
    F.o = [](double x) { return V3(std::cos(x) - 1, std::sin(x), 0); };
    F.o1 = [](double x) { return V3(-std::sin(x), std::cos(x), 0); };
    F.o2 = [](double x) { return V3(-std::cos(x), -std::sin(x), 0); };
    F.f = [B, E](const V3&, const V3& X1, double) { return V3(1.5 * (X1.cross(B) + E)); };
    const V3 r0(1, 0, 0), v0 = V3(0, 1, 0.5) - V3(0, 1, 0) - (0.5 * u).cross(r0);
    const auto ref = integrate_in_frame(F, r0, v0, 9);
    EXPECT_LT(relative(vec(t, "eval(s, vals, t = 9)"), ref[0]), 1e-9);
    EXPECT_LT(relative(vec(t, "eval(s', vals, t = 9)"), ref[1]), 1e-9);
}

// Kepler with the attracting centre at the inertial origin, seen from a frame in regular
// precession whose origin moves: R closed, psi by universal variables (the reduction object with
// the origin); verify and the independent integration agree.
TEST(MovingFrame, KeplerAboutTheInertialOriginFromAPrecessingTranslatingFrame) {
    test_session t;
    ASSERT_EQ(t.run("P0 := ode(x'' + mu*x/|x|^3 = 0, x(0) = [1, 0, 0], x'(0) = [0, 1.1, 0.2])\n"
                    "wp := [pa*sin(nu*t), pa*cos(nu*t), pb]\nP := moving_frame(P0, wp, [t/2, 0, t^2/10])\n"
                    "s := solve(P)"),
              0)
        << t.err.str();
    ASSERT_EQ(t.run("vals := [pa = 0.7, nu = 1.3, pb = -0.5, mu = 1]"), 0);
    EXPECT_LT(number(t, "verify(P, s, vals, 5)"), 1e-8);
    frame_data F;
    F.w = [](double x) { return V3(0.7 * std::sin(1.3 * x), 0.7 * std::cos(1.3 * x), -0.5); };
    F.dw = [](double x) { return V3(0.91 * std::cos(1.3 * x), -0.91 * std::sin(1.3 * x), 0); };
    F.o = [](double x) { return V3(x / 2, 0, x * x / 10); };
    F.o1 = [](double x) { return V3(0.5, 0, x / 5); };
    F.o2 = [](double) { return V3(0, 0, 0.2); };
    F.f = [](const V3& X, const V3&, double) { return V3(-X / std::pow(X.norm(), 3)); };
    const V3 r0(1, 0, 0), v0 = V3(0, 1.1, 0.2) - V3(0.5, 0, 0) - V3(0, 0.7, -0.5).cross(r0);
    const auto ref = integrate_in_frame(F, r0, v0, 4);
    EXPECT_LT(relative(vec(t, "eval(s, vals, t = 4)"), ref[0]), 1e-9);
    EXPECT_LT(relative(vec(t, "eval(s', vals, t = 4)"), ref[1]), 1e-9);
}

// A turning w (every component changes sign) with a translating origin: the numeric Thm 12,
// r = Q (psi - o) with Q by Magnus on SO(3) and psi by universal variables, against (b).
TEST(MovingFrame, KeplerFromATurningTranslatingFrameNumerically) {
    using namespace symrep::mechanics;
    numeric_moving_frame N;
    N.rotating.w = [](double x) { return V3(0.7 * std::sin(1.3 * x), 0.4 * std::cos(2.1 * x), -0.5); };
    N.rotating.w_dot = [](double x) { return V3(0.91 * std::cos(1.3 * x), -0.84 * std::sin(2.1 * x), 0); };
    N.rotating.field = central_field::kepler(1.0);
    const V3 X0(1, 0.5, -0.2), V0(0.1, 0.9, 0.3);
    // y = Q psi with y(0) = psi(0), y'(0) = psi'(0) - w(0) x psi(0)
    N.rotating.r0 = X0;
    N.rotating.v0 = V0 - N.rotating.w(0).cross(X0);
    N.origin = [](double x) { return V3(std::sin(x), x / 3, 0); };
    N.origin_velocity = [](double x) { return V3(std::cos(x), 1.0 / 3, 0); };
    const auto got = moving_frame_states(N, {1.0, 3.0, 6.0});
    frame_data F;
    F.w = N.rotating.w;
    F.dw = N.rotating.w_dot;
    F.o = N.origin;
    F.o1 = N.origin_velocity;
    F.o2 = [](double x) { return V3(-std::sin(x), 0, 0); };
    F.f = [](const V3& X, const V3&, double) { return V3(-X / std::pow(X.norm(), 3)); };
    const V3 r0 = X0 - F.o(0), v0 = V0 - F.o1(0) - F.w(0).cross(r0);
    const double T[] = {1.0, 3.0, 6.0};
    for (int k = 0; k < 3; ++k) {
        const auto ref = integrate_in_frame(F, r0, v0, T[k]);
        EXPECT_LT(relative(got[std::size_t(k)].r, ref[0]), 1e-9) << "t = " << T[k];
        EXPECT_LT(relative(got[std::size_t(k)].v, ref[1]), 1e-9) << "t = " << T[k];
    }
    // the same frame in the language: R(t) o(t) has no closed form; the frame's equation holds it as
    // R_o (a vector function of its own), the solution is the reduction object with the origin
    test_session t;
    ASSERT_EQ(t.run("P0 := ode(x'' + x/|x|^3 = 0, x(0) = [1, 0.5, -0.2], x'(0) = [0.1, 0.9, 0.3])\n"
                    "P := moving_frame(P0, [0.7*sin(1.3*t), 0.4*cos(2.1*t), -0.5], [sin(t), t/3, 0])\n"
                    "p := solve(P)"),
              0)
        << t.err.str();
    for (int k = 0; k < 3; ++k) {
        const auto ref = integrate_in_frame(F, r0, v0, T[k]);
        EXPECT_LT(relative(vec(t, "eval(p, [], t = " + std::to_string(T[k]) + ")"), ref[0]), 1e-8) << T[k];
        EXPECT_LT(relative(vec(t, "eval(p', [], t = " + std::to_string(T[k]) + ")"), ref[1]), 1e-8) << T[k];
    }
    EXPECT_LT(number(t, "verify(P, p, [], 5)"), 1e-8);
    // without a translation the turning frame is the thesis's VI.3 problem: the reduction object
    ASSERT_EQ(t.run("Q := moving_frame(P0, [0.7*sin(1.3*t), 0.4*cos(2.1*t), -0.5])\nq := solve(Q)"), 0)
        << t.err.str();
    EXPECT_LT(number(t, "verify(Q, q, [], 5)"), 1e-8);
}

// Gravity and a charge in E and B seen from a frame that turns with a w(t) without a closed R and
// whose origin moves: the frame's equation holds R g, R o, R o', R o'' (R E, R B) as vector functions
// of their own (R_V1, R_o, ...); solve gives r = R (psi - o) with psi closed and R by Magnus; eval
// against the independent integration (b), verify against the frame's equation with R beside it,
// check names the theorem proved below for every R.
TEST(MovingFrame, GravityAndChargeInATurningTranslatingFrame) {
    frame_data F;
    F.w = [](double x) { return V3(0.1 * std::sin(x), 0.2, 0.05 * x); };
    F.dw = [](double x) { return V3(0.1 * std::cos(x), 0, 0.05); };
    F.o = [](double x) { return V3(x * x, std::sin(x), 0); };
    F.o1 = [](double x) { return V3(2 * x, std::cos(x), 0); };
    F.o2 = [](double x) { return V3(2, -std::sin(x), 0); };
    F.f = [](const V3&, const V3&, double) { return V3(0, 0, -9.81); };
    const V3 X0(1, 2, 3), U0(0.5, 0, 1);
    const V3 r0 = X0 - F.o(0), v0 = U0 - F.o1(0) - F.w(0).cross(r0);
    test_session t;
    ASSERT_EQ(t.run("w := [0.1*sin(t), 0.2, 0.05*t]\n"
                    "P := moving_frame(ode(x'' = [0, 0, -9.81], x(0) = [1, 2, 3], x'(0) = [0.5, 0, 1]), w, "
                    "[t^2, sin(t), 0])\np := solve(P)"),
              0)
        << t.err.str();
    const std::string shown = symrep::lang::print_value(t.val("p"));
    EXPECT_NE(shown.find("R_ddo = R [2, -sin(t), 0]"), std::string::npos) << shown;
    EXPECT_NE(shown.find("R_V1 = R [0, 0, -9.81]"), std::string::npos) << shown;
    for (const double T : {0.5, 2.0, 4.0}) {
        const auto ref = integrate_in_frame(F, r0, v0, T);
        EXPECT_LT(relative(vec(t, "eval(p, [], t = " + std::to_string(T) + ")"), ref[0]), 1e-8) << T;
        EXPECT_LT(relative(vec(t, "eval(p', [], t = " + std::to_string(T) + ")"), ref[1]), 1e-8) << T;
    }
    EXPECT_LT(number(t, "verify(P, p, [], 4)"), 1e-8);
    EXPECT_NE(t.run("check(P, p)"), 0);
    EXPECT_NE(t.err.str().find("proved once for all"), std::string::npos) << t.err.str();
    // a charge, the fields given as values
    F.o = F.o1 = F.o2 = [](double) { return V3::Zero(); };
    F.f = [](const V3&, const V3& X1, double) { return V3(X1.cross(V3(0, 0, 1)) + V3(0.1, 0, 0)); };
    ASSERT_EQ(t.run("vector B, E\nC := moving_frame(ode(x'' = x' x B + E, x(0) = [0, 0, 0], x'(0) = [1, 0, 0]), w)\n"
                    "c := solve(C)\nv := [B = [0, 0, 1], E = [0.1, 0, 0]]"),
              0)
        << t.err.str();
    for (const double T : {1.0, 3.0}) {
        const auto ref = integrate_in_frame(F, V3::Zero(), V3(1, 0, 0), T);
        EXPECT_LT(relative(vec(t, "eval(c, v, t = " + std::to_string(T) + ")"), ref[0]), 1e-8) << T;
    }
    EXPECT_LT(number(t, "verify(C, c, v, 3)"), 1e-8);
    // a wrong frame (the sign of w) is seen by the independent integration
    F.w = [](double x) { return V3(-0.1 * std::sin(x), -0.2, -0.05 * x); };
    F.dw = [](double x) { return V3(-0.1 * std::cos(x), 0, -0.05); };
    EXPECT_GT(relative(vec(t, "eval(c, v, t = 3)"), integrate_in_frame(F, V3::Zero(), V3(1, 0, 0), 3)[0]), 1e-3);
}

// [CS21] Thm 11 once for all: for ANY R(t) with R' = -W R (nine free entries), any w, w', any paths
// psi and o (free values and derivatives), r = R (psi - o) gives
//   r + R o = R psi,  r' + w x r + R o' = R psi',  L[r] + R o'' = R psi''
// (L[r] = r'' + 2 w x r' + w' x r + w x (w x r)): the substitutions that make the frame's equation
// (moving_frame_problem) R times the inertial one. Derivatives by the chain rule on the free symbols.
TEST(MovingFrame, Theorem11HoldsForEveryRotation) {
    using GiNaC::ex;
    std::vector<GiNaC::realsymbol> syms;
    const auto sym = [&](const std::string& n) {
        syms.emplace_back(n);
        return ex(syms.back());
    };
    GiNaC::matrix R(3, 3);
    for (unsigned i = 0; i < 9; ++i) R(i / 3, i % 3) = sym("R" + std::to_string(i));
    const auto vec3 = [&](const std::string& n) {
        return GiNaC::matrix(3, 1, GiNaC::lst{sym(n + "1"), sym(n + "2"), sym(n + "3")});
    };
    const GiNaC::matrix w = vec3("w"), wd = vec3("wd"), p = vec3("p"), p1 = vec3("pa"), p2 = vec3("pb"),
                        p3 = vec3("pc"), o = vec3("o"), o1 = vec3("oa"), o2 = vec3("ob"), o3 = vec3("oc");
    const auto skew = [](const GiNaC::matrix& v) {
        return GiNaC::matrix(3, 3, GiNaC::lst{0, -v(2, 0), v(1, 0), v(2, 0), 0, -v(0, 0), -v(1, 0), v(0, 0), 0});
    };
    const auto cross = [&](const GiNaC::matrix& a, const GiNaC::matrix& b) { return skew(a).mul(b); };
    // the derivative of each free symbol
    GiNaC::exmap d;
    const GiNaC::matrix dR = skew(w).mul_scalar(-1).mul(R);
    for (unsigned i = 0; i < 9; ++i) d[R(i / 3, i % 3)] = dR(i / 3, i % 3);
    const std::pair<const GiNaC::matrix*, const GiNaC::matrix*> chains[] = {
        {&w, &wd}, {&p, &p1}, {&p1, &p2}, {&p2, &p3}, {&o, &o1}, {&o1, &o2}, {&o2, &o3}};
    for (const auto& [x, dx] : chains)
        for (unsigned i = 0; i < 3; ++i) d[(*x)(i, 0)] = (*dx)(i, 0);
    const auto D = [&](const GiNaC::matrix& v) {
        GiNaC::matrix out(3, 1);
        for (unsigned i = 0; i < 3; ++i) {
            ex s = 0;
            for (const auto& [x, dx] : d) s += v(i, 0).diff(GiNaC::ex_to<GiNaC::symbol>(x)) * dx;
            out(i, 0) = GiNaC::expand(s);
        }
        return out;
    };
    const auto zero = [](const GiNaC::matrix& m) {
        for (unsigned i = 0; i < 3; ++i)
            if (!GiNaC::expand(m(i, 0)).is_zero()) return false;
        return true;
    };
    const GiNaC::matrix r = R.mul(p.sub(o)), r1 = D(r), r2 = D(r1);
    const GiNaC::matrix L = r2.add(cross(w, r1).mul_scalar(2)).add(cross(wd, r)).add(cross(w, cross(w, r)));
    EXPECT_TRUE(zero(r.add(R.mul(o)).sub(R.mul(p))));
    EXPECT_TRUE(zero(r1.add(cross(w, r)).add(R.mul(o1)).sub(R.mul(p1))));
    EXPECT_TRUE(zero(L.add(R.mul(o2)).sub(R.mul(p2))));
    // with R' = +W R (the transposed convention) the Coriolis form breaks
    for (unsigned i = 0; i < 9; ++i) d[R(i / 3, i % 3)] = -dR(i / 3, i % 3);
    const GiNaC::matrix s1 = D(R.mul(p.sub(o)));
    EXPECT_FALSE(zero(s1.add(cross(w, r)).add(R.mul(o1)).sub(R.mul(p1))));
}

// At digits(40) a float value (pa = 0.7) was put in as the exact rational of its binary value (a
// 2^133 denominator): verify's system carried integers of 300 digits through sqrt and |x|^-3 and
// stopped with "the solution is not finite". Values are the decimals they print as now.
TEST(MovingFrame, FloatValuesAtFortyDigits) {
    test_session t;
    ASSERT_EQ(t.run("digits(40)\nP0 := ode(x'' + mu*x/|x|^3 = 0, x(0) = [1, 0, 0], x'(0) = [0, 1.1, 0.2])\n"
                    "P := moving_frame(P0, [pa*sin(nu*t), pa*cos(nu*t), pb], [t/2, 0, t^2/10])\ns := solve(P)"),
              0)
        << t.err.str();
    EXPECT_LT(number(t, "verify(P, s, [pa = 0.7, nu = 1.3, pb = -0.5, mu = 1], 5)"), 1e-8) << t.err.str();
    ASSERT_EQ(t.run("digits(17)"), 0);
}

// Bad inputs are refused by name.
TEST(MovingFrame, BadInputsAreRefused) {
    test_session t;
    ASSERT_EQ(t.run("vector x0, w\nA := ode(x' = w x x, x(0) = x0)\nS := ode(y'' = -y, y(0) = 1, y'(0) = 0)"), 0);
    EXPECT_NE(t.run("moving_frame(A, w, 0)"), 0);
    EXPECT_NE(t.err.str().find("second order"), std::string::npos) << t.err.str();
    EXPECT_NE(t.run("moving_frame(S, w, 0)"), 0);
    EXPECT_NE(t.run("moving_frame(ode(x'' = 0, x(0) = x0, x'(0) = 0*x0), [1/t, 0, 0], 0)"), 0);
    EXPECT_NE(t.err.str().find("t = 0"), std::string::npos) << t.err.str();
}

// Thm 12 for a rigid body: the frame's dual tensor Q^ = (I + eps skew(d)) R carries a line of the
// inertial frame, x^ = a + eps (p x a), to the line through R p + d with direction R a. The line
// of a particle's motion (through psi, along psi') is seen as the line through r = R (psi - o)
// along R psi': its dual part is r x R psi', proved exactly.
TEST(MovingFrame, TheDualTensorCarriesLinesIntoTheFrame) {
    using namespace symrep;
    test_session t;
    ASSERT_EQ(t.run("vector g, x0, u0, w, a\nP0 := ode(x'' = g, x(0) = x0, x'(0) = u0)\n"
                    "P := moving_frame(P0, w, a*t^2/2)\ns := solve(P)\npsi := solve(P0)"),
              0)
        << t.err.str();
    const mechanics::cauchy_problem& P = t.val("P").as_problem();
    const auto frame = mechanics::moving_frame_of(P);
    ASSERT_TRUE(frame);
    const GiNaC::ex psi = t.ex("psi"), s = t.ex("s"), tt = t.ex("t");
    const GiNaC::ex dpsi = diff_t(psi, tt);
    const GiNaC::ex line = dual::make_dual(dpsi, cross(psi, dpsi));
    const GiNaC::ex seen = mechanics::seen_from_frame(*frame, line, tt);
    const GiNaC::ex Rdpsi = dual::primal(seen);
    EXPECT_TRUE(equal(Rdpsi, t.ex("F(-w, diff(psi, t))")));
    EXPECT_TRUE(equal(dual::dual_part(seen), cross(s, Rdpsi)));
}
