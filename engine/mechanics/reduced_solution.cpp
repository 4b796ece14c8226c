// symrep/mechanics/reduced_solution.cpp -- numeric evaluation of r = F_(-w)(psi)
// (reduced_solution.h; thesis VI.3.2.1).
#include "symrep/mechanics/reduced_solution.h"

#include <cmath>

#include "symrep/core/error.h"
#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/integrate.h"
#include "symrep/numeric/reference.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

ex numeric_vector_literal(const ex& e, const std::string& what) {
    if (e.is_zero()) return vector_literal(0, 0, 0);
    ex v;
    try {
        v = subs_components(e, {});
    } catch (const type_error&) {
        throw type_error(what + " is not a vector of numbers: " + to_string(e) + " (give every vector a value)");
    }
    if (!is_vector_literal(v)) throw type_error(what + " is not a vector of numbers: " + to_string(e));
    return v;
}

namespace {

double number(const ex& e, const std::string& what) {
    try {
        return num::accurate_double(e);
    } catch (const domain_error&) {
        throw type_error(what + " does not evaluate to a real number: " + to_string(GiNaC::evalf(e)) +
                         " (give every symbol a value)");
    }
}

ex literal(const ex& e, const std::string& what) { return numeric_vector_literal(e, what); }

Eigen::Vector3d vector_number(const ex& e0, const std::string& what) {
    const ex e = literal(e0, what);
    return {number(e.op(0), what), number(e.op(1), what), number(e.op(2), what)};
}

// A vector function of t, compiled once (w, w').
num::angular_velocity vector_of_t(const ex& e0, const ex& t, const std::string& what) {
    if (e0.is_zero()) return [](double) { return Eigen::Vector3d::Zero(); };
    const ex e = literal(e0, what);
    auto f = std::make_shared<num::compiled_function>(num::compile(e, {t}));
    return [f, what](double x) {
        const Eigen::Vector3d v = f->eval3(&x);
        if (!v.allFinite())
            throw domain_error(what + " has no finite value at t = " + std::to_string(x));
        return v;
    };
}

std::function<double(double)> scalar_of(const ex& e, const ex& x) {
    auto f = std::make_shared<num::compiled_function>(num::compile(e, {x}));
    return [f](double v) {
        double out;
        f->eval(&v, &out);
        return out;
    };
}

// (Thm VI.3.2.1 with a free term F(t)) the part of psi that F drives, psi_F = -int_0^t G(t - tau)
// Q^T(tau) F(tau)/m dtau: psi_F'' + k psi_F = -Q^T F/m (order 1: psi_F' + k psi_F = -Q^T F/m),
// psi_F = psi_F' = 0 at t = 0, integrated with Q^T ((Q^T)' = Q^T W, Q^T(0) = I: Q' = -W Q)
// by Boost.Odeint (rkf78, 1e-13); r gets Q psi_F and r' gets Q psi_F' - w x (Q psi_F).
void add_forced_part(const reduced_solution& s, const value_map& put, const rotating_frame_problem& R,
                     const std::vector<double>& times, std::vector<rotating_frame_state>& out) {
    const cauchy_problem& P = *s.problem;
    const turning_frame_form& F = s.form();
    const ex& t = P.t;
    const num::angular_velocity force = vector_of_t(put(F.terms.free), t, "the free term F(t)");
    const double m = number(put(F.terms.m), "the coefficient m");
    const double k = number(put(P.order() == 1 ? F.k : GiNaC::normal(F.terms.g / F.terms.m)), "the constant k");
    const std::size_t M = P.order();
    const num::rhs_function rhs = [&](double x, const double* y, double* dy) {
        Eigen::Matrix3d Qt;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) Qt(i, j) = y[3 * i + j];
        const Eigen::Vector3d w = R.w(x), psi(y[9], y[10], y[11]);
        Eigen::Matrix3d W;
        W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
        const Eigen::Matrix3d dQt = Qt * W;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) dy[3 * i + j] = dQt(i, j);
        const Eigen::Vector3d a = -k * psi - Qt * force(x) / m;
        for (int i = 0; i < 3; ++i) {
            if (M == 1) {
                dy[9 + i] = a[i];
            } else {
                dy[9 + i] = y[12 + i];
                dy[12 + i] = a[i];
            }
        }
    };
    std::vector<double> y0(M == 1 ? 12 : 15, 0.0);
    y0[0] = y0[4] = y0[8] = 1;
    std::vector<double> distinct;
    for (const double x : times)
        if (distinct.empty() || x > distinct.back()) distinct.push_back(x);
    num::integration_options o;
    o.abs_tol = o.rel_tol = 1e-13;
    const num::integration_result res = num::integrate(rhs, 0.0, y0, distinct, o);
    std::size_t j = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        while (distinct[j] < times[i]) ++j;
        const Eigen::VectorXd y = res.state(j);
        Eigen::Matrix3d Qt;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) Qt(a, b) = y[3 * a + b];
        const Eigen::Vector3d psi(y[9], y[10], y[11]);
        const Eigen::Vector3d dpsi = M == 1 ? Eigen::Vector3d(-k * psi - Qt * force(times[i]) / m)
                                            : Eigen::Vector3d(y[12], y[13], y[14]);
        const Eigen::Vector3d r = Qt.transpose() * psi;
        out[i].r += r;
        out[i].v += Qt.transpose() * dpsi - R.w(times[i]).cross(r);
    }
}

}  // namespace

