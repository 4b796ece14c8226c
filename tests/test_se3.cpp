// Rigid motions in double precision (numeric/se3.h): the SE(3) exponential
// against Eigen's 4x4 matrix exponential, its logarithm, dual quaternions
// against the dual tensor and the screw form cos(a^/2) + sin(a^/2) u^, and the
// dual Poisson-Darboux problem Q^' = -Omega^ Q^ by the Magnus method against
// closed forms (constant twist, fixed screw axis with varying rates, regular
// screw precession) and against Boost.Odeint on the 12 components, written
// here independently of num::integrate.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/error.h"
#include "core/progress.h"
#include "numeric/rotation_tensor.h"
#include "numeric/se3.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;
using namespace symrep;
using num::rigid_motion;
using num::twist;

Matrix4d hat(const twist& x) {
    Matrix4d H = Matrix4d::Zero();
    H.topLeftCorner<3, 3>() = num::skew(x.w);
    H.topRightCorner<3, 1>() = x.v;
    return H;
}

// max(|R - R'|_F, |d - d'| / max(1, |d'|)): the error measure of these tests
double distance(const rigid_motion& a, const rigid_motion& b) {
    return std::max((a.R - b.R).norm(), (a.d - b.d).norm() / std::max(1.0, b.d.norm()));
}

double twist_distance(const twist& a, const twist& b) { return std::max((a.w - b.w).norm(), (a.v - b.v).norm()); }

rigid_motion random_motion(std::mt19937& gen, double max_angle) {
    std::uniform_real_distribution<double> U(-1, 1);
    const Vector3d axis = Vector3d(U(gen), U(gen), U(gen)).normalized();
    const double angle = max_angle * (U(gen) + 1) / 2;
    return {num::rotation_exp(angle * axis), 3.0 * Vector3d(U(gen), U(gen), U(gen))};
}

TEST(Se3, ExpAgreesWithTheMatrixExponential) {
    // from |w| = 0 to large angles, with a translation part of size 1 .. 10
    const Vector3d u = Vector3d(2, -1, 2) / 3.0;
    for (double p : {0.0, 1e-12, 1e-7, 1e-4, 0.05, 0.0999, 0.1, 0.7, 2.5, 3.1, 9.0}) {
        const twist x{p * u, Vector3d(0.4, -2.0, 7.0)};
        const rigid_motion g = num::se3_exp(x);
        const Matrix4d E = hat(x).exp();
        // tolerance: a few ulps of the entries (|d| ~ 7), Eigen's Pade approximant included
        EXPECT_LT((num::homogeneous(g) - E).norm(), 2e-14 * std::max(1.0, p)) << p;
        EXPECT_LT((g.R.transpose() * g.R - Matrix3d::Identity()).norm(), 1e-15) << p;
    }
    // pure translation: exactly (I, v)
    const rigid_motion t = num::se3_exp({Vector3d::Zero(), Vector3d(1, 2, 3)});
    EXPECT_EQ(t.R, Matrix3d::Identity());
    EXPECT_EQ(t.d, Vector3d(1, 2, 3));
}

TEST(Se3, LogInvertsExp) {
    std::mt19937 gen(31);
    for (int k = 0; k < 200; ++k) {
        const rigid_motion g = random_motion(gen, k < 100 ? std::numbers::pi : 1e-6);
        const twist x = num::se3_log(g);
        EXPECT_LE(x.w.norm(), std::numbers::pi * (1 + 1e-15));
        // tolerance: rounding, amplified near angle pi where the axis is ill-conditioned
        EXPECT_LT(distance(num::se3_exp(x), g), 1e-13) << k;
    }
    // log(exp(x)) = x for |w| < pi, small angles included
    for (double p : {0.0, 1e-10, 1e-3, 0.09, 0.11, 1.0, 3.0}) {
        const twist x{p * Vector3d(0.6, 0.0, -0.8), Vector3d(-1.0, 0.5, 2.0)};
        EXPECT_LT(twist_distance(num::se3_log(num::se3_exp(x)), x), 1e-14) << p;
    }
    // angle exactly pi: either sign is a log; the one returned is deterministic and exact
    const rigid_motion half{Vector3d(1, -1, -1).asDiagonal(), Vector3d(0.3, 1, 2)};
    const twist x = num::se3_log(half);
    EXPECT_NEAR(x.w.x(), std::numbers::pi, 1e-15);
    EXPECT_LT(distance(num::se3_exp(x), half), 1e-15);
    EXPECT_THROW(num::se3_log({1.01 * Matrix3d::Identity(), Vector3d::Zero()}), type_error);
    EXPECT_THROW(num::se3_log({Vector3d(1, 1, -1).asDiagonal(), Vector3d::Zero()}), type_error);
}

