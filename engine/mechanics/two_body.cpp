// symrep/mechanics/two_body.cpp -- the two-body problem's global characteristics (two_body.h).
#include "symrep/mechanics/two_body.h"

#include <map>

#include "symrep/core/error.h"
#include "symrep/mechanics/first_integrals.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;
using vmap = std::map<ex, ex, GiNaC::ex_is_less>;

namespace {

// The coupled motion: the bodies as vector functions X1(t), X2(t) of the problem's t.
struct coupled {
    ex t, w, m1, m2, M, m;
    ex x1, x2, v1, v2;  // the user's vector symbols
    ex X1, X2;          // the functions of t
    ex a1, a2;          // X1'', X2'' from the coupled equations
    // e(x_i, v_i) -> d/dt along the coupled equations
    // e on the motion: x_i -> X_i(t), v_i -> X_i'(t)
    ex on(const ex& e) const {
        return subs_vectors(e, {{x1, X1}, {x2, X2}, {v1, derivative(X1)}, {v2, derivative(X2)}});
    }
    ex along(const ex& e) const {
        return subs_vectors(diff_t(on(e), t), {{derivative(derivative(X1)), a1}, {derivative(derivative(X2)), a2}});
    }
};

ex sq(const ex& v) { return dot(v, v); }

}  // namespace

