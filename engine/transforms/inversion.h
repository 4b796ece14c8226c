// symrep/transforms/inversion.h -- the inversion integral of the Fourier-type transform
// (thesis V.2.36-39, Thm V.2.3), evaluated as an integral.
//
// Over the multicomplex algebra the inversion (1/2 pi i0) int_A T f(w) e^(w t) dw is, in the
// idempotent basis, the classical inversion on every component (V.2.37):
//     f~(t) = (1/2 pi) int_R F(i w) e^(i w t) dw,   f~(t) = (f(t+) + f(t-))/2   (V.2.38)
// and the sum over the idempotents is f~(t) times the unit (V.2.39). fourier_inversion
// computes that integral numerically for a transform F(s) = L f(s) given as a rational
// function with numeric coefficients (laplace() derives it): for a real f,
//     f~(t) = (1/pi) int_0^oo [Re F(i w) cos(w t) - Im F(i w) sin(w t)] dw,
// by Ooura and Mori's double-exponential formulas for Fourier integrals (Boost.Math
// ooura_fourier_cos / ooura_fourier_sin), which converge for integrands decaying only like 1/w
// (a jump of f at 0). F must be proper with its poles left of the imaginary axis.
#pragma once
#include <ginac/ginac.h>

namespace symrep::transforms {

struct inversion_value {
    double value = 0;           ///< f~(t0)
    double error_estimate = 0;  ///< Boost's estimate of the quadrature error
};

/// (V.2.36-38) f~(t0) = (1/2 pi) int F(i w) e^(i w t0) dw. symrep::domain_error when F is not
/// a proper rational function of s with numeric coefficients, or has a pole with Re >= 0 (the
/// transform does not converge on the imaginary axis: the integral is not the inverse there).
inversion_value fourier_inversion(const GiNaC::ex& F, const GiNaC::symbol& s, double t0);

/// (V.2.42-44, the frequency side) (1/2 pi) int_R F(i w) conj G(i w) dw = (1/pi) int_0^oo
/// Re[F(i w) conj G(i w)] dw (F, G transforms of real signals) by exp-sinh quadrature, for F, G
/// proper with numeric coefficients and poles left of the axis (refused as fourier_inversion
/// refuses).
inversion_value parseval_integral(const GiNaC::ex& F, const GiNaC::ex& G, const GiNaC::symbol& s);

}  // namespace symrep::transforms
