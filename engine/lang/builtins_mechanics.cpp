// symrep/lang/builtins_mechanics.cpp -- vectors, Cauchy problems and their exact
// solutions (thesis Ch. VI), with the numeric backend behind eval and verify.
//
//   vector w, r0, v0
//   P := ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)
//   s := solve(P)                      coordinate-free closed form
//   check(P, s)                        exact: residual and initial conditions
//   verify(P, s, values, T)            against Boost.Odeint on [0, T]
//   eval(s, values, t = 3600)          numbers
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>

#include "symrep/scalar/scalar.h"
#include "symrep/dual/dual.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/builtins_frames.h"
#include "symrep/output/printer.h"
#include "symrep/lang/values.h"
#include "symrep/lang/verify_dual.h"
#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/rotation_operator_algebra.h"
#include "symrep/mechanics/scene.h"
#include "symrep/numeric/reference.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/first_integrals.h"
#include "symrep/mechanics/orbit_decisions.h"
#include "symrep/mechanics/two_body.h"
#include "symrep/mechanics/relative_motion.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/mechanics/reduced_solution.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/numeric/verify.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

// lang/builtins_screw.cpp: F and F_adjoint with a dual w or x (a constant dual twist: exp(t W^) x^;
// a real w: real_operator, the builtin's own body, on each part of x)
bool has_dual_argument(const std::vector<value>& a);
value dual_rotation_operator(const builtin& b, const std::vector<value>& a, context& c,
                             const builtin_body& real_operator);

using output::print_ex;

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Vectors and mechanics";

ex vector_arg(const args_t& a, std::size_t i, const builtin& b) {
    const value& v = a[i];
    if (v.is_list() && v.as_list().size() == 3 && v.as_list()[0].is_ex() && v.as_list()[1].is_ex() &&
        v.as_list()[2].is_ex())
        return vector_literal(v.as_list()[0].as_ex(), v.as_list()[1].as_ex(), v.as_list()[2].as_ex());
    const ex& e = arg_ex(a, i, b);
    if (!e.is_zero() && !is_vector(e))
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a vector, not the scalar " +
                         print_ex(e) + " (usage: " + b.signature + ")");
    return e;
}

const mechanics::cauchy_problem& problem_arg(const args_t& a, std::size_t i, const builtin& b) {
    if (!a[i].is_problem())
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a problem made by ode(...), not " +
                         a[i].a_kind() + " (usage: " + b.signature + ")");
    return a[i].as_problem();
}

value numbers(const ex& c, const builtin& b) {
    // (num::from_double: a subnormal result is a number too, not CLN's underflow)
    if (!GiNaC::is_a<GiNaC::matrix>(c)) return value(ex(num::from_double(to_double(c, b, "the result"))));
    list l;
    for (const ex& x : components(c)) l.push_back(value(ex(num::from_double(to_double(x, b, "the result")))));
    return l;
}

std::string seconds(double s) {
    std::ostringstream os;
    os << std::setprecision(3);
    if (s < 1e-3) os << s * 1e6 << " us";
    else if (s < 1) os << s * 1e3 << " ms";
    else os << s << " s";
    return os.str();
}

/// Where the stable evaluator raised the precision of the closed form (numeric/stable_evaluator.h).
std::string precision_note(const num::verify_result& v) {
    const auto& n = v.closed_form_tiers;
    if (n[1] + n[2] == 0) return "";
    std::ostringstream os;
    os << " (";
    if (n[1]) os << n[1] << " points in binary128";
    if (n[1] && n[2]) os << ", ";
    if (n[2]) os << n[2] << " in multiprecision";
    os << ")";
    return os.str();
}

}  // namespace

namespace {

// The dual Poisson-Darboux problem with a twist that has no closed form (dual_darboux.h).
bool numeric_dual(const mechanics::cauchy_problem& P) {
    return P.dual_darboux && P.dual_darboux->twist.form == mechanics::dual_twist_form::kind::general;
}

bool is_dual_reduction(const reduction& r) { return bool(r.solution->problem->dual_darboux); }

}  // namespace

value solve_problem(const value& p) {
    if (const auto F = mechanics::moving_frame_of(p.as_problem()); F && F->rotating && mechanics::inertial_is_numeric(*F))
        // ([CS21] Thm 12) r = Q (psi - o), psi numeric (Kepler): the VI.3 object of y = Q psi, whose
        // problem carries the origin o (moving_frame_origin)
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(
            mechanics::reduced_solution{F->rotating, {}})});
    if (const auto F = mechanics::moving_frame_of(p.as_problem()); F && !F->carried.empty())
        // ([CS21] Thm 12) a turning frame that carries vectors: r = R (psi - o), R by Magnus
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(
            mechanics::reduced_solution{p.problem_pointer(), {}})});
    if (numeric_dual(p.as_problem()))
        // (issue 31 item 3) a twist without a closed form: x^ = Q^ x^0, Q^ by Magnus on SE(3)
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(
            mechanics::reduced_solution{p.problem_pointer(), {}})});
    if (p.as_problem().turning && !mechanics::closed_solution(p.as_problem(), *p.as_problem().turning))
        // (Thm VI.3.2.1) r = F_(-w)(psi): Q or psi has no closed form
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(
            mechanics::reduced_solution{p.problem_pointer(), {}})});
    return value(mechanics::solve(p.as_problem()));
}

namespace {

// The values of a solution by reduction: those bound by solve(P, values), then d's (d wins).
data_values reduction_values(const reduction& r, data_values d) {
    for (const auto& [k, v] : r.solution->values.vectors) d.vectors.emplace(k, v);
    for (const auto& [k, v] : r.solution->values.scalars) d.scalars.emplace(k, v);
    // a declared vector function w(t) given as [f1(t), f2(t), f3(t)]: w' is its derivative
    const ex& t = r.solution->problem->t;
    std::vector<std::pair<ex, ex>> derived;
    for (const auto& [k, v] : d.vectors)
        if (!diff_t(k, t).is_zero() && GiNaC::is_a<GiNaC::matrix>(v))
            derived.push_back({derivative(k), v.diff(GiNaC::ex_to<GiNaC::symbol>(t))});
    for (const auto& [k, v] : derived) d.vectors.emplace(k, v);
    return exact_values(std::move(d));
}

// The times in increasing order (order[k] the place of the k-th) for a solution by reduction.
std::pair<std::vector<std::size_t>, std::vector<double>> sorted_times(const std::vector<double>& times,
                                                                      const builtin& b) {
    std::vector<std::size_t> order(times.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });
    std::vector<double> sorted;
    for (const std::size_t i : order) {
        if (!(times[i] >= 0) || !std::isfinite(times[i]))
            throw type_error(b.name + ": a solution by reduction is evaluated at finite times t >= 0, not " +
                             std::to_string(times[i]));
        sorted.push_back(times[i]);
    }
    return {order, sorted};
}

