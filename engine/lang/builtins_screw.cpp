// symrep/lang/builtins_screw.cpp -- screw motion and dual quaternions in the language
// (issue 31 item 2; engine/dual/screw.h, dual_quaternion.h; docs/rigid_body.md section 2).
//
//   screw([0, 0, 1], [1, 0, 0], pi/2, 3, x)     Q^ x^, the dual Rodrigues formula
//   rigid_motion(u, p, a, d)                    [R, d] of the screw
//   screw_parameters(R, d)                      [u, p, a, d] back
//   q := dual_quaternion(u, p, a, d)            [s^, v^]; dual_quaternion(R, d) likewise
//   dq_product(q1, q2), dq_conjugate(q), dq_apply(q, x), dq_motion(q)
//   F(w, x) with dual w, x: exp(t W^) x^ (the dual rotation operator, constant twist)
#include "symrep/dual/dual.h"
#include "symrep/dual/dual_quaternion.h"
#include "symrep/dual/screw.h"
#include "symrep/lang/builtins.h"
#include "symrep/mechanics/dual_darboux.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;
using args_t = std::vector<value>;
using output::print_ex;

namespace {

const char* const section = "Screw motion and dual quaternions";

std::string usage(const builtin& b) { return " (usage: " + b.signature + ")"; }

// Argument i as a (dual) vector: an expression, or a list [x, y, z] whose entries may be dual.
ex dual_vector_arg(const args_t& a, std::size_t i, const builtin& b) {
    const value& v = a[i];
    ex e;
    if (v.is_list() && v.as_list().size() == 3 && v.as_list()[0].is_ex() && v.as_list()[1].is_ex() &&
        v.as_list()[2].is_ex())
        e = vector_literal(v.as_list()[0].as_ex(), v.as_list()[1].as_ex(), v.as_list()[2].as_ex());
    else
        e = arg_ex(a, i, b);
    const dual::dual_parts p = dual::parts(e);
    for (const ex& x : {p.primal, p.dual})
        if (!x.is_zero() && !is_vector(x))
            throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a (dual) vector, not " +
                             print_ex(e) + usage(b));
    return dual::make_dual(p.primal, p.dual);
}

// A real scalar argument (no eps, no vector).
ex real_scalar_arg(const args_t& a, std::size_t i, const builtin& b, const std::string& what) {
    const ex& e = arg_ex(a, i, b);
    if (dual::has_dual_unit(e) || is_vector(e))
        throw type_error(b.name + ": " + what + " (argument " + std::to_string(i + 1) + ") must be a real scalar, not " +
                         print_ex(e) + usage(b));
    return e;
}

// A real vector argument (no eps).
ex real_vector_arg(const args_t& a, std::size_t i, const builtin& b, const std::string& what) {
    const ex e = dual_vector_arg(a, i, b);
    if (dual::has_dual_unit(e))
        throw type_error(b.name + ": " + what + " (argument " + std::to_string(i + 1) + ") must be a real vector, not " +
                         print_ex(e) + usage(b));
    return e;
}

dual::screw screw_args(const args_t& a, std::size_t i, const builtin& b) {
    return {real_vector_arg(a, i, b, "the axis direction u"), real_vector_arg(a, i + 1, b, "the point p on the axis"),
            real_scalar_arg(a, i + 2, b, "the angle a"), real_scalar_arg(a, i + 3, b, "the translation d")};
}

// A 3x3 matrix: matrix([[...], [...], [...]]) or a list of three rows of three.
GiNaC::matrix rotation_arg(const args_t& a, std::size_t i, const builtin& b) {
    const value& v = a[i];
    if (v.is_list() && v.as_list().size() == 3) {
        GiNaC::matrix m(3, 3);
        for (unsigned r = 0; r < 3; ++r) {
            const value& row = v.as_list()[r];
            if (!row.is_list() || row.as_list().size() != 3)
                throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a 3x3 matrix R" + usage(b));
            for (unsigned c = 0; c < 3; ++c) {
                if (!row.as_list()[c].is_ex())
                    throw type_error(b.name + ": the entries of R must be expressions" + usage(b));
                m(r, c) = row.as_list()[c].as_ex();
            }
        }
        return m;
    }
    const ex& e = arg_ex(a, i, b);
    if (!GiNaC::is_a<GiNaC::matrix>(e) || GiNaC::ex_to<GiNaC::matrix>(e).rows() != 3 ||
        GiNaC::ex_to<GiNaC::matrix>(e).cols() != 3)
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a 3x3 matrix R, not " +
                         print_ex(e) + usage(b));
    return GiNaC::ex_to<GiNaC::matrix>(e);
}

