// symrep/mechanics/two_body.h -- the two-body problem in a frame rotating with any w(t)
// (thesis VI.3.4.2): its global characteristics, their relations and first integrals, derived
// from the two decoupled problems and proved along the coupled equations.
//
// The bodies x1 (mass m1) and x2 (m2) attract each other by a central force of the distance;
// the centre of mass r_c = (m1 x1 + m2 x2)/M, M = m1 + m2, solves the free rotating-frame problem
// (VI.3.202) and r = x2 - x1 the relative one with the reduced mass m = m1 m2/M (VI.3.216-218,
// r'' + 2 w x r' + w' x r + w x (w x r) + f(|r|) r/|r| = 0). Given those two problems (ode(...)),
// the coupled equations are
//     x1'' + C_w(x1) = (m/m1) f r/|r|,   x2'' + C_w(x2) = -(m/m2) f r/|r|,
// C_w(x) = 2 w x x' + w' x x + w x (w x x); the reading checks that they give the two problems
// back (the decoupling, VI.3.202 and 216). In the positions x1, x2 and velocities v1, v2 (vector
// symbols of those names) the quantities are
//   P, K0, E_cin (VI.3.253-255), I0 w (259), V_c (260), the interaction V = m U(|x2 - x1|) (U' = f);
//   H = sum m_i (v_i + w x x_i) (237): H' + w x H = 0 (240), H = P + M w x r_c (256),
//     H = M (r_c' + w x r_c) (238), H = F_(-w)(H0) (241; closed, 267, for a fixed direction);
//   L0 = sum m_i x_i x (v_i + w x x_i) (243): L0' + w x L0 = 0 (247), L0 = K0 + I0 w (257),
//     L0 = m r x (r' + w x r) + M r_c x (r_c' + w x r_c) (244), L0 = F_(-w)(L0^0) (245, 268);
//   T = sum m_i/2 |v_i + w x x_i|^2 (248): T = E_cin + V_c (258), T = m/2 |r' + w x r|^2 +
//     M/2 |r_c' + w x r_c|^2 (249), T + V constant (252, 263-264);
//   fixed direction: V(t, x1, x2) = w . L0^0 - sum m_i |w x x_i|^2/2 + V (265, E_cin + V constant);
//     constant w: V = -sum m_i |w x x_i|^2/2 + V (266, the centrifugal potential);
//   the centre-of-mass frame (x_i - r_c): H^c = 0 (273, 276), L_c = m r x (r' + w x r) (274, 277),
//     L_c = F_(-w)(L_c0) (279), T^c = m/2 |r' + w x r|^2 (275, 278), E_cin^c + V(t, r, r')
//     constant (286-288), its fixed-direction form (289-290) and Jacobi's integral (291).
// Each statement is proved by the vector zero test (identities as they stand; constants by the
// derivative along the coupled equations, vectors X by X' + w x X = 0 along them).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

/// One characteristic: its name and statement, the expression (in the vector symbols x1, x2,
/// v1, v2 and t; for the "(t)" forms, in the initial values of the two problems), and, for a
/// vector integral X = F_(-w)(X0) whose Q is not closed (a turning w), X0 and w (rotated empty).
struct two_body_quantity {
    std::string name;
    GiNaC::ex value;
    bool by_rotation = false;  ///< value is X0: the quantity is F_(-w)(X0), Q numeric
    GiNaC::ex w;               ///< the frame's w(t), for by_rotation
};

/// The characteristics of VI.3.4.2.4-5 for the centre-of-mass problem CM (free, w(t)) and the
/// relative problem REL (the same w, a central field), masses m1, m2; each proved (see above).
/// domain_error when CM has a field, the two w differ, or REL's potential is not elementary.
/// x1, x2, v1, v2: the vector symbols in which the quantities are written.
std::vector<two_body_quantity> two_body_characteristics(const cauchy_problem& CM, const cauchy_problem& REL,
                                                        const GiNaC::ex& m1, const GiNaC::ex& m2, const GiNaC::ex& x1,
                                                        const GiNaC::ex& x2, const GiNaC::ex& v1, const GiNaC::ex& v2);

}  // namespace symrep::mechanics
