// symrep/transforms/distribution.h -- the Dirac impulse and its derivatives as signals
// (thesis V.2.32-35, V.3.33-36).
//
// GiNaC has no Dirac distribution; symrep writes delta^(k)(x) as the function dirac(x, k)
// (dirac(x) = dirac(x, 0) in the language), with d/dx dirac(x, k) = dirac(x, k + 1) and
// dirac(x, k) = 0 for a number x != 0 (the value away from the support). A signal may hold
// such impulses linearly, c(t) dirac(alpha t + beta, k) with alpha a nonzero number: they are
// read as sum_j c_j delta^(j)(t - a) (below), whose transform over an algebra is
//     T delta^(k)(t - a) (d) = int delta^(k)(t - a) e^(-d t) dt = d^k e^(-a d)     (V.2.33, V.3.34)
// (by (-1)^k (d/dt)^k e^(-d t) at t = a), so T delta = 1 and T delta^(k) = d^k for a = 0. The
// causal transform counts an impulse at a = 0 (the lower limit is 0-, as L delta = 1, V.3.35).
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"

namespace symrep::transforms {

/// delta^(k)(x): k a non-negative integer.
DECLARE_FUNCTION_2P(dirac)

/// c delta^(k)(t - a), c and a free of t.
struct impulse {
    GiNaC::ex c, a;
    unsigned k = 0;
};

/// f = regular + sum of the impulses. A term c(t) dirac(alpha t + beta, k) (alpha a nonzero
/// number, beta free of t) is delta^(k)(alpha (t - a)) = delta^(k)(t - a) / (|alpha| alpha^k),
/// a = -beta/alpha, and c(t) delta^(k)(t - a) = sum_j (-1)^j C(k, j) c^(j)(a) delta^(k-j)(t - a).
/// domain_error naming the term when an impulse enters f otherwise (a product or power of
/// impulses, an impulse inside another function, a non-linear argument).
struct split_signal {
    GiNaC::ex regular;
    std::vector<impulse> impulses;
};
split_signal split_impulses(const GiNaC::ex& f, const GiNaC::symbol& t);

/// True when f holds dirac(...).
bool has_impulse(const GiNaC::ex& f);

/// (V.2.33, V.3.34) sum over the impulses with a >= 0 (causal: the others lie outside t >= 0)
/// of c d^k e^(-a d) on d's algebra; `all` counts every impulse (the transform over the whole
/// line). domain_error when the sign of a is not decided (a symbolic position).
coeffs impulse_transform(const algebra_ptr& A, const coeffs& d, const std::vector<impulse>& impulses, bool all);

}  // namespace symrep::transforms
