// symrep/mechanics/fixed_axis.cpp -- reduction of a fixed-axis rotating-frame
// problem to the inertial one (fixed_axis.h; thesis VI.2).
#include "mechanics/fixed_axis.h"

#include <map>

#include "core/error.h"
#include "mechanics/quasi_polynomial.h"
#include "scalar/scalar.h"
#include "vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

// e with the unknowns other than `keep` (npos: all) replaced by 0.
ex keep_only(const cauchy_problem& P, const ex& e, std::size_t keep) {
    vmap m;
    for (std::size_t k = 0; k < P.unknowns.size(); ++k)
        if (k != keep) m[P.unknowns[k]] = 0;
    return subs_vectors(e, m);
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

}  // namespace

std::optional<fixed_axis_form> read_fixed_axis(const cauchy_problem& P, std::string* why) {
    bool varying = false;  // a reason is given only for a w that depends on t (else reduce()'s error stands)
    auto refuse = [&](const std::string& reason) -> std::optional<fixed_axis_form> {
        if (why && varying) *why = reason;
        return std::nullopt;
    };
    const std::size_t M = P.order();
    if (!P.is_vector || (M != 1 && M != 2) || P.initial.size() != M) return std::nullopt;
    const ex& t = P.t;
    // xM the highest derivative, xc the one the cross terms act on (M w x xc)
    const ex &x = P.unknowns[0], &xc = P.unknowns[M - 1], &xM = P.unknowns[M];
    // the rotating-frame operator, as text for messages
    const std::string op = M == 2 ? P.unknown_name(2) + " + 2 w x " + P.unknown_name(1) + " + w' x " + P.name +
                                        " + w x (w x " + P.name + ")"
                                  : P.unknown_name(1) + " + w x " + P.name;
    try {
        const ex E = P.expression, f = keep_only(P, E, std::size_t(-1));
        // m x^(M): a constant scalar leading coefficient
        const auto m = multiple_of(P, keep_only(P, E, M) - f, xM);
        if (!m || m->is_zero() || m->has(t)) return std::nullopt;
        // the cross terms on x^(M-1): sum c_j a_j x x^(M-1) = M m w x x^(M-1)
        ex cross1 = 0;
        for (const vector_term& term : canonical_terms(keep_only(P, E, M - 1) - f)) {
            const ex& mono = term.monomial;
            if (has_unknown(P, term.coefficient)) return std::nullopt;
            if (!is_ex_the_function(mono, vcross)) continue;  // c x^(M-1): in the remainder below
            if (mono.op(1).is_equal(xc) && !has_unknown(P, mono.op(0))) cross1 += term.coefficient * mono.op(0);
            else if (mono.op(0).is_equal(xc) && !has_unknown(P, mono.op(1))) cross1 -= term.coefficient * mono.op(1);
            else if (M == 2) return std::nullopt;  // (order 1: w x (w x x) and the like are read below)
        }
        if (cross1.is_zero()) return std::nullopt;
        // w = s(t) u with a constant direction u: the first term's coefficient is s
        std::vector<vector_term> wt = canonical_terms(cross1 / (double(M) * *m));
        if (wt.empty()) return std::nullopt;
        for (vector_term& term : wt)  // a literal [0, 0, f(t)]: f(t) [0, 0, 1]
            if (is_vector_literal(term.monomial) && term.monomial.has(t)) {
                std::size_t k = 0;
                while (k < 3 && GiNaC::normal(term.monomial.op(k)).is_zero()) ++k;
                if (k == 3) continue;
                const ex c = term.monomial.op(k);
                term.coefficient = GiNaC::normal(term.coefficient * c);
                term.monomial = vector_literal(GiNaC::normal(term.monomial.op(0) / c), GiNaC::normal(term.monomial.op(1) / c),
                                               GiNaC::normal(term.monomial.op(2) / c));
            }
        const ex w0 = cross1 / (int(M) * *m);
        varying = w0.has(t);
        fixed_axis_form F;
        F.s = GiNaC::normal(wt[0].coefficient);
        F.u = 0;
        for (const vector_term& term : wt) {
            const ex ratio = GiNaC::normal(term.coefficient / F.s);
            if (ratio.has(t) || term.monomial.has(t))  // the direction turns: VI.3, no closed form for Q
                return refuse("the rotation w(t) = " + to_string(w0) +
                              " turns its direction: only a fixed axis, w(t) = s(t) u, is solved in closed form "
                              "(Thm VI.2.1.1); for a turning w the rotation tensor is numeric (VI.3)");
            F.u += ratio * term.monomial;
        }
        const ex w = F.s * F.u;
        const std::string form = "the problem has the rotating-frame terms of w(t) = " + to_string(w) + " (" +
                                 to_string(int(M) * w) + " x " + P.unknown_name(M - 1) + "), but ";
        // the rest of E is m (x'' + 2 w x x' + w' x x + w x (w x x)) + k x + F(t), or for
        // order 1 m (x' + w x x) + k x + F(t) (with w as the user wrote it, so that
        // literals [0, 0, f(t)] meet their own terms)
        const ex R = M == 2 ? *m * (xM + 2 * cross(w0, xc) + cross(diff_t(w0, t), x) + cross(w0, cross(w0, x)))
                            : *m * (xM + cross(w0, x));
        const ex rest = E - R, free = keep_only(P, rest, std::size_t(-1));
        for (std::size_t k = 1; k <= M; ++k)
            if (!equal(keep_only(P, rest, k) - free, 0))
                return refuse(form + "beside m (" + op + ") it has the terms " + to_string(keep_only(P, rest, k) - free) +
                              " in " + P.unknown_name(k) + " (Thm VI.2.2 reduces the undamped form only)");
        const ex L0 = keep_only(P, rest, 0) - free;
        ex k = 0;
        for (const vector_term& term : canonical_terms(L0))
            if (term.monomial.is_equal(x)) k += term.coefficient;
        k = GiNaC::normal(k);
        if (has_unknown(P, k) || k.has(t) || !equal(L0 - k * x, 0))
            return refuse(form + "the terms " + to_string(keep_only(P, rest, 0) - free) + " in " + P.name +
                          " are not the rotating-frame operator (m (" + op + ")) plus a constant multiple k " + P.name);
        if (!free.is_zero() && !equal(cross(F.u, free), 0))  // Q^T F = F needs F along u
            return refuse(form + "the free term " + to_string(free) + " is not along the axis " + to_string(F.u) +
                          " (the inertial problem would have the rotated force Q^T F)");
        // a(t) = |u| int_0^t s
        F.angle = norm(F.u) * quasi_polynomial::from_ex(F.s, t).antiderivative().to_ex();
        F.m = *m;
        F.k = k;
        F.free = free;
        // the inertial problem m psi'' + k psi + F = 0, psi(0) = r0, psi'(0) = v0 + w(0) x r0
        // (order 1: m psi' + k psi + F = 0, psi(0) = x0)
        auto I = std::make_shared<cauchy_problem>(P);
        I->expression = *m * xM + k * x + free;
        if (M == 2) I->initial = {P.initial[0], P.initial[1] + cross(w.subs(t == 0), P.initial[0])};
        I->reduced = std::make_shared<const operator_form>(reduce(*I));
        F.inertial = std::move(I);
        return F;
    } catch (const std::exception&) {
        // not this form (not a quasi-polynomial, a reading failed, 1/|r| at r = 0 of a
        // nonlinear term): the caller's error stands
        return std::nullopt;
    }
}

