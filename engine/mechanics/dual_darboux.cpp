// symrep/mechanics/dual_darboux.cpp -- the dual Poisson-Darboux problem: the readings of a
// twist and the closed forms by transference of the real ones (dual_darboux.h).
#include "symrep/mechanics/dual_darboux.h"

#include <algorithm>
#include <memory>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/residual_proof.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/numeric/reference.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

const ex& eps() { return dual::dual_unit(); }

bool is_zero_vector(const ex& v) { return v.is_zero() || equal(v, 0); }

// Q^ x^ for the constant twist v^ (s^ = 1, u^ = v^; a pure translation eps v' as s^ = eps, u = v').
ex constant_twist_motion(const ex& v, const ex& x, const ex& t) {
    const dual::dual_parts p = dual::parts(v);
    if (!is_zero_vector(p.primal)) return fixed_screw_motion(1, 0, v, x, t);
    if (!is_zero_vector(p.dual)) return fixed_screw_motion(0, 1, p.dual, x, t);
    return dual::reduce(x);
}

// Omega^ = (s + eps sigma) u^ with u^ constant: (s, sigma, u^) confirmed, or nothing.
std::optional<dual_twist_form> fixed_screw_axis(const ex& om, const ex& w, const ex& v, const ex& t) {
    dual_twist_form F;
    F.omega = om;
    F.form = dual_twist_form::kind::fixed_axis;
    if (!is_zero_vector(w) && !depends_on_time(om, t)) {  // a constant twist: s^ = 1, u^ = Omega^
        F.s = 1;
        F.sigma = 0;
        F.u = om;
        return F;
    }
    if (is_zero_vector(w)) {  // a pure translation eps v(t): v must keep its direction
        const auto d = fixed_direction(v, t);
        if (!d) return std::nullopt;
        F.s = 0;
        F.sigma = d->first;
        F.u = d->second;
    } else {
        const auto d = fixed_direction(w, t);
        if (!d) return std::nullopt;
        const ex& s = d->first;
        const ex& u = d->second;
        // v = sigma u + s u' with u' across u (a u' along u goes into sigma)
        const ex sigma = GiNaC::normal(dot(v, u) / dot(u, u));
        const ex across = canonical(v - sigma * u);
        ex u1 = 0;
        if (!is_zero_vector(across)) {
            const auto terms = terms_in_time(across, t);
            if (!terms) return std::nullopt;
            bool constant = true;
            for (const auto& [c, V] : *terms) {
                const ex r = GiNaC::normal(c / s);
                constant = constant && !r.has(t);
                u1 += r * V;
            }
            if (!constant) {  // (t V1 + V2)/(1 + t) with V1 = V2: the ratio at a t where s is not 0
                u1 = 0;
                ex at = 0;
                if (GiNaC::normal(s.subs(t == 0)).is_zero()) at = 1;
                if (GiNaC::normal(s.subs(t == at)).is_zero()) return std::nullopt;
                for (const auto& [c, V] : *terms) u1 += GiNaC::normal((c / s).subs(t == at)) * V;
            }
        }
        F.s = s;
        F.sigma = sigma;
        F.u = dual::make_dual(u, canonical(u1));
    }
    // confirmed: (s + eps sigma) u^ is Omega^
    if (!dual::dual_equal(dual::reduce((F.s + eps() * F.sigma) * F.u), om)) return std::nullopt;
    return F;
}