// r (or r') of a solution by reduction at each time, in the given order.
std::vector<Eigen::Vector3d> reduction_at(const reduction& r, const data_values& d, const std::vector<double>& times,
                                          const builtin& b) {
    const auto [order, sorted] = sorted_times(times, b);
    const auto put = [&](const ex& e) { return put_values_limit(e, d); };
    const auto states = mechanics::evaluate(*r.solution, put, sorted);
    std::vector<Eigen::Vector3d> out(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[order[k]] = r.derivative ? states[k].v : states[k].r;
    return out;
}

// x^ (or x^') of a numeric dual solution at each time, in the given order.
std::vector<num::twist> dual_reduction_at(const reduction& r, const data_values& d, const std::vector<double>& times,
                                          const builtin& b) {
    const auto [order, sorted] = sorted_times(times, b);
    const auto put = [&](const ex& e) { return put_values_limit(e, d); };
    const auto states = mechanics::dual_darboux_states(*r.solution->problem, put, sorted, r.derivative != 0);
    std::vector<num::twist> out(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[order[k]] = states[k];
    return out;
}

// [x1 + eps y1, x2 + eps y2, x3 + eps y3]
value dual_triple_value(const num::twist& x) {
    list out;
    for (int i = 0; i < 3; ++i)
        out.push_back(value(ex(num::from_double(x.w[i]) + dual::dual_unit() * num::from_double(x.v[i]))));
    return value(out);
}

value triple_value(const Eigen::Vector3d& x) {
    return value(list{value(ex(num::from_double(x.x()))), value(ex(num::from_double(x.y()))), value(ex(num::from_double(x.z())))});
}

// Argument i as a vector of numbers (a literal [x, y, z] whose entries evaluate to reals).
Eigen::Vector3d number_vector(const args_t& a, std::size_t i, const builtin& b, const std::string& what) {
    const ex v = vector_arg(a, i, b);
    if (v.is_zero()) return Eigen::Vector3d::Zero();
    if (!is_vector_literal(v))
        throw type_error(b.name + ": " + what + " (argument " + std::to_string(i + 1) +
                         ") must be a vector of numbers [x, y, z], not " + print_ex(v));
    return {to_double(v.op(0), b, what), to_double(v.op(1), b, what), to_double(v.op(2), b, what)};
}

// The times of a last argument t = T or t = [T1, T2, ...] (numbers >= 0, sorted here).
std::vector<double> times_arg(const args_t& a, std::size_t i, const builtin& b, bool& several) {
    const ex& tr = arg_ex(a, i, b);
    if (!GiNaC::is_a<GiNaC::relational>(tr) || !GiNaC::is_a<GiNaC::symbol>(tr.lhs()))
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be t = T (usage: " + b.signature + ")");
    const ex T = tr.rhs();
    several = GiNaC::is_a<GiNaC::lst>(T) || GiNaC::is_a<GiNaC::matrix>(T);
    std::vector<double> out;
    for (std::size_t k = 0; k < (several ? T.nops() : 1); ++k) {
        const double x = to_double(several ? T.op(k) : T, b, "the time");
        if (!(x >= 0) || !std::isfinite(x)) throw type_error(b.name + ": the times must be finite and >= 0");
        out.push_back(x);
    }
    return out;
}

// The arguments mu, R0, V0, rho0, rho0' of the relative-motion builtins.
struct relative_arguments {
    double mu;
    Eigen::Vector3d R0, V0;
    mechanics::relative_state start;
};
relative_arguments relative_args(const args_t& a, const builtin& b) {
    const double mu = to_double(arg_ex(a, 0, b), b, "mu");
    if (!(mu > 0)) throw type_error(b.name + ": mu must be positive");
    return {mu, number_vector(a, 1, b, "R0"), number_vector(a, 2, b, "V0"),
            {number_vector(a, 3, b, "rho0"), number_vector(a, 4, b, "rho0'")}};
}

// [[x, y, z], [x', y', z']] for one time, a list of those for several.
value relative_states(const std::vector<mechanics::relative_state>& s, bool several) {
    list out;
    for (const auto& x : s) out.push_back(value(list{triple_value(x.position), triple_value(x.velocity)}));
    return several ? value(out) : out[0];
}

}  // namespace

namespace {

// [w = [0, 0, W], g = [a, b, 0], ...] as the values of a scene (as for eval)
mechanics::parameter_values scene_values(const args_t& a, std::size_t i, const builtin& b) {
    const data_values d = read_values(a[i], b, i);
    return {d.vectors, d.scalars};
}

}  // namespace

value solve_scene(const builtin& b, const args_t& a, context& c) {
    const auto& P = problem_arg(a, 0, b);
    if (numeric_dual(P)) {  // (issue 31 item 3) the values bound, put in when it is evaluated
        c.out() << b.name << ": method: x = Q^ x(0) with Q^' = -Omega Q^, Q^(0) = I; the twist has no closed form: "
                << "Q^ numeric (Magnus on SE(3))\n";
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(
            mechanics::reduced_solution{a[0].problem_pointer(), scene_values(a, 1, b)})});
    }
    if (P.turning && !mechanics::closed_solution(P, *P.turning)) {
        // the reduction with the values bound (they are put in when it is evaluated)
        mechanics::reduced_solution s{a[0].problem_pointer(), scene_values(a, 1, b)};
        c.out() << b.name << ": method: reduction to the inertial problem (Thm VI.3.2.1), r = Q psi; "
                << (!s.form().angle ? "Q numeric (Magnus on SO(3))" : "Q in closed form (VI.2.12)") << ", "
                << (!s.form().psi ? "psi numeric" : "psi in closed form") << "\n";
        return value(reduction{std::make_shared<const mechanics::reduced_solution>(std::move(s))});
    }
    const mechanics::scene_solution s = mechanics::solve(P, scene_values(a, 1, b));
    std::istringstream report(s.model.report());
    for (std::string line; std::getline(report, line);) c.out() << b.name << ": " << line << "\n";
    return value(s.x);
}