// A screw about the axis u through p, angle a, translation h along u: R = exp(a u),
// d = p - R p + h u. Its twist is a (u + eps p x u) + eps h u, its dual quaternion
// cos(a^/2) + sin(a^/2) u^ with a^ = a + eps h and u^ = u + eps p x u (docs/rigid_body.md).
TEST(Se3, ScrewFormOfTheLogAndOfTheDualQuaternion) {
    const Vector3d u = Vector3d(1, 2, -2) / 3.0, p(0.5, -1.0, 2.0);
    for (double a : {1e-6, 0.4, 2.0, 3.0}) {
        const double h = 0.7;
        const Matrix3d R = num::rotation_exp(a * u);
        const rigid_motion g{R, p - R * p + h * u};
        const twist x = num::se3_log(g);
        EXPECT_LT(twist_distance(x, {a * u, a * p.cross(u) + h * u}), 1e-14) << a;
        const num::dual_quaternion q = num::to_dual_quaternion(g);
        const double c = std::cos(a / 2), s = std::sin(a / 2);
        // primal: (cos a/2, sin a/2 u); dual: (-h/2 sin a/2, sin a/2 (p x u) + h/2 cos a/2 u)
        EXPECT_NEAR(q.r.w(), c, 1e-15);
        EXPECT_LT((q.r.vec() - s * u).norm(), 1e-15);
        EXPECT_NEAR(q.e.w(), -h / 2 * s, 1e-15);
        EXPECT_LT((q.e.vec() - (s * p.cross(u) + h / 2 * c * u)).norm(), 1e-15) << a;
    }
}

TEST(Se3, DualQuaternionsComposeAndActOnLinesAsTheDualTensor) {
    std::mt19937 gen(7);
    for (int k = 0; k < 50; ++k) {
        const rigid_motion g1 = random_motion(gen, 3.0), g2 = random_motion(gen, 3.0);
        const num::dual_quaternion q1 = num::to_dual_quaternion(g1), q2 = num::to_dual_quaternion(g2);
        EXPECT_LT(distance(num::to_rigid_motion(q1), g1), 1e-14);
        // the product of dual quaternions is the composition of the motions
        EXPECT_LT(distance(num::to_rigid_motion(q1 * q2), g1 * g2), 1e-14);
        EXPECT_LT(distance(num::to_rigid_motion(q1 * num::conjugate(q1)), rigid_motion{}), 1e-15);
        EXPECT_LT(distance(g1 * num::inverse(g1), rigid_motion{}), 1e-14);
        // a line through P with direction x: Q^ x^ = R x + eps ((d + R P) x R x), by both
        const Vector3d P = g2.d, x = g2.R.col(0);
        const twist line{x, P.cross(x)};
        const twist image{g1.R * x, num::transform_point(g1, P).cross(g1.R * x)};
        EXPECT_LT(twist_distance(num::apply(g1, line), image), 1e-14);
        EXPECT_LT(twist_distance(num::apply(q1, line), image), 1e-14);
        // the adjoint action is the conjugation of se(3): hat(Q^ x^) = G hat(x^) G^-1
        const twist xi{Vector3d(0.3, -0.2, 0.9), Vector3d(1.0, 2.0, -0.5)};
        const Matrix4d G = num::homogeneous(g1);
        EXPECT_LT((hat(num::apply(g1, xi)) - G * hat(xi) * G.inverse()).norm(), 1e-13);
    }
    num::dual_quaternion bad;
    bad.e = Eigen::Quaterniond(0.5, 0, 0, 0);  // r . e != 0
    EXPECT_THROW(num::to_rigid_motion(bad), type_error);
}

