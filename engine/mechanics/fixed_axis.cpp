// symrep/mechanics/fixed_axis.cpp -- reduction of a fixed-axis rotating-frame
// problem to the inertial one (fixed_axis.h; thesis VI.2).
#include "symrep/mechanics/fixed_axis.h"

#include "symrep/numeric/quadrature.h"

#include <algorithm>
#include <map>

#include "symrep/core/error.h"
#include "symrep/mechanics/quasi_polynomial.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/scalar/scalar.h"
#include "symrep/scalar/rational_integral.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

std::optional<fixed_axis_form> read_fixed_axis(const cauchy_problem& P, std::string* why) {
    try {
        std::string inner;
        const auto T = read_frame_terms(P, &inner);
        if (!T) {
            if (why) *why = inner;
            return std::nullopt;
        }
        const auto d = fixed_direction(T->w, P.t);
        // a turning direction or a nonlinear central field: no closed form, and no reason
        // from here (turning_frame.h reads it, with Q or psi numeric)
        if (!d || T->g.has(T->p)) return std::nullopt;
        fixed_axis_form F;
        F.s = d->first;
        F.u = d->second;
        const ex w = F.s * F.u;
        // a(t) = |u| int_0^t s: in closed form for a quasi-polynomial s, else the integral
        // object (VI.2.12 holds for any signed rate; eval and verify by quadrature)
        F.angle = *rotation_angle(F.s, F.u, P.t, true);
        F.m = T->m;
        F.k = T->g;
        // F along u passes Q^T unchanged; across u it is rotated (solve_fixed_axis)
        F.free = T->free;
        F.across = 0;
        if (!T->free.is_zero() && !equal(cross(F.u, T->free), 0)) {
            // across the axis with an angle that is itself an integral: Duhamel's integrand holds
            // it, a nested integral (numeric/quadrature.h evaluates it)
            // (u . F)/|u|^2 u term by term over F = sum_j c_j(t) V_j with V_j constant: a literal
            // holding t ([t e^-t, 2, sin(2 t)]) would leave t inside u . F, which the inertial
            // problem cannot read as a function of t times a vector
            const auto terms = terms_in_time(T->free, P.t);
            ex along = 0;
            if (terms)
                for (const auto& [q, V] : *terms) along += q * dot(F.u, V);
            else
                along = dot(F.u, T->free);
            F.free = along / dot(F.u, F.u) * F.u;
            F.across = T->free - F.free;
        }
        // the inertial problem m psi'' + k psi + F = 0, psi(0) = r0, psi'(0) = v0 + w(0) x r0
        // (order 1: m psi' + k psi + F = 0, psi(0) = x0)
        const std::size_t M = P.order();
        const ex& x = P.unknowns[0];
        auto I = std::make_shared<cauchy_problem>(P);
        I->expression = F.m * P.unknowns[M] + F.k * x + F.free;
        if (M == 2) I->initial = {P.initial[0], P.initial[1] + cross(w.subs(P.t == 0), P.initial[0])};
        I->reduced = std::make_shared<const operator_form>(reduce(*I));
        F.inertial = std::move(I);
        return F;
    } catch (const std::exception&) {
        // not this form (not a quasi-polynomial, a reading failed, 1/|r| at r = 0 of a
        // nonlinear term): the caller's error stands
        return std::nullopt;
    }
}

const ex& integration_variable() {
    static const ex tau = GiNaC::realsymbol("tau");
    return tau;
}

namespace {

// G(t), the impulse response of m y^(M) + k y = 0: y(0) = ... = 0, y^(M-1)(0) = 1/m.
ex impulse_response(const cauchy_problem& P, const fixed_axis_form& F) {
    const std::size_t M = P.order();
    cauchy_problem G;
    G.name = "G";
    G.t = P.t;
    G.is_vector = false;
    for (std::size_t m = 0; m <= M; ++m) G.unknowns.push_back(GiNaC::realsymbol(G.unknown_name(m)));
    G.expression = F.m * G.unknowns[M] + F.k * G.unknowns[0];
    for (std::size_t m = 0; m < M; ++m) G.initial.push_back(m + 1 == M ? 1 / F.m : ex(0));
    return solve_unwitnessed(G);
}

// e = k * rest with k the factors free of x.
std::pair<ex, ex> split_constant(const ex& e, const ex& x) {
    if (!e.has(x)) return {e, 1};
    if (!GiNaC::is_a<GiNaC::mul>(e)) return {1, e};
    ex k = 1, rest = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) (e.op(i).has(x) ? rest : k) *= e.op(i);
    return {k, rest};
}

