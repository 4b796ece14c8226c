// symrep/identification/walsh_series.cpp -- truncated Walsh series (IV.2.1).
#include "symrep/identification/walsh_series.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "symrep/algebra/walsh_hadamard.h"
#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"

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

std::vector<double> block_averages(const std::function<double(double)>& f, unsigned n, double T,
                                   const std::vector<double>& jumps) {
    const std::size_t N = std::size_t(1) << n;
    const double h = T / double(N);
    std::vector<double> v(N);
    for (std::size_t k = 0; k < N; ++k) {
        const double a = double(k) * h, b = a + h;
        double I = 0, lo = a;  // piece by piece between the jumps inside the block
        for (double c : jumps)
            if (c > lo && c < b) {
                I += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, lo, c, 8, 1e-13);
                lo = c;
            }
        I += boost::math::quadrature::gauss_kronrod<double, 15>::integrate(f, lo, b, 8, 1e-13);
        if (!std::isfinite(I))
            throw domain_error("block average of the signal on [" + std::to_string(a) + ", " + std::to_string(b) +
                               "] is not finite");
        v[k] = I / h;
    }
    return v;
}

namespace {

// The breakpoints c of step(a t + b) and abs(a t + b) in f (a, b rational, a != 0; with
// `exact` false any real numbers a != 0, b).
void breakpoints(const GiNaC::ex& f, const GiNaC::symbol& t, std::vector<GiNaC::numeric>& out, bool exact = true) {
    for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::function>(*it)) continue;
        const std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
        if (name != "step" && name != "abs") continue;
        const GiNaC::ex u = GiNaC::expand(it->op(0));
        const GiNaC::ex a = u.coeff(t, 1), b = u.coeff(t, 0);
        const auto real = [exact](const GiNaC::ex& c) {
            return GiNaC::is_a<GiNaC::numeric>(c) &&
                   (exact ? GiNaC::ex_to<GiNaC::numeric>(c).is_rational() : GiNaC::ex_to<GiNaC::numeric>(c).is_real());
        };
        if (!u.is_polynomial(t) || u.degree(t) != 1 || !real(a) || !real(b))
            throw domain_error(std::string(exact ? "exact Walsh coefficients: " : "a signal with jumps: ") + name + "(" +
                               message_text(it->op(0), text_limit::fragment) + ") is not of an argument a t + b with " +
                               (exact ? "rational" : "real") + " a != 0 and b");
        out.push_back(GiNaC::ex_to<GiNaC::numeric>(-b / a));
    }
}

// f on an interval where every step() and abs() has a fixed sign: its value there, a polynomial.
GiNaC::ex piece(const GiNaC::ex& f, const GiNaC::symbol& t, const GiNaC::numeric& mid) {
    struct fix : GiNaC::map_function {
        const GiNaC::symbol* t;
        GiNaC::numeric mid;
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (GiNaC::is_a<GiNaC::function>(x)) {
                const std::string name = GiNaC::ex_to<GiNaC::function>(x).get_name();
                if (name == "step" || name == "abs") {
                    const GiNaC::ex u = x.op(0);
                    const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(u.subs(*t == mid));
                    if (name == "step") return v.is_positive() ? 1 : 0;
                    return v.is_positive() ? u.map(*this) : -u.map(*this);
                }
            }
            return x.map(*this);
        }
    } m;
    m.t = &t;
    m.mid = mid;
    return GiNaC::expand(m(f));
}

GiNaC::ex antiderivative(const GiNaC::ex& e, const GiNaC::symbol& t) {
    if (!e.is_polynomial(t))
        throw domain_error("exact Walsh coefficients: the signal is not a piecewise polynomial in " + t.get_name() +
                           " (polynomials, step(a t + b), abs(a t + b)); use samples or a numeric signal");
    GiNaC::ex F = 0;
    for (int d = e.ldegree(t); d <= e.degree(t); ++d) F += e.coeff(t, d) * GiNaC::pow(t, d + 1) / (d + 1);
    return F;
}

}  // namespace

std::vector<double> jump_points(const GiNaC::ex& f, const GiNaC::symbol& t, double T) {
    std::vector<GiNaC::numeric> cuts;
    breakpoints(f, t, cuts, false);
    std::vector<double> out;
    for (const auto& c : cuts) {
        const double x = c.to_double();
        if (x > 0 && x < T) out.push_back(x);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

GiNaC::ex piece_of(const GiNaC::ex& f, const GiNaC::symbol& t, double mid) {
    return piece(f, t, GiNaC::numeric(mid));
}

bool is_piecewise_polynomial(const GiNaC::ex& f, const GiNaC::symbol& t) {
    try {
        std::vector<GiNaC::numeric> cuts;
        breakpoints(f, t, cuts);
        for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::function>(*it)) {
                const std::string name = GiNaC::ex_to<GiNaC::function>(*it).get_name();
                if (name != "step" && name != "abs") return false;
            }
        return piece(f, t, GiNaC::numeric(1, 3)).is_polynomial(t);  // the pieces have no other functions
    } catch (const error&) {
        return false;
    }
}

std::vector<GiNaC::ex> block_averages_exact(const GiNaC::ex& f, const GiNaC::symbol& t, unsigned n,
                                            const GiNaC::ex& T) {
    if (!GiNaC::is_a<GiNaC::numeric>(T) || !GiNaC::ex_to<GiNaC::numeric>(T).is_rational() ||
        !GiNaC::ex_to<GiNaC::numeric>(T).is_positive())
        throw domain_error("exact Walsh coefficients: the period must be a positive rational");
    std::vector<GiNaC::numeric> cuts;
    breakpoints(f, t, cuts);
    const std::size_t N = std::size_t(1) << n;
    const GiNaC::numeric h = GiNaC::ex_to<GiNaC::numeric>(T) / GiNaC::numeric(long(N));
    std::vector<GiNaC::ex> v(N);
    for (std::size_t k = 0; k < N; ++k) {
        const GiNaC::numeric lo = h * GiNaC::numeric(long(k)), hi = lo + h;
        std::vector<GiNaC::numeric> ends{lo};
        for (const auto& c : cuts)
            if (c > lo && c < hi) ends.push_back(c);
        std::sort(ends.begin(), ends.end(), [](const GiNaC::numeric& a, const GiNaC::numeric& b) { return a < b; });
        ends.erase(std::unique(ends.begin(), ends.end(),
                               [](const GiNaC::numeric& a, const GiNaC::numeric& b) { return a == b; }),
                   ends.end());
        ends.push_back(hi);
        GiNaC::ex I = 0;
        for (std::size_t j = 0; j + 1 < ends.size(); ++j) {  // (IV.2.4) piece by piece
            const GiNaC::ex F = antiderivative(piece(f, t, (ends[j] + ends[j + 1]) / 2), t);
            I += F.subs(t == ends[j + 1]) - F.subs(t == ends[j]);
        }
        v[k] = GiNaC::normal(I / h);
    }
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
