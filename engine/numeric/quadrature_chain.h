// symrep/numeric/quadrature_chain.h -- a chain of quadratures, integrated once on adaptive
// Chebyshev panels.
//
// The integral objects of a closed form nested in one another form a lower-triangular
// system of quadratures
//     y_j(x) = y_j(a) + int_a^x g_j(s, y_0(s), ..., y_{j-1}(s)) ds,   j = 0 .. n-1:
// the position of a charge in B(t) with E across B (VI.2.51 with VI.2.62) holds
// int_0^t c(tau) (int_0^tau g(sigma) dsigma) dtau, which is y_1(t) for g_0 = g, g_1 = c y_0.
// The system is integrated once from a to b (the work is linear in the length of [a, b],
// in the number of oscillations of the integrands), not as a quadrature at each node of
// another one (quadratic).
//
// The rule. On a panel [p, p + h] every g_j is sampled at the 63 interior points of the
// Chebyshev grid of degree 64 (x = p + h (1 - cos(pi k/64))/2, k = 1..63: no endpoint, so an
// integrand singular at a or b is not evaluated there); y_j at the same points is y_j(p)
// plus the integral of the polynomial interpolating g_j (the spectral integration matrix,
// exact for degree 62, computed once in long double), and y_j(p + h) by the weights of the
// same rule (Fejer's second rule). So the inner values at the outer nodes come with the
// inner quadrature itself.
//
// Error control and estimate. The 31 points of every other node (the grid of degree 32)
// give a second, lower-order value of every y_j at those points and at p + h. A panel is
// accepted when the two increments agree, for every component, to 1e-13 of the component's
// scale (int |g_j| so far) times the panel's share h/(b - a) of the interval, or to 1e-12 of
// the panel's own int |g_j| (the rounding of an integrand in double is not chased); otherwise
// it is halved. A halving that no longer shrinks the difference (rounding noise of the
// integrand, the two rules agreeing to 1e-3 of the panel's own size) ends the refinement
// there, as does a panel of 2^-45 of the interval; their difference stays in the estimate.
// The estimate: the 31-point rule is also run along the whole march as a second trajectory
// with its own inner values (so an inner error propagated through the outer integrands is in
// it), and error_j = sum over the panels of |its increment of y_j - the 63-point rule's|.
// That is an estimate of the lower rule's error, pessimistic for the value returned (the
// 63-point rule's): a smooth integrand gives a few ulps with an estimate near 1e-14 of the
// scale. The caller judges it against the scale of the whole integral (quadrature.h).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace symrep::num {

struct chain_result {
    std::vector<double> value;     ///< y_j(b)
    std::vector<double> error;     ///< the estimate of |error of y_j(b)| (see above)
    std::vector<double> l1;        ///< int_a^b |g_j| (by the 63-point rule)
    std::size_t panels = 0;        ///< accepted panels
    std::size_t evaluations = 0;   ///< of the g_j
};

/// g(j, x, y) = g_j(x, y_0, ..., y_{j-1}): y holds n values, of which only the first j are set.
using chain_integrand = std::function<double(std::size_t j, double x, const double* y)>;

/// The most panels (accepted or not) one march may take: about 1.2e7 evaluations per component
/// (a phase of about 1e6 rad; a few seconds before a refusal).
constexpr std::size_t chain_max_panels = std::size_t(1) << 17;

/// y(b) from y(a) = start (n values), a < b or a > b. variable names x in messages.
/// symrep::domain_error when a g_j is not finite at a node (the point is said) or when the
/// march needs more than chain_max_panels panels (an integrand that oscillates too fast over
/// [a, b]); the convergence itself is the caller's to judge from error and l1.
chain_result integrate_chain(const chain_integrand& g, std::size_t n, double a, double b,
                             const std::vector<double>& start, const std::string& variable = "x");

}  // namespace symrep::num
