// symrep/mechanics/first_integrals.cpp -- vector first integrals and generalized potentials
// (first_integrals.h).
#include "symrep/mechanics/first_integrals.h"

#include "symrep/core/error.h"
#include "symrep/mechanics/fixed_axis.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

void require_zero(const ex& e, const std::string& what) {
    if (!equal(e, 0)) throw internal_error("internal check failed: " + what + " is not proved 0");
}

central_motion read_central_motion(const cauchy_problem& P, const std::string& who) {
    if (!P.is_vector || P.order() != 2)
        throw domain_error(who + ": the problem has order " + std::to_string(P.order()) +
                           "; the first integrals of Thm VI.3.2.2 are of the second-order vector problem");
    central_motion C;
    C.t = P.t;
    C.r = P.unknowns[0];
    C.r1 = P.unknowns[1];
    C.r2 = P.unknowns[2];
    C.r0 = P.initial[0];
    C.v0 = P.initial[1];
    std::string why;
    if (P.turning) {
        const turning_frame_form& F = *P.turning;
        C.m = F.terms.m;
        C.w = F.terms.w;
        C.central = F.f.subs(F.terms.p == norm(C.r)) * C.r / norm(C.r);
        if (F.potential) C.potential = F.potential->subs(F.terms.p == norm(C.r));
        C.u = F.u;
    } else {
        const auto fa = P.fixed_axis ? std::optional<fixed_axis_form>(*P.fixed_axis) : read_fixed_axis(P, &why);
        if (!fa)
            throw domain_error(who + ": the problem is not m (r'' + 2 w x r' + w' x r + w x (w x r)) + m f(|r|) r/|r| = 0" +
                               (why.empty() ? std::string() : " (" + why + ")"));
        if (!fa->free.is_zero() || !fa->across.is_zero())
            throw domain_error(who + ": the free term " + to_string(fa->free + fa->across) + " does work on " + P.name +
                               ": the energy is not conserved");
        C.m = fa->m;
        C.w = fa->s * fa->u;
        C.central = fa->k / fa->m * C.r;
        C.potential = fa->k / fa->m * dot(C.r, C.r) / 2;
        C.u = fa->u;
    }
    C.constant_w = !depends_on_time(C.w, C.t);
    C.acceleration = -(2 * cross(C.w, C.r1) + cross(diff_t(C.w, C.t), C.r) + cross(C.w, cross(C.w, C.r))) - C.central;
    // the reading against the equation itself: E(r'' = acceleration) = 0
    require_zero(subs_vectors(P.expression, {{C.r2, C.acceleration}}), who + ": the equation at the read acceleration");
    return C;
}

ex derivative_along(const central_motion& C, const ex& e) { return subs_vectors(diff_t(e, C.t), {{C.r2, C.acceleration}}); }

ex frame_rate_at_zero(const central_motion& C) {
    require_value_at_zero(C.w, C.t, "w(t)");
    return C.w.subs(C.t == 0);
}

namespace {

// The reading of turning_frame.h for the frame's own w: Q in closed form or not.
turning_frame_form rotation_of(const ex& w, const ex& t) {
    turning_frame_form F;
    F.terms.w = w;
    if (const auto d = fixed_direction(w, t)) {
        F.u = d->second;
        F.angle = rotation_angle(d->first, d->second, t, true);
    } else {
        F.precessing = regular_precession(w, t);
    }
    return F;
}

}  // namespace

std::optional<ex> rotated_back(const ex& w, const ex& x0, const ex& t) {
    // (VI.3.117-118, VI.2.12) Q x0
    const auto y = closed_rotation(rotation_of(w, t), x0, t);
    if (!y) return std::nullopt;
    // proved: y' + w x y = 0 (VI.3.159) and y(0) = x0, so y = F_(-w)(x0) by uniqueness
    require_zero(diff_t(*y, t) + cross(w, *y), "F_(-w)(x0): y' + w x y");
    require_zero(y->subs(t == 0) - x0, "F_(-w)(x0) at t = 0");
    return y;
}

