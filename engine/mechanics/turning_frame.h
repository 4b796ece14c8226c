// symrep/mechanics/turning_frame.h -- problems in a frame that rotates with an
// arbitrary angular velocity w(t) (thesis VI.3), with a central positional field,
// as a user writes them, and their reduction to the inertial problem.
//
// The problem (m a constant, w(t) any vector expression in t: a literal with
// components in t, s(t) u, a sum of such; f a function of |r| only):
//     m (r'' + 2 w x r' + w' x r + w x (w x r)) + m f(|r|) r/|r| = 0,
//     r(0) = r0,  r'(0) = v0                                      (VI.3.132)
// (order 1: m (x' + w x x) + k x = 0, x(0) = x0, a charge in B(t) with w = q B/m).
// read_frame_terms() reads m, w (the cross terms on r' over 2 m) and what is
// left beside the rotating-frame operator; read_turning_frame() accepts it
// when that rest is a central field g(|r|) r (a constant k, k r/|r|^3 for
// Kepler, any g given as an expression in |r|), and a free term F(t) only with
// a constant k (a sum of functions of t times constant vectors, each finite for
// t >= 0): then psi'' + k/m psi = -Q^T F(t)/m (Thm VI.3.2.1 with a force; order 1
// likewise), psi = psi_unforced - int_0^t G(t - tau) Q^T(tau) F(tau)/m dtau,
// evaluated with Q^T by Boost.Odeint (reduced_solution.h).
// By Thm VI.3.2.1 the solution is
//     r = F_{-w}(psi) = Q psi,  Q' = -W Q, Q(0) = I  (W x = w x x, VI.3.117),
// psi the inertial solution of psi'' + f(|psi|) psi/|psi| = 0 with
// psi(0) = r0 and psi'(0) = v0 + w(0) x r0 (VI.3.133), r' = Q psi' - w x r.
// Q has no closed form for a turning w: the solution is an object
// (reduced_solution) that prints this derivation and is evaluated numerically
// (numeric/rotation_tensor.h: Magnus on SO(3); closed form (VI.2.12) when w has
// a fixed direction; psi in closed form for f = 0, f = w0^2 p and Kepler's
// f = mu/p^2 by universal variables, numeric/kepler.h; odeint otherwise).
//
// A fixed direction with a constant k and a free term along the axis is read
// first by fixed_axis.h, which gives a closed form; this header takes the rest.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

/// What read_frame_terms() finds in E: E = m (operator) + g(|x|) x + free.
struct frame_terms {
    std::size_t order = 2;
    GiNaC::ex m;      ///< the constant leading coefficient
    GiNaC::ex w;      ///< w(t) as the user wrote it (cross terms / (order m))
    GiNaC::ex g;      ///< the coefficient of x, a function of the symbol p = |x| (constant for a linear term)
    GiNaC::ex free;   ///< the terms without an unknown
    GiNaC::ex p;      ///< the positive symbol standing for |x| in g
    std::string form; ///< "the problem has the rotating-frame terms of w(t) = ... (2 w x r'), but " for messages
};

/// Reads E as m (x'' + 2 w x x' + w' x x + w x (w x x)) + g(|x|) x + F(t) (order 2) or
/// m (x' + w x x) + g x + F(t) (order 1). Nothing when E has no cross terms on
/// x^(M-1) (or is not of order 1 or 2); with cross terms but another form, nothing
/// and `why` names what is wrong (damping, a missing w' x r, a non-central term).
std::optional<frame_terms> read_frame_terms(const cauchy_problem& P, std::string* why = nullptr);

/// w = s(t) u with u constant (a literal [0, 0, f(t)] read as f(t) [0, 0, 1]): (s, u); nothing
/// when the direction of w turns.
std::optional<std::pair<GiNaC::ex, GiNaC::ex>> fixed_direction(const GiNaC::ex& w, const GiNaC::ex& t);

/// domain_error "<what> = w has no value at t = 0 ..." when w(0) is not finite (1/t, a pole).
void require_value_at_zero(const GiNaC::ex& w, const GiNaC::ex& t, const std::string& what);

/// e depends on t: t occurs in it, or a vector declared as a function of t (vector w(t)).
bool depends_on_time(const GiNaC::ex& e, const GiNaC::ex& t);

/// cos(a) and sin(a) with a's own minus sign taken out where a prints with one in front
/// (to_string: deterministic, unlike GiNaC's sign of a sum): cos(-b) = cos(b), sin(-b) = -sin(b).
/// The rotation of Q' = -W Q turns by -alpha; its closed forms print cos(t^2/2), not cos(-t^2/2).
std::pair<GiNaC::ex, GiNaC::ex> cos_sin_of_angle(const GiNaC::ex& a);

/// A vector v as sum_j c_j(t) V_j with every V_j constant (free of t and of vectors declared as
/// functions of t): its canonical terms, a literal that holds t split by components
/// (c [x(t), y(t), 0] = c x(t) [1, 0, 0] + c y(t) [0, 1, 0]), the terms with the same c_j(t) (up
/// to a factor free of t) grouped. Nothing when a term depends on t otherwise (a vector
/// function w(t)). A literal's t is no constant vector: left in V_j, a solver that treats V_j
/// as constant would move c(t) out of an integral in t (issue 27).
std::optional<std::vector<std::pair<GiNaC::ex, GiNaC::ex>>> terms_in_time(const GiNaC::ex& v, const GiNaC::ex& t);

