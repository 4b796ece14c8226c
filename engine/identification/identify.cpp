// symrep/identification/identify.cpp -- the identification procedure of IV.2.3, its
// integral-form variant, the forward model and the baseline of regression on derivatives.
#include "symrep/identification/identify.h"
#include "symrep/identification/identify_detail.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "symrep/core/error.h"
#include "symrep/core/progress.h"
#include "symrep/identification/operational_matrix.h"
#include "symrep/identification/walsh_series.h"
#include "symrep/numeric/integrate.h"

namespace symrep::identification {

namespace detail {

double rms(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return v.empty() ? 0 : std::sqrt(s / double(v.size()));
}

unsigned check_system(const measured_system& s, const linear_part& a) {
    const unsigned n = log2_of_count(s.q.size(), "identify: the output q");
    if (s.u.size() != s.q.size())
        throw domain_error("identify: the input u has " + std::to_string(s.u.size()) + " block values and the output q " +
                           std::to_string(s.q.size()) + "; both need the same 2^n");
    if (a.empty()) throw domain_error("identify: the order m of the system must be at least 1");
    if (!(s.period > 0) || !std::isfinite(s.period)) throw domain_error("identify: the period T must be positive");
    for (std::size_t k = 0; k < s.q.size(); ++k)
        if (!std::isfinite(s.q[k]) || !std::isfinite(s.u[k]))
            throw domain_error("identify: block value " + std::to_string(k + 1) + " is not finite");
    if (rms(s.q) == 0) throw domain_error("identify: the output q is 0 on every block: nothing to identify from");
    return n;
}

// The a_k, every one known (the thesis's procedure, IV.2.45).
std::vector<double> known(const linear_part& a) {
    std::vector<double> av;
    for (std::size_t k = 0; k < a.size(); ++k) {
        if (!a[k])
            throw domain_error("identify: a_" + std::to_string(k + 1) +
                               " is unknown; the thesis's procedure (IV.2.45) needs every a_k: use the integral "
                               "method, which estimates them jointly");
        av.push_back(*a[k]);
    }
    return av;
}

// sum_i c_i x^i
double horner(const std::vector<double>& c, double x) {
    double v = 0;
    for (std::size_t i = c.size(); i-- > 0;) v = v * x + c[i];
    return v;
}

void refuse_collinear(const linear_part& a, unsigned degree) {
    if (!a.back() && degree >= 1)
        throw domain_error("identify: a_" + std::to_string(a.size()) +
                           " (unknown) and the linear term of f multiply the same function q: they cannot be told "
                           "apart; give a_" + std::to_string(a.size()) + " a value (0 folds it into f)");
}

// The residual of the integrated equation (IV.2.39) with f and a: rms over rms(q).
double integrated_residual(const measured_system& s, const std::vector<double>& a, const std::vector<double>& f) {
    const long m = long(a.size());
    std::vector<double> r = s.q, fq(s.q.size());
    for (long j = 1; j <= m; ++j) {
        const std::vector<double> I = integrate_blocks(s.q, j, s.period);
        for (std::size_t k = 0; k < r.size(); ++k) r[k] += a[std::size_t(j - 1)] * I[k];
    }
    for (std::size_t k = 0; k < fq.size(); ++k) fq[k] = horner(f, s.q[k]) - s.u[k];
    const std::vector<double> I = integrate_blocks(fq, m, s.period);
    for (std::size_t k = 0; k < r.size(); ++k) r[k] += I[k];
    return rms(r) / rms(s.q);
}

// min |A x - b| with the columns scaled to unit norm; the condition number of the scaled A.
lsq least_squares(Eigen::MatrixXd A, const Eigen::VectorXd& b) {
    Eigen::VectorXd scale(A.cols());
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
        scale(j) = A.col(j).norm();
        if (scale(j) == 0) scale(j) = 1;
        A.col(j) /= scale(j);
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const auto& sv = svd.singularValues();
    const double cond = sv(sv.size() - 1) > 0 ? sv(0) / sv(sv.size() - 1) : INFINITY;
    Eigen::VectorXd x = svd.solve(b);
    for (Eigen::Index j = 0; j < x.size(); ++j) x(j) /= scale(j);
    return {x, cond};
}

std::string condition_warning(double cond) {
    if (cond < 1e8) return "";
    std::ostringstream os;
    os << "ill-conditioned least squares (condition number " << cond
       << "): the estimates may carry large errors; lower the degree or excite the system more";
    return os.str();
}

// (IV.2.38) q(0) = q'(0) = ... = 0 makes the first block average O(h^m) of q's scale: a first
// block above 5 % of the largest |q| (with 16 blocks or more) means data that do not start from
// rest, which the integrated equation does not describe.
std::string initial_data_warning(const measured_system& s) {
    double most = 0;
    for (double x : s.q) most = std::max(most, std::abs(x));
    if (s.q.size() < 16 || std::abs(s.q[0]) <= 0.05 * most) return "";
    std::ostringstream os;
    os << "q does not start from rest (first block average " << s.q[0] << ", largest " << most
       << "): the procedure assumes zero initial data (IV.2.38); the result is not the system's f";
    return os.str();
}

std::string warnings(const measured_system& s, double cond) {
    std::vector<std::string> all;
    if (s.q.size() < 16)
        all.push_back("only " + std::to_string(s.q.size()) +
                      " blocks: the O(h^2) error of the truncated series is large (Duffing at 16 blocks: 60 %); "
                      "use 2^8 or more");
    for (std::string w : {initial_data_warning(s), condition_warning(cond)})
        if (!w.empty()) all.push_back(w);
    std::string out;
    for (const auto& w : all) out += (out.empty() ? "" : "; ") + w;
    return out;
}

identification_report report_of(const measured_system& s, const linear_part& a, const std::vector<std::size_t>& unknown,
                                unsigned degree, const Eigen::VectorXd& x, std::size_t points, double cond) {
    identification_report rep;
    rep.points = points;
    rep.condition_number = cond;
    rep.a.resize(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) rep.a[k] = a[k] ? *a[k] : 0.0;
    for (std::size_t j = 0; j < unknown.size(); ++j) rep.a[unknown[j]] = x(Eigen::Index(j));
    for (unsigned i = 0; i <= degree; ++i) rep.f.push_back(x(Eigen::Index(unknown.size() + i)));
    rep.residual = integrated_residual(s, rep.a, rep.f);
    rep.warning = warnings(s, cond);
    return rep;
}

}  // namespace detail

using namespace detail;

std::vector<double> fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, unsigned degree,
                                   double* cond) {
    if (x.size() != y.size()) throw domain_error("fit_polynomial: different numbers of points and values");
    if (x.size() < degree + 1)
        throw domain_error("fit_polynomial: " + std::to_string(x.size()) + " points for a polynomial of degree " +
                           std::to_string(degree));
    double lo = *std::min_element(x.begin(), x.end()), hi = *std::max_element(x.begin(), x.end());
    const double c = (lo + hi) / 2, h = (hi - lo) / 2 > 0 ? (hi - lo) / 2 : 1;
    const auto N = Eigen::Index(x.size());
    Eigen::MatrixXd V(N, degree + 1);
    Eigen::VectorXd b(N);
    for (Eigen::Index k = 0; k < N; ++k) {
        const double s = (x[std::size_t(k)] - c) / h;
        double p = 1;
        for (unsigned i = 0; i <= degree; ++i, p *= s) V(k, i) = p;
        b(k) = y[std::size_t(k)];
    }
    const lsq r = least_squares(V, b);
    if (cond) *cond = r.cond;
    // sum_i b_i ((x - c)/h)^i in monomials of x
    std::vector<double> out(degree + 1, 0.0);
    for (unsigned i = 0; i <= degree; ++i) {
        double binom = 1;  // C(i, j)
        for (unsigned j = 0; j <= i; ++j) {
            out[j] += r.x(i) * binom * std::pow(-c, double(i - j)) / std::pow(h, double(i));
            binom = binom * double(i - j) / double(j + 1);
        }
    }
    return out;
}

