// The dual Poisson-Darboux problem Q^' = -Omega^(t) Q^ on SE(3) (numeric/se3.h,
// docs/rigid_body.md section 3): error against cost for the sixth-order Magnus
// method on SE(3), for Boost.Odeint on the 12 components of (R, d)
// (R' = -W R, d' = -w x d - v; rkf78, dopri5), and for the closed form where
// there is one.
//
// Two twists, t in [0, 200]:
//   Se3Moving_*      Omega^ = w + eps v, w = (0.7 sin 1.3t, 0.4 cos 2.1t, 0.5),
//                    v = (0.3 cos 0.9t, -0.2, 0.5 sin 1.7t): no closed form;
//                    reference the Magnus method at rel_tol 1e-15 (tests/test_se3.cpp
//                    checks it against rkf78 written directly on Boost.Odeint).
//   Se3Precession_*  the regular screw precession Omega^(t) = b^ + Q_b(t) a^,
//                    Q_b = exp(-t b^), whose closed form is Q^ = exp(-t b^) exp(-t a^)
//                    (a^, b^ constant twists; the axis of Omega^ moves);
//                    reference the closed form in long double (64-bit mantissa).
// Error: max(|R - R_ref|_F, |d - d_ref| / |d_ref|) at t = 200. Counters `error`,
// `twist_evals` and `orthogonality` (|R^T R - I|_F) are the chart's data:
//   bash bench/plot_se3.sh [build-dir]        (docs/figures/se3_wp.{csv,png})
#include <benchmark/benchmark.h>

#include <cmath>
#include <utility>

#include "numeric/integrate.h"
#include "numeric/rotation_tensor.h"
#include "numeric/se3.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using namespace symrep;
using num::rigid_motion;
using num::twist;

const double T = 200.0;

twist moving(double t) {
    return {Vector3d(0.7 * std::sin(1.3 * t), 0.4 * std::cos(2.1 * t), 0.5),
            Vector3d(0.3 * std::cos(0.9 * t), -0.2, 0.5 * std::sin(1.7 * t))};
}

const twist spin{Vector3d(0.2, -0.4, 1.3), Vector3d(0.1, 0.3, -0.2)};   // a^
const twist prec{Vector3d(0.0, 0.5, 0.2), Vector3d(-0.4, 0.0, 0.25)};  // b^
twist precession(double t) { return prec + num::apply(num::se3_exp(-t * prec), spin); }
rigid_motion precession_exact(double t) { return num::se3_exp(-t * prec) * num::se3_exp(-t * spin); }

// exp of a twist in long double (Rodrigues and the translation part, written out
// again here: the reference of the closed form's rounding)
using M3 = Eigen::Matrix<long double, 3, 3>;
using V3 = Eigen::Matrix<long double, 3, 1>;
std::pair<M3, V3> exp_ld(const twist& x, long double s) {
    const V3 w = s * x.w.cast<long double>(), v = s * x.v.cast<long double>();
    const long double p = w.norm();
    M3 K;
    K << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    const long double a = std::sin(p) / p, b = (1 - std::cos(p)) / (p * p), c = (p - std::sin(p)) / (p * p * p);
    const M3 I = M3::Identity();
    return {I + a * K + b * K * K, (I + b * K + c * K * K) * v};
}

const rigid_motion& reference(bool moving_twist) {
    static const rigid_motion m = [] {
        num::se3_tensor_options o;
        o.rel_tol = 1e-15;
        return num::se3_tensor(moving, {T}, o).Q[0];
    }();
    static const rigid_motion p = [] {
        const auto [Rb, db] = exp_ld(prec, -T);
        const auto [Ra, da] = exp_ld(spin, -T);
        return rigid_motion{(Rb * Ra).cast<double>(), (db + Rb * da).cast<double>()};
    }();
    return moving_twist ? m : p;
}

