// Tests of engine/identification (thesis IV.2): Walsh series in Paley's ordering, the
// operational matrices P (IV.2.19) and Q (IV.2.21) exactly, the Toeplitz powers of Q, and the
// identification procedure on synthetic systems (Duffing, pendulum, a quadratic f, order 3).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "algebra/walsh.h"
#include "core/error.h"
#include "identification/identify.h"
#include "identification/operational_matrix.h"
#include "identification/walsh_series.h"

using namespace symrep;
using namespace symrep::identification;

namespace {

GiNaC::matrix hadamard_natural(unsigned n) {
    const unsigned N = 1U << n;
    GiNaC::matrix H{N, N};
    for (unsigned p = 0; p < N; ++p)
        for (unsigned k = 0; k < N; ++k) H(p, k) = (__builtin_popcount(p & k) & 1) ? -1 : 1;
    return H;
}

bool equal(const GiNaC::matrix& a, const GiNaC::matrix& b) {
    return (a.sub(b)).evalm().is_zero_matrix();
}

}  // namespace

// (IV.2.19) and (IV.2.22-23): P = W Q W^T / N exactly with Paley's W = H R, n = 1 .. 6; with
// the natural Hadamard matrix of (IV.2.14) only for n = 1 (the reading in walsh_series.h).
TEST(Identification, OperationalMatricesAreSimilarExactly) {
    for (unsigned n = 1; n <= 6; ++n) {
        const GiNaC::matrix P = operational_matrix_exact(n), Q = block_pulse_matrix_exact(n);
        const GiNaC::matrix W = walsh_matrix_exact(n);
        const GiNaC::numeric N(1L << n);
        const GiNaC::matrix WQW = W.mul(Q).mul(W.transpose()).mul_scalar(1 / N);
        EXPECT_TRUE(equal(P, WQW)) << "n = " << n;
        // W W^T = N I (IV.2.15a for W)
        EXPECT_TRUE(equal(W.mul(W.transpose()), GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(1U << n)).mul_scalar(N)));
        const GiNaC::matrix H = hadamard_natural(n);
        EXPECT_EQ(equal(P, H.mul(Q).mul(H).mul_scalar(1 / N)), n == 1) << "n = " << n;
    }
}

// (IV.2.18, IV.2.20): the block averages of int_0^t w_p are the block values of row p of P w,
// exactly (w_p piecewise constant: its integral is piecewise linear, averaged at block midpoints).
TEST(Identification, PIntegratesWalshFunctions) {
    for (unsigned n = 1; n <= 5; ++n) {
        const unsigned N = 1U << n;
        const GiNaC::matrix P = operational_matrix_exact(n), W = walsh_matrix_exact(n);
        const GiNaC::matrix PW = P.mul(W);
        for (unsigned p = 0; p < N; ++p) {
            GiNaC::numeric acc = 0;  // int_0^(k h) w_p
            for (unsigned k = 0; k < N; ++k) {
                const GiNaC::numeric h(1, long(N));
                const GiNaC::numeric avg = acc + h / 2 * walsh_sign(p, k, n);
                EXPECT_EQ(GiNaC::ex(avg), PW(p, k)) << "n " << n << " p " << p << " block " << k;
                acc += h * walsh_sign(p, k, n);
            }
        }
    }
}

// chi = minimal polynomial = (lambda - 1/2^(n+1))^(2^n): Delta = Q - I/2N is nilpotent of index
// exactly N (IV.2.48-50), and P has the same characteristic polynomial (n <= 3 by determinant).
TEST(Identification, CharacteristicAndMinimalPolynomial) {
    for (unsigned n = 1; n <= 6; ++n) {
        const unsigned N = 1U << n;
        const GiNaC::matrix Q = block_pulse_matrix_exact(n);
        const GiNaC::matrix D = Q.sub(GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(N)).mul_scalar(GiNaC::numeric(1, 2 * N)));
        GiNaC::matrix Dk = D;
        for (unsigned k = 1; k < N - 1; ++k) Dk = Dk.mul(D);
        EXPECT_FALSE(Dk.is_zero_matrix()) << n;  // Delta^(N-1) != 0
        EXPECT_TRUE(Dk.mul(D).is_zero_matrix()) << n;
    }
    const GiNaC::symbol l("lambda");
    for (unsigned n = 1; n <= 3; ++n) {
        const unsigned N = 1U << n;
        const GiNaC::ex chi = GiNaC::pow(l - GiNaC::numeric(1, 2 * N), N);
        EXPECT_TRUE(GiNaC::expand(operational_matrix_exact(n).charpoly(l) - chi).is_zero()) << n;
    }
}