namespace {

// The end time T, the number of sample times n (default 200) and the stepper (controlled:
// rkf78 by default, tolerances 1e-12) of verify(P, s, values, T [, n [, stepper]]).
std::tuple<double, long, num::integration_options> verify_arguments(const args_t& a, const builtin& b) {
    const double T = to_double(arg_ex(a, 3, b), b, "the end time T");
    if (!(T > 0) || !std::isfinite(T)) throw type_error(b.name + ": the end time T must be positive");
    const long n = a.size() > 4 ? arg_int(a, 4, b, 2, 10000000) : 200;
    num::integration_options opt;
    opt.abs_tol = opt.rel_tol = 1e-12;
    if (a.size() > 5) opt.stepper = num::stepper_from_name(arg_string(a, 5, b));
    if (opt.stepper == num::stepper_kind::rk4)
        throw type_error(b.name + ": rk4 has no error control; use rkf78, bulirsch_stoer or dopri5");
    return {T, n, opt};
}

// verify(P, s, values, T [, n [, stepper]]) for a solution by reduction: r and r'
// (x for order 1) from Q psi against Boost.Odeint on P as stated in the rotating frame.
value verify_reduction(const builtin& b, const args_t& a, context& c) {
    const auto& P = problem_arg(a, 0, b);
    const reduction& r = a[1].as_reduction();
    if (r.derivative) throw type_error(b.name + ": argument 2 must be the solution, not its derivative");
    const data_values d = reduction_values(r, read_values(a[2], b, 2));
    const auto [T, n, opt] = verify_arguments(a, b);
    if (const auto F = mechanics::moving_frame_of(P); F && !F->carried.empty()) {
        // ([CS21] Thm 12) against the frame's equation with R integrated beside it
        const auto put = [&](const ex& e) { return put_values_limit(e, d); };
        const num::sampled_function cf = [&](const std::vector<double>& times, double* out) {
            const auto x = mechanics::evaluate(*r.solution, put, times);
            for (std::size_t k = 0; k < times.size(); ++k)
                for (int i = 0; i < 3; ++i) out[6 * k + i] = x[k].r[i], out[6 * k + 3 + i] = x[k].v[i];
        };
        return verify_carried_frame(b, P, *F, cf, d, T, std::size_t(n), opt, c);
    }
    if (is_dual_reduction(r)) {  // x^ = Q^ x^0 (Magnus on SE(3)) against P as six real equations
        if (!P.dual_darboux) throw type_error(b.name + ": the solution is of a dual problem, P is not");
        const auto put = [&](const ex& e) { return put_values_limit(e, d); };
        const mechanics::cauchy_problem& S = *r.solution->problem;
        const num::sampled_function cf = [&](const std::vector<double>& times, double* out) {
            const auto x = mechanics::dual_darboux_states(S, put, times);
            for (std::size_t k = 0; k < times.size(); ++k)
                for (int i = 0; i < 3; ++i) out[6 * k + i] = x[k].w[i], out[6 * k + 3 + i] = x[k].v[i];
        };
        return verify_dual(P, cf, d, T, std::size_t(n), opt, b, c);
    }
    const auto t0 = std::chrono::steady_clock::now();
    data_values dp = d;
    dp.scalars.erase(P.t);
    const first_order_system sys = first_order(P, dp, b);
    num::symbolic_system rhs(sys.rhs, GiNaC::ex_to<GiNaC::symbol>(P.t), sys.state, {});
    const std::size_t m = sys.state.size();  // r and r' (order 2), x (order 1)
    const auto put = [&](const ex& e) { return put_values_limit(e, dp); };
    const num::sampled_function cf = [&](const std::vector<double>& times, double* out) {
        const auto states = mechanics::evaluate(*r.solution, put, times);
        for (std::size_t k = 0; k < times.size(); ++k)
            for (std::size_t i = 0; i < m; ++i) out[k * m + i] = i < 3 ? states[k].r[int(i)] : states[k].v[int(i - 3)];
    };
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const num::verify_result v = num::verify(cf, m, rhs.function(), sys.initial, 0.0, T, std::size_t(n), opt);
    static const char* axes[] = {"x", "y", "z", "x'", "y'", "z'"};
    c.out() << "verify: max relative difference " << std::setprecision(3) << v.max_relative_difference
            << " (component " << axes[v.component_of_max] << " of " << P.name << (v.component_of_max < 3 ? "" : "'")
            << ", t = " << std::setprecision(6) << v.time_of_max << ") over " << v.n_points << " points in [0, " << T
            << "]; reduction " << seconds(v.closed_form_seconds) << ", " << num::stepper_name(opt.stepper) << " "
            << seconds(v.integration_seconds) << " (" << v.rhs_evaluations << " right-hand sides), setup "
            << seconds(prep) << "\n";
    return value(ex(num::from_double(v.max_relative_difference)));
}

value builtin_cross(const builtin& b, const args_t& a, context&) {
    return value(cross(vector_arg(a, 0, b), vector_arg(a, 1, b)));
}

value builtin_dot(const builtin& b, const args_t& a, context&) {
    return value(dot(vector_arg(a, 0, b), vector_arg(a, 1, b)));
}

value builtin_triple(const builtin& b, const args_t& a, context&) {
    return value(triple(vector_arg(a, 0, b), vector_arg(a, 1, b), vector_arg(a, 2, b)));
}

value builtin_norm(const builtin& b, const args_t& a, context&) {
    return value(norm(vector_arg(a, 0, b)));
}

value builtin_skew(const builtin& b, const args_t& a, context&) {
    const ex w = vector_arg(a, 0, b);
    if (!is_vector_literal(w))
        throw type_error(b.name + ": argument 1 must be a vector given by its components [w1, w2, w3]");
    const ex x = w.op(0), y = w.op(1), z = w.op(2);
    return value(ex(GiNaC::matrix(3, 3, GiNaC::lst{0, -z, y, z, 0, -x, -y, x, 0})));
}

value builtin_rotation_operator(const builtin& b, const args_t& a, context&) {
    const ex w = vector_arg(a, 0, b), t = arg_ex(a, 1, b), x = vector_arg(a, 2, b);
    if (w.is_zero()) return value(x);
    const GiNaC::possymbol W("|w|");
    const mechanics::rotation_operator_algebra R(W);
    const element E = R.exp_minus_Kt(t);
    auto c = [&](std::size_t k) { return E[k].subs(W == norm(w)); };
    return value(c(0) * x + c(1) * cross(w, x) + c(2) * cross(w, cross(w, x)));
}

// The operands w, x of F(w, x) and F_adjoint(w, x) and the time t, w required to have a value at
// t = 0; `identity` when the operator leaves x as it is (w = 0 or x = 0).
struct rotation_operands {
    ex w, x, t;
    bool identity = false;
};
rotation_operands read_rotation_operands(const builtin& b, const args_t& a, context& c) {
    rotation_operands o{vector_arg(a, 0, b), vector_arg(a, 1, b), c.symbol("t")};
    o.identity = o.w.is_zero() || o.x.is_zero() || equal(o.w, 0);
    if (o.identity) return o;
    try {
        mechanics::require_value_at_zero(o.w, o.t, "w(t)");
    } catch (const domain_error& e) {
        throw domain_error(b.name + ": " + e.what());
    }
    return o;
}

value builtin_F(const builtin& b, const args_t& a, context& c) {
    if (has_dual_argument(a)) return dual_rotation_operator(b, a, c, builtin_F);  // dual w or x (builtins_screw.cpp)
    const auto [w, x, t, identity] = read_rotation_operands(b, a, c);
    if (identity) return value(x);
    // F_w = F_(-v) with v = -w, the Q of v (turning_frame.h): closed for a fixed direction
    // (a constant w too; VI.2.12, the angle an integral object when not elementary) and for
    // a regular precession
    mechanics::turning_frame_form F;
    F.terms.w = -w;
    if (const auto d = mechanics::fixed_direction(w, t)) {  // -w = s(t) (-u): the angle of w about -u
        F.u = -d->second;
        F.angle = mechanics::rotation_angle(d->first, d->second, t, true);
    } else {
        F.precessing = mechanics::regular_precession(-w, t);
    }
    if (const auto y = mechanics::closed_rotation(F, x, t))  // literals: one literal
        return value(vector_symbols(*y).empty() ? subs_components(*y, {}) : *y);
    if (mechanics::depends_on_time(x, t))
        throw domain_error(b.name + ": w(t) = " + print_ex(w) + " turns, so R has no closed form, and x = " +
                           print_ex(x) + " depends on t: F_w(x) is evaluated for a constant x only "
                           "(F(w, x0), then eval)");
    return value(reduction{std::make_shared<const mechanics::reduced_solution>(
        mechanics::reduced_solution{mechanics::rotation_problem(w, x, t), {}, true})});
}

value builtin_vector_series(const builtin& b, const args_t& a, context&) {
    const ex& e = arg_ex(a, 0, b);
    const ex& w = arg_ex(a, 1, b);
    if (!is_vector_symbol(w))
        throw type_error(b.name + ": argument 2 must be a vector symbol (usage: " + b.signature + ")");
    const long n = arg_int(a, 2, b, 0, 60);
    // |w| and w . w through a positive symbol W, so that |eps w| = eps W
    const GiNaC::possymbol eps("eps"), W("W");
    const ex ew = e.subs(norm(w) == W).subs(dot(w, w) == GiNaC::pow(W, 2));
    const ex es = subs_vectors(ew, {{w, eps * w}}).subs(W == eps * W);
    const ex ser = GiNaC::series_to_poly(es.series(eps == 0, int(n) + 1));
    return value(GiNaC::expand(ser.subs(eps == 1)).subs(W == norm(w)));
}

value builtin_ode(const builtin& b, const args_t&, context&) {
    throw type_error(b.name + ": internal: ode is evaluated by the interpreter");
}

value builtin_first_integrals(const builtin& b, const args_t& a, context&) {
    const auto& P = problem_arg(a, 0, b);
    if (P.turning) {
        list out;
        for (const ex& I : mechanics::first_integrals(P, *P.turning)) out.push_back(value(I));
        return value(out);
    }
    std::string why;
    const auto fa = P.fixed_axis ? std::optional<mechanics::fixed_axis_form>(*P.fixed_axis)
                                 : mechanics::read_fixed_axis(P, &why);
    if (!fa)
        throw domain_error(b.name + ": the problem is not m (r'' + 2 w x r' + w' x r + w x (w x r)) + k r = 0 "
                           "with w = s(t) u" + (why.empty() ? std::string() : " (" + why + ")"));
    list out;
    for (const ex& I : mechanics::first_integrals(P, *fa)) out.push_back(value(I));
    return value(out);
}

value builtin_check(const builtin& b, const args_t& a, context& c) {
    const auto& P0 = problem_arg(a, 0, b);
    if (a[1].is_reduction() && mechanics::moving_frame_of(P0) && a.size() == 2) return check_moving_frame(b, P0, c);
    if (a[1].is_reduction() && is_dual_reduction(a[1].as_reduction()))
        throw domain_error(b.name + ": the solution of " + P0.name + " is numeric (Q^ by Magnus on SE(3): the "
                           "twist has no closed form), nothing exact to substitute: compare it with the "
                           "equation numerically, verify(P, s, values, T)");
    if (a[1].is_reduction())
        throw domain_error(b.name + ": the solution is the reduction " + P0.name +
                           " = F_(-w)(psi) (Thm VI.3.2.1, proved once for all w in the tests), not a closed "
                           "form in t: compare it with the equation numerically, verify(P, s, values, T)");
    const mechanics::parameter_values vals =
        a.size() == 3 ? scene_values(a, 2, b) : mechanics::parameter_values{};
    const mechanics::cauchy_problem P = a.size() == 3 ? mechanics::with_values(P0, vals) : P0;
    // the values go into s too (a general solution checked for the scene's values)
    const ex s0 = P.is_vector ? vector_arg(a, 1, b) : arg_ex(a, 1, b);
    const ex s = a.size() == 3 ? mechanics::put_values(s0, vals) : s0;
    const mechanics::solution_check k = mechanics::check(P, s);
    // a vector as the language writes it: one literal [x, y, z] when no vector symbol is left
    auto shown = [&](const ex& x) {
        if (P.is_vector && is_vector(x) && vector_symbols(x).empty())
            return print_ex(subs_components(x, {}));
        return print_ex(x);
    };
    if (!k) {
        // false only when shown: a residual or difference that is neither proved 0 nor
        // seen nonzero at a point is undecided (scalar/equality.h), never reported as false
        std::vector<std::pair<std::string, ex>> open;
        bool some_no = k.residual_seen_nonzero;
        if (!k.residual_zero && !k.residual_seen_nonzero) open.push_back({"the residual", k.residual});
        for (std::size_t m = 0; m < k.initial_differences.size(); ++m)
            if (!k.initial_differences[m].is_zero())
                open.push_back({P.unknown_name(m) + "(0) minus its value", k.initial_differences[m]});
        std::string undecided;
        for (const auto& [what, x] : open) {
            const zero_decision z = P.is_vector ? decide_zero_vector(x) : decide_zero(x);
            // a point value of an integral object is a quadrature's, not exact: with one,
            // a residual not proved 0 stays undecided
            if (z.is_zero == truth::no && !num::has_integral(x)) some_no = true;
            if ((z.is_zero != truth::no || num::has_integral(x)) && undecided.empty())
                undecided = what + " " + shown(x);
        }
        if (!some_no && !undecided.empty())
            throw domain_error(b.name + ": cannot decide whether " + undecided +
                               " is 0 (the zero test does not prove it, and no point was found where it "
                               "is not 0)");
    }
    if (!k.residual_zero) c.out() << "check: the residual is " << shown(k.residual) << ", not 0\n";
    if (k && k.rounding > 0) {
        std::ostringstream ratio;  // not on c.out(): its precision stays as it is
        ratio << std::setprecision(2) << k.rounding;
        c.out() << "check: 0 up to rounding (floating-point values): what remains is at most " << ratio.str()
                << " times the largest term\n";
    }
    for (std::size_t m = 0; m < k.initial_differences.size(); ++m)
        if (!k.initial_differences[m].is_zero())
            c.out() << "check: " << P.unknown_name(m) << "(0) differs from its value by "
                    << shown(k.initial_differences[m]) << "\n";
    return value(bool(k));
}

value builtin_model(const builtin& b, const args_t& a, context&) {
    return value(mechanics::classify(problem_arg(a, 0, b), scene_values(a, 1, b)).report());
}

value eval_expression(const builtin& b, const args_t& a);
value eval_reduction(const builtin& b, const args_t& a);

value builtin_eval(const builtin& b, const args_t& a, context&) {
    if (a[0].is_reduction()) return named_by(b, [&] { return eval_reduction(b, a); });
    return eval_expression(b, a);
}

value eval_reduction(const builtin& b, const args_t& a) {
    // r = F_(-w)(psi) (or r') at the given times, numerically
    const reduction& red = a[0].as_reduction();
    if (a.size() != 3)
        throw type_error(b.name + ": a solution by reduction is evaluated at times: eval(s, values, t = T)");
    const ex& tr = arg_ex(a, 2, b);
    if (!GiNaC::is_a<GiNaC::relational>(tr) || !tr.lhs().is_equal(red.solution->problem->t))
        throw type_error(b.name + ": argument 3 must be t = T (usage: " + b.signature + ")");
    std::vector<double> times;
    const ex T = tr.rhs();
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::lst>(T) || GiNaC::is_a<GiNaC::matrix>(T) ? T.nops() : 1); ++i)
        times.push_back(to_double(GiNaC::is_a<GiNaC::lst>(T) || GiNaC::is_a<GiNaC::matrix>(T) ? T.op(i) : T, b, "the time"));
    const bool one = !GiNaC::is_a<GiNaC::lst>(T) && !GiNaC::is_a<GiNaC::matrix>(T);
    if (is_dual_reduction(red)) {  // x^ = Q^ x^0 (or x^'), Q^ by Magnus on SE(3)
        const auto x = dual_reduction_at(red, reduction_values(red, read_values(a[1], b, 1)), times, b);
        if (x.size() == 1 && one) return dual_triple_value(x[0]);
        list out;
        for (const auto& v : x) out.push_back(dual_triple_value(v));
        return value(out);
    }
    const auto x = reduction_at(red, reduction_values(red, read_values(a[1], b, 1)), times, b);
    if (x.size() == 1 && one) return triple_value(x[0]);
    list out;
    for (const auto& v : x) out.push_back(triple_value(v));
    return value(out);
}