// The coefficients of 1, cos(c t), sin(c t), t cos(c t), t sin(c t) in a vector that is a sum of
// such terms times constant vectors; nothing otherwise. `secular`: t cos, t sin allowed.
struct trig_coefficients {
    ex one = 0, cos = 0, sin = 0, tcos = 0, tsin = 0;
};
std::optional<trig_coefficients> read_trig(const ex& w, const ex& c, const ex& t, bool secular) {
    trig_coefficients out;
    if (is_zero_vector(w)) return out;
    const auto terms = terms_in_time(w, t);
    if (!terms) return std::nullopt;
    const GiNaC::symbol X("X"), Y("Y");
    GiNaC::exmap trig;
    trig[GiNaC::cos(c * t)] = X;
    trig[GiNaC::sin(c * t)] = Y;
    trig[GiNaC::cos(-c * t)] = X;
    trig[GiNaC::sin(-c * t)] = -Y;
    for (const auto& [k, V] : *terms) {
        const ex e = GiNaC::expand(GiNaC::expand(k).subs(trig));
        if (e.degree(t) > (secular ? 1 : 0) || e.ldegree(t) < 0) return std::nullopt;
        const ex e0 = e.coeff(t, 0), e1 = e.coeff(t, 1);
        for (const ex& f : {e0, e1})
            if (f.has(t) || f.degree(X) > 1 || f.degree(Y) > 1 || f.coeff(X, 1).has(Y) || f.ldegree(X) < 0 ||
                f.ldegree(Y) < 0)
                return std::nullopt;
        if (!e1.subs(GiNaC::lst{X == 0, Y == 0}).is_zero()) return std::nullopt;  // t alone: no precession
        out.one += e0.subs(GiNaC::lst{X == 0, Y == 0}) * V;
        out.cos += e0.coeff(X, 1) * V;
        out.sin += e0.coeff(Y, 1) * V;
        out.tcos += e1.coeff(X, 1) * V;
        out.tsin += e1.coeff(Y, 1) * V;
    }
    return out;
}

// The frequency c: the first argument c t of a sin or cos in e.
ex frequency(const ex& e, const ex& t) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if ((is_ex_the_function(*it, GiNaC::sin) || is_ex_the_function(*it, GiNaC::cos)) && it->op(0).has(t))
            return GiNaC::normal(it->op(0) / t);
    return 0;
}

// Omega^ = c^ u1^ + A^(t) v^ (dual_darboux.h), confirmed, or nothing.
std::optional<dual_twist_form> screw_precession(const ex& om, const ex& w, const ex& v, const ex& t) {
    ex c = frequency(w, t);
    if (c.is_zero()) c = frequency(v, t);
    if (c.is_zero() || c.has(t)) return std::nullopt;
    const auto P = read_trig(w, c, t, false);
    const auto D = read_trig(v, c, t, true);
    if (!P || !D) return std::nullopt;
    // the dual part of cos(c^ t), sin(c^ t): c' t (S cos - C sin)
    ex c1 = 0;
    if (!is_zero_vector(D->tcos) || !is_zero_vector(D->tsin)) {
        if (!is_zero_vector(P->sin)) c1 = GiNaC::normal(dot(D->tcos, P->sin) / dot(P->sin, P->sin));
        else if (!is_zero_vector(P->cos)) c1 = GiNaC::normal(-dot(D->tsin, P->cos) / dot(P->cos, P->cos));
        else return std::nullopt;
    }
    const ex W0 = dual::make_dual(P->one, D->one), C = dual::make_dual(P->cos, D->cos),
             S = dual::make_dual(P->sin, D->sin), ch = dual::make_dual(c, c1);
    std::vector<ex> axes;  // u1^ x C^ = -S^: u1^ = -(C^ x S^)/|C^|^2, or along W0^ when C = 0
    if (!is_zero_vector(P->cos)) {
        axes.push_back(dual::reduce(-dual::dual_cross(C, S) / dual::dual_dot(C, C)));
    } else {
        if (is_zero_vector(P->one)) return std::nullopt;
        const ex n = dual::reduce(W0 / GiNaC::sqrt(dual::dual_dot(W0, W0)));
        axes = {n, dual::reduce(-n)};
    }
    for (const ex& u1 : axes) {
        dual_twist_form F;
        F.omega = om;
        F.form = dual_twist_form::kind::precession;
        F.u1 = u1;
        F.c = ch;
        F.v = dual::reduce(C + (dual::dual_dot(W0, u1) - ch) * u1);
        // confirmed: c^ u1^ + A^(t) v^ is Omega^ (A^ the screw by -c^ t about u1^)
        const dual::dual_parts cp = dual::parts(ch);
        const ex rebuilt = dual::reduce(ch * u1 + fixed_screw_motion(cp.primal, cp.dual, u1, F.v, t));
        if (dual::dual_equal(rebuilt, om)) return F;
    }
    return std::nullopt;
}

}  // namespace

