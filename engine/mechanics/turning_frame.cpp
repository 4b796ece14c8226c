// symrep/mechanics/turning_frame.cpp -- the reading of rotating-frame problems
// and their reduction to the inertial problem (turning_frame.h; thesis VI.2-VI.3).
#include "symrep/mechanics/turning_frame.h"

#include "symrep/numeric/quadrature.h"
#include "symrep/mechanics/fixed_axis.h"

#include <algorithm>
#include <map>

#include "symrep/core/error.h"
#include "symrep/mechanics/quasi_polynomial.h"
#include "symrep/scalar/floats.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

void require_value_at_zero(const ex& w, const ex& t, const std::string& what) {
    bool finite = true;
    try {
        static_cast<void>(w.subs(t == 0));  // GiNaC evaluates 1/0, log(0) ... to an error
    } catch (const std::exception&) {  // GiNaC's pole_error: 1/t at t = 0
        finite = false;
    }
    if (!finite)
        throw domain_error(what + " = " + to_string(w) + " has no value at t = 0: the frame's angular velocity must be "
                           "defined (and differentiable) from t = 0 on");
}

std::optional<ex> rotation_angle(const ex& s, const ex& u, const ex& t, bool integral_object) {
    try {
        return norm(u) * quasi_polynomial::from_ex(s, t).antiderivative().to_ex();
    } catch (const domain_error&) {
        if (!integral_object) return std::nullopt;
        const ex& tau = integration_variable();
        return norm(u) * GiNaC::integral(tau, 0, t, s.subs(t == tau));
    }
}

bool depends_on_time(const ex& e, const ex& t) {
    if (e.has(t)) return true;
    for (const ex& v : vector_symbols(e))
        if (!diff_t(v, t).is_zero()) return true;
    return false;
}

std::optional<std::vector<std::pair<ex, ex>>> terms_in_time(const ex& v, const ex& t) {
    std::vector<std::pair<ex, ex>> out;  // (c_j(t), V_j)
    auto add = [&](const ex& c, const ex& V) {
        // c = k q(t) with k free of t: q is the key, k goes into V
        ex k = 1, q = 1;
        if (!c.has(t)) k = c;
        else if (!GiNaC::is_a<GiNaC::mul>(c)) q = c;
        else
            for (std::size_t i = 0; i < c.nops(); ++i) (c.op(i).has(t) ? q : k) *= c.op(i);
        if (k.is_zero()) return;
        auto g = std::find_if(out.begin(), out.end(), [&](const auto& p) { return p.first.is_equal(q); });
        if (g == out.end()) out.push_back({q, k * V});
        else g->second += k * V;
    };
    for (const vector_term& term : canonical_terms(v)) {
        if (is_vector_literal(term.monomial) && term.monomial.has(t))
            for (int i = 0; i < 3; ++i) add(term.coefficient * term.monomial.op(i), vector_literal(i == 0, i == 1, i == 2));
        else
            add(term.coefficient, term.monomial);
    }
    // what is left in a V_j that depends on time (a vector function w(t), a dot product with one)
    for (const auto& [q, V] : out)
        if (depends_on_time(V, t)) return std::nullopt;
    return out;
}

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

bool has_unknown(const cauchy_problem& P, const ex& e);

// E split by the unknowns: part k holds the terms in x^(k) (k <= M), part M + 1 those
// without an unknown. Nothing when a term holds two different unknowns (not linear in
// the derivatives). Done on the expanded terms, not by putting 0 for the unknowns: a
// central field k x/|x|^3 has no value at x = 0.
std::optional<std::vector<ex>> split_by_unknown(const cauchy_problem& P, const ex& E) {
    const std::size_t M = P.order();
    std::vector<ex> part(M + 2, ex(0));
    const ex e = GiNaC::expand(E);
    const std::size_t n = GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
    for (std::size_t i = 0; i < n; ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        std::size_t found = M + 1;
        for (std::size_t k = 0; k <= M; ++k)
            if (term.has(P.unknowns[k])) {
                if (found != M + 1) return std::nullopt;
                found = k;
            }
        part[found] += term;
    }
    return part;
}

