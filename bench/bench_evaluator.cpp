// Benchmarks of the numeric evaluator (numeric/evaluator.h) on a closed form
// of Ch. VI: the free motion seen from a frame rotating with constant angular
// velocity w, r'' + 2 w x r' + w x (w x r) = 0, whose solution is
//   r(t) = exp(-W t) u,  u = r0 + (v0 + w x r0) t,
// written out with the Rodrigues formula (Omega = |w|):
//   r(t) = u cos(Omega t) - sin(Omega t)/Omega w x u + (1 - cos(Omega t))/Omega^2 (w.u) w.
// Per point (one value of t, three components):
//   Compiled/*:   compiled_function::eval (the flat double program),
//   GiNaC/*:      subs(t = value) + evalf of the three components,
//   Lambda/*:     a hand-written C++ lambda of the same formula,
//   *Many/*:      1024 points per call (eval_many, blocks of 16 points; the
//                 lambda in a plain loop); items_per_second gives points/s.
// "Numeric" variants substitute the parameters (exact rationals) before
// compiling, so the program has one input t; "Symbolic" variants keep
// w, r0, v0 as 9 more inputs.
//   Stable/*:     stable_function::eval (numeric/stable_evaluator.h) on the same
//                 form; counters give the share of points per precision tier.
//                 Stable_SmallRate scales w by 1e-6 (w t ~ 1e-6 .. 1e-3:
//                 the formula cancels, binary128); Stable_Binary64Bound is
//                 tier 1 alone (the program with its running error bound).
// Run: ./build/symrep_bench --benchmark_filter=Evaluator
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>

#include "numeric/evaluator.h"
#include "numeric/stable_evaluator.h"

using namespace symrep::num;
using GiNaC::ex;
using GiNaC::symbol;

