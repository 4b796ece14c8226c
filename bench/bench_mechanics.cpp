// Benchmarks of the Ch. VI solver as a user meets it: the time to derive each
// application's closed form from its problem (ode(...) read, reduced to the
// algebra of K = w x, solved, recombined), with a general axis (w abstract), and
// the time to evaluate a derived solution per point against a hand-written C++
// closed form of the same solution (VI.1.79) and against GiNaC subs + evalf.
// Run: ./build/symrep_bench --benchmark_filter=Mechanics
#include <chrono>
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include "lang/interpreter.h"
#include "mechanics/cauchy_problem.h"
#include "mechanics/solution_witness.h"
#include "numeric/evaluator.h"
#include "vector/vector.h"

using namespace symrep;
using GiNaC::ex;

namespace {

struct application {
    const char* declarations;
    const char* problem;
};

// The thesis's problems (VI.1.26-28, 50, 56, 58 for v and r, 68, VI.2.93), general axis.
const application apps[] = {
    {"vector w, a, b, r0", "ode(r' + w x r = cos(2*t)*a + t*exp(-t)*b, r(0) = r0)"},
    {"vector w, g, r0, v0", "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)"},
    {"vector w, g, r0, v0", "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)"},
    {"vector E, B, v0; positive m", "ode(m*v' = q*(v x B + E), v(0) = v0)"},
    {"vector E, B, v0, r0; positive m", "ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)"},
    {"vector w, r0, v0; positive w0", "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)"},
    {"vector w, r0, v0; positive w0", "ode(r'' + 2*w x r' + w0^2*r = 0, r(0) = r0, r'(0) = v0)"},
};
const char* const app_names[] = {"VI.1.28_first_order", "VI.1.50_coriolis", "VI.1.56_centrifugal",
                                 "VI.1.58_charge_velocity", "VI.1.58_charge_position", "VI.1.68_foucault",
                                 "VI.2.93_reduced_foucault"};

void BM_Mechanics_Derive(benchmark::State& state) {
    const application& a = apps[state.range(0)];
    std::ostringstream out, err;
    lang::session s(out, err);
    s.evaluate(a.declarations);
    const std::string stmt = std::string("solve(") + a.problem + ")";
    for (auto _ : state) benchmark::DoNotOptimize(s.evaluate(stmt));
    state.SetLabel(app_names[state.range(0)]);
}
BENCHMARK(BM_Mechanics_Derive)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

// Issue 15.1: the Foucault operator with quasi-polynomial forcings of growing degree; the
// counter `chars` is the length of the printed result.
const char* const forcings[] = {"g",
                                "t^3*g",
                                "t^6*g",
                                "(1 + t + t^2 + t^3 + t^4 + t^5 + t^6)*g",
                                "exp(-k*t)*g",
                                "t*exp(-k*t)*g",
                                "t^2*exp(-k*t)*g",
                                "t^3*exp(-k*t)*g",
                                "t*exp(-t)*cos(2*t)*g"};

void BM_Mechanics_DeriveForced(benchmark::State& state) {
    std::ostringstream out, err;
    lang::session s(out, err);
    s.evaluate("vector w, g, r0, v0; positive w0");
    const std::string stmt = std::string("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = ") +
                             forcings[state.range(0)] + ", r(0) = r0, r'(0) = v0))";
    lang::value v;
    for (auto _ : state) benchmark::DoNotOptimize(v = s.evaluate(stmt));
    std::ostringstream shown;
    shown << v.as_ex();
    state.counters["chars"] = double(shown.str().size());
    state.SetLabel(forcings[state.range(0)]);
}
BENCHMARK(BM_Mechanics_DeriveForced)->DenseRange(0, 8)->Unit(benchmark::kMillisecond);

// The same forcings on the Coriolis operator r'' + 2 w x r' = f(t) g, where Maxima's desolve has a
// closed form to compare with (bench/work_precision/maxima_derive.py; docs/performance.md).
void BM_Mechanics_DeriveForcedCoriolis(benchmark::State& state) {
    std::ostringstream out, err;
    lang::session s(out, err);
    s.evaluate("vector w, g, r0, v0");
    const std::string stmt = std::string("solve(ode(r'' + 2*w x r' = ") + forcings[state.range(0)] +
                             ", r(0) = r0, r'(0) = v0))";
    lang::value v;
    for (auto _ : state) benchmark::DoNotOptimize(v = s.evaluate(stmt));
    state.SetLabel(forcings[state.range(0)]);
}
BENCHMARK(BM_Mechanics_DeriveForcedCoriolis)->DenseRange(0, 8)->Unit(benchmark::kMillisecond);

// Issue 15.2: the exact check check(P, solve(P)), the solution derived once outside the loop; the
// counter `x_solve` is the check's time over the derivation's, both measured here.
void check_over_solve(benchmark::State& state, const std::string& declarations, const std::string& problem,
                      const std::string& label) {
    std::ostringstream out, err;
    lang::session s(out, err);
    s.evaluate(declarations);
    s.evaluate("P := " + problem);
    const auto t0 = std::chrono::steady_clock::now();
    s.evaluate("sol := solve(P)");
    const double solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double check_s = 0;
    long n = 0;
    for (auto _ : state) {
        const auto c0 = std::chrono::steady_clock::now();
        const lang::value v = s.evaluate("check(P, sol)");
        check_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count();
        ++n;
        if (!v.as_bool()) state.SkipWithError("check(P, sol) is not true");
    }
    state.counters["x_solve"] = check_s / double(n) / solve_s;
    state.SetLabel(label);
}

// ... on the forced problems above
void BM_Mechanics_CheckForced(benchmark::State& state) {
    check_over_solve(state, "vector w, g, r0, v0; positive w0",
                     std::string("ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = ") + forcings[state.range(0)] +
                         ", r(0) = r0, r'(0) = v0)",
                     forcings[state.range(0)]);
}
BENCHMARK(BM_Mechanics_CheckForced)->DenseRange(0, 8)->Unit(benchmark::kMillisecond);

// ... on the thesis's problems of BM_Mechanics_Derive
void BM_Mechanics_Check(benchmark::State& state) {
    const application& a = apps[state.range(0)];
    check_over_solve(state, a.declarations, a.problem, app_names[state.range(0)]);
}
BENCHMARK(BM_Mechanics_Check)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

// Issue 27: the cost of solve's witness (mechanics/solution_witness.h), the residual at one
// point before solve returns. One problem per row: the thesis's problems above, forcings of
// BM_Mechanics_DeriveForced, and the fixed-axis paths (closed form, integral objects, nested
// integrals by a velocity, a turning closed form). Each iteration derives with
// solve_unwitnessed and then runs the witness, timed apart; the counters are the witness's
// time over the derivation's (`x_solve`) and its milliseconds (`witness_ms`).
const application witness_apps[] = {
    apps[0],
    apps[5],
    apps[6],
    {"vector w, g, r0, v0; positive w0",
     "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = t*exp(-t)*cos(2*t)*g, r(0) = r0, r'(0) = v0)"},
    {"vector u, r0, v0; positive w0; w := (a + b*sin(c*t))*u",
     "ode(r'' + 2*w x r' + w' x r + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)"},
    {"vector r0, v0; w := (1/2 + t)*[0, 0, 1]",
     "ode(r'' + 2*w x r' + w' x r + w x (w x r) = cos(t)*[1, 0, 0], r(0) = r0, r'(0) = v0)"},
    {"vector n, v0, E; positive m", "ode(m*v' = q*(v x ((B0 + B1*cos(f*t))*n) + E), v(0) = v0)"},
    {"vector r0, v0, E; positive m", "ode(m*r'' = q*(r' x ((1 + t)*[0, 0, 1]) + E), r(0) = r0, r'(0) = v0)"},
    {"vector r0, v0; w := [a*sin(c*t), a*cos(c*t), b]",
     "ode(r'' + 2*w x r' + w' x r + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)"},
};
const char* const witness_names[] = {"VI.1.28_first_order", "VI.1.68_foucault", "VI.2.93_reduced_foucault",
                                     "foucault_t_e^-t_cos2t", "VI.2.70_varying_rate", "fixed_axis_force_across",
                                     "VI.2.62_E_across_B(t)", "VI.2.51_position_nested", "VI.3_precession"};

void BM_Mechanics_Witness(benchmark::State& state) {
    const application& a = witness_apps[state.range(0)];
    std::ostringstream out, err;
    lang::session s(out, err);
    s.evaluate(a.declarations);
    const lang::value P = s.evaluate(a.problem);
    double solve_s = 0, witness_s = 0;
    long n = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const ex x = mechanics::solve_unwitnessed(P.as_problem());
        const auto t1 = std::chrono::steady_clock::now();
        const mechanics::witness_report w = mechanics::witness(P.as_problem(), x);
        const auto t2 = std::chrono::steady_clock::now();
        solve_s += std::chrono::duration<double>(t1 - t0).count();
        witness_s += std::chrono::duration<double>(t2 - t1).count();
        ++n;
        if (w.seen_nonzero) state.SkipWithError("the witness sees the solution wrong");
    }
    state.counters["x_solve"] = witness_s / solve_s;
    state.counters["witness_ms"] = 1e3 * witness_s / double(n);
    state.SetLabel(witness_names[state.range(0)]);
}
BENCHMARK(BM_Mechanics_Witness)->DenseRange(0, 8)->Unit(benchmark::kMillisecond);

