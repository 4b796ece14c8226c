// The double-precision paths (multicomplex_d, walsh_d, walsh_complex_d, sobrero_d)
// for EVERY n = 1..12, one or two random elements each, fixed seeds: products
// against a structure-constant product computed here, inverse, exp(s) exp(t) =
// exp(s + t), exp(log w) = w, zero-divisor ranks, and the components against a
// direct Hadamard sum (n <= 10). The structure-constant rules used at large n are
// first checked against the exact classes' basis products at small n.
//
// Tolerances (eps = DBL_EPSILON, D = dimension, N = number of components):
//  * Random elements of the idempotent families are built from components of
//    modulus in [1/2, 2] (condition number kappa = max|c| / min|c| <= 4). A fast
//    operation is two FWHTs of length N (error <= n eps times the 1-norm of the
//    partial sums, i.e. <= n eps max|c| after the 2^-n scaling) plus a componentwise
//    operation with relative error a few eps times kappa, so
//        tol_fast(n) = 64 (n + 1) kappa eps       (about 7e-13 at n = 12),
//    as a max-norm difference divided by max(1, max-norm of the expected value).
//  * Product against the O(D^2) structure-constant sum: each output coordinate is a
//    sum of D terms whose absolute values add up to at most |a|_2 |b|_2 (the map
//    q -> p xor q is a permutation; Cauchy-Schwarz), so naive summation is off by at
//    most D eps |a|_2 |b|_2; with the fast path's error,
//        tol_prod = (D + 64 (n + 1)) eps |a|_2 |b|_2      (absolute).
//  * Components against the direct sum_q (-1)^{<p,q>} f_q: (N + n) eps |f|_1 (absolute).
//  * Sobrero: xi_0 = 3/2 + j u, xi_k = (u + j u')/(2n) for k >= 1 (u, u' in [-1, 1]),
//    so sum_{k>=1} |xi_k| / |xi_0| <= 0.48 and every series (inverse, log, exp) has
//    coefficients bounded by a small constant B; a truncated convolution of length
//    n + 1 has error <= (n + 1) eps B_a B_b, so
//        tol_s = 64 (n + 1)^2 eps B_a B_b,  B = sum_k |xi_k| (data-dependent, absolute).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <random>

#include "algebra/multicomplex.h"
#include "algebra/multicomplex_double.h"
#include "scalar/scalar.h"
#include "algebra/sobrero.h"
#include "algebra/walsh.h"
#include "algebra/walsh_complex.h"
#include "algebra/walsh_double.h"
#include "core/error.h"
#include "test_util.h"

using namespace symrep;
using symrep::test::what_of;
using vec = std::vector<double>;
using cvec = std::vector<std::complex<double>>;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr unsigned max_n = 12;

double tol_fast(unsigned n, double kappa = 4.0) { return 64.0 * (n + 1) * kappa * eps; }

double norm2(const vec& a) {
    double s = 0;
    for (double x : a) s += x * x;
    return std::sqrt(s);
}
double norm1(const vec& a) {
    double s = 0;
    for (double x : a) s += std::abs(x);
    return s;
}
double max_abs_diff(const vec& a, const vec& b) {
    if (a.size() != b.size()) return INFINITY;
    double d = 0;
    for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::abs(a[k] - b[k]));
    return d;
}
double rel_diff(const vec& a, const vec& b) {
    double m = 1;
    for (double x : b) m = std::max(m, std::abs(x));
    return max_abs_diff(a, b) / m;
}
vec add(const vec& a, const vec& b) {
    vec r(a);
    for (std::size_t k = 0; k < r.size(); ++k) r[k] += b[k];
    return r;
}