dual::rigid_motion motion_args(const args_t& a, std::size_t i, const builtin& b) {
    return {rotation_arg(a, i, b), dual::components_of(real_vector_arg(a, i + 1, b, "the translation d"),
                                                       b.name + ": the translation d")};
}

// A dual quaternion [s^, v^].
dual::dual_quaternion dq_arg(const args_t& a, std::size_t i, const builtin& b) {
    const value& v = a[i];
    if (!v.is_list() || v.as_list().size() != 2 || !v.as_list()[0].is_ex())
        throw type_error(b.name + ": argument " + std::to_string(i + 1) +
                         " must be a dual quaternion [s, v] (a dual scalar and a dual vector, as dual_quaternion "
                         "gives)" + usage(b));
    const args_t parts{v.as_list()[0], v.as_list()[1]};
    const ex s = parts[0].as_ex();
    if (is_vector(dual::primal(s)) || is_vector(dual::dual_part(s)))
        throw type_error(b.name + ": the first entry of the dual quaternion must be a (dual) scalar" + usage(b));
    return dual::make_dual_quaternion(s, dual_vector_arg(parts, 1, b));
}

value dq_value(const dual::dual_quaternion& q) { return value(list{value(q.scalar), value(q.vector)}); }

value motion_value(const dual::rigid_motion& m) { return value(list{value(ex(m.R)), value(m.d)}); }


value builtin_screw(const builtin& b, const args_t& a, context&) {
    const dual::screw s = screw_args(a, 0, b);
    const ex x = dual_vector_arg(a, 4, b);
    return value(named_by(b, [&] { return dual::screw_apply(s, x); }));
}

value builtin_twist_exp(const builtin& b, const args_t& a, context&) {
    const ex w = dual_vector_arg(a, 0, b), x = dual_vector_arg(a, 1, b);
    return value(named_by(b, [&] { return dual::exp_dual_skew(w, x); }));
}

value builtin_rigid_motion(const builtin& b, const args_t& a, context&) {
    const dual::screw s = screw_args(a, 0, b);
    return motion_value(named_by(b, [&] { return dual::motion_of_screw(s); }));
}

value builtin_screw_parameters(const builtin& b, const args_t& a, context&) {
    const dual::rigid_motion m = motion_args(a, 0, b);
    const dual::screw s = named_by(b, [&] { return dual::screw_of_motion(m); });
    return value(list{value(s.axis), value(s.point), value(s.angle), value(s.translation)});
}

value builtin_dual_quaternion(const builtin& b, const args_t& a, context&) {
    if (a.size() == 4) {
        const dual::screw s = screw_args(a, 0, b);
        return dq_value(named_by(b, [&] { return dual::dq_of_screw(s); }));
    }
    if (a.size() != 2) throw type_error(b.name + ": give the screw (u, p, a, d) or the motion (R, d)" + usage(b));
    const dual::rigid_motion m = motion_args(a, 0, b);
    return dq_value(named_by(b, [&] { return dual::dq_of_motion(m); }));
}

value builtin_dq_product(const builtin& b, const args_t& a, context&) {
    const dual::dual_quaternion p = dq_arg(a, 0, b), q = dq_arg(a, 1, b);
    return dq_value(dual::dq_product(p, q));
}

value builtin_dq_conjugate(const builtin& b, const args_t& a, context&) { return dq_value(dual::dq_conjugate(dq_arg(a, 0, b))); }

value builtin_dq_apply(const builtin& b, const args_t& a, context&) {
    const dual::dual_quaternion q = dq_arg(a, 0, b);
    const ex x = dual_vector_arg(a, 1, b);
    return value(named_by(b, [&] { return dual::dq_apply(q, x); }));
}

value builtin_dq_motion(const builtin& b, const args_t& a, context&) {
    const dual::dual_quaternion q = dq_arg(a, 0, b);
    return motion_value(named_by(b, [&] { return dual::motion_of_dq(q); }));
}

value builtin_motion_apply(const builtin& b, const args_t& a, context&) {
    const dual::rigid_motion m = motion_args(a, 0, b);
    const ex x = dual_vector_arg(a, 2, b);
    return value(named_by(b, [&] {
        dual::require_rotation(m.R, b.name);
        return dual::motion_apply(m, x);
    }));
}

}  // namespace