std::string reduced_solution::to_string() const {
    std::string s;
    const auto frame = moving_frame_of(*problem);
    if (frame && !frame->carried.empty()) {  // ([CS21] Thm 12) a turning frame that carries vectors
        s = problem->name + " = R (psi - o), R' = -W R, R(0) = I, w(t) = " + symrep::to_string(frame->w) +
            "   ([CS21] Thm 12; numeric: Magnus on SO(3))\n  psi: the solution of the inertial problem " +
            symrep::to_string(frame->inertial->expression) + " = 0";
        if (!frame->o.is_zero()) s += "\n  o(t) = " + symrep::to_string(frame->o);
        std::string names;
        for (const auto& [sym, v] : frame->carried)
            names += (names.empty() ? "" : ", ") + symrep::to_string(sym) + " = R " + symrep::to_string(v);
        s += "\n  the frame's equation holds " + names;
    } else if (problem->dual_darboux) {  // (issue 31 item 3) a twist without a closed form
        // the twist (F: w = -Omega) as one literal where it has components
        ex omega = rotation_operator ? -problem->dual_darboux->twist.omega : problem->dual_darboux->twist.omega;
        if (vector_symbols(omega).empty() && !is_vector_literal(omega)) omega = subs_components(omega, {});
        const std::string x0 = symrep::to_string(problem->dual_darboux->x0);
        if (rotation_operator)  // F_w(x0) over a dual w(t): Omega^ = -w
            s = "F_w(" + x0 + ") = R^ " + x0 + ", R^' = W R^, R^(0) = I, W x = w x x, w(t) = " +
                symrep::to_string(omega);
        else
            s = problem->name + " = Q^ " + x0 + ", Q^' = -Omega Q^, Q^(0) = I, Omega = " + symrep::to_string(omega);
        s += "   (docs/rigid_body.md section 3; numeric: Magnus on SE(3))";
    } else if (rotation_operator) {  // (VI.3.118-119) y = F_w(x0) = R x0 with w = -(the problem's w)
        s = "F_w(" + symrep::to_string(problem->initial[0]) + ") = R " + symrep::to_string(problem->initial[0]) +
            ", R' = W R, R(0) = I, W x = w x x, w(t) = " + symrep::to_string(-form().terms.w) +
            "   (VI.3.118-119; numeric: Magnus on SO(3))";
    } else {
        s = describe_reduction(*problem, form());
    }
    if (const ex origin = moving_frame_origin(*problem); !origin.is_zero())
        s += "\n  seen from the frame whose origin moves along o(t) = " + symrep::to_string(origin) + ": " +
             problem->name + " = Q (psi - o)   ([CS21] Thm 12)";
    std::vector<std::string> given;
    for (const auto& [k, v] : values.vectors) given.push_back(symrep::to_string(k) + " = " + symrep::to_string(v));
    for (const auto& [k, v] : values.scalars) given.push_back(symrep::to_string(k) + " = " + symrep::to_string(v));
    for (std::size_t i = 0; i < given.size(); ++i) s += (i ? ", " : "\n  with ") + given[i];
    return s;
}