// (IV.2.24) P^m = W Q^m W^T / N for m = 2, 3 and the inverse (m = -1, -2), exactly, n <= 5.
TEST(Identification, PowersAndInverseOfP) {
    for (unsigned n = 1; n <= 5; ++n) {
        const unsigned N = 1U << n;
        const GiNaC::matrix P = operational_matrix_exact(n);
        const GiNaC::matrix I = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(N));
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, 1), P)) << n;
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, 2), P.mul(P))) << n;
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, 3), P.mul(P).mul(P))) << n;
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, -1).mul(P), I)) << n;
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, -2).mul(P.mul(P)), I)) << n;
        EXPECT_TRUE(equal(operational_matrix_power_exact(n, 0), I)) << n;
    }
}

// Q^m from the power series (1/2N)^m ((1 + x)/(1 - x))^m equals the matrix power, for m = 1 .. 4
// and m = -1, -2 (the inverse), exactly; integrate_blocks agrees with the dense matrices, the
// FFT path (N > 256) included.
TEST(Identification, ToeplitzPowersOfQ) {
    for (unsigned n = 1; n <= 4; ++n) {
        const unsigned N = 1U << n;
        const GiNaC::matrix Q = block_pulse_matrix_exact(n);
        const GiNaC::matrix Qi = Q.inverse();
        for (long m : {1L, 2L, 3L, 4L, -1L, -2L}) {
            GiNaC::matrix M = m > 0 ? Q : Qi;
            for (long k = 1; k < std::labs(m); ++k) M = M.mul(m > 0 ? Q : Qi);
            const auto row = block_pulse_power_row_exact(n, m);
            for (unsigned i = 0; i < N; ++i)
                for (unsigned j = 0; j < N; ++j)
                    EXPECT_EQ(M(i, j), j >= i ? GiNaC::ex(row[j - i]) : GiNaC::ex(0)) << n << " " << m;
        }
    }
    // n = 5, 6: Q^m from its row against Q times Q^(m-1), and Q^-m Q^m = I, all exact
    for (unsigned n = 5; n <= 6; ++n) {
        const unsigned N = 1U << n;
        const auto toeplitz = [&](long m) {
            const auto row = block_pulse_power_row_exact(n, m);
            GiNaC::matrix M{N, N};
            for (unsigned i = 0; i < N; ++i)
                for (unsigned j = i; j < N; ++j) M(i, j) = row[j - i];
            return M;
        };
        const GiNaC::matrix Q = block_pulse_matrix_exact(n);
        EXPECT_TRUE(equal(toeplitz(1), Q));
        EXPECT_TRUE(equal(toeplitz(2), Q.mul(Q)));
        EXPECT_TRUE(equal(toeplitz(3), Q.mul(toeplitz(2))));
        const GiNaC::matrix I = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(N));
        EXPECT_TRUE(equal(toeplitz(-1).mul(Q), I));
        EXPECT_TRUE(equal(toeplitz(-2).mul(toeplitz(2)), I));
    }
    for (unsigned n : {4U, 10U}) {
        const Eigen::MatrixXd Q = block_pulse_matrix(n);
        const auto N = Eigen::Index(1) << n;
        Eigen::VectorXd g(N);
        for (Eigen::Index k = 0; k < N; ++k) g(k) = std::sin(0.37 * double(k)) + 0.5;
        const std::vector<double> gv(g.data(), g.data() + N);
        for (long m : {1L, 2L, 3L}) {
            Eigen::MatrixXd M = Eigen::MatrixXd::Identity(N, N);
            for (long k = 0; k < m; ++k) M = M * Q;
            const Eigen::VectorXd want = M.transpose() * g;
            const std::vector<double> got = integrate_blocks(gv, m);
            for (Eigen::Index k = 0; k < N; ++k) EXPECT_NEAR(got[std::size_t(k)], want(k), 1e-12 * want.cwiseAbs().maxCoeff());
        }
    }
}