bool has_dual_argument(const args_t& a) {
    for (const value& v : a) {
        if (v.is_ex() && dual::has_dual_unit(v.as_ex())) return true;
        if (v.is_list())
            for (const value& y : v.as_list())
                if (y.is_ex() && dual::has_dual_unit(y.as_ex())) return true;
    }
    return false;
}

value dual_rotation_operator(const builtin& b, const args_t& a, context& c, const builtin_body& real_operator) {
    const ex w = dual_vector_arg(a, 0, b), x = dual_vector_arg(a, 1, b);
    const ex t = c.symbol("t");
    if (!dual::has_dual_unit(w)) {
        // a real w: the operator is linear, F(w, x + eps x') = F(w, x) + eps F(w, x')
        const dual::dual_parts xp = dual::parts(x);
        const value y = real_operator(b, {a[0], value(xp.primal)}, c), y1 = real_operator(b, {a[0], value(xp.dual)}, c);
        if (!y.is_ex() || !y1.is_ex())
            throw closed_form_error(b.name + ": w = " + print_ex(w) +
                                    " turns (R numeric): F of a dual x is in closed form only where R is");
        return value(dual::make_dual(y.as_ex(), y1.as_ex()));
    }
    // (VI.1.13-15) by transference: R' = W^ R, R(0) = I gives R = exp(t W^) for a constant twist
    const ex dw = diff_t(w, t);  // (a literal's derivative is a matrix of zeros)
    if (!w.has(t) && (dw.is_zero() || equal(dw, 0)))
        return value(named_by(b, [&] { return dual::exp_dual_skew(w, x, t); }));
    // a dual twist w(t): y = F_w(x) solves y' = w x y, y(0) = x, the dual Poisson-Darboux problem
    // with Omega^ = -w: closed for a fixed screw axis and a regular screw precession
    // (mechanics/dual_darboux.h), else numeric (Magnus on SE(3)), evaluated by eval
    if (mechanics::depends_on_time(x, t))
        throw closed_form_error(b.name + ": x = " + print_ex(x) + " depends on t: over a turning dual twist w(t) "
                                "F(w, x) takes a constant x");
    const auto P = named_by(b, [&] { return mechanics::dual_rotation_problem(w, x, t); });
    if (const auto y = mechanics::dual_darboux_motion(P->dual_darboux->twist, P->dual_darboux->x0, t))
        // one literal [a + eps b, ...] where the data have components (as F of a real w prints)
        return value(vector_symbols(*y).empty() ? dual::reduce(subs_components(*y, {})) : *y);
    return value(reduction{std::make_shared<const mechanics::reduced_solution>(
        mechanics::reduced_solution{P, {}, true})});
}

