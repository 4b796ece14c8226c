// symrep/numeric/kepler_universal.h -- Kepler's problem by universal variables in any
// floating-point type: double for the evaluator (kepler.h), a multiprecision type
// (boost::multiprecision::cpp_bin_float_50, _100, ...) for reference values.
//
// The same method as kepler.h describes (Lagrange coefficients f, g, f', g' in the
// universal anomaly chi with the Stumpff functions c2, c3; the universal Kepler equation
// solved by Laguerre-Conway and polished by Newton), written once for a Real with
// std-style sqrt, sin, cos, sinh, log, abs found by argument-dependent lookup. The
// series of the Stumpff functions takes as many terms as Real's epsilon needs, the
// convergence tests are relative to that epsilon: a result is as accurate as Real
// allows (tests: double against cpp_bin_float_50, energy and angular momentum of the
// 50-digit orbit conserved to 1e-45).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>

#include "symrep/core/error.h"

namespace symrep::num {

template <class Real>
using triple_of = std::array<Real, 3>;

template <class Real>
struct kepler_state_of {
    triple_of<Real> position;
    triple_of<Real> velocity;
};

namespace kepler_detail {

template <class Real>
Real dot(const triple_of<Real>& a, const triple_of<Real>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Real>
triple_of<Real> cross(const triple_of<Real>& a, const triple_of<Real>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// sum_k (-z)^k / (2k + first)! for |z| < 1, to Real's epsilon
template <class Real>
Real stumpff_series(const Real& z, int first) {
    using std::abs;
    Real term = 1, sum = 0;
    for (int k = first; k > 1; --k) term /= k;
    const Real eps = std::numeric_limits<Real>::epsilon();
    for (int k = 0; k < 200; ++k) {
        sum += term;
        if (abs(term) <= eps * abs(sum) / 4) break;
        term *= -z / Real((2 * k + first + 1) * (2 * k + first + 2));
    }
    return sum;
}

}  // namespace kepler_detail

/// c2(z) = (1 - cos sqrt z)/z (and its continuation), in Real.
template <class Real>
Real stumpff_c2_of(const Real& z) {
    using std::abs, std::sqrt, std::sin, std::sinh;
    if (abs(z) < 1) return kepler_detail::stumpff_series(z, 2);
    if (z > 0) {
        const Real s = sqrt(z), h = sin(s / 2);
        return 2 * h * h / z;
    }
    const Real s = sqrt(-z), h = sinh(s / 2);
    return -2 * h * h / z;
}

/// c3(z) = (sqrt z - sin sqrt z)/z^(3/2) (and its continuation), in Real.
template <class Real>
Real stumpff_c3_of(const Real& z) {
    using std::abs, std::sqrt, std::sin, std::sinh;
    if (abs(z) < 1) return kepler_detail::stumpff_series(z, 3);
    if (z > 0) {
        const Real s = sqrt(z);
        return (s - sin(s)) / (z * s);
    }
    const Real s = sqrt(-z);
    return (sinh(s) - s) / (-z * s);
}

/// The state at t of psi'' = -mu psi/|psi|^3 from (r0, v0), in Real (see kepler.h for the
/// method and the errors: domain_error for mu <= 0, r0 = 0, a radial orbit, no convergence).
template <class Real>
kepler_state_of<Real> kepler_propagate_of(const Real& mu, const triple_of<Real>& r0v, const triple_of<Real>& v0,
                                          const Real& t) {
    using std::abs, std::sqrt, std::log, std::round;
    using kepler_detail::cross, kepler_detail::dot;
    if (!(mu > 0)) throw domain_error("kepler: mu must be a positive number");
    const Real r0 = sqrt(dot(r0v, r0v)), vv = dot(v0, v0);
    if (r0 == 0) throw domain_error("kepler: the initial position is the centre of the field (|r0| = 0)");
    const Real eps = std::numeric_limits<Real>::epsilon();
    // r0 x v0 of the unit vectors: |r0 x v0|^2 itself leaves the range of Real first (it
    // scales as length^4: 0 at |r0| = 1e-86, a radial orbit refused until issue 27.6)
    triple_of<Real> ur = r0v, uv = v0;
    for (int i = 0; i < 3; ++i) ur[i] /= r0, uv[i] /= sqrt(vv);
    const triple_of<Real> h = cross(ur, uv);
    if (vv == 0 || sqrt(dot(h, h)) <= 10 * eps)
        throw domain_error("kepler: a radial orbit (r0 x v0 = 0) falls into the centre of the field or comes out of "
                           "it; it is not solved here");
    const Real smu = sqrt(mu), sigma0 = dot(r0v, v0) / smu, alpha = 2 / r0 - vv / mu;
    const Real tiny = Real(1) / 1000000000000;  // |alpha r0| below 1e-12: started as a parabola
    Real tr = t;
    if (alpha * r0 > tiny) {  // elliptic: t modulo the period
        const Real period = 2 * boost::math::constants::pi<Real>() / sqrt(mu * alpha * alpha * alpha);
        tr = t - period * round(t / period);
    }
    if (tr == 0) return {r0v, v0};
    Real chi;
    if (alpha * r0 > tiny) {
        chi = smu * tr * alpha;
    } else if (alpha * r0 < -tiny) {
        const Real a = 1 / alpha, s = tr > 0 ? Real(1) : Real(-1);
        const Real arg = (-2 * mu * alpha * tr) / (dot(r0v, v0) + s * sqrt(-mu * a) * (1 - r0 * alpha));
        chi = arg > 0 ? Real(s * sqrt(-a) * log(arg)) : Real(smu * tr / r0);
    } else {
        chi = smu * tr / r0;
    }
    const Real b = 1 - alpha * r0;
    auto F = [&](const Real& x, Real& dF, Real& d2F, Real& scale) {
        const Real z = alpha * x * x, c2 = stumpff_c2_of(z), c3 = stumpff_c3_of(z);
        dF = sigma0 * x * (1 - z * c3) + b * x * x * c2 + r0;
        d2F = sigma0 * (1 - z * c2) + b * x * (1 - z * c3);
        scale = abs(sigma0 * x * x * c2) + abs(b * x * x * x * c3) + abs(r0 * x) + smu * abs(tr);
        return sigma0 * x * x * c2 + b * x * x * x * c3 + r0 * x - smu * tr;
    };
    const Real n = 5;
    bool converged = false;
    for (int it = 0; it < 400; ++it) {
        Real dF, d2F, scale;
        const Real f = F(chi, dF, d2F, scale);
        if (abs(f) <= 8 * eps * scale) {
            converged = true;
            break;
        }
        const Real disc = sqrt(abs((n - 1) * (n - 1) * dF * dF - n * (n - 1) * f * d2F));
        const Real den = dF + (dF >= 0 ? disc : Real(-disc));
        const Real delta = den != 0 ? Real(n * f / den) : Real(f / dF);
        chi -= delta;
        // relative to chi itself: chi has the unit sqrt(length), so an absolute floor (1 until
        // issue 27.6) accepted the first step at small lengths (|r0| = 1e-30: 2.5e-10 off)
        if (abs(delta) <= 10 * eps * abs(chi)) {
            converged = true;
            break;
        }
    }
    for (int it = 0; it < 2; ++it) {
        Real dF, d2F, scale;
        const Real f = F(chi, dF, d2F, scale);
        if (dF != 0) chi -= f / dF;
    }
    Real r, d2F, scale;
    F(chi, r, d2F, scale);
    if (!converged || !(r > 0))
        throw domain_error("kepler: the orbit reaches the centre of the field before t (a radial fall) or Kepler's "
                           "equation did not converge");
    const Real z = alpha * chi * chi, c2 = stumpff_c2_of(z), c3 = stumpff_c3_of(z);
    const Real f = 1 - chi * chi * c2 / r0;
    const Real g = (sigma0 * chi * chi * c2 + r0 * chi * (1 - z * c3)) / smu;
    const Real fd = smu * chi * (z * c3 - 1) / (r * r0);
    const Real gd = 1 - chi * chi * c2 / r;
    kepler_state_of<Real> out;
    for (int i = 0; i < 3; ++i) {
        out.position[i] = f * r0v[i] + g * v0[i];
        out.velocity[i] = fd * r0v[i] + gd * v0[i];
    }
    return out;
}

}  // namespace symrep::num