// The se(3) bracket is the matrix commutator (the dual cross product).
TEST(Se3, TwistCrossIsTheCommutator) {
    const twist a{Vector3d(0.3, -1.0, 2.0), Vector3d(0.5, 0.1, -0.7)}, b{Vector3d(-1.5, 0.2, 0.4), Vector3d(2.0, -3.0, 1.0)};
    const Matrix4d C = hat(a) * hat(b) - hat(b) * hat(a);
    EXPECT_LT((hat(num::twist_cross(a, b)) - C).norm(), 1e-15);
}

// A twist whose axis moves and whose translation part varies: no closed form.
const num::twist_function moving = [](double t) {
    return twist{Vector3d(0.7 * std::sin(1.3 * t), 0.4 * std::cos(2.1 * t), 0.5),
                 Vector3d(0.3 * std::cos(0.9 * t), -0.2, 0.5 * std::sin(1.7 * t))};
};

// Q^' = -Omega^ Q^ as R' = -W R, d' = -w x d - v on 12 components, by Boost.Odeint's
// controlled Runge-Kutta-Fehlberg 7(8), not through num::integrate.
rigid_motion by_odeint(const num::twist_function& xi, double T, double tol) {
    using state = std::array<double, 12>;
    namespace odeint = boost::numeric::odeint;
    state y{};
    Eigen::Map<Matrix3d>(y.data()) = Matrix3d::Identity();
    auto rhs = [&](const state& s, state& ds, double t) {
        const twist x = xi(t);
        Eigen::Map<const Matrix3d> R(s.data());
        Eigen::Map<const Vector3d> d(s.data() + 9);
        Eigen::Map<Matrix3d>(ds.data()) = -num::skew(x.w) * R;
        Eigen::Map<Vector3d>(ds.data() + 9) = -x.w.cross(d) - x.v;
    };
    odeint::integrate_adaptive(odeint::make_controlled(tol, tol, odeint::runge_kutta_fehlberg78<state>()), rhs, y,
                               0.0, T, 1e-3);
    return {Eigen::Map<const Matrix3d>(y.data()), Eigen::Map<const Vector3d>(y.data() + 9)};
}

TEST(Se3, MagnusAgreesWithOdeintOnTwelveComponents) {
    const double T = 10.0;
    num::se3_tensor_options o;
    o.rel_tol = 1e-12;
    const auto r = num::se3_tensor(moving, {0.0, 2.5, T}, o);
    ASSERT_EQ(r.Q.size(), 3u);
    EXPECT_EQ(num::homogeneous(r.Q[0]), Matrix4d::Identity());
    const rigid_motion ref = by_odeint(moving, T, 1e-13);
    // tolerance: both methods at 1e-12 .. 1e-13 per unit time over 10 time units,
    // the propagator of this bounded twist of norm ~1 grows errors by at most ~10
    EXPECT_LT(distance(r.Q[2], ref), 1e-10) << distance(r.Q[2], ref);
    EXPECT_LT(distance(r.Q[1], by_odeint(moving, 2.5, 1e-13)), 1e-10);
    // structure: R orthogonal to rounding (rkf78 drifts with its tolerance)
    EXPECT_LT((r.Q[2].R.transpose() * r.Q[2].R - Matrix3d::Identity()).norm(), 1e-15);
    EXPECT_GT(r.steps, 0u);
    // three Gauss nodes times three Magnus steps (one step, two half steps) per attempt, plus w(0)
    EXPECT_GE(r.evaluations, 9 * r.steps + 1);
    EXPECT_EQ((r.evaluations - 1) % 9, 0u);
}

