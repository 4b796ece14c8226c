// symrep/mechanics/moving_frame.h -- motion seen from a frame that rotates AND translates
// ([CS21] Condurache-Sfartz, Symmetry 13:1963 (2021), Thms 11-12; docs/rigid_body.md section 4):
// solve in the frozen inertial frame (the moving frame at t = 0), then apply the frame's rigid
// motion.
//
// The frame turns with the angular velocity w(t) (its components in the frame) and its origin moves
// along o(t), a path given in the frozen inertial frame. Its rigid motion is the dual orthogonal
// tensor Q^ = (I + eps skew(d)) R of docs/rigid_body.md, R' = -W R, R(0) = I (VI.3.117), d = -R o:
// a point X of the inertial frame is seen at r = R X + d = R (X - o). Its twist is
// Omega^ = w + eps v with v = R o' (the origin's velocity seen in the frame): d' = -w x d - v.
// Differentiating X = R^T (r - d) twice (R^T' = R^T W),
//     R X'' = L[r] + A,   L[r] = r'' + 2 w x r' + w' x r + w x (w x r),   A = R o'' = -L[d]
// (A the acceleration of the origin seen in the frame), and R X' = (r - d)' + w x (r - d).
// So the inertial problem E0(X, X', X'', t) = 0, X(0) = X0, X'(0) = V0 (any problem that ode()
// reads and solve() solves: gravity m X'' = m g, a charge m X'' = q (X' x B + E), Kepler
// X'' + mu X/|X|^3 = 0 with the attracting centre at the inertial origin, an oscillator ...)
// is, seen from the frame, the problem
//     R E0(R^T (r - d), ..., t) = E0 with X -> r - d, X' -> (r - d)' + w x (r - d), X'' -> L[r - d],
//                                 and every constant vector V -> R V,                (Thm 11)
//     r(0) = X0 - o(0),  r'(0) = V0 - o'(0) - w(0) x r(0),
// which holds because E0 is built of vector operations only (sums, products by scalars, cross, dot,
// norm), which R commutes with (R (a x b) = R a x R b, |R a| = |a|). Its solution is
//     r = R (psi - o),  psi = the solution of the inertial problem                     (Thm 12)
// in closed form when psi is (solve of the inertial problem) and R is: a constant w (Rodrigues), a
// fixed direction w = s(t) u (VI.2.12, the angle |u| int_0^t s), a regular precession (Q = A B,
// turning_frame.h). Kepler's psi is numeric (universal variables): the solution is then the
// reduction object of reduced_solution.h with the origin o(t) (r = Q (psi - o)), evaluated by eval
// and verify. A turning w has no closed R: the frame's equation then holds each R(t) V it needs (a
// constant vector of P0, o, o', o'') as a vector function of t of its own (moving_frame_form::
// carried), solved numerically by carried_frame_states() (psi closed) or moving_frame_states()
// (Kepler), R by Magnus on SO(3); a problem stated directly in the frame with the origin's
// acceleration A(t) as a free term, m (L[r] + A(t)) = F(t), is solved by the VI.3 path
// (turning_frame.h) already.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/rotating_frame.h"
#include "symrep/scalar/equality.h"

