// The rotation tensor Q' = -W Q (VI.3.117) of an arbitrary w(t): error against
// cost for the sixth-order Magnus method on SO(3) (numeric/rotation_tensor.h)
// and for Boost.Odeint on the nine components (rkf78, dopri5), and the
// reduction r = Q psi of Kepler's problem in a rotating frame (Thm VI.3.2.1)
// against direct integration of the rotating-frame ODE.
//
// w(t) = (0.7 sin 1.3t, 0.4 cos 2.1t, 0.5), t in [0, 200] (about 25 turns).
// Error: Frobenius norm of Q - Q_ref at t = 200, Q_ref the Magnus method at
// rel_tol 1e-15 (checked against rkf78 at 1e-15 to 1e-12); Kepler: |r - r_ref|/|r_ref|
// against the reduction at 1e-15. The counters `error`, `w_evals` and
// `orthogonality` (|Q^T Q - I|) are the chart's data:
//   build/symrep_bench --benchmark_filter=RotationTensor --benchmark_format=csv > rt.csv
//   bash bench/plot_rotation_tensor.sh rt.csv        (docs/figures/rotation_tensor_wp.png)
// RelativeMotion_* (LVLH of a circular target at 7000 km, separations 1 m to
// 100 km, 1 and 10 orbits): the cost of the exact relative motion and the
// relative error of the Clohessy-Wiltshire model against it (counter
// `cw_relative_error`; docs/figures/relative_motion_cw.png).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "mechanics/relative_motion.h"
#include "mechanics/rotating_frame.h"
#include "numeric/integrate.h"
#include "numeric/rotation_tensor.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using namespace symrep;

const double T = 200.0;

Vector3d omega(double t) { return Vector3d(0.7 * std::sin(1.3 * t), 0.4 * std::cos(2.1 * t), 0.5); }
Vector3d omega_dot(double t) { return Vector3d(0.7 * 1.3 * std::cos(1.3 * t), -0.4 * 2.1 * std::sin(2.1 * t), 0.0); }

const Matrix3d& reference() {
    static const Matrix3d Q = [] {
        num::rotation_tensor_options o;
        o.rel_tol = 1e-15;
        return num::rotation_tensor(omega, {T}, o).Q[0];
    }();
    return Q;
}

double tolerance_of(const benchmark::State& state) { return std::pow(10.0, -double(state.range(0))); }

void RotationTensor_Magnus6(benchmark::State& state) {
    num::rotation_tensor_options o;
    o.rel_tol = tolerance_of(state);
    num::rotation_tensor_result r;
    for (auto _ : state) {
        r = num::rotation_tensor(omega, {T}, o);
        benchmark::DoNotOptimize(std::as_const(r));
    }
    state.counters["error"] = (r.Q[0] - reference()).norm();
    state.counters["w_evals"] = double(r.evaluations);
    state.counters["orthogonality"] = (r.Q[0].transpose() * r.Q[0] - Matrix3d::Identity()).norm();
}
BENCHMARK(RotationTensor_Magnus6)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);

void nine_components(benchmark::State& state, num::stepper_kind kind) {
    std::size_t evals = 0;
    const num::rhs_function rhs = [&](double s, const double* y, double* dy) {
        ++evals;
        Eigen::Map<const Matrix3d> Q(y);
        Eigen::Map<Matrix3d> dQ(dy);
        dQ = -num::skew(omega(s)) * Q;
    };
    num::integration_options o;
    o.stepper = kind;
    o.rel_tol = o.abs_tol = tolerance_of(state);
    const Matrix3d I = Matrix3d::Identity();
    Matrix3d Q;
    std::size_t per_run = 0;
    for (auto _ : state) {
        evals = 0;
        const num::integration_result r =
            num::integrate(rhs, 0.0, std::vector<double>(I.data(), I.data() + 9), {T}, o);
        for (int i = 0; i < 9; ++i) Q.data()[i] = r.states(0, i);
        per_run = evals;
    }
    state.counters["error"] = (Q - reference()).norm();
    state.counters["w_evals"] = double(per_run);
    state.counters["orthogonality"] = (Q.transpose() * Q - Matrix3d::Identity()).norm();
}
void RotationTensor_Odeint9_rkf78(benchmark::State& s) { nine_components(s, num::stepper_kind::rkf78); }
void RotationTensor_Odeint9_dopri5(benchmark::State& s) { nine_components(s, num::stepper_kind::dopri5); }
BENCHMARK(RotationTensor_Odeint9_rkf78)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(RotationTensor_Odeint9_dopri5)->DenseRange(4, 12, 2)->Unit(benchmark::kMicrosecond);

