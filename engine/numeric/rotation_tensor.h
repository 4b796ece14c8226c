// symrep/numeric/rotation_tensor.h -- the rotation tensor Q(t) of an arbitrary
// angular velocity w(t), evaluated numerically on SO(3).
//
// Thesis VI.3.1: for a frame rotating with angular velocity w(t), the rotation
// tensor solves
//     Q' = -W(t) Q,   Q(0) = I,            W x = w(t) x x           (VI.3.117)
// (the sign of FORMULAS.md: taking VI.2's Q' = +W Q and transposing is wrong
// once the direction of w moves). Then F_{-w}(x) = Q x is the operator of
// Thm VI.3.1.1 and the solution of the rotating-frame problem is r = Q psi,
// psi the inertial solution (Thm VI.3.2.1; mechanics/rotating_frame.h).
//
// Q has no closed form for a general w(t). It is integrated here with the
// sixth-order Magnus method of Blanes, Casas and Ros on three Gauss-Legendre
// nodes: each step multiplies Q by exp(Omega), Omega in so(3) written as a
// 3-vector (the commutator of so(3) is the cross product), and exp is the
// Rodrigues formula. So Q stays orthogonal to rounding whatever the step
// (no drift of det Q or of |Q x|), unlike a Runge-Kutta method on the nine
// components. The step is controlled by comparing one step with two half
// steps (local error O(h^7)), so that the truncation error per unit time stays
// below rel_tol / max(1, t_end): the global error over [0, t_end] is then about
// rel_tol, plus rounding that grows like sqrt(steps) ulps.
//
// Closed form where w has a fixed direction: w(t) = w(t) u, u a constant unit
// vector and w(t) a signed scalar with alpha(t) = integral_0^t w, gives
//     Q x = (u . x) u - sin(alpha) u x x - cos(alpha) u x (u x x)   (VI.2.12)
// (fixed_direction_rotation below).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace symrep::num {

/// An angular velocity as a function of time.
using angular_velocity = std::function<Eigen::Vector3d(double t)>;

struct rotation_tensor_options {
    /// Bound on the local error per unit time (Frobenius norm of the difference
    /// between one step and two half steps, divided by the step).
    double rel_tol = 1e-13;
    /// Largest step (0: no bound besides the span).
    double max_step = 0.0;
    /// symrep::error beyond this many accepted steps in one call.
    std::size_t max_steps = 50'000'000;
};

struct rotation_tensor_result {
    std::vector<Eigen::Matrix3d> Q;  ///< Q at each requested time
    std::size_t steps = 0;           ///< accepted Magnus steps
    std::size_t evaluations = 0;     ///< evaluations of w
};

/// The 3x3 skew matrix of a: W x = a x x.
Eigen::Matrix3d skew(const Eigen::Vector3d& a);

/// exp(skew(theta)) by Rodrigues' formula (VI.1.13-14), accurate for small |theta|.
Eigen::Matrix3d rotation_exp(const Eigen::Vector3d& theta);

/// The so(3) vector of one sixth-order Magnus step of Q' = -W(t) Q over [t, t + h]:
/// Q(t + h) = rotation_exp(magnus6_step(w, t, h)) Q(t) + O(h^7).
Eigen::Vector3d magnus6_step(const angular_velocity& w, double t, double h);

/// Q(t) at each of `times` (sorted, >= 0; 0 may be among them) for Q' = -W Q,
/// Q(0) = I (VI.3.117). symrep::type_error for unsorted or negative times or a
/// bad tolerance; symrep::error when w is not finite or the step limit is hit.
rotation_tensor_result rotation_tensor(const angular_velocity& w, const std::vector<double>& times,
                                       const rotation_tensor_options& options = {});

/// Q x for w(t) = w(t) u of fixed direction (VI.2.12, FORMULAS.md): alpha the
/// integral of the signed rate from 0 to t, u a unit vector.
Eigen::Matrix3d fixed_direction_rotation(const Eigen::Vector3d& u, double alpha);

}  // namespace symrep::num
