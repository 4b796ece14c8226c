// symrep/signals/modulation.h -- a represented signal as a carrier with amplitude and
// phase modulation (thesis IV.1.26-30 over the multicomplex algebra, IV.1.2.20-25 over
// the Sobrero algebra).
//
// When d = omega J + r with J^2 = -1 and J r = r J, exp(d t) = (cos omega t + J sin omega t)
// exp(r t), so the signal lambda(w exp(d t)) of w is
//     a cos(omega t) + b sin(omega t) = A cos(omega t - theta),
//     a = lambda(w E), b = lambda(J w E), E = exp(r t),
//     A = sqrt(a^2 + b^2), theta = atan2(b, a):
// the carrier omega modulated in amplitude by A and in phase by theta, both derived by
// the algebra's product.
#pragma once

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"
#include "symrep/signals/representation.h"

namespace symrep::signals {

struct modulation {
    GiNaC::ex a, b, amplitude, phase;
};

/// a = lambda(w E), b = lambda(J w E) and A, theta from them (see above).
modulation carrier_modulation(const representation& R, const coeffs& J, const coeffs& E, const coeffs& w);

/// (IV.1.2.8, 20-25) The Sobrero algebra with d = delta + beta eps + ... + j omega (omega the
/// coordinate of j): J = j, E = exp((d - omega j) t). Throws type_error when R is not on a
/// Sobrero algebra.
modulation sobrero_modulation(const representation& R, const coeffs& w, const GiNaC::ex& t);

}  // namespace symrep::signals
