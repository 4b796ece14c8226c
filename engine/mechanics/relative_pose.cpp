// symrep/mechanics/relative_pose.cpp -- exact full-body relative orbital motion (see
// relative_pose.h): the relative pose as Q_L (I + eps skew(psi)) R0 Q_D^T.
#include "symrep/mechanics/relative_pose.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "symrep/core/error.h"
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/relative_motion.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

namespace {

Eigen::Vector3d unit(const Eigen::Vector3d& u, const char* what) {
    const double n = u.norm();
    if (!(n > 0) || !std::isfinite(n))
        throw domain_error(std::string("relative_pose: the ") + what + " must be a nonzero finite vector");
    return u / n;
}

// |R^T R - I| and det R: a rotation, to rounding
void require_rotation(const Eigen::Matrix3d& R, const char* what) {
    if (!R.allFinite() || (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-9 || R.determinant() < 0)
        throw domain_error(std::string("relative_pose: ") + what +
                           " is not a rotation matrix (R^T R = I and det R = 1 to 1e-9)");
}

/// One body's attitude along its orbit: Q(t) and its w(t) (body components) at the times.
struct attitude_track {
    std::vector<Eigen::Matrix3d> Q;
    std::vector<Eigen::Vector3d> w;
};

// The orbital frame's tensor and rate: L(t) the LVLH axes (columns) of the body's orbit,
// B = L(0)^T C(0); Q = B^T L(t)^T L(0) B, w = B^T (R x V)/|R|^2 in LVLH components.
attitude_track track(const attitude_motion& m, const std::vector<double>& times,
                     const std::vector<Eigen::Vector3d>& R, const std::vector<Eigen::Vector3d>& V,
                     const Eigen::Vector3d& R0, const Eigen::Vector3d& V0, const Eigen::Matrix3d& C0) {
    attitude_track out;
    const std::size_t n = times.size();
    out.Q.resize(n), out.w.resize(n);
    using K = attitude_motion::kind;
    switch (m.how) {
    case K::constant:
        for (std::size_t k = 0; k < n; ++k) out.Q[k] = num::rotation_exp(-times[k] * m.w), out.w[k] = m.w;
        break;
    case K::fixed_axis:
        for (std::size_t k = 0; k < n; ++k) {
            const double a = m.angle(times[k]), s = m.spin(times[k]);
            if (!std::isfinite(a) || !std::isfinite(s))
                throw domain_error("relative_pose: the fixed-axis rate or its angle has no finite value at t = " +
                                   std::to_string(times[k]));
            out.Q[k] = num::fixed_direction_rotation(m.axis, a), out.w[k] = s * m.axis;  // (VI.2.12)
        }
        break;
    case K::precession: {
        for (std::size_t k = 0; k < n; ++k) {
            const double t = times[k];
            const Eigen::Matrix3d A = num::rotation_exp(-m.rate * t * m.axis);
            const Eigen::Matrix3d B = num::rotation_exp(-t * m.w);
            out.Q[k] = A * B;
            out.w[k] = m.rate * m.axis + A * m.w;
        }
        break;
    }
    case K::orbital: {
        const Eigen::Matrix3d L0 = lvlh_axes(R0, V0).transpose();
        const Eigen::Matrix3d B = L0.transpose() * C0;
        for (std::size_t k = 0; k < n; ++k) {
            const Eigen::Matrix3d Lt = lvlh_axes(R[k], V[k]);  // L(t)^T
            out.Q[k] = B.transpose() * Lt * L0 * B;
            out.w[k] = B.transpose() * Eigen::Vector3d(0, 0, R[k].cross(V[k]).norm() / R[k].squaredNorm());
        }
        break;
    }
    case K::numeric: {
        if (!m.omega) throw domain_error("relative_pose: a numeric attitude motion needs w(t)");
        std::vector<std::size_t> order(n);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });
        std::vector<double> sorted;
        for (const std::size_t i : order) sorted.push_back(times[i]);
        const num::rotation_tensor_result r = num::rotation_tensor(m.omega, sorted, m.options);
        for (std::size_t k = 0; k < n; ++k) out.Q[order[k]] = r.Q[k], out.w[order[k]] = m.omega(sorted[k]);
        break;
    }
    }
    return out;
}

}  // namespace

attitude_motion attitude_motion::constant(const Eigen::Vector3d& w) {
    if (!w.allFinite()) throw domain_error("relative_pose: the angular velocity must be finite");
    attitude_motion m;
    m.how = kind::constant;
    m.w = w;
    return m;
}

attitude_motion attitude_motion::fixed_axis(const Eigen::Vector3d& u, std::function<double(double)> s,
                                            std::function<double(double)> alpha) {
    attitude_motion m;
    m.how = kind::fixed_axis;
    m.axis = unit(u, "fixed axis");
    m.spin = std::move(s);
    m.angle = std::move(alpha);
    if (!m.spin || !m.angle) throw domain_error("relative_pose: a fixed-axis motion needs its rate and its angle");
    return m;
}