bool has_unknown(const cauchy_problem& P, const ex& e) {
    for (const ex& u : P.unknowns)
        if (e.has(u)) return true;
    return false;
}

// The coefficient c of L = c x (L a scalar multiple of the unknown x), or nothing.
std::optional<ex> multiple_of(const cauchy_problem& P, const ex& L, const ex& x) {
    ex c = 0;
    for (const vector_term& term : canonical_terms(L)) {
        if (!term.monomial.is_equal(x) || has_unknown(P, term.coefficient)) return std::nullopt;
        c += term.coefficient;
    }
    return GiNaC::normal(c);
}

// V(p) = int f dp for f a sum of c p^n (c free of p): 0 at infinity for n < -1, at 0 for
// n > -1, log p for n = -1; empty when a term is not of that form.
std::optional<ex> potential_of(const ex& f, const ex& p) {
    const ex e = GiNaC::expand(f);
    ex V = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        if (term.is_zero()) continue;
        const int deg = term.degree(p), ldeg = term.ldegree(p);
        if (deg != ldeg) return std::nullopt;
        const ex c = term.coeff(p, deg);
        if (c.has(p)) return std::nullopt;
        if (deg == -1) V += c * GiNaC::log(p);
        else V += c * GiNaC::pow(p, deg + 1) / (deg + 1);
    }
    return V;
}

}  // namespace

namespace {

/// A literal of floats [f1(t), f2(t), f3(t)] whose components are one function of t
/// times a constant vector to the working precision: as (s(t), u). b(t) [0.1, 0.2, 0.3]
/// reaches here as [0.0666...67 t + 0.075, 0.1333...33 t + 0.15, ...]: the rate was
/// multiplied into the floats, each product rounded to D digits (scalar/floats.h), so
/// the components are proportional only up to the last digits. Each component is a
/// sum of float coefficients times functions of t (a matrix A, rows the components,
/// columns the functions); A has rank 1 when every 2x2 minor is below 10^(3-D) of its
/// terms (the rounding of a few operations at D digits) and every exact zero is a
/// zero of its whole row. Nothing otherwise.
std::optional<std::pair<ex, ex>> float_direction(const ex& literal, const ex& t) {
    std::vector<ex> functions;
    std::vector<std::map<std::size_t, GiNaC::numeric>> rows(3);
    for (unsigned k = 0; k < 3; ++k) {
        const ex f = GiNaC::expand(literal.op(k));
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(f) ? f.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(f) ? f.op(i) : f;
            if (term.is_zero()) continue;
            const auto [c, rest] = split_numeric_factor(term);
            if (!c.is_real()) return std::nullopt;
            std::size_t col = 0;
            while (col < functions.size() && !functions[col].is_equal(rest)) ++col;
            if (col == functions.size()) functions.push_back(rest);
            rows[k][col] += c;
        }
    }
    const GiNaC::numeric tol = GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(GiNaC::numeric(10), 3 - long(GiNaC::Digits)));
    const auto at = [&](unsigned k, std::size_t j) {
        const auto it = rows[k].find(j);
        return it == rows[k].end() ? GiNaC::numeric(0) : it->second;
    };
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned k = i + 1; k < 3; ++k)
            for (std::size_t j = 0; j < functions.size(); ++j)
                for (std::size_t l = j + 1; l < functions.size(); ++l) {
                    const GiNaC::numeric p = at(i, j) * at(k, l), q = at(i, l) * at(k, j);
                    if (abs(p - q) > tol * (abs(p) + abs(q))) return std::nullopt;
                    // an exact zero against a nonzero product: not a rounding
                    if ((p.is_zero() != q.is_zero())) return std::nullopt;
                }
    // u: the column of the largest norm; s(t) = sum_j (A_j . u)/(u . u) phi_j(t)
    std::size_t best = 0;
    GiNaC::numeric best_norm = -1;
    for (std::size_t j = 0; j < functions.size(); ++j) {
        GiNaC::numeric n = 0;
        for (unsigned k = 0; k < 3; ++k) n += at(k, j) * at(k, j);
        if (n > best_norm) {
            best_norm = n;
            best = j;
        }
    }
    if (!best_norm.is_positive()) return std::nullopt;
    ex s = 0;
    for (std::size_t j = 0; j < functions.size(); ++j) {
        GiNaC::numeric d = 0;
        for (unsigned k = 0; k < 3; ++k) d += at(k, j) * at(k, best);
        s += (d / best_norm) * functions[j];
    }
    if (!s.has(t)) return std::nullopt;  // constant: not this case
    return std::make_pair(s, vector_literal(at(0, best), at(1, best), at(2, best)));
}

}  // namespace

