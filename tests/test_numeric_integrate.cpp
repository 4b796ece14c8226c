// Tests of the reference integrator (numeric/integrate.h) and of verify()
// (numeric/verify.h) against exact solutions.
//
// Tolerance argument: each stepper keeps the local error per step below
// abs_tol + rel_tol |y| = 1e-10 (scaled); over [0, 20] the global error is the
// sum of the propagated local errors. For the oscillator the propagator is a
// rotation (norm 1), for the rotating frame it grows linearly in t (the
// secular term (v0 + W r0) t), so the global error is ~1e-10 times the number
// of steps that contribute, times a factor ~20: below 1e-8 is the bound
// (observed values are 1e-11 .. 1e-9).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/error.h"
#include "numeric/integrate.h"
#include "numeric/verify.h"

using namespace symrep;
using namespace symrep::num;
using GiNaC::ex;
using GiNaC::symbol;

namespace {

const stepper_kind all_steppers[] = {stepper_kind::rkf78, stepper_kind::bulirsch_stoer, stepper_kind::dopri5};

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
    Eigen::Matrix3d W;
    W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return W;  // W r = w x r
}

/// x'' = -omega^2 x, x(0) = x0, x'(0) = v0, with its exact solution.
struct oscillator {
    double omega = 1.7, x0 = 0.8, v0 = -0.3;
    rhs_function rhs() const {
        return [w = omega](double, const double* y, double* d) {
            d[0] = y[1];
            d[1] = -w * w * y[0];
        };
    }
    double x(double t) const { return x0 * std::cos(omega * t) + v0 / omega * std::sin(omega * t); }
};

}  // namespace

// rk4 with a fixed step: fourth order, so halving the step divides the global
// error by about 16 (between 12 and 20 allowed); 4 evaluations per step; every
// output time is hit exactly (the last step before it is shortened); no step: type_error.
TEST(NumericIntegrate, FixedStepRungeKutta4) {
    const oscillator h;
    const std::vector<double> times = linspace(0, 20, 11);
    auto error_with = [&](double step, integration_result& r) {
        integration_options o;
        o.stepper = stepper_kind::rk4;
        o.fixed_step = step;
        r = integrate(h.rhs(), 0.0, {h.x0, h.v0}, times, o);
        double err = 0;
        for (std::size_t i = 0; i < times.size(); ++i) err = std::max(err, std::fabs(r.states(i, 0) - h.x(times[i])));
        return err;
    };
    integration_result r1, r2;
    const double e1 = error_with(0.02, r1), e2 = error_with(0.01, r2);
    EXPECT_LT(e1, 1e-5);
    EXPECT_GT(e1 / e2, 12.0);
    EXPECT_LT(e1 / e2, 20.0);
    EXPECT_EQ(r1.rhs_evaluations, 4 * r1.steps);
    EXPECT_GE(r1.steps, 1000u);  // 10 intervals of 2 = 100 steps of 0.02 each (+ a rounding remainder)
    EXPECT_LE(r1.steps, 1010u);
    EXPECT_EQ(stepper_from_name("rk4"), stepper_kind::rk4);
    EXPECT_STREQ(stepper_name(stepper_kind::rk4), "rk4");
    integration_options o;
    o.stepper = stepper_kind::rk4;
    EXPECT_THROW(integrate(h.rhs(), 0.0, {h.x0, h.v0}, times, o), type_error);
}

TEST(NumericIntegrate, HarmonicOscillatorEveryStepper) {
    const oscillator h;
    const double omega = h.omega, x0 = h.x0, v0 = h.v0;
    const rhs_function f = h.rhs();
    const std::vector<double> times = linspace(0, 20, 41);
    for (stepper_kind k : all_steppers) {
        integration_options o;
        o.stepper = k;
        const integration_result r = integrate(f, 0.0, {x0, v0}, times, o);
        ASSERT_EQ(r.states.rows(), 41);
        double err = 0;
        for (std::size_t i = 0; i < times.size(); ++i) {
            const double t = times[i];
            const double v = -x0 * omega * std::sin(omega * t) + v0 * std::cos(omega * t);
            err = std::max({err, std::fabs(r.states(i, 0) - h.x(t)), std::fabs(r.states(i, 1) - v)});
        }
        EXPECT_LT(err, 1e-8) << stepper_name(k);
        EXPECT_EQ(r.state(0)[0], x0);  // t0 is among the output times: the initial state itself
        EXPECT_GT(r.rhs_evaluations, 100u) << stepper_name(k);
        EXPECT_LT(r.rhs_evaluations, 200000u) << stepper_name(k);
        EXPECT_GT(r.steps, 0u);
        EXPECT_GE(r.wall_seconds, 0.0);
        RecordProperty(std::string("evals_") + stepper_name(k), static_cast<int>(r.rhs_evaluations));
    }
}

