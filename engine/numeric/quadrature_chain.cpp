// symrep/numeric/quadrature_chain.cpp -- see quadrature_chain.h.
#include "symrep/numeric/quadrature_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "symrep/core/error.h"

namespace symrep::num {

namespace {

// A Chebyshev rule on (-1, 1): the N - 1 interior points xi_k = -cos(pi (k + 1)/N) (ascending),
// the integration matrix M (row k: int_{-1}^{xi_k} of the interpolating polynomial, by the
// values at the nodes) and the weights w (int_{-1}^{1}).
struct chebyshev_rule {
    std::size_t n = 0;
    std::vector<double> xi, M, w;
};

chebyshev_rule make_rule(std::size_t N) {
    using ld = long double;
    const ld pi = 3.141592653589793238462643383279502884L;
    const std::size_t n = N - 1;
    chebyshev_rule R;
    R.n = n;
    // V[k][i] = T_i(xi_k) = cos(i theta_k), theta_k = pi (N - k - 1)/N
    std::vector<ld> V(n * n), inv(n * n, 0.0L), xi(n);
    for (std::size_t k = 0; k < n; ++k) {
        const ld theta = pi * ld(N - k - 1) / ld(N);
        xi[k] = std::cos(theta);
        for (std::size_t i = 0; i < n; ++i) V[k * n + i] = std::cos(ld(i) * theta);
        inv[k * n + k] = 1;
    }
    // V^{-1} by Gauss-Jordan with partial pivoting (V is well conditioned: about sqrt(n))
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t piv = c;
        for (std::size_t r = c + 1; r < n; ++r)
            if (std::fabs(V[r * n + c]) > std::fabs(V[piv * n + c])) piv = r;
        for (std::size_t j = 0; j < n; ++j) {
            std::swap(V[c * n + j], V[piv * n + j]);
            std::swap(inv[c * n + j], inv[piv * n + j]);
        }
        const ld d = V[c * n + c];
        for (std::size_t j = 0; j < n; ++j) {
            V[c * n + j] /= d;
            inv[c * n + j] /= d;
        }
        for (std::size_t r = 0; r < n; ++r) {
            if (r == c) continue;
            const ld f = V[r * n + c];
            if (f == 0) continue;
            for (std::size_t j = 0; j < n; ++j) {
                V[r * n + j] -= f * V[c * n + j];
                inv[r * n + j] -= f * inv[c * n + j];
            }
        }
    }
    // J[k][i] = int_{-1}^{xi_k} T_i; W[i] = int_{-1}^{1} T_i
    auto T = [](std::size_t i, ld x) { return std::cos(ld(i) * std::acos(std::clamp(x, ld(-1), ld(1)))); };
    std::vector<ld> J(n * n), W(n, 0.0L);
    for (std::size_t k = 0; k < n; ++k) {
        const ld x = xi[k];
        for (std::size_t i = 0; i < n; ++i) {
            ld v;
            if (i == 0) {
                v = x + 1;
            } else if (i == 1) {
                v = (x * x - 1) / 2;
            } else {
                const ld sign = (i % 2 == 1) ? 1 : -1;  // (-1)^(i+1)
                v = (T(i + 1, x) / ld(i + 1) - T(i - 1, x) / ld(i - 1)) / 2 -
                    sign * (1 / ld(i + 1) - 1 / ld(i - 1)) / 2;
            }
            J[k * n + i] = v;
        }
    }
    for (std::size_t i = 0; i < n; i += 2) W[i] = 2 / (1 - ld(i) * ld(i));
    R.xi.resize(n);
    R.M.resize(n * n);
    R.w.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        R.xi[k] = static_cast<double>(xi[k]);
        for (std::size_t m = 0; m < n; ++m) {
            ld s = 0;
            for (std::size_t i = 0; i < n; ++i) s += J[k * n + i] * inv[i * n + m];
            R.M[k * n + m] = static_cast<double>(s);
        }
    }
    for (std::size_t m = 0; m < n; ++m) {
        ld s = 0;
        for (std::size_t i = 0; i < n; ++i) s += W[i] * inv[i * n + m];
        R.w[m] = static_cast<double>(s);
    }
    return R;
}

