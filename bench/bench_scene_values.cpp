// Benchmarks of scenes whose values are the exact rationals of binary64 numbers (0.1 written
// 3602879701896397/36028797018963968, as a program that prints exact doubles writes it;
// issue 27), against the general path (docs/performance.md, "Scenes with the exact rationals
// of doubles"):
//   BinaryScene_Solve/k:   solve(P, values) through the library (classify, derive with the
//                          exact values in, values put in);
//   BinaryScene_General/k: solve(P) (the general model), the values put in and the result
//                          evaluated at one t with 17 digits: what solve(P) + eval costs.
// The radicals and logarithms of rationals are written over primes below 2^16; a 100-digit
// numerator of such a value cost 65 536 trial divisions at every look before (13 to more
// than 120 s per scene), and a zero pivot sqrt(N1) c1 - c2 sqrt(N2) with N2 = N1 q^2 (q of
// primes above 2^16) was refused. The setup checks that the scene's solution equals the
// general one with the values put in at 60 digits (tests/test_scene_values.cpp asserts it).
// Run: ./build/symrep_bench --benchmark_filter=BinaryScene_ --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "lang/values.h"
#include "mechanics/scene.h"
#include "vector/vector.h"

using namespace symrep;
using GiNaC::ex;

namespace {

struct binary_scene_spec {
    const char* label;
    const char* declarations;
    const char* problem;
    const char* values;
};

const char* const foucault_problem = "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)";

// Earth's rate 7.2921e-5 rad/s at latitude 48.6 (0.66, 0.75 of it), g = 9.81, w0 = sqrt(9.81/67).
const binary_scene_spec binary_scenes[] = {
    {"README Foucault, w = [0, 0, 0.1]", "vector w, r0, v0; positive w0", foucault_problem,
     "[w = [0, 0, 3602879701896397/36028797018963968], w0 = 1/2, r0 = [3, 0, 0], v0 = [0, 0, 0]]"},
    {"Foucault at latitude 48.6", "vector w, r0, v0; positive w0", foucault_problem,
     "[w = [0, 887802316235323/18446744073709551616, 4035465073796923/73786976294838206464], "
     "w0 = 6893136334659029/18014398509481984, r0 = [3, 0, 0], v0 = [0, 0, 0]]"},
    {"Foucault, general directions", "vector w, r0, v0; positive w0", foucault_problem,
     "[w = [7493989779944505/576460752303423488, 1188950301625811/18014398509481984, "
     "5404319552844595/72057594037927936], w0 = 3332663724254167/9007199254740992, "
     "r0 = [3, 3602879701896397/36028797018963968, 0], v0 = [0, 3602879701896397/18014398509481984, "
     "5764607523034235/576460752303423488]]"},
    {"gravity, rotating frame", "vector w, g, r0, v0", "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)",
     "[w = [0, 887802316235323/18446744073709551616, 4035465073796923/73786976294838206464], "
     "g = [0, 0, -5522539043063071/562949953421312], r0 = [0, 0, 100], v0 = [10, 0, 0]]"},
    {"Coriolis only", "vector w, g, r0, v0", "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)",
     "[w = [0, 887802316235323/18446744073709551616, 4035465073796923/73786976294838206464], "
     "g = [0, 0, -5522539043063071/562949953421312], r0 = [0, 0, 100], v0 = [10, 0, 0]]"},
    {"charge velocity in E and B", "vector E, B, v0; positive m", "ode(m*v' = q*(v x B + E), v(0) = v0)",
     "[B = [5404319552844595/18014398509481984, 3602879701896397/36028797018963968, "
     "5404319552844595/4503599627370496], E = [1/2, 3602879701896397/18014398509481984, "
     "3602879701896397/36028797018963968], v0 = [3/2, 0, 5404319552844595/18014398509481984], "
     "q = 3602879701896397/2251799813685248, m = 8106479329266893/9007199254740992]"},
    {"charge position in E and B (was refused)", "vector E, B, v0, r0; positive m",
     "ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)",
     "[B = [5404319552844595/18014398509481984, 3602879701896397/36028797018963968, "
     "5404319552844595/4503599627370496], E = [1/2, 3602879701896397/18014398509481984, "
     "3602879701896397/36028797018963968], r0 = [3602879701896397/36028797018963968, 0, 0], "
     "v0 = [3/2, 0, 5404319552844595/18014398509481984], q = 3602879701896397/2251799813685248, "
     "m = 8106479329266893/9007199254740992]"},
};
constexpr int n_binary_scenes = sizeof(binary_scenes) / sizeof(binary_scenes[0]);

struct binary_prepared {
    std::ostringstream out, err;
    lang::session s{out, err};
    std::shared_ptr<const mechanics::cauchy_problem> P;
    mechanics::parameter_values values;
    lang::data_values data;
    explicit binary_prepared(const binary_scene_spec& sc) {
        s.evaluate(sc.declarations);
        const lang::value p = s.evaluate(std::string("P := ") + sc.problem);
        P = std::make_shared<const mechanics::cauchy_problem>(p.as_problem());
        lang::builtin b;
        b.name = "bench";
        data = lang::read_values(s.evaluate(sc.values), b, 0);
        values = {data.vectors, data.scalars};
        // the scene's solution is the general one with the values put in (60 digits at t = 3)
        const ex x = mechanics::solve(*P, values).x, g = mechanics::put_values(mechanics::solve(*P), values);
        const long saved = GiNaC::Digits;
        GiNaC::Digits = 60;
        const ex d = GiNaC::evalf((x - g).evalm().subs(P->t == 3)), size = GiNaC::evalf(g.subs(P->t == 3));
        GiNaC::Digits = saved;
        // exactly 0 (GiNaC cancels the two forms), or 0 to 1e-30 of the size component by component
        bool equal = d.is_zero() || (GiNaC::is_a<GiNaC::matrix>(d) && GiNaC::is_a<GiNaC::matrix>(size) &&
                                     d.nops() == size.nops());
        for (std::size_t i = 0; equal && !d.is_zero() && i < d.nops(); ++i)
            equal = GiNaC::is_a<GiNaC::numeric>(d.op(i)) && GiNaC::is_a<GiNaC::numeric>(size.op(i)) &&
                    GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(d.op(i))) <=
                        GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(size.op(i))) * GiNaC::numeric("1e-30") +
                            GiNaC::numeric("1e-40");
        if (!equal)
        {
            std::ostringstream why;
            why << "bench: the scene's solution differs from the general one: " << sc.label << ": " << d << " against "
                << size;
            throw std::runtime_error(why.str());
        }
    }
};

binary_prepared& binary_scene(int k) {
    static std::vector<std::unique_ptr<binary_prepared>> cache(n_binary_scenes);
    if (!cache[k]) cache[k] = std::make_unique<binary_prepared>(binary_scenes[k]);
    return *cache[k];
}

void BM_BinaryScene_Solve(benchmark::State& state) {
    binary_prepared& p = binary_scene(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(mechanics::solve(*p.P, p.values));
    state.SetLabel(binary_scenes[state.range(0)].label);
}
BENCHMARK(BM_BinaryScene_Solve)->DenseRange(0, n_binary_scenes - 1)->Unit(benchmark::kMillisecond);

void BM_BinaryScene_General(benchmark::State& state) {
    binary_prepared& p = binary_scene(int(state.range(0)));
    for (auto _ : state) {
        const ex g = mechanics::put_values(mechanics::solve(*p.P), p.values);
        benchmark::DoNotOptimize(GiNaC::evalf(g.subs(p.P->t == 3)));
    }
    state.SetLabel(binary_scenes[state.range(0)].label);
}
BENCHMARK(BM_BinaryScene_General)->DenseRange(0, n_binary_scenes - 1)->Unit(benchmark::kMillisecond);

}  // namespace
