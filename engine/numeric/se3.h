// symrep/numeric/se3.h -- rigid motions in double precision: twists, the dual
// orthogonal tensor Q^ = (I + eps skew(d)) R, its exponential and logarithm,
// dual quaternions, and the dual Poisson-Darboux problem Q^' = -Omega^(t) Q^
// integrated on SE(3) (docs/rigid_body.md section 3; issue 31 items 2-3).
//
// Conventions (docs/rigid_body.md, the same as engine/dual/):
//   - a twist (dual angular velocity) is Omega^ = w + eps v; a line through p
//     with direction x is the dual vector x + eps (p x x). Both are `twist`s
//     here: a pair of 3-vectors read as primal + eps dual.
//   - the rigid motion "rotate by R, then translate by d" is
//     Q^ = (I + eps skew(d)) R; on points p -> R p + d, on the dual vector of a
//     line x + eps m -> R x + eps (d x R x + R m). As a 4x4 matrix it is
//     [[R, d], [0, 1]], and the product of dual tensors is the matrix product.
//   - the twist w + eps v is the element [[skew(w), v], [0, 0]] of se(3); its
//     bracket is the dual cross product
//         [w1 + eps v1, w2 + eps v2] = w1 x w2 + eps (w1 x v2 + v1 x w2).
//   - the dual Poisson-Darboux problem ([CS21], thesis VI.3.117 on dual vectors)
//         Q^' = -Omega^(t) Q^,  Q^(0) = I,  i.e.  R' = -W R,  d' = -w x d - v,
//     whose solution for a constant twist is Q^(t) = se3_exp(-t Omega^).
//
// se3_tensor integrates it with the sixth-order Magnus method of Blanes, Casas
// and Ros on three Gauss-Legendre nodes, as rotation_tensor (rotation_tensor.h)
// does on SO(3): each step multiplies Q^ by se3_exp(Omega), Omega a twist, so
// R stays orthogonal to rounding whatever the step, and Q^ stays a rigid motion
// (a Runge-Kutta method on the 12 components of (R, d) does not keep either).
// The step is controlled by comparing one step with two half steps in the norm
//     |E|^2 = |R_E|_F^2 + |d_E|^2 / L^2
// (lengths measured in a scale L: options.length_scale, or the largest |d|
// reached so far), so that the global errors of R and of d / L over [0, t_end]
// stay near rel_tol.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace symrep::num {

/// A dual vector w + eps v of 3-vectors: a twist (dual angular velocity), or the
/// dual vector x + eps (p x x) of a line.
struct twist {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();  ///< primal part (angular velocity, line direction)
    Eigen::Vector3d v = Eigen::Vector3d::Zero();  ///< dual part (linear velocity, line moment)
};

inline twist operator+(const twist& a, const twist& b) { return {a.w + b.w, a.v + b.v}; }
inline twist operator-(const twist& a, const twist& b) { return {a.w - b.w, a.v - b.v}; }
inline twist operator-(const twist& a) { return {-a.w, -a.v}; }
inline twist operator*(double s, const twist& a) { return {s * a.w, s * a.v}; }

/// The se(3) bracket, the dual cross product: w1 x w2 + eps (w1 x v2 + v1 x w2).
twist twist_cross(const twist& a, const twist& b);

/// The rigid motion "rotate by R, then translate by d": Q^ = (I + eps skew(d)) R.
struct rigid_motion {
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
};

/// Composition: (a * b) applies b first, then a (the product of dual tensors):
/// (R_a R_b, d_a + R_a d_b).
rigid_motion operator*(const rigid_motion& a, const rigid_motion& b);
/// The inverse motion (R^T, -R^T d); Q^^-1 = Q^^T for a dual orthogonal tensor.
rigid_motion inverse(const rigid_motion& g);
/// The image R p + d of a point.
Eigen::Vector3d transform_point(const rigid_motion& g, const Eigen::Vector3d& p);
/// Q^ x^ for a dual vector x^ = x + eps m (a line, a twist: the adjoint action):
/// R x + eps (d x R x + R m).
twist apply(const rigid_motion& g, const twist& x);
/// The 4x4 homogeneous matrix [[R, d], [0, 1]].
Eigen::Matrix4d homogeneous(const rigid_motion& g);