namespace {

using vec = std::array<ex, 3>;

vec cross(const vec& a, const vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
ex dot(const vec& a, const vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// r(t) in components for given w, r0, v0 (symbols or numbers).
std::vector<ex> rotating_frame_solution(const symbol& t, const vec& w, const vec& r0, const vec& v0) {
    const ex Omega = GiNaC::sqrt(dot(w, w));
    const vec wr0 = cross(w, r0);
    vec u;
    for (int i = 0; i < 3; ++i) u[i] = r0[i] + (v0[i] + wr0[i]) * t;
    const vec wu = cross(w, u);
    const ex wdu = dot(w, u);
    std::vector<ex> r(3);
    for (int i = 0; i < 3; ++i)
        r[i] = u[i] * GiNaC::cos(Omega * t) - GiNaC::sin(Omega * t) / Omega * wu[i] +
               (1 - GiNaC::cos(Omega * t)) / GiNaC::pow(Omega, 2) * wdu * w[i];
    return r;
}

const GiNaC::numeric W[3] = {GiNaC::numeric(3, 10), GiNaC::numeric(-1, 2), GiNaC::numeric(4, 5)};
const GiNaC::numeric R0[3] = {GiNaC::numeric(1), GiNaC::numeric(0), GiNaC::numeric(1, 2)};
const GiNaC::numeric V0[3] = {GiNaC::numeric(0), GiNaC::numeric(1), GiNaC::numeric(1, 5)};

std::vector<ex> numeric_closed_form(const symbol& t) {
    return rotating_frame_solution(t, {W[0], W[1], W[2]}, {R0[0], R0[1], R0[2]}, {V0[0], V0[1], V0[2]});
}

/// The same formula by hand, in doubles.
struct hand_written {
    double w[3], r0[3], v0[3];
    void operator()(double t, double* r) const {
        const double Om = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        const double wr0[3] = {w[1] * r0[2] - w[2] * r0[1], w[2] * r0[0] - w[0] * r0[2], w[0] * r0[1] - w[1] * r0[0]};
        double u[3];
        for (int i = 0; i < 3; ++i) u[i] = r0[i] + (v0[i] + wr0[i]) * t;
        const double wu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
        const double wdu = w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
        const double c = std::cos(Om * t), s = std::sin(Om * t) / Om, k = (1 - c) / (Om * Om) * wdu;
        for (int i = 0; i < 3; ++i) r[i] = u[i] * c - s * wu[i] + k * w[i];
    }
};

hand_written numeric_lambda() {
    hand_written h{};
    for (int i = 0; i < 3; ++i) {
        h.w[i] = W[i].to_double();
        h.r0[i] = R0[i].to_double();
        h.v0[i] = V0[i].to_double();
    }
    return h;
}

void BM_Evaluator_Compiled_Numeric(benchmark::State& state) {
    symbol t("t");
    const compiled_function f = compile(numeric_closed_form(t), {t});
    double tv = 0, out[3];
    for (auto _ : state) {
        tv += 1e-3;
        f.eval(&tv, out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
    state.counters["instructions"] = static_cast<double>(f.n_instructions());
}

void BM_Evaluator_Lambda_Numeric(benchmark::State& state) {
    const hand_written h = numeric_lambda();
    double tv = 0, out[3];
    for (auto _ : state) {
        tv += 1e-3;
        h(tv, out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void BM_Evaluator_GiNaC_Numeric(benchmark::State& state) {
    symbol t("t");
    const std::vector<ex> r = numeric_closed_form(t);
    double tv = 0, out[3];
    for (auto _ : state) {
        tv += 1e-3;
        const ex val = GiNaC::numeric(tv);
        for (int i = 0; i < 3; ++i) out[i] = GiNaC::ex_to<GiNaC::numeric>(r[i].subs(t == val).evalf()).to_double();
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

void BM_Evaluator_Compiled_Symbolic(benchmark::State& state) {
    symbol t("t"), w1("w1"), w2("w2"), w3("w3"), x0("x0"), y0("y0"), z0("z0"), u0("u0"), v0("v0"), s0("s0");
    const compiled_function f = compile(rotating_frame_solution(t, {w1, w2, w3}, {x0, y0, z0}, {u0, v0, s0}),
                                        {t, w1, w2, w3, x0, y0, z0, u0, v0, s0});
    const hand_written h = numeric_lambda();
    double in[10] = {0, h.w[0], h.w[1], h.w[2], h.r0[0], h.r0[1], h.r0[2], h.v0[0], h.v0[1], h.v0[2]}, out[3];
    for (auto _ : state) {
        in[0] += 1e-3;
        f.eval(in, out);
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
    state.counters["instructions"] = static_cast<double>(f.n_instructions());
}

void BM_Evaluator_GiNaC_Symbolic(benchmark::State& state) {
    symbol t("t"), w1("w1"), w2("w2"), w3("w3"), x0("x0"), y0("y0"), z0("z0"), u0("u0"), v0("v0"), s0("s0");
    const std::vector<ex> r = rotating_frame_solution(t, {w1, w2, w3}, {x0, y0, z0}, {u0, v0, s0});
    const hand_written h = numeric_lambda();
    GiNaC::exmap m = {{w1, h.w[0]}, {w2, h.w[1]}, {w3, h.w[2]}, {x0, h.r0[0]}, {y0, h.r0[1]},
                      {z0, h.r0[2]}, {u0, h.v0[0]}, {v0, h.v0[1]}, {s0, h.v0[2]}};
    double tv = 0, out[3];
    for (auto _ : state) {
        tv += 1e-3;
        m[t] = GiNaC::numeric(tv);
        for (int i = 0; i < 3; ++i) out[i] = GiNaC::ex_to<GiNaC::numeric>(r[i].subs(m).evalf()).to_double();
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
}

// Many points per call: eval_many runs blocks of 16 points through the program.
constexpr int many = 1024;

void BM_Evaluator_CompiledMany_Numeric(benchmark::State& state) {
    symbol t("t");
    const compiled_function f = compile(numeric_closed_form(t), {t});
    std::vector<double> ts(many), out(3 * many);
    for (int i = 0; i < many; ++i) ts[i] = 1e-2 * i;
    for (auto _ : state) {
        f.eval_many(ts.data(), out.data(), many);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * many);
}

void BM_Evaluator_LambdaMany_Numeric(benchmark::State& state) {
    const hand_written h = numeric_lambda();
    std::vector<double> ts(many), out(3 * many);
    for (int i = 0; i < many; ++i) ts[i] = 1e-2 * i;
    for (auto _ : state) {
        for (int i = 0; i < many; ++i) h(ts[i], &out[3 * i]);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * many);
}

void BM_Evaluator_CompiledMany_Symbolic(benchmark::State& state) {
    symbol t("t"), w1("w1"), w2("w2"), w3("w3"), x0("x0"), y0("y0"), z0("z0"), u0("u0"), v0("v0"), s0("s0");
    const compiled_function f = compile(rotating_frame_solution(t, {w1, w2, w3}, {x0, y0, z0}, {u0, v0, s0}),
                                        {t, w1, w2, w3, x0, y0, z0, u0, v0, s0});
    const hand_written h = numeric_lambda();
    std::vector<double> in(10 * many), out(3 * many);
    for (int i = 0; i < many; ++i) {
        const double row[10] = {1e-2 * i, h.w[0], h.w[1], h.w[2], h.r0[0], h.r0[1], h.r0[2], h.v0[0], h.v0[1], h.v0[2]};
        std::copy(row, row + 10, &in[10 * i]);
    }
    for (auto _ : state) {
        f.eval_many(in.data(), out.data(), many);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * many);
}

void BM_Evaluator_Compile_Numeric(benchmark::State& state) {
    symbol t("t");
    const std::vector<ex> r = numeric_closed_form(t);
    for (auto _ : state) benchmark::DoNotOptimize(compile(r, {t}));
}

}  // namespace

/// stable_function::eval at t = 1e-3, 2e-3, ... with w scaled by `scale`; tiers counted.
void stable_run(benchmark::State& state, double scale) {
    symbol t("t");
    const GiNaC::numeric k = scale == 1 ? GiNaC::numeric(1) : GiNaC::numeric(1, 1000000);
    const std::vector<ex> r = rotating_frame_solution(t, {k * W[0], k * W[1], k * W[2]}, {R0[0], R0[1], R0[2]},
                                                      {V0[0], V0[1], V0[2]});
    const stable_function f(r, {t});
    double tv = 0, out[3];
    double tiers[3] = {0, 0, 0};
    for (auto _ : state) {
        tv += 1e-3;
        if (tv > 1) tv = 1e-3;
        tiers[static_cast<int>(f.eval(&tv, out))] += 1;
        benchmark::DoNotOptimize(out);
        benchmark::ClobberMemory();
    }
    const double n = std::max(1.0, tiers[0] + tiers[1] + tiers[2]);
    state.counters["binary64"] = tiers[0] / n;
    state.counters["binary128"] = tiers[1] / n;
    state.counters["multiprecision"] = tiers[2] / n;
}

void BM_Evaluator_Stable_Numeric(benchmark::State& state) { stable_run(state, 1); }
void BM_Evaluator_Stable_SmallRate(benchmark::State& state) { stable_run(state, 1e-6); }

void BM_Evaluator_Stable_Binary64Bound(benchmark::State& state) {
    symbol t("t");
    const stable_function f(numeric_closed_form(t), {t});
    double tv = 0, out[3], bound[3];
    for (auto _ : state) {
        tv += 1e-3;
        f.eval_binary64(&tv, out, bound);
        benchmark::DoNotOptimize(out);
        benchmark::DoNotOptimize(bound);
        benchmark::ClobberMemory();
    }
}

BENCHMARK(BM_Evaluator_Compiled_Numeric);
BENCHMARK(BM_Evaluator_Lambda_Numeric);
BENCHMARK(BM_Evaluator_GiNaC_Numeric);
BENCHMARK(BM_Evaluator_Compiled_Symbolic);
BENCHMARK(BM_Evaluator_GiNaC_Symbolic);
BENCHMARK(BM_Evaluator_CompiledMany_Numeric);
BENCHMARK(BM_Evaluator_LambdaMany_Numeric);
BENCHMARK(BM_Evaluator_CompiledMany_Symbolic);
BENCHMARK(BM_Evaluator_Compile_Numeric);
BENCHMARK(BM_Evaluator_Stable_Numeric);
BENCHMARK(BM_Evaluator_Stable_SmallRate);
BENCHMARK(BM_Evaluator_Stable_Binary64Bound);
