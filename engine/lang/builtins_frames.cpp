// symrep/lang/builtins_frames.cpp -- motion seen from a frame that rotates and translates
// ([CS21] Thms 11-12; mechanics/moving_frame.h, docs/rigid_body.md section 4).
//
//   P0 := ode(x'' = g, x(0) = x0, x'(0) = u0)     the problem in the frozen inertial frame
//   P := moving_frame(P0, w, o)                    seen from the frame (w, origin path o(t))
//   s := solve(P)                                   r = R (psi - o)
//   check(P, s)                                     exact;  verify(P, s, values, T): numeric
#include "symrep/lang/builtins_frames.h"

#include <chrono>
#include <iomanip>

#include "symrep/numeric/reference.h"
#include "symrep/lang/interpreter.h"
#include "symrep/lang/values.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Vectors and mechanics";

ex frame_vector(const args_t& a, std::size_t i, const builtin& b, const char* what) {
    if (is_triple(a[i])) return as_literal(a[i]);
    const ex& e = arg_ex(a, i, b);
    if (!e.is_zero() && !is_vector(e))
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " (" + what + ") must be a vector, not " +
                         output::print_ex(e) + " (usage: " + b.signature + ")");
    return e;
}

value builtin_moving_frame(const builtin& b, const args_t& a, context&) {
    if (!a[0].is_problem())
        throw type_error(b.name + ": argument 1 must be the inertial problem made by ode(...), not " + a[0].a_kind() +
                         " (usage: " + b.signature + ")");
    const ex w = frame_vector(a, 1, b, "the frame's angular velocity w(t)");
    const ex o = a.size() > 2 ? frame_vector(a, 2, b, "the path o(t) of the frame's origin") : ex(0);
    try {
        return value(mechanics::moving_frame_problem(a[0].problem_pointer(), w, o));
    } catch (const domain_error& e) {
        const std::string m = e.what();
        throw domain_error(m.rfind("moving_frame", 0) == 0 ? m : b.name + ": " + m);
    }
}

}  // namespace

value check_moving_frame(const builtin& b, const mechanics::cauchy_problem& P, context& c) {
    zero_decision z;
    try {
        z = mechanics::prove_moving_frame(P, *mechanics::moving_frame_of(P));
    } catch (const domain_error& e) {
        throw domain_error(b.name + ": " + e.what());
    }
    if (z.is_zero == truth::unknown)
        throw domain_error(b.name + ": cannot decide whether the residual of " + P.name + " = R (psi - o) is R times "
                           "the inertial residual of psi (the zero test does not prove it, and no point was found "
                           "where it is not)");
    if (z.is_zero == truth::no) {
        c.out() << "check: the residual of " << P.name << " = R (psi - o) differs from R times the inertial "
                << "residual of psi " << witness_text(z) << "\n";
        return value(false);
    }
    c.out() << "check: exact for every psi: the residual of " << P.name << " = R (psi - o) is R times the inertial "
            << "residual of psi ([CS21] Thm 11), and the initial values are the inertial ones carried into the "
            << "frame; psi itself is the inertial problem's numeric solution\n";
    return value(true);
}