dual_twist_form read_dual_twist(const ex& omega, const ex& t) {
    const ex om = dual::reduce(omega);
    const dual::dual_parts p = dual::parts(om);
    dual_twist_form F;
    F.omega = om;
    if (is_zero_vector(p.primal) && is_zero_vector(p.dual)) {
        F.form = dual_twist_form::kind::zero;
        return F;
    }
    if (auto A = fixed_screw_axis(om, p.primal, p.dual, t)) return *A;
    if (!is_zero_vector(p.primal))
        if (auto B = screw_precession(om, p.primal, p.dual, t)) return *B;
    return F;
}

ex fixed_screw_motion(const ex& s, const ex& sigma, const ex& u, const ex& x, const ex& t) {
    // VI.2.12 with dual data: a^ = |u^| int_0^t (s + eps sigma), Q^ x^ = closed_rotation
    turning_frame_form F;
    F.terms.w = u;  // not 0: the closed form of a fixed direction
    F.u = u;
    F.angle = GiNaC::sqrt(dual::dual_dot(u, u)) * (integral_in_t(s, t) + eps() * integral_in_t(sigma, t));
    return dual::reduce(*closed_rotation(F, x, t));
}

ex screw_precession_motion(const ex& u1, const ex& c, const ex& v, const ex& x, const ex& t) {
    // Q^ = A^(t) B^(t): B^ the constant twist v^, A^ the screw by -c^ t about u1^ (turning_frame.h)
    const dual::dual_parts cp = dual::parts(c);
    return fixed_screw_motion(cp.primal, cp.dual, u1, constant_twist_motion(v, x, t), t);
}

std::optional<ex> dual_darboux_motion(const dual_twist_form& F, const ex& x, const ex& t) {
    switch (F.form) {
        case dual_twist_form::kind::zero: return dual::reduce(x);
        case dual_twist_form::kind::fixed_axis: return fixed_screw_motion(F.s, F.sigma, F.u, x, t);
        case dual_twist_form::kind::precession: return screw_precession_motion(F.u1, F.c, F.v, x, t);
        case dual_twist_form::kind::general: break;
    }
    return std::nullopt;
}

namespace {

// A real vector expression proved 0 (integral objects, quasi-polynomial coefficients, components).
bool proved_zero(const ex& r, const ex& t) {
    if (r.is_zero()) return true;
    if (num::has_integral(r)) return integral_residual_zero(r);
    return quasi_polynomial_residual_zero(r, t) || equal(r, 0);
}

}  // namespace

bool dual_darboux_solves(const ex& omega, const ex& x0, const ex& x, const ex& t) {
    const dual::dual_parts r = dual::parts(diff_t(x, t) + dual::dual_cross(omega, x));
    if (!proved_zero(r.primal, t) || !proved_zero(r.dual, t)) return false;
    const dual::dual_parts i = dual::parts(x.subs(t == 0) - x0);
    return proved_zero(i.primal, t) && proved_zero(i.dual, t);
}

bool is_dual_problem(const cauchy_problem& P) {
    if (dual::has_dual_unit(P.expression)) return true;
    for (const ex& x : P.initial)
        if (dual::has_dual_unit(x)) return true;
    return false;
}

std::optional<dual_darboux_form> read_dual_darboux(const cauchy_problem& P, std::string* why) {
    if (!P.is_vector || P.order() != 1 || !is_dual_problem(P)) return std::nullopt;
    auto refuse = [&](const std::string& reason) -> std::optional<dual_darboux_form> {
        if (why) *why = reason;
        return std::nullopt;
    };
    std::string inner;
    const auto T = read_frame_terms(P, &inner);
    if (!T) return refuse(inner);
    if (!T->free.is_zero() || !T->g.is_zero())
        return refuse(T->form + "a dual problem is solved in the form m (" + P.unknown_name(1) + " + Omega x " +
                      P.name + ") = 0 only (the dual Poisson-Darboux problem), without the terms " +
                      to_string(canonical(T->g * P.unknowns[0] + T->free)));
    if (dual::primal(T->m).is_zero())
        return refuse("the leading coefficient " + to_string(T->m) + " of the dual problem is a zero divisor");
    dual_darboux_form F;
    F.twist = read_dual_twist(T->w, P.t);
    F.x0 = dual::reduce(P.initial[0]);
    return F;
}