namespace {

// The two readings of the thesis's procedure: the report with the known a_k, and its end -- f
// fitted to the values at the points, the residual of the integrated equation, the warnings.
identification_report values_report(const measured_system& s, const linear_part& a) {
    check_system(s, a);
    identification_report rep;
    rep.points = s.q.size();
    rep.a = known(a);
    return rep;
}

identification_report fitted(identification_report rep, const measured_system& s, unsigned degree) {
    rep.points = rep.points_q.size();
    rep.f = fit_polynomial(rep.points_q, rep.values_f, degree, &rep.condition_number);
    rep.residual = integrated_residual(s, rep.a, rep.f);
    rep.warning = warnings(s, rep.condition_number);
    return rep;
}

}  // namespace

identification_report identify_values(const measured_system& s, const linear_part& a, unsigned degree) {
    identification_report rep = values_report(s, a);
    const std::vector<double>& av = rep.a;
    const long m = long(a.size());
    // (IV.2.45) f(q_e) = u_e - sum_(j=0..m) a_j (Q^T)^(j-m) q_e, a_0 = 1. (Q^T)^(-m) is the Toeplitz
    // matrix of (2N/T)^m ((1 - x)/(1 + x))^m: an m-fold pole at x = -1. The first blocks' mismatch
    // between (Q^T)^m and the m-fold integral of a function that is not piecewise constant (for
    // m = 2 the diagonal h^2/4 against h^2/6) excites it: the values as printed carry a
    // (-1)^k k^(m-1) component that does not vanish as n grows. Averaging neighbours m times,
    // ((1 + x)/2)^m, cancels the pole; applied to the symbols, each term becomes the finite
    // stencil (N/T)^(m-j) (1 - x)^(m-j) ((1 + x)/2)^j (no large intermediate values to cancel):
    // the m-th backward difference of the block averages, consistent to O(h^2) at the averaged
    // points, and m-fold differentiation of the data (noise amplified by about (N/T)^m).
    const std::size_t N = s.q.size();
    const double NT = double(N) / s.period;
    auto stencil = [](long minus, long plus) {  // coefficients of (1 - x)^minus ((1 + x)/2)^plus
        std::vector<double> c{1.0};
        for (long i = 0; i < minus + plus; ++i) {
            std::vector<double> d(c.size() + 1, 0.0);
            for (std::size_t k = 0; k < c.size(); ++k) {
                d[k] += i < minus ? c[k] : c[k] / 2;
                d[k + 1] += i < minus ? -c[k] : c[k] / 2;
            }
            c = d;
        }
        return c;
    };
    auto apply = [&](const std::vector<double>& c, const std::vector<double>& v, std::size_t k) {
        double y = 0;
        for (std::size_t i = 0; i < c.size(); ++i) y += c[i] * v[k - i];
        return y;
    };
    const std::vector<double> average = stencil(0, m);
    for (std::size_t k = std::size_t(m); k < N; ++k) {
        double f = apply(average, s.u, k);
        for (long j = 0; j <= m; ++j) {
            const double aj = j == 0 ? 1.0 : av[std::size_t(j - 1)];
            if (aj != 0) f -= aj * std::pow(NT, double(m - j)) * apply(stencil(m - j, j), s.q, k);
        }
        rep.values_f.push_back(f);
        rep.points_q.push_back(apply(average, s.q, k));
    }
    return fitted(std::move(rep), s, degree);
}