TEST(Se3, ConstantTwistIsTheExponential) {
    const twist xi{Vector3d(0.3, -0.8, 1.1), Vector3d(2.0, 0.5, -1.0)};
    const std::vector<double> times{0.5, 3.0, 40.0};
    const auto r = num::se3_tensor([&](double) { return xi; }, times);
    for (std::size_t k = 0; k < times.size(); ++k) {
        const rigid_motion want = num::se3_exp(-times[k] * xi);
        // tolerance: rounding of ~100 steps plus the closed form's own rounding of sin |w| t
        EXPECT_LT(distance(r.Q[k], want), 1e-13) << times[k];
        // and the closed form against the 4x4 matrix exponential
        EXPECT_LT((num::homogeneous(want) - (-times[k] * hat(xi)).exp()).norm(), 1e-12 * times[k]);
    }
}

// Omega^(t) = s^(t) u^ with u^ = u + eps p x u fixed and s^ = s + eps sigma: all the
// Omega^(t) commute, so Q^(t) = exp(-(S u^ + eps Sigma u)), S and Sigma the integrals.
TEST(Se3, FixedScrewAxisWithVaryingRates) {
    const Vector3d u = Vector3d(-2, 1, 2) / 3.0, p(1.0, 0.5, -0.3);
    const twist uh{u, p.cross(u)};
    const num::twist_function xi = [&](double t) {
        const double s = 1 + 0.5 * std::cos(2 * t), sigma = 0.3 * std::sin(t);
        return twist{s * uh.w, s * uh.v + sigma * u};
    };
    const std::vector<double> times{1.0, 7.0, 30.0};
    num::se3_tensor_options o;
    o.rel_tol = 1e-12;
    const auto r = num::se3_tensor(xi, times, o);
    for (std::size_t k = 0; k < times.size(); ++k) {
        const double t = times[k], S = t + 0.25 * std::sin(2 * t), Sigma = 0.3 * (1 - std::cos(t));
        const rigid_motion want = num::se3_exp({-S * uh.w, -S * uh.v - Sigma * u});
        // tolerance: rel_tol 1e-12 and rounding over ~30 time units
        EXPECT_LT(distance(r.Q[k], want), 1e-11) << t;
    }
}

// The regular screw precession: Q^(t) = exp(-t b^) exp(-t a^) solves Q^' = -Omega^ Q^ for
// Omega^(t) = b^ + Q_b(t) a^ (the adjoint action of Q_b = exp(-t b^) on the twist a^):
// the spin a^ carried by the precession b^. The twist's axis moves.
struct precession {
    twist a{Vector3d(0.2, -0.4, 1.3), Vector3d(0.1, 0.3, -0.2)};
    twist b{Vector3d(0.0, 0.5, 0.2), Vector3d(-0.4, 0.0, 0.25)};
    twist operator()(double t) const { return b + num::apply(num::se3_exp(-t * b), a); }
    rigid_motion exact(double t) const { return num::se3_exp(-t * b) * num::se3_exp(-t * a); }
};

TEST(Se3, RegularScrewPrecessionAgainstItsClosedForm) {
    const precession P;
    const std::vector<double> times{0.3, 5.0, 60.0};
    num::se3_tensor_options o;
    o.rel_tol = 1e-12;
    const auto r = num::se3_tensor(P, times, o);
    for (std::size_t k = 0; k < times.size(); ++k) {
        // tolerance: rel_tol 1e-12 (global, relative to |d| ~ 10 at t = 60) and rounding
        EXPECT_LT(distance(r.Q[k], P.exact(times[k])), 2e-11) << times[k];
    }
    // the closed form itself solves the ODE: a central difference of Q^ against -Omega^ Q^
    for (double t : {0.7, 13.0}) {
        const double e = 1e-4;
        const Matrix4d dQ = (num::homogeneous(P.exact(t + e)) - num::homogeneous(P.exact(t - e))) / (2 * e);
        // tolerance: the difference quotient's truncation e^2 |Q'''| / 6 ~ 1e-8 plus rounding/e
        EXPECT_LT((dQ + hat(P(t)) * num::homogeneous(P.exact(t))).norm(), 1e-7) << t;
    }
}