// (Thm VI.2.1.1, VI.2.9-12) r = Q psi, Q the rotation by -a(t) about n = u/|u|.
ex solve_fixed_axis(const cauchy_problem&, const fixed_axis_form& F) {
    const ex psi = solve(*F.inertial);
    const ex U = norm(F.u), c = GiNaC::cos(F.angle), s = GiNaC::sin(F.angle);
    return c * psi - s / U * cross(F.u, psi) + (1 - c) / (U * U) * dot(F.u, psi) * F.u;
}

std::vector<ex> first_integrals(const cauchy_problem& P, const fixed_axis_form& F) {
    if (P.order() != 2)
        throw domain_error("first_integrals: the problem has order " + std::to_string(P.order()) +
                           "; the first integrals of Thm VI.2.2.3.3 are of the second-order problem");
    if (!F.free.is_zero())
        throw domain_error("first_integrals: the free term " + to_string(F.free) +
                           " does work on " + P.name + ": the energy is not conserved");
    const ex &r = P.unknowns[0], &r1 = P.unknowns[1];
    const ex p = r1 + cross(F.s * F.u, r);
    const ex L = cross(r, p);
    return {F.m * dot(p, p) / 2 + F.k * dot(r, r) / 2, dot(F.u, L), dot(L, L)};
}

}  // namespace symrep::mechanics