std::optional<std::pair<ex, ex>> fixed_direction(const ex& w, const ex& t) {
    std::vector<vector_term> wt = canonical_terms(w);
    if (wt.empty()) return std::nullopt;
    for (vector_term& term : wt)  // a literal [0, 0, f(t)]: f(t) [0, 0, 1]
        if (is_vector_literal(term.monomial) && term.monomial.has(t) && has_float(term.monomial)) {
            if (const auto d = float_direction(term.monomial, t)) {
                term.coefficient = GiNaC::normal(term.coefficient * d->first);
                term.monomial = d->second;
            }
        } else if (is_vector_literal(term.monomial) && term.monomial.has(t)) {
            std::size_t k = 0;
            while (k < 3 && GiNaC::normal(term.monomial.op(k)).is_zero()) ++k;
            if (k == 3) continue;
            const ex c = term.monomial.op(k);
            term.coefficient = GiNaC::normal(term.coefficient * c);
            term.monomial = vector_literal(GiNaC::normal(term.monomial.op(0) / c),
                                           GiNaC::normal(term.monomial.op(1) / c),
                                           GiNaC::normal(term.monomial.op(2) / c));
        }
    const ex s = GiNaC::normal(wt[0].coefficient);
    ex u = 0;
    for (const vector_term& term : wt) {
        const ex ratio = GiNaC::normal(term.coefficient / s);
        if (ratio.has(t) || depends_on_time(term.monomial, t)) return std::nullopt;  // the direction turns
        u += ratio * term.monomial;
    }
    return std::make_pair(s, u);
}

std::optional<turning_frame_form::precession> regular_precession(const ex& w, const ex& t) {
    // w as a sum of scalar functions of t times constant vectors (literals by components)
    const auto read = terms_in_time(w, t);
    if (!read) return std::nullopt;
    const std::vector<std::pair<ex, ex>>& terms = *read;
    // the frequency c: the first argument c t of a sin or cos
    ex c;
    for (const auto& [k, V] : terms)
        for (auto it = k.preorder_begin(); it != k.preorder_end() && c.is_zero(); ++it)
            if ((is_ex_the_function(*it, GiNaC::sin) || is_ex_the_function(*it, GiNaC::cos)) && it->op(0).has(t))
                c = GiNaC::normal(it->op(0) / t);
    if (c.is_zero() || c.has(t)) return std::nullopt;
    const GiNaC::symbol X("X"), Y("Y");
    GiNaC::exmap trig;
    trig[GiNaC::cos(c * t)] = X;
    trig[GiNaC::sin(c * t)] = Y;
    trig[GiNaC::cos(-c * t)] = X;
    trig[GiNaC::sin(-c * t)] = -Y;
    ex w0 = 0, C = 0, S = 0;
    for (const auto& [k, V] : terms) {
        const ex e = GiNaC::expand(GiNaC::expand(k).subs(trig));
        if (e.has(t) || e.degree(X) > 1 || e.degree(Y) > 1 || e.coeff(X, 1).has(Y) || e.ldegree(X) < 0 ||
            e.ldegree(Y) < 0)
            return std::nullopt;
        w0 += e.subs(GiNaC::lst{X == 0, Y == 0}) * V;
        C += e.coeff(X, 1) * V;
        S += e.coeff(Y, 1) * V;
    }
    // |C| = |S|, C . S = 0, C != 0, w0 along C x S (each proved; undecided: not a precession)
    if (equal(C, 0) || !equal(dot(C, C), dot(S, S)) || !equal(dot(C, S), 0)) return std::nullopt;
    const ex CS = cross(C, S);
    if (!equal(cross(w0, CS), 0)) return std::nullopt;
    // u1 x C = -S: u1 = -(C x S)/|C|^2 (|C x S| = |C| |S| = |C|^2)
    const ex u1 = canonical(-CS / dot(C, C));
    return turning_frame_form::precession{u1, c, canonical(C + (dot(w0, u1) - c) * u1)};
}