const chebyshev_rule& fine_rule() {
    static const chebyshev_rule R = make_rule(64);
    return R;
}
const chebyshev_rule& coarse_rule() {
    static const chebyshev_rule R = make_rule(32);
    return R;
}

// One rule on the panel [p, p + h] from the start values s: the values of every y_j at the
// nodes (Y, row j), at p + h (end), their increments from s (dY, dend: compared without the
// rounding of s + increment) and the panel's int |g_j| (l1).
struct panel_values {
    std::vector<double> Y, dY, end, dend, l1;
};

class marcher {
public:
    marcher(const chain_integrand& g, std::size_t n, const std::string& variable)
        : g_(g), n_(n), variable_(variable), y_(n, 0.0) {}

    std::size_t evaluations = 0;

    void run(const chebyshev_rule& R, double p, double h, const std::vector<double>& s, panel_values& out) {
        const std::size_t m = R.n;
        out.Y.assign(n_ * m, 0.0);
        out.dY.assign(n_ * m, 0.0);
        out.end.assign(n_, 0.0);
        out.dend.assign(n_, 0.0);
        out.l1.assign(n_, 0.0);
        G_.resize(m);
        x_.resize(m);
        for (std::size_t k = 0; k < m; ++k) x_[k] = p + h * (1 + R.xi[k]) / 2;
        for (std::size_t j = 0; j < n_; ++j) {
            for (std::size_t k = 0; k < m; ++k) {
                for (std::size_t i = 0; i < j; ++i) y_[i] = out.Y[i * m + k];
                const double v = g_(j, x_[k], y_.data());
                if (!std::isfinite(v)) {
                    std::ostringstream os;
                    os.precision(17);
                    os << "integral: the integrand is not finite at " << variable_ << " = " << x_[k];
                    throw domain_error(os.str());
                }
                G_[k] = v;
            }
            evaluations += m;
            double* Yj = &out.Y[j * m];
            for (std::size_t k = 0; k < m; ++k) {
                double acc = 0;
                const double* row = &R.M[k * m];
                for (std::size_t l = 0; l < m; ++l) acc += row[l] * G_[l];
                out.dY[j * m + k] = h / 2 * acc;
                Yj[k] = s[j] + out.dY[j * m + k];
            }
            double acc = 0, abs_acc = 0;
            for (std::size_t l = 0; l < m; ++l) {
                acc += R.w[l] * G_[l];
                abs_acc += R.w[l] * std::fabs(G_[l]);  // Fejer's weights are positive
            }
            out.dend[j] = h / 2 * acc;
            out.end[j] = s[j] + out.dend[j];
            out.l1[j] = std::fabs(h) / 2 * abs_acc;
        }
    }

private:
    const chain_integrand& g_;
    std::size_t n_;
    std::string variable_;
    std::vector<double> y_, G_, x_;
};

}  // namespace

