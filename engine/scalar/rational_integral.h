// symrep/scalar/rational_integral.h -- int_0^t f(x) dx in closed form for a rational
// function f, by partial fractions over the factors of its denominator in Q[x].
//
// The Duhamel integrals of the vector Cauchy problems (Thm VI.1.2.2-4, VI.1.16-38) hold
// "for every f"; where f is not a quasi-polynomial they stay integral objects, except
// where the integral is elementary. This is the elementary case that occurs first: a
// rational integrand such as a/(1 + tau^2), whose integral is a atan t. Linear factors
// of any multiplicity give logarithms and powers, irreducible quadratics (no real zero)
// of multiplicity one give a logarithm and an arctangent; anything else is left to the
// caller (nothing is returned). The answer is checked by differentiation before it is
// returned: a closed form that is not proved is never given.
#pragma once

#include <optional>
#include <ginac/ginac.h>

namespace symrep {

/// int_0^t f(x) dx for f rational in x with a denominator of rational coefficients and
/// no zero in [0, inf) (the numerator may hold symbols free of x), valid for every
/// t >= 0; nothing when the denominator has a factor of degree > 2, a repeated quadratic
/// factor, a zero in [0, inf), or when the differentiation check does not close.
std::optional<GiNaC::ex> definite_rational_integral(const GiNaC::ex& f, const GiNaC::ex& x, const GiNaC::ex& t);

}  // namespace symrep