double distance(const rigid_motion& g, const rigid_motion& ref) {
    return std::max((g.R - ref.R).norm(), (g.d - ref.d).norm() / ref.d.norm());
}

void counters(benchmark::State& state, const rigid_motion& g, bool moving_twist, double evals) {
    state.counters["error"] = distance(g, reference(moving_twist));
    state.counters["twist_evals"] = evals;
    state.counters["orthogonality"] = (g.R.transpose() * g.R - Matrix3d::Identity()).norm();
}

double tolerance_of(const benchmark::State& state) { return std::pow(10.0, -double(state.range(0))); }

template <bool Moving>
void magnus(benchmark::State& state) {
    num::se3_tensor_options o;
    o.rel_tol = tolerance_of(state);
    num::se3_tensor_result r;
    for (auto _ : state) {
        r = num::se3_tensor(Moving ? moving : precession, {T}, o);
        benchmark::DoNotOptimize(std::as_const(r));
    }
    counters(state, r.Q[0], Moving, double(r.evaluations));
}

template <bool Moving>
void twelve_components(benchmark::State& state, num::stepper_kind kind) {
    std::size_t evals = 0;
    const num::rhs_function rhs = [&](double s, const double* y, double* dy) {
        ++evals;
        const twist x = Moving ? moving(s) : precession(s);
        Eigen::Map<const Matrix3d> R(y);
        Eigen::Map<const Vector3d> d(y + 9);
        Eigen::Map<Matrix3d> dR(dy);
        Eigen::Map<Vector3d> dd(dy + 9);
        dR = -num::skew(x.w) * R;
        dd = -x.w.cross(d) - x.v;
    };
    num::integration_options o;
    o.stepper = kind;
    o.rel_tol = o.abs_tol = tolerance_of(state);
    std::vector<double> y0(12, 0.0);
    y0[0] = y0[4] = y0[8] = 1.0;
    rigid_motion g;
    std::size_t per_run = 0;
    for (auto _ : state) {
        evals = 0;
        const num::integration_result r = num::integrate(rhs, 0.0, y0, {T}, o);
        for (int i = 0; i < 9; ++i) g.R.data()[i] = r.states(0, i);
        for (int i = 0; i < 3; ++i) g.d[i] = r.states(0, 9 + i);
        per_run = evals;
    }
    counters(state, g, Moving, double(per_run));
}

void Se3Moving_Magnus6(benchmark::State& s) { magnus<true>(s); }
void Se3Moving_Odeint12_rkf78(benchmark::State& s) { twelve_components<true>(s, num::stepper_kind::rkf78); }
void Se3Moving_Odeint12_dopri5(benchmark::State& s) { twelve_components<true>(s, num::stepper_kind::dopri5); }
void Se3Precession_Magnus6(benchmark::State& s) { magnus<false>(s); }
void Se3Precession_Odeint12_rkf78(benchmark::State& s) { twelve_components<false>(s, num::stepper_kind::rkf78); }
void Se3Precession_Odeint12_dopri5(benchmark::State& s) { twelve_components<false>(s, num::stepper_kind::dopri5); }
BENCHMARK(Se3Moving_Magnus6)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Se3Moving_Odeint12_rkf78)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Se3Moving_Odeint12_dopri5)->DenseRange(4, 12, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Se3Precession_Magnus6)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Se3Precession_Odeint12_rkf78)->DenseRange(4, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(Se3Precession_Odeint12_dopri5)->DenseRange(4, 12, 2)->Unit(benchmark::kMicrosecond);

// The closed form of the precession at t = 200: two exponentials and a product.
void Se3Precession_ClosedForm(benchmark::State& state) {
    rigid_motion g;
    for (auto _ : state) {
        g = precession_exact(T);
        benchmark::DoNotOptimize(std::as_const(g));
    }
    counters(state, g, false, 0.0);
}
BENCHMARK(Se3Precession_ClosedForm)->Arg(0)->Unit(benchmark::kMicrosecond);

}  // namespace