TEST(NumericIntegrate, RotatingFrameLinearSystemEveryStepper) {
    // r'' + 2 W r' + W^2 r = 0, exact r = exp(-W t) (r0 + (v0 + W r0) t).
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 3; ++trial) {
        const Eigen::Vector3d w(u(rng), u(rng), u(rng)), r0(u(rng), u(rng), u(rng)), v0(u(rng), u(rng), u(rng));
        const Eigen::Matrix3d W = skew(w), W2 = W * W;
        auto f = [&](double, const double* y, double* d) {
            const Eigen::Map<const Eigen::Vector3d> r(y), v(y + 3);
            Eigen::Map<Eigen::Vector3d> dr(d), dv(d + 3);
            dr = v;
            dv = -2 * W * v - W2 * r;
        };
        const std::vector<double> times = linspace(0, 20, 21);
        Eigen::VectorXd y0(6);
        y0 << r0, v0;
        for (stepper_kind k : all_steppers) {
            integration_options o;
            o.stepper = k;
            const integration_result res = integrate(f, 0.0, y0, times, o);
            double err = 0;
            for (std::size_t i = 0; i < times.size(); ++i) {
                const double t = times[i];
                const Eigen::Matrix3d E = (-W * t).exp();
                const Eigen::Vector3d a = r0 + (v0 + W * r0) * t;
                const Eigen::Vector3d r = E * a;
                const Eigen::Vector3d v = -W * r + E * (v0 + W * r0);
                const Eigen::VectorXd y = res.state(i);
                err = std::max(err, (y.head<3>() - r).norm() / std::max(1.0, r.norm()));
                err = std::max(err, (y.tail<3>() - v).norm() / std::max(1.0, v.norm()));
            }
            EXPECT_LT(err, 1e-8) << stepper_name(k) << " trial " << trial;
            EXPECT_GT(res.rhs_evaluations, 0u);
        }
    }
}