value eval_expression(const builtin& b, const args_t& a) {
    // floats taken as the exact numbers they are, so that nothing is rounded before
    // to_double's precision-controlled evaluation (cancellation, long phases)
    const ex e = num::exact_floats_of(arg_ex(a, 0, b));
    const data_values d = exact_values(read_values(a[1], b, 1));
    std::vector<ex> times;
    ex tsym;
    if (a.size() == 3) {
        const ex& tr = arg_ex(a, 2, b);
        if (!GiNaC::is_a<GiNaC::relational>(tr) || !GiNaC::is_a<GiNaC::symbol>(tr.lhs()))
            throw type_error(b.name + ": argument 3 must be t = T (usage: " + b.signature + ")");
        tsym = tr.lhs();
        const ex T = tr.rhs();
        if (GiNaC::is_a<GiNaC::lst>(T) || GiNaC::is_a<GiNaC::matrix>(T))  // t = [T1, T2, ...]
            for (std::size_t i = 0; i < T.nops(); ++i) times.push_back(num::decimal_floats_of(T.op(i)));
        else
            times.push_back(num::decimal_floats_of(T));  // t = 1e300 is 10^300 (a long phase shows the difference)
    }
    if (a.size() == 3 && a[2].is_ex() && times.empty())
        throw type_error(b.name + ": no time given");
    // the symbols of e other than t are constants: a value that depends on t would
    // evaluate a frozen solution of a different problem without a word (refused)
    const auto constants = [&](const auto& values) {
        for (const auto& [k, x] : values)
            if (x.has(tsym))
                throw domain_error(b.name + ": the value of " + print_ex(k) + " depends on " +
                                   print_ex(tsym) + ": the values are constants (the expression is "
                                   "evaluated at " + print_ex(tsym) + " = T)");
    };
    if (!times.empty()) {
        constants(d.scalars);
        constants(d.vectors);
    }
    // e at the values: where they make it divide by zero, its limit as the values approach
    // them (put_values_limit); where that is not established, the denominator named and
    // solve(P, values) proposed (it derives the solution of that scene)
    auto at = [&](const data_values& dv) -> value {
        try {
            return numbers(put_values_limit(e, dv, tsym), b);
        } catch (const domain_error& x) {
            const std::string m = x.what();
            if (m.rfind(singular_values_message, 0) != 0) throw;
            throw domain_error(b.name + ": " + m + "; for a solution of a problem P, solve(P, values) "
                               "derives the solution of this scene");
        }
    };
    try {
        if (times.empty()) return at(d);
        list out;
        for (const ex& T : times) {
            data_values dt = d;
            dt.scalars[tsym] = T;
            out.push_back(at(dt));
        }
        return times.size() == 1 ? out[0] : value(out);
    } catch (const type_error& x) {
        const std::string m = x.what();
        if (m.rfind(b.name + ": ", 0) == 0) throw;
        throw type_error(b.name + ": " + m);
    }
}