ex solve_dual_darboux(const cauchy_problem& P, const dual_darboux_form& F) {
    if (const auto x = dual_darboux_motion(F.twist, F.x0, P.t)) return *x;
    throw closed_form_error("the dual Poisson-Darboux problem " + P.unknown_name(1) + " + Omega x " + P.name +
                            " = 0 with Omega = " + to_string(F.twist.omega) +
                            " has no closed form here: Omega is neither a fixed screw axis (s(t) u with a constant "
                            "dual u) nor a regular screw precession (docs/rigid_body.md section 3)");
}

std::pair<cauchy_problem, cauchy_problem> dual_darboux_parts(const cauchy_problem& P, const dual_darboux_form& F,
                                                             const ex& s) {
    const dual::dual_parts om = dual::parts(F.twist.omega), x0 = dual::parts(F.x0);
    const ex& x = P.unknowns[0];
    cauchy_problem A;
    A.name = P.name;
    A.t = P.t;
    A.unknowns = P.unknowns;
    A.is_vector = true;
    A.expression = P.unknowns[1] + cross(om.primal, x);
    A.initial = {x0.primal};
    cauchy_problem B = A;
    B.expression = P.unknowns[1] + cross(om.primal, x) + cross(om.dual, dual::primal(s));
    B.initial = {x0.dual};
    return {A, B};
}

namespace {

Eigen::Vector3d numbers(const ex& e, const std::string& what) {
    const ex v = numeric_vector_literal(e, what);
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
        try {
            out[i] = num::accurate_double(v.op(unsigned(i)));
        } catch (const domain_error&) {
            throw type_error(what + " does not evaluate to real numbers: " + to_string(GiNaC::evalf(v)) +
                             " (give every symbol a value)");
        }
    }
    return out;
}

}  // namespace

std::vector<num::twist> dual_darboux_states(const cauchy_problem& P, const value_map& put,
                                            const std::vector<double>& times, bool derivative) {
    if (!P.dual_darboux) throw error("dual_darboux_states: internal: not a dual Poisson-Darboux problem");
    const dual_darboux_form& F = *P.dual_darboux;
    const dual::dual_parts om = dual::parts(dual::reduce(put(F.twist.omega)));
    const dual::dual_parts x0 = dual::parts(dual::reduce(put(F.x0)));
    const ex w = numeric_vector_literal(om.primal, "the twist's primal part w(t)");
    const ex v = numeric_vector_literal(om.dual, "the twist's dual part v(t)");
    auto fw = std::make_shared<num::compiled_function>(num::compile(w, {P.t}));
    auto fv = std::make_shared<num::compiled_function>(num::compile(v, {P.t}));
    const num::twist_function xi = [fw, fv](double x) { return num::twist{fw->eval3(&x), fv->eval3(&x)}; };
    const num::twist a{numbers(x0.primal, P.name + "(0)"), numbers(x0.dual, "the dual part of " + P.name + "(0)")};
    num::se3_tensor_options o;
    o.max_steps = 5'000'000;  // about 10 s of work: t = 1e12 is refused with a reason, not run for hours
    for (std::size_t k = 0; k < times.size(); ++k)
        if (!(times[k] >= 0) || !std::isfinite(times[k]) || (k && times[k] < times[k - 1]))
            throw type_error("the dual problem is evaluated at sorted finite times t >= 0");
    const num::se3_tensor_result Q = num::se3_tensor(xi, times, o);
    std::vector<num::twist> out;
    out.reserve(times.size());
    for (std::size_t k = 0; k < times.size(); ++k) {
        const num::twist x = num::apply(Q.Q[k], a);  // x^ = Q^ x^0
        out.push_back(derivative ? -num::twist_cross(xi(times[k]), x) : x);  // x^' = -Omega^ x x^
    }
    return out;
}

std::shared_ptr<const cauchy_problem> dual_rotation_problem(const ex& w, const ex& x0, const ex& t) {
    // y' = w x y, i.e. y' + Omega^ x y = 0 with Omega^ = -w, y(0) = x0 (as rotation_problem)
    const auto P = rotation_statement(w, x0, t);
    std::string why;
    auto F = read_dual_darboux(*P, &why);
    if (!F) throw domain_error("F_w(x): " + (why.empty() ? "the dual w(t) = " + to_string(w) + " is not read" : why));
    P->dual_darboux = std::make_shared<const dual_darboux_form>(std::move(*F));
    return P;
}

}  // namespace symrep::mechanics