value verify_carried_frame(const builtin& b, const mechanics::cauchy_problem& P, const mechanics::moving_frame_form& F,
                           const num::sampled_function& solution, const data_values& d0, double T, std::size_t n,
                           const num::integration_options& opt, context& c) {
    const auto t0 = std::chrono::steady_clock::now();
    data_values d = d0;
    d.scalars.erase(P.t);
    const GiNaC::symbol& t = GiNaC::ex_to<GiNaC::symbol>(P.t);
    // the state: r (y0..y2), r' (y3..y5), R by rows (y6..y14); r'' = a solved from the equation
    std::vector<ex> state, acc;
    for (int i = 0; i < 15; ++i) state.push_back(GiNaC::symbol("y" + std::to_string(i)));
    for (int i = 0; i < 3; ++i) acc.push_back(GiNaC::symbol("a" + std::to_string(i)));
    GiNaC::matrix R(3, 3);
    for (unsigned i = 0; i < 9; ++i) R(i / 3, i % 3) = state[6 + i];
    const auto literal = [&](const ex& e, const std::string& what) {
        const ex v = put_values_limit(e.is_zero() ? vector_literal(0, 0, 0) : e, d);
        const ex l = GiNaC::is_a<GiNaC::matrix>(v) ? v : subs_components(v, {});
        if (!is_vector_literal(l))
            throw type_error(b.name + ": " + what + " is not a vector of numbers and t: " + output::print_ex(v));
        return l;
    };
    vmap with = d.vectors;
    with[P.unknowns[0]] = vector_literal(state[0], state[1], state[2]);
    with[P.unknowns[1]] = vector_literal(state[3], state[4], state[5]);
    with[P.unknowns[2]] = vector_literal(acc[0], acc[1], acc[2]);
    for (const auto& [sym, V] : F.carried)  // R_V -> R V(t)
        with[sym] = R.mul(GiNaC::ex_to<GiNaC::matrix>(literal(V, "the carried vector " + output::print_ex(V))));
    const ex E = put_values(subs_components(P.expression, with), d);
    GiNaC::lst eqs, unk;
    for (const ex& x : components(E)) eqs.append(GiNaC::expand(x) == 0);
    for (const ex& a : acc) unk.append(a);
    const ex sol = GiNaC::lsolve(eqs, unk);
    if (sol.nops() != 3)
        throw domain_error(b.name + ": the frame's equation cannot be solved for " + P.unknown_name(2));
    std::vector<ex> rhs{state[3], state[4], state[5]};
    for (std::size_t i = 0; i < 3; ++i) rhs.push_back(GiNaC::expand(sol.op(i).rhs()));
    // R' = -W R (VI.3.117)
    const ex w = literal(F.w, "the frame's w(t)");
    const GiNaC::matrix W(3, 3, GiNaC::lst{0, -w.op(2), w.op(1), w.op(2), 0, -w.op(0), -w.op(1), w.op(0), 0});
    const GiNaC::matrix dR = W.mul_scalar(-1).mul(R);
    for (unsigned i = 0; i < 9; ++i) rhs.push_back(GiNaC::expand(dR(i / 3, i % 3)));
    std::vector<double> initial;
    for (std::size_t m = 0; m < 2; ++m) {
        const ex x0 = literal(P.initial[m], P.unknown_name(m) + "(0)");
        for (unsigned i = 0; i < 3; ++i) initial.push_back(to_double(x0.op(i), b, P.unknown_name(m) + "(0)"));
    }
    for (int i = 0; i < 9; ++i) initial.push_back(i % 4 == 0 ? 1.0 : 0.0);
    num::symbolic_system sys(rhs, t, state, {});
    const double prep = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const num::verify_result v = num::verify(solution, 6, sys.function(), initial, 0.0, T, n, opt);
    static const char* axes[] = {"x", "y", "z", "x'", "y'", "z'"};
    c.out() << "verify: max relative difference " << std::setprecision(3) << v.max_relative_difference
            << " (component " << axes[v.component_of_max] << " of " << P.name << (v.component_of_max < 3 ? "" : "'")
            << ", t = " << std::setprecision(6) << v.time_of_max << ") over " << v.n_points << " points in [0, " << T
            << "]; reduction (Magnus on SO(3)) against the frame's equation with R' = -W R integrated beside it, "
            << num::stepper_name(opt.stepper) << " (" << v.rhs_evaluations << " right-hand sides), setup "
            << std::setprecision(3) << prep << " s\n";
    return value(ex(num::from_double(v.max_relative_difference)));
}

void register_frames_builtins(registry& r) {
    add_builtins(
        r, section,
        {
            {"moving_frame", "moving_frame(P, w, o)",
             "The problem P, stated in an inertial frame (ode(x'' = ..., x(0) = X0, x'(0) = V0): gravity, a charge "
             "in E and B, Kepler about the origin ...), seen from a frame that turns with the angular velocity w(t) "
             "(its components in the frame) and whose origin moves along o(t) (a path in the inertial frame, which "
             "is the frame frozen at t = 0; o may be left out: 0). The result is the problem in the frame, "
             "m (r'' + 2 w x r' + w' x r + w x (w x r) + A) = R F, A = R o'' the origin's acceleration seen in the "
             "frame, r(0) = X0 - o(0), r'(0) = V0 - o'(0) - w(0) x r(0); solve gives r = R (psi - o), psi the "
             "inertial solution and R' = -W R: in closed form for a constant w, a fixed direction and a regular "
             "precession when psi is (a reduction object, evaluated by eval and verify, for Kepler). check(P, s) "
             "proves it, verify(P, s, values, T) integrates the frame's equation. For a w(t) that turns otherwise "
             "(R numeric) each R V the equation needs (a constant vector of P, the origin's path and its "
             "derivatives) is written as a vector function of its own (R_g, R_V1, R_o, R_do, R_ddo); solve gives "
             "the reduction object with R by Magnus on SO(3), verify integrates the equation with R beside it.",
             "[CS21] Thms 11-12; (VI.3.117, VI.3.132)",
             "vector g, x0, u0\nP := moving_frame(ode(x'' = g, x(0) = x0, x'(0) = u0), [0, 0, 1], [t^2, 0, 0])\n"
             "s := solve(P)\ncheck(P, s)",
             2, 3, builtin_moving_frame},
        });
}

}  // namespace symrep::lang
