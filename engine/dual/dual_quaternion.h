// symrep/dual/dual_quaternion.h -- dual quaternions, coordinate-free: a second
// representation of rigid motions (issue 31 item 2; docs/rigid_body.md section 2).
//
// A dual quaternion is a pair (dual scalar s^, dual vector v^), both expressions in
// the dual unit eps (dual.h). The product is the quaternion product with every
// quantity dual (transference):
//     (s1, v1)(s2, v2) = (s1 s2 - v1 . v2, s1 v2 + s2 v1 + v1 x v2),
// the conjugate (s, v)* = (s, -v). The motion of the screw (u^, a^) (screw.h) is the
// unit dual quaternion
//     q^ = cos(a^/2) + sin(a^/2) u^                                   ([CB14])
// (unit: q^ q^* = 1, i.e. s^2 + v.v = 1 and s s' + v . v' = 0 for s^ = s + eps s',
// v^ = v + eps v'), and it acts on the dual vector of a line by x^ -> q^ x^ q^*:
//     q^ x^ q^* = x^ + 2 s^ v^ x x^ + 2 v^ x (v^ x x^),
// the same as the dual tensor Q^ x^. The rigid motion (R, d) (Q^ = (I + eps skew(d)) R)
// is q^ = r + eps (1/2) d r with r = (s, v) the unit quaternion of R
// (s = cos(a/2) >= 0, sin(a/2) u = v), and back:
//     R x = (s^2 - v.v) x + 2 (v.x) v + 2 s v x x,   d = 2 (s v' - s' v + v x v').
// Composition of motions is the product: q^(Q1^ Q2^) = q1^ q2^ (checked in the tests).
#pragma once

#include <ginac/ginac.h>

#include "symrep/dual/screw.h"

namespace symrep::dual {

struct dual_quaternion {
    GiNaC::ex scalar;  ///< a dual scalar s^
    GiNaC::ex vector;  ///< a dual vector v^ (or 0)
};

/// (s^, v^) checked (s^ a scalar, v^ a vector or 0) and reduced; type_error naming what is wrong.
dual_quaternion make_dual_quaternion(const GiNaC::ex& s, const GiNaC::ex& v);

/// q^ = cos(a^/2) + sin(a^/2) u^ of the screw (u^, a^).
dual_quaternion dq_of_screw(const screw& s);
/// The product q1^ q2^ (first q2^, then q1^ when acting), reduced.
dual_quaternion dq_product(const dual_quaternion& a, const dual_quaternion& b);
/// The conjugate (s^, -v^); for a unit dual quaternion its inverse.
dual_quaternion dq_conjugate(const dual_quaternion& q);
/// q^ q^* - 1 as (scalar part, its dual part): (s^2 + v.v - 1) + eps 2 (s s' + v . v').
GiNaC::ex dq_norm_defect(const dual_quaternion& q);
/// domain_error unless q^ is proved a unit dual quaternion (`who` names the caller).
void require_unit(const dual_quaternion& q, const std::string& who);
/// q^ x^ q^* for a unit q^ (checked) and a dual vector x^.
GiNaC::ex dq_apply(const dual_quaternion& q, const GiNaC::ex& x);
/// The unit dual quaternion of a rigid motion, with s = cos(a/2) >= 0 (a = pi: s = 0 and
/// the sign of v from (R + I)/2, as screw_of_motion); R checked a rotation.
dual_quaternion dq_of_motion(const rigid_motion& m);
/// The rigid motion (R, d) of a unit dual quaternion (checked) whose parts have components.
rigid_motion motion_of_dq(const dual_quaternion& q);

}  // namespace symrep::dual
