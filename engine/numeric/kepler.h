// symrep/numeric/kepler.h -- the inertial Kepler problem psi'' = -mu psi/|psi|^3
// in closed form, by universal variables (elliptic, parabolic and hyperbolic
// orbits alike).
//
// Thm VI.3.2.1 reduces Kepler's problem in an arbitrarily rotating frame to the
// inertial one (VI.3.153-157): r = Q psi. The inertial solution is
//     psi(t) = f psi0 + g v0,   psi'(t) = f' psi0 + g' v0
// with the Lagrange coefficients in the universal anomaly chi and the Stumpff
// functions c2, c3 of z = alpha chi^2 (alpha = 2/|psi0| - |v0|^2/mu, the inverse
// semi-major axis):
//     f = 1 - chi^2 c2 / r0,   g = t - chi^3 c3 / sqrt(mu),
//     f' = sqrt(mu) chi (z c3 - 1) / (r r0),   g' = 1 - chi^2 c2 / r,
// where chi solves the universal Kepler equation
//     sqrt(mu) t = sigma0 chi^2 c2 + (1 - alpha r0) chi^3 c3 + r0 chi,
//     sigma0 = psi0 . v0 / sqrt(mu),
// solved here by the Laguerre-Conway iteration (it converges from the usual
// starting guesses for every conic) and polished by Newton steps to full double
// accuracy. Elliptic orbits reduce t modulo the period first, so chi stays
// bounded over any number of revolutions. The Stumpff functions use their
// series for |z| < 1 (no cancellation) and the closed forms beyond. The method is
// written once for any floating-point type in numeric/kepler_universal.h; these
// are its double instances, and cpp_bin_float_50 (or wider) gives the reference
// values (Kepler.FullDoubleAccuracyAgainstTheFiftyDigitReference).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace symrep::num {

struct kepler_state {
    Eigen::Vector3d position;
    Eigen::Vector3d velocity;
};

/// c2(z) = (1 - cos sqrt z)/z, c3(z) = (sqrt z - sin sqrt z)/z^(3/2) (and their
/// hyperbolic continuations for z < 0; c2(0) = 1/2, c3(0) = 1/6).
double stumpff_c2(double z);
double stumpff_c3(double z);

/// Specific orbital energy |v|^2/2 - mu/|r| (VI.3.154: the orbit is bounded iff it is < 0).
double kepler_energy(double mu, const Eigen::Vector3d& r, const Eigen::Vector3d& v);

/// The solution of psi'' = -mu psi/|psi|^3, psi(0) = r0, psi'(0) = v0, at time t
/// (any sign). symrep::domain_error for mu <= 0, r0 = 0 or non-finite data, and
/// for a radial orbit (r0 x v0 = 0, which meets the centre of the field).
kepler_state kepler_propagate(double mu, const Eigen::Vector3d& r0, const Eigen::Vector3d& v0, double t);

}  // namespace symrep::num
