// symrep/mechanics/relative_pose.h -- exact full-body relative orbital motion ([C23]):
// the pose (position and attitude) of a deputy rigid body seen from the body frame of
// a leader, both on Keplerian orbits, each turning with a given attitude motion.
//
// Frames and tensors (docs/rigid_body.md section 5). C_L(t), C_D(t): the body axes of
// leader and deputy as the columns of a matrix (inertial components). An attitude motion
// is given by the body's angular velocity w(t) in its own body components; its rotation
// tensor Q(t) = C(t)^T C(0) solves the Poisson-Darboux problem Q' = -W Q, Q(0) = I
// (VI.3.117). The relative pose is the rigid motion
//     Q^_rel = C^_L^T C^_D = (I + eps skew(rho)) R,   rho = C_L^T (r_D - r_L),  R = C_L^T C_D
// (C^ = (I + eps skew(r)) C the pose of a body in the inertial frame): rho the deputy's
// position in the leader's body components, R the deputy's axes in the leader's body
// components. As in Thm VI.3.2.1 the rotating frames are undone by their tensors:
//     Q^_rel(t) = Q_L(t) (I + eps skew(psi(t))) R0 Q_D(t)^T,                         (*)
//     psi(t) = C_L(0)^T (psi_D(t) - psi_L(t)),   R0 = R(0),
// psi_L, psi_D the two inertial Kepler orbits (universal variables, any conic), so
//     rho = Q_L psi,   R = Q_L R0 Q_D^T,
//     rho' = Q_L psi' - w_L x rho,   w_rel = R w_D - w_L   (R' = W_rel R),
// no linearization in the separation, no attitude coordinates (no Euler angles: no
// singularity), nothing integrated where Q_L, Q_D are closed: no secular error terms.
// The orbits are propagated at 50 digits and differenced once (mechanics/relative_motion.h
// kepler_pair), the Kepler equation is solved modulo the period. Q is closed for
//   constant w:       Q = exp(-t W) (Rodrigues, VI.1.13);
//   fixed axis:       w = s(t) u, Q = rotation by -alpha(t) about u, alpha = int_0^t s (VI.2.12);
//   regular precession: w = c u1 + R_u1(-c t) v, Q = A B, A = rotation by -c t about u1,
//                     B by -|v| t about v (Q' = -(c K1 + A K_v A^T) Q = -W Q; a torque-free
//                     axisymmetric body precesses so, its body rate w(t) being of this form);
//   orbital:          the body keeps its attitude relative to its own orbital (LVLH) frame:
//                     Q = B^T L(t)^T L(0) B, L the LVLH axes (relative_motion.h), B = L(0)^T C(0),
//                     w = B^T (|h|/|r|^2) z -- closed through Kepler's solution;
// and otherwise integrated by the sixth-order Magnus method on SO(3) (numeric/rotation_tensor.h).
// With the leader's frame its LVLH frame (orbital, B = I) the translational part is
// relative_motion_exact (a test).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <ginac/ginac.h>

#include "symrep/numeric/rotation_tensor.h"
#include "symrep/numeric/se3.h"

namespace symrep::mechanics {

/// How a body turns: its angular velocity in its own body components and the kind of its
/// rotation tensor (closed or numeric). Make one with the static functions.
struct attitude_motion {
    enum class kind { constant, fixed_axis, precession, orbital, numeric };
    kind how = kind::constant;
    Eigen::Vector3d w = Eigen::Vector3d::Zero();     ///< constant: w; precession: the carried spin v
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); ///< fixed_axis: u; precession: u1 (unit vectors)
    double rate = 0;                                 ///< precession: c
    std::function<double(double)> spin, angle;       ///< fixed_axis: s(t) and alpha(t) = int_0^t s
    num::angular_velocity omega;                     ///< numeric: w(t)
    num::rotation_tensor_options options;            ///< numeric: the Magnus method's tolerance

