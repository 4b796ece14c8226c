// symrep/signals/sobrero_subalgebra.h -- where the representation of a signal lies in the
// generalized Sobrero algebra S (thesis IV.1.2.7, 26-37, corrected in FORMULAS.md).
//
// With d = delta + eps + j omega (IV.1.2.8, omega != 0) and Psi^-1(w) = Re of the coordinate of
// eps^n in w e^(d t) (IV.1.2.17-18 corrected, representation.h), w = sum_k (a_k + j b_k) eps^k
// represents a signal whose least equation is ((D - delta)^2 + omega^2)^(n + 1 - k0), k0 the first
// k with a_k + j b_k != 0 (w in eps^k0 S, and multiplication by d - delta - j omega = eps lowers
// the order by one per power). So the second-order signals A e^(delta t) cos(omega t - phi) are
// represented in eps^n C = {(a + j b) eps^n}, not in the subalgebras R or C printed in IV.1.2.31-35
// (for n >= 1 the unit represents a signal of order 2(n + 1)); P (IV.1.2.36-37) holds the signals
// whose sine parts vanish in the basis e^(delta t) t^k cos, sin only for n = 0. eps^n C is closed
// under products (all products 0 for n >= 1): a subalgebra without unit, an ideal of S.
#pragma once

#include <string>
#include <vector>

#include "symrep/algebra/algebra.h"

namespace symrep::signals {

struct sobrero_place {
    std::vector<std::string> subalgebras;  ///< of "R", "C", "P", "eps^n C" (n the algebra's), those holding w
    long first_power = -1;                 ///< k0: w in eps^k0 S (-1 for w = 0)
    long signal_order = 0;                 ///< 2 (n + 1 - k0): the order of the least equation of Psi^-1(w)
    std::string report;
};

/// Which of the distinguished subalgebras R, C, P (IV.1.2.7) and eps^n C the element w of a Sobrero
/// algebra lies in, and the order of the signal it represents for d = delta + eps + j omega,
/// omega != 0. Each coordinate decided 0 or not by the exact zero test (domain_error when undecided).
sobrero_place sobrero_subalgebra(const algebra& S, const coeffs& w);

}  // namespace symrep::signals
