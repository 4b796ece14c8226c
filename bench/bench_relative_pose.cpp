// Exact full-body relative orbital motion (mechanics/relative_pose.h, issue 31 item 5):
// speed against accuracy of the closed form against a direct 6-DOF integration.
//
// Scene: a leader on an inclined orbit with e ~ 0.2 (perigee ~ 7000 km) turning with a
// constant w, a torque-free axisymmetric deputy 1.5 km away (a regular precession, 0.05
// rad/s spin: ~ 500 turns), the pose after 10 orbits (~ 6e4 s).
//   RelativePose_Closed           the closed form (Kepler by universal variables at 50 digits,
//                                 both attitudes closed)
//   RelativePose_MagnusDeputy/k   the same with the deputy's attitude by Magnus on SO(3) at 1e-k
//   RelativePose_SixDof_<stepper>/k  Boost.Odeint on the 20 states (leader orbit, separation,
//                                 two attitude quaternions) at 1e-k, absolute and relative
// Counters: pos_error = |rho - rho_ref|/|rho_ref|, att_error = |A - A_ref| (Frobenius), the
// reference being the closed form; the closed form's own counters are its differences from
// independent methods (bounds of its error): the position from the 6-DOF rkf78 at 1e-12, the
// attitude from the same form with the deputy's tensor by Magnus at 1e-13.
//   bash bench/plot_relative_pose.sh      (docs/figures/relative_pose_wp.{csv,png})
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "mechanics/relative_motion.h"
#include "mechanics/relative_pose.h"
#include "numeric/integrate.h"

namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using namespace symrep;

const double mu = 398600.4418;
const double spin_a = 0.01, spin_3 = 0.05, spin_l = 0.6 * spin_3;  // I3/I1 = 1.6
const Vector3d leader_w(0.002, -0.001, 0.004);

Vector3d deputy_w(double t) { return Vector3d(spin_a * std::cos(spin_l * t), spin_a * std::sin(spin_l * t), spin_3); }

