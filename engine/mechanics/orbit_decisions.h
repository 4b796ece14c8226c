// symrep/mechanics/orbit_decisions.h -- decisions about the motion in a rotating frame, made from
// its first integrals (thesis VI.3.3, VI.3.4.2.5): is the Kepler orbit bounded (Consequence
// VI.3.3.2), does the orbit keep one plane (VI.3.282-284). Each computes the deciding quantity
// from the problem (and values) and decides it exactly where the data allow; otherwise it says
// that it cannot decide (never a guess).
//
//  * bounded: for m (r'' + 2 w x r' + w' x r + w x (w x r)) + m k r/|r|^3 = 0, k > 0, w(t) any,
//    |r| = |psi| (Q is a rotation) and psi is the Kepler orbit with psi(0) = r0,
//    psi'(0) = p0 = v0 + w(0) x r0 (VI.3.155): bounded iff E < 0,
//    E = |p0|^2/2 - k/|r0| (VI.3.154). E < 0: |r| <= k/|E|. E >= 0 and Omega0 = r0 x p0 != 0: a
//    parabola or hyperbola, unbounded; E >= 0 and Omega0 = 0 (radial): unbounded when it moves
//    out (r0 . p0 >= 0), a fall into the centre at a finite time otherwise (refused by name).
//  * planar: w = s(t) u of fixed direction and a central field: the orbit lies in the plane
//    through the centre normal to L_c = r x (r' + w x r) (VI.3.281), and L_c = F_(-w)(L_c0)
//    turns about u, so that plane is fixed iff u x L_c0 = 0 (VI.3.282), for L_c0 != 0 the same
//    as r0 . u = 0 and v0 . u = 0 (VI.3.283-284; then the plane is normal to u). r0 . u = 0 and
//    v0 . u = 0 are sufficient in every case (L_c0 = 0 too: psi stays normal to u); a radial
//    motion (L_c0 = 0) is also planar when r0 x u = 0 (on the axis), and otherwise not decided.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/mechanics/scene.h"

namespace symrep::mechanics {

/// A decision and what it rests on.
struct orbit_decision {
    bool answer = false;
    GiNaC::ex quantity;   ///< E (bounded) or u x L_c0 (planar), with the values put in
    std::string reason;   ///< one line: why
};

/// +1, -1 or 0 when the sign of x is established exactly (a number: by the zero test and a
/// 40/80-digit evaluation; with symbols: only when GiNaC knows it, e.g. a sum of positive
/// terms); 2 when not.
int decided_sign(const GiNaC::ex& x);

/// (Consequence VI.3.3.2) domain_error "cannot decide" (naming E) when the sign of E or of k
/// is not established, and for a problem that is not Kepler's.
orbit_decision bounded(const cauchy_problem& P, const parameter_values& values);

/// (VI.3.282-284) domain_error for a turning w, and "cannot decide" when u x L_c0 is neither
/// proved 0 nor a nonzero number.
orbit_decision planar(const cauchy_problem& P, const parameter_values& values);

}  // namespace symrep::mechanics
