// symrep/identification/sindy.cpp -- the cross-validated SINDy pipeline (sindy.h): Savitzky-Golay
// derivatives, STLSQ, the window and the threshold by blocked cross-validation.
#include "symrep/identification/sindy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "symrep/core/error.h"
#include "symrep/identification/identify_detail.h"

namespace symrep::identification {

using namespace detail;

std::vector<std::vector<double>> savitzky_golay(const std::vector<double>& y, double h, unsigned half_width,
                                                unsigned order, unsigned derivatives) {
    const std::size_t N = y.size(), L = 2 * std::size_t(half_width) + 1;
    if (L <= order || L > N)
        throw domain_error("savitzky_golay: a window of " + std::to_string(L) + " samples for order " +
                           std::to_string(order) + " and " + std::to_string(N) + " samples");
    const auto w = Eigen::Index(half_width), P = Eigen::Index(order) + 1;
    // V(j, i) = z_j^i, z = offset / w in [-1, 1]; the fit's coefficients are pinv(V) y
    Eigen::MatrixXd V(Eigen::Index(L), P);
    for (Eigen::Index j = 0; j < Eigen::Index(L); ++j)
        for (Eigen::Index i = 0; i < P; ++i) V(j, i) = std::pow(double(j - w) / double(w), double(i));
    const Eigen::MatrixXd pinv = V.completeOrthogonalDecomposition().pseudoInverse();  // P x L
    // weights[r][o]: the r-th derivative at offset o - w of the window, as a row over its samples
    std::vector<std::vector<Eigen::RowVectorXd>> weights(derivatives + 1);
    for (unsigned r = 0; r <= derivatives; ++r) {
        const double scale = std::pow(double(w) * h, -double(r));
        for (Eigen::Index o = 0; o < Eigen::Index(L); ++o) {
            const double z = double(o - w) / double(w);
            Eigen::RowVectorXd e = Eigen::RowVectorXd::Zero(P);  // d^r/dz^r z^i at z
            for (Eigen::Index i = Eigen::Index(r); i < P; ++i) {
                double falling = 1;
                for (unsigned k = 0; k < r; ++k) falling *= double(i - Eigen::Index(k));
                e(i) = falling * std::pow(z, double(i - Eigen::Index(r)));
            }
            weights[r].push_back(scale * e * pinv);
        }
    }
    std::vector<std::vector<double>> out(derivatives + 1, std::vector<double>(N));
    for (std::size_t k = 0; k < N; ++k) {
        // the window: centred, or the first / last full one at the ends
        const std::size_t start = k < half_width ? 0 : std::min(k - half_width, N - L);
        const auto o = Eigen::Index(k - start);
        for (unsigned r = 0; r <= derivatives; ++r) {
            const Eigen::RowVectorXd& g = weights[r][std::size_t(o)];
            double v = 0;
            for (Eigen::Index j = 0; j < Eigen::Index(L); ++j) v += g(j) * y[start + std::size_t(j)];
            out[r][k] = v;
        }
    }
    return out;
}

namespace {

// Sequentially thresholded least squares over the rows `rows` of A, b: a column whose share
// |x_j| |A_j| / |b| falls below lambda is dropped, the rest refitted (at most one round per column).
Eigen::VectorXd stlsq(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double lambda, double* cond = nullptr) {
    const Eigen::Index cols = A.cols();
    std::vector<bool> active(std::size_t(cols), true);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(cols);
    const double bn = b.norm() > 0 ? b.norm() : 1;
    for (Eigen::Index round = 0; round <= cols; ++round) {
        std::vector<Eigen::Index> idx;
        for (Eigen::Index c = 0; c < cols; ++c)
            if (active[std::size_t(c)]) idx.push_back(c);
        x.setZero();
        if (idx.empty()) break;
        Eigen::MatrixXd active_columns(A.rows(), Eigen::Index(idx.size()));
        for (std::size_t j = 0; j < idx.size(); ++j) active_columns.col(Eigen::Index(j)) = A.col(idx[j]);
        const lsq r = least_squares(active_columns, b);
        if (round == 0 && cond) *cond = r.cond;
        for (std::size_t j = 0; j < idx.size(); ++j) x(idx[j]) = r.x(Eigen::Index(j));
        bool changed = false;
        for (Eigen::Index c : idx)
            if (std::abs(x(c)) * A.col(c).norm() < lambda * bn) {
                active[std::size_t(c)] = false;
                changed = true;
            }
        if (!changed) break;
    }
    return x;
}

// The regression of one window: the library A (columns: the unknown a_k's q^(m-k), then
// q^0 .. q^d of the smoothed q) and the target b, at every sample.
struct regression {
    Eigen::MatrixXd A;
    Eigen::VectorXd b;
};

regression build(const measured_system& s, const linear_part& a, unsigned degree, unsigned half_width,
                 const std::vector<std::size_t>& unknown) {
    const std::size_t m = a.size(), N = s.q.size();
    const double h = s.period / double(N);
    const auto D = savitzky_golay(s.q, h, half_width, unsigned(m) + 2, unsigned(m));
    regression r{Eigen::MatrixXd(Eigen::Index(N), Eigen::Index(unknown.size() + degree + 1)),
                 Eigen::VectorXd(Eigen::Index(N))};
    for (std::size_t k = 0; k < N; ++k) {
        double y = s.u[k] - D[m][k];
        for (std::size_t j = 1; j <= m; ++j)
            if (a[j - 1]) y -= *a[j - 1] * D[m - j][k];
        r.b(Eigen::Index(k)) = y;
        Eigen::Index c = 0;
        for (std::size_t j : unknown) r.A(Eigen::Index(k), c++) = D[m - (j + 1)][k];
        double p = 1;
        for (unsigned i = 0; i <= degree; ++i, p *= D[0][k]) r.A(Eigen::Index(k), c++) = p;
    }
    return r;
}

// phi = (s (1 - s))^(m+6) on [0, 1] in powers of s, and its derivatives to order m: coefficient
// lists. phi^(m) q vanishes to order 6 at the ends, so that the trapezoidal rule's error (the
// Euler-Maclaurin terms, odd derivatives at the ends) is O(h^6): the score can tell models apart
// far below the data's own error.
std::vector<std::vector<double>> bump(std::size_t m) {
    std::vector<double> c{1.0};
    for (std::size_t i = 0; i < m + 6; ++i) {  // times (s - s^2)
        std::vector<double> d(c.size() + 2, 0.0);
        for (std::size_t k = 0; k < c.size(); ++k) {
            d[k + 1] += c[k];
            d[k + 2] -= c[k];
        }
        c = d;
    }
    std::vector<std::vector<double>> out{c};
    for (std::size_t r = 1; r <= m; ++r) {
        std::vector<double> d(c.size() - 1);
        for (std::size_t k = 1; k < c.size(); ++k) d[k - 1] = double(k) * c[k];
        out.push_back(c = d);
    }
    return out;
}

// The weak form of the equation on one test function of a held-out block: the integrals that do
// not depend on the model, by the trapezoidal rule over the samples (phi and its first m
// derivatives vanish at the ends).
struct test_function {
    double U = 0;               // int phi u
    std::vector<double> G;      // int phi q^i, i = 0 .. d
    std::vector<double> Dq;     // int phi^(r) q (d/dt), r = 0 .. m
};

test_function weak_integrals(const measured_system& s, std::size_t k0, std::size_t k1, unsigned degree,
                             const std::vector<std::vector<double>>& phi) {
    const std::size_t m = phi.size() - 1;
    const double h = s.period / double(s.q.size()), width = double(k1 - k0) * h;
    test_function tf;
    tf.G.assign(degree + 1, 0.0);
    tf.Dq.assign(m + 1, 0.0);
    for (std::size_t k = k0; k <= k1; ++k) {
        const double z = double(k - k0) / double(k1 - k0);
        const double wgt = (k == k0 || k == k1) ? h / 2 : h;
        for (std::size_t r = 0; r <= m; ++r) {
            const double v = horner(phi[r], z) * std::pow(width, -double(r));
            if (r == 0) {
                tf.U += wgt * v * s.u[k];
                double p = 1;
                for (unsigned i = 0; i <= degree; ++i, p *= s.q[k]) tf.G[i] += wgt * v * p;
            }
            tf.Dq[r] += wgt * v * s.q[k];
        }
    }
    return tf;
}

// The weak residual of the model (x: the unknown a_k, then c_0 .. c_d) on one test function:
// int phi (u - f(q)) - sum_(j=0..m) a_j (-1)^(m-j) int phi^(m-j) q, a_0 = 1.
double weak_residual(const test_function& tf, const linear_part& a, const std::vector<std::size_t>& unknown,
                     const Eigen::VectorXd& x) {
    const std::size_t m = a.size();
    std::vector<double> av(m + 1, 1.0);
    for (std::size_t k = 0; k < m; ++k) av[k + 1] = a[k] ? *a[k] : 0.0;
    for (std::size_t u = 0; u < unknown.size(); ++u) av[unknown[u] + 1] = x(Eigen::Index(u));
    double r = tf.U;
    for (std::size_t i = 0; i < tf.G.size(); ++i) r -= x(Eigen::Index(unknown.size() + i)) * tf.G[i];
    for (std::size_t j = 0; j <= m; ++j) r -= av[j] * ((m - j) % 2 ? -1.0 : 1.0) * tf.Dq[m - j];
    return r;
}

}  // namespace

identification_report identify_sindy_cv(const measured_system& s, const linear_part& a, unsigned degree) {
    check_system(s, a);
    refuse_collinear(a, degree);
    const std::size_t m = a.size(), N = s.q.size();
    if (N < 64)
        throw domain_error("identify (sindy): " + std::to_string(N) +
                           " samples; the cross-validated pipeline needs at least 64 (5 blocks, windows of 7 or more)");
    std::vector<std::size_t> unknown;
    for (std::size_t k = 0; k < m; ++k)
        if (!a[k]) unknown.push_back(k);
    const unsigned order = unsigned(m) + 2;
    std::vector<unsigned> windows;
    for (unsigned w = std::max(3u, order / 2 + 1); 2 * w + 1 <= N / 8 && w <= 256;
         w = std::max(w + 1, unsigned(std::lround(1.5 * w))))
        windows.push_back(w);
    if (windows.empty())
        throw domain_error("identify (sindy): " + std::to_string(N) + " samples are too few for a window of order " +
                           std::to_string(order));
    const double lambdas[] = {0, 1e-4, 1e-3, 1e-2, 3e-2, 1e-1};
    // five contiguous folds; in each, test functions on pieces of about 64 samples (1 .. 4 of them)
    const std::size_t folds = 5;
    const auto phi = bump(m);
    std::vector<std::size_t> fold_start;
    for (std::size_t f = 0; f <= folds; ++f) fold_start.push_back(f * N / folds);
    std::vector<std::vector<test_function>> tests(folds);
    for (std::size_t f = 0; f < folds; ++f) {
        const std::size_t lo = fold_start[f], hi = fold_start[f + 1] - 1, len = hi - lo;
        const std::size_t pieces = std::clamp<std::size_t>(len / 64, 1, 4);
        for (std::size_t p = 0; p < pieces; ++p)
            tests[f].push_back(weak_integrals(s, lo + p * len / pieces, lo + (p + 1) * len / pieces, degree, phi));
    }
    double best = std::numeric_limits<double>::infinity();
    unsigned best_w = windows.front();
    double best_lambda = 0;
    for (unsigned w : windows) {
        const regression full = build(s, a, degree, w, unknown);
        for (double lambda : lambdas) {
            double score = 0;
            for (std::size_t f = 0; f < folds; ++f) {
                const auto lo = Eigen::Index(fold_start[f]), hi = Eigen::Index(fold_start[f + 1]);
                const Eigen::Index rows = Eigen::Index(N) - (hi - lo);
                Eigen::MatrixXd A(rows, full.A.cols());
                Eigen::VectorXd b(rows);
                A.topRows(lo) = full.A.topRows(lo);
                A.bottomRows(Eigen::Index(N) - hi) = full.A.bottomRows(Eigen::Index(N) - hi);
                b.head(lo) = full.b.head(lo);
                b.tail(Eigen::Index(N) - hi) = full.b.tail(Eigen::Index(N) - hi);
                const Eigen::VectorXd x = stlsq(A, b, lambda);
                for (const auto& tf : tests[f]) {
                    const double r = weak_residual(tf, a, unknown, x);
                    score += r * r;
                }
            }
            if (score < best) {
                best = score;
                best_w = w;
                best_lambda = lambda;
            }
        }
    }
    const regression full = build(s, a, degree, best_w, unknown);
    double cond = 0;
    const Eigen::VectorXd x = stlsq(full.A, full.b, best_lambda, &cond);
    identification_report rep = report_of(s, a, unknown, degree, x, N, cond);
    rep.window = 2 * std::size_t(best_w) + 1;
    rep.threshold = best_lambda;
    return rep;
}

}  // namespace symrep::identification