identification_report identify_values_as_printed(const measured_system& s, const linear_part& a, unsigned degree) {
    identification_report rep = values_report(s, a);
    const std::vector<double>& av = rep.a;
    const long m = long(a.size());
    rep.points_q = s.q;
    rep.values_f = s.u;
    for (long j = 0; j <= m; ++j) {  // (IV.2.45) as printed
        const double aj = j == 0 ? 1.0 : av[std::size_t(j - 1)];
        if (aj == 0) continue;
        const std::vector<double> d = integrate_blocks(s.q, j - m, s.period);
        for (std::size_t k = 0; k < d.size(); ++k) rep.values_f[k] -= aj * d[k];
    }
    return fitted(std::move(rep), s, degree);
}

identification_report identify_integral(const measured_system& s, const linear_part& a, unsigned degree) {
    check_system(s, a);
    refuse_collinear(a, degree);
    const long m = long(a.size());
    const auto N = Eigen::Index(s.q.size());
    std::vector<std::size_t> unknown;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!a[k]) unknown.push_back(k);
    if (std::size_t(N) < unknown.size() + degree + 1)
        throw domain_error("identify: " + std::to_string(N) + " blocks for " +
                           std::to_string(unknown.size() + degree + 1) + " unknowns");
    Eigen::MatrixXd A(N, Eigen::Index(unknown.size() + degree + 1));
    Eigen::VectorXd b(N);
    // right side I^m u - q - sum_(known) a_j I^j q (IV.2.39)
    const std::vector<double> Imu = integrate_blocks(s.u, m, s.period);
    for (Eigen::Index k = 0; k < N; ++k) b(k) = Imu[std::size_t(k)] - s.q[std::size_t(k)];
    Eigen::Index col = 0;
    for (long j = 1; j <= m; ++j) {
        const std::vector<double> I = integrate_blocks(s.q, j, s.period);
        if (a[std::size_t(j - 1)]) {
            for (Eigen::Index k = 0; k < N; ++k) b(k) -= *a[std::size_t(j - 1)] * I[std::size_t(k)];
        }
    }
    for (std::size_t k : unknown) {
        const std::vector<double> I = integrate_blocks(s.q, long(k) + 1, s.period);
        for (Eigen::Index i = 0; i < N; ++i) A(i, col) = I[std::size_t(i)];
        ++col;
    }
    std::vector<double> power(s.q.size(), 1.0);
    for (unsigned i = 0; i <= degree; ++i) {
        const std::vector<double> I = integrate_blocks(power, m, s.period);
        for (Eigen::Index k = 0; k < N; ++k) A(k, col) = I[std::size_t(k)];
        ++col;
        for (std::size_t k = 0; k < power.size(); ++k) power[k] *= s.q[k];
    }
    const lsq r = least_squares(A, b);
    identification_report rep;
    rep.points = std::size_t(N);
    rep.condition_number = r.cond;
    rep.a.resize(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) rep.a[k] = a[k] ? *a[k] : 0.0;
    for (std::size_t u = 0; u < unknown.size(); ++u) rep.a[unknown[u]] = r.x(Eigen::Index(u));
    for (unsigned i = 0; i <= degree; ++i) rep.f.push_back(r.x(Eigen::Index(unknown.size() + i)));
    rep.residual = integrated_residual(s, rep.a, rep.f);
    rep.warning = warnings(s, rep.condition_number);
    return rep;
}