// The Foucault solution at Paris, derived by symrep, in components with the
// parameters put in; one input t.
struct foucault_at_paris {
    GiNaC::realsymbol t{"t"};
    std::vector<ex> components;
    foucault_at_paris() {
        std::ostringstream out, err;
        lang::session s(out, err);
        s.evaluate("vector w, r0, v0; positive w0");
        const ex sol = s.evaluate("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))")
                           .as_ex();
        const double phi = 48.85 * M_PI / 180;
        std::map<ex, ex, GiNaC::ex_is_less> m{
            {s.symbol("w"), vector_literal(7.2921e-5 * std::cos(phi), 0, 7.2921e-5 * std::sin(phi))},
            {s.symbol("r0"), vector_literal(3, 0, 0)},
            {s.symbol("v0"), vector_literal(0, 0, 0)}};
        const ex c = subs_components(sol, m).subs(GiNaC::lst{s.symbol("w0") == std::sqrt(9.81 / 67),
                                                              s.symbol("t") == t});
        for (unsigned i = 0; i < 3; ++i) components.push_back(c.op(i));
    }
};

// (VI.1.79) by hand: r = psi - sin(W t)/W w x psi + (1 - cos(W t))/W^2 w x (w x psi).
struct hand_written {
    std::array<double, 3> w, r0{3, 0, 0}, v0{0, 0, 0};
    double W, w0 = std::sqrt(9.81 / 67);
    hand_written() {
        const double phi = 48.85 * M_PI / 180;
        w = {7.2921e-5 * std::cos(phi), 0, 7.2921e-5 * std::sin(phi)};
        W = 7.2921e-5;
    }
    static std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    std::array<double, 3> operator()(double t) const {
        const auto wr = cross(w, r0);
        const double c0 = std::cos(w0 * t), s0 = std::sin(w0 * t);
        std::array<double, 3> psi;
        for (int i = 0; i < 3; ++i) psi[i] = r0[i] * c0 + (v0[i] + wr[i]) / w0 * s0;
        const auto a = cross(w, psi), b = cross(w, a);
        const double s = std::sin(W * t) / W, c = (1 - std::cos(W * t)) / (W * W);
        return {psi[0] - s * a[0] + c * b[0], psi[1] - s * a[1] + c * b[1], psi[2] - s * a[2] + c * b[2]};
    }
};

