// symrep/numeric/quadrature.h -- integral objects int_a^b f(tau) dtau of closed
// forms, evaluated by adaptive Gauss-Kronrod quadrature (Boost.Math).
//
// A solution keeps an integral it cannot do in closed form as a GiNaC::integral
// (the I_c, I_s of VI.2.62-63: int_0^t cos alpha(tau) dtau with alpha not linear).
// GiNaC's own evalf of an integral is an adaptive Simpson rule to 1e-8 relative;
// here each integral with numeric limits and an integrand in tau alone is
// compiled (numeric/evaluator.h) and integrated by the 61-point Gauss-Kronrod
// rule: once over the interval, then over its two halves; when the two agree to
// 1e-13 of the L1 norm (a smooth integrand: a few ulps, 183 evaluations) that is
// the value. Otherwise the rule is subdivided adaptively (to depth 15) until the
// Kronrod error estimate is below 1e-14 of the L1 norm; that estimate is
// pessimistic (on short intervals it has a floor near 1e-14 absolute), and an
// integrand with rounding noise never meets 1e-14, so a result is refused only
// when the estimate stays above 1e-8 of the L1 norm.
#pragma once

#include <ginac/ginac.h>

namespace symrep::num {

/// True when e holds a GiNaC::integral.
bool has_integral(const GiNaC::ex& e);

/// int_a^b f: symrep::type_error when a, b are not numbers or f has a symbol
/// other than the variable; symrep::domain_error when f is not finite on [a, b]
/// or the quadrature does not converge (the estimate is said). `l1` (if given) receives the
/// rule's int_a^b |f|, the scale of its error (below 1e-8 of it, or the quadrature refuses).
double integrate_numerically(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand,
                            double* l1 = nullptr);

/// int_a^b f(x) dx where f holds integral objects int_c^x g(s) ds (c a number, g in its own
/// variable s alone): the nested integrals of a position integrated from a velocity that holds
/// integral objects (VI.2.51 with VI.2.62). Each inner integral by the same rule at each node of
/// the outer one (a smooth integrand: 183 x 183 evaluations). Not as the ODE system y' = g,
/// z' = f(x, y): Fehlberg 7(8)'s error estimate vanishes on y' = g(x) (its stages 12 and 13
/// repeat 1 and 11), and rkf78 at 1e-13 left 2e-10 there. domain_error for another form of
/// nesting or a symbol left. `l1`: the outer rule's int_a^b |f|, as integrate_numerically.
double integrate_nested(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand,
                        double* l1 = nullptr);

/// e with every integral object whose limits are numbers and whose integrand has
/// no symbol but its variable (or nested integrals, integrate_nested) replaced by its value.
GiNaC::ex integrals_as_numbers(const GiNaC::ex& e);

}  // namespace symrep::num