TEST(NumericIntegrate, SymbolicSystemMatchesHandWritten) {
    // The rotating-frame system from symbolic right-hand sides with parameters w1, w2, w3.
    symbol t("t"), w1("w1"), w2("w2"), w3("w3");
    std::vector<ex> s;
    for (const char* n : {"x", "y", "z", "vx", "vy", "vz"}) s.push_back(symbol(n));
    const GiNaC::matrix W{{0, -w3, w2}, {w3, 0, -w1}, {-w2, w1, 0}};
    const GiNaC::matrix r{{s[0]}, {s[1]}, {s[2]}}, v{{s[3]}, {s[4]}, {s[5]}};
    const GiNaC::matrix acc = W.mul(v).mul_scalar(-2).add(W.mul(W).mul(r).mul_scalar(-1));
    const std::vector<ex> rhs = {s[3], s[4], s[5], acc(0, 0), acc(1, 0), acc(2, 0)};
    symbolic_system sys(rhs, t, s, {{w1, 0.3}, {w2, -0.5}, {w3, 0.8}});
    EXPECT_EQ(sys.dimension(), 6u);

    const Eigen::Vector3d w(0.3, -0.5, 0.8), r0(1, 0, 0.5), v0(0, 1, 0);
    const Eigen::Matrix3d Wn = skew(w);
    auto F = sys.function();
    const double y[6] = {1, 2, 3, 4, 5, 6};
    double d[6];
    F(0.0, y, d);
    const Eigen::Vector3d expect = -2 * Wn * Eigen::Vector3d(4, 5, 6) - Wn * Wn * Eigen::Vector3d(1, 2, 3);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(d[i], y[i + 3]);
        EXPECT_NEAR(d[i + 3], expect[i], 1e-14);
    }
    Eigen::VectorXd y0(6);
    y0 << r0, v0;
    const integration_result res = integrate(F, 0.0, y0, {20.0});
    const Eigen::Vector3d rt = (-Wn * 20.0).exp() * (r0 + (v0 + Wn * r0) * 20.0);
    EXPECT_LT((res.state(0).head<3>() - rt).norm() / rt.norm(), 1e-8);

    sys.set_parameter(w3, 0.0);
    sys.function()(0.0, y, d);
    const Eigen::Matrix3d W0 = skew(Eigen::Vector3d(0.3, -0.5, 0.0));
    const Eigen::Vector3d expect0 = -2 * W0 * Eigen::Vector3d(4, 5, 6) - W0 * W0 * Eigen::Vector3d(1, 2, 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(d[i + 3], expect0[i], 1e-14);
    F(0.0, y, d);  // the function made before keeps its parameter values
    EXPECT_NEAR(d[3], expect[0], 1e-14);
    EXPECT_THROW(sys.set_parameter(t, 1.0), type_error);

    // A symbol without value is named.
    symbol k("k");
    try {
        symbolic_system bad({s[1], -k * s[0]}, t, {s[0], s[1]});
        FAIL() << "no error";
    } catch (const type_error& e) {
        EXPECT_NE(std::string(e.what()).find("'k'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(symbolic_system({s[1]}, t, {s[0], s[1]}), type_error);
}

TEST(NumericIntegrate, BadArgumentsAndFailures) {
    auto f = [](double, const double* y, double* d) { d[0] = y[0]; };
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{}, {1.0}), type_error);
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{1.0}, {}), type_error);
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{1.0}, {2.0, 1.0}), type_error);
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{1.0}, {-1.0}), type_error);
    integration_options o;
    o.abs_tol = 0;
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{1.0}, {1.0}, o), type_error);
    EXPECT_THROW(stepper_from_name("euler"), type_error);
    EXPECT_EQ(stepper_from_name("dopri5"), stepper_kind::dopri5);

    // y' = y^2, y(0) = 1 blows up at t = 1: reported as symrep::error, never a hang or a crash.
    auto blow = [](double, const double* y, double* d) { d[0] = y[0] * y[0]; };
    for (stepper_kind k : all_steppers) {
        integration_options ob;
        ob.stepper = k;
        ob.max_steps_between_outputs = 20000;
        EXPECT_THROW(integrate(blow, 0.0, std::vector<double>{1.0}, {0.5, 2.0}, ob), symrep::error) << stepper_name(k);
    }
    // Evaluation budget.
    integration_options oe;
    oe.max_rhs_evaluations = 50;
    EXPECT_THROW(integrate(f, 0.0, std::vector<double>{1.0}, {10.0}, oe), symrep::error);
}

TEST(NumericVerify, OscillatorCorrectAndWrongClosedForms) {
    symbol t("t"), x("x"), v("v"), w("w");
    const std::vector<ex> rhs = {v, -w * w * x};
    const parameter_values p = {{w, 1.3}};
    // x(t) = cos(w t) + 2 sin(w t) / w, v = x'.
    const ex xs = GiNaC::cos(w * t) + 2 * GiNaC::sin(w * t) / w;
    const std::vector<ex> good = {xs, xs.diff(t)};
    const verify_result ok = verify(good, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 101);
    EXPECT_LT(ok.max_relative_difference, 1e-8);
    EXPECT_EQ(ok.n_points, 101u);
    EXPECT_GT(ok.rhs_evaluations, 0u);
    EXPECT_GE(ok.closed_form_seconds, 0.0);
    EXPECT_GE(ok.integration_seconds, 0.0);

    // Initial state from the closed form itself.
    const verify_result ok2 = verify(good, t, rhs, {x, v}, {}, p, 0.0, 20.0, 50);
    EXPECT_LT(ok2.max_relative_difference, 1e-8);

    // Only the position checked against the state (x, v).
    const verify_result ok3 = verify({xs}, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 50);
    EXPECT_LT(ok3.max_relative_difference, 1e-8);

    // Wrong: the frequency is off by 1 %; and a wrong sign.
    const ex wrong = GiNaC::cos(w * t * GiNaC::numeric(101, 100)) + 2 * GiNaC::sin(w * t) / w;
    const verify_result bad = verify({wrong}, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 101);
    EXPECT_GT(bad.max_relative_difference, 0.05);
    EXPECT_EQ(bad.component_of_max, 0u);
    const verify_result bad2 = verify({GiNaC::cos(w * t) - 2 * GiNaC::sin(w * t) / w}, t, rhs, {x, v}, {1.0, 2.0},
                                      p, 0.0, 20.0, 101);
    EXPECT_GT(bad2.max_relative_difference, 0.5);

    // Errors.
    symbol k("k");
    EXPECT_THROW(verify({xs * k}, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 10), type_error);
    EXPECT_THROW(verify({xs, xs, xs}, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 10), type_error);
    EXPECT_THROW(verify(good, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 1), type_error);
    EXPECT_THROW(verify(good, t, rhs, {x, v}, {1.0, 2.0}, p, 5.0, 1.0, 10), type_error);
    EXPECT_THROW(verify({xs}, t, rhs, {x, v}, {}, p, 0.0, 1.0, 10), type_error);
    // A closed form that is not finite somewhere is infinitely wrong.
    const verify_result nan = verify({GiNaC::log(t - 10)}, t, rhs, {x, v}, {1.0, 2.0}, p, 0.0, 20.0, 11);
    EXPECT_TRUE(std::isinf(nan.max_relative_difference));
}