    static attitude_motion constant(const Eigen::Vector3d& w);
    /// w = s(t) u, alpha(t) = int_0^t s (the caller's closed form); u is normalized here.
    static attitude_motion fixed_axis(const Eigen::Vector3d& u, std::function<double(double)> s,
                                      std::function<double(double)> alpha);
    /// w = c u1 + R_u1(-c t) v; u1 is normalized here.
    static attitude_motion precession(const Eigen::Vector3d& u1, double c, const Eigen::Vector3d& v);
    /// Locked to the body's own orbital (LVLH) frame.
    static attitude_motion orbital();
    static attitude_motion numeric(num::angular_velocity w, const num::rotation_tensor_options& o = {});

    /// "constant", "fixed axis", "regular precession", "orbital", "numeric (Magnus)"
    const char* name() const;
};

/// The relative pose at one time: the rigid motion Q^_rel = (I + eps skew(position)) attitude.
struct pose_state {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< rho: the deputy in leader body components
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< rho': d/dt of those components
    Eigen::Matrix3d attitude = Eigen::Matrix3d::Identity();  ///< R: the deputy's axes in leader body components
    Eigen::Vector3d rate = Eigen::Vector3d::Zero();      ///< w_rel = R w_D - w_L (leader components), R' = W_rel R
    /// The pose as the rigid motion (I + eps skew(position)) attitude (numeric/se3.h; its dual
    /// quaternion by num::to_dual_quaternion).
    num::rigid_motion motion() const { return {attitude, position}; }
};

struct relative_pose_problem {
    double mu = 0;
    Eigen::Vector3d R0, V0;  ///< the leader's inertial state at t = 0
    /// C_L(0): the leader's body axes (columns, inertial components) at t = 0; with
    /// leader_axes_lvlh (default) they are its LVLH axes times leader_offset:
    /// C_L(0) = lvlh_axes(R0, V0)^T leader_offset.
    bool leader_axes_lvlh = true;
    Eigen::Matrix3d leader_offset = Eigen::Matrix3d::Identity();
    Eigen::Matrix3d leader_axes = Eigen::Matrix3d::Identity();  ///< used when !leader_axes_lvlh
    attitude_motion leader, deputy;
    pose_state start;  ///< rho(0), rho'(0), R(0) (start.rate is ignored: it follows from the motions)
};

/// The relative pose at each of `times` (finite, >= 0, any order). domain_error for a
/// non-orthogonal attitude, mu <= 0, a radial orbit where an orbital frame is asked for, and
/// the errors of Kepler's solution and of the Magnus integrator.
std::vector<pose_state> relative_pose(const relative_pose_problem& P, const std::vector<double>& times);

/// The exact side of (*): a body's rotation tensor Q(t) (Q' = -W Q, Q(0) = I) in closed form from
/// its angular velocity w(t) (body components, an expression in t with numbers only), derived by
/// the engine's closed rotation (turning_frame.h: Rodrigues for a constant w, VI.2.12 for a fixed
/// axis, the composition A B of a regular precession) on the three basis vectors, each column
/// checked as the solution of y' + w x y = 0, y(0) = e_i (mechanics::check: the residual proved 0,
/// exactly, or up to rounding where w holds floats, and the initial value). With both tensors
/// proved, (*) needs nothing more: A = Q_L A0 Q_D^T gives A' = -W_L A + A W_D = W_rel A for every
/// pair of solutions, and rho = Q_L psi carries the inertial equation into the leader's frame for
/// every psi (Thm VI.3.2.1), both proved once for all in tests/test_relative_pose.cpp.
struct closed_attitude {
    GiNaC::ex Q;          ///< the 3x3 matrix Q(t)
    bool proved = false;  ///< every column checked
    double rounding = 0;  ///< > 0: proved up to rounding (floats), the largest remainder ratio
};

/// Nothing when w has no closed rotation tensor here (it turns otherwise: Magnus on SO(3)).
std::optional<closed_attitude> closed_attitude_tensor(const GiNaC::ex& w, const GiNaC::ex& t);

}  // namespace symrep::mechanics