// sin, cos, sinh, cosh, exp of an argument a + b (a in x, b free of x) by the addition
// theorems, so that G(t - tau) separates into functions of t times functions of tau.
ex separate_argument(const ex& e, const ex& x) {
    struct recurse : GiNaC::map_function {
        const ex& x;
        explicit recurse(const ex& v) : x(v) {}
        ex operator()(const ex& c) override { return separate_argument(c, x); }
    } inner(x);
    const ex m = e.map(inner);
    if (!GiNaC::is_a<GiNaC::function>(m) || m.nops() != 1) return m;
    const ex arg = GiNaC::expand(m.op(0));
    if (!arg.has(x)) return m;
    ex a = 0, b = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(arg) ? arg.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(arg) ? arg.op(i) : arg;
        (term.has(x) ? a : b) += term;
    }
    if (b.is_zero()) return m;
    using namespace GiNaC;
    if (is_ex_the_function(m, sin)) return sin(a) * cos(b) + cos(a) * sin(b);
    if (is_ex_the_function(m, cos)) return cos(a) * cos(b) - sin(a) * sin(b);
    if (is_ex_the_function(m, sinh)) return sinh(a) * cosh(b) + cosh(a) * sinh(b);
    if (is_ex_the_function(m, cosh)) return cosh(a) * cosh(b) + sinh(a) * sinh(b);
    if (is_ex_the_function(m, exp)) return exp(a) * exp(b);
    return m;
}

// The integral objects int_0^t g(tau) dtau of c with their variable renamed sigma, so that c(tau)
// (c.subs(t == tau)) holds int_0^tau g(sigma) dsigma and not a captured tau.
ex inner_variable(const ex& c, const ex& t) {
    const ex& tau = integration_variable();
    static const ex sigma = GiNaC::realsymbol("sigma");
    GiNaC::exmap inner;
    for (auto it = c.preorder_begin(); it != c.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::integral>(*it)) {
            if (!it->op(0).is_equal(tau) || !it->op(2).is_equal(t) || num::has_integral(it->op(3)))
                throw domain_error("int_0^t of " + to_string(c) +
                                   ": it holds an integral object that is not int_0^t g(tau) dtau");
            inner[*it] = GiNaC::integral(sigma, it->op(1), t, it->op(3).subs(tau == sigma));
        }
    return inner.empty() ? c : c.subs(inner, GiNaC::subs_options::no_pattern);
}

// int_0^t f(tau) dtau: in closed form where f is rational in tau (scalar/rational_integral.h:
// a/(1 + tau^2) gives a atan t), otherwise the integral object.
ex integral_object(const ex& f, const ex& t) {
    const ex& tau = integration_variable();
    if (const auto R = definite_rational_integral(f, tau, t)) return *R;
    return GiNaC::integral(tau, 0, t, f);
}

}  // namespace

ex duhamel(const ex& G, const ex& c, const ex& t) {
    try {
        return convolution(quasi_polynomial::from_ex(c, t), quasi_polynomial::from_ex(G, t)).to_ex();
    } catch (const domain_error&) {
        // sum_i k_i(t) int_0^t f_i(tau) dtau: what does not depend on tau (t too) outside, the
        // terms grouped by their part in tau (G(t - tau) = sin(w0 t) cos(w0 tau) - ... splits)
        const ex& tau = integration_variable();
        // (cos(w (t - tau)) = cos(w t) cos(-w tau) - ...: the signs out, cos(w tau), -sin(w tau))
        const ex e = GiNaC::expand(
            normalize_trig_signs(separate_argument(G.subs(t == t - tau), tau) * inner_variable(c, t).subs(t == tau)));
        std::vector<std::pair<ex, ex>> parts;  // f_i(tau), k_i
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
            const auto [k, f] = split_constant(GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e, tau);
            auto p = std::find_if(parts.begin(), parts.end(), [&](const auto& x) { return x.first.is_equal(f); });
            if (p == parts.end()) parts.push_back({f, k});
            else p->second += k;
        }
        ex out = 0;
        for (const auto& [f, k] : parts) out += k * integral_object(f, t);
        return out;
    }
}

