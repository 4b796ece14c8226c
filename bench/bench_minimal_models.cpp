// Benchmarks of the minimal model of a scene (mechanics/scene.h) against the
// general model, on scenes of Ch. VI whose data relate specially to the axis
// (data along w, perpendicular to w, w0 = 0) and one generic scene as a control:
//   MinimalModel_Derive/k:    solve(P, values): classify, derive in the smallest
//                             algebra, put the values in;
//   GeneralModel_Derive/k:    solve(P) (the general model, every scalar problem
//                             and coefficient) and the values put in afterwards;
//   MinimalModel_Eval/k, GeneralModel_Eval/k: the scene's closed form (three
//                             components, one input t) compiled by
//                             numeric/evaluator.h and run by eval_many on 1024
//                             points; "compile_us" is the compile time once.
//                             Where the general form is singular at the values
//                             (w0 = 0) it cannot be compiled: eval's limit per
//                             point is timed instead (one point per iteration).
// Each scene twice: with exact values (rationals; GiNaC then simplifies the general
// form with the values put in, often to the minimal one) and with the same values
// as floating-point numbers, as typed in a script (no such cancellation). The
// setup checks that both closed forms are exactly equal (vector::equal; skipped
// with floats, where the two forms round differently) and reports, per form, the
// largest error over 64 times against the exact value at 40 digits
// (numeric/reference.h), relative to the largest component.
// Run: ./build/symrep_bench --benchmark_filter=Model_ --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "lang/interpreter.h"
#include "lang/values.h"
#include "mechanics/scene.h"
#include "numeric/evaluator.h"
#include "numeric/reference.h"
#include "vector/vector.h"

using namespace symrep;
using GiNaC::ex;

