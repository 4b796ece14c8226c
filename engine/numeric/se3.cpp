// symrep/numeric/se3.cpp -- rigid motions, dual quaternions and the dual
// Poisson-Darboux problem on SE(3) by a sixth-order Magnus method (see se3.h).
#include "symrep/numeric/se3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/core/progress.h"
#include "symrep/numeric/magnus_control.h"
#include "symrep/numeric/rotation_tensor.h"

namespace symrep::num {

twist twist_cross(const twist& a, const twist& b) { return {a.w.cross(b.w), a.w.cross(b.v) + a.v.cross(b.w)}; }

rigid_motion operator*(const rigid_motion& a, const rigid_motion& b) { return {a.R * b.R, a.d + a.R * b.d}; }

rigid_motion inverse(const rigid_motion& g) {
    const Eigen::Matrix3d Rt = g.R.transpose();
    return {Rt, -(Rt * g.d)};
}

Eigen::Vector3d transform_point(const rigid_motion& g, const Eigen::Vector3d& p) { return g.R * p + g.d; }

// (I + eps skew(d)) R (x + eps m) = R x + eps (R m + d x R x)
twist apply(const rigid_motion& g, const twist& x) {
    const Eigen::Vector3d Rx = g.R * x.w;
    return {Rx, g.R * x.v + g.d.cross(Rx)};
}

Eigen::Matrix4d homogeneous(const rigid_motion& g) {
    Eigen::Matrix4d H = Eigen::Matrix4d::Identity();
    H.topLeftCorner<3, 3>() = g.R;
    H.topRightCorner<3, 1>() = g.d;
    return H;
}

// exp [[K, v], [0, 0]] = [[exp K, V v], [0, 1]], K = skew(w), p = |w|:
//   V = sum_k K^k / (k + 1)! = I + (1 - cos p)/p^2 K + (p - sin p)/p^3 K^2.
// The coefficient of K^2 by its series below p = 0.1 (the division by p^3 would
// leave only rounding for small p); the first one as in rotation_exp.
rigid_motion se3_exp(const twist& xi) {
    const double p2 = xi.w.squaredNorm();
    const double p = std::sqrt(p2);
    double b, c;  // (1 - cos p) / p^2, (p - sin p) / p^3
    if (p < 1e-4) {
        b = 0.5 - p2 / 24.0 + p2 * p2 / 720.0;
    } else {
        const double s = std::sin(p / 2) / (p / 2);
        b = 0.5 * s * s;
    }
    if (p < 0.1) {
        // sum_k (-1)^k p^(2k) / (2k + 3)!, k = 0..4 (the next term is below 2e-20)
        c = 1.0 / 6.0 + p2 * (-1.0 / 120.0 + p2 * (1.0 / 5040.0 + p2 * (-1.0 / 362880.0 + p2 / 39916800.0)));
    } else {
        c = (p - std::sin(p)) / (p2 * p);
    }
    const Eigen::Matrix3d K = skew(xi.w);
    const Eigen::Matrix3d V = Eigen::Matrix3d::Identity() + b * K + c * (K * K);
    return {rotation_exp(xi.w), V * xi.v};
}

// The inverse of V above: V^-1 = I - K/2 + (1 - (p/2) cot(p/2))/p^2 K^2 (|p| < 2 pi);
// its coefficient by series below p = 0.1: 1/12 + p^2/720 + p^4/30240 + p^6/1209600 + p^8/47900160.
twist se3_log(const rigid_motion& g) {
    if (!g.R.allFinite() || !g.d.allFinite()) throw type_error("se3_log: the rigid motion is not finite");
    if ((g.R.transpose() * g.R - Eigen::Matrix3d::Identity()).norm() > 1e-9 || g.R.determinant() < 0)
        throw type_error("se3_log: R is not a rotation (R^T R = I and det R = 1 fail beyond 1e-9)");
    Eigen::Quaterniond q(g.R);
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    Eigen::Vector3d u = q.vec();
    const double s = u.norm();
    Eigen::Vector3d w = Eigen::Vector3d::Zero();
    if (s > 0) {
        if (q.w() == 0) {  // angle pi: both signs are logs; take the largest component positive
            Eigen::Index k;
            u.cwiseAbs().maxCoeff(&k);
            if (u[k] < 0) u = -u;
        }
        w = (2.0 * std::atan2(s, q.w()) / s) * u;  // angle in [0, pi]
    }
    const double p2 = w.squaredNorm();
    const double p = std::sqrt(p2);
    double c;
    if (p < 0.1) {
        c = 1.0 / 12.0 + p2 * (1.0 / 720.0 + p2 * (1.0 / 30240.0 + p2 * (1.0 / 1209600.0 + p2 / 47900160.0)));
    } else {
        c = (1.0 - (p / 2) / std::tan(p / 2)) / p2;
    }
    const Eigen::Matrix3d K = skew(w);
    return {w, g.d - 0.5 * K * g.d + c * (K * (K * g.d))};
}

namespace {

Eigen::Quaterniond quat_add(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return Eigen::Quaterniond(a.coeffs() + b.coeffs());
}

Eigen::Quaterniond pure(const Eigen::Vector3d& x) { return Eigen::Quaterniond(0, x.x(), x.y(), x.z()); }

}  // namespace

dual_quaternion operator*(const dual_quaternion& a, const dual_quaternion& b) {
    return {a.r * b.r, quat_add(a.r * b.e, a.e * b.r)};
}

dual_quaternion conjugate(const dual_quaternion& q) { return {q.r.conjugate(), q.e.conjugate()}; }

// r the quaternion of R, e = t r / 2 (t the translation as a pure quaternion)
dual_quaternion to_dual_quaternion(const rigid_motion& g) {
    Eigen::Quaterniond r(g.R);
    if (r.w() < 0) r.coeffs() = -r.coeffs();
    Eigen::Quaterniond e = pure(g.d) * r;
    e.coeffs() *= 0.5;
    return {r, e};
}

rigid_motion to_rigid_motion(const dual_quaternion& q) {
    if (!q.r.coeffs().allFinite() || !q.e.coeffs().allFinite())
        throw type_error("to_rigid_motion: the dual quaternion is not finite");
    if (std::abs(q.r.squaredNorm() - 1.0) > 1e-9 || std::abs(q.r.coeffs().dot(q.e.coeffs())) > 1e-9)
        throw type_error("to_rigid_motion: not a unit dual quaternion (|r| = 1 and r . e = 0 fail beyond 1e-9)");
    const Eigen::Quaterniond t = q.e * q.r.conjugate();
    return {q.r.toRotationMatrix(), 2.0 * t.vec()};
}

// (r + eps e)(x + eps m)(r* + eps e*) = r x r* + eps (r m r* + e x r* + r x e*)
twist apply(const dual_quaternion& q, const twist& x) {
    const Eigen::Quaterniond X = pure(x.w), M = pure(x.v);
    const Eigen::Quaterniond rc = q.r.conjugate(), ec = q.e.conjugate();
    const Eigen::Quaterniond primal = q.r * X * rc;
    const Eigen::Quaterniond dual = quat_add(quat_add(q.r * M * rc, q.e * X * rc), q.r * X * ec);
    return {primal.vec(), dual.vec()};
}

// The sixth-order Magnus method of Blanes, Casas and Ros (rotation_tensor.cpp's
// magnus6_step) with A = -hat(Omega^) in se(3), whose bracket is twist_cross:
//   a1 = h A2, a2 = (sqrt(15) h / 3) (A3 - A1), a3 = (10 h / 3) (A3 - 2 A2 + A1),
//   C1 = [a1, a2], C2 = -[a1, 2 a3 + C1] / 60,
//   Omega = a1 + a3 / 12 + [-20 a1 - a3 + C1, a2 + C2] / 240.
twist se3_magnus6_step(const twist_function& xi, double t, double h) {
    static const double r15 = std::sqrt(15.0);
    const double c1 = 0.5 - r15 / 10.0, c3 = 0.5 + r15 / 10.0;
    const twist A1 = -xi(t + c1 * h), A2 = -xi(t + 0.5 * h), A3 = -xi(t + c3 * h);
    const twist a1 = h * A2;
    const twist a2 = (r15 * h / 3.0) * (A3 - A1);
    const twist a3 = (10.0 * h / 3.0) * (A3 - 2.0 * A2 + A1);
    const twist C1 = twist_cross(a1, a2);
    const twist C2 = (-1.0 / 60.0) * twist_cross(a1, 2.0 * a3 + C1);
    return a1 + (1.0 / 12.0) * a3 + (1.0 / 240.0) * twist_cross(-20.0 * a1 - a3 + C1, a2 + C2);
}

se3_tensor_result se3_tensor(const twist_function& xi, const std::vector<double>& times,
                             const se3_tensor_options& options) {
    if (!(options.rel_tol > 0) || !std::isfinite(options.rel_tol))
        throw type_error("se3_tensor: the tolerance must be a positive number");
    if (!(options.length_scale >= 0) || !std::isfinite(options.length_scale))
        throw type_error("se3_tensor: the length scale must be a number >= 0 (0: automatic)");
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k]) || times[k] < 0)
            throw type_error("se3_tensor: the times must be finite and >= 0");
        if (k > 0 && times[k] < times[k - 1]) throw type_error("se3_tensor: the times must be sorted");
    }
    se3_tensor_result res;
    res.Q.reserve(times.size());
    if (times.empty()) return res;
    std::size_t evaluations = 0;
    const twist_function counted = [&](double s) {
        ++evaluations;
        const twist x = xi(s);
        if (!x.w.allFinite() || !x.v.allFinite())
            throw error("se3_tensor: the twist is not finite at t = " + std::to_string(s));
        return x;
    };
    // the step control of numeric/magnus_control.h on SE(3), in the norm
    // |E|^2 = |R_E|_F^2 + |d_E|^2 / L^2 (L the length scale: given, or the largest |d| so far)
    struct se3 {
        using element = rigid_motion;
        const twist_function& xi;
        double L;
        bool automatic_scale;
        element step(double t0, double h) const { return se3_exp(se3_magnus6_step(xi, t0, h)); }
        double distance(const element& a, const element& b, const element& Q) {
            if (automatic_scale) L = std::max({L, Q.d.norm(), b.d.norm()});
            double d2 = (a.R - b.R).squaredNorm();
            if (L > 0) d2 += (a.d - b.d).squaredNorm() / (L * L);
            return std::sqrt(d2);
        }
        void advance(element& Q, const element& E) const {
            Q = E * Q;
            // one Newton-Schulz step towards the nearest rotation (R^T R stays I to rounding)
            Q.R = 0.5 * Q.R * (3.0 * Eigen::Matrix3d::Identity() - Q.R.transpose() * Q.R);
        }
    } group{counted, options.length_scale, options.length_scale == 0};
    const magnus_control control{"se3_tensor", "the twist", "twist", "SE(3) tensor",
                                 options.rel_tol, options.max_step, options.max_steps};
    res.Q = magnus_integrate(group, rigid_motion{}, times, counted(0.0).w.norm(), control, res.steps);
    res.evaluations = evaluations;
    return res;
}

}  // namespace symrep::num