// (Thm VI.2.1.1, VI.2.9-12) r = Q psi, Q the rotation by -a(t) about n = u/|u|.
ex solve_fixed_axis(const cauchy_problem& P, const fixed_axis_form& F) {
    ex psi = solve_unwitnessed(*F.inertial);
    if (!F.across.is_zero()) {
        // (VI.2.57-59, 62) psi_perp = -int_0^t G(t - tau) Q^T(tau) F_perp(tau) dtau
        // F_perp = sum_q q(t) W_q with every W_q constant (terms_in_time: t inside a literal,
        // [cos(t), 0, 0], goes into q, never stays in W outside the integral); a constant E: one
        // group, W = F_perp, and the two integrals I_c, I_s of VI.2.62
        const auto groups = terms_in_time(F.across, P.t);
        if (!groups)
            throw closed_form_error("the force " + to_string(F.across) + " across the axis " + to_string(F.u) +
                                    " is not a sum of functions of " + to_string(P.t) + " times constant vectors");
        const ex G = impulse_response(P, F), U = norm(F.u);
        for (const auto& [q, W] : *groups) {
            num::require_finite_on_half_line(q, P.t, "the free term " + to_string(-q * W));  // as on the right
            const ex C = duhamel(G, q * GiNaC::cos(F.angle), P.t);
            const ex S = duhamel(G, q * GiNaC::sin(F.angle), P.t);
            psi -= C * canonical(W) + S / U * canonical(cross(F.u, W));
        }
    }
    const ex U = norm(F.u);
    const auto [c, s] = cos_sin_of_angle(F.angle);
    const ex r = c * psi - s / U * cross(F.u, psi) + (1 - c) / (U * U) * dot(F.u, psi) * F.u;
    // with integral objects: one term per vector (the literal parts and the dot products of
    // a literal axis collected), which is what a reader needs to see I_c and I_s
    return F.across.is_zero() ? r : canonical(r);
}

std::vector<ex> first_integrals(const cauchy_problem& P, const fixed_axis_form& F) {
    if (P.order() != 2)
        throw domain_error("first_integrals: the problem has order " + std::to_string(P.order()) +
                           "; the first integrals of Thm VI.2.2.3.3 are of the second-order problem");
    if (!F.free.is_zero() || !F.across.is_zero())
        throw domain_error("first_integrals: the free term " + to_string(F.free + F.across) +
                           " does work on " + P.name + ": the energy is not conserved");
    const ex &r = P.unknowns[0], &r1 = P.unknowns[1];
    const ex p = r1 + cross(F.s * F.u, r);
    const ex L = cross(r, p);
    return {F.m * dot(p, p) / 2 + F.k * dot(r, r) / 2, dot(F.u, L), dot(L, L)};
}

ex integral_in_t(const ex& v, const ex& t) {
    const ex& tau = integration_variable();
    // the terms of c with an elementary integral one by one, the rest as one integral object
    auto scalar = [&](const ex& c0) -> ex {
        const ex c = GiNaC::expand(c0);
        if (c.is_zero()) return 0;
        ex done = 0, rest = 0;
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(c) ? c.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(c) ? c.op(i) : c;
            if (!term.has(t)) {
                done += term * t;
                continue;
            }
            try {
                done += quasi_polynomial::from_ex(term, t).antiderivative().to_ex();
                continue;
            } catch (const domain_error&) {
            }
            // an integral object inside (int_0^t g(tau) dtau, from the velocity): its variable
            // becomes sigma, so that the outer integral's tau only moves its upper limit
            rest += inner_variable(term, t);
        }
        if (rest.is_zero()) return done;
        // a common factor free of t stays outside: (v0 . u) int_0^t cos(a) dtau
        const ex r = GiNaC::factor(rest.subs(t == tau));
        ex outside = 1, inside = r;
        if (GiNaC::is_a<GiNaC::mul>(r)) {
            inside = 1;
            for (std::size_t i = 0; i < r.nops(); ++i) (r.op(i).has(tau) ? inside : outside) *= r.op(i);
        }
        return done + outside * integral_object(inside, t);
    };
    ex out = 0;
    for (const vector_term& term : canonical_terms(v)) {
        if (is_vector_literal(term.monomial) && term.monomial.has(t)) {
            const ex& M = term.monomial;
            out += vector_literal(scalar(GiNaC::expand(term.coefficient * M.op(0))),
                                  scalar(GiNaC::expand(term.coefficient * M.op(1))),
                                  scalar(GiNaC::expand(term.coefficient * M.op(2))));
        } else {
            out += scalar(term.coefficient) * term.monomial;
        }
    }
    return out;
}

}  // namespace symrep::mechanics