/// N complex components of modulus in [1/2, 2], any angle, with the given ones zero.
cvec random_components(std::size_t N, unsigned seed, const std::vector<std::size_t>& zero = {}) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> mod(0.5, 2.0), ang(-M_PI, M_PI);
    cvec c(N);
    for (auto& z : c) z = std::polar(mod(g), ang(g));
    for (std::size_t r : zero) c[r] = 0.0;
    return c;
}
/// Real components of modulus in [1/2, 2], random sign unless `positive`.
vec random_real_components(std::size_t N, unsigned seed, bool positive, const std::vector<std::size_t>& zero = {}) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> mod(0.5, 2.0);
    std::bernoulli_distribution sign(0.5);
    vec a(N);
    for (auto& x : a) x = (positive || sign(g)) ? mod(g) : -mod(g);
    for (std::size_t r : zero) a[r] = 0.0;
    return a;
}
vec random_coords(std::size_t D, unsigned seed) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    vec w(D);
    for (auto& x : w) x = u(g);
    return w;
}

/// Rank sets for the zero-divisor tests (distinct, sorted).
std::vector<std::vector<std::size_t>> rank_sets(std::size_t N) {
    std::vector<std::vector<std::size_t>> out = {{0}, {N - 1}};
    if (N >= 4) out.push_back({1, N / 2, N - 1});
    if (N >= 16) out.push_back({3, 5, 6, 9, N - 2});
    return out;
}

// --- structure-constant products, written from the rules -----------------------------
// (III.1.7) e_p e_q = (-1)^{<p,q>} e_{p xor q}
vec multicomplex_direct(const vec& a, const vec& b) {
    vec r(a.size(), 0.0);
    for (std::size_t p = 0; p < a.size(); ++p) {
        if (a[p] == 0) continue;
        for (std::size_t q = 0; q < b.size(); ++q)
            r[p ^ q] += (std::popcount(p & q) & 1) ? -a[p] * b[q] : a[p] * b[q];
    }
    return r;
}
// (III.3.6) w_p w_q = w_{p xor q}
vec walsh_direct(const vec& a, const vec& b) {
    vec r(a.size(), 0.0);
    for (std::size_t p = 0; p < a.size(); ++p)
        for (std::size_t q = 0; q < b.size(); ++q) r[p ^ q] += a[p] * b[q];
    return r;
}
// W* in the basis {w_p} u {i0 w_p} (index s N + p): (w_p)(w_q) = w_{p^q}, (w_p)(i0 w_q) =
// i0 w_{p^q}, (i0 w_p)(i0 w_q) = -w_{p^q}. With N a power of two and p, q < N this is
// b_i b_j = (-1)^{[i >= N][j >= N]} b_{i xor j}; checked against walsh_complex below.
int wc_sign(std::size_t i, std::size_t j, std::size_t N) { return (i >= N && j >= N) ? -1 : 1; }
vec walsh_complex_direct(const vec& a, const vec& b) {
    const std::size_t N = a.size() / 2;
    vec r(a.size(), 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) r[i ^ j] += wc_sign(i, j, N) * a[i] * b[j];
    return r;
}
// (III.2.4) truncated complex convolution, [a_0..a_n, b_0..b_n]
vec sobrero_direct(const vec& u, const vec& v) {
    const std::size_t m = u.size() / 2;
    vec r(u.size(), 0.0);
    for (std::size_t k = 0; k < m; ++k)
        for (std::size_t l = 0; k + l < m; ++l) {
            r[k + l] += u[k] * v[l] - u[m + k] * v[m + l];
            r[m + k + l] += u[k] * v[m + l] + u[m + k] * v[l];
        }
    return r;
}

double to_d(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

}  // namespace

// The rules above reproduce the exact classes' structure constants (n <= 3).
TEST(DoublePaths, StructureRulesMatchExactClasses) {
    for (unsigned n = 1; n <= 3; ++n) {
        auto M = multicomplex::make(n);
        auto W = walsh::make(n);
        auto C = walsh_complex::make(n);
        auto S = sobrero::make(n);
        auto check = [](const algebra& A, const std::function<vec(const vec&, const vec&)>& rule) {
            for (std::size_t i = 0; i < A.dim(); ++i)
                for (std::size_t j = 0; j < A.dim(); ++j) {
                    vec ei(A.dim(), 0.0), ej(A.dim(), 0.0);
                    ei[i] = ej[j] = 1.0;
                    const vec r = rule(ei, ej);
                    const coeffs e = A.basis_product(i, j);
                    for (std::size_t k = 0; k < A.dim(); ++k)
                        ASSERT_EQ(r[k], to_d(e[k])) << A.name() << " " << i << " " << j << " " << k;
                }
        };
        check(*M, multicomplex_direct);
        check(*W, walsh_direct);
        check(*C, walsh_complex_direct);
        check(*S, sobrero_direct);
    }
}