mechanics::relative_pose_problem problem() {
    mechanics::relative_pose_problem P;
    P.mu = mu;
    P.R0 = Vector3d(7000, 300, -200);
    P.V0 = Vector3d(-0.4, 8.1, 2.6);
    P.start.position = Vector3d(0.8, -1.1, 0.6);
    P.start.velocity = Vector3d(1e-3, -2e-3, 5e-4);
    P.start.attitude = Eigen::AngleAxisd(2.3, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    P.leader = mechanics::attitude_motion::constant(leader_w);
    P.deputy = mechanics::attitude_motion::precession(Vector3d::UnitZ(), -spin_l, Vector3d(spin_a, 0, spin_3 + spin_l));
    return P;
}

double end_time() {
    const auto P = problem();
    const double a = 1 / (2 / P.R0.norm() - P.V0.squaredNorm() / mu);
    return 10 * 2 * std::numbers::pi * std::sqrt(a * a * a / mu);
}

const mechanics::pose_state& reference() {
    static const mechanics::pose_state p = mechanics::relative_pose(problem(), {end_time()})[0];
    return p;
}

// The 6-DOF integration: y = (r_L, v_L, s = r_D - r_L, s', q_L, q_D), q body to inertial.
mechanics::pose_state six_dof(num::stepper_kind stepper, double tol, std::size_t& evals) {
    const auto P = problem();
    const Matrix3d CL0 = mechanics::lvlh_axes(P.R0, P.V0).transpose();
    const Vector3d s0 = CL0 * P.start.position, ds0 = CL0 * (P.start.velocity + leader_w.cross(P.start.position));
    const Quaterniond qL(CL0), qD(Matrix3d(CL0 * P.start.attitude));
    std::vector<double> y0 = {P.R0.x(), P.R0.y(), P.R0.z(), P.V0.x(), P.V0.y(), P.V0.z(), s0.x(), s0.y(), s0.z(),
                              ds0.x(), ds0.y(), ds0.z(), qL.w(), qL.x(), qL.y(), qL.z(), qD.w(), qD.x(), qD.y(), qD.z()};
    auto quaternion_rate = [](const double* q, const Vector3d& w, double* dq) {
        const Quaterniond r = Quaterniond(q[0], q[1], q[2], q[3]) * Quaterniond(0, w.x(), w.y(), w.z());
        dq[0] = 0.5 * r.w(), dq[1] = 0.5 * r.x(), dq[2] = 0.5 * r.y(), dq[3] = 0.5 * r.z();
    };
    const num::rhs_function rhs = [&](double t, const double* y, double* dy) {
        const Vector3d r(y[0], y[1], y[2]), s(y[6], y[7], y[8]);
        const Vector3d gL = -mu * r / std::pow(r.norm(), 3), gD = -mu * (r + s) / std::pow((r + s).norm(), 3);
        for (int i = 0; i < 3; ++i) dy[i] = y[3 + i], dy[3 + i] = gL[i], dy[6 + i] = y[9 + i], dy[9 + i] = gD[i] - gL[i];
        quaternion_rate(y + 12, leader_w, dy + 12);
        quaternion_rate(y + 16, deputy_w(t), dy + 16);
    };
    num::integration_options o;
    o.stepper = stepper;
    o.rel_tol = o.abs_tol = tol;
    const num::integration_result res = num::integrate(rhs, 0.0, y0, {end_time()}, o);
    evals = res.rhs_evaluations;
    const Eigen::VectorXd y = res.states.row(0);
    const Matrix3d CL = Quaterniond(y[12], y[13], y[14], y[15]).normalized().toRotationMatrix();
    const Matrix3d CD = Quaterniond(y[16], y[17], y[18], y[19]).normalized().toRotationMatrix();
    mechanics::pose_state p;
    p.position = CL.transpose() * Vector3d(y[6], y[7], y[8]);
    p.attitude = CL.transpose() * CD;
    return p;
}

void errors(benchmark::State& state, const mechanics::pose_state& p, const mechanics::pose_state& ref) {
    state.counters["pos_error"] = (p.position - ref.position).norm() / ref.position.norm();
    state.counters["att_error"] = (p.attitude - ref.attitude).norm();
    state.counters["rhs_evals"] = 0;  // the CSV reporter wants the same counters in every row
}

void RelativePose_Closed(benchmark::State& state) {
    const auto P = problem();
    mechanics::pose_state p;
    for (auto _ : state) {
        p = mechanics::relative_pose(P, {end_time()})[0];
        benchmark::DoNotOptimize(std::as_const(p));
    }
    // bounds of its own error: the position against rkf78 at 1e-12, the attitude against the
    // deputy's tensor by Magnus at 1e-13 (two independent methods)
    std::size_t evals = 0;
    mechanics::pose_state bound = six_dof(num::stepper_kind::rkf78, 1e-12, evals);
    auto M = P;
    num::rotation_tensor_options o;
    o.rel_tol = 1e-13;
    M.deputy = mechanics::attitude_motion::numeric(deputy_w, o);
    bound.attitude = mechanics::relative_pose(M, {end_time()})[0].attitude;
    errors(state, p, bound);
}
BENCHMARK(RelativePose_Closed)->Unit(benchmark::kMicrosecond);

void RelativePose_MagnusDeputy(benchmark::State& state) {
    auto P = problem();
    num::rotation_tensor_options o;
    o.rel_tol = std::pow(10.0, -double(state.range(0)));
    P.deputy = mechanics::attitude_motion::numeric(deputy_w, o);
    mechanics::pose_state p;
    for (auto _ : state) {
        p = mechanics::relative_pose(P, {end_time()})[0];
        benchmark::DoNotOptimize(std::as_const(p));
    }
    errors(state, p, reference());
}
BENCHMARK(RelativePose_MagnusDeputy)->DenseRange(6, 14, 2)->Unit(benchmark::kMicrosecond);

void six_dof_bench(benchmark::State& state, num::stepper_kind k) {
    const double tol = std::pow(10.0, -double(state.range(0)));
    mechanics::pose_state p;
    std::size_t evals = 0;
    for (auto _ : state) {
        p = six_dof(k, tol, evals);
        benchmark::DoNotOptimize(std::as_const(p));
    }
    errors(state, p, reference());
    state.counters["rhs_evals"] = double(evals);
}
void RelativePose_SixDof_rkf78(benchmark::State& state) { six_dof_bench(state, num::stepper_kind::rkf78); }
void RelativePose_SixDof_dopri5(benchmark::State& state) { six_dof_bench(state, num::stepper_kind::dopri5); }
BENCHMARK(RelativePose_SixDof_rkf78)->DenseRange(6, 14, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(RelativePose_SixDof_dopri5)->DenseRange(6, 12, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
