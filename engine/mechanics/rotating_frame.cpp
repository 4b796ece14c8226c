// symrep/mechanics/rotating_frame.cpp -- reduction of rotating-frame central-field
// problems to the inertial problem (see rotating_frame.h).
#include "symrep/mechanics/rotating_frame.h"

#include <cmath>

#include "symrep/core/error.h"
#include "symrep/numeric/kepler.h"

namespace symrep::mechanics {

double central_field::force(double p) const {
    switch (type) {
        case kind::free: return 0.0;
        case kind::harmonic: return parameter * p;
        case kind::kepler: return parameter / (p * p);
        case kind::general: return f(p);
    }
    return 0.0;
}

std::optional<double> central_field::energy_potential(double p) const {
    switch (type) {
        case kind::free: return 0.0;
        case kind::harmonic: return parameter * p * p / 2;
        case kind::kepler: return -parameter / p;
        case kind::general:
            if (potential) return potential(p);
            return std::nullopt;
    }
    return std::nullopt;
}

std::string central_field::name() const {
    switch (type) {
        case kind::free: return "no field";
        case kind::harmonic: return "isotropic oscillator";
        case kind::kepler: return "Kepler field";
        case kind::general: return "central field f(|r|)";
    }
    return "";
}

std::vector<rotating_frame_state> inertial_solution(const central_field& field, const Eigen::Vector3d& psi0,
                                                    const Eigen::Vector3d& dpsi0, const std::vector<double>& times,
                                                    double rel_tol) {
    std::vector<rotating_frame_state> out;
    out.reserve(times.size());
    switch (field.type) {
        case central_field::kind::free:
            for (const double t : times) out.push_back({psi0 + t * dpsi0, dpsi0});
            return out;
        case central_field::kind::harmonic: {
            const double k = field.parameter;
            const double w0 = std::sqrt(std::abs(k));
            for (const double t : times) {
                double c, s, sd;  // psi = c psi0 + s dpsi0, psi' = sd psi0 + c dpsi0
                if (k > 0) {
                    c = std::cos(w0 * t);
                    s = std::sin(w0 * t) / w0;
                    sd = -w0 * std::sin(w0 * t);
                } else if (k < 0) {  // a repulsive linear field
                    c = std::cosh(w0 * t);
                    s = std::sinh(w0 * t) / w0;
                    sd = w0 * std::sinh(w0 * t);
                } else {
                    c = 1;
                    s = t;
                    sd = 0;
                }
                out.push_back({c * psi0 + s * dpsi0, sd * psi0 + c * dpsi0});
            }
            return out;
        }
        case central_field::kind::kepler:
            for (const double t : times) {
                const num::kepler_state k = num::kepler_propagate(field.parameter, psi0, dpsi0, t);
                out.push_back({k.position, k.velocity});
            }
            return out;
        case central_field::kind::general: {
            const num::rhs_function rhs = [&](double, const double* y, double* dy) {
                const Eigen::Vector3d p(y[0], y[1], y[2]);
                const double rho = p.norm();
                if (rho == 0) throw domain_error("the motion reaches the centre of the field (|r| = 0)");
                const Eigen::Vector3d a = -field.f(rho) / rho * p;
                for (int i = 0; i < 3; ++i) {
                    dy[i] = y[3 + i];
                    dy[3 + i] = a[i];
                }
            };
            num::integration_options o;
            o.rel_tol = o.abs_tol = rel_tol;
            const std::vector<double> y0{psi0.x(), psi0.y(), psi0.z(), dpsi0.x(), dpsi0.y(), dpsi0.z()};
            const num::integration_result res = num::integrate(rhs, 0.0, y0, times, o);
            for (std::size_t k = 0; k < times.size(); ++k) {
                const Eigen::VectorXd y = res.state(k);
                out.push_back({y.head<3>(), y.tail<3>()});
            }
            return out;
        }
    }
    return out;
}

std::vector<rotating_frame_state> solve_by_reduction(const rotating_frame_problem& P, const std::vector<double>& times,
                                                     const num::rotation_tensor_options& options) {
    // (VI.3.133) psi(0) = r0, psi'(0) = v0 + w(0) x r0
    const Eigen::Vector3d dpsi0 = P.v0 + P.w(0.0).cross(P.r0);
    const std::vector<rotating_frame_state> psi = inertial_solution(P.field, P.r0, dpsi0, times);
    std::vector<Eigen::Matrix3d> Q;
    if (P.rotation) {
        for (const double t : times) Q.push_back(P.rotation(t));
    } else if (P.axis && P.angle) {
        for (const double t : times) Q.push_back(num::fixed_direction_rotation(*P.axis, P.angle(t)));  // (VI.2.12)
    } else {
        Q = num::rotation_tensor(P.w, times, options).Q;  // (VI.3.117)
    }
    std::vector<rotating_frame_state> out;
    out.reserve(times.size());
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Eigen::Vector3d r = Q[k] * psi[k].r;                    // (VI.3.138) r = F_{-w}(psi)
        const Eigen::Vector3d v = Q[k] * psi[k].v - P.w(times[k]).cross(r);  // r' = Q psi' - w x r
        out.push_back({r, v});
    }
    return out;
}

std::vector<rotating_frame_state> integrate_rotating_frame(const rotating_frame_problem& P,
                                                           const std::vector<double>& times,
                                                           const num::integration_options& options) {
    const num::rhs_function rhs = [&](double t, const double* y, double* dy) {
        const Eigen::Vector3d r(y[0], y[1], y[2]), v(y[3], y[4], y[5]);
        const Eigen::Vector3d w = P.w(t), wd = P.w_dot(t);
        const double rho = r.norm();
        Eigen::Vector3d a = -2.0 * w.cross(v) - w.cross(w.cross(r)) - wd.cross(r);
        if (P.field.type != central_field::kind::free) {
            if (rho == 0) throw domain_error("the motion reaches the centre of the field (|r| = 0)");
            a -= P.field.force(rho) / rho * r;
        }
        for (int i = 0; i < 3; ++i) {
            dy[i] = v[i];
            dy[3 + i] = a[i];
        }
    };
    const std::vector<double> y0{P.r0.x(), P.r0.y(), P.r0.z(), P.v0.x(), P.v0.y(), P.v0.z()};
    const num::integration_result res = num::integrate(rhs, 0.0, y0, times, options);
    std::vector<rotating_frame_state> out;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Eigen::VectorXd y = res.state(k);
        out.push_back({y.head<3>(), y.tail<3>()});
    }
    return out;
}

std::optional<double> energy_integral(const rotating_frame_problem& P, double t, const rotating_frame_state& s) {
    const std::optional<double> V = P.field.energy_potential(s.r.norm());
    if (!V) return std::nullopt;
    const Eigen::Vector3d w = P.w(t);
    // (VI.3.140) |r'|^2/2 + (w, r, r') + |w x r|^2/2 + V(|r|)
    return s.v.squaredNorm() / 2 + w.dot(s.r.cross(s.v)) + w.cross(s.r).squaredNorm() / 2 + *V;
}

Eigen::Vector3d angular_momentum_integral(const rotating_frame_problem& P, double t, const rotating_frame_state& s) {
    return s.r.cross(s.v + P.w(t).cross(s.r));  // (VI.3.141)
}

}  // namespace symrep::mechanics