// (III.1.7) product, (III.1.57) inverse, (III.1.45-53) exp and log, n = 1..12.
TEST(DoublePaths, MulticomplexProductInverseExpLogN1to12) {
    for (unsigned n = 1; n <= max_n; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        multicomplex_d A(n);
        const vec a = A.from_idempotent_components(random_components(A.half_dim(), 1100 + n));
        const vec b = A.from_idempotent_components(random_components(A.half_dim(), 1200 + n));
        const double tp = (A.dim() + 64.0 * (n + 1)) * eps * norm2(a) * norm2(b);
        const vec ab = A.multiply(a, b);
        EXPECT_LT(max_abs_diff(ab, multicomplex_direct(a, b)), tp);
        if (n <= 9) { EXPECT_LT(max_abs_diff(ab, A.multiply_structure(a, b)), tp); }
        EXPECT_LT(rel_diff(A.multiply(a, A.inverse(a)), A.unit()), tol_fast(n));
        EXPECT_LT(rel_diff(A.multiply(b, A.inverse(b)), A.unit()), tol_fast(n));
        const vec u = A.log(a);  // components log r + i phi, |.| <= pi + log 2
        EXPECT_LT(rel_diff(A.exp(u), a), tol_fast(n));
        EXPECT_LT(rel_diff(A.multiply(A.exp(b, 0.3), A.exp(b, -0.55)), A.exp(b, -0.25)), tol_fast(n));
        EXPECT_LT(rel_diff(A.exp(add(u, b)), A.multiply(a, A.exp(b))), tol_fast(n));
    }
}

TEST(DoublePaths, WalshProductInverseExpLogN1to12) {
    for (unsigned n = 1; n <= max_n; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        walsh_d A(n);
        const vec a = A.from_components(random_real_components(A.dim(), 2100 + n, false));
        const vec b = A.from_components(random_real_components(A.dim(), 2200 + n, false));
        const vec pos = A.from_components(random_real_components(A.dim(), 2300 + n, true));
        const double tp = (A.dim() + 64.0 * (n + 1)) * eps * norm2(a) * norm2(b);
        EXPECT_LT(max_abs_diff(A.multiply(a, b), walsh_direct(a, b)), tp);
        EXPECT_LT(rel_diff(A.multiply(a, A.inverse(a)), A.unit()), tol_fast(n));
        EXPECT_LT(rel_diff(A.exp(A.log(pos)), pos), tol_fast(n));  // (III.3.40)
        EXPECT_LT(rel_diff(A.multiply(A.exp(b, 0.3), A.exp(b, -0.55)), A.exp(b, -0.25)), tol_fast(n));
        // a negative component: no log in W, pointed to W*
        if (n == 5) { EXPECT_THROW(A.log(a), domain_error); }
    }
}

TEST(DoublePaths, WalshComplexProductInverseExpLogN1to12) {
    for (unsigned n = 1; n <= max_n; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        walsh_complex_d A(n);
        const vec a = A.from_components(random_components(A.size(), 3100 + n));
        const vec b = A.from_components(random_components(A.size(), 3200 + n));
        const double tp = (A.dim() + 64.0 * (n + 1)) * eps * norm2(a) * norm2(b);
        EXPECT_LT(max_abs_diff(A.multiply(a, b), walsh_complex_direct(a, b)), tp);
        EXPECT_LT(rel_diff(A.multiply(a, A.inverse(a)), A.unit()), tol_fast(n));
        EXPECT_LT(rel_diff(A.exp(A.log(a)), a), tol_fast(n));  // (III.3.67), any non-zero-divisor
        EXPECT_LT(rel_diff(A.exp(A.log(b)), b), tol_fast(n));
        EXPECT_LT(rel_diff(A.multiply(A.exp(b, 0.3), A.exp(b, -0.55)), A.exp(b, -0.25)), tol_fast(n));
        // i0^2 = -1, and the W part is the subalgebra W
        vec m1 = A.multiply(A.i0(), A.i0());
        m1[0] += 1.0;
        EXPECT_LT(max_abs_diff(m1, vec(A.dim(), 0.0)), tol_fast(n));
    }
}

