// symrep/identification/walsh_series.cpp -- truncated Walsh series (IV.2.1).
#include "identification/walsh_series.h"

#include <bit>
#include <cmath>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "algebra/walsh_hadamard.h"
#include "core/error.h"

namespace symrep::identification {

unsigned log2_of_count(std::size_t N, const char* what) {
    if (N < 2 || !is_pow2(N))
        throw domain_error(std::string(what) + ": " + std::to_string(N) +
                           " values; a truncated Walsh series needs a power of two (2, 4, 8, ...) of block values");
    return unsigned(std::countr_zero(N));
}

double rademacher(unsigned k, double t) {
    const double s = t - std::floor(t);  // 1-periodic
    const auto half_waves = static_cast<unsigned long long>(std::floor(std::ldexp(s, int(k))));
    return (half_waves & 1ULL) ? -1.0 : 1.0;
}

double walsh_function(std::size_t p, double t) {
    double v = 1;
    for (unsigned j = 0; p >> j; ++j)
        if ((p >> j) & 1U) v *= rademacher(j + 1, t);
    return v;
}

std::size_t bit_reverse(std::size_t k, unsigned n) {
    std::size_t r = 0;
    for (unsigned j = 0; j < n; ++j)
        if ((k >> j) & 1U) r |= std::size_t(1) << (n - 1 - j);
    return r;
}

int walsh_sign(std::size_t p, std::size_t k, unsigned n) {
    return (std::popcount(p & bit_reverse(k, n)) & 1) ? -1 : 1;
}

GiNaC::matrix walsh_matrix_exact(unsigned n) {
    const std::size_t N = std::size_t(1) << n;
    GiNaC::matrix W{unsigned(N), unsigned(N)};
    for (std::size_t p = 0; p < N; ++p)
        for (std::size_t k = 0; k < N; ++k) W(unsigned(p), unsigned(k)) = walsh_sign(p, k, n);
    return W;
}

Eigen::MatrixXd walsh_matrix(unsigned n) {
    const auto N = Eigen::Index(1) << n;
    Eigen::MatrixXd W(N, N);
    for (Eigen::Index p = 0; p < N; ++p)
        for (Eigen::Index k = 0; k < N; ++k) W(p, k) = walsh_sign(std::size_t(p), std::size_t(k), n);
    return W;
}

namespace {

// W v = H (R v): the bit-reversal permutation, then the Hadamard transform.
template <class T>
void to_walsh(std::vector<T>& v, unsigned n) {
    for (std::size_t k = 0; k < v.size(); ++k) {
        const std::size_t r = bit_reverse(k, n);
        if (r > k) std::swap(v[k], v[r]);
    }
    fwht(v);
}

}  // namespace

std::vector<double> walsh_from_blocks(std::vector<double> v) {
    const unsigned n = log2_of_count(v.size(), "Walsh coefficients");
    to_walsh(v, n);
    for (double& x : v) x /= double(v.size());
    return v;
}

std::vector<GiNaC::ex> walsh_from_blocks(std::vector<GiNaC::ex> v) {
    const unsigned n = log2_of_count(v.size(), "Walsh coefficients");
    to_walsh(v, n);
    for (GiNaC::ex& x : v) x = GiNaC::normal(x / GiNaC::numeric(long(v.size())));
    return v;
}

namespace {

template <class T>
std::vector<T> from_walsh(std::vector<T> c) {
    const unsigned n = log2_of_count(c.size(), "Walsh series");
    fwht(c);  // W^T c = R H c
    for (std::size_t k = 0; k < c.size(); ++k) {
        const std::size_t r = bit_reverse(k, n);
        if (r > k) std::swap(c[k], c[r]);
    }
    return c;
}

}  // namespace

std::vector<double> blocks_from_walsh(std::vector<double> c) { return from_walsh(std::move(c)); }

std::vector<GiNaC::ex> blocks_from_walsh(std::vector<GiNaC::ex> c) {
    std::vector<GiNaC::ex> v = from_walsh(std::move(c));
    for (auto& x : v) x = GiNaC::normal(x);
    return v;
}

std::vector<double> block_averages(const std::function<double(double)>& f, unsigned n, double T) {
    const std::size_t N = std::size_t(1) << n;
    const double h = T / double(N);
    std::vector<double> v(N);
    for (std::size_t k = 0; k < N; ++k) {
        const double a = double(k) * h, b = a + h;
        const double I = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, a, b, 8, 1e-13);
        if (!std::isfinite(I))
            throw domain_error("block average of the signal on [" + std::to_string(a) + ", " + std::to_string(b) +
                               "] is not finite");
        v[k] = I / h;
    }
    return v;
}

std::vector<GiNaC::ex> block_averages_exact(const GiNaC::ex& f, const GiNaC::symbol& t, unsigned n,
                                            const GiNaC::ex& T) {
    const GiNaC::ex e = GiNaC::expand(f);
    if (!e.is_polynomial(t))
        throw domain_error("exact Walsh coefficients: the signal is not a polynomial in " + GiNaC::ex_to<GiNaC::symbol>(t).get_name() +
                           " (use samples or a numeric signal)");
    // the antiderivative F, term by term
    GiNaC::ex F = 0;
    for (int d = e.ldegree(t); d <= e.degree(t); ++d) F += e.coeff(t, d) * GiNaC::pow(t, d + 1) / (d + 1);
    const std::size_t N = std::size_t(1) << n;
    const GiNaC::ex h = T / GiNaC::numeric(long(N));
    std::vector<GiNaC::ex> v(N);
    for (std::size_t k = 0; k < N; ++k)
        v[k] = GiNaC::normal((F.subs(t == h * GiNaC::numeric(long(k + 1))) - F.subs(t == h * GiNaC::numeric(long(k)))) / h);
    return v;
}

double walsh_series_value(const std::vector<double>& c, double t, double T) {
    const unsigned n = log2_of_count(c.size(), "Walsh series");
    const double s = t / T - std::floor(t / T);
    const std::size_t k = std::min(c.size() - 1, std::size_t(std::floor(s * double(c.size()))));
    double v = 0;
    for (std::size_t p = 0; p < c.size(); ++p) v += c[p] * walsh_sign(p, k, n);
    return v;
}

std::vector<double> walsh_product(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size())
        throw domain_error("Walsh product: series of " + std::to_string(a.size()) + " and " +
                           std::to_string(b.size()) + " terms");
    std::vector<double> va = blocks_from_walsh(a);
    const std::vector<double> vb = blocks_from_walsh(b);
    for (std::size_t k = 0; k < va.size(); ++k) va[k] *= vb[k];  // (IV.2.9) e_p e_q = delta_pq e_p
    return walsh_from_blocks(va);
}

}  // namespace symrep::identification