// Kepler in the rotating frame (VI.3.153): the reduction against the ODE as stated.
mechanics::rotating_frame_problem kepler_problem() {
    mechanics::rotating_frame_problem P;
    P.w = omega;
    P.w_dot = omega_dot;
    P.field = mechanics::central_field::kepler(1.0);
    P.r0 = Vector3d(1.0, 0.1, -0.2);
    P.v0 = Vector3d(0.05, 0.6, 0.1);
    return P;
}
const Vector3d& kepler_reference() {
    static const Vector3d r = [] {
        num::rotation_tensor_options o;
        o.rel_tol = 1e-15;
        return mechanics::solve_by_reduction(kepler_problem(), {T}, o)[0].r;
    }();
    return r;
}

void RotatingKepler_Reduction(benchmark::State& state) {
    const mechanics::rotating_frame_problem P = kepler_problem();
    num::rotation_tensor_options o;
    o.rel_tol = tolerance_of(state);
    Vector3d r;
    for (auto _ : state) {
        r = mechanics::solve_by_reduction(P, {T}, o)[0].r;
        benchmark::DoNotOptimize(std::as_const(r));
    }
    state.counters["error"] = (r - kepler_reference()).norm() / kepler_reference().norm();
}
BENCHMARK(RotatingKepler_Reduction)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);

template <num::stepper_kind K>
void RotatingKepler_Odeint(benchmark::State& state) {
    const mechanics::rotating_frame_problem P = kepler_problem();
    num::integration_options o;
    o.stepper = K;
    o.rel_tol = o.abs_tol = tolerance_of(state);
    Vector3d r;
    for (auto _ : state) {
        r = mechanics::integrate_rotating_frame(P, {T}, o)[0].r;
        benchmark::DoNotOptimize(std::as_const(r));
    }
    state.counters["error"] = (r - kepler_reference()).norm() / kepler_reference().norm();
}
void RotatingKepler_Odeint_rkf78(benchmark::State& s) { RotatingKepler_Odeint<num::stepper_kind::rkf78>(s); }
void RotatingKepler_Odeint_dopri5(benchmark::State& s) { RotatingKepler_Odeint<num::stepper_kind::dopri5>(s); }
void RotatingKepler_Odeint_bulirsch_stoer(benchmark::State& s) {
    RotatingKepler_Odeint<num::stepper_kind::bulirsch_stoer>(s);
}
BENCHMARK(RotatingKepler_Odeint_rkf78)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(RotatingKepler_Odeint_dopri5)->DenseRange(4, 12, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(RotatingKepler_Odeint_bulirsch_stoer)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
// rk4 has no error control: range(0) = log2 of the steps per unit time
void RotatingKepler_Odeint_rk4(benchmark::State& state) {
    const mechanics::rotating_frame_problem P = kepler_problem();
    num::integration_options o;
    o.stepper = num::stepper_kind::rk4;
    o.fixed_step = std::ldexp(1.0, -int(state.range(0)));
    Vector3d r;
    for (auto _ : state) {
        r = mechanics::integrate_rotating_frame(P, {T}, o)[0].r;
        benchmark::DoNotOptimize(std::as_const(r));
    }
    state.counters["error"] = (r - kepler_reference()).norm() / kepler_reference().norm();
}
BENCHMARK(RotatingKepler_Odeint_rk4)->DenseRange(4, 10, 2)->Unit(benchmark::kMicrosecond);

// (Thm VI.3.2.2) drift of the energy integral E (VI.3.140) over a long time: the reduction
// keeps it to rounding (psi exactly on its conic, Q orthogonal), an integrator lets it drift.
// range(0) = the time in units of 100.
template <bool Reduction>
void RotatingKepler_EnergyDrift(benchmark::State& state) {
    const mechanics::rotating_frame_problem P = kepler_problem();
    const double t_end = 100.0 * double(state.range(0));
    mechanics::rotating_frame_state s;
    for (auto _ : state) {
        if constexpr (Reduction) {
            s = mechanics::solve_by_reduction(P, {t_end})[0];
        } else {
            num::integration_options o;
            o.rel_tol = o.abs_tol = 1e-12;
            s = mechanics::integrate_rotating_frame(P, {t_end}, o)[0];
        }
        benchmark::DoNotOptimize(std::as_const(s));
    }
    const double E0 = *mechanics::energy_integral(P, 0.0, {P.r0, P.v0});
    state.counters["time"] = t_end;
    state.counters["energy_drift"] = std::abs(*mechanics::energy_integral(P, t_end, s) - E0) / std::abs(E0);
}
void RotatingKepler_EnergyDrift_Reduction(benchmark::State& s) { RotatingKepler_EnergyDrift<true>(s); }
void RotatingKepler_EnergyDrift_rkf78(benchmark::State& s) { RotatingKepler_EnergyDrift<false>(s); }
BENCHMARK(RotatingKepler_EnergyDrift_Reduction)->RangeMultiplier(4)->Range(1, 64)->Unit(benchmark::kMillisecond);
BENCHMARK(RotatingKepler_EnergyDrift_rkf78)->RangeMultiplier(4)->Range(1, 64)->Unit(benchmark::kMillisecond);

// Exact relative motion (two Kepler orbits rotated into the LVLH frame) and the
// error of the Clohessy-Wiltshire model: range(0) = log10(separation in m), range(1) = orbits.
void RelativeMotion_ExactAgainstCW(benchmark::State& state) {
    const double mu = 398600.4418, r = 7000.0, n = std::sqrt(mu / (r * r * r));
    const Vector3d R0(r, 0, 0), V0(0, n * r, 0);
    const double d = std::pow(10.0, double(state.range(0))) / 1000.0;  // km
    const double t = double(state.range(1)) * 2 * std::numbers::pi / n;
    const mechanics::relative_state s{d * Vector3d(0.3, -0.8, 0.5).normalized(), 1e-4 * d * Vector3d(0.2, 0.1, -0.3)};
    mechanics::relative_state exact;
    for (auto _ : state) {
        exact = mechanics::relative_motion_exact(mu, R0, V0, s, t);
        benchmark::DoNotOptimize(std::as_const(exact));
    }
    const mechanics::relative_state cw = mechanics::clohessy_wiltshire(n, s, t);
    state.counters["separation_m"] = d * 1000.0;
    state.counters["cw_relative_error"] = (cw.position - exact.position).norm() / exact.position.norm();
}
BENCHMARK(RelativeMotion_ExactAgainstCW)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {1, 10}})->Unit(benchmark::kMicrosecond);

