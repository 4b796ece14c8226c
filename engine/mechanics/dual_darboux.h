// symrep/mechanics/dual_darboux.h -- the dual Poisson-Darboux problem in closed form
// (issue 31 item 3; docs/rigid_body.md section 3).
//
// The rigid motion of a frame with the twist Omega^(t) = w(t) + eps v(t) (dual angular
// velocity) is the dual orthogonal tensor Q^ with
//     Q^' = -Omega^ Q^,  Q^(0) = I        (the dual counterpart of VI.3.117),
// that is R' = -W R, d' = -w x d - v for Q^ = (I + eps skew(d)) R; on a dual vector
// x^ = x + eps y (a line, a screw) x^(t) = Q^ x^0 solves
//     x^' + Omega^ x x^ = 0,  x^(0) = x^0.
// Nothing here is typed in: each closed form is the engine's real closed form of Q
// (turning_frame.h closed_rotation: VI.2.12 for a fixed axis, the composition A B of a
// regular precession) with dual data put in and reduced modulo eps^2 (dual/dual.h). That
// is the transference principle: the real Q is an analytic function of its data (the
// rate, the axis, the spin), the dual problem is the real one to first order along the
// dual parts, and the dual extension f(a + eps b) = f(a) + eps b f'(a) is that first order.
// The three forms, each read from Omega^ as given and then confirmed by rebuilding Omega^
// from what was read (dual_equal: a reading that is not exact is no reading):
//   - a fixed screw axis, Omega^ = s^(t) u^ with u^ = u + eps u' constant (primal u != 0)
//     and s^ = s(t) + eps sigma(t): the screw about the line of u^ (direction u, moment u')
//     turning by a^ = |u^| int_0^t s^ (translating along it by the dual part of a^ over |u|).
//     A constant twist is s^ = 1, u^ = Omega^; a pure translation eps sigma(t) u has s = 0.
//   - a regular screw precession, Omega^ = c^ u1^ + A^(t) v^ with A^(t) the screw by
//     -c^ t about the dual unit axis u1^ (c^ = c + eps c': a rate and a translation speed
//     along the axis), v^ a constant twist carried round: Q^ = A^(t) B^(t), B^ the constant
//     twist v^'s motion. Read from Omega^ = W0^ + C^ cos(c^ t) + S^ sin(c^ t), whose dual part
//     holds c' t (S cos(c t) - C sin(c t)) when the precession rate has a dual part.
// Otherwise (a general Omega^(t)) there is no closed form: closed_form_error by the caller.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/reduced_solution.h"
#include "symrep/numeric/se3.h"

namespace symrep::mechanics {

/// The reading of a twist Omega^(t) (all dual quantities reduced, in dual::dual_unit()).
struct dual_twist_form {
    enum class kind { zero, fixed_axis, precession, general } form = kind::general;
    GiNaC::ex omega;        ///< Omega^ reduced
    /// fixed_axis: Omega^ = (s + eps sigma) u^, u^ constant with a nonzero primal part
    GiNaC::ex s, sigma, u;
    /// precession: Omega^ = c^ u1^ + A^(t) v^ (u1^ a dual unit vector, c^ a dual rate, v^ constant)
    GiNaC::ex u1, c, v;
};

/// Reads Omega^ (a dual vector expression in t, reduced or not) as above; kind::general when
/// none of the closed forms fits (never a guess: each reading is confirmed exactly).
/// domain_error when a zero test it needs cannot be decided.
dual_twist_form read_dual_twist(const GiNaC::ex& omega, const GiNaC::ex& t);

/// Q^ x^ for the fixed screw axis Omega^ = (s + eps sigma) u^ (VI.2.12 by transference),
/// reduced. s, sigma real scalar functions of t, u^ a constant dual vector with u != 0.
GiNaC::ex fixed_screw_motion(const GiNaC::ex& s, const GiNaC::ex& sigma, const GiNaC::ex& u, const GiNaC::ex& x,
                             const GiNaC::ex& t);

/// Q^ x^ = A^(t) B^(t) x^ for the regular screw precession (the composition of
/// turning_frame.h by transference), reduced.
GiNaC::ex screw_precession_motion(const GiNaC::ex& u1, const GiNaC::ex& c, const GiNaC::ex& v, const GiNaC::ex& x,
                                  const GiNaC::ex& t);

/// Q^ x^ for a twist read above; nothing for kind::general.
std::optional<GiNaC::ex> dual_darboux_motion(const dual_twist_form& F, const GiNaC::ex& x, const GiNaC::ex& t);

/// The exact check: x^' + Omega^ x x^ reduced modulo eps^2 is proved 0 part by part
/// (dual_equal), and x^(0) = x^0. False when not proved.
bool dual_darboux_solves(const GiNaC::ex& omega, const GiNaC::ex& x0, const GiNaC::ex& x, const GiNaC::ex& t);

/// A problem in the dual unit: its expression or an initial value holds eps.
bool is_dual_problem(const cauchy_problem& P);

/// The reading of a dual problem m (x' + Omega^ x x) = 0, x(0) = x^0 (m a nonzero constant,
/// dual or not), for read_problem(): nothing (and `why` the reason) when P is of another form.
struct dual_darboux_form {
    dual_twist_form twist;
    GiNaC::ex x0;  ///< x^0 reduced
};
std::optional<dual_darboux_form> read_dual_darboux(const cauchy_problem& P, std::string* why = nullptr);

/// The closed form x^(t) = Q^ x^0; closed_form_error naming Omega^ when the twist has none.
GiNaC::ex solve_dual_darboux(const cauchy_problem& P, const dual_darboux_form& F);

/// (The real problems behind a dual one, for the witness and the checks.) x^ = x + eps y of
/// m (x' + Omega^ x x) = 0 as two real problems: the primal x' + w x x = 0, x(0) = x0, and the
/// dual y' + w x y + v x x_s(t) = 0, y(0) = y0, with x_s the primal part of the candidate s.
std::pair<cauchy_problem, cauchy_problem> dual_darboux_parts(const cauchy_problem& P, const dual_darboux_form& F,
                                                             const GiNaC::ex& s);

/// (Otherwise: a twist without a closed form, numerically.) x^(t) = Q^(t) x^0 at each of `times`
/// (sorted, >= 0) for P.dual_darboux: Q^' = -Omega^ Q^, Q^(0) = I by the sixth-order Magnus method
/// on SE(3) (num::se3_tensor, relative tolerance 1e-13; Q^ stays a rigid motion whatever the step),
/// with every value put in by `put`; with `derivative`, x^' = -Omega^ x x^ instead. Each result is
/// the pair (primal, dual part). type_error naming a symbol left without a value; the errors of
/// se3_tensor (a twist not finite, the step limit of about 10 s of work).
std::vector<num::twist> dual_darboux_states(const cauchy_problem& P, const value_map& put,
                                            const std::vector<double>& times, bool derivative = false);

/// y = F_w(x0) for a dual w(t) (the rotation operator of VI.3.118 by transference): the problem
/// y' = w x y, y(0) = x0 read as the dual Poisson-Darboux problem with Omega^ = -w (P.dual_darboux
/// set); x0 a constant dual vector.
std::shared_ptr<const cauchy_problem> dual_rotation_problem(const GiNaC::ex& w, const GiNaC::ex& x0,
                                                            const GiNaC::ex& t);

}  // namespace symrep::mechanics
