// symrep/dual/screw.cpp -- the dual Rodrigues formula, screw parameters and rigid
// motions (screw.h).
#include "symrep/dual/screw.h"

#include <cmath>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

namespace symrep::dual {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::matrix;

namespace {

std::string text(const ex& e) { return symrep::to_string(e); }

// s v for a scalar s and a vector v: entrywise on a literal (GiNaC keeps s * matrix unevaluated).
ex scaled(const ex& s, const ex& v) {
    if (!is_vector_literal(v)) return s * v;
    return vector_literal(tidy(s * v.op(0)), tidy(s * v.op(1)), tidy(s * v.op(2)));
}

// a + s b for literals a, b, entrywise.
ex plus_scaled(const ex& a, const ex& s, const ex& b) {
    return vector_literal(a.op(0) + s * b.op(0), a.op(1) + s * b.op(1), a.op(2) + s * b.op(2));
}

ex tidy_literal(const ex& v) {
    return vector_literal(simplify_scalar(v.op(0)), simplify_scalar(v.op(1)), simplify_scalar(v.op(2)));
}

// A real vector (or 0) free of eps; type_error naming `what` otherwise.
ex real_vector(const ex& e, const std::string& what) {
    if (has_dual_unit(e)) throw type_error(what + " must be a real vector, not the dual quantity " + text(e));
    if (!e.is_zero() && !is_vector(e)) throw type_error(what + " must be a vector, not the scalar " + text(e));
    return e;
}

// A dual vector: its primal and dual parts are vectors (or 0).
void require_dual_vector(const ex& e, const std::string& what) {
    const dual_parts p = parts(e);
    for (const ex& x : {p.primal, p.dual})
        if (!x.is_zero() && !is_vector(x))
            throw type_error(what + " must be a (dual) vector, not the scalar " + text(e));
}

ex mat_vec(const matrix& A, const ex& v) {
    const matrix r = A.mul(ex_to<matrix>(v));
    return vector_literal(r(0, 0), r(1, 0), r(2, 0));
}

matrix skew_matrix(const ex& v) {
    return matrix(3, 3, GiNaC::lst{0, -v.op(2), v.op(1), v.op(2), 0, -v.op(0), -v.op(1), v.op(0), 0});
}

// Zero for the rotation test: proved 0, or (an entry with floats) at most 1e-12 in size.
truth entry_is_zero(const ex& x) {
    const ex e = GiNaC::expand(x);
    if (is_a<GiNaC::numeric>(e) && !ex_to<GiNaC::numeric>(e).is_rational())
        return std::abs(ex_to<GiNaC::numeric>(e).to_double()) <= 1e-12 ? truth::yes : truth::no;
    return decide_zero(e).is_zero;
}

}  // namespace

ex tidy_dual(const ex& e) {
    const dual_parts p = parts(e);
    const auto one = [](const ex& x) -> ex {
        if (x.is_zero()) return x;
        if (!is_vector(x)) return simplify_scalar(x);
        if (vector_symbols(x).empty()) return tidy_literal(components_of(x, "a vector"));
        return canonical(x);
    };
    return make_dual(one(p.primal), one(p.dual));
}

ex dual_axis(const screw& s) {
    const ex u = real_vector(s.axis, "the screw axis");
    const ex p = real_vector(s.point, "the point on the screw axis");
    if (u.is_zero() || equal(u, 0)) throw type_error("the screw axis must be a nonzero vector, not 0");
    if (!is_nonzero_generic(dot(u, u), "|u|^2 of the screw axis u = " + text(u)))
        throw type_error("the screw axis " + text(u) + " is 0: it has no direction");
    const ex n = norm(u);
    const ex unit = scaled(1 / n, u);
    return make_dual(unit, cross(p, unit));
}

ex dual_angle(const screw& s) {
    if (is_vector(s.angle) || is_vector(s.translation))
        throw type_error("the screw angle and translation must be scalars");
    return reduce(s.angle + dual_unit() * s.translation);
}

ex exp_dual_skew(const ex& w, const ex& x, const ex& s) {
    require_dual_vector(w, "the twist w^");
    require_dual_vector(x, "the dual vector x^");
    const dual_parts wp = parts(w);
    const ex wx = dual_cross(w, x);
    // exp(eps V) = I + eps V: (eps V)^2 = 0
    if (has_dual_unit(s) || is_vector(s)) throw type_error("the time s of exp(s W^) must be a real scalar");
    if (wp.primal.is_zero() || equal(wp.primal, 0)) return tidy_dual(x + s * wx);
    if (!is_nonzero_generic(dot(wp.primal, wp.primal), "|w|^2 of the twist's primal part w = " + text(wp.primal)))
        return tidy_dual(x + s * wx);
    const ex th = GiNaC::sqrt(dual_dot(w, w));  // the dual norm |w^|
    return tidy_dual(x + GiNaC::sin(s * th) / th * wx +
                     (1 - GiNaC::cos(s * th)) / GiNaC::pow(th, 2) * dual_cross(w, wx));
}

ex screw_apply(const screw& s, const ex& x) {
    require_dual_vector(x, "the dual vector x^");
    const ex u = dual_axis(s), a = dual_angle(s);
    // [CB14] the dual Rodrigues formula
    return tidy_dual(GiNaC::cos(a) * x + GiNaC::sin(a) * dual_cross(u, x) + (1 - GiNaC::cos(a)) * dual_dot(u, x) * u);
}

ex components_of(const ex& e, const std::string& what) {
    if (has_dual_unit(e)) throw type_error(what + " must be a real vector, not the dual quantity " + text(e));
    if (e.is_zero()) return vector_literal(0, 0, 0);
    if (!is_vector(e)) throw type_error(what + " must be a vector, not the scalar " + text(e));
    if (is_vector_literal(e)) return e;
    if (!vector_symbols(e).empty())
        throw type_error(what + " must be given by its components [x, y, z] here (the matrix of R needs them), not " +
                         text(e));
    return subs_components(e, {});
}

rigid_motion motion_of_screw(const screw& s) {
    const ex u0 = components_of(s.axis, "the screw axis");
    const ex p = components_of(s.point, "the point on the screw axis");
    const dual_parts ua = parts(dual_axis(s));  // checks the axis
    const ex u = tidy_literal(ua.primal);
    const ex a = s.angle, d = s.translation;
    if (has_dual_unit(a) || has_dual_unit(d) || is_vector(a) || is_vector(d))
        throw type_error("the screw angle and translation must be real scalars");
    const ex c = GiNaC::cos(a), sn = GiNaC::sin(a);
    // (VI.1.13-15) Rodrigues: R = cos a I + sin a skew(u) + (1 - cos a) u u^T
    const matrix uu = ex_to<matrix>(u).mul(ex_to<matrix>(u).transpose());
    matrix R = ex_to<matrix>(GiNaC::unit_matrix(3)).mul_scalar(c).add(skew_matrix(u).mul_scalar(sn)).add(uu.mul_scalar(1 - c));
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) R(i, j) = tidy(R(i, j));
    // d = (I - R) p + d u
    const ex Rp = mat_vec(R, p);
    const ex dv = vector_literal(tidy(p.op(0) - Rp.op(0) + d * u.op(0)), tidy(p.op(1) - Rp.op(1) + d * u.op(1)),
                                 tidy(p.op(2) - Rp.op(2) + d * u.op(2)));
    (void)u0;
    return {R, dv};
}

