// Benchmarks of the multicomplex algebra (x)C^{n+1} (thesis III.1):
//   double path: product, inverse and exp through the idempotent components
//   (one FWHT each way, O(n 2^n)) for n = 1..20, and the structure-constant
//   product (III.1.7) from a precomputed table, O(4^n), for n = 1..12;
//   exact path: the product (GiNaC rationals) for n = 1..8.
// Run: ./build/symrep_bench --benchmark_filter=Multicomplex
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "algebra/multicomplex.h"
#include "algebra/multicomplex_double.h"
#include "algebra/multicomplex_transform.h"

using namespace symrep;

namespace {

std::vector<double> random_element(const multicomplex_d& A, unsigned seed) {
    std::mt19937_64 g(seed);
    std::uniform_real_distribution<double> mod(0.5, 2.0), ang(-M_PI, M_PI);
    multicomplex_d::components c(A.half_dim());
    for (auto& z : c) z = std::polar(mod(g), ang(g));
    return A.from_idempotent_components(c);
}

void set_counters(benchmark::State& state, const multicomplex_d& A) {
    state.counters["dim"] = static_cast<double>(A.dim());
    state.SetComplexityN(static_cast<benchmark::IterationCount>(A.dim()));
}

void BM_MulticomplexDouble_Product(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 1), b = random_element(A, 2);
    for (auto _ : state) benchmark::DoNotOptimize(A.multiply(a, b));
    set_counters(state, A);
}

void BM_MulticomplexDouble_Inverse(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 3);
    for (auto _ : state) benchmark::DoNotOptimize(A.inverse(a));
    set_counters(state, A);
}

void BM_MulticomplexDouble_Exp(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 4);
    for (auto _ : state) benchmark::DoNotOptimize(A.exp(a, 0.5));
    set_counters(state, A);
}

// Before issue 15.5: one call of libm's exp, cos and sin per component (III.1.45-52),
// kept here to measure the batched exp against in one run.
void BM_MulticomplexDouble_ExpScalar(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 4);
    for (auto _ : state) {
        auto c = A.idempotent_components(a);
        for (auto& z : c) z = multicomplex_component_exp<double>(z.real(), z.imag(), 0.5);
        benchmark::DoNotOptimize(A.from_idempotent_components(c));
    }
    set_counters(state, A);
}

// The bound for exp (issue 15.5): the two transforms alone, to the idempotent
// components and back, on a reused buffer as exp and multiply use.
void BM_MulticomplexDouble_TransformPair(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 4);
    multicomplex_d::components c;
    for (auto _ : state) {
        multicomplex_components_into<double>(a, A.order(), c);
        benchmark::DoNotOptimize(multicomplex_from_components_inplace<double>(c, A.order()));
    }
    set_counters(state, A);
}

void BM_MulticomplexDouble_ProductStructure(benchmark::State& state) {
    const multicomplex_d A(static_cast<unsigned>(state.range(0)));
    const auto a = random_element(A, 1), b = random_element(A, 2);
    benchmark::DoNotOptimize(A.multiply_structure(a, b));  // builds the table outside the timing
    for (auto _ : state) benchmark::DoNotOptimize(A.multiply_structure(a, b));
    set_counters(state, A);
}

void BM_MulticomplexExact_Product(benchmark::State& state) {
    const auto A = multicomplex::make(static_cast<unsigned>(state.range(0)));
    std::mt19937 g(5);
    std::uniform_int_distribution<int> num(-9, 9), den(1, 4);
    coeffs a(A->dim()), b(A->dim());
    for (auto& x : a) x = GiNaC::numeric(num(g), den(g));
    for (auto& x : b) x = GiNaC::numeric(num(g), den(g));
    for (auto _ : state) benchmark::DoNotOptimize(A->multiply(a, b));
    state.counters["dim"] = static_cast<double>(A->dim());
}

}  // namespace

BENCHMARK(BM_MulticomplexDouble_Product)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexDouble_Inverse)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexDouble_Exp)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexDouble_ExpScalar)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexDouble_TransformPair)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexDouble_ProductStructure)->DenseRange(1, 12)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MulticomplexExact_Product)->DenseRange(1, 8)->Unit(benchmark::kMicrosecond);
