// symrep/dual/screw.h -- screw motion: the dual orthogonal tensor as the exponential
// of a dual skew tensor (the dual Rodrigues formula), its screw parameters, and
// the rigid motion (R, d) it stands for (issue 31 item 2; docs/rigid_body.md section 2).
//
// A screw is an axis (direction u, through the point p), an angle a about it and a
// translation d along it (pitch d/a). In dual form ([CB14]):
//     u^ = u + eps (p x u)     the dual unit axis (u a unit vector: u^ . u^ = 1)
//     a^ = a + eps d           the dual angle
// and the motion acts on the dual vector of a line x^ = x + eps (q x x) by the dual
// Rodrigues formula, the real one with every quantity dual (transference):
//     Q^ x^ = cos(a^) x^ + sin(a^) u^ x x^ + (1 - cos(a^)) (u^ . x^) u^ ,
// that is Q^ = exp(a^ U^), U^ y^ = u^ x y^ the dual skew tensor. For any dual vector
// w^ = w + eps v (a twist times a time: the dual vector a^ u^ = a u + eps (a p x u + d u)
// is the twist (w, v) in Pluecker coordinates),
//     exp(W^) x^ = x^ + sin|w^|/|w^| w^ x x^ + (1 - cos|w^|)/|w^|^2 w^ x (w^ x x^),
// |w^| = sqrt(w^ . w^) the dual norm; for w = 0 (a pure translation) exp(eps V) = I + eps V.
//
// The same motion is the rigid motion "rotate by R, then translate by d",
// Q^ = (I + eps skew(d)) R (docs/rigid_body.md conventions), with
//     R = exp(a U),  d = (I - R) p + d u.
// screw_of_motion() inverts it: cos a = (tr R - 1)/2, sin a u = vee(R - R^T)/2, a in [0, pi],
//     p = (w + cot(a/2) u x w)/2 with w = d - (u . d) u  (the point of the axis nearest 0),
// the cases a = 0 (a pure translation: u = d/|d|) and a = pi (u from (R + I)/2 = u u^T)
// apart; an angle that cannot be decided 0 or pi is refused, never guessed.
//
// Everything here is exact: dual quantities are expressions in the dual unit eps
// (dual.h), reduced modulo eps^2.
#pragma once

#include <string>

#include <ginac/ginac.h>

namespace symrep::dual {

/// The screw parameters: the axis through `point` along `axis` (any nonzero direction;
/// the formulas use u = axis/|axis|), the angle about it and the translation along it.
struct screw {
    GiNaC::ex axis;
    GiNaC::ex point;
    GiNaC::ex angle;
    GiNaC::ex translation;
};

/// e reduced, each part in the form results are given in: a vector without vector symbols
/// as one literal with simplified entries, another vector in canonical form (vector.h), a
/// scalar simplified.
GiNaC::ex tidy_dual(const GiNaC::ex& e);

/// The dual unit axis u^ = u + eps (p x u), u = axis/|axis|; type_error when the axis is
/// not a vector or is 0, domain_error when it cannot be decided nonzero.
GiNaC::ex dual_axis(const screw& s);
/// The dual angle a^ = a + eps d.
GiNaC::ex dual_angle(const screw& s);

/// exp(s W^) x^ with W^ y^ = w^ x y^, for any dual vector w^, dual vector x^ and real scalar
/// s (a time; 1 by default): x^ + sin(s|w^|)/|w^| w^ x x^ + (1 - cos(s|w^|))/|w^|^2 w^ x (w^ x x^)
/// (the dual Rodrigues formula, above), reduced. A primal part w proved 0: x^ + s eps v x x^.
GiNaC::ex exp_dual_skew(const GiNaC::ex& w, const GiNaC::ex& x, const GiNaC::ex& s = 1);

/// Q^ x^ = cos(a^) x^ + sin(a^) u^ x x^ + (1 - cos(a^)) (u^ . x^) u^ ([CB14]), reduced.
GiNaC::ex screw_apply(const screw& s, const GiNaC::ex& x);

/// The rigid motion "rotate by R, then translate by d": Q^ = (I + eps skew(d)) R.
struct rigid_motion {
    GiNaC::matrix R;  ///< 3x3, orthogonal with det 1
    GiNaC::ex d;      ///< a vector literal [d1, d2, d3]
};

/// The components of a vector expression without vector symbols, as a literal; type_error
/// naming `what` when e is not a vector or still has vector symbols.
GiNaC::ex components_of(const GiNaC::ex& e, const std::string& what);

/// R = exp(a U), d = (I - R) p + d u. The axis and the point must have components
/// (literals, no vector symbols): R is a matrix.
rigid_motion motion_of_screw(const screw& s);

/// Checks that R is a rotation: R^T R = I and det R = 1 proved (entries that are floats:
/// to 1e-12); domain_error naming the entry that is not, or cannot be decided.
void require_rotation(const GiNaC::matrix& R, const std::string& who);

/// Q^ x^ = R x + eps (d x R x + R x') for x^ = x + eps x' with components.
GiNaC::ex motion_apply(const rigid_motion& m, const GiNaC::ex& x);

/// The unit axis u of a rotation R by the angle pi (R = 2 u u^T - I): the column i of
/// (R + I)/2 = u u^T with the first diagonal entry u_i^2 not proved 0, over u_i > 0.
GiNaC::ex half_turn_axis(const GiNaC::matrix& R, const std::string& who);

/// The screw parameters of a rigid motion (above): a in [0, pi], u a unit vector, p the
/// point of the axis nearest the origin. domain_error for the identity (no axis), for an
/// R that is not a rotation and for an angle not decided 0, pi or neither.
screw screw_of_motion(const rigid_motion& m);

}  // namespace symrep::dual