// Walsh coefficients: exact for polynomials (t^2: c_0 = 1/3, c_1 = int t^2 r_1 = -1/4), the fast
// transform round trip, walsh_function against the signs, the product as the Walsh algebra's.
TEST(Identification, WalshSeries) {
    const GiNaC::symbol t("t");
    const auto v = block_averages_exact(GiNaC::pow(t, 2), t, 3);
    const auto c = walsh_from_blocks(v);
    EXPECT_EQ(c[0], GiNaC::ex(GiNaC::numeric(1, 3)));
    EXPECT_EQ(c[1], GiNaC::ex(GiNaC::numeric(-1, 4)));
    std::vector<double> vd;
    for (const auto& x : v) vd.push_back(GiNaC::ex_to<GiNaC::numeric>(x).to_double());
    const auto back = blocks_from_walsh(walsh_from_blocks(vd));
    for (std::size_t k = 0; k < vd.size(); ++k) EXPECT_NEAR(back[k], vd[k], 1e-15);
    for (std::size_t p = 0; p < 16; ++p)
        for (std::size_t k = 0; k < 16; ++k)
            EXPECT_EQ(walsh_function(p, (double(k) + 0.5) / 16), double(walsh_sign(p, k, 4)));
    // w_3 w_5 = w_6 (IV.2.3)
    std::vector<double> a(8, 0.0), b(8, 0.0);
    a[3] = 1;
    b[5] = 1;
    const auto ab = walsh_product(a, b);
    for (std::size_t p = 0; p < 8; ++p) EXPECT_NEAR(ab[p], p == 6 ? 1.0 : 0.0, 1e-15);
    EXPECT_NEAR(walsh_series_value(c.size() ? std::vector<double>{0, 1, 0, 0, 0, 0, 0, 0} : a, 0.7), -1.0, 0);
    // piecewise polynomials exactly: step(t - 1/3) has the block averages 0, 2/3, 1, 1;
    // t step(t - 1/2) + t^2 the coefficients 17/24, -5/8; abs(t - 1/2) the mean 1/4
    const auto st = walsh_from_blocks(block_averages_exact(GiNaC::step(t - GiNaC::numeric(1, 3)), t, 2));
    EXPECT_EQ(st[0], GiNaC::ex(GiNaC::numeric(2, 3)));
    const auto sv = block_averages_exact(GiNaC::step(t - GiNaC::numeric(1, 3)), t, 2);
    EXPECT_EQ(sv[1], GiNaC::ex(GiNaC::numeric(2, 3)));
    const auto pw = walsh_from_blocks(block_averages_exact(t * GiNaC::step(t - GiNaC::numeric(1, 2)) + t * t, t, 1));
    EXPECT_EQ(pw[0], GiNaC::ex(GiNaC::numeric(17, 24)));
    EXPECT_EQ(pw[1], GiNaC::ex(GiNaC::numeric(-5, 8)));
    EXPECT_EQ(walsh_from_blocks(block_averages_exact(GiNaC::abs(t - GiNaC::numeric(1, 2)), t, 3))[0],
              GiNaC::ex(GiNaC::numeric(1, 4)));
    EXPECT_TRUE(is_piecewise_polynomial(GiNaC::abs(2 * t - 1) * t, t));
    EXPECT_FALSE(is_piecewise_polynomial(GiNaC::step(t * t - 1), t));
    EXPECT_FALSE(is_piecewise_polynomial(GiNaC::exp(t), t));
    EXPECT_THROW(block_averages_exact(GiNaC::step(t * t - 1), t, 2), domain_error);
    EXPECT_THROW(walsh_from_blocks(std::vector<double>(6, 1.0)), domain_error);
    EXPECT_THROW(block_averages_exact(GiNaC::sin(t), t, 3), domain_error);
}