namespace {

struct scene_spec {
    const char* label;
    const char* declarations;
    const char* problem;
    const char* exact_values;  // rationals: the general form with them put in is as simplified as GiNaC makes it
    const char* float_values;  // the same scene as typed in a script: floating-point numbers
    double T;                  // evaluation on [0, T]
};

const char* const centrifugal = "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)";
const char* const coriolis = "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)";
const char* const charge = "ode(m*v' = q*(v x B + E), v(0) = v0)";
const char* const foucault = "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)";

// Earth's rate 7.2921e-5 rad/s, g = 9.81 m/s^2.
const scene_spec scenes[] = {
    {"gravity, w parallel to g, data along w (1-D)", "vector w, g, r0, v0", centrifugal,
     "[w = [0, 0, 72921/10^9], g = [0, 0, -981/100], r0 = [0, 0, 100], v0 = [0, 0, 5]]",
     "[w = [0, 0, 7.2921e-5], g = [0, 0, -9.81], r0 = [0, 0, 100], v0 = [0, 0, 5]]", 10},
    {"gravity, w perpendicular to g and data (Coriolis, equator)", "vector w, g, r0, v0", coriolis,
     "[w = [0, 72921/10^9, 0], g = [0, 0, -981/100], r0 = [0, 0, 100], v0 = [10, 0, 0]]",
     "[w = [0, 7.2921e-5, 0], g = [0, 0, -9.81], r0 = [0, 0, 100], v0 = [10, 0, 0]]", 10},
    {"charge, E perpendicular to B", "vector E, B, v0", charge,
     "[B = [0, 0, 1], E = [0, 1/2, 0], v0 = [1, 0, 0], q = 1, m = 1]",
     "[B = [0, 0, 1.0], E = [0, 0.5, 0], v0 = [1.0, 0, 0], q = 1.0, m = 1.0]", 20},
    {"charge, E parallel to B", "vector E, B, v0", charge,
     "[B = [0, 0, 1], E = [0, 0, 1/2], v0 = [1, 0, 0], q = 1, m = 1]",
     "[B = [0, 0, 1.0], E = [0, 0, 0.5], v0 = [1.0, 0, 0], q = 1.0, m = 1.0]", 20},
    {"Foucault at the pole, swing across w", "vector w, r0, v0", foucault,
     "[w = [0, 0, 72921/10^9], w0 = 3/8, r0 = [3, 0, 0], v0 = [0, 0, 0]]",
     "[w = [0, 0, 7.2921e-5], w0 = 0.375, r0 = [3, 0, 0], v0 = [0, 0, 0]]", 86400},
    {"Foucault with w0 = 0 (general form singular)", "vector w, r0, v0", foucault,
     "[w = [0, 0, 1/10], w0 = 0, r0 = [3, 0, 0], v0 = [0, 1/10, 0]]",
     "[w = [0, 0, 0.1], w0 = 0.0, r0 = [3.0, 0, 0], v0 = [0, 0.1, 0]]", 100},
    {"control: gravity, general directions", "vector w, g, r0, v0", centrifugal,
     "[w = [1/10, 2/10, 2/10], g = [0, 0, -981/100], r0 = [1, 0, 0], v0 = [0, 1, 0]]",
     "[w = [0.1, 0.2, 0.2], g = [0, 0, -9.81], r0 = [1.0, 0, 0], v0 = [0, 1.0, 0]]", 10},
};
constexpr int n_scenes = sizeof(scenes) / sizeof(scenes[0]);

struct prepared {
    std::ostringstream out, err;
    lang::session s{out, err};
    std::shared_ptr<const mechanics::cauchy_problem> P;
    mechanics::parameter_values values;
    ex minimal, general;  // the scene's closed forms ([x, y, z] in t); general empty when singular
    ex general_symbolic;  // solve(P)
    lang::data_values data;
    std::string report;
    prepared(const scene_spec& sc, bool floats) {
        s.evaluate(sc.declarations);
        const lang::value p = s.evaluate(std::string("P := ") + sc.problem);
        P = std::make_shared<const mechanics::cauchy_problem>(p.as_problem());
        lang::builtin b;
        b.name = "bench";
        data = lang::read_values(s.evaluate(floats ? sc.float_values : sc.exact_values), b, 0);
        values = {data.vectors, data.scalars};
        const mechanics::scene_solution m = mechanics::solve(*P, values);
        minimal = m.x;
        report = m.model.report();
        general_symbolic = mechanics::solve(*P);
        try {
            general = mechanics::put_values(general_symbolic, values);
        } catch (const symrep::error&) {
            general = ex();
        }
    }
};

// Benchmark argument k: scene k % n_scenes, with exact values (k < n_scenes) or floats.
prepared& scene(int k) {
    static std::vector<std::unique_ptr<prepared>> cache(2 * n_scenes);
    if (!cache[k]) cache[k] = std::make_unique<prepared>(scenes[k % n_scenes], k >= n_scenes);
    return *cache[k];
}
std::string label(int k) {
    return std::string(scenes[k % n_scenes].label) + (k >= n_scenes ? " [floats]" : " [exact]");
}

std::string short_model(const prepared& p) {
    const std::string first = p.report.substr(0, p.report.find('\n'));
    const std::size_t a = first.find("R[X]/("), b = first.find(')', a);
    return a == std::string::npos ? first : first.substr(a, b - a + 1);
}

void BM_MinimalModel_Derive(benchmark::State& state) {
    prepared& p = scene(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(mechanics::solve(*p.P, p.values));
    state.SetLabel(label(int(state.range(0))) + "; " + short_model(p));
}
BENCHMARK(BM_MinimalModel_Derive)->DenseRange(0, 2 * n_scenes - 1)->Unit(benchmark::kMillisecond);

void BM_GeneralModel_Derive(benchmark::State& state) {
    prepared& p = scene(int(state.range(0)));
    if (p.general.is_zero() && !p.minimal.is_zero()) {
        state.SkipWithError("the general form is singular at the values (eval takes a limit)");
        return;
    }
    for (auto _ : state) benchmark::DoNotOptimize(mechanics::put_values(mechanics::solve(*p.P), p.values));
    state.SetLabel(label(int(state.range(0))));
}
BENCHMARK(BM_GeneralModel_Derive)->DenseRange(0, 2 * n_scenes - 1)->Unit(benchmark::kMillisecond);

// Compiles a closed form, runs it on 1024 points of [0, T], and measures its
// error against the exact value (40 digits) at 64 of them.
void evaluate(benchmark::State& state, const ex& form, const prepared& p) {
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(p.P->t);
    const double T = scenes[state.range(0) % n_scenes].T;
    const auto c0 = std::chrono::steady_clock::now();
    const num::compiled_function cf = num::compile(form, {t});
    const double compile_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
    std::vector<double> in(1024), out(3 * 1024);
    for (int i = 0; i < 1024; ++i) in[i] = T * i / 1023;
    // accuracy against the exact minimal form (equal to the general one) at 40 digits
    const std::vector<ex> exact = num::flatten_outputs(p.minimal);
    double max_err = 0, scale = 0;
    for (int i = 0; i < 1024; i += 16) {
        const std::vector<long double> ref = num::reference_eval(exact, {t}, {in[i]}, 40);
        const std::vector<double> got = cf({in[i]});
        for (int k = 0; k < 3; ++k) {
            scale = std::max(scale, double(std::fabs(ref[k])));
            max_err = std::max(max_err, double(std::fabs((long double)got[k] - ref[k])));
        }
    }
    for (auto _ : state) {
        cf.eval_many(in.data(), out.data(), 1024);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * 1024);
    state.counters["instructions"] = double(cf.n_instructions());
    state.counters["compile_us"] = compile_s * 1e6;
    state.counters["max_rel_err"] = scale > 0 ? max_err / scale : max_err;
    state.SetLabel(label(int(state.range(0))));
}

void BM_MinimalModel_Eval(benchmark::State& state) {
    const prepared& p = scene(int(state.range(0)));
    evaluate(state, p.minimal, p);
}
BENCHMARK(BM_MinimalModel_Eval)->DenseRange(0, 2 * n_scenes - 1);

// Where the general form is singular at the values (w0 = 0), it has no compiled
// form: eval takes its limit at every point (lang/values.h, a series at each time).
void evaluate_by_limits(benchmark::State& state, const prepared& p) {
    const double T = scenes[state.range(0) % n_scenes].T;
    int i = 0;
    for (auto _ : state) {
        lang::data_values d = p.data;
        d.scalars[p.P->t] = GiNaC::numeric(T * (i++ % 1024) / 1023);
        benchmark::DoNotOptimize(GiNaC::evalf(lang::put_values_limit(p.general_symbolic, d)));
    }
    state.SetItemsProcessed(state.iterations());
    state.SetLabel(label(int(state.range(0))) + ": general form singular, eval's limit per point");
}

void BM_GeneralModel_Eval(benchmark::State& state) {
    const prepared& p = scene(int(state.range(0)));
    if (p.general.is_zero() && !p.minimal.is_zero()) {
        evaluate_by_limits(state, p);
        return;
    }
    if (int(state.range(0)) < n_scenes && !equal(p.general, p.minimal)) {
        state.SkipWithError("the general and the minimal closed forms differ");
        return;
    }
    evaluate(state, p.general, p);
}
BENCHMARK(BM_GeneralModel_Eval)->DenseRange(0, 2 * n_scenes - 1);

}  // namespace