/// exp of the twist [[skew(w), v], [0, 0]] in closed form: R = exp(skew(w)) by
/// Rodrigues (VI.1.13-14, rotation_exp), d = V v with
/// V = I + (1 - cos p)/p^2 skew(w) + (p - sin p)/p^3 skew(w)^2, p = |w|
/// (coefficients by series for small p: accurate for any |w|, 0 included).
rigid_motion se3_exp(const twist& xi);

/// The principal logarithm: the twist xi with |xi.w| <= pi and se3_exp(xi) = g.
/// At rotation angle pi the two logs +-pi u are both exact; the one returned has
/// its largest component of u positive. symrep::type_error when R is not a
/// rotation (|R^T R - I| > 1e-9 or det R < 0) or g is not finite.
twist se3_log(const rigid_motion& g);

/// A unit dual quaternion q^ = r + eps e (r, e quaternions; e = t r / 2 for the
/// translation t): for a screw of dual angle a + eps h about the dual unit axis
/// u + eps (p x u) it is cos(a^/2) + sin(a^/2) u^.
struct dual_quaternion {
    Eigen::Quaterniond r = Eigen::Quaterniond::Identity();
    Eigen::Quaterniond e = Eigen::Quaterniond(0, 0, 0, 0);
};

/// The product (r_a r_b, r_a e_b + e_a r_b): composition as for rigid_motion.
dual_quaternion operator*(const dual_quaternion& a, const dual_quaternion& b);
/// The quaternion conjugate of both parts (the inverse of a unit dual quaternion).
dual_quaternion conjugate(const dual_quaternion& q);
/// The dual quaternion of a rigid motion (r with r.w() >= 0).
dual_quaternion to_dual_quaternion(const rigid_motion& g);
/// The rigid motion of a unit dual quaternion; symrep::type_error when q is not a
/// unit dual quaternion (|r| != 1 or r . e != 0 beyond 1e-9).
rigid_motion to_rigid_motion(const dual_quaternion& q);
/// q^ x^ q^* for a dual vector x^ (a line): the same as apply(to_rigid_motion(q), x).
twist apply(const dual_quaternion& q, const twist& x);

/// A twist as a function of time.
using twist_function = std::function<twist(double t)>;

struct se3_tensor_options {
    /// Bound on the local error per unit time (the norm above of the difference
    /// between one step and two half steps, divided by the step).
    double rel_tol = 1e-13;
    /// Length scale L of the error norm (0: the largest |d| reached so far).
    double length_scale = 0.0;
    /// Largest step (0: no bound besides the span).
    double max_step = 0.0;
    /// symrep::error beyond this many accepted steps in one call.
    std::size_t max_steps = 50'000'000;
};

struct se3_tensor_result {
    std::vector<rigid_motion> Q;  ///< Q^ at each requested time
    std::size_t steps = 0;        ///< accepted Magnus steps
    std::size_t evaluations = 0;  ///< evaluations of the twist
};

/// The twist of one sixth-order Magnus step of Q^' = -Omega^(t) Q^ over [t, t + h]:
/// Q^(t + h) = se3_exp(se3_magnus6_step(xi, t, h)) Q^(t) + O(h^7).
twist se3_magnus6_step(const twist_function& xi, double t, double h);

/// Q^(t) at each of `times` (sorted, >= 0; 0 may be among them) for
/// Q^' = -Omega^(t) Q^, Q^(0) = I. symrep::type_error for unsorted or negative
/// times or a bad tolerance or length scale; symrep::error when the twist is not
/// finite, not smooth enough for the step control, or the step limit is hit.
se3_tensor_result se3_tensor(const twist_function& xi, const std::vector<double>& times,
                             const se3_tensor_options& options = {});

}  // namespace symrep::num
