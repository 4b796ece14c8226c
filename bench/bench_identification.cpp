// Benchmarks of the identification layer (issue 17.3; docs/identification.md and
// docs/performance.md, "Identification"): Duffing q'' + 4 q + 50 q^3 = 40 sin(2 pi t) +
// 20 cos(6 pi t) on 2^n blocks, the data made once per n by Boost.Odeint at 1e-12
// (outside the timing). Three methods: the integral form (least squares in the integrated
// equation), the thesis's values (IV.2.36, its alternating pole cancelled), regression on
// finite-difference derivatives (the SINDy baseline, plain least squares); and, for the
// convergence chart, the thesis's values as printed (no cancellation of the pole); for the
// noise chart, SINDy's sequentially thresholded least squares (threshold 0.5). The counter
// `error` is |c - c_true| / |c_true| over the coefficients of f.
//
//   ./build/symrep_bench --benchmark_filter=Identif
//   bash bench/plot_identification.sh        (the CSV and the charts in docs/figures)
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "identification/identify.h"
#include "identification/operational_matrix.h"

using namespace symrep::identification;

namespace {

const std::vector<double> truth{0, 4, 0, 50};

struct dataset {
    measured_system blocks, samples;
};

const dataset& duffing_data(unsigned n) {
    static std::map<unsigned, dataset> cache;
    auto it = cache.find(n);
    if (it == cache.end()) {
        dataset d;
        d.blocks = simulate_system([](double q) { return 4 * q + 50 * q * q * q; },
                                   [](double t) { return 40 * std::sin(2 * M_PI * t) + 20 * std::cos(6 * M_PI * t); },
                                   {0, 0}, n, 1, &d.samples);
        it = cache.emplace(n, d).first;
    }
    return it->second;
}

double coefficient_error(const std::vector<double>& c) {
    double e = 0, s = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        e += (c[i] - truth[i]) * (c[i] - truth[i]);
        s += truth[i] * truth[i];
    }
    return std::sqrt(e / s);
}

identification_report run(int method, const measured_system& blocks, const measured_system& samples) {
    const linear_part a{0.0, 0.0};
    if (method == 0) return identify_integral(blocks, a, 3);
    if (method == 1) return identify_values(blocks, a, 3);
    if (method == 3) return identify_values_as_printed(blocks, a, 3);
    if (method == 4) return identify_sindy(samples, a, 3, 0.5);  // STLSQ: |c| < 0.5 dropped
    return identify_sindy(samples, a, 3, 0.0);
}

const char* const method_names[] = {"integral", "values", "derivatives", "values_as_printed", "sindy_stlsq"};

// method, n: cost and error against the number of blocks (no noise)
void BM_Identify(benchmark::State& state) {
    const int method = int(state.range(0));
    const unsigned n = unsigned(state.range(1));
    const dataset& d = duffing_data(n);
    identification_report r;
    for (auto _ : state) benchmark::DoNotOptimize(r = run(method, d.blocks, d.samples));
    state.counters["error"] = coefficient_error(r.f);
    state.counters["blocks"] = double(std::size_t(1) << n);
    state.SetLabel(method_names[method]);
}
BENCHMARK(BM_Identify)
    ->ArgsProduct({{0, 1, 2, 3}, {4, 6, 8, 10, 12, 14, 16}})
    ->Unit(benchmark::kMillisecond);

// method, noise level: relative Gaussian noise on the measured q (rms of q times the level;
// seed fixed), 2^10 blocks
void BM_IdentifyNoise(benchmark::State& state) {
    const int method = int(state.range(0));
    const double levels[] = {0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2};
    const double level = levels[state.range(1)];
    dataset d = duffing_data(10);
    double rms = 0;
    for (double x : d.blocks.q) rms += x * x;
    rms = std::sqrt(rms / double(d.blocks.q.size()));
    std::mt19937 gen(2026);
    std::normal_distribution<double> noise(0, level * rms);
    if (level > 0) {
        for (double& x : d.blocks.q) x += noise(gen);
        for (double& x : d.samples.q) x += noise(gen);
    }
    identification_report r;
    for (auto _ : state) benchmark::DoNotOptimize(r = run(method, d.blocks, d.samples));
    state.counters["error"] = coefficient_error(r.f);
    state.counters["noise"] = level;
    state.SetLabel(method_names[method]);
}
BENCHMARK(BM_IdentifyNoise)->ArgsProduct({{0, 1, 2, 4}, {0, 1, 2, 3, 4, 5}})->Unit(benchmark::kMillisecond);

// The m-fold integral of 2^n block values by the Toeplitz row of Q^m (O(N^2) to 256 blocks,
// FFT above): the kernel of every method.
void BM_IdentificationIntegrateBlocks(benchmark::State& state) {
    const unsigned n = unsigned(state.range(0));
    std::vector<double> g(std::size_t(1) << n);
    for (std::size_t k = 0; k < g.size(); ++k) g[k] = std::sin(0.01 * double(k));
    for (auto _ : state) benchmark::DoNotOptimize(integrate_blocks(g, 2));
    state.SetComplexityN(long(g.size()));
}
BENCHMARK(BM_IdentificationIntegrateBlocks)->DenseRange(4, 16, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
