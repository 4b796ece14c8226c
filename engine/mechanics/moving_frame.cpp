// symrep/mechanics/moving_frame.cpp -- motion seen from a frame that rotates and translates
// ([CS21] Thms 11-12; moving_frame.h): the inertial problem carried into the frame by the frame's
// rigid motion (R, d = -R o), and its solution r = R (psi - o).
#include "symrep/mechanics/moving_frame.h"

#include <cmath>
#include <algorithm>
#include <mutex>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/mechanics/reduced_solution.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/rotation_tensor.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

// A vector without vector symbols as one literal [x, y, z]; otherwise its canonical form.
ex tidy(const ex& v) {
    if (v.is_zero()) return v;
    if (vector_symbols(v).empty()) return subs_components(v, {});
    return canonical(v);
}

ex at_zero(const ex& v, const ex& t) { return tidy(v.subs(t == 0)); }

// L[x] = x'' + 2 w x x' + w' x x + w x (w x x) (VI.3.132) of a vector function x of t given by
// its value x and derivatives x1, x2.
ex frame_operator(const ex& w, const ex& dw, const ex& x, const ex& x1, const ex& x2) {
    return x2 + 2 * cross(w, x1) + cross(dw, x) + cross(w, cross(w, x));
}

// E0 with its unknowns X, X', X'' replaced by `unknowns` and every other vector (a vector symbol
// or literal: a constant vector, or a declared vector function of t) by R V, in one pass that does
// not enter what it put in. `rotate` gives R V; nothing (R not closed) is an error naming V.
ex carried(const ex& E0, const std::vector<ex>& X, const std::vector<ex>& unknowns,
           const std::function<std::optional<ex>(const ex&)>& rotate) {
    struct carry : GiNaC::map_function {
        const std::vector<ex>* X;
        const std::vector<ex>* Y;
        const std::function<std::optional<ex>(const ex&)>* rotate;
        ex operator()(const ex& e) override {
            for (std::size_t m = 0; m < X->size(); ++m)
                if (e.is_equal((*X)[m])) return (*Y)[m];
            if (is_vector_symbol(e) || is_vector_literal(e)) {
                const auto r = (*rotate)(e);
                if (!r)
                    throw domain_error("the frame turns with a w(t) whose rotation R(t) has no closed form, and the "
                                       "inertial problem holds the vector " + to_string(e) +
                                       ", which the frame sees as R(t) " + to_string(e) + ": the equation in the frame "
                                       "cannot be written (state the problem in the frame, or use the numeric "
                                       "moving_frame_states)");
                return *r;
            }
            return e.map(*this);
        }
    } c;
    c.X = &X;
    c.Y = &unknowns;
    c.rotate = &rotate;
    return c(E0);
}

// The registry of moving_frame_of() and moving_frame_origin(): each entry is keyed weakly by its
// problem object and dropped once that object is gone (pruned on every registration).
struct frame_entry {
    std::weak_ptr<const cauchy_problem> problem;
    std::shared_ptr<const moving_frame_form> frame;  ///< for the problem in the frame
    ex origin;                                       ///< for the rotating problem y = Q psi
};
std::mutex frame_registry_mutex;
std::vector<frame_entry>& frame_registry() {
    static std::vector<frame_entry> r;
    return r;
}
void register_frame_entry(frame_entry e) {
    const std::lock_guard<std::mutex> lock(frame_registry_mutex);
    auto& r = frame_registry();
    r.erase(std::remove_if(r.begin(), r.end(), [](const frame_entry& x) { return x.problem.expired(); }), r.end());
    r.push_back(std::move(e));
}
std::optional<frame_entry> find_frame_entry(const cauchy_problem& P) {
    const std::lock_guard<std::mutex> lock(frame_registry_mutex);
    for (const frame_entry& e : frame_registry())
        if (const auto p = e.problem.lock(); p && p.get() == &P) return e;
    return std::nullopt;
}

}  // namespace

std::shared_ptr<const moving_frame_form> moving_frame_of(const cauchy_problem& P) {
    const auto e = find_frame_entry(P);
    return e ? e->frame : nullptr;
}

ex moving_frame_origin(const cauchy_problem& P) {
    const auto e = find_frame_entry(P);
    return e ? e->origin : ex(0);
}

std::optional<ex> frame_rotation(const ex& w, const ex& x, const ex& t) {
    if (w.is_zero() || x.is_zero()) return x;
    turning_frame_form F;  // Q of F.terms.w: Q' = -W Q, Q(0) = I (turning_frame.h)
    F.terms.w = w;
    if (const auto fd = fixed_direction(w, t)) {
        F.u = fd->second;
        F.angle = rotation_angle(fd->first, fd->second, t, true);
    } else {
        F.precessing = regular_precession(w, t);
    }
    return closed_rotation(F, x, t);
}

