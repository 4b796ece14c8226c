// symrep/signals/sampling_numeric.h -- sampling (Thm II.3.4, Cor. II.3.5) when the minimal
// polynomial p of d has a rational factor whose roots have no closed form (degree > 3):
// the numeric form, marked as such, with an error bound.
//
// With numeric coefficients and a numeric step h, the roots r_i of p are found at 90 digits
// (Eigen's eigenvalues of the companion matrix, then Newton's iteration on p). Each disk
// |z - r_i| <= n |p(r_i)/p'(r_i)| holds a root of p (n = deg p); the disks must be disjoint
// (then each holds exactly one: p is squarefree). The eigenvalues of exp(h d) are
// mu_i = e^(h r_i), each within eps_i = |mu_i| (e^(|h| delta_i) - 1) of its exact value, and
// the coefficients of q(l) = prod (l - mu_i), the elementary symmetric functions of the mu_i,
// are within the coefficients of prod (l + |mu_i| + eps_i) - prod (l + |mu_i|) of theirs
// (bounded term by term). q is printed with 30 significant digits; the bound adds their
// rounding. exp(h d) = c(d), c the interpolant of e^(h z) at the roots, is computed at 60
// and at 90 digits and given to 30 digits where both agree to 35 (else refused). Aliasing is
// "no" when the disks around the mu_i are pairwise disjoint, else not decided.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/signals/representation.h"

namespace symrep::signals {

/// The numeric sampling of R at step h (see above); `why` names the factor without closed-form
/// roots (for the report). domain_error when h or a coefficient of p is not a real number, or p
/// has a repeated factor; algebra_error when the roots cannot be separated at 90 digits.
sampling sample_numerically(const representation& R, const GiNaC::ex& h, const GiNaC::symbol& l,
                            const std::string& why);

}  // namespace symrep::signals