std::optional<ex> rotated_adjoint(const ex& w, const ex& x, const ex& t) {
    const turning_frame_form F = rotation_of(w, t);
    ex y;
    if (F.u && F.angle) {  // a fixed direction: Q^T is the rotation by the opposite angle
        turning_frame_form G = F;
        G.angle = -*F.angle;
        const auto q = closed_rotation(G, x, t);
        if (!q) return std::nullopt;
        y = *q;
    } else {
        // (Q^T x)_i = sum_j Q_ji (x . e_j), Q_ji the components of the literal Q e_i
        const ex e[3] = {vector_literal(1, 0, 0), vector_literal(0, 1, 0), vector_literal(0, 0, 1)};
        ex c[3];
        for (int i = 0; i < 3; ++i) {
            const auto q = closed_rotation(F, e[i], t);  // Q e_i
            if (!q || !vector_symbols(*q).empty()) return std::nullopt;
            const ex Qe = subs_components(*q, {});
            c[i] = 0;
            for (unsigned j = 0; j < 3; ++j) c[i] += GiNaC::normal(Qe.op(j)) * dot(e[j], x);
        }
        y = vector_literal(c[0], c[1], c[2]);
    }
    // (Thm VI.3.1.1, 6) Q (Q^T x) = x
    const auto back = closed_rotation(F, y, t);
    if (!back) return std::nullopt;
    require_zero(*back - x, "Q (Q^T x) - x");
    return y;
}

std::vector<vector_first_integral> vector_first_integrals(const cauchy_problem& P) {
    const central_motion C = read_central_motion(P, "vector_first_integrals");
    const ex w0 = frame_rate_at_zero(C);
    const ex p = C.r1 + cross(C.w, C.r), p0 = C.v0 + cross(w0, C.r0);
    std::vector<vector_first_integral> out;
    auto add = [&](const std::string& name, const ex& X, const ex& X0) {
        // (VI.3.159) X' + w x X = 0 along the equation: X = F_(-w)(X0)
        require_zero(derivative_along(C, X) + cross(C.w, X), name + ": X' + w x X along the equation");
        out.push_back({name, X, X0, rotated_back(C.w, X0, C.t)});
    };
    // free motion: p = r' + w x r itself (the centre of mass, VI.3.240-241)
    if (equal(C.central, 0)) add("r' + w x r = F_(-w)(v0 + w(0) x r0)   (VI.3.240-241)", p, p0);
    add("r x (r' + w x r) = F_(-w)(Omega0), Omega0 = r0 x (v0 + w(0) x r0)   (VI.2.99, VI.3.141)", cross(C.r, p),
        cross(C.r0, p0));
    return out;
}

std::vector<generalized_potential> generalized_potentials(const cauchy_problem& P) {
    const central_motion C = read_central_motion(P, "generalized_potentials");
    if (!C.potential)
        throw domain_error("generalized_potentials: the potential of the central field " + to_string(C.central) +
                           " is not elementary");
    const ex w0 = frame_rate_at_zero(C);
    const ex &m = C.m, &r = C.r, &w = C.w;
    const ex U = m * *C.potential, kinetic = m * dot(C.r1, C.r1) / 2;
    std::vector<generalized_potential> out;
    // (VI.2.110, VI.3.225) velocity-dependent
    const ex V1 = m * triple(w, r, C.r1) + m * dot(cross(w, r), cross(w, r)) / 2 + U;
    require_zero(derivative_along(C, kinetic + V1), "m |r'|^2/2 + V(t, r, r') along the equation");
    out.push_back({"V(t, r, r') = m (w, r, r') + m |w x r|^2/2 + m U(|r|)   (VI.2.110, VI.3.225)", V1});
    if (!C.u) return out;
    // (VI.2.111-114, VI.3.227) w = s(t) u: V2 - V1 = m w . (Omega0 - Omega), u . Omega constant
    const ex Omega = cross(r, C.r1 + cross(w, r)), Omega0 = cross(C.r0, C.v0 + cross(w0, C.r0));
    const ex V2 = m * dot(w, Omega0) - m * dot(cross(w, r), cross(w, r)) / 2 + U;
    require_zero(V2 - V1 - m * dot(w, Omega0 - Omega), "V(t, r) - V(t, r, r') - m w . (Omega0 - Omega)");
    require_zero(derivative_along(C, dot(*C.u, Omega)), "(u . Omega)' along the equation");
    require_zero(cross(w, *C.u), "w x u (the fixed direction)");
    out.push_back({"V(t, r) = m w . Omega0 - m |w x r|^2/2 + m U(|r|), Omega0 = r0 x (v0 + w(0) x r0)   "
                   "(VI.2.113-114, VI.3.227)",
                   V2});
    if (!C.constant_w) return out;
    // (VI.2.115, VI.3.229) w constant: m w . Omega0 is a constant
    out.push_back({"V(r) = -m |w x r|^2/2 + m U(|r|), the centrifugal potential   (VI.2.115, VI.3.229)",
                   V2 - m * dot(w, Omega0)});
    return out;
}

}  // namespace symrep::mechanics