bool inertial_is_numeric(const moving_frame_form& F) {
    const cauchy_problem& P0 = *F.inertial;
    return !P0.reduced && !P0.fixed_axis && !P0.velocity && P0.turning && !closed_solution(P0, *P0.turning);
}

std::shared_ptr<const cauchy_problem> moving_frame_problem(const std::shared_ptr<const cauchy_problem>& P0p,
                                                           const ex& w0, const ex& o0) {
    const cauchy_problem& P0 = *P0p;
    if (!P0.is_vector || P0.order() != 2)
        throw domain_error("moving_frame: the inertial problem must be of the second order in a vector (the law of "
                           "motion X'' = ...), not " + std::string(P0.is_vector ? "of order " + std::to_string(P0.order())
                                                                               : "a scalar one"));
    const ex& t = P0.t;
    const ex& w = w0;
    const ex& o = o0;
    if (!w.is_zero() && !is_vector(w))
        throw domain_error("moving_frame: the angular velocity w must be a vector, not " + to_string(w));
    if (!o.is_zero() && !is_vector(o))
        throw domain_error("moving_frame: the origin's path o must be a vector, not " + to_string(o));
    if (!w.is_zero()) require_value_at_zero(w, t, "moving_frame: the angular velocity w(t)");
    if (!o.is_zero()) {
        require_value_at_zero(o, t, "moving_frame: the origin's path o(t)");
        require_value_at_zero(diff_t(o, t), t, "moving_frame: the origin's velocity o'(t)");
    }
    for (const ex& x : vector_symbols(w))
        if (x.is_equal(P0.unknowns[0]) || x.is_equal(P0.unknowns[1]))
            throw domain_error("moving_frame: the frame's w depends on the unknown " + P0.name);
    for (const ex& x : vector_symbols(o))
        if (x.is_equal(P0.unknowns[0]) || x.is_equal(P0.unknowns[1]))
            throw domain_error("moving_frame: the origin's path depends on the unknown " + P0.name);

    auto F = std::make_shared<moving_frame_form>();
    F->w = w;
    F->o = o;
    F->inertial = P0p;
    const ex dw = w.is_zero() ? ex(0) : diff_t(w, t);
    const auto strict = [&](const ex& V) { return frame_rotation(w, V, t); };
    // R closed (a constant w, a fixed direction, a regular precession), or each R V the frame's
    // equation needs a vector function of its own (moving_frame_form::carried)
    const bool closed_R = w.is_zero() || frame_rotation(w, vector_literal(1, 0, 0), t).has_value();
    std::vector<std::pair<ex, ex>> carried_list;
    const auto carried_symbol = [&](const ex& V, const std::string& name) -> ex {
        if (V.is_zero() || (is_vector_literal(V) && equal(V, 0))) return 0;
        for (const auto& [sym, v] : carried_list)
            if (v.is_equal(V)) return sym;
        const ex sym = GiNaC::realsymbol(name);
        register_vector_function(sym, t);
        carried_list.push_back({sym, V});
        return sym;
    };
    const auto rotate = [&](const ex& V) -> std::optional<ex> {
        if (closed_R) return strict(V);
        if (is_vector_symbol(V)) return carried_symbol(V, "R_" + to_string(V));
        std::size_t literals = 1;  // R_V1, R_V2, ... for the literals, in the order met
        for (const auto& [sym, v] : carried_list) literals += to_string(sym).rfind("R_V", 0) == 0;
        return carried_symbol(V, "R_V" + std::to_string(literals));
    };

    // d = -R o: where the frame sees the inertial origin (the attracting centre)
    if (!o.is_zero()) F->d = -*(closed_R ? strict(o) : std::optional<ex>(carried_symbol(o, "R_o")));
    const ex& X = P0.unknowns[0];
    const ex &X1 = P0.unknowns[1], &X2 = P0.unknowns[2];

    // y = R psi: the inertial problem seen from the frame turning about the inertial origin (VI.3.132)
    {
        auto Pr = std::make_shared<cauchy_problem>();
        Pr->name = P0.name;
        Pr->t = t;
        Pr->unknowns = P0.unknowns;
        Pr->is_vector = true;
        const ex y = X, y1 = X1, y2 = X2;
        try {
            Pr->expression = carried(P0.expression, {X, X1, X2},
                                     {y, y1 + cross(w, y), frame_operator(w, dw, y, y1, y2)}, strict);
            const ex w00 = w.is_zero() ? ex(0) : at_zero(w, t);
            Pr->initial = {P0.initial[0], tidy(P0.initial[1] - cross(w00, P0.initial[0]))};
            read_problem(*Pr);
            F->rotating = Pr;
        } catch (const error&) {
            // a constant vector under a turning w: no reduction object (the frame's problem refuses too)
        }
    }

    // the problem in the frame (Thm 11), with r - d = r + R o (R' = -W R):
    //   X -> r + R o,  X' -> r' + w x r + R o',  X'' -> L[r] + A,  A = R o''
    cauchy_problem P;
    P.name = P0.name;
    P.t = t;
    P.unknowns = P0.unknowns;
    P.is_vector = true;
    const ex& r = X;
    const ex &r1 = X1, &r2 = X2;
    ex Ro, Ro1, A;
    if (!o.is_zero()) {
        const ex o1 = diff_t(o, t), o2 = diff_t(o1, t);
        Ro = -F->d;
        Ro1 = closed_R ? *strict(o1) : carried_symbol(o1, "R_do");
        A = closed_R ? *strict(o2) : carried_symbol(o2, "R_ddo");
    }
    P.expression = carried(P0.expression, {X, X1, X2},
                           {r + Ro, r1 + cross(w, r) + Ro1, frame_operator(w, dw, r, r1, r2) + A}, rotate);
    const ex r00 = tidy(P0.initial[0] - (o.is_zero() ? ex(0) : at_zero(o, t)));
    const ex v00 = tidy(P0.initial[1] - (o.is_zero() ? ex(0) : at_zero(diff_t(o, t), t)) -
                        (w.is_zero() ? ex(0) : cross(at_zero(w, t), r00)));
    P.initial = {r00, v00};
    F->carried = carried_list;
    auto Pp = std::make_shared<const cauchy_problem>(std::move(P));
    if (F->rotating && !o.is_zero()) register_frame_entry({F->rotating, nullptr, o});
    register_frame_entry({Pp, F, 0});
    return Pp;
}