TEST(DoublePaths, SobreroProductInverseExpLogN1to12) {
    for (unsigned n = 1; n <= max_n; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        sobrero_d A(n);
        std::mt19937_64 g(4100 + n);
        std::uniform_real_distribution<double> u(-1, 1);
        auto element = [&] {
            vec w(A.dim());
            w[0] = 1.5;
            w[n + 1] = u(g);
            for (unsigned k = 1; k <= n; ++k) {
                w[k] = u(g) / (2.0 * n);
                w[n + 1 + k] = u(g) / (2.0 * n);
            }
            return w;
        };
        auto B = [&](const vec& w) {
            double s = 0;
            for (unsigned k = 0; k <= n; ++k) s += std::hypot(w[k], w[n + 1 + k]);
            return s;
        };
        auto tol_s = [&](double ba, double bb) { return 64.0 * (n + 1) * (n + 1) * eps * ba * bb; };
        const vec a = element(), b = element();
        const vec ab = A.multiply(a, b);
        EXPECT_LT(max_abs_diff(ab, sobrero_direct(a, b)), tol_s(B(a), B(b)));
        const vec ai = A.inverse(a);
        EXPECT_LT(max_abs_diff(A.multiply(a, ai), A.unit()), tol_s(B(a), B(ai)));
        const vec l = A.log(a), el = A.exp(l);
        EXPECT_LT(max_abs_diff(el, a), tol_s(B(a), B(l) + 1));
        const vec e1 = A.exp(b, 0.3), e2 = A.exp(b, -0.55), e12 = A.exp(b, -0.25);
        EXPECT_LT(max_abs_diff(A.multiply(e1, e2), e12), tol_s(B(e1), B(e2)));
        // (III.2.13) zero divisors: xi_0 = 0 (nilpotent, III.2.15)
        vec z = a;
        z[0] = 0;
        z[n + 1] = 0;
        EXPECT_TRUE(A.is_zero_divisor(z));
        EXPECT_FALSE(A.is_zero_divisor(a));
        vec zn = z;  // z^{n+1} = 0
        for (unsigned k = 0; k < n; ++k) zn = A.multiply(zn, z);
        EXPECT_LT(max_abs_diff(zn, vec(A.dim(), 0.0)), tol_s(B(z), 1));
        try {
            A.inverse(z);
            ADD_FAILURE() << "no exception";
        } catch (const zero_divisor_error& e) {
            EXPECT_EQ(e.ranks, (std::vector<std::size_t>{0}));
        }
        EXPECT_THROW(A.log(z), zero_divisor_error);
        vec near = z;
        near[0] = 1e-6;  // well above the relative tolerance 1e-12
        EXPECT_FALSE(A.is_zero_divisor(near));
    }
}