// (IV.2.5-9) the truncated series form an algebra isomorphic to the Walsh algebra of III.3: the
// product of two series is the algebra's product of their coefficient vectors.
TEST(Identification, SeriesProductIsTheWalshAlgebrasProduct) {
    const auto A = symrep::walsh::make(3);
    std::mt19937 gen(7);
    std::uniform_int_distribution<int> d(-9, 9);
    std::vector<double> a(8), b(8);
    symrep::coeffs ea(8), eb(8);
    for (std::size_t k = 0; k < 8; ++k) {
        a[k] = d(gen);
        b[k] = d(gen);
        ea[k] = int(a[k]);
        eb[k] = int(b[k]);
    }
    const auto ab = walsh_product(a, b);
    const symrep::coeffs e = A->multiply(ea, eb);
    for (std::size_t k = 0; k < 8; ++k)
        EXPECT_NEAR(ab[k], GiNaC::ex_to<GiNaC::numeric>(e[k]).to_double(), 1e-12) << k;
    // and the value of the series at t is its block value
    const auto v = blocks_from_walsh(ab);
    for (std::size_t k = 0; k < 8; ++k) EXPECT_NEAR(walsh_series_value(ab, (double(k) + 0.25) / 8), v[k], 1e-12);
}

namespace {

const auto duffing = [](double q) { return 4 * q + 50 * q * q * q; };
const auto drive = [](double t) { return 40 * std::sin(2 * M_PI * t) + 20 * std::cos(6 * M_PI * t); };

}  // namespace

// Duffing q'' + 4 q + 50 q^3 = u: both forms converge to the coefficients as n grows (the error
// at least 3x smaller per level from n = 6 to 9: O(h^2)); at 2^10 blocks within 2e-3 relative.
TEST(Identification, DuffingConverges) {
    double prev_values = 1e9, prev_integral = 1e9;
    for (unsigned n = 6; n <= 10; ++n) {
        const measured_system s = simulate_system(duffing, drive, {0, 0}, n);
        const auto rv = identify_values(s, {0.0, 0.0}, 3);
        const auto ri = identify_integral(s, {0.0, 0.0}, 3);
        const double ev = std::hypot(rv.f[1] - 4, rv.f[3] - 50) / 50, ei = std::hypot(ri.f[1] - 4, ri.f[3] - 50) / 50;
        if (n <= 9) {
            EXPECT_LT(ev, prev_values / 3) << n;
            EXPECT_LT(ei, prev_integral / 3) << n;
        }
        prev_values = ev;
        prev_integral = ei;
        if (n == 10) {
            EXPECT_LT(ev, 2e-3);
            EXPECT_LT(ei, 2e-3);
            EXPECT_LT(ri.residual, 1e-5);
            EXPECT_EQ(ri.points, 1024u);
            EXPECT_LT(ri.condition_number, 1e3);
            EXPECT_TRUE(ri.warning.empty());
        }
    }
}

// The printed system (IV.2.36) without the cancellation: the fitted cubic coefficient stays
// about 10 away from 50 from 2^8 to 2^12 blocks (the claim of docs/identification.md).
TEST(Identification, ThePrintedValuesDoNotConverge) {
    for (unsigned n : {8U, 10U, 12U}) {
        const measured_system s = simulate_system(duffing, drive, {0, 0}, n);
        EXPECT_GT(std::abs(identify_values_as_printed(s, {0.0, 0.0}, 3).f[3] - 50), 5.0) << n;
        EXPECT_LT(std::abs(identify_values(s, {0.0, 0.0}, 3).f[3] - 50), 0.1) << n;
    }
}

// The pendulum q'' + 10 sin q = u (f not a polynomial): a degree-5 fit reproduces f on the range
// of q within 1e-3 of its size; a quadratic f = 3 q + 2 q^2 with the order-3 operator
// q''' + 2 q'' + 5 q' + (known a) and with a_1, a_2 unknown, estimated jointly.
TEST(Identification, PendulumQuadraticAndOrderThree) {
    const auto pend = [](double q) { return 10 * std::sin(q); };
    const auto u = [](double t) { return 20 * std::sin(2 * M_PI * t); };
    const measured_system s = simulate_system(pend, u, {0, 0}, 10);
    const auto r = identify_integral(s, {0.0, 0.0}, 5);
    double lo = 1e9, hi = -1e9, err = 0;
    for (double q : s.q) lo = std::min(lo, q), hi = std::max(hi, q);
    for (int k = 0; k <= 100; ++k) {
        const double q = lo + (hi - lo) * k / 100.0;
        double v = 0;
        for (std::size_t i = r.f.size(); i-- > 0;) v = v * q + r.f[i];
        err = std::max(err, std::abs(v - pend(q)));
    }
    EXPECT_GT(hi - lo, 1.0);
    EXPECT_LT(err, 1e-2);
    const auto quad = [](double q) { return 3 * q + 2 * q * q; };
    const auto u3 = [](double t) { return 200 * std::sin(2 * M_PI * t) + 80 * std::cos(4 * M_PI * t); };
    const measured_system s3 = simulate_system(quad, u3, {2, 5, 0}, 10);
    const auto known = identify_integral(s3, {2.0, 5.0, 0.0}, 2);
    EXPECT_NEAR(known.f[1], 3, 1e-2);
    EXPECT_NEAR(known.f[2], 2, 1e-2);
    const auto joint = identify_integral(s3, {std::nullopt, std::nullopt, 0.0}, 2);
    EXPECT_NEAR(joint.a[0], 2, 1e-2);
    EXPECT_NEAR(joint.a[1], 5, 2e-2);
    EXPECT_NEAR(joint.f[2], 2, 2e-2);
    const auto values3 = identify_values(s3, {2.0, 5.0, 0.0}, 2);
    EXPECT_NEAR(values3.f[2], 2, 1e-3);
}