value builtin_verify(const builtin& b, const args_t& a, context& c) {
    const auto& P = problem_arg(a, 0, b);
    if (a[1].is_reduction()) return named_by(b, [&] { return verify_reduction(b, a, c); });
    const ex s = P.is_vector ? vector_arg(a, 1, b) : arg_ex(a, 1, b);
    data_values d = exact_values(read_values(a[2], b, 2));  // no rounding before the stable evaluator
    const auto [T, n, opt] = verify_arguments(a, b);
    if (P.dual_darboux) return verify_dual(P, s, d, T, std::size_t(n), opt, b, c);  // issue 31 item 3
    const auto t0 = std::chrono::steady_clock::now();
    // the closed form with the values put in (t stays free)
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(P.t);
    d.scalars.erase(P.t);
    const std::vector<ex> cf = components(put_values_limit(s, d));
    // the first-order system: state x, x', ..., x^(M-1); x^(M) solved from the equation
    const first_order_system sys = first_order(P, d, b);
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    num::verify_result v;
    if (std::any_of(cf.begin(), cf.end(), [](const ex& x) { return num::has_integral(x); })) {
        // integral objects (int_0^t ... dtau, fixed_axis.h): sampled, each by quadrature
        const num::sampled_function at = [&](const std::vector<double>& times, double* out) {
            for (std::size_t k = 0; k < times.size(); ++k)
                for (std::size_t i = 0; i < cf.size(); ++i)
                    out[k * cf.size() + i] =
                        to_double(cf[i].subs(t == GiNaC::numeric(times[k])), b, "the closed form");
        };
        num::symbolic_system rhs(sys.rhs, t, sys.state, {});
        v = num::verify(at, cf.size(), rhs.function(), sys.initial, 0.0, T, std::size_t(n), opt);
    } else {
        v = num::verify(cf, t, sys.rhs, sys.state, sys.initial, {}, 0.0, T, std::size_t(n), opt);
    }
    static const char* axes[] = {"x", "y", "z"};
    c.out() << "verify: max relative difference " << std::setprecision(3) << v.max_relative_difference
            << " (component " << (P.is_vector ? axes[v.component_of_max] : P.name.c_str()) << ", t = "
            << std::setprecision(6) << v.time_of_max << ") over " << v.n_points << " points in [0, " << T
            << "]; closed form " << seconds(v.closed_form_seconds) << precision_note(v) << ", "
            << num::stepper_name(opt.stepper) << " " << seconds(v.integration_seconds) << " ("
            << v.rhs_evaluations << " right-hand sides), setup " << seconds(prep + v.compile_seconds)
            << "\n";
    return value(ex(num::from_double(v.max_relative_difference)));
}

value builtin_relative_motion(const builtin& b, const args_t& a, context&) {
    const relative_arguments ra = relative_args(a, b);
    bool several = false;
    std::vector<mechanics::relative_state> out;
    for (const double t : times_arg(a, 5, b, several))
        out.push_back(mechanics::relative_motion_exact(ra.mu, ra.R0, ra.V0, ra.start, t));
    return relative_states(out, several);
}

value builtin_clohessy_wiltshire(const builtin& b, const args_t& a, context&) {
    const double n = to_double(arg_ex(a, 0, b), b, "n");
    if (!(n > 0)) throw type_error(b.name + ": the mean motion n must be positive");
    const mechanics::relative_state s{number_vector(a, 1, b, "rho0"), number_vector(a, 2, b, "rho0'")};
    bool several = false;
    std::vector<mechanics::relative_state> out;
    for (const double t : times_arg(a, 3, b, several)) out.push_back(mechanics::clohessy_wiltshire(n, s, t));
    return relative_states(out, several);
}

value builtin_tschauner_hempel(const builtin& b, const args_t& a, context&) {
    const relative_arguments ra = relative_args(a, b);
    bool several = false;
    std::vector<double> times = times_arg(a, 5, b, several);
    std::vector<std::size_t> order(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return times[i] < times[j]; });
    std::vector<double> sorted;
    for (const std::size_t k : order) sorted.push_back(times[k]);
    const auto states = mechanics::tschauner_hempel(ra.mu, ra.R0, ra.V0, ra.start, sorted);
    std::vector<mechanics::relative_state> out(times.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[order[k]] = states[k];
    return relative_states(out, several);
}

value builtin_yamanaka_ankersen(const builtin& b, const args_t& a, context&) {
    const relative_arguments ra = relative_args(a, b);
    bool several = false;
    const std::vector<double> times = times_arg(a, 5, b, several);
    return relative_states(mechanics::yamanaka_ankersen(ra.mu, ra.R0, ra.V0, ra.start, times), several);
}

}  // namespace

