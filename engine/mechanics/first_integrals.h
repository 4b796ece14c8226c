// symrep/mechanics/first_integrals.h -- the vector first integrals and the generalized
// potential energies of motion in a rotating frame (thesis VI.2.2.3 b, VI.3.2), derived for
// the problem at hand and proved along its equation.
//
// The problem (a reading of a problem made by ode(...): fixed_axis.h or turning_frame.h)
//     m (r'' + 2 w x r' + w' x r + w x (w x r)) + m f(|r|) r/|r| = 0,  r(0) = r0, r'(0) = v0,
// w(t) any (fixed direction or turning), f a central field per unit mass with potential
// U (U' = f; k r: U = k |r|^2/(2 m)). With p = r' + w x r (= Q psi', Thm VI.3.1.1):
//  * a vector X(r, r', t) is a vector first integral when X' + w x X = 0 along the equation;
//    then X = F_(-w)(X(0)) (the rotation tensor of VI.3.117-118: y' + w x y = 0 has the unique
//    solution y = Q y(0)). Proved here for Omega = r x p (VI.2.99, 109; VI.3.141, 221) and, for
//    free motion (f = 0), for p itself (the centre of mass, VI.3.240-241);
//  * the generalized potential energy V with |r'|^2/2 m + V = const (VI.2.110, VI.3.225):
//    V(t, r, r') = m (w, r, r') + m |w x r|^2/2 + m U(|r|); for w = s(t) u of fixed direction,
//    with u . Omega = u . Omega0 (VI.2.111-112), V(t, r) = m w . Omega0 - m |w x r|^2/2 + m U
//    (VI.2.113-114, VI.3.227), and for a constant w the centrifugal potential
//    V(r) = -m |w x r|^2/2 + m U (VI.2.115, VI.3.229; Jacobi).
// "Proved" means: the derivative along the equation (r'' replaced by the equation's
// acceleration) is exactly 0 by the vector zero test (vector/vector.h, equal), and the
// acceleration is itself checked against the problem's equation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

/// The reading of a second-order rotating-frame problem with a central field and no free term.
struct central_motion {
    GiNaC::ex m, w, t;                  ///< the mass, w(t), the time
    GiNaC::ex r, r1, r2;                ///< the unknowns r, r', r''
    GiNaC::ex r0, v0;                   ///< the initial values
    GiNaC::ex central;                  ///< f(|r|) r/|r| (per unit mass), in r
    GiNaC::ex acceleration;             ///< r'' from the equation, in t, r, r'
    std::optional<GiNaC::ex> potential; ///< U(|r|) per unit mass (U' = f), in r; empty when not elementary
    std::optional<GiNaC::ex> u;         ///< w = s(t) u: the fixed direction (empty: w turns)
    bool constant_w = false;            ///< w free of t
};

/// The reading of P, or domain_error naming what is not of the form (order 1, a free term F(t),
/// no rotating-frame terms). The acceleration is checked against P's equation (internal error
/// otherwise).
central_motion read_central_motion(const cauchy_problem& P, const std::string& who);

/// d/dt e along the motion: r'' replaced by the acceleration.
GiNaC::ex derivative_along(const central_motion& C, const GiNaC::ex& e);

/// w(0) (domain_error when w has no value at t = 0).
GiNaC::ex frame_rate_at_zero(const central_motion& C);

/// (VI.3.118) F_(-w)(x0) = Q x0 in closed form (fixed direction, regular precession), proved:
/// y' + w x y = 0 and y(0) = x0 by the zero test; nothing when Q is numeric (a turning w).
std::optional<GiNaC::ex> rotated_back(const GiNaC::ex& w, const GiNaC::ex& x0, const GiNaC::ex& t);

/// (VI.3.119) F*_w(x) = Q^T x, Q the tensor of F_(-w) (Q' = -W Q, Q(0) = I), in closed form where Q
/// is: (Q^T x)_i = (Q e_i) . x; x may depend on t. Proved: Q (Q^T x) = x (Thm VI.3.1.1, 6).
/// Nothing when Q is numeric (a turning w).
std::optional<GiNaC::ex> rotated_adjoint(const GiNaC::ex& w, const GiNaC::ex& x, const GiNaC::ex& t);

/// A vector first integral X = F_(-w)(X0).
struct vector_first_integral {
    std::string name;                  ///< "r x (r' + w x r) = F_(-w)(Omega0)   (VI.3.141)"
    GiNaC::ex quantity;                ///< X in r, r' (and t)
    GiNaC::ex initial;                 ///< X0 = X at t = 0, in r0, v0
    std::optional<GiNaC::ex> rotated;  ///< F_(-w)(X0) in closed form (rotated_back)
};
/// The vector first integrals of P (see the header), each proved: X' + w x X = 0 along the equation.
std::vector<vector_first_integral> vector_first_integrals(const cauchy_problem& P);

/// A generalized potential energy: m |r'|^2/2 + V is constant along every solution.
struct generalized_potential {
    std::string name;
    GiNaC::ex V;
};
/// The generalized potentials of P (see the header), each proved: V(t, r, r') by its derivative
/// along the equation; V(t, r) (fixed direction) as V(t, r, r') plus s(t) m (u . Omega0 - u . Omega)
/// with u . Omega proved constant; V(r) (constant w) as V(t, r) minus the constant m w . Omega0.
/// domain_error when U is not elementary.
std::vector<generalized_potential> generalized_potentials(const cauchy_problem& P);

/// "internal check failed" (logic_error) unless e is proved 0: a derivation that must hold.
void require_zero(const GiNaC::ex& e, const std::string& what);

}  // namespace symrep::mechanics
