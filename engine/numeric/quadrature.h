// symrep/numeric/quadrature.h -- integral objects int_a^b f(tau) dtau of closed
// forms, evaluated by adaptive Gauss-Kronrod quadrature (Boost.Math).
//
// A solution keeps an integral it cannot do in closed form as a GiNaC::integral
// (the I_c, I_s of VI.2.62-63: int_0^t cos alpha(tau) dtau with alpha not linear).
// GiNaC's own evalf of an integral is an adaptive Simpson rule to 1e-8 relative;
// here each integral with numeric limits and an integrand in tau alone is
// compiled (numeric/evaluator.h) and integrated by the 61-point Gauss-Kronrod
// rule, subdivided adaptively (to depth 15) until the Kronrod error estimate is
// below 1e-14 of the integral's L1 norm. Smooth integrands give the value to a few
// ulps at the first level; the estimate |K - G| is pessimistic, and an integrand
// with rounding noise never meets 1e-14, so a result is refused only when the
// estimate stays above 1e-8 of the L1 norm.
#pragma once

#include <ginac/ginac.h>

namespace symrep::num {

/// True when e holds a GiNaC::integral.
bool has_integral(const GiNaC::ex& e);

/// int_a^b f: symrep::type_error when a, b are not numbers or f has a symbol
/// other than the variable; symrep::domain_error when f is not finite on [a, b]
/// or the quadrature does not converge (the estimate is said).
double integrate_numerically(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand);

/// int_a^b f(x) dx where f holds integral objects int_c^x g(s) ds (c a number, g in its own
/// variable s alone): the nested integrals of a position integrated from a velocity that holds
/// integral objects (VI.2.51 with VI.2.62). The inner integrals and the outer one are solved
/// together as the first-order system y_j' = g_j(x), z' = f(x, y) from x = a (Boost.Odeint rkf78
/// at 1e-13 relative: about 1e-13, not the last digit of the single quadratures).
/// domain_error for another form of nesting or a symbol left.
double integrate_nested(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand);

/// e with every integral object whose limits are numbers and whose integrand has
/// no symbol but its variable (or nested integrals, integrate_nested) replaced by its value.
GiNaC::ex integrals_as_numbers(const GiNaC::ex& e);

}  // namespace symrep::num
