// symrep/dual/dual_quaternion.cpp -- dual quaternions and their conversions
// (dual_quaternion.h).
#include "symrep/dual/dual_quaternion.h"

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

namespace symrep::dual {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::matrix;

namespace {

std::string text(const ex& e) { return symrep::to_string(e); }

}  // namespace

dual_quaternion make_dual_quaternion(const ex& s, const ex& v) {
    const dual_parts sp = parts(s), vp = parts(v);
    if (is_vector(sp.primal) || is_vector(sp.dual))
        throw type_error("the scalar part of a dual quaternion must be a (dual) scalar, not " + text(s));
    for (const ex& x : {vp.primal, vp.dual})
        if (!x.is_zero() && !is_vector(x))
            throw type_error("the vector part of a dual quaternion must be a (dual) vector, not the scalar " + text(v));
    return {tidy_dual(make_dual(sp.primal, sp.dual)), tidy_dual(make_dual(vp.primal, vp.dual))};
}

dual_quaternion dq_of_screw(const screw& s) {
    const ex u = dual_axis(s), a = dual_angle(s);
    // [CB14] q^ = cos(a^/2) + sin(a^/2) u^
    return make_dual_quaternion(reduce(GiNaC::cos(a / 2)), reduce(GiNaC::sin(a / 2) * u));
}

dual_quaternion dq_product(const dual_quaternion& a, const dual_quaternion& b) {
    const ex s = reduce(a.scalar * b.scalar - dual_dot(a.vector, b.vector));
    const ex v = reduce(a.scalar * b.vector + b.scalar * a.vector + dual_cross(a.vector, b.vector));
    return make_dual_quaternion(s, v);
}

dual_quaternion dq_conjugate(const dual_quaternion& q) { return make_dual_quaternion(q.scalar, reduce(-q.vector)); }

ex dq_norm_defect(const dual_quaternion& q) {
    return reduce(q.scalar * q.scalar + dual_dot(q.vector, q.vector) - 1);
}

void require_unit(const dual_quaternion& q, const std::string& who) {
    const dual_parts d = parts(dq_norm_defect(q));
    for (const ex& x : {d.primal, d.dual}) {
        const ex e = tidy(GiNaC::expand(x));
        const truth z = decide_zero(e).is_zero;
        if (z == truth::no)
            throw domain_error(who + ": not a unit dual quaternion: q^ q^* - 1 = " + text(make_dual(d.primal, d.dual)) +
                               ", not 0");
        if (z == truth::unknown)
            throw domain_error(who + ": cannot decide whether the dual quaternion is a unit one (q^ q^* - 1 = " +
                               text(make_dual(d.primal, d.dual)) + ")");
    }
}

ex dq_apply(const dual_quaternion& q, const ex& x) {
    require_unit(q, "dq_apply");
    const dual_parts xp = parts(x);
    for (const ex& y : {xp.primal, xp.dual})
        if (!y.is_zero() && !is_vector(y)) throw type_error("dq_apply: x^ must be a (dual) vector, not " + text(x));
    const ex vx = dual_cross(q.vector, x);
    // q^ x^ q^* = x^ + 2 s^ v^ x x^ + 2 v^ x (v^ x x^) for a unit q^
    return tidy_dual(x + 2 * q.scalar * vx + 2 * dual_cross(q.vector, vx));
}

dual_quaternion dq_of_motion(const rigid_motion& m) {
    const std::string who = "dual_quaternion";
    require_rotation(m.R, who);
    const ex dv = components_of(m.d, "the translation d");
    const matrix& R = m.R;
    const ex tr1 = simplify_scalar(R.trace() + 1);  // 4 cos^2(a/2)
    ex s, v;
    if (!is_nonzero_generic(tr1, "1 + tr R = " + text(tr1) + " (is the angle pi?)")) {
        s = 0;  // a = pi: v = u, the axis of the half turn
        v = half_turn_axis(R, who);
    } else {
        s = simplify_scalar(GiNaC::sqrt(tr1) / 2);
        const ex k = 1 / (4 * s);  // v = vee(R - R^T)/(4 s)
        v = tidy_dual(vector_literal(k * (R(2, 1) - R(1, 2)), k * (R(0, 2) - R(2, 0)), k * (R(1, 0) - R(0, 1))));
    }
    // q^ = r + eps (1/2) (0, d) r = r + eps (1/2) (-d . v, s d + d x v)
    const ex dvx = components_of(cross(dv, v), "d x v");
    const ex sd = simplify_scalar(-dot(dv, v) / 2);
    const ex vd = tidy_dual(vector_literal((s * dv.op(0) + dvx.op(0)) / 2, (s * dv.op(1) + dvx.op(1)) / 2,
                                             (s * dv.op(2) + dvx.op(2)) / 2));
    return make_dual_quaternion(make_dual(s, sd), make_dual(v, vd));
}

rigid_motion motion_of_dq(const dual_quaternion& q) {
    const std::string who = "dq_motion";
    require_unit(q, who);
    const dual_parts sp = parts(q.scalar), vp = parts(q.vector);
    const ex s = sp.primal, s1 = sp.dual;
    const ex v = components_of(vp.primal, "the vector part of q^"), v1 = components_of(vp.dual, "the dual vector part of q^");
    // R = (s^2 - v.v) I + 2 v v^T + 2 s skew(v)
    const matrix& V = ex_to<matrix>(v);
    const matrix S(3, 3, GiNaC::lst{0, -v.op(2), v.op(1), v.op(2), 0, -v.op(0), -v.op(1), v.op(0), 0});
    matrix R = ex_to<matrix>(GiNaC::unit_matrix(3))
                   .mul_scalar(s * s - dot(v, v))
                   .add(V.mul(V.transpose()).mul_scalar(2))
                   .add(S.mul_scalar(2 * s));
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) R(i, j) = simplify_scalar(R(i, j));
    // d = 2 (s v' - s' v + v x v')
    const ex c = components_of(cross(v, v1), "v x v'");
    const ex d = tidy_dual(vector_literal(2 * (s * v1.op(0) - s1 * v.op(0) + c.op(0)),
                                            2 * (s * v1.op(1) - s1 * v.op(1) + c.op(1)),
                                            2 * (s * v1.op(2) - s1 * v.op(2) + c.op(2))));
    return {R, d};
}

}  // namespace symrep::dual