void BM_Mechanics_Foucault_CompiledMany(benchmark::State& state) {
    foucault_at_paris f;
    const num::compiled_function cf = num::compile(f.components, {f.t});
    std::vector<double> in(1024), out(3 * 1024);
    for (int i = 0; i < 1024; ++i) in[i] = 84.375 * i;
    for (auto _ : state) {
        cf.eval_many(in.data(), out.data(), 1024);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * 1024);
    state.SetLabel(std::to_string(cf.n_instructions()) + " instructions");
}
BENCHMARK(BM_Mechanics_Foucault_CompiledMany);

void BM_Mechanics_Foucault_HandWrittenMany(benchmark::State& state) {
    const hand_written h;
    std::vector<double> out(3 * 1024);
    for (auto _ : state) {
        for (int i = 0; i < 1024; ++i) {
            const auto r = h(84.375 * i);
            out[3 * i] = r[0];
            out[3 * i + 1] = r[1];
            out[3 * i + 2] = r[2];
        }
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations() * 1024);
}
BENCHMARK(BM_Mechanics_Foucault_HandWrittenMany);

void BM_Mechanics_Foucault_GiNaC(benchmark::State& state) {
    foucault_at_paris f;
    double t = 3600;
    for (auto _ : state) {
        for (const ex& c : f.components) benchmark::DoNotOptimize(GiNaC::evalf(c.subs(f.t == t)));
        t += 1;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Mechanics_Foucault_GiNaC);

}  // namespace
