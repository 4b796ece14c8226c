// symrep/signals/z_transform.h -- the Z transform of a sequence through its representation
// (thesis IV.3.2 remark 4: the Z transfer function; II.3 with the shift).
//
// A sequence f(k) = lambda(w d^k) (Thm II.3.3, d = v on the least algebra P_n = R[X]/(p)) has
//     Z{f}(z) = sum_(k >= 0) f(k) z^(-k) = lambda(w sum_k (d/z)^k) = z lambda(w (z - d)^(-1)),
// and (z - d)^(-1) = Q(z, d)/p(z) with Q(z, X) = (p(z) - p(X))/(z - X) (a polynomial, as
// p(d) = 0): Z{f}(z) = z lambda(w Q(z, d))/p(z), for |z| larger than every root of p.
// Remark 4 in the form that holds: the zero-state response x of a_0 x(k+m) + ... + a_m x(k) =
// b_0 f(k+p) + ... + b_p f(k) (x(0) = ... = x(m-1) = 0) has
//     p(z) Z{x}(z) = q(z) Z{f}(z) - sum_(i=1..p) q_i sum_(j<i) f(j) z^(i-j),   q_i the coefficient of z^i,
// so Z{x} = H(z) Z{f} with H(z) = q(z)/p(z), the transmittance's rational function, when the
// input's first p values vanish or p = 0.
#pragma once

#include <ginac/ginac.h>

namespace symrep::signals {

/// Z{f}(z) = sum_(k >= 0) f(k) z^(-k) in closed form (a rational function of z, one fraction) for a
/// sequence f(k) of the kind sequence_annihilator() reads.
GiNaC::ex z_transform(const GiNaC::ex& f, const GiNaC::symbol& k, const GiNaC::ex& z);

}  // namespace symrep::signals