// (III.1.54-56, III.3.31) zero divisors with chosen vanishing components at n = 1..12:
// the ranks are found, and inverse / log throw zero_divisor_error naming them.
TEST(DoublePaths, ZeroDivisorRanksN1to12) {
    for (unsigned n = 1; n <= max_n; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        multicomplex_d M(n);
        walsh_d W(n);
        walsh_complex_d C(n);
        const std::size_t N = std::size_t{1} << n;
        unsigned seed = 5000 + 10 * n;
        for (const auto& ranks : rank_sets(N)) {
            SCOPED_TRACE("ranks " + rank_list(ranks));
            const vec m = M.from_idempotent_components(random_components(N, seed++, ranks));
            const vec w = W.from_components(random_real_components(N, seed++, false, ranks));
            const vec c = C.from_components(random_components(N, seed++, ranks));
            EXPECT_EQ(M.zero_divisor_ranks(m), ranks);
            EXPECT_EQ(W.zero_divisor_ranks(w), ranks);
            EXPECT_EQ(C.zero_divisor_ranks(c), ranks);
            const std::string msg = "rank " + rank_list(ranks);
            auto expect_ranks = [&](const std::function<void()>& f, const char* what) {
                try {
                    f();
                    ADD_FAILURE() << what << ": no exception";
                } catch (const zero_divisor_error& e) {
                    EXPECT_EQ(e.ranks, ranks) << what;
                    EXPECT_NE(std::string(e.what()).find(msg), std::string::npos) << what << ": " << e.what();
                }
            };
            expect_ranks([&] { M.inverse(m); }, "multicomplex_d inverse");
            expect_ranks([&] { M.log(m); }, "multicomplex_d log");
            expect_ranks([&] { W.inverse(w); }, "walsh_d inverse");
            expect_ranks([&] { C.inverse(c); }, "walsh_complex_d inverse");
            expect_ranks([&] { C.log(c); }, "walsh_complex_d log");
            EXPECT_THROW(W.log(w), zero_divisor_error);
            // a zero divisor annihilates the idempotent of each rank: w e_r = 0
            for (std::size_t r : ranks) {
                cvec er(N, 0.0);
                er[r] = 1.0;
                EXPECT_LT(max_abs_diff(M.multiply(m, M.from_idempotent_components(er)), vec(M.dim(), 0.0)),
                          tol_fast(n));
            }
        }
        // non-zero-divisors have no ranks
        EXPECT_TRUE(M.zero_divisor_ranks(M.from_idempotent_components(random_components(N, seed++))).empty());
        EXPECT_TRUE(W.zero_divisor_ranks(W.from_components(random_real_components(N, seed++, false))).empty());
        EXPECT_TRUE(C.zero_divisor_ranks(C.from_components(random_components(N, seed++))).empty());
    }
}

