// symrep/numeric/quadrature.h -- integral objects int_a^b f(tau) dtau of closed forms,
// nested ones included, evaluated by one march of Chebyshev panels (quadrature_chain.h).
//
// A solution keeps an integral it cannot do in closed form as a GiNaC::integral (the
// I_c, I_s of VI.2.62-63: int_0^t cos alpha(tau) dtau with alpha not linear), and the
// position of a charge integrated from such a velocity holds nested ones (VI.2.51):
// int_0^t c(tau) (int_0^tau g(sigma) dsigma) dtau. GiNaC's own evalf of an integral is an
// adaptive Simpson rule to 1e-8 relative; here an integral with numeric limits is compiled
// (numeric/evaluator.h) with every integral object inside it, to any depth, as one
// unknown of a lower-triangular system y_j' = g_j(x, y_0, ..., y_{j-1}) (an inner
// int_c^x g(s) ds is y_j with y_j(c) = 0), and that system is integrated once from a to b
// on adaptive Chebyshev panels: the inner values at the outer nodes come with the inner
// quadrature, so the work is linear in the length of [a, b] (t = 30 for the charge in
// B = (1 + t^2/10) n: about 1e5 evaluations), where a quadrature at each node of another
// one was quadratic (minutes).
//
// Accuracy: a few ulps of the scale for smooth integrands. The estimate (the lower-order
// rule's own trajectory, quadrature_chain.h) is judged against the scale of the whole
// integral, S = max(int_a^b |f|, |value|), never of a piece: the value is refused, with
// the estimate said, when the estimate exceeds 1e-10 S (an integrand that is not finite,
// not integrable, or noisy beyond that).
#pragma once

#include <cstddef>
#include <string>

#include <ginac/ginac.h>

namespace symrep::num {

/// True when e holds a GiNaC::integral.
bool has_integral(const GiNaC::ex& e);

/// One integral with its estimate (see above).
struct integral_value {
    double value = 0;
    double error = 0;           ///< the estimate of |value - exact|
    double scale = 0;           ///< max(int_a^b |f|, |value|)
    std::size_t panels = 0;     ///< accepted panels of the march
    std::size_t evaluations = 0;  ///< of the integrands, inner ones included
};

/// int_a^b f(x) dx where f may hold integral objects int_c^x g(s) ds (c a number, g in its
/// own variable s alone and in integral objects int_d^s ... of the same form, to any depth):
/// the value and its estimate, not judged. symrep::type_error for limits that are not finite;
/// symrep::domain_error for another form of nesting or a symbol left (named), an integrand
/// that is not finite at a node (the point said), or a march of more than chain_max_panels.
integral_value evaluate_integral(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand);

/// int_a^b f: evaluate_integral, refused (symrep::domain_error with the estimate) when the
/// estimate exceeds 1e-10 of the scale.
double integrate_numerically(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand);

/// The same for an integrand with integral objects inside (kept for its name: one method).
double integrate_nested(const GiNaC::ex& variable, double a, double b, const GiNaC::ex& integrand);

/// e with every integral object whose limits are numbers and whose integrand has no symbol
/// but its variable (and nested integral objects of the form above) replaced by its value.
GiNaC::ex integrals_as_numbers(const GiNaC::ex& e);

/// The precondition of an integral object int_0^t K(t - tau) f(tau) dtau kept for every t >= 0
/// (the Duhamel integrals of VI.1.26-38, VI.2, VI.3): f finite and continuous at every x >= 0,
/// decided exactly. f is built from numbers, symbols free of x, x, sums, products, natural
/// powers and exp, sin, cos, sinh, cosh, tanh, atan, abs; another power (1/p, sqrt(p)) or log(p)
/// only of a polynomial p in x with rational coefficients that Sturm's theorem shows without a
/// zero in [0, inf) (a positive exponent: p >= 0 there, a zero at x = 0 allowed), or of a
/// p free of x. Otherwise domain_error naming `what` and the factor: "is not finite at x = ..."
/// (a pole or a logarithm's zero at some x >= 0), or "cannot decide that ... is finite".
void require_finite_on_half_line(const GiNaC::ex& f, const GiNaC::ex& x, const std::string& what);

}  // namespace symrep::num
