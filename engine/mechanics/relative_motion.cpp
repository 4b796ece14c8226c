// symrep/mechanics/relative_motion.cpp -- exact relative orbital motion and the
// Clohessy-Wiltshire model (see relative_motion.h).
#include "symrep/mechanics/relative_motion.h"

#include <cmath>

#include <Eigen/LU>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "symrep/core/error.h"
#include "symrep/numeric/integrate.h"
#include "symrep/numeric/kepler.h"
#include "symrep/numeric/kepler_universal.h"

namespace symrep::mechanics {

Eigen::Matrix3d lvlh_axes(const Eigen::Vector3d& R, const Eigen::Vector3d& V) {
    const Eigen::Vector3d h = R.cross(V);
    if (h.norm() == 0 || R.norm() == 0)
        throw domain_error("LVLH frame: the target's orbit is radial (R x V = 0), its frame has no normal");
    const Eigen::Vector3d x = R.normalized(), z = h.normalized(), y = z.cross(x);
    Eigen::Matrix3d Ct;
    Ct.row(0) = x.transpose();
    Ct.row(1) = y.transpose();
    Ct.row(2) = z.transpose();
    return Ct;
}

Eigen::Vector3d lvlh_rate(const Eigen::Vector3d& R, const Eigen::Vector3d& V) {
    return R.cross(V) / R.squaredNorm();
}

namespace {

using wide = boost::multiprecision::cpp_bin_float_50;

num::triple_of<wide> widened(const Eigen::Vector3d& a) { return {wide(a.x()), wide(a.y()), wide(a.z())}; }

/// a - b of two wide triples, rounded once to double.
Eigen::Vector3d difference(const num::triple_of<wide>& a, const num::triple_of<wide>& b) {
    return {static_cast<double>(a[0] - b[0]), static_cast<double>(a[1] - b[1]), static_cast<double>(a[2] - b[2])};
}

Eigen::Vector3d narrowed(const num::triple_of<wide>& a) {
    return {static_cast<double>(a[0]), static_cast<double>(a[1]), static_cast<double>(a[2])};
}

}  // namespace

orbit_pair kepler_pair(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0, const Eigen::Vector3d& d0,
                       const Eigen::Vector3d& dv0, double t) {
    if (!(mu > 0) || !std::isfinite(mu)) throw domain_error("kepler: mu must be a positive number");
    if (!R0.allFinite() || !V0.allFinite() || !d0.allFinite() || !dv0.allFinite() || !std::isfinite(t))
        throw domain_error("kepler: the initial state and the time must be finite");
    // both orbits in closed form (the inertial problems of Thm VI.3.2.1) at 50 digits, then
    // their difference rounded once: in doubles, R0 + d0 and r_c - R lose the digits of
    // |R|/|rho| (1e7 at a separation of 1e-7 |R|; the differential harness saw 3e-7 there)
    const num::triple_of<wide> R0w = widened(R0), V0w = widened(V0), d0w = widened(d0), dv0w = widened(dv0);
    num::triple_of<wide> rc0, vc0;
    for (int i = 0; i < 3; ++i) rc0[i] = R0w[i] + d0w[i], vc0[i] = V0w[i] + dv0w[i];
    const wide muw(mu), tw(t);
    const num::kepler_state_of<wide> first = num::kepler_propagate_of<wide>(muw, R0w, V0w, tw);
    const num::kepler_state_of<wide> second = num::kepler_propagate_of<wide>(muw, rc0, vc0, tw);
    orbit_pair out{narrowed(first.position), narrowed(first.velocity), difference(second.position, first.position),
                   difference(second.velocity, first.velocity)};
    if (!out.R.allFinite() || !out.V.allFinite() || !out.d.allFinite() || !out.dv.allFinite())
        throw domain_error("kepler: the orbit reaches the centre of the field before t (a radial fall) or Kepler's "
                           "equation did not converge");
    return out;
}

relative_state relative_motion_exact(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                     const relative_state& start, double t) {
    if (!(mu > 0) || !std::isfinite(mu)) throw domain_error("kepler: mu must be a positive number");
    if (!R0.allFinite() || !V0.allFinite() || !start.position.allFinite() || !start.velocity.allFinite() ||
        !std::isfinite(t))
        throw domain_error("kepler: the initial state and the time must be finite");
    // the chaser in inertial components: d/dt (C rho) = C rho' + w x (C rho)
    const Eigen::Matrix3d C0 = lvlh_axes(R0, V0).transpose();
    const Eigen::Vector3d d0 = C0 * start.position;
    const Eigen::Vector3d dv0 = C0 * start.velocity + lvlh_rate(R0, V0).cross(d0);
    const orbit_pair o = kepler_pair(mu, R0, V0, d0, dv0, t);
    const Eigen::Matrix3d Ct = lvlh_axes(o.R, o.V);
    const Eigen::Vector3d w = lvlh_rate(o.R, o.V);
    return {Ct * o.d, Ct * (o.dv - w.cross(o.d))};
}

relative_state clohessy_wiltshire(double n, const relative_state& s, double t) {
    const double c = std::cos(n * t), sn = std::sin(n * t), nt = n * t;
    const Eigen::Vector3d& p = s.position;
    const Eigen::Vector3d& v = s.velocity;
    relative_state out;
    out.position = Eigen::Vector3d((4 - 3 * c) * p.x() + sn / n * v.x() + 2 / n * (1 - c) * v.y(),
                                   6 * (sn - nt) * p.x() + p.y() - 2 / n * (1 - c) * v.x() + (4 * sn - 3 * nt) / n * v.y(),
                                   c * p.z() + sn / n * v.z());
    out.velocity = Eigen::Vector3d(3 * n * sn * p.x() + c * v.x() + 2 * sn * v.y(),
                                   -6 * n * (1 - c) * p.x() - 2 * sn * v.x() + (4 * c - 3) * v.y(),
                                   -n * sn * p.z() + c * v.z());
    return out;
}

std::vector<relative_state> tschauner_hempel(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                             const relative_state& start, const std::vector<double>& times,
                                             double rel_tol) {
    lvlh_axes(R0, V0);  // refuses a radial target orbit
    // state: the target (R, V) in inertial components, then rho, rho' in the LVLH frame
    const num::rhs_function rhs = [mu](double, const double* y, double* dy) {
        const Eigen::Vector3d R(y[0], y[1], y[2]), V(y[3], y[4], y[5]), p(y[6], y[7], y[8]), v(y[9], y[10], y[11]);
        const double r = R.norm(), h = R.cross(V).norm(), rdot = R.dot(V) / r;
        const Eigen::Vector3d w(0, 0, h / (r * r)), wd(0, 0, -2 * h * rdot / (r * r * r));
        const double k = mu / (r * r * r);
        // (rho - 3 (rho . x) x) with x = (1, 0, 0) in the frame
        const Eigen::Vector3d tidal(-2 * p.x(), p.y(), p.z());
        const Eigen::Vector3d a = -2 * w.cross(v) - wd.cross(p) - w.cross(w.cross(p)) - k * tidal;
        const Eigen::Vector3d A = -k * R;
        for (int i = 0; i < 3; ++i) {
            dy[i] = V[i], dy[3 + i] = A[i], dy[6 + i] = v[i], dy[9 + i] = a[i];
        }
    };
    std::vector<double> y0(R0.data(), R0.data() + 3);
    y0.insert(y0.end(), V0.data(), V0.data() + 3);
    y0.insert(y0.end(), start.position.data(), start.position.data() + 3);
    y0.insert(y0.end(), start.velocity.data(), start.velocity.data() + 3);
    num::integration_options o;
    o.rel_tol = rel_tol;
    o.abs_tol = rel_tol * std::max(start.position.stableNorm(), 1e-300);  // norm() overflows at 1e155
    const num::integration_result res = num::integrate(rhs, 0.0, y0, times, o);
    std::vector<relative_state> out;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Eigen::VectorXd y = res.states.row(Eigen::Index(k));
        out.push_back({y.segment<3>(6), y.segment<3>(9)});
    }
    return out;
}

