// symrep/mechanics/reduced_solution.cpp -- numeric evaluation of r = F_(-w)(psi)
// (reduced_solution.h; thesis VI.3.2.1).
#include "mechanics/reduced_solution.h"

#include <cmath>

#include "core/error.h"
#include "numeric/evaluator.h"
#include "numeric/reference.h"
#include "vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

double number(const ex& e, const std::string& what) {
    try {
        return num::accurate_double(e);
    } catch (const domain_error&) {
        throw type_error(what + " does not evaluate to a real number: " + to_string(GiNaC::evalf(e)) +
                         " (give every symbol a value)");
    }
}

// A vector expression without vector symbols as one literal [x, y, z].
ex literal(const ex& e, const std::string& what) {
    if (e.is_zero()) return vector_literal(0, 0, 0);
    try {
        return subs_components(e, {});
    } catch (const type_error&) {
        throw type_error(what + " is not a vector of numbers: " + to_string(e) + " (give every vector a value)");
    }
}

Eigen::Vector3d vector_number(const ex& e0, const std::string& what) {
    const ex e = literal(e0, what);
    if (!is_vector_literal(e)) throw type_error(what + " is not a vector of numbers: " + to_string(e));
    return {number(e.op(0), what), number(e.op(1), what), number(e.op(2), what)};
}

// A vector function of t, compiled once (w, w').
num::angular_velocity vector_of_t(const ex& e0, const ex& t, const std::string& what) {
    if (e0.is_zero()) return [](double) { return Eigen::Vector3d::Zero(); };
    const ex e = literal(e0, what);
    if (!is_vector_literal(e)) throw type_error(what + " is not a vector of numbers: " + to_string(e));
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

}  // namespace

std::string reduced_solution::to_string() const {
    std::string s;
    if (rotation_operator)  // (VI.3.118-119) y = F_w(x0) = R x0 with w = -(the problem's w)
        s = "F_w(" + symrep::to_string(problem->initial[0]) + ") = R " + symrep::to_string(problem->initial[0]) +
            ", R' = W R, R(0) = I, W x = w x x, w(t) = " + symrep::to_string(-form().terms.w) +
            "   (VI.3.118-119; numeric: Magnus on SO(3))";
    else
        s = describe_reduction(*problem, form());
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
    const rotating_frame_problem R = numeric_problem(s, put);
    // a bound on the Magnus steps (about 10 s), so that t = 1e12 is refused with a reason
    // instead of running for hours
    num::rotation_tensor_options o;
    o.max_steps = 5'000'000;
    if (P.order() == 2) return solve_by_reduction(R, times, o);
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
    return out;
}

}  // namespace symrep::mechanics
