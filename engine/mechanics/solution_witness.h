// symrep/mechanics/solution_witness.h -- the cheap witness that a candidate solution of a
// Cauchy problem is wrong: its residual and initial differences at one point (issue 27).
//
// solve(cauchy_problem) never returns a result that its own residual test sees as nonzero.
// Before it returns, the residual E(s, s', ..., s^(M)) and the initial differences
// s^(m)(0) - X_m are evaluated at one point, the point of check()'s "seen nonzero": t = 7/10,
// every other symbol a rational in [1.1, 2.9] and every vector symbol a literal of such
// rationals, each fixed by its name (the same on every run). The value is computed at 40
// digits together with a bound on the size its rounding can have: the magnitude M of the
// expression, |x| for a number, M(a) + M(b) for a + b, M(a) M(b) for a b,
// |f(a)| + |f'(a)| M(a) for a function, |a^p| (1 + |p| M(a)/|a|) for a power (what the terms
// would add up to without cancellation: its rounding is at most a few ulps of M). The
// integral objects int_0^t g(tau) dtau of fixed_axis.h are evaluated by Gauss-Kronrod
// (numeric/quadrature.h) in double precision, their magnitude the rule's int |g|. A
// component is seen nonzero when |value| exceeds
//   1e-20 M  with exact numbers only (40 digits: rounding ~1e-40 M),
//   rounding_tolerance() M (1e-12 at 17 digits) with floating-point numbers in the problem
//            or the solution (they carry ~17 digits; check() takes the same ratio as rounding),
//   1e-6 M   with integral objects (the quadrature's error is below 1e-8 of int |g|, or it
//            refuses; on these smooth integrands it is ~1e-13).
// A point that does not decide is no witness, and nothing is seen: a pole, a value that is
// not a real number, a refused quadrature, a vector function w(t) left in the residual.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

struct witness_report {
    bool seen_nonzero = false;
    std::string what;  ///< "the residual (component 2)", "the initial value r'(0) (component 1)"
    double value = 0;  ///< its value at the point
    double size = 0;   ///< its magnitude M there
};

/// The witness above for the candidate s of P (nothing is seen when the point does not decide).
witness_report witness(const cauchy_problem& P, const GiNaC::ex& s);

/// internal_error naming P and what was seen when witness(P, s) sees s wrong; nothing otherwise.
void require_witness(const cauchy_problem& P, const GiNaC::ex& s);

/// The rational of the point for a name: salt 0 for a scalar, 1..3 for the components of a
/// vector; in [1.1, 2.9], fixed by the name (shared with check()'s point).
GiNaC::numeric witness_rational(const std::string& name, int salt);

/// t at the point: 7/10.
GiNaC::numeric witness_time();

}  // namespace symrep::mechanics