// ---- the first integrals as vectors, the generalized potentials, the two-body problem and the
// decisions of VI.3.3-VI.3.4 (mechanics/first_integrals.h, two_body.h, orbit_decisions.h)
namespace {

// F_(-w)(X0): closed, or the rotation problem (Q numeric) as a solution by reduction (as F(-w, X0))
value rotated_value(const ex& w, const ex& X0, const ex& t) {
    if (const auto y = mechanics::rotated_back(w, X0, t)) return value(*y);
    return value(reduction{std::make_shared<const mechanics::reduced_solution>(
        mechanics::reduced_solution{mechanics::rotation_problem(-w, X0, t), {}, true})});
}

value builtin_vector_first_integrals(const builtin& b, const args_t& a, context&) {
    const auto& P = problem_arg(a, 0, b);
    list out;
    for (const auto& I : mechanics::vector_first_integrals(P))
        out.push_back(value(list{value(I.name), value(I.quantity), rotated_value(P.turning ? P.turning->terms.w
                                                                                             : mechanics::read_central_motion(P, b.name).w,
                                                                                   I.initial, P.t)}));
    return value(out);
}

value builtin_generalized_potentials(const builtin& b, const args_t& a, context&) {
    list out;
    for (const auto& V : mechanics::generalized_potentials(problem_arg(a, 0, b)))
        out.push_back(value(list{value(V.name), value(V.V)}));
    return value(out);
}

value builtin_two_body(const builtin& b, const args_t& a, context& c) {
    const auto& CM = problem_arg(a, 0, b);
    const auto& REL = problem_arg(a, 1, b);
    ex s[4];
    const char* names[4] = {"x1", "x2", "v1", "v2"};
    for (int i = 0; i < 4; ++i) {
        s[i] = c.symbol(names[i]);
        register_vector(s[i]);
    }
    list out;
    for (const auto& q : mechanics::two_body_characteristics(CM, REL, arg_ex(a, 2, b), arg_ex(a, 3, b), s[0], s[1], s[2],
                                                             s[3]))
        out.push_back(value(list{value(q.name), q.by_rotation ? rotated_value(q.w, q.value, REL.t) : value(q.value)}));
    return value(out);
}

value orbit_decision_value(const builtin& b, const mechanics::orbit_decision& d, context& c) {
    c.out() << b.name << ": " << d.reason << "; " << (b.name == "bounded" ? "E = " : "u x L_c0 = ") << print_ex(d.quantity)
            << "\n";
    return value(d.answer);
}

value builtin_bounded(const builtin& b, const args_t& a, context& c) {
    const auto vals = a.size() == 2 ? scene_values(a, 1, b) : mechanics::parameter_values{};
    return orbit_decision_value(b, mechanics::bounded(problem_arg(a, 0, b), vals), c);
}

value builtin_planar(const builtin& b, const args_t& a, context& c) {
    const auto vals = a.size() == 2 ? scene_values(a, 1, b) : mechanics::parameter_values{};
    return orbit_decision_value(b, mechanics::planar(problem_arg(a, 0, b), vals), c);
}

value builtin_F_adjoint(const builtin& b, const args_t& a, context& c) {
    // a constant dual twist: Q^T = exp(t W^) = F_w (builtins_screw.cpp)
    if (has_dual_argument(a)) return dual_rotation_operator(b, a, c, builtin_F_adjoint);
    const auto [w, x, t, identity] = read_rotation_operands(b, a, c);
    if (identity) return value(x);
    const auto y = mechanics::rotated_adjoint(w, x, t);
    if (!y)
        throw domain_error(b.name + ": w(t) = " + print_ex(w) + " turns and Q has no closed form: F*_w(x) = Q^T x is "
                           "not available (the reduction uses Q psi = F(-w, psi))");
    return value(vector_symbols(*y).empty() ? subs_components(*y, {}) : *y);
}

void register_two_body_builtins(registry& r) {
    add_builtins(r, section, {
        {"vector_first_integrals", "vector_first_integrals(P)",
         "The vector first integrals (VI.2.99, 109; VI.3.141, 221) of P, m (r'' + 2 w x r' + w' x r + w x (w x r)) + "
         "m f(|r|) r/|r| = 0 with any w(t) (a constant k r included): a list of [statement, X, F_(-w)(X0)] with X in "
         "r, r' and X0 its value at t = 0: X = r x (r' + w x r), X0 = Omega0 = r0 x (v0 + w(0) x r0), and for free "
         "motion also X = r' + w x r (VI.3.240). Each is proved: X' + w x X = 0 along the equation (exactly), so "
         "X = F_(-w)(X0), the rotation tensor of the frame (closed for a fixed direction or a regular precession, "
         "proved y' + w x y = 0 and y(0) = X0; for a turning w a solution by reduction, evaluated by eval).",
         "(VI.2.99), (VI.2.109), (VI.3.141), (VI.3.211), (VI.3.221-223)",
         "vector u, r0, v0\nw := (1 + cos(t))*u\nvector_first_integrals(ode(r'' + 2*w x r' + w' x r + w x (w x r) + "
         "k*r/|r|^3 = 0, r(0) = r0, r'(0) = v0))",
         1, 1, builtin_vector_first_integrals},
        {"generalized_potentials", "generalized_potentials(P)",
         "The generalized potential energies V of P (as for vector_first_integrals, with an elementary potential U, "
         "U' = f): m |r'|^2/2 + V is constant along every solution. A list of [statement, V]: V(t, r, r') = "
         "m (w, r, r') + m |w x r|^2/2 + m U(|r|) (VI.2.110, VI.3.225); for w = s(t) u of fixed direction "
         "V(t, r) = m w . Omega0 - m |w x r|^2/2 + m U (VI.2.113-114, VI.3.227, using u . (r x p) = u . Omega0); "
         "for a constant w the centrifugal potential V(r) = -m |w x r|^2/2 + m U (VI.2.115, VI.3.229). Each proved "
         "(the derivative along the equation exactly 0; the fixed-direction form as the first plus "
         "m s(t) (u . Omega0 - u . Omega), u . Omega proved constant).",
         "(VI.2.110-115), (VI.3.224-230)",
         "vector u, r0, v0\ngeneralized_potentials(ode(r'' + 2*W*u x r' + W*u x (W*u x r) + k*r/|r|^3 = 0, r(0) = r0, "
         "r'(0) = v0))",
         1, 1, builtin_generalized_potentials},
        {"two_body", "two_body(CM, REL, m1, m2)",
         "The two-body problem in a frame rotating with w(t) (VI.3.4.2): CM the centre of mass's free problem "
         "(R'' + 2 w x R' + w' x R + w x (w x R) = 0), REL the relative one (r = x2 - x1, the same w, a central "
         "field f(|r|) r/|r| per unit mass), m1, m2 the masses. The coupled equations are checked to give CM and REL "
         "back. Returns [statement, value] pairs in the vector symbols x1, x2 (positions), v1, v2 (velocities; "
         "declared vectors by the call): P, K0, E_cin, I0 w, V_c, V (VI.3.253-260); H, L0, T with H = P + M w x r_c, "
         "L0 = K0 + I0 w, T = E_cin + V_c (VI.3.237-258), H' + w x H = 0, L0' + w x L0 = 0, T + V constant; "
         "H(t) = F_(-w)(H0), L0(t) = F_(-w)(L0^0) from CM's and REL's initial values (closed for a fixed direction: "
         "VI.3.267-268); the generalized potentials (VI.3.264-266); the centre-of-mass frame H^c = 0, L_c, L_c(t), "
         "T^c, and E_cin^c + V constant with its fixed-direction form and Jacobi's integral (VI.3.273-291). Every "
         "statement is proved (identities by the zero test; constants by the derivative along the coupled equations).",
         "(VI.3.237-268), (VI.3.273-291)",
         "vector R0, V0, r0, u0\nw := [0, 0, W]\nCM := ode(R'' + 2*w x R' + w x (w x R) = 0, R(0) = R0, R'(0) = V0)\n"
         "REL := ode(r'' + 2*w x r' + w x (w x r) + G*M*r/|r|^3 = 0, r(0) = r0, r'(0) = u0)\ntwo_body(CM, REL, m1, m2)[6]",
         4, 4, builtin_two_body},
        {"bounded", "bounded(P [, values])",
         "Consequence VI.3.3.2 decided: P is Kepler's problem in a frame rotating with any w(t), "
         "r'' + 2 w x r' + w' x r + w x (w x r) + k r/|r|^3 = 0 with k > 0. Computes E = |v0 + w(0) x r0|^2/2 - k/|r0| "
         "(VI.3.154; values put in as for eval) and returns true when E < 0 (|r| <= k/|E|), false when E >= 0 (a "
         "parabola or hyperbola, or a radial motion outwards); prints the reason and E. An error says \"cannot "
         "decide\" when the sign of E (or of k) is not established, and names a radial fall into the centre.",
         "(VI.3.153-154)",
         "vector r0, v0\nw := (1 + cos(t))*[0, 0, 1]\nK := ode(r'' + 2*w x r' + w' x r + w x (w x r) + k*r/|r|^3 = 0, "
         "r(0) = r0, r'(0) = v0)\nbounded(K, [k = 1, r0 = [1, 0, 0], v0 = [0, 0.5, 0]])",
         1, 2, builtin_bounded},
        {"planar", "planar(P [, values])",
         "The planarity criterion (VI.3.281-284) decided: P a rotating-frame problem with a central field and w = "
         "s(t) u of fixed direction. The orbit lies in the plane through the centre normal to L_c = r x (r' + w x r), "
         "which turns with L_c = F_(-w)(L_c0): true when that plane is fixed, u x L_c0 = 0 (VI.3.282; with "
         "L_c0 != 0 the same as r0 . u = 0 and v0 . u = 0, VI.3.284), false when u x L_c0 != 0 (the plane turns "
         "about u). A radial motion (L_c0 = 0) is planar when r0 . u = 0 or r0 x u = 0, and otherwise refused. "
         "Prints the reason; \"cannot decide\" when u x L_c0 is neither proved 0 nor a nonzero number.",
         "(VI.3.281-284)",
         "vector r0, v0\nw := (1/2 + sin(t))*[0, 0, 1]\nplanar(ode(r'' + 2*w x r' + w' x r + w x (w x r) + k*r/|r|^3 = "
         "0, r(0) = r0, r'(0) = v0), [r0 = [a, b, 0], v0 = [c, d, 0]])",
         1, 2, builtin_planar},
        {"F_adjoint", "F_adjoint(w, x)",
         "The transformation F*_w(x) = Q^T x of Thm VI.3.1.1 (VI.3.119), Q the tensor of F_(-w) (Q' = -W Q, "
         "Q(0) = I): the reduction psi = F*_w(r) of Thm VI.3.2.1. In closed form where Q is (a fixed direction: "
         "the rotation by the opposite angle, = F(w, x); a regular precession: (Q^T x)_i = (Q e_i) . x), proved "
         "Q (Q^T x) = x; x may depend on t. Refused for a turning w (Q numeric). A constant dual twist "
         "w0 + eps v: exp(t W) x, as F (docs/rigid_body.md section 2).",
         "(VI.3.119), (Thm VI.3.1.1)",
         "vector x\nF_adjoint([sin(t), cos(t), 1], x)",
         2, 2, builtin_F_adjoint},
    });
}

}  // namespace