measured_system simulate_system(const std::function<double(double)>& f, const std::function<double(double)>& u,
                                const std::vector<double>& a, unsigned n, double T, measured_system* samples) {
    if (a.empty()) throw domain_error("simulate_system: the order m must be at least 1");
    if (n < 1 || n > 20) throw domain_error("simulate_system: n must be 1 .. 20 (2^n blocks)");
    const std::size_t m = a.size(), N = std::size_t(1) << n;
    const double h = T / double(N);
    // state: q, q', ..., q^(m-1), int q, int u
    const num::rhs_function rhs = [&](double t, const double* y, double* dy) {
        for (std::size_t k = 0; k + 1 < m; ++k) dy[k] = y[k + 1];
        double top = u(t) - f(y[0]);
        for (std::size_t k = 1; k <= m; ++k) top -= a[k - 1] * y[m - k];
        dy[m - 1] = top;
        dy[m] = y[0];
        dy[m + 1] = u(t);
    };
    std::vector<double> times;
    for (std::size_t k = 0; k <= N; ++k) {
        times.push_back(double(k) * h);
        if (samples && k < N) times.push_back((double(k) + 0.5) * h);
    }
    num::integration_options opt;
    opt.abs_tol = opt.rel_tol = 1e-12;
    progress_task task("simulate_system", 1);
    task.nest(0, 1);
    const num::integration_result r = num::integrate(rhs, 0.0, std::vector<double>(m + 2, 0.0), times, opt);
    measured_system out;
    out.period = T;
    const std::size_t stride = samples ? 2 : 1;
    for (std::size_t k = 0; k < N; ++k) {
        const auto i0 = Eigen::Index(stride * k), i1 = Eigen::Index(stride * (k + 1));
        out.q.push_back((r.states(i1, Eigen::Index(m)) - r.states(i0, Eigen::Index(m))) / h);
        out.u.push_back((r.states(i1, Eigen::Index(m + 1)) - r.states(i0, Eigen::Index(m + 1))) / h);
        if (samples) {
            samples->q.push_back(r.states(i0 + 1, 0));
            samples->u.push_back(u((double(k) + 0.5) * h));
        }
    }
    if (samples) samples->period = T;
    task.finish();
    return out;
}