attitude_motion attitude_motion::precession(const Eigen::Vector3d& u1, double c, const Eigen::Vector3d& v) {
    if (!std::isfinite(c) || !v.allFinite()) throw domain_error("relative_pose: the precession's rates must be finite");
    attitude_motion m;
    m.how = kind::precession;
    m.axis = unit(u1, "precession axis");
    m.rate = c;
    m.w = v;
    return m;
}

attitude_motion attitude_motion::orbital() {
    attitude_motion m;
    m.how = kind::orbital;
    return m;
}

attitude_motion attitude_motion::numeric(num::angular_velocity w, const num::rotation_tensor_options& o) {
    attitude_motion m;
    m.how = kind::numeric;
    m.omega = std::move(w);
    m.options = o;
    return m;
}

const char* attitude_motion::name() const {
    switch (how) {
    case kind::constant: return "constant";
    case kind::fixed_axis: return "fixed axis";
    case kind::precession: return "regular precession";
    case kind::orbital: return "orbital";
    case kind::numeric: return "numeric (Magnus)";
    }
    return "";
}

std::vector<pose_state> relative_pose(const relative_pose_problem& P, const std::vector<double>& times) {
    if (!(P.mu > 0) || !std::isfinite(P.mu)) throw domain_error("relative_pose: mu must be a positive number");
    for (const double t : times)
        if (!(t >= 0) || !std::isfinite(t)) throw domain_error("relative_pose: the times must be finite and >= 0");
    const pose_state& s0 = P.start;
    if (!P.R0.allFinite() || !P.V0.allFinite() || !s0.position.allFinite() || !s0.velocity.allFinite())
        throw domain_error("relative_pose: the initial state must be finite");
    require_rotation(s0.attitude, "the initial relative attitude A(0)");
    Eigen::Matrix3d CL0;
    if (P.leader_axes_lvlh) {
        require_rotation(P.leader_offset, "the leader's attitude relative to its LVLH frame");
        CL0 = lvlh_axes(P.R0, P.V0).transpose() * P.leader_offset;
    } else {
        require_rotation(P.leader_axes, "the leader's initial axes C_L(0)");
        CL0 = P.leader_axes;
    }
    const Eigen::Matrix3d CD0 = CL0 * s0.attitude;
    // the leader's rate at t = 0 for the deputy's inertial velocity: d/dt (C_L rho) = C_L (rho' + w_L x rho)
    const attitude_track L0 = track(P.leader, {0.0}, {P.R0}, {P.V0}, P.R0, P.V0, CL0);
    const Eigen::Vector3d d0 = CL0 * s0.position;
    const Eigen::Vector3d dv0 = CL0 * (s0.velocity + L0.w[0].cross(s0.position));
    // the two inertial Kepler orbits (Thm VI.3.2.1), 50 digits, differenced once
    std::vector<orbit_pair> orbits;
    orbits.reserve(times.size());
    std::vector<Eigen::Vector3d> RL, VL, RD, VD;
    for (const double t : times) {
        orbits.push_back(kepler_pair(P.mu, P.R0, P.V0, d0, dv0, t));
        const orbit_pair& o = orbits.back();
        RL.push_back(o.R), VL.push_back(o.V), RD.push_back(o.R + o.d), VD.push_back(o.V + o.dv);
    }
    const attitude_track QL = track(P.leader, times, RL, VL, P.R0, P.V0, CL0);
    const attitude_track QD = track(P.deputy, times, RD, VD, P.R0 + d0, P.V0 + dv0, CD0);
    std::vector<pose_state> out(times.size());
    for (std::size_t k = 0; k < times.size(); ++k) {
        // (*): rho = Q_L psi, R = Q_L R0 Q_D^T with psi = C_L(0)^T (psi_D - psi_L)
        const Eigen::Matrix3d M = QL.Q[k] * CL0.transpose();
        pose_state& p = out[k];
        p.position = M * orbits[k].d;
        p.velocity = M * orbits[k].dv - QL.w[k].cross(p.position);
        p.attitude = QL.Q[k] * s0.attitude * QD.Q[k].transpose();
        p.rate = p.attitude * QD.w[k] - QL.w[k];
    }
    return out;
}

std::optional<closed_attitude> closed_attitude_tensor(const GiNaC::ex& w, const GiNaC::ex& t) {
    closed_attitude out;
    GiNaC::matrix Q(3, 3);
    out.proved = true;
    for (unsigned i = 0; i < 3; ++i) {
        const GiNaC::ex e = vector_literal(i == 0, i == 1, i == 2);
        // the column Q e_i: y' = -w x y, y(0) = e_i (VI.3.117 on a vector)
        const auto P = rotation_problem(-w, e, t);
        const auto y = closed_solution(*P, *P->turning);
        if (!y) return std::nullopt;
        const solution_check k = check(*P, *y);
        out.proved = out.proved && bool(k);
        out.rounding = std::max(out.rounding, k.rounding);
        const GiNaC::ex c = vector_symbols(*y).empty() ? subs_components(*y, {}) : *y;
        if (!is_vector_literal(c)) return std::nullopt;
        for (unsigned r = 0; r < 3; ++r) Q(r, i) = c.op(r);
    }
    out.Q = Q;
    return out;
}

}  // namespace symrep::mechanics
