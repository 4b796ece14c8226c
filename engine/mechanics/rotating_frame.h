// symrep/mechanics/rotating_frame.h -- motion in a central positional field
// seen from a frame rotating with an arbitrary angular velocity w(t), by
// reduction to the inertial problem (thesis VI.3.2).
//
// Thm VI.3.2.1: the solution of
//     r'' + 2 w x r' + w x (w x r) + w' x r + f(|r|) r/|r| = 0,
//     r(0) = r0, r'(0) = v0                                          (VI.3.132)
// is r = F_{-w}(psi) = Q psi, Q the rotation tensor (Q' = -W Q, Q(0) = I;
// numeric/rotation_tensor.h) and psi the solution of the inertial problem
//     psi'' + f(|psi|) psi/|psi| = 0, psi(0) = r0, psi'(0) = v0 + w(0) x r0.  (VI.3.133)
// Differentiating, r' = Q psi' - w x r.
//
// The inertial problem is solved in closed form for the free particle (f = 0),
// the isotropic oscillator (f(p) = w0^2 p) and Kepler's field (f(p) = mu/p^2,
// numeric/kepler.h), and by Boost.Odeint for any other f. Q is in closed form
// when w has a fixed direction (VI.2.12), numeric (sixth-order Magnus on
// SO(3)) otherwise.
//
// Thm VI.3.2.2 gives the first integrals (VI.3.140-141):
//     E = |r'|^2/2 + (w, r, r') + |w x r|^2/2 + V(|r|),   V' = f,
//     Q^T (r x (r' + w x r)) = Omega_0 = r0 x (v0 + w(0) x r0).
// integrate_rotating_frame() solves (VI.3.132) directly with Boost.Odeint, as
// the reference the reduction is checked against.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "symrep/numeric/integrate.h"
#include "symrep/numeric/rotation_tensor.h"

namespace symrep::mechanics {

/// The central field f(|r|) r/|r| of (VI.3.132), with its potential V (V' = f).
struct central_field {
    enum class kind { free, harmonic, kepler, general };
    kind type = kind::free;
    double parameter = 0;  ///< w0^2 (harmonic) or mu (kepler)
    std::function<double(double)> f;          ///< general only
    std::function<double(double)> potential;  ///< general only (may be empty: no energy integral)

    static central_field none() { return {}; }
    static central_field harmonic(double w0_squared) { return {kind::harmonic, w0_squared, {}, {}}; }
    static central_field kepler(double mu) { return {kind::kepler, mu, {}, {}}; }
    static central_field general(std::function<double(double)> f, std::function<double(double)> V = {}) {
        return {kind::general, 0, std::move(f), std::move(V)};
    }
    /// f(p), p = |r| > 0.
    double force(double p) const;
    /// V(p) with V' = f (the constant chosen so that V vanishes at infinity for
    /// Kepler and at 0 for the oscillator); nullopt when no potential was given.
    std::optional<double> energy_potential(double p) const;
    std::string name() const;
};

/// The Cauchy problem (VI.3.132). `w_dot` is w'(t); when w has a fixed
/// direction, `axis` (a unit vector) and `angle` (alpha(t) = integral_0^t of the
/// signed rate) give Q in closed form (VI.2.12).
struct rotating_frame_problem {
    num::angular_velocity w;
    num::angular_velocity w_dot;
    central_field field;
    Eigen::Vector3d r0 = Eigen::Vector3d::Zero();
    Eigen::Vector3d v0 = Eigen::Vector3d::Zero();
    std::optional<Eigen::Vector3d> axis;
    std::function<double(double)> angle;
    /// Q(t) in closed form for another reason (a regular precession); used when set.
    std::function<Eigen::Matrix3d(double)> rotation;
};

struct rotating_frame_state {
    Eigen::Vector3d r;
    Eigen::Vector3d v;  ///< r' (velocity relative to the rotating frame)
};

/// The inertial solution of (VI.3.133) at each time (psi, psi').
std::vector<rotating_frame_state> inertial_solution(const central_field& field, const Eigen::Vector3d& psi0,
                                                    const Eigen::Vector3d& dpsi0, const std::vector<double>& times,
                                                    double rel_tol = 1e-13);

/// (Thm VI.3.2.1) r = Q psi, r' = Q psi' - w x r at each time (sorted, >= 0).
std::vector<rotating_frame_state> solve_by_reduction(const rotating_frame_problem& P, const std::vector<double>& times,
                                                     const num::rotation_tensor_options& options = {});

/// (VI.3.132) integrated directly with Boost.Odeint (state r, r').
std::vector<rotating_frame_state> integrate_rotating_frame(const rotating_frame_problem& P,
                                                           const std::vector<double>& times,
                                                           const num::integration_options& options = {});

/// (VI.3.140) the energy integral at (t, r, r'); nullopt when the field has no potential.
std::optional<double> energy_integral(const rotating_frame_problem& P, double t, const rotating_frame_state& s);

/// (VI.3.141) r x (r' + w x r), which equals Q Omega_0 (its length is constant).
Eigen::Vector3d angular_momentum_integral(const rotating_frame_problem& P, double t, const rotating_frame_state& s);

}  // namespace symrep::mechanics