namespace {

// The rotation by -theta about the unit vector n: Q' = -W Q for w = theta' n (VI.2.12).
ex rotate_unit(const ex& n, const ex& theta, const ex& x) {
    const auto [c, s] = cos_sin_of_angle(theta);
    return c * x - s * cross(n, x) + (1 - c) * dot(n, x) * n;
}

}  // namespace

std::optional<ex> closed_rotation(const turning_frame_form& F, const ex& x, const ex& t) {
    if (F.terms.w.is_zero()) return x;
    if (F.u && F.angle) {
        const ex U = norm(*F.u);
        const auto [c, s] = cos_sin_of_angle(*F.angle);
        return c * x - s / U * cross(*F.u, x) + (1 - c) / (U * U) * dot(*F.u, x) * *F.u;
    }
    if (F.precessing) {  // Q = A(t) B(t): the spin v first, then the carrying rotation about u1
        const auto& p = *F.precessing;
        const ex V = norm(p.v);
        const ex inner = GiNaC::cos(V * t) * x - GiNaC::sin(V * t) / V * cross(p.v, x) +
                         (1 - GiNaC::cos(V * t)) / (V * V) * dot(p.v, x) * p.v;
        return rotate_unit(p.u1, p.c * t, inner);
    }
    return std::nullopt;
}

std::optional<ex> closed_solution(const cauchy_problem& P, const turning_frame_form& F) {
    if (!F.psi) return std::nullopt;
    return closed_rotation(F, *F.psi, P.t);
}