void register_screw_builtins(registry& r) {
    add_builtins(r, section, {
        {"screw", "screw(u, p, a, d, x)",
         "The screw motion about the axis through p along u (any nonzero direction, normalized), by the angle a "
         "about it and the translation d along it (pitch d/a), applied to the dual vector x = x0 + eps m (a line: "
         "direction x0, moment m = q x x0 for a point q on it; a real x is a line through the origin): the dual "
         "Rodrigues formula Q x = cos(A) x + sin(A) U x x + (1 - cos(A)) (U . x) U with the dual axis "
         "U = u + eps p x u and the dual angle A = a + eps d, i.e. Q = exp(A U x), reduced modulo eps^2.",
         "[CB14] dual Rodrigues formula; (VI.1.13-15) by transference",
         "screw([0, 0, 1], [1, 0, 0], pi/2, 3, [1, 0, 0])", 5, 5, builtin_screw},
        {"twist_exp", "twist_exp(w, x)",
         "exp(W) x for a dual vector w = w0 + eps v (a twist times a time; W y = w x y the dual skew tensor) and a "
         "dual vector x: x + sin|w|/|w| w x x + (1 - cos|w|)/|w|^2 w x (w x x) with the dual norm |w|; for w0 = 0 "
         "(a pure translation) x + eps v x x. The screw (u, p, a, d) is the twist w = a u + eps (a p x u + d u).",
         "[CB14] exponential of a dual skew tensor",
         "twist_exp([0, 0, 1], [0, 1, 0])", 2, 2, builtin_twist_exp},
        {"rigid_motion", "rigid_motion(u, p, a, d)",
         "The rigid motion of a screw as [R, d]: rotate by R, then translate by d (the dual tensor "
         "(I + eps skew(d)) R), R = exp(a skew(u)) by Rodrigues and d = (I - R) p + d u. u and p need components.",
         "[CB14] screw to (R, d)",
         "rigid_motion([0, 0, 1], [1, 0, 0], pi/2, 3)", 4, 4, builtin_rigid_motion},
        {"screw_parameters", "screw_parameters(R, d)",
         "The screw [u, p, a, d] of the rigid motion (R, d): cos a = (tr R - 1)/2 and sin a u = vee(R - R^T)/2 with "
         "a in [0, pi], p = (w + cot(a/2) u x w)/2 the point of the axis nearest the origin (w = d - (u . d) u), "
         "d = u . d. a = 0 is a pure translation (u = d/|d|, p = 0); a = pi takes u from (R + I)/2 = u u^T. "
         "Refused: R not a rotation (R^T R = I and det R = 1 proved; float entries to 1e-12), the identity (no "
         "axis), and an angle that cannot be decided 0, pi or neither.",
         "[CB14] (R, d) to screw",
         "screw_parameters([[0, -1, 0], [1, 0, 0], [0, 0, 1]], [1, 1, 3])", 2, 2, builtin_screw_parameters},
        {"dual_quaternion", "dual_quaternion(u, p, a, d) or dual_quaternion(R, d)",
         "The unit dual quaternion [s, v] (a dual scalar, a dual vector) of a screw, cos(A/2) + sin(A/2) U "
         "(U = u + eps p x u, A = a + eps d), or of a rigid motion (R, d): r + eps d r/2 with r = (cos(a/2), "
         "sin(a/2) u) from R, cos(a/2) >= 0. The two agree up to the sign of q, which both represent.",
         "[CB14] dual quaternions",
         "dual_quaternion([0, 0, 1], [1, 0, 0], pi/2, 3)", 2, 4, builtin_dual_quaternion},
        {"dq_product", "dq_product(q1, q2)",
         "The product q1 q2 of dual quaternions [s, v]: [s1 s2 - v1 . v2, s1 v2 + s2 v1 + v1 x v2] (dual): the "
         "motion q2, then q1.",
         "[CB14] dual quaternion product",
         "q := dual_quaternion([0, 0, 1], [1, 0, 0], pi/2, 3)\ndq_product(q, q)", 2, 2, builtin_dq_product},
        {"dq_conjugate", "dq_conjugate(q)",
         "The conjugate [s, -v] of a dual quaternion: the inverse motion of a unit one.",
         "[CB14] dual quaternion conjugate",
         "dq_conjugate(dual_quaternion([0, 0, 1], [1, 0, 0], pi/2, 3))", 1, 1, builtin_dq_conjugate},
        {"dq_apply", "dq_apply(q, x)",
         "q x q* for a unit dual quaternion q (checked) and a dual vector x (a line): x + 2 s v x x + 2 v x (v x x), "
         "the same as the dual tensor of q.",
         "[CB14] action on lines",
         "dq_apply(dual_quaternion([0, 0, 1], [1, 0, 0], pi/2, 3), [1, 0, 0])", 2, 2, builtin_dq_apply},
        {"dq_motion", "dq_motion(q)",
         "The rigid motion [R, d] of a unit dual quaternion q = [s + eps s', v + eps v'] (checked): "
         "R x = (s^2 - v . v) x + 2 (v . x) v + 2 s v x x, d = 2 (s v' - s' v + v x v').",
         "[CB14] dual quaternion to (R, d)",
         "dq_motion(dual_quaternion([0, 0, 1], [1, 0, 0], pi/2, 3))", 1, 1, builtin_dq_motion},
        {"motion_apply", "motion_apply(R, d, x)",
         "The rigid motion (R, d) applied to the dual vector x = x0 + eps m of a line: R x0 + eps (d x R x0 + R m) "
         "(the dual tensor (I + eps skew(d)) R); R is checked a rotation.",
         "[CB14] dual orthogonal tensor",
         "motion_apply([[0, -1, 0], [1, 0, 0], [0, 0, 1]], [1, 1, 3], [1, 0, 0])", 3, 3, builtin_motion_apply},
    });
}

}  // namespace symrep::lang