void register_mechanics_builtins(registry& r) {
    add_builtins(r, section, {
        {"cross", "cross(a, b)",
         "The cross product a x b (same as the operator x).",
         "", "vector a, b\ncross(a, b) + cross(b, a)", 2, 2, builtin_cross},
        {"dot", "dot(a, b)",
         "The scalar product a . b (same as the operator .).",
         "", "vector a\ndot(a, [1, 0, 0])", 2, 2, builtin_dot},
        {"triple", "triple(a, b, c)",
         "The scalar triple product [a, b, c] = a . (b x c).",
         "", "vector a, b, c\ntriple(a, b, c) + triple(b, a, c)", 3, 3, builtin_triple},
        {"norm", "norm(a)",
         "The length |a| = sqrt(a . a) of a vector.",
         "", "vector a\nnorm(a)^2", 1, 1, builtin_norm},
        {"skew", "skew(w)",
         "The skew matrix of w = [w1, w2, w3] (its matrix representation: skew(w) * x = w x x for columns x).",
         "(VI.1.1-11)", "skew([1, 2, 3]) * matrix([[4], [5], [6]])", 1, 1, builtin_skew},
        {"rotation_operator", "rotation_operator(w, t, x)",
         "exp(-K t) x with K = w x, derived by the algebra layer from the minimal polynomial X^3 + |w|^2 X of K "
         "(Hermite interpolation, Thm II.2.3): x - sin(|w| t)/|w| w x x + (1 - cos(|w| t))/|w|^2 w x (w x x), "
         "the solution of x' + w x x = 0 (Rodrigues).",
         "(VI.1.13-15)", "vector w, x\nrotation_operator(w, t, x)", 3, 3, builtin_rotation_operator},
        {"F", "F(w, x)",
         "The rotation operator F_w(x) = R x of the thesis, R' = W R, R(0) = I (W y = w x y): the solution of "
         "y' = w x y with y(0) = x, so that F(-w, psi) is Q psi of the reduction r = F_(-w)(psi). In closed form "
         "for a constant w (Rodrigues), a fixed direction w = s(t) u (angle a(t) = |u| int_0^t s, an integral "
         "object when int s is not elementary) and a regular precession; for a turning w (x constant) a solution "
         "by reduction, evaluated by eval with R numeric (Magnus on SO(3)). x may depend on t where R is closed. "
         "Dual arguments (docs/rigid_body.md section 2): a constant dual twist w = w0 + eps v gives exp(t W) x, the "
         "dual Rodrigues formula (R' = W R by transference); a dual twist w(t) that turns gives the solution of the "
         "dual Poisson-Darboux problem y' = w x y, y(0) = x (x constant): closed for a fixed screw axis s(t) u^ and a "
         "regular screw precession, otherwise numeric (Magnus on SE(3)), evaluated by eval; a real w acts on each "
         "part of a dual x.",
         "(VI.2.9-12), (VI.3.118-119)", "vector u, x\nF((1 + sin(t))*u, x)", 2, 2, builtin_F},
        {"vector_series", "vector_series(e, w, n)",
         "The expansion of e in powers of the vector w up to total degree n (w -> eps w, a series in eps, "
         "eps = 1): the small-rotation approximations of the thesis, derived from the exact solution.",
         "(VI.1.51-55)", "vector w, g\nvector_series(sin(norm(w)*t)/norm(w)*(w x g), w, 3)",
         3, 3, builtin_vector_series},
        {"ode", "ode(equation, x(0) = x0, x'(0) = v0, ...)",
         "A linear Cauchy problem for x(t): the equation (x, x', x'' ... stand for the unknown and its "
         "derivatives in t) and one initial condition per order. x is a vector when an initial value is. "
         "The operator part must be a polynomial in one K = w x (terms c x, c w x x, c w x (w x x), "
         "c (w . x) w); the free part functions of t times constant vectors (or a literal [f1(t), f2(t), f3(t)]): "
         "quasi-polynomials in closed form, any other function finite for t >= 0 (a/(1 + t^2), exp(-t^2)) by its "
         "Duhamel integral int_0^t Y(t - tau) f(tau) dtau (VI.1.26-38 for every f), evaluated by quadrature; one "
         "singular at some t >= 0 (1/(t - 1)) is refused. Also the rotating-frame "
         "form m (r'' + 2 w x r' + w' x r + w x (w x r)) + g(|r|) r + F(t) = 0 with w(t) of fixed direction "
         "(closed form; F by integral objects) or turning, and a central field g(|r|) r "
         "(k r/|r|^3: Kepler; with F only for a constant g: psi'' + g/m psi = Q^T f, Thm VI.3.2.1 with a force) "
         "(the reduction of Thm VI.3.2.1). A second-order problem without r itself "
         "(m r'' = q (r' x B(t) + E)) is solved for v = r' and r = r(0) + int_0^t v (VI.2.50-52). The problem is "
         "checked when it is made.",
         "(VI.1.26), (VI.1.29), (VI.1.47), (VI.1.62), (VI.1.68)", "vector w, g, r0, v0\nP := ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)",
         2, any_number, builtin_ode},
        {"first_integrals", "first_integrals(P)",
         "The first integrals (Thm VI.2.2.3.3, VI.3.140-141) of a problem in a frame rotating about a fixed axis, "
         "m (r'' + 2 w x r' + w' x r + w x (w x r)) + k r = 0 with w = s(t) u (s constant or not): with "
         "p = r' + w x r, the list [energy (m |p|^2 + k |r|^2)/2, u . (r x p), |r x p|^2], in r and r'. For a "
         "turning w(t) or a central field g(|r|) r (Thm VI.3.2.2): [m (|p|^2/2 + V(|r|)) (V' = g |r|/m, when "
         "elementary), |r x p|^2]. Each is constant along every solution (derivative along the equation exactly 0). "
         "The vector invariants themselves: vector_first_integrals(P).",
         "(VI.3.140-141)", "vector u, r0, v0\nw := (1 + sin(t))*u\nfirst_integrals(ode(r'' + 2*w x r' + w' x r + w x (w x r) + "
         "4*r = 0, r(0) = r0, r'(0) = v0))", 1, 1, builtin_first_integrals},
        {"check", "check(P, s [, values])",
         "Substitutes s into the problem P made by ode(...): true when the residual of the equation and "
         "every initial difference are exactly 0 (vectors compared by components, see docs/vectors.md; with "
         "floating-point values, 0 up to rounding: at most 10^(5 - Digits) times the largest term, and said); "
         "otherwise prints what is not 0 and returns false. With values (as for eval), P is taken with the "
         "values put in: the check of a scene's solution solve(P, values). Integral objects in s are "
         "differentiated and merged over the same range before the zero test. A solution by reduction (VI.3) "
         "is not a closed form: refused, use verify.",
         "", "vector r0\ncheck(ode(r' = 0, r(0) = r0), r0)", 2, 3, builtin_check},
        {"model", "model(P, values)",
         "The smallest exact model of the scene (P made by ode(...), values as for eval): how each data "
         "vector relates to the operator K = w x (0, along w, perpendicular to w, general) and the algebra "
         "R[X]/(m_P) of its local minimal polynomial, the terms that vanish for the values, the scene's "
         "algebra (the lcm of the m_P), and the method with its reason; the report solve(P, values) prints, "
         "as a string, without solving.",
         "(II.1.23-24), (VI.1.12-15)", "vector w, g, r0, v0\nmodel(ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0), [w = [0, 0, 1], g = [0, 0, -10]])",
         2, 2, builtin_model},
        {"eval", "eval(e, values, t = T)",
         "Evaluates e (a scalar or vector expression, e.g. a solution) at the given values and time(s): "
         "values is a list of name = value (vectors as [x, y, z]; a value may use other values); T a "
         "number or a list of numbers (a time written as a decimal, 1e300, is that decimal number exactly). Returns a number or a list of components (a list of those for "
         "several times). Where the values make the closed form divide by zero (w = [0, 0, 0] in sin(|w| t)/|w|, "
         "a double root c^2 = 4 k, a resonance w0 = 2, also given as the float 2.0), the exact limit is taken "
         "as the values approach those given (along lines through the point from both sides, accepted where "
         "all agree and, with several values moving, proved through the one quantity that vanishes; "
         "docs/numeric.md); where it is not established (a pole, a limit that depends on the "
         "direction or on the curve of approach) eval names the denominator that vanishes and why, and proposes solve(P, values), the solution of that scene. Numbers in e and values are taken as the exact numbers they denote and the "
         "result is evaluated with as many digits as its proved error bound needs to be correct to double precision "
         "(no loss where the closed form cancels, e.g. (1 - cos(w t))/w^2 at w t = 1e-12 or 1e-300, or at long "
         "phases; where 2560 digits do not suffice, an error says so). Integral objects "
         "(int_0^t f dtau, nested ones too) are evaluated by quadrature on Chebyshev panels, to a few ulps of their scale, "
         "refused with the error estimate where it does not converge (docs/numeric.md). e may be a solution by reduction s "
         "(VI.3) or its derivative s': r or r' at the times (t >= 0), numerically (Q by Magnus on SO(3)).",
         "", "vector w, r0\ns := r0 + t*(w x r0)\neval(s, [w = [0, 0, 1], r0 = [1, 0, 0]], t = 2)",
         2, 3, builtin_eval},
        {"verify", "verify(P, s, values, T [, n [, stepper]])",
         "Compares the closed form s of the problem P with a numerical integration of P itself "
         "(Boost.Odeint, from P's own initial values) on [0, T] at n sample times (default 200): prints "
         "the largest relative difference (per component, relative to that component's largest value), "
         "where it occurs, and the time each method took; returns the largest relative difference. "
         "stepper: \"rkf78\" (default, controlled Runge-Kutta-Fehlberg 7(8)), \"bulirsch_stoer\", "
         "\"dopri5\"; tolerances 1e-12 absolute and relative. For a solution by reduction (VI.3) r and r' "
         "are compared (six components).",
         "", "vector r0\nverify(ode(r'' + 4*r = 0, r(0) = r0, r'(0) = 0), cos(2*t)*r0, [r0 = [1, 2, 3]], 10)",
         4, 6, builtin_verify},
        {"relative_motion", "relative_motion(mu, R0, V0, rho0, rho0', t = T)",
         "Exact relative orbital motion: a chaser seen from the LVLH frame (x radial, y along the track, z "
         "normal) of a target on a Keplerian orbit (R0, V0 inertial, gravitational parameter mu), starting at rho0 "
         "with relative velocity rho0' (LVLH components). The frame turns with w = |h|/|R|^2 about the orbit "
         "normal; undone as in Thm VI.3.2.1 the motion is the difference of two Kepler orbits (universal "
         "variables), any eccentricity, no linearization. Returns [rho, rho'] at T (a list of them for a list of "
         "times).",
         "(VI.3.132-138)", "relative_motion(398600.4418, [7000, 0, 0], [0, 7.546, 0], [0.1, 0, 0], [0, 0, 0], t = 600)",
         6, 6, builtin_relative_motion},
        {"clohessy_wiltshire", "clohessy_wiltshire(n, rho0, rho0', t = T)",
         "The Clohessy-Wiltshire solution: the relative motion linearized about a circular target orbit of mean "
         "motion n (LVLH components as for relative_motion), the first-order limit of the exact motion in the "
         "separation. Returns [rho, rho'] at T (a list of them for a list of times).",
         "", "clohessy_wiltshire(0.00108, [0.1, 0, 0], [0, 0, 0], t = 600)", 4, 4, builtin_clohessy_wiltshire},
        {"tschauner_hempel", "tschauner_hempel(mu, R0, V0, rho0, rho0', t = T)",
         "The linear model of the relative motion about an elliptic target orbit (Tschauner-Hempel): the LVLH "
         "equation linearized in rho, rho'' + 2 w x rho' + w' x rho + w x (w x rho) + (mu/|R|^3)(rho - 3 (rho . x) x) "
         "= 0, integrated with the target's orbit (Boost.Odeint rkf78 at 1e-13). Arguments and result as for "
         "relative_motion.",
         "", "tschauner_hempel(398600.4418, [7000, 0, 0], [0, 8.5, 1.2], [0.1, 0, 0], [0, 0, 0], t = 600)",
         6, 6, builtin_tschauner_hempel},
        {"yamanaka_ankersen", "yamanaka_ankersen(mu, R0, V0, rho0, rho0', t = T)",
         "The same linear model as tschauner_hempel in closed form (Yamanaka-Ankersen), derived from the "
         "Tschauner-Hempel equations in the true anomaly: x~ = rho x, solutions rho sin, rho cos, 2 - 3 e s J with "
         "J = k^2 t (mechanics/relative_motion.h); any eccentricity, no integration. Arguments and result as for "
         "relative_motion.",
         "", "yamanaka_ankersen(398600.4418, [7000, 0, 0], [0, 8.5, 1.2], [0.1, 0, 0], [0, 0, 0], t = 600)",
         6, 6, builtin_yamanaka_ankersen},
    });
    register_two_body_builtins(r);
}

}  // namespace symrep::lang
