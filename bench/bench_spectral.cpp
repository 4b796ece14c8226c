// Benchmarks of numeric/spectral_evaluator.h against the compiled double
// program (numeric/evaluator.h) on the closed forms of the work-precision
// scenes (docs/performance.md, "Full accuracy at compiled speed"): the solver's
// form of each problem with the scene's numbers in, 200 times spread over the
// scene's span, one trajectory per iteration (eval_many). Counter: seconds per point.
//
//   ./build/symrep_bench --benchmark_filter=Spectral --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true   (one line)
#include <benchmark/benchmark.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "lang/values.h"
#include "numeric/evaluator.h"
#include "numeric/spectral_evaluator.h"

using namespace symrep;
using GiNaC::ex;

namespace {

struct scene {
    std::vector<ex> outputs;
    ex t;
    std::vector<double> times;
};

ex symbol_in(const ex& e, const std::string& name) {
    for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i)
        if (GiNaC::is_a<GiNaC::symbol>(*i) && GiNaC::ex_to<GiNaC::symbol>(*i).get_name() == name) return *i;
    return 0;
}

scene make_scene(const std::string& script, double span) {
    std::ostringstream out, err;
    lang::session S(out, err);
    const ex closed_form = S.evaluate(script).as_ex();
    scene s;
    s.outputs = lang::components(closed_form);
    s.t = symbol_in(closed_form, "t");
    for (int k = 1; k <= 200; ++k) s.times.push_back(span * (k - 0.5 * ((k * 7) % 5) / 5.0) / 200);
    return s;
}

const scene& scene_of(int id) {
    static const std::vector<scene> scenes = {
        make_scene("vector w, r0, v0\npositive w0\n"
                   "s := solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))\n"
                   "subs(s, [w = 7.2921e-5*[cos(48.85*pi/180), 0, sin(48.85*pi/180)], w0 = sqrt(9.81/67), "
                   "r0 = [3, 0, 0], v0 = [0, 0, 0]])",
                   86400),
        make_scene("vector w, g, r0, v0\n"
                   "s := solve(ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0))\n"
                   "subs(s, [w = 7.2921e-5*[cos(pi/4), 0, sin(pi/4)], g = [0, 0, -9.81], r0 = [0, 0, 100], "
                   "v0 = [10, 5, 20]])",
                   60),
        make_scene("vector E, B, v0, r0\npositive m\n"
                   "s := solve(ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0))\n"
                   "subs(s, [q = 1.602176634e-19, m = 1.67262192e-27, B = [0, 0, 1], E = [1000*sin(pi/3), 0, "
                   "1000*cos(pi/3)], v0 = [1e5, 0, 0], r0 = [0, 0, 0]])",
                   6.56e-5),
    };
    return scenes[static_cast<std::size_t>(id)];
}

template <class F>
void run(benchmark::State& state, const F& f, const scene& s) {
    std::vector<double> out(s.times.size() * s.outputs.size());
    for (auto _ : state) {
        f.eval_many(s.times.data(), out.data(), s.times.size());
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["per_point"] = benchmark::Counter(static_cast<double>(s.times.size()),
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

void BM_Spectral_Compiled(benchmark::State& state) {
    const scene& s = scene_of(static_cast<int>(state.range(0)));
    const num::compiled_function f = num::compile(s.outputs, {s.t});
    run(state, f, s);
}

void BM_Spectral_Spectral(benchmark::State& state) {
    const scene& s = scene_of(static_cast<int>(state.range(0)));
    const num::spectral_function f(s.outputs, s.t);
    run(state, f, s);
}

}  // namespace

// 0: Foucault at Paris, 1 day; 1: gravity with Coriolis, 60 s; 2: proton in E and B, 1000 gyrations
BENCHMARK(BM_Spectral_Compiled)->DenseRange(0, 2);
BENCHMARK(BM_Spectral_Spectral)->DenseRange(0, 2);