namespace symrep::mechanics {

/// The frame of a problem made by moving_frame_problem().
struct moving_frame_form {
    GiNaC::ex w;  ///< the frame's angular velocity w(t), its components in the frame
    GiNaC::ex o;  ///< the path of its origin in the frozen inertial frame
    GiNaC::ex d;  ///< d = -R o, where the inertial origin is seen from the frame (0 when o = 0)
    std::shared_ptr<const cauchy_problem> inertial;  ///< the problem in the frozen inertial frame (psi)
    /// y = R psi, the same problem seen from the frame turning with w about the inertial origin
    /// (VI.3.132), read by read_problem(): the reduction when psi has no closed form; may be null.
    std::shared_ptr<const cauchy_problem> rotating;
    /// Where R(t) has no closed form (a turning w) and the frame's equation needs R V (a constant
    /// vector of P0, the origin's path o and its derivatives): each R(t) V(t) is a vector function
    /// of t of its own, named R_V (R_g, R_o, R_do, R_ddo, R_V1 for a literal), paired here with V.
    /// Empty when R is closed. Such a problem is solved numerically (r = Q (psi - o), Q by Magnus on
    /// SO(3), psi closed or by universal variables) and verified with R integrated beside it.
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> carried;
};

/// R x in closed form for the frame's w (R' = -W R, R(0) = I: a constant w, a fixed direction, a
/// regular precession); nothing when w turns otherwise.
std::optional<GiNaC::ex> frame_rotation(const GiNaC::ex& w, const GiNaC::ex& x, const GiNaC::ex& t);

/// (Thm 11) The inertial problem P0 (second order, vector) seen from the frame (w, o): the problem
/// in the frame (its unknown named as P0's), registered as a moving-frame problem (moving_frame_of).
/// With a turning w (R(t) not closed) every R V the equation needs is a vector function of its own
/// (moving_frame_form::carried). domain_error: a scalar or first-order P0, a w without a value at
/// t = 0, an o that is not a vector of t finite at 0.
std::shared_ptr<const cauchy_problem> moving_frame_problem(const std::shared_ptr<const cauchy_problem>& P0,
                                                           const GiNaC::ex& w, const GiNaC::ex& o);

/// The frame of P when P is (the very object) made by moving_frame_problem(), else null. The frame
/// is kept beside the problem, in a registry keyed by the problem object (weakly: an entry goes with
/// its problem), not in a field of cauchy_problem: a copy of P (a scene, with_values) is not a
/// moving-frame problem and is read as any other (where it is refused: not a wrong reading).
std::shared_ptr<const moving_frame_form> moving_frame_of(const cauchy_problem& P);

/// The origin's path o(t) when P is the rotating problem (moving_frame_form::rotating) of a frame
/// that translates, else 0: reduced_solution.h evaluates its object as r = Q (psi - o).
GiNaC::ex moving_frame_origin(const cauchy_problem& P);

/// (Thm 12) r = R (psi - o) in closed form; closed_form_error when psi is numeric (Kepler: the
/// reduction object of P.moving->rotating with the origin o, reduced_solution.h).
GiNaC::ex solve_moving_frame(const cauchy_problem& P, const moving_frame_form& F);

/// (Thm 11 for this problem, exactly) P's equation is E0 with X -> r + R o, X' -> r' + w x r + R o',
/// X'' -> L[r] + R o'' and every vector V -> R V. With p(t) an arbitrary vector function and R in
/// closed form, the zero test proves the kinematics at r = R (p - o):
///     r + R o = R p,   r' + w x r + R o' = R p',   L[r] + R o'' = R p'',
/// so that P's residual at R (p - o) is E0(R p, R p', R p'', R V) = R E0(p, p', p'', V) (E0 is built
/// of vector operations, which commute with a rotation), and P's initial values are the inertial
/// ones carried (by construction): every solution psi of the inertial problem (Kepler's by
/// universal variables too) gives the solution R (psi - o) of P. yes (proved), no (seen nonzero at
/// a point: a defect), or unknown; domain_error when R has no closed form.
zero_decision prove_moving_frame(const cauchy_problem& P, const moving_frame_form& F);

/// (Thm 12 for a rigid body) the frame's dual tensor on a dual vector: a line of a body, x^ = a + eps b
/// (direction a through the point p, b = p x a) in the frozen inertial frame at time t, is seen
/// from the frame as Q^ x^ = R a + eps (R b + d x R a) (= R a + eps ((d + R p) x R a), the line
/// through r = R p + d), Q^ = (I + eps skew(d)) R, in closed form. domain_error when R has none.
GiNaC::ex seen_from_frame(const moving_frame_form& F, const GiNaC::ex& line, const GiNaC::ex& t);

/// True when the inertial psi has no closed form (a nonlinear central field): solve() refuses and
/// the solution is the reduction object.
bool inertial_is_numeric(const moving_frame_form& F);

/// (Thm 12 numerically, for a frame with carried vectors) r = Q (psi - o) and r' = Q (psi' - o') - w x r
/// at each time (sorted, >= 0): psi the inertial problem's closed form with the values put in by
/// `put`, o(t) likewise, Q by Magnus on SO(3) (num::rotation_tensor, 1e-13). type_error naming a
/// symbol without a value; closed_form_error when psi has no closed form (Kepler: the reduction
/// object of `rotating` with the origin, reduced_solution.h).
std::vector<rotating_frame_state> carried_frame_states(const moving_frame_form& F,
                                                       const std::function<GiNaC::ex(const GiNaC::ex&)>& put,
                                                       const std::vector<double>& times);

/// The numeric frame (any w(t), a turning one too): the rotating-frame problem of the inertial
/// motion (w, field, psi(0), psi'(0) as rotating_frame_problem's r0 and v0 + w(0) x r0 ... see the
/// .cpp) and the origin's path o(t) with its derivative.
struct numeric_moving_frame {
    rotating_frame_problem rotating;    ///< y = Q psi: w, w', the central field, y(0), y'(0)
    std::function<Eigen::Vector3d(double)> origin, origin_velocity;  ///< o(t), o'(t)
};

/// (Thm 12 numerically) r = Q (psi - o), r' = Q (psi' - o') - w x r at each time (sorted, >= 0): Q by
/// Magnus on SO(3) (or its closed form when given), psi in closed form or by universal variables.
std::vector<rotating_frame_state> moving_frame_states(const numeric_moving_frame& P, const std::vector<double>& times,
                                                      const num::rotation_tensor_options& options = {});

}  // namespace symrep::mechanics
