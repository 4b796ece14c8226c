// symrep/numeric/kepler.cpp -- Kepler's problem by universal variables (see kepler.h).
#include "symrep/numeric/kepler.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "symrep/core/error.h"
#include "symrep/numeric/kepler_universal.h"

namespace symrep::num {

double stumpff_c2(double z) { return stumpff_c2_of(z); }

double stumpff_c3(double z) { return stumpff_c3_of(z); }

double kepler_energy(double mu, const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
    return v.squaredNorm() / 2 - mu / r.norm();
}

kepler_state kepler_propagate(double mu, const Eigen::Vector3d& r0v, const Eigen::Vector3d& v0, double t) {
    if (!(mu > 0) || !std::isfinite(mu)) throw domain_error("kepler: mu must be a positive number");
    if (!r0v.allFinite() || !v0.allFinite() || !std::isfinite(t))
        throw domain_error("kepler: the initial state and the time must be finite");
    const kepler_state_of<double> s =
        kepler_propagate_of<double>(mu, {r0v.x(), r0v.y(), r0v.z()}, {v0.x(), v0.y(), v0.z()}, t);
    const Eigen::Vector3d r(s.position[0], s.position[1], s.position[2]);
    const Eigen::Vector3d v(s.velocity[0], s.velocity[1], s.velocity[2]);
    if (!r.allFinite() || !v.allFinite())
        throw domain_error("kepler: the orbit reaches the centre of the field before t (a radial fall) or Kepler's "
                           "equation did not converge");
    return {r, v};
}

}  // namespace symrep::num