void require_rotation(const matrix& R, const std::string& who) {
    if (R.rows() != 3 || R.cols() != 3) throw type_error(who + ": R must be a 3x3 matrix");
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j)
            if (has_dual_unit(R(i, j)) || is_vector(R(i, j)))
                throw type_error(who + ": the entries of R must be real scalars");
    const matrix G = R.transpose().mul(R).sub(ex_to<matrix>(GiNaC::unit_matrix(3)));
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = i; j < 3; ++j) {
            const truth z = entry_is_zero(G(i, j));
            if (z == truth::no)
                throw domain_error(who + ": R is not a rotation: entry (" + std::to_string(i + 1) + ", " +
                                   std::to_string(j + 1) + ") of R^T R - I is " + text(tidy(G(i, j))) + ", not 0");
            if (z == truth::unknown)
                throw domain_error(who + ": cannot decide whether R is orthogonal: entry (" + std::to_string(i + 1) +
                                   ", " + std::to_string(j + 1) + ") of R^T R - I is " + text(tidy(G(i, j))));
        }
    const ex det = R.determinant();
    const truth z = entry_is_zero(det - 1);
    if (z == truth::no)
        throw domain_error(who + ": R is orthogonal but det R = " + text(tidy(det)) +
                           ", not 1: a reflection, not a rotation");
    if (z == truth::unknown) throw domain_error(who + ": cannot decide whether det R = 1 (det R = " + text(det) + ")");
}