rotating_frame_problem numeric_problem(const reduced_solution& s, const value_map& put) {
    const cauchy_problem& P = *s.problem;
    const turning_frame_form& F = s.form();
    const ex& t = P.t;
    rotating_frame_problem R;
    // w' from w with its values in (a declared w(t) gets its value as a function of t)
    const ex wv = F.terms.w.is_zero() ? ex(0) : literal(put(F.terms.w), "w(t)");
    R.w = vector_of_t(wv, t, "w(t)");
    R.w_dot = vector_of_t(wv.is_zero() ? wv : wv.diff(GiNaC::ex_to<GiNaC::symbol>(t)), t, "w'(t)");
    R.r0 = vector_number(put(P.initial[0]), P.name + "(0)");
    if (P.order() == 2) R.v0 = vector_number(put(P.initial[1]), P.unknown_name(1) + "(0)");
    if (F.precessing) {  // Q = A(t) B(t): exp(-c t K_u1) exp(-t K_v)
        const Eigen::Vector3d u1 = vector_number(put(F.precessing->u1), "the axis u1");
        const Eigen::Vector3d v = vector_number(put(F.precessing->v), "the spin v");
        const double c = number(put(F.precessing->c), "the precession rate");
        R.rotation = [u1, v, c](double x) { return Eigen::Matrix3d(num::rotation_exp(-c * x * u1) * num::rotation_exp(-x * v)); };
    } else if (F.terms.w.is_zero()) {  // Q = I
        R.axis = Eigen::Vector3d(0, 0, 1);
        R.angle = [](double) { return 0.0; };
    } else if (F.u) {
        const Eigen::Vector3d u = vector_number(put(*F.u), "the axis " + to_string(*F.u));
        if (u.norm() > 0) {
            R.axis = u.normalized();
            if (F.angle) R.angle = scalar_of(put(*F.angle), t);
        }
    }
    if (P.order() == 1) return R;
    // the field: f = 0, c p (harmonic), mu/p^2 (Kepler, mu > 0), or any f(p)
    const ex& p = F.terms.p;
    const ex f = put(F.f);
    if (f.has(t)) throw domain_error("the central field " + to_string(f) + " depends on t");
    const ex lin = GiNaC::normal(f / p), inv2 = GiNaC::normal(f * p * p);
    if (f.is_zero()) {
        R.field = central_field::none();
    } else if (!lin.has(p)) {
        R.field = central_field::harmonic(number(lin, "the field's constant"));
    } else if (!inv2.has(p) && number(inv2, "Kepler's constant mu") > 0) {
        R.field = central_field::kepler(number(inv2, "Kepler's constant mu"));
    } else {
        R.field = central_field::general(scalar_of(f, p), F.potential ? scalar_of(put(*F.potential), p)
                                                                       : std::function<double(double)>());
    }
    const double rho0 = R.r0.norm();
    if (R.field.type != central_field::kind::free && R.field.type != central_field::kind::harmonic &&
        (rho0 == 0 || !std::isfinite(R.field.force(rho0))))
        throw domain_error("the central field " + to_string(F.f.subs(p == norm(P.unknowns[0]))) + " is singular at " +
                           P.name + "(0) (|" + P.name + "(0)| = " + std::to_string(rho0) + ")");
    return R;
}

std::vector<rotating_frame_state> evaluate(const reduced_solution& s, const value_map& put,
                                           const std::vector<double>& times) {
    const cauchy_problem& P = *s.problem;
    if (const auto frame = moving_frame_of(P); frame && !frame->carried.empty())
        return carried_frame_states(*frame, put, times);  // ([CS21] Thm 12) r = Q (psi - o)
    const rotating_frame_problem R = numeric_problem(s, put);
    // a bound on the Magnus steps (about 10 s), so that t = 1e12 is refused with a reason
    // instead of running for hours
    num::rotation_tensor_options o;
    o.max_steps = 5'000'000;
    if (P.order() == 2) {
        std::vector<rotating_frame_state> out;
        if (const ex origin = moving_frame_origin(P); origin.is_zero()) {
            out = solve_by_reduction(R, times, o);
        } else {  // ([CS21] Thm 12) r = Q (psi - o)
            const ex ov = literal(put(origin), "the origin's path o(t)");
            out = moving_frame_states({R, vector_of_t(ov, P.t, "o(t)"),
                                       vector_of_t(ov.diff(GiNaC::ex_to<GiNaC::symbol>(P.t)), P.t, "o'(t)")},
                                      times, o);
        }
        if (!s.form().terms.free.is_zero()) add_forced_part(s, put, R, times, out);
        return out;
    }
    // order 1: x = Q psi, psi = exp(-k t) x0, x' = Q psi' - w x x
    const double k = number(put(s.form().k), "the constant k");
    std::vector<Eigen::Matrix3d> Q;
    if (R.rotation) {
        for (const double t : times) Q.push_back(R.rotation(t));
    } else if (R.axis && R.angle) {
        for (const double t : times) Q.push_back(num::fixed_direction_rotation(*R.axis, R.angle(t)));
    } else {
        Q = num::rotation_tensor(R.w, times, o).Q;
    }
    std::vector<rotating_frame_state> out;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const Eigen::Vector3d psi = std::exp(-k * times[i]) * R.r0;
        const Eigen::Vector3d x = Q[i] * psi;
        out.push_back({x, Q[i] * (-k * psi) - R.w(times[i]).cross(x)});
    }
    if (!s.form().terms.free.is_zero()) add_forced_part(s, put, R, times, out);
    return out;
}

}  // namespace symrep::mechanics
