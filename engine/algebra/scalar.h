// symrep/algebra/scalar.h -- the two coefficient types of symrep and what the
// algebra code needs to treat them alike.
//
// Exact arithmetic uses GiNaC::ex (CLN rationals, algebraic numbers, symbols);
// the fast numeric path uses double. Family code that is written once as a
// template over T calls only the functions below (plus +,-,*,/ and the
// elementary functions found by argument-dependent lookup: exp, log, cos, sin,
// sqrt, atan2), so that one implementation serves both paths.
#pragma once

#include <cmath>
#include <ginac/ginac.h>

namespace symrep {

/// Exact zero test: true when the expression normalizes to 0.
inline bool is_zero_scalar(const GiNaC::ex& x) { return x.is_zero() || GiNaC::normal(x).is_zero(); }
/// Double zero test with an absolute tolerance (callers scale it to the data).
inline bool is_zero_scalar(double x, double tol = 0.0) { return std::abs(x) <= tol; }

/// Bring an exact coefficient to its simplest stored form (expanded, normalized
/// rationals); identity for doubles.
inline GiNaC::ex tidy(const GiNaC::ex& x) { return GiNaC::normal(GiNaC::expand(x)); }
inline double tidy(double x) { return x; }

/// Scalar from an integer, for both paths.
template <class T> T from_int(long k) { return T(k); }
template <> inline GiNaC::ex from_int<GiNaC::ex>(long k) { return GiNaC::ex(GiNaC::numeric(k)); }

/// One over 2^n, exact or double.
template <class T> T inv_pow2(unsigned n) { return std::ldexp(1.0, -int(n)); }
template <> inline GiNaC::ex inv_pow2<GiNaC::ex>(unsigned n) {
    return GiNaC::ex(GiNaC::numeric(1) / GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(n)));
}

}  // namespace symrep
