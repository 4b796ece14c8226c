// symrep/transforms/algebra_inversion.h -- the inversion of an algebra-valued transform
// (thesis Thm V.2.3, V.2.36-39, and Thm V.3.3, V.3.37-41), derived per idempotent component
// or per power of eps.
//
// Multicomplex (Fourier type, V.2). T is a function of d = sum_k omega_k i_k (symbols). In the
// idempotent basis d = sum_p (i Omega_p) e_p and T = sum_p T_p e_p; each T_p must be a function
// of i Omega_p alone (checked: with one omega solved from i Omega_p = s, T_p becomes F_p(s) free
// of the others). The componentwise inversion (V.2.37) of F_p along the imaginary axis is the
// two-sided inverse: F_p = (polynomial part) + (proper part); the polynomial sum c_k s^k is
// sum c_k delta^(k)(t) (V.2.33-35), the proper part's inverse_laplace is split by its exponents:
// Re lambda < 0 gives the signal for t >= 0, Re lambda > 0 (with the sign changed) the signal for
// t < 0 (int_-oo^0 e^(lambda t) e^(-s t) dt = -1/(s - lambda) for Re s < Re lambda), Re lambda = 0
// is refused (F_p is then not the Fourier transform of an L1 signal). V.2.39: every component
// gives the same f~, so sum_p f~ e_p = f~ times the unit; this is checked (each f_p == f_0).
//
// Sobrero (Laplace type, V.3). d = sigma + eps (+ j omega), sigma (and omega) symbols; T =
// sum_k eps^k (a_k + j b_k), F_k(s) = (a_k + i b_k) at sigma = s, omega = 0. Then f = L^-1 F_0
// (causal; a polynomial part gives impulses), and (V.3.40) L^-1 F_k = (-t)^k f / k! is checked
// for every k, and with it (V.3.41): the eps^m coefficient of (1/2 pi j) int T(s + eps)
// e^((s + eps) t) ds, sum_k (-t)^k/k! t^(m-k)/(m-k)! f = f t^m (1 - 1)^m / m!, is 0 for m >= 1.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"

namespace symrep::transforms {

struct algebra_inverse {
    GiNaC::ex f;      ///< the signal for t >= 0 (impulses as dirac(t, k))
    GiNaC::ex g = 0;  ///< the signal for t < 0 (multicomplex only; 0 for a causal signal)
    std::string report;
};

/// (Thm V.2.3, Thm V.3.3) The signal whose transform over d's algebra is T (see above).
/// domain_error naming the component that is not a function of i Omega_p (or of s + eps), a
/// pole on the imaginary axis, an exponent whose real part's sign is not decided, or a check
/// that fails; algebra_error for an algebra other than multicomplex(n) and sobrero(n).
algebra_inverse inverse_transform(const algebra_ptr& A, const coeffs& T, const coeffs& d, const GiNaC::symbol& t);

}  // namespace symrep::transforms