/// (VI.2.12) a(t) = |u| int_0^t s for w = s(t) u: in closed form when s is a quasi-polynomial;
/// otherwise the integral object |u| int_0^t s(tau) dtau when `integral_object`, else nothing.
std::optional<GiNaC::ex> rotation_angle(const GiNaC::ex& s, const GiNaC::ex& u, const GiNaC::ex& t,
                                        bool integral_object);

/// The reading of a problem solved by Thm VI.3.2.1.
struct turning_frame_form {
    frame_terms terms;
    GiNaC::ex f;          ///< f(p) = p g(p)/m, the central force per unit mass (order 2), in terms.p
    std::optional<GiNaC::ex> potential;  ///< V(p) with V' = f (0 at infinity for p^n, n < -1; at 0 otherwise); empty if not elementary
    GiNaC::ex k;          ///< order 1: g/m, a constant (psi = exp(-k t) x0)
    GiNaC::ex w0;         ///< w(0)
    GiNaC::ex psi_initial_velocity;  ///< v0 + w(0) x r0 (order 2)
    std::optional<GiNaC::ex> psi;        ///< the inertial solution in closed form (f = 0 or f = c p; order 1), else empty
    /// With a free term F(t) (terms.free, constant k only): psi without it, in closed form; psi is then
    /// psi_unforced - int_0^t G(t - tau) Q^T(tau) F(tau)/m dtau (Thm VI.3.2.1 with a force), numeric.
    std::optional<GiNaC::ex> psi_unforced;
    /// A fixed direction, w = s(t) u: the unit-free direction u and a(t) = |u| int_0^t s (nothing: turning; angle nothing when int s is not elementary).
    std::optional<GiNaC::ex> u, angle;
    /// A regular precession, w(t) = c u1 + R_u1(-c t) v (a constant spin v carried round a
    /// fixed axis u1 at the rate c): Q = A(t) B(t), A the rotation by -c t about u1, B by -|v| t
    /// about v, both Rodrigues (Q' = -(K1 + A K_v A^T) Q = -W Q). Nothing otherwise.
    struct precession {
        GiNaC::ex u1;  ///< unit vector (exact)
        GiNaC::ex c;   ///< the rate of the carrying rotation
        GiNaC::ex v;   ///< the carried spin (constant vector)
    };
    std::optional<precession> precessing;
};

/// The reading above; nothing (and `why`, if given, the reason when the problem
/// has the rotating-frame terms) when P is not of that form.
std::optional<turning_frame_form> read_turning_frame(const cauchy_problem& P, std::string* why = nullptr);

/// Q x in closed form (VI.2.12 for a fixed direction with an elementary angle, the
/// composition A(B x) for a regular precession); nothing when Q is numeric.
std::optional<GiNaC::ex> closed_rotation(const turning_frame_form& F, const GiNaC::ex& x, const GiNaC::ex& t);

/// w(t) = w0 + C cos(c t) + S sin(c t) with |C| = |S|, C . S = 0, C != 0 and w0 along
/// C x S: a regular precession (see turning_frame_form::precession); nothing otherwise or
/// when a condition cannot be decided.
std::optional<turning_frame_form::precession> regular_precession(const GiNaC::ex& w, const GiNaC::ex& t);

/// r = Q psi in closed form when both are (the oscillator or free motion, and a closed Q);
/// nothing otherwise (the reduction is then an object: reduced_solution.h).
std::optional<GiNaC::ex> closed_solution(const cauchy_problem& P, const turning_frame_form& F);

/// The derivation r = F_{-w}(psi) as text (several lines), in the thesis's notation.
std::string describe_reduction(const cauchy_problem& P, const turning_frame_form& F);

/// (Thm VI.3.2.2, VI.3.140-141) with p = r' + w x r: the energy m (|p|^2/2 + V(|r|))
/// (when V is elementary), |r x p|^2 (psi x psi' = Q^T (r x p) is constant), and for a
/// fixed direction u also u . (r x p). domain_error for a first-order problem.
std::vector<GiNaC::ex> first_integrals(const cauchy_problem& P, const turning_frame_form& F);

/// (VI.3.118-119) The problem y' = w x y, y(0) = x0, read (turning set), whose solution
/// is y = F_w(x0) = R x0 with R' = W R, R(0) = I: the rotation operator with angular
/// velocity w as a solution by reduction (reduced_solution.h) when R has no closed form.
/// domain_error when w is not read as an angular velocity (a w depending on y, say).
std::shared_ptr<const cauchy_problem> rotation_problem(const GiNaC::ex& w, const GiNaC::ex& x0, const GiNaC::ex& t);
/// The same problem y' = w x y, y(0) = x0 as stated, not read (rotation_problem reads it as a
/// turning frame, dual_darboux.h's dual_rotation_problem as a dual Poisson-Darboux problem).
std::shared_ptr<cauchy_problem> rotation_statement(const GiNaC::ex& w, const GiNaC::ex& x0, const GiNaC::ex& t);

}  // namespace symrep::mechanics
