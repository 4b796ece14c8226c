// symrep/numeric/kepler.cpp -- Kepler's problem by universal variables (see kepler.h).
#include "numeric/kepler.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace symrep::num {

namespace {

// sum_k (-z)^k / (2k + first)!  for |z| < 1: 14 terms reach 1e-30.
double stumpff_series(double z, int first) {
    double term = 1.0, sum = 0.0;
    for (int k = first; k > 1; --k) term /= k;  // 1/first!
    for (int k = 0; k < 14; ++k) {
        sum += term;
        term *= -z / ((2.0 * k + first + 1) * (2.0 * k + first + 2));
    }
    return sum;
}

}  // namespace

double stumpff_c2(double z) {
    if (std::abs(z) < 1.0) return stumpff_series(z, 2);
    if (z > 0) {
        const double s = std::sqrt(z);
        const double h = std::sin(s / 2);
        return 2.0 * h * h / z;  // (1 - cos s)/z without cancellation
    }
    const double s = std::sqrt(-z);
    const double h = std::sinh(s / 2);
    return -2.0 * h * h / z;  // (cosh s - 1)/(-z)
}

double stumpff_c3(double z) {
    if (std::abs(z) < 1.0) return stumpff_series(z, 3);
    if (z > 0) {
        const double s = std::sqrt(z);
        return (s - std::sin(s)) / (z * s);
    }
    const double s = std::sqrt(-z);
    return (std::sinh(s) - s) / (-z * s);
}

double kepler_energy(double mu, const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
    return v.squaredNorm() / 2 - mu / r.norm();
}

kepler_state kepler_propagate(double mu, const Eigen::Vector3d& r0v, const Eigen::Vector3d& v0, double t) {
    if (!(mu > 0) || !std::isfinite(mu)) throw domain_error("kepler: mu must be a positive number");
    if (!r0v.allFinite() || !v0.allFinite() || !std::isfinite(t))
        throw domain_error("kepler: the initial state and the time must be finite");
    const double r0 = r0v.norm();
    if (r0 == 0) throw domain_error("kepler: the initial position is the centre of the field (|r0| = 0)");
    if (r0v.cross(v0).norm() <= 1e-15 * r0 * v0.norm() || v0.norm() == 0)
        throw domain_error("kepler: a radial orbit (r0 x v0 = 0) falls into the centre of the field or comes out of "
                           "it; it is not solved here");
    const double smu = std::sqrt(mu);
    const double sigma0 = r0v.dot(v0) / smu;
    const double alpha = 2.0 / r0 - v0.squaredNorm() / mu;  // 1/a
    // elliptic: the motion is periodic, reduce t modulo the period
    double tr = t;
    if (alpha * r0 > 1e-12) {
        const double period = 2.0 * std::numbers::pi / std::sqrt(mu * alpha * alpha * alpha);
        tr = t - period * std::nearbyint(t / period);
    }
    if (tr == 0) return {r0v, v0};
    // starting guess (Vallado, Algorithm 8)
    double chi;
    if (alpha * r0 > 1e-12) {
        chi = smu * tr * alpha;
    } else if (alpha * r0 < -1e-12) {
        const double a = 1.0 / alpha;
        const double s = tr > 0 ? 1.0 : -1.0;
        const double arg = (-2.0 * mu * alpha * tr) / (r0v.dot(v0) + s * std::sqrt(-mu * a) * (1.0 - r0 * alpha));
        chi = arg > 0 ? s * std::sqrt(-a) * std::log(arg) : smu * tr / r0;
    } else {
        chi = smu * tr / r0;
    }
    const double b = 1.0 - alpha * r0;
    const auto F = [&](double x, double& dF, double& d2F) {
        const double z = alpha * x * x;
        const double c2 = stumpff_c2(z), c3 = stumpff_c3(z);
        dF = sigma0 * x * (1.0 - z * c3) + b * x * x * c2 + r0;
        d2F = sigma0 * (1.0 - z * c2) + b * x * (1.0 - z * c3);
        return sigma0 * x * x * c2 + b * x * x * x * c3 + r0 * x - smu * tr;
    };
    // Laguerre-Conway (n = 5), then Newton to the last digit
    const double n = 5.0;
    bool converged = false;
    for (int it = 0; it < 200; ++it) {
        double dF, d2F;
        const double f = F(chi, dF, d2F);
        // the residual at rounding level: the sum's terms are what it is rounded against (near a
        // pericentre of an eccentric orbit dF is small and the step itself never gets below
        // 1e-15 chi, though chi is as exact as doubles allow)
        const double z = alpha * chi * chi;
        const double scale = std::abs(sigma0 * chi * chi * stumpff_c2(z)) + std::abs(b * chi * chi * chi * stumpff_c3(z)) +
                             std::abs(r0 * chi) + smu * std::abs(tr);
        if (std::abs(f) <= 8 * std::numeric_limits<double>::epsilon() * scale) {
            converged = true;
            break;
        }
        const double disc = std::sqrt(std::abs((n - 1) * (n - 1) * dF * dF - n * (n - 1) * f * d2F));
        const double den = dF + (dF >= 0 ? disc : -disc);
        const double delta = den != 0 ? n * f / den : f / dF;
        chi -= delta;
        if (std::abs(delta) <= 1e-15 * std::max(1.0, std::abs(chi))) {
            converged = true;
            break;
        }
    }
    for (int it = 0; it < 2; ++it) {
        double dF, d2F;
        const double f = F(chi, dF, d2F);
        if (dF != 0) chi -= f / dF;
    }
    double r, d2F;
    F(chi, r, d2F);
    if (!converged || !std::isfinite(chi) || !(r > 0))
        throw domain_error("kepler: the orbit reaches the centre of the field before t (a radial fall) or Kepler's "
                           "equation did not converge");
    const double z = alpha * chi * chi;
    const double c2 = stumpff_c2(z), c3 = stumpff_c3(z);
    const double f = 1.0 - chi * chi * c2 / r0;
    // g = t - chi^3 c3/sqrt(mu), written with Kepler's equation so that no large terms cancel
    const double g = (sigma0 * chi * chi * c2 + r0 * chi * (1.0 - z * c3)) / smu;
    const double fd = smu * chi * (z * c3 - 1.0) / (r * r0);
    const double gd = 1.0 - chi * chi * c2 / r;
    return {f * r0v + g * v0, fd * r0v + gd * v0};
}

}  // namespace symrep::num