ex motion_apply(const rigid_motion& m, const ex& x) {
    require_dual_vector(x, "the dual vector x^");
    const dual_parts xp = parts(x);
    const ex a = components_of(xp.primal, "the direction of x^"), b = components_of(xp.dual, "the moment of x^");
    const ex Rx = mat_vec(m.R, a), Rb = mat_vec(m.R, b);
    const ex c = components_of(cross(m.d, Rx), "d x R x");
    // Q^ x^ = R x + eps (d x R x + R x')
    const ex dual = vector_literal(tidy(c.op(0) + Rb.op(0)), tidy(c.op(1) + Rb.op(1)), tidy(c.op(2) + Rb.op(2)));
    return make_dual(vector_literal(tidy(Rx.op(0)), tidy(Rx.op(1)), tidy(Rx.op(2))), dual);
}

ex half_turn_axis(const matrix& R, const std::string& who) {
    // R = 2 u u^T - I, so (R + I)/2 = u u^T; a column with a nonzero diagonal entry is u_i u
    const matrix M = R.add(ex_to<matrix>(GiNaC::unit_matrix(3))).mul_scalar(GiNaC::numeric(1, 2));
    for (unsigned i = 0; i < 3; ++i) {
        const ex mii = simplify_scalar(M(i, i));
        if (!is_nonzero_generic(mii, "u_" + std::to_string(i + 1) + "^2 = " + text(mii))) continue;
        const ex r = simplify_scalar(GiNaC::sqrt(mii));
        return tidy_literal(vector_literal(M(0, i) / r, M(1, i) / r, M(2, i) / r));
    }
    throw internal_error(who + ": a rotation by pi with (R + I)/2 = 0");
}

screw screw_of_motion(const rigid_motion& m) {
    const std::string who = "screw_parameters";
    require_rotation(m.R, who);
    const ex dv = components_of(m.d, "the translation d");
    const matrix& R = m.R;
    const ex c = simplify_scalar((R.trace() - 1) / 2);  // cos a
    // sin a u = vee(R - R^T)/2
    const ex sv = tidy_literal(vector_literal((R(2, 1) - R(1, 2)) / 2, (R(0, 2) - R(2, 0)) / 2, (R(1, 0) - R(0, 1)) / 2));
    if (!is_nonzero_generic(1 - c, "1 - cos a = " + text(1 - c) + " (is the angle 0?)")) {
        // a = 0: R = I, a pure translation along d
        const ex dd = simplify_scalar(dot(dv, dv));
        if (!is_nonzero_generic(dd, "|d|^2 = " + text(dd)))
            throw domain_error(who + ": the identity motion (R = I, d = 0) has no screw axis");
        const ex n = simplify_scalar(GiNaC::sqrt(dd));
        return {tidy_literal(scaled(1 / n, dv)), vector_literal(0, 0, 0), 0, n};
    }
    if (!is_nonzero_generic(1 + c, "1 + cos a = " + text(1 + c) + " (is the angle pi?)")) {
        // a = pi: the axis of the half turn
        const ex u = half_turn_axis(R, who);
        const ex t = simplify_scalar(dot(u, dv));
        const ex w = tidy_literal(scaled(GiNaC::numeric(1, 2), plus_scaled(dv, -t, u)));
        return {u, w, GiNaC::Pi, t};
    }
    const ex s = simplify_scalar(GiNaC::sqrt(simplify_scalar(dot(sv, sv))));  // sin a >= 0
    const ex u = tidy_literal(scaled(1 / s, sv));
    const ex a = atan2_exact(s, c);
    const ex t = simplify_scalar(dot(u, dv));
    const ex w = tidy_literal(plus_scaled(dv, -t, u));
    const ex cot = s / (1 - c);  // cot(a/2) = sin a/(1 - cos a)
    const ex p = tidy_literal(scaled(GiNaC::numeric(1, 2), plus_scaled(w, cot, components_of(cross(u, w), "u x w"))));
    return {u, p, a, t};
}

}  // namespace symrep::dual
