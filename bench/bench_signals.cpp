// Benchmarks of the signals and transforms layers (issue 16.5; docs/performance.md,
// "Signals and transforms"): a system of order m = 4, 8, 12 with a quasi-polynomial
// input (the response with its classification and the zero-state response, every
// result substituted back), the transmittance and sampling on the input's algebra, and
// the Laplace transform with its check, and the inputs of the SymPy side-by-side
// (bench/signals/sympy_transforms.py): inverse Laplace, Fibonacci, a geometric recurrence.
//
//   ./build/symrep_bench --benchmark_filter=Signals --benchmark_repetitions=3
//       --benchmark_report_aggregates_only=true   (one line)
#include <benchmark/benchmark.h>

#include <vector>

#include "algebra/polynomial_algebra.h"
#include "signals/representation.h"
#include "signals/response.h"
#include "transforms/laplace.h"

using namespace symrep;
using GiNaC::ex;

namespace {

const GiNaC::symbol t("t"), X("X"), l("l"), s("s");

/// a_0 .. a_m of prod_{k=1}^m (D + k/2) (distinct real modes, none shared with the input)
std::vector<ex> system_of_order(int m) {
    ex p = 1;
    for (int k = 1; k <= m; ++k) p *= X + GiNaC::numeric(k, 2);
    p = p.expand();
    std::vector<ex> a;
    for (int j = m; j >= 0; --j) a.push_back(p.coeff(X, j));
    return a;
}

const ex input = t * GiNaC::exp(-t / 3) * GiNaC::cos(3 * t) + GiNaC::sin(2 * t);

void BM_Signals_Response(benchmark::State& state) {
    const std::vector<ex> a = system_of_order(int(state.range(0))), b{1, 1};
    for (auto _ : state) benchmark::DoNotOptimize(signals::respond(a, b, input, t));
}

void BM_Signals_Transmittance(benchmark::State& state) {
    const std::vector<ex> a = system_of_order(int(state.range(0))), b{1, 1};
    const auto R = signals::polynomial_representation(signals::annihilator(input, t, X), X);
    for (auto _ : state) benchmark::DoNotOptimize(signals::transmittance(*R.A, R.d, a, b));
}

void BM_Signals_Sampling(benchmark::State& state) {
    const auto R = signals::polynomial_representation(signals::annihilator(input, t, X), X);
    for (auto _ : state) benchmark::DoNotOptimize(signals::sample(R, GiNaC::numeric(1, 10), l));
}

void BM_Signals_Laplace(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(transforms::laplace(input, t, s));
}

// The inputs of bench/signals/sympy_transforms.py (the side-by-side with SymPy).
void BM_Signals_InverseLaplace(benchmark::State& state) {
    const ex F = transforms::laplace(input, t, s);
    for (auto _ : state) benchmark::DoNotOptimize(transforms::inverse_laplace(F, s, t));
}

void BM_Signals_FibonacciFormula(benchmark::State& state) {
    const GiNaC::symbol k("k");
    for (auto _ : state) {
        const auto R = signals::polynomial_representation(X * X - X - 1, X);
        benchmark::DoNotOptimize(signals::sequence_formula(R, R.d, k));
    }
}

void BM_Signals_GeometricRecurrence(benchmark::State& state) {
    const GiNaC::symbol k("k");
    for (auto _ : state)
        benchmark::DoNotOptimize(signals::respond_discrete({1, ex(-1) / 2}, {1}, ex(1), k));
}

}  // namespace

BENCHMARK(BM_Signals_InverseLaplace)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_FibonacciFormula)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_GeometricRecurrence)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_Response)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_Transmittance)->Arg(4)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_Sampling)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Signals_Laplace)->Unit(benchmark::kMillisecond);