zero_decision prove_moving_frame(const cauchy_problem& P, const moving_frame_form& F) {
    const ex& t = P.t;
    const ex p = GiNaC::realsymbol("psi");  // an arbitrary vector function of t (its own symbol)
    register_vector_function(p, t);
    const ex p1 = derivative(p), p2 = derivative(p1);
    const ex& w = F.w;
    const auto R = [&](const ex& x) {
        const auto y = frame_rotation(w, x, t);
        if (!y)
            throw domain_error("the rotation R(t) of the frame, R' = -W R with w(t) = " + to_string(w) +
                               ", has no closed form: r = R (psi - o) solves the frame's equation for every R with "
                               "R' = -W R and every psi ([CS21] Thm 11, proved once for all in "
                               "tests/test_moving_frame.cpp), R is numeric here; compare the solution with the "
                               "frame's equation numerically: verify(P, s, values, T)");
        return *y;
    };
    // P's equation is E0 with X -> r + R o, X' -> r' + w x r + R o', X'' -> L[r] + R o'' and V -> R V
    // (moving_frame_problem); at r = R (p - o) these are R p, R p', R p'' (Thm 11's kinematics,
    // proved here), so P's residual is E0(R p, R p', R p'', R V) = R E0(p, p', p'', V): E0 is built
    // of vector operations, which commute with a rotation.
    const ex o = F.o, o1 = o.is_zero() ? ex(0) : diff_t(o, t), o2 = o.is_zero() ? ex(0) : diff_t(o1, t);
    const ex r = R(o.is_zero() ? p : p - o), r1 = diff_t(r, t), r2 = diff_t(r1, t);
    const ex dw = w.is_zero() ? ex(0) : diff_t(w, t);
    const ex k0 = r + R(o) - R(p);
    const ex k1 = r1 + cross(w, r) + R(o1) - R(p1);
    const ex k2 = frame_operator(w, dw, r, r1, r2) + R(o2) - R(p2);
    zero_decision z;
    z.is_zero = truth::yes;
    for (const ex& k : {k0, k1, k2}) {
        const zero_decision d = decide_zero_vector(k);
        if (d.is_zero == truth::no) return d;
        if (d.is_zero == truth::unknown) z.is_zero = truth::unknown;
    }
    return z;
}

ex seen_from_frame(const moving_frame_form& F, const ex& line, const ex& t) {
    const dual::dual_parts x = dual::parts(line);
    const auto Ra = frame_rotation(F.w, x.primal, t), Rb = frame_rotation(F.w, x.dual, t);
    if (!Ra || !Rb)
        throw domain_error("the rotation R(t) of the frame, R' = -W R with w(t) = " + to_string(F.w) +
                           ", has no closed form: the frame's dual tensor is numeric");
    return dual::make_dual(tidy(*Ra), tidy(F.d.is_zero() ? *Rb : *Rb + cross(F.d, *Ra)));
}

