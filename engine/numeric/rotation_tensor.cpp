// symrep/numeric/rotation_tensor.cpp -- Q' = -W Q on SO(3) by a sixth-order
// Magnus method (see rotation_tensor.h).
#include "symrep/numeric/rotation_tensor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/core/progress.h"
#include "symrep/numeric/magnus_control.h"

namespace symrep::num {

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
    Eigen::Matrix3d W;
    W << 0, -a.z(), a.y(),  //
        a.z(), 0, -a.x(),   //
        -a.y(), a.x(), 0;
    return W;
}

// (VI.1.13-14) exp(hat(theta)) = I + (sin p / p) hat(theta) + ((1 - cos p) / p^2) hat(theta)^2, p = |theta|;
// the two coefficients by series below p = 1e-4 (no cancellation in 1 - cos p).
Eigen::Matrix3d rotation_exp(const Eigen::Vector3d& theta) {
    const double p2 = theta.squaredNorm();
    const double p = std::sqrt(p2);
    double a, b;  // sin p / p, (1 - cos p) / p^2
    if (p < 1e-4) {
        a = 1.0 - p2 / 6.0 + p2 * p2 / 120.0;
        b = 0.5 - p2 / 24.0 + p2 * p2 / 720.0;
    } else {
        a = std::sin(p) / p;
        const double s = std::sin(p / 2) / (p / 2);
        b = 0.5 * s * s;  // (1 - cos p)/p^2 = 2 sin^2(p/2)/p^2
    }
    const Eigen::Matrix3d K = skew(theta);
    return Eigen::Matrix3d::Identity() + a * K + b * (K * K);
}

// Sixth-order Magnus integrator of Blanes, Casas and Ros (three Gauss-Legendre
// nodes): with A_i = A(t + c_i h),
//   a1 = h A2, a2 = (sqrt(15) h / 3) (A3 - A1), a3 = (10 h / 3) (A3 - 2 A2 + A1),
//   C1 = [a1, a2], C2 = -[a1, 2 a3 + C1] / 60,
//   Omega = a1 + a3 / 12 + [-20 a1 - a3 + C1, a2 + C2] / 240.
// Here A = -hat(w) and [hat(x), hat(y)] = hat(x cross y).
Eigen::Vector3d magnus6_step(const angular_velocity& w, double t, double h) {
    static const double r15 = std::sqrt(15.0);
    const double c1 = 0.5 - r15 / 10.0, c3 = 0.5 + r15 / 10.0;
    const Eigen::Vector3d A1 = -w(t + c1 * h), A2 = -w(t + 0.5 * h), A3 = -w(t + c3 * h);
    const Eigen::Vector3d a1 = h * A2;
    const Eigen::Vector3d a2 = (r15 * h / 3.0) * (A3 - A1);
    const Eigen::Vector3d a3 = (10.0 * h / 3.0) * (A3 - 2.0 * A2 + A1);
    const Eigen::Vector3d C1 = a1.cross(a2);
    const Eigen::Vector3d C2 = -a1.cross(2.0 * a3 + C1) / 60.0;
    return a1 + a3 / 12.0 + (-20.0 * a1 - a3 + C1).cross(a2 + C2) / 240.0;
}

rotation_tensor_result rotation_tensor(const angular_velocity& w, const std::vector<double>& times,
                                       const rotation_tensor_options& options) {
    if (!(options.rel_tol > 0) || !std::isfinite(options.rel_tol))
        throw type_error("rotation_tensor: the tolerance must be a positive number");
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k]) || times[k] < 0)
            throw type_error("rotation_tensor: the times must be finite and >= 0");
        if (k > 0 && times[k] < times[k - 1]) throw type_error("rotation_tensor: the times must be sorted");
    }
    rotation_tensor_result res;
    res.Q.reserve(times.size());
    if (times.empty()) return res;
    std::size_t evaluations = 0;
    const angular_velocity counted = [&](double s) {
        ++evaluations;
        const Eigen::Vector3d v = w(s);
        if (!v.allFinite())
            throw error("rotation_tensor: the angular velocity is not finite at t = " + std::to_string(s));
        return v;
    };
    // the step control of numeric/magnus_control.h on SO(3)
    struct so3 {
        using element = Eigen::Matrix3d;
        const angular_velocity& w;
        element step(double t0, double h) const { return rotation_exp(magnus6_step(w, t0, h)); }
        double distance(const element& a, const element& b, const element&) const { return (a - b).norm(); }
        void advance(element& Q, const element& E) const {
            Q = E * Q;
            // one Newton-Schulz step towards the nearest rotation: the rounding of the
            // products does not accumulate in Q^T Q
            Q = 0.5 * Q * (3.0 * Eigen::Matrix3d::Identity() - Q.transpose() * Q);
        }
    } group{counted};
    const magnus_control control{"rotation_tensor", "the angular velocity", "w(t)", "rotation tensor",
                                 options.rel_tol, options.max_step, options.max_steps};
    res.Q = magnus_integrate(group, Eigen::Matrix3d::Identity(), times, counted(0.0).norm(), control, res.steps);
    res.evaluations = evaluations;
    return res;
}

// (VI.2.12 with FORMULAS.md) Q x = (u.x) u - sin(alpha) u x x - cos(alpha) u x (u x x):
// as a matrix u u^T - sin(alpha) hat(u) - cos(alpha) hat(u)^2.
Eigen::Matrix3d fixed_direction_rotation(const Eigen::Vector3d& u, double alpha) {
    const Eigen::Matrix3d U = skew(u);
    return u * u.transpose() - std::sin(alpha) * U - std::cos(alpha) * (U * U);
}

}  // namespace symrep::num
