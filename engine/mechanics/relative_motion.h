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
// eccentricity; no linearization. Both orbits are propagated at 50 digits
// (numeric/kepler_universal.h) and their difference rounded once: in doubles the
// difference keeps only eps |R|/|rho| of rho (1e-7 relative at |rho| = 1e-9 |R|).
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

/// Two Kepler orbits at time t: the first from (R0, V0), the second from (R0 + d0, V0 + dv0)
/// (inertial components). R, V the first; d, dv the second minus the first. Both are
/// propagated at 50 digits (numeric/kepler_universal.h) and their difference rounded once,
/// so d keeps full double accuracy however small |d0| is against |R0|. domain_error for bad
/// data or an orbit that reaches the centre before t.
struct orbit_pair {
    Eigen::Vector3d R, V;    ///< the first orbit
    Eigen::Vector3d d, dv;   ///< second minus first
};
orbit_pair kepler_pair(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0, const Eigen::Vector3d& d0,
                       const Eigen::Vector3d& dv0, double t);

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

/// The same linear model in closed form (Yamanaka-Ankersen), derived here from the
/// Tschauner-Hempel equations in the true anomaly theta with x~ = rho x, rho = 1 + e cos(theta),
/// ' = d/dtheta (x radial, y along track, z normal):
///     x~'' = 3 x~/rho + 2 y~',   y~'' = -2 x~',   z~'' = -z~.
/// y~' = -2 x~ + C turns the first into L[x~] = x~'' + (4 - 3/rho) x~ = 2 C, whose solutions are
/// s = rho sin(theta) (L[s] = 0), c = rho cos(theta) (L[c] = 2 e) and 2 - 3 e s J (L = 2), with
/// J = int_theta0^theta dtheta/rho^2 = k^2 (t - t0), k^2 = h/p^2 (theta' = k^2 rho^2 in t); then
///     x~ = d1 s + d2 c + d3 (2 - 3 e s J),
///     y~ = d1 c (1 + 1/rho) - d2 s (1 + 1/rho) - 3 d3 rho^2 J + d4,   z~ = d5 sin + d6 cos,
/// no secular theta left (J carries the drift), so only cos and sin of theta are needed: from
/// the target's position (numeric/kepler.h) against the perifocal axes fixed at t = 0. The
/// constants d come from the state at t = 0 (a 4x4 solve, the pseudo-initial values of
/// Yamanaka and Ankersen). Any eccentricity (circular: Clohessy-Wiltshire; hyperbolic too).
std::vector<relative_state> yamanaka_ankersen(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                              const relative_state& start, const std::vector<double>& times);

}  // namespace symrep::mechanics