chain_result integrate_chain(const chain_integrand& g, std::size_t n, double a, double b,
                             const std::vector<double>& start, const std::string& variable) {
    if (start.size() != n) throw type_error("integral: " + std::to_string(start.size()) + " start values for " +
                                            std::to_string(n) + " quadratures");
    if (!std::isfinite(a) || !std::isfinite(b)) throw type_error("integral: the limits must be finite numbers");
    chain_result r;
    r.value = start;
    r.error.assign(n, 0.0);
    r.l1.assign(n, 0.0);
    if (a == b || n == 0) return r;
    const chebyshev_rule& F = fine_rule();
    const chebyshev_rule& C = coarse_rule();
    const double L = b - a, length = std::fabs(L);
    marcher M(g, n, variable);
    std::vector<double> yc = start;  // the lower rule's own trajectory (the estimate)
    panel_values fine, local, coarse;
    std::vector<double> e(n), parent(n);
    std::size_t attempts = 0;
    double p = a, h = L;
    bool halved = false;  // this attempt halves a rejected panel at the same p
    double first = h;     // the width the halvings at p started from
    int steady = 0;       // panels accepted at this width without growing
    while (p != b) {
        if (++attempts > chain_max_panels) {
            std::ostringstream os;
            os << "integral: the quadrature over [" << a << ", " << b << "] needs more than " << chain_max_panels
               << " panels (an integrand that oscillates too fast, is not smooth, or is rounded in double beyond 1e-12 of "
                  "itself there: a phase of 1e4 rad or more); not evaluated";
            throw domain_error(os.str());
        }
        // the last panel ends exactly at b
        if (std::fabs(h) >= std::fabs(b - p) * (1 - 1e-12)) h = b - p;
        M.run(F, p, h, r.value, fine);
        M.run(C, p, h, r.value, local);
        const double share = std::fabs(h) / length;
        bool accept = true, forced = false;
        double worst = 0;  // max_j e_j / tol_j
        for (std::size_t j = 0; j < n; ++j) {
            double d = std::fabs(local.dend[j] - fine.dend[j]);
            for (std::size_t k = 0; k < C.n; ++k)
                d = std::max(d, std::fabs(local.dY[j * C.n + k] - fine.dY[j * F.n + 2 * k + 1]));
            e[j] = d;
            // not below 1e-12 of the panel's own int |g_j|: the rounding of an integrand in double
            // (a phase of 1e4 rad is rounded to 1e-12) is not chased (the estimate keeps it)
            const double tol = std::max(1e-13 * (r.l1[j] + fine.l1[j]) * share, 1e-12 * fine.l1[j]);
            if (d <= tol) {
                if (d > 0) worst = std::max(worst, d / tol);
                continue;
            }
            // rounding noise of the integrand (a cancellation such as 3/4 - 3 cos(tau)/4 near 0):
            // the halving did not shrink the difference, which is far below the panel's own size
            // (an integrand of 31 points resolved to 1e-3 shrinks it by 1e9 at a halving)
            // A panel wider than 1e-3 of [a, b] is never taken as noise: a smooth integrand not yet
            // resolved there (e^(-u/2) over [0, 120]) shrinks its difference slowly at first.
            const bool stalled = halved && std::fabs(h) <= 1e-3 * length && d > parent[j] / 8 &&
                                 d <= 1e-3 * fine.l1[j];
            if (!stalled) accept = false;
            forced = true;
        }
        const bool smallest = std::fabs(h) <= length * std::ldexp(1.0, -45) ||
                              std::fabs(h) <= 64 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(p), std::fabs(p + h));
        if (!accept && !smallest) {
            steady = 0;
            if (!halved) first = h;
            parent = e;
            halved = true;
            h /= 2;
            continue;
        }
        forced = forced || !accept;
        // accepted: the lower rule's trajectory from its own values, the estimate its difference
        // (one quadrature alone: the same increments as the local run)
        if (n > 1) M.run(C, p, h, yc, coarse);
        for (std::size_t j = 0; j < n; ++j) {
            const double step = n > 1 ? coarse.dend[j] : local.dend[j];
            r.error[j] += std::fabs(step - fine.dend[j]);
            yc[j] += step;
            r.value[j] = fine.end[j];
            r.l1[j] += fine.l1[j];
        }
        ++r.panels;
        p = (h == b - p) ? b : p + h;
        halved = false;
        // the next panel: the lower rule's difference grows about like h^31, rounding noise like h
        // (so a width lost to a noisy panel is tried again after four panels); after a panel
        // accepted at the noise (or the smallest width), the width the halvings started from
        if (forced) {
            h = std::max(std::fabs(h), std::fabs(first)) * (h < 0 ? -1 : 1);
        } else if (worst < 1e-9 || ++steady >= 4) {
            h *= 2;
            steady = 0;
        } else if (worst < 1e-3) {
            h *= 1.5;
            steady = 0;
        }
    }
    r.evaluations = M.evaluations;
    return r;
}

}  // namespace symrep::num