ex solve_moving_frame(const cauchy_problem& P, const moving_frame_form& F) {
    if (!F.carried.empty())
        throw closed_form_error("the solution " + P.name + " = R (psi - o) of the problem seen from the frame: R' = -W R "
                                "with w(t) = " + to_string(F.w) + " has no closed form (Magnus on SO(3) evaluates it)");
    if (inertial_is_numeric(F))
        throw closed_form_error("the solution " + P.name + " = R (psi - o) of the problem seen from the frame: psi, " +
                                describe_reduction(*F.inertial, *F.inertial->turning) +
                                "\nhas no closed form in t (the reduction object evaluates it)");
    const ex psi = solve_unwitnessed(*F.inertial);
    const auto r = frame_rotation(F.w, F.o.is_zero() ? psi : psi - F.o, P.t);
    if (!r)
        throw closed_form_error("the rotation R(t) of the frame, R' = -W R with w(t) = " + to_string(F.w) +
                                ", has no closed form");
    const ex x = tidy(*r);
    return problem_has_float(P) ? GiNaC::evalf(x) : x;
}

std::vector<rotating_frame_state> moving_frame_states(const numeric_moving_frame& P, const std::vector<double>& times,
                                                      const num::rotation_tensor_options& options) {
    // y = Q psi, y' = Q psi' - w x y (Thm VI.3.2.1), then r = y - Q o, r' = y' - Q o' + w x (Q o)
    std::vector<rotating_frame_state> out = solve_by_reduction(P.rotating, times, options);
    if (!P.origin) return out;
    std::vector<Eigen::Matrix3d> Q;
    if (P.rotating.rotation) {
        for (const double x : times) Q.push_back(P.rotating.rotation(x));
    } else if (P.rotating.axis && P.rotating.angle) {
        for (const double x : times) Q.push_back(num::fixed_direction_rotation(*P.rotating.axis, P.rotating.angle(x)));
    } else {
        Q = num::rotation_tensor(P.rotating.w, times, options).Q;
    }
    for (std::size_t i = 0; i < times.size(); ++i) {
        const Eigen::Vector3d Qo = Q[i] * P.origin(times[i]);
        out[i].r -= Qo;
        out[i].v += -(Q[i] * P.origin_velocity(times[i])) + P.rotating.w(times[i]).cross(Qo);
    }
    return out;
}

std::vector<rotating_frame_state> carried_frame_states(const moving_frame_form& F,
                                                       const std::function<ex(const ex&)>& put,
                                                       const std::vector<double>& times) {
    const cauchy_problem& P0 = *F.inertial;
    if (inertial_is_numeric(F))
        throw closed_form_error("the inertial solution psi, " + describe_reduction(P0, *P0.turning) +
                                "\nhas no closed form, and the frame carries constant vectors: not evaluated");
    const ex& t = P0.t;
    const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
    const ex psi = numeric_vector_literal(put(solve_unwitnessed(P0)), "the inertial solution " + P0.name);
    const ex o = numeric_vector_literal(put(F.o), "the origin's path o(t)");
    const ex w = numeric_vector_literal(put(F.w), "the frame's w(t)");
    const auto f = [&](const ex& e) { return std::make_shared<num::compiled_function>(num::compile(e, {t})); };
    const auto p0 = f(psi), p1 = f(psi.diff(ts)), q0 = f(o), q1 = f(o.diff(ts)), fw = f(w);
    const num::angular_velocity omega = [fw](double x) {
        const Eigen::Vector3d v = fw->eval3(&x);
        if (!v.allFinite()) throw domain_error("w(t) has no finite value at t = " + std::to_string(x));
        return v;
    };
    num::rotation_tensor_options options;
    options.max_steps = 5'000'000;  // about 10 s of work (as reduced_solution.cpp)
    const std::vector<Eigen::Matrix3d> Q = num::rotation_tensor(omega, times, options).Q;
    std::vector<rotating_frame_state> out;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double x = times[i];
        // (Thm 12) r = Q (psi - o), r' = Q (psi' - o') - w x r (Q' = -W Q)
        const Eigen::Vector3d r = Q[i] * (p0->eval3(&x) - q0->eval3(&x));
        const Eigen::Vector3d v = Q[i] * (p1->eval3(&x) - q1->eval3(&x)) - omega(x).cross(r);
        if (!r.allFinite() || !v.allFinite())
            throw domain_error("the solution in the frame has no finite value at t = " + std::to_string(x));
        out.push_back({r, v});
    }
    return out;
}

}  // namespace symrep::mechanics
