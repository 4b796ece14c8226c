// Tests of the batched componentwise exponential (algebra/batched_exp.h) against
// libm one value at a time: z -> e^(a t) (cos b t + i sin b t) (III.1.45-52).
//
// Tolerance: glibc documents its vector functions (libmvec) within 4 ulp, libm's
// scalar exp/sin/cos within 1 ulp; each output is a product e * c of two such
// values, so the two paths differ by at most about 2 * (4 + 1) ulp of the result:
// 16 eps relative to |e^(a t)| (the modulus of the result; a component near a
// zero of cos or sin is compared absolutely against that modulus).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "algebra/batched_exp.h"

using namespace symrep;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

std::complex<double> reference(std::complex<double> z, double t) {
    const double e = std::exp(z.real() * t);
    return {e * std::cos(z.imag() * t), e * std::sin(z.imag() * t)};
}

}  // namespace

TEST(BatchedExp, AgreesWithLibmValueByValue) {
    // Sizes around the block (256) and the vector widths (2, 4, 8): every tail path.
    std::mt19937_64 g(15);
    std::uniform_real_distribution<double> re(-30, 30), im(-1e4, 1e4), small(-1, 1);
    for (std::size_t count : {0u, 1u, 3u, 7u, 9u, 255u, 256u, 257u, 1000u}) {
        std::vector<std::complex<double>> z(count);
        for (std::size_t k = 0; k < count; ++k)
            z[k] = k % 3 ? std::complex<double>(re(g), im(g)) : std::complex<double>(small(g), small(g));
        auto w = z;
        const double t = 0.75;
        exp_components(w.data(), w.size(), t);
        for (std::size_t k = 0; k < count; ++k) {
            const auto r = reference(z[k], t);
            const double scale = std::abs(r);
            EXPECT_LE(std::abs(w[k] - r), 16 * eps * scale)
                << "count " << count << ", k " << k << ", z " << z[k] << " (kernel " << exp_components_kernel()
                << ")";
        }
    }
}

TEST(BatchedExp, LargeArgumentsAndSpecialValues) {
    // Large b t needs the full range reduction; a t beyond +-709 overflows or underflows
    // as exp does; inf and nan propagate as in libm (inf * cos(0) = inf, inf * sin(0) = nan).
    const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::complex<double>> z = {{0, 1e22}, {0, 1e300}, {1, -3.5e15}, {-800, 1}, {800, 1},
                                           {0, 0},    {inf, 0},   {-inf, 2},    {nan, 1},  {1, nan},
                                           {0, inf},  {0, -0.0}};
    auto w = z;
    exp_components(w.data(), w.size(), 1.0);
    for (std::size_t k = 0; k < z.size(); ++k) {
        const auto r = reference(z[k], 1.0);
        for (int part = 0; part < 2; ++part) {
            const double x = part ? w[k].imag() : w[k].real(), y = part ? r.imag() : r.real();
            if (std::isnan(y)) {
                EXPECT_TRUE(std::isnan(x)) << "z " << z[k];
            } else if (std::isinf(y) || y == 0) {
                EXPECT_EQ(x, y) << "z " << z[k];
            } else {
                EXPECT_LE(std::abs(x - y), 16 * eps * std::abs(r)) << "z " << z[k];
            }
        }
    }
}

TEST(BatchedExp, NamesItsKernel) {
    const std::string k = exp_components_kernel();
    EXPECT_TRUE(k == "avx512" || k == "avx2" || k == "sse" || k == "scalar") << k;
}