namespace {

// The in-plane fundamental matrix of the Tschauner-Hempel equations in the true anomaly
// (see yamanaka_ankersen in relative_motion.h): columns the four solutions, rows x~, y~,
// x~', y~' at cos(theta) = ct, sin(theta) = st and J = k^2 (t - t0).
Eigen::Matrix4d in_plane_basis(double e, double ct, double st, double J) {
    const double rho = 1 + e * ct, s = rho * st, c = rho * ct;
    const double ds = ct + e * (ct * ct - st * st), dc = -st - 2 * e * st * ct;
    const double X3 = 2 - 3 * e * s * J, dX3 = -3 * e * (ds * J + s / (rho * rho));
    Eigen::Matrix4d M;
    M << s, c, X3, 0,                                        // x~
        c * (1 + 1 / rho), -s * (1 + 1 / rho), -3 * rho * rho * J, 1,  // y~
        ds, dc, dX3, 0,                                      // x~'
        -2 * s, -2 * c + e, -2 * X3 + 1, 0;                  // y~' = -2 x~ + const
    return M;
}

}  // namespace

std::vector<relative_state> yamanaka_ankersen(double mu, const Eigen::Vector3d& R0, const Eigen::Vector3d& V0,
                                              const relative_state& start, const std::vector<double>& times) {
    lvlh_axes(R0, V0);  // refuses a radial target orbit
    if (!(mu > 0) || !std::isfinite(mu)) throw domain_error("yamanaka_ankersen: mu must be positive");
    const Eigen::Vector3d H = R0.cross(V0);
    const double h = H.norm(), p = h * h / mu, k2 = h / (p * p);
    const Eigen::Vector3d ev = V0.cross(H) / mu - R0.normalized();
    const double e = ev.norm();
    // the perifocal directions, fixed along a Kepler orbit; for e = 0 any origin of theta serves
    const Eigen::Vector3d P = e > 0 ? Eigen::Vector3d(ev / e) : Eigen::Vector3d(R0.normalized());
    const Eigen::Vector3d Qd = H.normalized().cross(P);
    auto anomaly = [&](const Eigen::Vector3d& R, double& ct, double& st) {
        const Eigen::Vector3d u = R.normalized();
        ct = u.dot(P), st = u.dot(Qd);
    };
    // x~ = rho x, x~' = -e sin(theta) x + x'/(k^2 rho) (' in theta on the left, in t on the right)
    double c0, s0;
    anomaly(R0, c0, s0);
    const double rho0 = 1 + e * c0;
    const Eigen::Vector3d& q = start.position;
    const Eigen::Vector3d& v = start.velocity;
    auto tilde_rate = [&](double x, double xd) { return -e * s0 * x + xd / (k2 * rho0); };
    const Eigen::Vector4d plane0(rho0 * q.x(), rho0 * q.y(), tilde_rate(q.x(), v.x()), tilde_rate(q.y(), v.y()));
    const Eigen::Vector4d d = in_plane_basis(e, c0, s0, 0).partialPivLu().solve(plane0);
    // out of the plane: z~ = d5 sin(theta) + d6 cos(theta)
    const double z0 = rho0 * q.z(), dz0 = tilde_rate(q.z(), v.z());
    const double d5 = z0 * s0 + dz0 * c0, d6 = z0 * c0 - dz0 * s0;
    std::vector<relative_state> out;
    out.reserve(times.size());
    for (const double t : times) {
        if (!(t >= 0) || !std::isfinite(t)) throw domain_error("yamanaka_ankersen: the times must be finite and >= 0");
        const num::kepler_state target = num::kepler_propagate(mu, R0, V0, t);
        double ct, st;
        anomaly(target.position, ct, st);
        const double rho = 1 + e * ct;
        const Eigen::Vector4d x = in_plane_basis(e, ct, st, k2 * t) * d;
        const double z = d5 * st + d6 * ct, dz = d5 * ct - d6 * st;
        // back: x = x~/rho, x' = k^2 (rho x~' + e sin(theta) x~)
        auto rate = [&](double xt, double dxt) { return k2 * (rho * dxt + e * st * xt); };
        out.push_back({Eigen::Vector3d(x[0] / rho, x[1] / rho, z / rho),
                       Eigen::Vector3d(rate(x[0], x[2]), rate(x[1], x[3]), rate(z, dz))});
    }
    return out;
}

}  // namespace symrep::mechanics