// Components against the direct sums, n <= 10: Walsh a_p = sum_q (-1)^{<p,q>} f_q
// (III.3.25); W* c_p + i d_p with c = H a, d = H b (III.3.62-63); multicomplex
// c_p = sum_q (-1)^{<p,q>} i^{|q|} (w_q + i w_{2^n + q}) (III.1.39-41, docs/algebras.md).
TEST(DoublePaths, ComponentsVsDirectHadamardN1to10) {
    for (unsigned n = 1; n <= 10; ++n) {
        SCOPED_TRACE("n = " + std::to_string(n));
        const std::size_t N = std::size_t{1} << n;
        walsh_d W(n);
        walsh_complex_d C(n);
        multicomplex_d M(n);
        const vec f = random_coords(N, 6100 + n), w = random_coords(2 * N, 6200 + n);
        const double tf = (N + n) * eps * norm1(f), tw = 2 * (N + n) * eps * norm1(w);
        const vec a = W.components(f);
        const cvec y = C.components(w), c = M.idempotent_components(w);
        double da = 0, dy = 0, dc = 0;
        static const std::complex<double> ipow[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
        for (std::size_t p = 0; p < N; ++p) {
            double s = 0;
            std::complex<double> sy = 0, sc = 0;
            for (std::size_t q = 0; q < N; ++q) {
                const double h = (std::popcount(p & q) & 1) ? -1.0 : 1.0;
                s += h * f[q];
                sy += h * std::complex<double>(w[q], w[N + q]);
                sc += h * ipow[std::popcount(q) % 4] * std::complex<double>(w[q], w[N + q]);
            }
            da = std::max(da, std::abs(a[p] - s));
            dy = std::max(dy, std::abs(y[p] - sy));
            dc = std::max(dc, std::abs(c[p] - sc));
        }
        EXPECT_LT(da, tf);
        EXPECT_LT(dy, tw);
        EXPECT_LT(dc, tw);
        // round trips (III.3.21, III.3.57, III.1.42-43): 2^-n H inverts H
        EXPECT_LT(max_abs_diff(W.from_components(a), f), tf);
        EXPECT_LT(max_abs_diff(C.from_components(y), w), tw);
        EXPECT_LT(max_abs_diff(M.from_idempotent_components(c), w), tw);
    }
}

// Issue 13 (4.6): float elements of the exact multicomplex algebra take the double
// path, and multicomplex(n) for 10 < n <= max_order() is double-precision only.
// Tolerances: one FWHT and a componentwise operation on components of modulus
// O(1) (tol_fast above, about 64 (n + 1) eps), so 1e-12 relative for n <= 11.
TEST(DoublePathsIssue13, FloatElementsTakeTheDoublePath) {
    using symrep::multicomplex;
    const auto A = multicomplex::make(1);
    const coeffs xf{GiNaC::numeric(1.5), 2, 3, 4}, xe{GiNaC::numeric(3, 2), 2, 3, 4};
    const coeffs ef = A->exp(xf, 1), ee = A->exp(xe, 1);
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(ef[k])) << ef[k];  // numbers, not cos(1), sin(5) ...
        EXPECT_FALSE(GiNaC::ex_to<GiNaC::numeric>(ef[k]).is_rational()) << ef[k];
        const double want = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(ee[k])).to_double();
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(ef[k]).to_double(), want, 1e-12 * std::abs(want)) << k;
    }
    // exact coordinates stay exact
    EXPECT_TRUE(GiNaC::ex_to<GiNaC::numeric>(A->multiply(xe, xe)[0]).is_rational());

    const unsigned n = 11;
    ASSERT_LE(n, multicomplex_d::max_order());
    const auto B = multicomplex::make(n);
    EXPECT_FALSE(B->exact());
    coeffs z = B->zero();
    z[0] = GiNaC::numeric(1.5);
    z[B->dim() / 2] = 1;  // i0
    z[1] = GiNaC::numeric(0.25);  // i11
    const coeffs u = B->inverse(z), one = B->multiply(u, z);
    for (std::size_t k = 0; k < B->dim(); ++k)
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(one[k]).to_double(), k == 0 ? 1.0 : 0.0, 1e-12) << k;
    // exp(z) = exp(i0) exp(1.5 + 0.25 i11), each by the double path
    coeffs i0 = B->zero(), rest = z;
    i0[B->dim() / 2] = GiNaC::numeric(1.0);
    rest[B->dim() / 2] = 0;
    const coeffs lhs = B->exp(z, 1), rhs = B->multiply(B->exp(i0, 1), B->exp(rest, 1));
    for (std::size_t k = 0; k < B->dim(); ++k)
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(lhs[k]).to_double(), GiNaC::ex_to<GiNaC::numeric>(rhs[k]).to_double(),
                    1e-12 * 8)
            << k;  // |exp(z)| <= e^1.75 < 8
    // 1 + i0 i1 is a zero divisor (III.1.55): ranks found, the inverse refused
    coeffs zd = B->zero();
    zd[0] = GiNaC::numeric(1.0);
    zd[(B->dim() / 2) | (B->dim() / 4)] = 1;
    EXPECT_FALSE(B->zero_divisor_ranks(zd).empty());
    EXPECT_THROW(B->inverse(zd), zero_divisor_error);
    // the exact-only operations and symbolic coordinates are refused by name
    const GiNaC::symbol X("X"), a("a");
    const std::string m = what_of([&] { B->minpoly(z, X); });
    EXPECT_NE(m.find("n <= 10"), std::string::npos) << m;
    coeffs za = z;
    za[2] = a;
    const std::string ms = what_of([&] { B->exp(za, 1); });
    EXPECT_NE(ms.find("symbolic coordinates"), std::string::npos) << ms;
    EXPECT_THROW(multicomplex::make(multicomplex_d::max_order() + 1), size_error);
}

