// symrep/numeric/certified.h -- the value of a symbol-free closed form with a
// proved error bound, at whatever precision the bound needs.
//
// A fixed-precision evaluation, or two of them that agree, proves nothing where
// a closed form cancels: (1 - cos(w))/w^2 at w = 1e-100 is 0 at 40, 80 and 160
// digits alike (cos(1e-100) rounds to 1 at each), though its value is 1/2; and
// (w - sin(w))/w^3 + 1 agrees on 1 at every precision below 300 digits. So the
// exact evaluation here carries, beside each intermediate value, a bound on its
// distance to the exact value (Wilkinson's running error analysis, as the double
// and binary128 tiers of numeric/stable_evaluator.h do), in CLN floats of p bits:
//
//   sums and products   the operand bounds propagated exactly plus one rounding,
//                       2^(1-p) |v| (a rounding is at most one ulp);
//   quotients           (|a/b| eb + ea)/(|b| - eb) plus the rounding; a divisor
//                       whose bound reaches it has no bound (more precision);
//   functions           L ea with L a bound of |f'| over [a - ea, a + ea], plus
//                       CLN's own error, taken as 16 ulp of the value, and an ulp
//                       of the argument for the argument reduction of sin, cos,
//                       tan, exp beyond |a| = 1;
//   powers              integer exponents by repeated multiplication, halves by
//                       sqrt, others as exp(x log b) for a positive base.
//
// The precision is doubled (30, 60, 120 ... decimal digits) until the bound is at
// most rel_tol |value| (Ziv's strategy with a proved test). A value whose whole
// error interval lies below 2^-1080 is 0 as a double and accepted as such.
//
// What is not bounded here (a complex intermediate value, a function other than
// sin cos tan exp log abs atan sinh cosh tanh, a non-real result) throws
// not_certifiable; the callers then use their previous evaluation and say so
// in their docs. Division by an exact zero throws symrep::domain_error.
#pragma once

#include <stdexcept>

#include <ginac/ginac.h>

namespace symrep::num {

/// The closed form contains something the bounded evaluation does not cover.
struct not_certifiable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Outcome of certified_double.
struct certified_result {
    double value = 0;     ///< the double nearest the computed value
    double bound = 0;     ///< a bound on |value - exact| before the rounding to double (relative bound * |value|)
    int digits = 0;       ///< the decimal precision that achieved it
    bool proved = false;  ///< false: max_digits did not reach rel_tol (value is the last one, unproved)
};

/// e (symbol-free; floats taken as the exact binary numbers they denote)
/// evaluated with 30, 60, 120 ... up to max_digits decimal digits until the
/// running error bound is at most rel_tol |value| (or the value is 0 to double
/// precision). Throws not_certifiable (see above) and domain_error (division by
/// an exact zero).
certified_result certified_double(const GiNaC::ex& e, double rel_tol, int max_digits = 2560);

}  // namespace symrep::num