std::optional<frame_terms> read_frame_terms(const cauchy_problem& P, std::string* why) {
    bool varying = false;  // a reason is given only for a w that depends on t or a nonlinear term
    auto refuse = [&](const std::string& reason) -> std::optional<frame_terms> {
        if (why && varying) *why = reason;
        return std::nullopt;
    };
    const std::size_t M = P.order();
    if (!P.is_vector || (M != 1 && M != 2) || P.initial.size() != M) return std::nullopt;
    const ex& t = P.t;
    const ex &x = P.unknowns[0], &xc = P.unknowns[M - 1], &xM = P.unknowns[M];
    const std::string op = M == 2 ? P.unknown_name(2) + " + 2 w x " + P.unknown_name(1) + " + w' x " + P.name +
                                        " + w x (w x " + P.name + ")"
                                  : P.unknown_name(1) + " + w x " + P.name;
    const auto parts = split_by_unknown(P, P.expression);
    if (!parts) return std::nullopt;
    const auto m = multiple_of(P, (*parts)[M], xM);
    if (!m || m->is_zero() || m->has(t)) return std::nullopt;
    // the cross terms on x^(M-1): sum c_j a_j x x^(M-1) = M m w x x^(M-1)
    ex cross1 = 0;
    for (const vector_term& term : canonical_terms((*parts)[M - 1])) {
        const ex& mono = term.monomial;
        if (!is_ex_the_function(mono, vcross)) continue;  // c x^(M-1), g(|x|) x: in the remainder below
        if (has_unknown(P, term.coefficient)) return std::nullopt;
        if (mono.op(1).is_equal(xc) && !has_unknown(P, mono.op(0))) cross1 += term.coefficient * mono.op(0);
        else if (mono.op(0).is_equal(xc) && !has_unknown(P, mono.op(1))) cross1 -= term.coefficient * mono.op(1);
        else if (M == 2) return std::nullopt;  // (order 1: w x (w x x) and the like are read below)
    }
    frame_terms T;
    T.order = M;
    T.m = *m;
    T.w = cross1 / (int(M) * *m);
    T.p = GiNaC::possymbol("p");
    varying = depends_on_time(T.w, t);  // t in it, or a declared vector function w(t)
    T.form = "the problem has the rotating-frame terms of w(t) = " + to_string(T.w) + " (" +
             to_string(int(M) * T.w) + " x " + P.unknown_name(M - 1) + "), but ";
    if (varying) require_value_at_zero(T.w, t, "w(t)");
    const ex R = M == 2 ? *m * (xM + 2 * cross(T.w, xc) + cross(diff_t(T.w, t), x) + cross(T.w, cross(T.w, x)))
                        : *m * (xM + cross(T.w, x));
    const auto rest = split_by_unknown(P, P.expression - R);
    if (!rest) return std::nullopt;
    T.free = (*rest)[M + 1];
    for (std::size_t k = 1; k <= M; ++k)
        if (!equal((*rest)[k], 0))
            return refuse(T.form + "beside m (" + op + ") it has the terms " + to_string((*rest)[k]) + " in " +
                          P.unknown_name(k) + " (Thm VI.2.2 and VI.3.2.1 reduce the undamped form only)");
    const ex L0 = (*rest)[0];
    ex g = 0;
    bool central = true;
    for (const vector_term& term : canonical_terms(L0)) {
        if (!term.monomial.is_equal(x)) central = false;
        else g += term.coefficient;
    }
    // |x| as p: dot(x, x) = p^2 (norm(x) = sqrt(dot(x, x)) = p, p > 0)
    g = GiNaC::normal(g.subs(vdot(x, x) == GiNaC::pow(T.p, 2)));
    central = central && !has_unknown(P, g) && !g.has(t);
    // without cross terms (w = 0) only a nonlinear central field is this reading's
    // (a linear problem is reduce()'s, and its error stands)
    if (cross1.is_zero() && (M != 2 || !(central && g.has(T.p)))) return std::nullopt;
    if (!central)
        return refuse(T.form + "the terms " + to_string(L0) + " in " + P.name +
                      " are not the rotating-frame operator (m (" + op + ")) plus a central field g(|" + P.name +
                      "|) " + P.name + " (a function of |" + P.name + "| only, constant in t)");
    T.g = g;
    return T;
}