// The same for the Walsh algebra and its complex extension: float elements agree
// with the exact path evaluated (1e-12 relative, as above), and walsh(20),
// walsh_complex(18) are double-precision only.
TEST(DoublePathsIssue13, WalshFloatElementsTakeTheDoublePath) {
    auto close = [](const coeffs& f, const coeffs& e, const char* what) {
        for (std::size_t k = 0; k < f.size(); ++k) {
            ASSERT_TRUE(f[k].is_zero() || !GiNaC::ex_to<GiNaC::numeric>(f[k]).is_rational()) << what << k << ": " << f[k];
            const double want = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e[k])).to_double();
            EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(f[k])).to_double(), want, 1e-12 * (1 + std::abs(want)))
                << what << " " << k;
        }
    };
    const auto W = walsh::make(2);
    const coeffs xf{GiNaC::numeric(1.5), GiNaC::numeric(0.25), GiNaC::numeric(0.5), GiNaC::numeric(0.125)},
        xe{GiNaC::numeric(3, 2), GiNaC::numeric(1, 4), GiNaC::numeric(1, 2), GiNaC::numeric(1, 8)};
    close(W->exp(xf, 1), W->exp(xe, 1), "walsh exp");
    close(W->inverse(xf), W->inverse(xe), "walsh inverse");
    close(W->log(xf), W->log(xe), "walsh log");
    close(W->multiply(xf, xf), W->multiply(xe, xe), "walsh product");
    const auto C = walsh_complex::make(1);
    close(C->log(xf), C->log(xe), "walsh_complex log");
    close(C->exp(xf, 1), C->exp(xe, 1), "walsh_complex exp");

    const auto V = walsh::make(20);
    coeffs z = V->zero();
    z[0] = GiNaC::numeric(2.0);
    z[std::size_t(1) << 19] = GiNaC::numeric(0.5);  // u_0 / 2
    const coeffs one = V->multiply(V->inverse(z), z);
    for (std::size_t k = 0; k < V->dim(); k += 4099)
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(one[k])).to_double(), k == 0 ? 1.0 : 0.0, 1e-12) << k;
    const GiNaC::symbol X("X");
    EXPECT_THROW(V->minpoly(z, X), size_error);
    EXPECT_THROW(walsh::make(walsh_d::max_n + 1), size_error);
    EXPECT_FALSE(dynamic_cast<const walsh_complex&>(*walsh_complex::make(18)).exact());
    EXPECT_THROW(walsh_complex::make(walsh_complex_d::max_n + 1), size_error);
}

// Sobrero: float elements take sobrero_d (products, inverse, exp, zero divisors;
// 1e-12 relative against the exact path evaluated, the truncated series of
// length n + 1 = 3 adding no more than a few eps), sobrero(1000) is
// double-precision only, and log there is refused (sobrero_d has none).
TEST(DoublePathsIssue13, SobreroFloatElementsTakeTheDoublePath) {
    const auto S = sobrero::make(2);
    const coeffs xf{GiNaC::numeric(1.5), GiNaC::numeric(0.25), GiNaC::numeric(0.5), GiNaC::numeric(0.125), 1, 2},
        xe{GiNaC::numeric(3, 2), GiNaC::numeric(1, 4), GiNaC::numeric(1, 2), GiNaC::numeric(1, 8), 1, 2};
    for (const auto& [f, e] : {std::pair{S->exp(xf, 1), S->exp(xe, 1)}, std::pair{S->inverse(xf), S->inverse(xe)},
                               std::pair{S->multiply(xf, xf), S->multiply(xe, xe)}})
        for (std::size_t k = 0; k < f.size(); ++k) {
            ASSERT_TRUE(f[k].is_zero() || !GiNaC::ex_to<GiNaC::numeric>(f[k]).is_rational()) << k << ": " << f[k];
            const double want = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e[k])).to_double();
            EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(f[k]).to_double(), want, 1e-12 * (1 + std::abs(want))) << k;
        }
    const auto T = sobrero::make(1000);
    coeffs z = T->zero();
    z[0] = GiNaC::numeric(2.0);
    z[1] = 1;  // eps
    const coeffs one = T->multiply(T->inverse(z), z);
    for (std::size_t k = 0; k < T->dim(); k += 97)
        EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(one[k])).to_double(), k == 0 ? 1.0 : 0.0, 1e-12) << k;
    EXPECT_THROW(T->log(z), size_error);
    EXPECT_THROW(sobrero::make(sobrero_d::max_n + 1), size_error);
}