// With noise in the measured q (fixed seed): the integral form degrades gracefully, regression on
// derivatives (and the thesis's pointwise values, which differentiate too) do not.
TEST(Identification, NoiseFavoursTheIntegralForm) {
    measured_system samples;
    measured_system s = simulate_system(duffing, drive, {0, 0}, 10, 1, &samples);
    std::mt19937 gen(12345);
    double rq = 0;
    for (double x : s.q) rq += x * x;
    rq = std::sqrt(rq / double(s.q.size()));
    std::normal_distribution<double> noise(0, 1e-2 * rq);
    for (auto& x : s.q) x += noise(gen);
    for (auto& x : samples.q) x += noise(gen);
    const auto ri = identify_integral(s, {0.0, 0.0}, 3);
    const auto rs = identify_sindy(samples, {0.0, 0.0}, 3, 0.0);
    const auto rv = identify_values(s, {0.0, 0.0}, 3);
    EXPECT_NEAR(ri.f[3], 50, 1.0);
    EXPECT_GT(std::abs(rs.f[3] - 50), 10.0);
    EXPECT_GT(std::abs(rv.f[3] - 50), 10.0);
    // without noise the baseline is right too (central differences, O(h^2))
    measured_system clean_samples;
    simulate_system(duffing, drive, {0, 0}, 10, 1, &clean_samples);
    const auto clean = identify_sindy(clean_samples, {0.0, 0.0}, 3, 0.0);
    EXPECT_NEAR(clean.f[3], 50, 1e-2);
    EXPECT_NEAR(clean.f[1], 4, 1e-2);
}

// Bad input: not a power of two, different lengths, an unknown a_m with a linear term, the
// thesis's procedure with an unknown a_k, nothing measured.
TEST(Identification, BadInputIsRefusedByName) {
    measured_system s = simulate_system(duffing, drive, {0, 0}, 4);
    measured_system odd = s;
    odd.q.pop_back();
    odd.u.pop_back();
    EXPECT_THROW(identify_integral(odd, {0.0, 0.0}, 3), domain_error);
    measured_system mixed = s;
    mixed.u.resize(8);
    EXPECT_THROW(identify_integral(mixed, {0.0, 0.0}, 3), domain_error);
    try {
        identify_integral(s, {0.0, std::nullopt}, 3);
        FAIL();
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot be told apart"), std::string::npos) << e.what();
    }
    EXPECT_THROW(identify_values(s, {std::nullopt, 0.0}, 3), domain_error);
    measured_system zero = s;
    for (auto& x : zero.q) x = 0;
    EXPECT_THROW(identify_integral(zero, {0.0, 0.0}, 3), domain_error);
    EXPECT_THROW(operational_matrix_exact(13), size_error);
    // data that do not start from rest (q(0) = 1 instead of 0) are identified with a warning
    measured_system moved = simulate_system(duffing, drive, {0, 0}, 8);
    for (auto& x : moved.q) x += 1;
    EXPECT_NE(identify_integral(moved, {0.0, 0.0}, 3).warning.find("zero initial data"), std::string::npos);
    EXPECT_TRUE(identify_integral(simulate_system(duffing, drive, {0, 0}, 8), {0.0, 0.0}, 3).warning.empty());
}