std::optional<turning_frame_form> read_turning_frame(const cauchy_problem& P, std::string* why) {
    std::string inner;
    const auto T = read_frame_terms(P, &inner);
    if (!T) {
        if (why) *why = inner;
        return std::nullopt;
    }
    const bool reasons = depends_on_time(T->w, P.t) || T->g.has(T->p);
    auto refuse = [&](const std::string& reason) -> std::optional<turning_frame_form> {
        if (why && reasons) *why = reason;
        return std::nullopt;
    };
    const ex& t = P.t;
    if (!T->free.is_zero()) {
        // (Thm VI.3.2.1 with a free term) psi'' + k psi = -Q^T F(t)/m: linear in psi only, where the
        // rotated force enters by Duhamel's integral (reduced_solution.cpp); a nonlinear field
        // would couple psi to Q
        if (T->g.has(T->p))
            return refuse(T->form + "it has the free term " + to_string(T->free) +
                          " beside a nonlinear central field: the inertial problem would couple psi to Q through "
                          "the rotated force Q^T F(t) (Thm VI.3.2.1 is reduced with a free term for a constant k "
                          "only)");
        const auto terms = terms_in_time(T->free, t);
        if (!terms)
            return refuse(T->form + "its free term " + to_string(T->free) + " is not a sum of functions of " +
                          to_string(t) + " times constant vectors");
        for (const auto& [q, V] : *terms)
            num::require_finite_on_half_line(q, t, "the free term " + to_string(-q * V));  // as on the right
    }
    turning_frame_form F;
    F.terms = *T;
    F.w0 = T->w.subs(t == 0);
    {  // a declared vector function w(t) at t = 0: the vector w_0
        std::map<ex, ex, GiNaC::ex_is_less> at0;
        for (const ex& v : vector_symbols(F.w0))
            if (!diff_t(v, t).is_zero()) at0[v] = vector_symbol(to_string(v) + "_0");
        if (!at0.empty()) F.w0 = subs_vectors(F.w0, at0);
    }
    if (!T->w.is_zero() && !fixed_direction(T->w, t)) F.precessing = regular_precession(T->w, t);
    if (const auto d = fixed_direction(T->w, t)) {
        F.u = d->second;
        // int s not elementary: Q numeric (Magnus) like a turning w
        F.angle = rotation_angle(d->first, d->second, t, false);
    }
    const ex& x = P.unknowns[0];
    if (P.order() == 1) {
        if (T->g.has(T->p))
            return refuse(T->form + "the term " + to_string(T->g.subs(T->p == norm(x)) * x) +
                          " is nonlinear: a first-order problem is reduced with a constant k x only");
        F.k = GiNaC::normal(T->g / T->m);
        auto I = std::make_shared<cauchy_problem>(P);
        I->expression = T->m * P.unknowns[1] + T->g * x;
        I->turning.reset();
        I->reduced = std::make_shared<const operator_form>(reduce(*I));
        (T->free.is_zero() ? F.psi : F.psi_unforced) = solve(*I);
        return F;
    }
    F.f = GiNaC::normal(T->p * T->g / T->m);
    F.potential = potential_of(F.f, T->p);
    F.psi_initial_velocity = P.initial[1] + cross(F.w0, P.initial[0]);
    if (!T->g.has(T->p)) {  // f = k/m p: the inertial problem has constant coefficients
        auto I = std::make_shared<cauchy_problem>(P);
        I->expression = T->m * P.unknowns[2] + T->g * x;
        I->turning.reset();
        I->initial = {P.initial[0], F.psi_initial_velocity};
        I->reduced = std::make_shared<const operator_form>(reduce(*I));
        (T->free.is_zero() ? F.psi : F.psi_unforced) = solve(*I);
    }
    return F;
}

std::string describe_reduction(const cauchy_problem& P, const turning_frame_form& F) {
    const std::string r = P.name, W = to_string(F.terms.w);
    std::string s = r + " = F_(-w)(psi) = Q psi   (Thm VI.3.2.1)\n";
    if (F.terms.w.is_zero())
        s += "  Q = I (w = 0: an inertial frame)\n";
    else if (F.precessing)
        s += "  Q = A B: B the rotation by -|v| t about v = " + to_string(F.precessing->v) + ", A by -(" +
             to_string(F.precessing->c) + ") t about u1 = " + to_string(F.precessing->u1) +
             "   (a regular precession: w(t) = " + W + " = (" + to_string(F.precessing->c) + ") u1 + A v)\n";
    else if (!F.angle || !F.u)
        s += "  Q' = -W Q, Q(0) = I, W x = w x x, w(t) = " + W +
             (!F.u ? "   (VI.3.117; numeric: Magnus on SO(3))\n"
                   : "   (fixed direction " + to_string(*F.u) + "; numeric: Magnus on SO(3))\n");
    else
        s += "  Q x = cos(a) x - sin(a)/|u| u x x + (1 - cos(a))/|u|^2 (u . x) u, u = " + to_string(*F.u) +
             ", a(t) = " + to_string(*F.angle) + "   (VI.2.12, w(t) = " + W + ")\n";
    // (Thm VI.3.2.1 with a free term F(t)) the rotated force on the right, its Duhamel integral
    const bool forced = !F.terms.free.is_zero();
    // f(t) = -F(t)/m, the force per unit mass on the right side
    const std::string right =
        forced ? "Q^T f(t), f(t) = " + to_string(canonical(-F.terms.free / F.terms.m)) : std::string("0");
    auto forced_psi = [&](const std::string& G) {
        return "  psi = " + to_string(*F.psi_unforced) + " + int_0^t " + G + "Q^T(tau) f(tau) dtau   (Duhamel; "
               "numeric: Q^T with psi by Boost.Odeint)";
    };
    if (P.order() == 1) {
        s += "  psi'" + (F.k.is_zero() ? std::string() : " + (" + to_string(F.k) + ") psi") + " = " + right +
             ", psi(0) = " + to_string(P.initial[0]) + "\n";
        if (forced) return s + forced_psi(F.k.is_zero() ? "" : "exp(-(" + to_string(F.k) + ") (t - tau)) ");
        s += "  psi = " + to_string(*F.psi);
        return s;
    }
    const GiNaC::possymbol q("|psi|");
    const ex f = F.f.subs(F.terms.p == q), lin = GiNaC::normal(F.terms.g / F.terms.m);
    s += "  psi''" + (f.is_zero() ? std::string() : F.terms.g.has(F.terms.p) ? " + (" + to_string(f) + ") psi/|psi|"
                                                                            : " + (" + to_string(lin) + ") psi") +
         " = " + right + ", psi(0) = " +
         to_string(P.initial[0]) + ", psi'(0) = " + to_string(F.psi_initial_velocity) + "   (VI.3.133)\n";
    if (forced) s += forced_psi("G(t - tau) ") + ",\n  G the impulse response of psi'' + (" + to_string(lin) + ") psi";
    else if (F.psi) s += "  psi = " + to_string(*F.psi);
    else if (GiNaC::normal(F.f * GiNaC::pow(F.terms.p, 2)).has(F.terms.p))
        s += "  psi: the inertial orbit in the central field, numeric (Boost.Odeint)";
    else
        s += "  psi: the Kepler orbit with mu = " + to_string(GiNaC::normal(F.f * GiNaC::pow(F.terms.p, 2))) +
             " (universal variables, VI.3.153-157)";
    return s;
}