// Halving a fixed step divides the error by about 2^6 (against the exact precession).
TEST(Se3, MagnusStepHasOrderSix) {
    const precession P;
    const double T = 4.0;
    const rigid_motion ref = P.exact(T);
    double previous = 0;
    for (int n : {8, 16, 32}) {
        rigid_motion Q;
        const double h = T / n;
        for (int k = 0; k < n; ++k) Q = num::se3_exp(num::se3_magnus6_step(P, k * h, h)) * Q;
        const double err = distance(Q, ref);
        if (previous > 0) {
            // tolerance: an observed order in [5.3, 7] (2^5.3 ~ 40), far above a 4th-order method's 16
            EXPECT_GT(previous / err, 40.0) << n << ": " << err << " after " << previous;
            EXPECT_LT(previous / err, 130.0) << n;
        }
        previous = err;
    }
}

// With v = 0 the SE(3) problem is the SO(3) one: the same R as rotation_tensor, d = 0 exactly.
TEST(Se3, PureRotationIsTheRotationTensor) {
    const num::twist_function xi = [](double t) { return twist{moving(t).w, Vector3d::Zero()}; };
    const auto r = num::se3_tensor(xi, {6.0});
    const auto q = num::rotation_tensor([](double t) { return moving(t).w; }, {6.0});
    EXPECT_LT((r.Q[0].R - q.Q[0]).norm(), 1e-13);
    EXPECT_EQ(r.Q[0].d, Vector3d::Zero());
}

// The integrator reports its progress in time units, ending at the last time.
TEST(Se3, ReportsProgress) {
    std::vector<progress_report> seen;
    progress_scope scope([&](const progress_report& r) { seen.push_back(r); }, std::chrono::steady_clock::duration::zero());
    num::se3_tensor(moving, {1.0, 5.0});
    ASSERT_FALSE(seen.empty());
    for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k].done, seen[k - 1].done);
    EXPECT_EQ(seen.back().task, "SE(3) tensor");
    EXPECT_TRUE(seen.back().final);
    EXPECT_EQ(seen.back().done, 5.0);
    EXPECT_EQ(seen.back().total, 5.0);
}

TEST(Se3, TensorRefusesBadInput) {
    const num::twist_function xi = [](double) { return twist{Vector3d(1, 0, 0), Vector3d(0, 1, 0)}; };
    EXPECT_TRUE(num::se3_tensor(xi, {}).Q.empty());
    EXPECT_THROW(num::se3_tensor(xi, {2.0, 1.0}), type_error);
    EXPECT_THROW(num::se3_tensor(xi, {-1.0}), type_error);
    EXPECT_THROW(num::se3_tensor(xi, {std::numeric_limits<double>::infinity()}), type_error);
    num::se3_tensor_options o;
    o.rel_tol = 0;
    EXPECT_THROW(num::se3_tensor(xi, {1.0}, o), type_error);
    o.rel_tol = 1e-10;
    o.length_scale = -1;
    EXPECT_THROW(num::se3_tensor(xi, {1.0}, o), type_error);
    const num::twist_function nan = [](double t) {
        return twist{Vector3d(1, 0, 0), Vector3d(t > 0.5 ? std::nan("") : 0.0, 0, 0)};
    };
    try {
        num::se3_tensor(nan, {1.0});
        ADD_FAILURE() << "no error for a twist that is not finite";
    } catch (const type_error&) {
        ADD_FAILURE() << "a twist that is not finite is not a type error";
    } catch (const error& e) {
        EXPECT_NE(std::string(e.what()).find("not finite"), std::string::npos) << e.what();
    }
    o.length_scale = 0;
    o.max_steps = 3;
    EXPECT_THROW(num::se3_tensor(xi, {100.0}, o), error);
}

}  // namespace
