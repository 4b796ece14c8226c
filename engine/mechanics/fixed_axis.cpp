// symrep/mechanics/fixed_axis.cpp -- reduction of a fixed-axis rotating-frame
// problem to the inertial one (fixed_axis.h; thesis VI.2).
#include "mechanics/fixed_axis.h"

#include <map>

#include "core/error.h"
#include "mechanics/quasi_polynomial.h"
#include "mechanics/turning_frame.h"
#include "scalar/scalar.h"
#include "vector/vector.h"

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
        const bool varying = T->w.has(P.t);  // a reason is given only for a w that depends on t
        auto refuse = [&](const std::string& reason) -> std::optional<fixed_axis_form> {
            if (why && varying) *why = reason;
            return std::nullopt;
        };
        const auto d = fixed_direction(T->w, P.t);
        // a turning direction or a nonlinear central field: no closed form, and no reason
        // from here (turning_frame.h reads it, with Q or psi numeric)
        if (!d || T->g.has(T->p)) return std::nullopt;
        fixed_axis_form F;
        F.s = d->first;
        F.u = d->second;
        const ex w = F.s * F.u;
        if (!T->free.is_zero() && !equal(cross(F.u, T->free), 0))  // Q^T F = F needs F along u
            return refuse(T->form + "the free term " + to_string(T->free) + " is not along the axis " +
                          to_string(F.u) + " (the inertial problem would have the rotated force Q^T F)");
        // a(t) = |u| int_0^t s
        F.angle = norm(F.u) * quasi_polynomial::from_ex(F.s, P.t).antiderivative().to_ex();
        F.m = T->m;
        F.k = T->g;
        F.free = T->free;
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