std::vector<ex> first_integrals(const cauchy_problem& P, const turning_frame_form& F) {
    if (P.order() != 2)
        throw domain_error("first_integrals: the problem has order " + std::to_string(P.order()) +
                           "; the first integrals of Thm VI.3.2.2 are of the second-order problem");
    const ex &r = P.unknowns[0], &r1 = P.unknowns[1];
    const ex p = r1 + cross(F.terms.w, r);
    const ex L = cross(r, p);
    std::vector<ex> out;
    if (F.potential) out.push_back(F.terms.m * (dot(p, p) / 2 + F.potential->subs(F.terms.p == norm(r))));
    if (F.u) out.push_back(dot(*F.u, L));
    out.push_back(dot(L, L));
    return out;
}

std::shared_ptr<cauchy_problem> rotation_statement(const ex& w, const ex& x0, const ex& t) {
    // (VI.3.118-119) y = F_w(x0): y' = w x y, i.e. y' + v x y = 0 with v = -w, y(0) = x0
    auto P = std::make_shared<cauchy_problem>();
    P->name = "y";
    P->t = t;
    P->is_vector = true;
    const ex y = GiNaC::realsymbol("y");
    register_vector_function(y, t);
    P->unknowns = {y, derivative(y)};
    P->initial = {x0};
    P->expression = P->unknowns[1] - cross(w, y);
    return P;
}

std::shared_ptr<const cauchy_problem> rotation_problem(const ex& w, const ex& x0, const ex& t) {
    const auto P = rotation_statement(w, x0, t);
    std::string why;
    auto F = read_turning_frame(*P, &why);
    if (!F) throw domain_error("F_w(x): " + (why.empty() ? std::string("w(t) = " + to_string(w) + " is not read") : why));
    P->turning = std::make_shared<const turning_frame_form>(std::move(*F));
    return P;
}

// True when a is printed with a minus sign in front (-t^2/2, -sin(t), -(1 + 2*t - cos(2*t))*|u|/2):
// by the printed text, not by GiNaC's form, whose choice of the sign of a sum factor follows its
// term order, which varies from run to run (as positive_trig_arguments in cauchy_solve.cpp)
static bool shows_minus(const ex& a) { return to_string(a).rfind('-', 0) == 0; }

std::pair<ex, ex> cos_sin_of_angle(const ex& a) {
    if (shows_minus(a)) return {GiNaC::cos(-a), -GiNaC::sin(-a)};
    return {GiNaC::cos(a), GiNaC::sin(a)};
}

}  // namespace symrep::mechanics
