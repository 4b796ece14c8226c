// Benchmarks of the identification layer (issue 17.3; docs/identification.md and
// docs/performance.md, "Identification"): Duffing q'' + 4 q + 50 q^3 = 40 sin(2 pi t) +
// 20 cos(6 pi t) on 2^n blocks, the data made once per n by Boost.Odeint at 1e-12
// (outside the timing). Three methods: the integral form (least squares in the integrated
// equation), the thesis's values (IV.2.36, its alternating pole cancelled), regression on
// finite-difference derivatives (the SINDy baseline, plain least squares); and, for the
// convergence chart, the thesis's values as printed (no cancellation of the pole); for the
// noise chart, SINDy's sequentially thresholded least squares (threshold 0.5) and the strong
// baseline: the cross-validated SINDy pipeline (identification/sindy.h: Savitzky-Golay
// derivatives, STLSQ, window and threshold by blocked cross-validation). The counter `error`
// is |c - c_true| / |c_true| over the coefficients of f. BM_IdentifySystems compares the
// integral form, unsmoothed derivatives and the strong baseline on five systems and four
// noise levels (docs/identification.md, "Against the strong baseline").
//
//   ./build/symrep_bench --benchmark_filter=Identif
//   bash bench/plot_identification.sh        (the CSV and the charts in docs/figures)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <map>
#include <random>
#include <vector>

#include "identification/identify.h"
#include "identification/operational_matrix.h"
#include "identification/sindy.h"

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
    if (method == 5) return identify_sindy_cv(samples, a, 3);
    return identify_sindy(samples, a, 3, 0.0);
}

const char* const method_names[] = {"integral", "values", "derivatives", "values_as_printed", "sindy_stlsq", "sindy_cv"};

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
    ->ArgsProduct({{0, 1, 2, 3, 5}, {4, 6, 8, 10, 12, 14, 16}})
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
BENCHMARK(BM_IdentifyNoise)->ArgsProduct({{0, 1, 2, 4, 5}, {0, 1, 2, 3, 4, 5}})->Unit(benchmark::kMillisecond);

// Five systems q^(m) + a_1 q^(m-1) + ... + f(q) = u on [0, 1), 2^10 blocks / samples, relative
// Gaussian noise on q (seed fixed; independent draws for the block averages and the samples):
//   0 Duffing q'' + 4 q + 50 q^3 = 40 sin 2 pi t + 20 cos 6 pi t (a known, degree 3)
//   1 damped Duffing, the same with 0.8 q' (a_1 unknown)
//   2 q'' + 2 q + 3 q^2 = 30 sin 2 pi t, library of degree 4 (two zero terms)
//   3 q''' + 2 q'' + 5 q' + 3 q + 2 q^2 = 200 sin 2 pi t + 80 cos 4 pi t (a_1, a_2 unknown)
//   4 the pendulum q'' + 10 sin q = 20 sin 2 pi t (f not a polynomial; degree 5)
// error: the largest of max |f_id - f| / max |f| over the range of q (101 points) and the
// relative errors of the unknown a_k.
struct system_case {
    std::function<double(double)> f, u;
    std::vector<double> a;
    linear_part given;
    unsigned degree;
};

const system_case& system_of(int i) {
    static const std::vector<system_case> cases{
        {[](double q) { return 4 * q + 50 * q * q * q; },
         [](double t) { return 40 * std::sin(2 * M_PI * t) + 20 * std::cos(6 * M_PI * t); }, {0, 0}, {0.0, 0.0}, 3},
        {[](double q) { return 4 * q + 50 * q * q * q; },
         [](double t) { return 40 * std::sin(2 * M_PI * t) + 20 * std::cos(6 * M_PI * t); }, {0.8, 0},
         {std::nullopt, 0.0}, 3},
        {[](double q) { return 2 * q + 3 * q * q; }, [](double t) { return 30 * std::sin(2 * M_PI * t); }, {0, 0},
         {0.0, 0.0}, 4},
        {[](double q) { return 3 * q + 2 * q * q; },
         [](double t) { return 200 * std::sin(2 * M_PI * t) + 80 * std::cos(4 * M_PI * t); }, {2, 5, 0},
         {std::nullopt, std::nullopt, 0.0}, 2},
        {[](double q) { return 10 * std::sin(q); }, [](double t) { return 20 * std::sin(2 * M_PI * t); }, {0, 0},
         {0.0, 0.0}, 5},
    };
    return cases[std::size_t(i)];
}

double system_error(const system_case& c, const measured_system& clean, const identification_report& r) {
    double lo = 1e300, hi = -1e300, err = 0, size = 0;
    for (double q : clean.q) lo = std::min(lo, q), hi = std::max(hi, q);
    for (int k = 0; k <= 100; ++k) {
        const double q = lo + (hi - lo) * k / 100.0;
        double v = 0;
        for (std::size_t i = r.f.size(); i-- > 0;) v = v * q + r.f[i];
        err = std::max(err, std::abs(v - c.f(q)));
        size = std::max(size, std::abs(c.f(q)));
    }
    double e = err / size;
    for (std::size_t k = 0; k < c.given.size(); ++k)
        if (!c.given[k]) e = std::max(e, std::abs(r.a[k] - c.a[k]) / std::abs(c.a[k]));
    return e;
}

// method (0 integral, 2 derivatives, 5 sindy_cv), system, noise level
void BM_IdentifySystems(benchmark::State& state) {
    const int method = int(state.range(0));
    const system_case& c = system_of(int(state.range(1)));
    const double levels[] = {0, 1e-4, 1e-3, 1e-2};
    const double level = levels[state.range(2)];
    dataset d;
    d.blocks = simulate_system(c.f, c.u, c.a, 10, 1, &d.samples);
    const measured_system clean = d.blocks;
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
    for (auto _ : state) {
        if (method == 0) r = identify_integral(d.blocks, c.given, c.degree);
        else if (method == 2) r = identify_sindy(d.samples, c.given, c.degree, 0.0);
        else r = identify_sindy_cv(d.samples, c.given, c.degree);
        benchmark::DoNotOptimize(r);
    }
    state.counters["error"] = system_error(c, clean, r);
    state.counters["system"] = double(state.range(1));
    state.counters["noise"] = level;
    state.counters["window"] = double(r.window);
    state.SetLabel(method_names[method]);
}
BENCHMARK(BM_IdentifySystems)->ArgsProduct({{0, 2, 5}, {0, 1, 2, 3, 4}, {0, 1, 2, 3}})->Unit(benchmark::kMillisecond);

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