// A target on an orbit with e ~ 0.3 (perigee 7000 km): the elliptic linear model (Tschauner-
// Hempel, integrated; Yamanaka-Ankersen is its closed form) and Clohessy-Wiltshire with the mean
// motion, against the exact motion. range(0) = log10(separation in m), range(1) = orbits.
void RelativeMotion_EccentricAgainstLinear(benchmark::State& state) {
    const double mu = 398600.4418;
    const Vector3d R0(7000.0, 0, 0), V0(0, 8.5, 1.2);
    const double a = 1 / (2 / R0.norm() - V0.squaredNorm() / mu), n = std::sqrt(mu / (a * a * a));
    const double d = std::pow(10.0, double(state.range(0))) / 1000.0;  // km
    const double t = double(state.range(1)) * 2 * std::numbers::pi / n;
    const mechanics::relative_state s{d * Vector3d(0.3, -0.8, 0.5).normalized(), 1e-4 * d * Vector3d(0.2, 0.1, -0.3)};
    mechanics::relative_state th;
    for (auto _ : state) {
        th = mechanics::tschauner_hempel(mu, R0, V0, s, {t})[0];
        benchmark::DoNotOptimize(std::as_const(th));
    }
    const mechanics::relative_state exact = mechanics::relative_motion_exact(mu, R0, V0, s, t);
    const mechanics::relative_state cw = mechanics::clohessy_wiltshire(n, s, t);
    state.counters["separation_m"] = d * 1000.0;
    state.counters["th_relative_error"] = (th.position - exact.position).norm() / exact.position.norm();
    state.counters["cw_relative_error"] = (cw.position - exact.position).norm() / exact.position.norm();
}
BENCHMARK(RelativeMotion_EccentricAgainstLinear)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {1, 10}})->Unit(benchmark::kMillisecond);

// The same linear model in closed form (Yamanaka-Ankersen, mechanics::yamanaka_ankersen): its
// cost per point and its difference from the integrated Tschauner-Hempel model (the same
// equation: rounding plus odeint's 1e-13), e ~ 0.3 as above. range(0) = orbits.
void RelativeMotion_YamanakaAnkersen(benchmark::State& state) {
    const double mu = 398600.4418;
    const Vector3d R0(7000.0, 0, 0), V0(0, 8.5, 1.2);
    const double a = 1 / (2 / R0.norm() - V0.squaredNorm() / mu), n = std::sqrt(mu / (a * a * a));
    const double t = double(state.range(0)) * 2 * std::numbers::pi / n;
    const mechanics::relative_state s{Vector3d(0.3, -0.8, 0.5).normalized(), 1e-4 * Vector3d(0.2, 0.1, -0.3)};
    mechanics::relative_state ya;
    for (auto _ : state) {
        ya = mechanics::yamanaka_ankersen(mu, R0, V0, s, {t})[0];
        benchmark::DoNotOptimize(std::as_const(ya));
    }
    const mechanics::relative_state th = mechanics::tschauner_hempel(mu, R0, V0, s, {t})[0];
    state.counters["ya_vs_th"] = (ya.position - th.position).norm() / th.position.norm();
}
BENCHMARK(RelativeMotion_YamanakaAnkersen)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);

}  // namespace
