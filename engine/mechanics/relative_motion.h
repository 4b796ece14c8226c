// symrep/mechanics/relative_motion.h -- exact relative orbital motion: a chaser
// seen from the orbital (LVLH) frame of a target on a Keplerian orbit, and the
// linear Clohessy-Wiltshire model as its limit.
//
// The LVLH frame of the target (x radial, R/|R|; z along the orbit normal
// h = R x V; y = z x x, along the track) rotates with w(t) = (|h|/|R|^2) z, of
// fixed direction (the orbit normal) and varying rate. The chaser's position
// relative to the target, rho = r_c - R, obeys in that frame
//     rho'' + 2 w x rho' + w x (w x rho) + w' x rho = -mu (R + rho)/|R + rho|^3 + mu R/|R|^3,
// the difference of two central fields. As in Thm VI.3.2.1 the rotating frame
// is undone by the rotation tensor: rho = Q (psi_c - psi_t), Q = C(t)^T the
// LVLH axes, psi_c and psi_t the inertial Kepler orbits (numeric/kepler.h) of
// chaser and target. That is the exact nonlinear relative motion for any
// eccentricity, evaluated to rounding; no linearization.
//
// clohessy_wiltshire() is the classical linear model for a circular target
// (mean motion n): the first-order terms of the above in |rho|/|R|;
// tschauner_hempel() the linear model for an elliptic target.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace symrep::mechanics {

struct relative_state {
    Eigen::Vector3d position;  ///< in the LVLH frame (x radial, y along track, z normal)
    Eigen::Vector3d velocity;  ///< d/dt of the LVLH components (relative to the rotating frame)
};

/// The LVLH axes of an orbital state as the rows of a matrix C^T: C^T x gives
/// the components of an inertial vector x in the frame. Throws domain_error when
/// R x V = 0.
Eigen::Matrix3d lvlh_axes(const Eigen::Vector3d& R, const Eigen::Vector3d& V);

/// The angular velocity of the LVLH frame in inertial components: (R x V)/|R|^2.
Eigen::Vector3d lvlh_rate(const Eigen::Vector3d& R, const Eigen::Vector3d& V);

/// Exact relative motion: target (R0, V0) and a chaser starting at rho0 with
/// relative velocity drho0 (both in the LVLH frame at t = 0), at time t.
relative_state relative_motion_exact(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                     const relative_state& start, double t);

/// The Clohessy-Wiltshire solution for a circular target of mean motion n.
relative_state clohessy_wiltshire(double n, const relative_state& start, double t);

/// The linear model for a target on an elliptic orbit (Tschauner-Hempel): the
/// relative equation above linearized in rho,
///     rho'' + 2 w x rho' + w' x rho + w x (w x rho) + (mu/|R|^3) (rho - 3 (rho . x) x) = 0,
/// w = |h|/|R|^2 z (x radial, z normal), integrated numerically together with the
/// target's orbit (Boost.Odeint rkf78 at rel_tol; Yamanaka-Ankersen's state-transition
/// matrix is the closed form of the same linear equation). At each of `times` (sorted, >= 0).
std::vector<relative_state> tschauner_hempel(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                             const relative_state& start, const std::vector<double>& times,
                                             double rel_tol = 1e-13);

}  // namespace symrep::mechanics