identification_report identify_sindy(const measured_system& s, const linear_part& a, unsigned degree,
                                     double threshold) {
    check_system(s, a);
    refuse_collinear(a, degree);
    const std::size_t m = a.size(), N = s.q.size();
    const double h = s.period / double(N);
    const std::size_t margin = (m + 1) / 2;
    if (N < 2 * margin + degree + 2) throw domain_error("identify (derivatives): too few samples");
    // the j-th derivative at the interior points by central differences
    auto derivative = [&](std::size_t j) {
        std::vector<double> d = s.q;
        std::size_t left = j;
        while (left >= 2) {
            std::vector<double> e(N, 0.0);
            for (std::size_t k = 1; k + 1 < N; ++k) e[k] = (d[k + 1] - 2 * d[k] + d[k - 1]) / (h * h);
            d = e;
            left -= 2;
        }
        if (left == 1) {
            std::vector<double> e(N, 0.0);
            for (std::size_t k = 1; k + 1 < N; ++k) e[k] = (d[k + 1] - d[k - 1]) / (2 * h);
            d = e;
        }
        return d;
    };
    std::vector<std::vector<double>> D(m + 1);
    for (std::size_t j = 0; j <= m; ++j) D[j] = derivative(j);
    std::vector<std::size_t> unknown;
    for (std::size_t k = 0; k < m; ++k)
        if (!a[k]) unknown.push_back(k);
    const auto rows = Eigen::Index(N - 2 * margin);
    const auto cols = Eigen::Index(unknown.size() + degree + 1);
    Eigen::MatrixXd A(rows, cols);
    Eigen::VectorXd b(rows);
    for (Eigen::Index r = 0; r < rows; ++r) {
        const std::size_t k = std::size_t(r) + margin;
        double y = s.u[k] - D[m][k];
        for (std::size_t j = 1; j <= m; ++j)
            if (a[j - 1]) y -= *a[j - 1] * D[m - j][k];
        b(r) = y;
        Eigen::Index c = 0;
        for (std::size_t j : unknown) A(r, c++) = D[m - (j + 1)][k];
        double p = 1;
        for (unsigned i = 0; i <= degree; ++i, p *= s.q[k]) A(r, c++) = p;
    }
    // sequentially thresholded least squares
    std::vector<bool> active(std::size_t(cols), true);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(cols);
    double cond = 0;
    for (int round = 0; round < 10; ++round) {
        std::vector<Eigen::Index> idx;
        for (Eigen::Index c = 0; c < cols; ++c)
            if (active[std::size_t(c)]) idx.push_back(c);
        if (idx.empty()) break;
        Eigen::MatrixXd Asub(rows, Eigen::Index(idx.size()));
        for (std::size_t j = 0; j < idx.size(); ++j) Asub.col(Eigen::Index(j)) = A.col(idx[j]);
        const lsq r = least_squares(Asub, b);
        if (round == 0) cond = r.cond;
        x.setZero();
        for (std::size_t j = 0; j < idx.size(); ++j) x(idx[j]) = r.x(Eigen::Index(j));
        bool changed = false;
        for (Eigen::Index c = 0; c < cols; ++c)
            if (active[std::size_t(c)] && std::abs(x(c)) < threshold) {
                active[std::size_t(c)] = false;
                x(c) = 0;
                changed = true;
            }
        if (!changed) break;
    }
    return report_of(s, a, unknown, degree, x, std::size_t(rows), cond);
}

}  // namespace symrep::identification