std::vector<two_body_quantity> two_body_characteristics(const cauchy_problem& CMP, const cauchy_problem& RELP,
                                                        const ex& m1, const ex& m2, const ex& x1s, const ex& x2s,
                                                        const ex& v1s, const ex& v2s) {
    const std::string who = "two_body";
    const central_motion CM = read_central_motion(CMP, who), REL = read_central_motion(RELP, who);
    if (!equal(CM.central, 0))
        throw domain_error(who + ": the centre of mass moves freely (VI.3.202), but the first problem has the field " +
                           to_string(CM.central));
    if (!equal(CM.w - REL.w, 0))
        throw domain_error(who + ": the two problems are in different frames: w = " + to_string(CM.w) + " and " +
                           to_string(REL.w));
    if (!REL.potential)
        throw domain_error(who + ": the potential of the central field " + to_string(REL.central) + " is not elementary");
    coupled B;
    B.t = REL.t;
    B.w = REL.w;
    B.m1 = m1;
    B.m2 = m2;
    B.M = m1 + m2;
    B.m = m1 * m2 / B.M;
    B.x1 = x1s;
    B.x2 = x2s;
    B.v1 = v1s;
    B.v2 = v2s;
    B.X1 = GiNaC::realsymbol("body1");  // names apart from the user's (vector_symbols goes by name)
    B.X2 = GiNaC::realsymbol("body2");
    register_vector_function(B.X1, B.t);
    register_vector_function(B.X2, B.t);
    const ex &w = B.w, &M = B.M, &m = B.m, &t = B.t;
    const ex wd = diff_t(w, t);
    auto frame_operator = [&](const ex& X) {
        return 2 * cross(w, derivative(X)) + cross(wd, X) + cross(w, cross(w, X));
    };
    // the relative field f(|r|) r/|r| at r = x2 - x1 (REL's own unknown replaced)
    const ex field = subs_vectors(REL.central, {{REL.r, B.X2 - B.X1}});
    B.a1 = -frame_operator(B.X1) + m2 / M * field;
    B.a2 = -frame_operator(B.X2) - m1 / M * field;
    // the decoupling (VI.3.202, 216-218): the two problems back from the coupled equations
    const ex Rc = (m1 * B.X1 + m2 * B.X2) / M;
    require_zero((m1 * B.a1 + m2 * B.a2) / M - subs_vectors(CM.acceleration, {{CM.r, Rc}, {CM.r1, diff_t(Rc, t)}}),
                 who + ": the centre of mass's acceleration");
    require_zero(B.a2 - B.a1 - subs_vectors(REL.acceleration, {{REL.r, B.X2 - B.X1}, {REL.r1, diff_t(B.X2 - B.X1, t)}}),
                 who + ": the relative acceleration");

    const ex &x1 = B.x1, &x2 = B.x2, &v1 = B.v1, &v2 = B.v2;
    const ex rc = (m1 * x1 + m2 * x2) / M, vc = (m1 * v1 + m2 * v2) / M, r = x2 - x1, v = v2 - v1;
    const ex pc = vc + cross(w, rc), pr = v + cross(w, r);
    const ex p1 = v1 + cross(w, x1), p2 = v2 + cross(w, x2);
    const ex V = m * subs_vectors(*REL.potential, {{REL.r, r}});
    std::vector<two_body_quantity> out;
    auto add = [&](const std::string& name, const ex& e) { out.push_back({name, is_vector(e) ? canonical(e) : e, false, w}); };
    auto constant = [&](const ex& e, const std::string& what) { require_zero(B.along(e), who + ": (" + what + ")'"); };
    auto rotating = [&](const ex& X, const std::string& what) {
        require_zero(B.along(X) + cross(w, B.on(X)), who + ": " + what + "' + w x " + what);
    };
    // (VI.3.253-255, 259-260) the quantities of the rotating frame itself
    const ex P = m1 * v1 + m2 * v2, K0 = m1 * cross(x1, v1) + m2 * cross(x2, v2), Ecin = m1 * sq(v1) / 2 + m2 * sq(v2) / 2;
    const ex I0w = m1 * cross(x1, cross(w, x1)) + m2 * cross(x2, cross(w, x2));
    const ex Vc = m1 * triple(w, x1, v1) + m1 * sq(cross(w, x1)) / 2 + m2 * triple(w, x2, v2) + m2 * sq(cross(w, x2)) / 2;
    add("P = m1 v1 + m2 v2   (VI.3.253)", P);
    add("K0 = m1 x1 x v1 + m2 x2 x v2   (VI.3.254)", K0);
    add("E_cin = m1 |v1|^2/2 + m2 |v2|^2/2   (VI.3.255)", Ecin);
    add("I0 w = sum m_i x_i x (w x x_i)   (VI.3.259)", I0w);
    add("V_c = sum m_i ((w, x_i, v_i) + |w x x_i|^2/2)   (VI.3.260)", Vc);
    add("V = m U(|x2 - x1|), the interaction, m = m1 m2/M   (VI.3.189, 252)", V);
    // (VI.3.237-242, 256) the modified linear momentum
    const ex H = m1 * p1 + m2 * p2;
    require_zero(H - (P + M * cross(w, rc)), who + ": H - (P + M w x r_c)");
    require_zero(H - M * pc, who + ": H - M (r_c' + w x r_c)");
    rotating(H, "H");
    add("H = sum m_i (v_i + w x x_i) = P + M w x r_c = M (r_c' + w x r_c); H' + w x H = 0   (VI.3.237-240, 256)", H);
    // (VI.3.243-247, 257) the modified angular momentum
    const ex L0 = m1 * cross(x1, p1) + m2 * cross(x2, p2);
    require_zero(L0 - (K0 + I0w), who + ": L0 - (K0 + I0 w)");
    require_zero(L0 - (m * cross(r, pr) + M * cross(rc, pc)), who + ": L0 - (m r x (r' + w x r) + M r_c x (r_c' + w x r_c))");
    rotating(L0, "L0");
    add("L0 = sum m_i x_i x (v_i + w x x_i) = K0 + I0 w = m r x (r' + w x r) + M r_c x (r_c' + w x r_c); "
        "L0' + w x L0 = 0   (VI.3.243-247, 257)",
        L0);
    // (VI.3.248-252, 258, 263-264) the modified kinetic energy and the energy integral
    const ex T = m1 * sq(p1) / 2 + m2 * sq(p2) / 2;
    require_zero(T - (Ecin + Vc), who + ": T - (E_cin + V_c)");
    require_zero(T - (m * sq(pr) / 2 + M * sq(pc) / 2), who + ": T - (m |r' + w x r|^2/2 + M |r_c' + w x r_c|^2/2)");
    constant(T + V, "T + V");
    add("T = sum m_i |v_i + w x x_i|^2/2 = E_cin + V_c = m |r' + w x r|^2/2 + M |r_c' + w x r_c|^2/2   (VI.3.248-249, 258)",
        T);
    add("E_cin + V_c + V = T + V, constant: V_c + V the generalized potential   (VI.3.252, 263-264)", Ecin + Vc + V);
    // (VI.3.241, 245, 267-268) the vector integrals from their initial values
    const ex w0 = frame_rate_at_zero(REL);
    const ex H0 = M * (CM.v0 + cross(w0, CM.r0));
    const ex L00 = m * cross(REL.r0, REL.v0 + cross(w0, REL.r0)) + M * cross(CM.r0, CM.v0 + cross(w0, CM.r0));
    auto by_rotation = [&](const std::string& name, const ex& X0) {
        if (const auto y = rotated_back(w, X0, t)) out.push_back({name, *y, false, w});  // the form of VI.2.12
        else out.push_back({name + "   (Q numeric: X0 given)", X0, true, w});
    };
    by_rotation("H(t) = F_(-w)(H0), H0 = M (V0 + w(0) x R0)   (VI.3.241, 267)", H0);
    by_rotation("L0(t) = F_(-w)(L0^0), L0^0 = m r0 x (u0 + w(0) x r0) + M R0 x (V0 + w(0) x R0)   (VI.3.245, 268)", L00);
    const auto u = REL.u;
    if (u) {
        // (VI.3.265) E_cin + V(t, x1, x2) = T + V + w . (L0^0 - L0), u . L0 constant (from L0' + w x L0 = 0)
        const ex V265 = dot(w, L00) - m1 * sq(cross(w, x1)) / 2 - m2 * sq(cross(w, x2)) / 2 + V;
        require_zero(Ecin + V265 - (T + V) - dot(w, L00 - L0), who + ": E_cin + V(t, x1, x2) - (T + V) - w . (L0^0 - L0)");
        constant(dot(*u, L0), "u . L0");
        require_zero(cross(w, *u), who + ": w x u");
        add("V(t, x1, x2) = w . L0^0 - sum m_i |w x x_i|^2/2 + V: E_cin + V constant (fixed direction)   (VI.3.265)", V265);
        if (REL.constant_w)
            add("V(x1, x2) = -sum m_i |w x x_i|^2/2 + V, the centrifugal potential (w constant)   (VI.3.266)",
                V265 - dot(w, L00));
    }
    // (VI.3.269-291) the centre-of-mass frame: x_i' = x_i - r_c, synchronous with the frame
    const ex y1 = x1 - rc, y2 = x2 - rc, u1 = v1 - vc, u2 = v2 - vc;
    const ex q1 = u1 + cross(w, y1), q2 = u2 + cross(w, y2);
    require_zero(m1 * q1 + m2 * q2, who + ": H^c");
    add("H^c = sum m_i (y_i' + w x y_i), y_i = x_i - r_c (the centre-of-mass frame): 0   (VI.3.269-273, 276)", m1 * q1 + m2 * q2);
    const ex Lc = m1 * cross(y1, q1) + m2 * cross(y2, q2);
    require_zero(Lc - m * cross(r, pr), who + ": L_c - m r x (r' + w x r)");
    rotating(Lc, "L_c");
    require_zero(dot(y1, Lc), who + ": x1' . L_c");
    require_zero(dot(y2, Lc), who + ": x2' . L_c");
    add("L_c = sum m_i y_i x (y_i' + w x y_i) = m r x (r' + w x r); L_c' + w x L_c = 0; y_i . L_c = 0   "
        "(VI.3.274, 277, 280-281)",
        Lc);
    by_rotation("L_c(t) = F_(-w)(L_c0), L_c0 = m r0 x (u0 + w(0) x r0)   (VI.3.279)",
                m * cross(REL.r0, REL.v0 + cross(w0, REL.r0)));
    const ex Tc = m1 * sq(q1) / 2 + m2 * sq(q2) / 2, Ecc = m1 * sq(u1) / 2 + m2 * sq(u2) / 2;
    require_zero(Tc - m * sq(pr) / 2, who + ": T^c - m |r' + w x r|^2/2");
    require_zero(Ecc - m * sq(v) / 2, who + ": E_cin^c - m |r'|^2/2");
    constant(Tc + V, "T^c + V");
    add("T^c = sum m_i |y_i' + w x y_i|^2/2 = m |r' + w x r|^2/2; T^c + V constant   (VI.3.275, 278, 285)", Tc);
    const ex V287 = m * triple(w, r, v) + m * sq(cross(w, r)) / 2 + V;
    require_zero(Ecc + V287 - (Tc + V), who + ": E_cin^c + V(t, r, r') - (T^c + V)");
    add("V(t, r, r') = m (w, r, r') + m |w x r|^2/2 + V: E_cin^c + V constant, r = x2 - x1   (VI.3.286-288)", V287);
    if (u) {
        const ex Omega0 = cross(REL.r0, REL.v0 + cross(w0, REL.r0)), Omega = cross(r, pr);
        const ex V290 = m * dot(w, Omega0) - m * sq(cross(w, r)) / 2 + V;
        require_zero(V290 - V287 - m * dot(w, Omega0 - Omega), who + ": V(t, r) - V(t, r, r') - m w . (Omega0 - Omega)");
        constant(dot(*u, Omega), "u . (r x (r' + w x r))");
        add("V(t, r) = m w . Omega0 - m |w x r|^2/2 + V: E_cin^c + V constant (fixed direction)   (VI.3.289-290)", V290);
        if (REL.constant_w)
            add("V(r) = -m |w x r|^2/2 + V: E_cin^c + V constant, Jacobi's integral (w constant)   (VI.3.291)",
                V290 - m * dot(w, Omega0));
    }
    return out;
}

}  // namespace symrep::mechanics
