// symrep/identification/operational_matrix.cpp -- P (IV.2.19), Q (IV.2.21), powers of Q.
#include "symrep/identification/operational_matrix.h"

#include <complex>
#include <string>

#include <unsupported/Eigen/FFT>

#include "symrep/core/error.h"
#include "symrep/core/progress.h"
#include "symrep/identification/walsh_series.h"

namespace symrep::identification {

namespace {

void check_dense(unsigned n, unsigned most, const char* what) {
    if (n < 1 || n > most)
        throw size_error(std::string(what) + " of order 2^" + std::to_string(n) + ": n must be 1 .. " +
                         std::to_string(most) + " for a dense matrix (the Toeplitz rows and fast transforms "
                         "of identify() go further)");
}

// (IV.2.19) P_1 = 1/2, P_m = [[P_(m/2), -1/(2m) I], [1/(2m) I, 0]]
template <class M, class S>
void fill_P(M& P, std::size_t m, const S& half, const std::function<S(long)>& inv) {
    if (m == 1) {
        P(0, 0) = half;
        return;
    }
    fill_P(P, m / 2, half, inv);
    for (std::size_t i = 0; i < m / 2; ++i) {
        P(i, m / 2 + i) = -inv(long(2 * m));
        P(m / 2 + i, i) = inv(long(2 * m));
    }
}

}  // namespace

GiNaC::matrix operational_matrix_exact(unsigned n) {
    check_dense(n, 12, "the operational matrix P");
    const std::size_t N = std::size_t(1) << n;
    GiNaC::matrix P{unsigned(N), unsigned(N)};
    struct ref {
        GiNaC::matrix& P;
        GiNaC::ex& operator()(std::size_t i, std::size_t j) { return P(unsigned(i), unsigned(j)); }
    } r{P};
    fill_P<ref, GiNaC::ex>(r, N, GiNaC::numeric(1, 2),
                           [](long d) { return GiNaC::ex(GiNaC::numeric(1, d)); });
    return P;
}

Eigen::MatrixXd operational_matrix(unsigned n) {
    check_dense(n, 13, "the operational matrix P");
    const std::size_t N = std::size_t(1) << n;
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(Eigen::Index(N), Eigen::Index(N));
    struct ref {
        Eigen::MatrixXd& P;
        double& operator()(std::size_t i, std::size_t j) { return P(Eigen::Index(i), Eigen::Index(j)); }
    } r{P};
    fill_P<ref, double>(r, N, 0.5, [](long d) { return 1.0 / double(d); });
    return P;
}

GiNaC::matrix block_pulse_matrix_exact(unsigned n) {
    check_dense(n, 12, "the operational matrix Q");
    const std::size_t N = std::size_t(1) << n;
    GiNaC::matrix Q{unsigned(N), unsigned(N)};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i; j < N; ++j)
            Q(unsigned(i), unsigned(j)) = GiNaC::numeric(j == i ? 1 : 2, long(2 * N));  // (IV.2.21)
    return Q;
}

Eigen::MatrixXd block_pulse_matrix(unsigned n) {
    check_dense(n, 13, "the operational matrix Q");
    const auto N = Eigen::Index(1) << n;
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(N, N);
    for (Eigen::Index i = 0; i < N; ++i)
        for (Eigen::Index j = i; j < N; ++j) Q(i, j) = (j == i ? 0.5 : 1.0) / double(N);
    return Q;
}

GiNaC::matrix operational_matrix_power_exact(unsigned n, long m) {
    check_dense(n, 8, "a power of the operational matrix P");
    const unsigned N = 1U << n;
    const auto row = block_pulse_power_row_exact(n, m);
    // (W Q^m W^T)_(p, q) = sum_(i <= j) W(p, i) r_(j - i) W(q, j)
    GiNaC::matrix out{N, N};
    std::vector<GiNaC::numeric> WQ(N);
    progress_task task("operational matrix", N);
    for (unsigned p = 0; p < N; ++p) {
        for (unsigned j = 0; j < N; ++j) {
            GiNaC::numeric acc = 0;
            for (unsigned i = 0; i <= j; ++i) acc += walsh_sign(p, i, n) * row[j - i];
            WQ[j] = acc;
        }
        for (unsigned q = 0; q < N; ++q) {
            GiNaC::numeric acc = 0;
            for (unsigned j = 0; j < N; ++j) acc += WQ[j] * walsh_sign(q, j, n);
            out(p, q) = acc / GiNaC::numeric(long(N));
        }
        task.report(p + 1);
    }
    return out;
}

std::vector<GiNaC::numeric> block_pulse_power_row_exact(unsigned n, long m) {
    const std::size_t N = std::size_t(1) << n;
    std::vector<GiNaC::numeric> g(N);
    g[0] = 1;
    if (N > 1) g[1] = 2 * m;
    for (std::size_t k = 1; k + 1 < N; ++k)
        g[k + 1] = (2 * m * g[k] + GiNaC::numeric(long(k) - 1) * g[k - 1]) / GiNaC::numeric(long(k + 1));
    const GiNaC::numeric s = GiNaC::pow(GiNaC::numeric(1, long(2 * N)), GiNaC::numeric(m));
    for (auto& x : g) x *= s;
    return g;
}

std::vector<double> block_pulse_power_row(unsigned n, long m, double T) {
    const std::size_t N = std::size_t(1) << n;
    std::vector<double> g(N);
    g[0] = 1;
    if (N > 1) g[1] = 2.0 * double(m);
    for (std::size_t k = 1; k + 1 < N; ++k)
        g[k + 1] = (2.0 * double(m) * g[k] + (double(k) - 1) * g[k - 1]) / double(k + 1);
    const double s = std::pow(T / (2.0 * double(N)), double(m));
    for (auto& x : g) x *= s;
    return g;
}

std::vector<double> integrate_blocks(const std::vector<double>& g, long m, double T) {
    const unsigned n = log2_of_count(g.size(), "integrate_blocks");
    const std::size_t N = g.size();
    if (m == 0) return g;
    const std::vector<double> r = block_pulse_power_row(n, m, T);
    std::vector<double> y(N, 0.0);
    if (N <= 256) {  // (Q^m)^T g: y_k = sum_(i <= k) r_(k-i) g_i
        for (std::size_t k = 0; k < N; ++k) {
            double s = 0;
            for (std::size_t i = 0; i <= k; ++i) s += r[k - i] * g[i];
            y[k] = s;
        }
        return y;
    }
    // the same causal convolution by FFT on 2N points (no wrap-around)
    // (one transform object per thread: it keeps its plans and twiddles between calls)
    thread_local Eigen::FFT<double> fft;
    std::vector<double> a(2 * N, 0.0), b(2 * N, 0.0), c;
    std::copy(r.begin(), r.end(), a.begin());
    std::copy(g.begin(), g.end(), b.begin());
    std::vector<std::complex<double>> A, B;
    fft.fwd(A, a);
    fft.fwd(B, b);
    for (std::size_t k = 0; k < A.size(); ++k) A[k] *= B[k];
    fft.inv(c, A);
    std::copy(c.begin(), c.begin() + long(N), y.begin());
    return y;
}

}  // namespace symrep::identification