TEST(NumericVerify, RotatingFrameRodriguesClosedForm) {
    // r(t) = exp(-W t) u, u = r0 + (v0 + w x r0) t, by the Rodrigues formula, against
    // the symbolic system r' = v, v' = -2 w x v - w x (w x r), parameters w1, w2, w3.
    symbol t("t"), w1("w1"), w2("w2"), w3("w3");
    std::vector<ex> s;
    for (const char* n : {"x", "y", "z", "vx", "vy", "vz"}) s.push_back(symbol(n));
    const GiNaC::matrix W{{0, -w3, w2}, {w3, 0, -w1}, {-w2, w1, 0}};
    const GiNaC::matrix r{{s[0]}, {s[1]}, {s[2]}}, v{{s[3]}, {s[4]}, {s[5]}};
    const GiNaC::matrix acc = W.mul(v).mul_scalar(-2).add(W.mul(W).mul(r).mul_scalar(-1));
    const std::vector<ex> rhs = {s[3], s[4], s[5], acc(0, 0), acc(1, 0), acc(2, 0)};

    const GiNaC::matrix w{{w1}, {w2}, {w3}}, r0{{1}, {0}, {GiNaC::numeric(1, 2)}}, v0{{0}, {1}, {GiNaC::numeric(1, 5)}};
    const ex Omega = GiNaC::sqrt(w1 * w1 + w2 * w2 + w3 * w3);
    const GiNaC::matrix u = r0.add(v0.add(W.mul(r0)).mul_scalar(t));
    const ex wu = (w.transpose().mul(u))(0, 0);
    const GiNaC::matrix rt = u.mul_scalar(GiNaC::cos(Omega * t))
                                 .sub(W.mul(u).mul_scalar(GiNaC::sin(Omega * t) / Omega))
                                 .add(w.mul_scalar((1 - GiNaC::cos(Omega * t)) / (Omega * Omega) * wu));
    std::vector<ex> cf = flatten_outputs(rt);
    for (int i = 0; i < 3; ++i) cf.push_back(cf[i].diff(t));  // and the velocity

    const parameter_values p = {{w1, 0.3}, {w2, -0.5}, {w3, 0.8}};
    for (stepper_kind k : all_steppers) {
        integration_options o;
        o.stepper = k;
        const verify_result res = verify(cf, t, rhs, s, {}, p, 0.0, 20.0, 201, o);
        EXPECT_LT(res.max_relative_difference, 1e-8) << stepper_name(k);
        EXPECT_GT(res.rhs_evaluations, 0u);
    }
    // A wrong sign of the Coriolis rotation (exp(+W t) instead of exp(-W t)) is caught.
    GiNaC::exmap flip = {{w1, -w1}, {w2, -w2}, {w3, -w3}};
    std::vector<ex> wrong;
    for (int i = 0; i < 3; ++i) wrong.push_back(cf[i].subs(flip));
    const verify_result bad = verify(wrong, t, rhs, s, {1, 0, 0.5, 0, 1, 0.2}, p, 0.0, 20.0, 201);
    EXPECT_GT(bad.max_relative_difference, 0.1);
}
