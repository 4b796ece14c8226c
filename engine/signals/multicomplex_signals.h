// symrep/signals/multicomplex_signals.h -- signals over the multicomplex algebra
// (thesis IV.1.1: IV.1.9-30 and IV.1.50-57).
//
// With d = sigma + omega_0 i_0 + ... + omega_n i_n (IV.1.9; sigma = 0 in the thesis)
// the solutions of p(D) f = 0, p = prod_p (X^2 + Omega_p^2) (IV.1.12), are represented
// on A = multicomplex(n) by
//     Psi^-1(w)(t) = scal(w exp(d t)),
// scal the coordinate of 1. scal(x y) is the algebra's own nondegenerate form
// (e_m^2 = +-1, III.1.7), so Psi^-1 is one-to-one whenever d generates A, and
// Psi^-1(d w) = Psi^-1(w)'. The thesis's printed map Psi(phi_p) = v_p (IV.1.16) is
// scal(conj(w) exp(d t)) instead, which turns d into -d (Psi(f') = -d Psi(f)); with
// scal, Psi^-1(v_p) = v_p^2 phi_p: the printed correspondences hold up to the sign
// of v_p^2 (IV.1.16, 25, 34: Psi^-1(i0 e_p) = -sin(Omega_p t)/2^n) and
// ../shared/thesis/FORMULAS.md.
//
// exp(d t) is formed as the product prod_k (cos omega_k t + i_k sin omega_k t)
// (IV.1.15) by the algebra's multiplication, so a signal comes out as a sum of
// products of cosines and sines of the carriers omega_k t (IV.1.24-25); through the
// idempotents (IV.1.17) the same signal is a sum of cos(Omega_p t - ...): the two
// forms are the identities IV.1.18.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/multicomplex.h"
#include "symrep/scalar/equality.h"
#include "symrep/signals/modulation.h"
#include "symrep/signals/representation.h"

namespace symrep::signals {

/// d = sigma + sum_k omega_k i_k, read off d's coordinates; nullopt when d has other
/// components (products of imaginary units).
struct carriers {
    GiNaC::ex sigma;
    std::vector<GiNaC::ex> omega;  ///< omega_0 .. omega_n
};
std::optional<carriers> carriers_of(const multicomplex& A, const coeffs& d);

/// (IV.1.15) exp(d t) = e^(sigma t) prod_k (cos omega_k t + i_k sin omega_k t), multiplied
/// out by the algebra: each coordinate a product of cosines and sines of the carriers.
coeffs exp_product_form(const multicomplex& A, const carriers& c, const GiNaC::ex& t);

/// (IV.1.26-30) The signal Psi^-1(w) as a carrier omega_0 with amplitude and phase
/// modulation: phi = a cos(omega_0 t) + b sin(omega_0 t) = A cos(omega_0 t - theta),
/// A = sqrt(a^2 + b^2), theta = atan2(b, a); a = scal(w E), b = scal(w i0 E),
/// E = e^(sigma t) prod_(k >= 1) (cos omega_k t + i_k sin omega_k t).
/// (R on A, with lambda = scal) the carrier modulation of signals/modulation.h with J = i0.
modulation modulation_of(const representation& R, const carriers& c, const coeffs& w, const GiNaC::ex& t);

/// (IV.1.50-57, the conditions IV.1.64-68 read without branches) Does w represent a purely
/// amplitude-modulated signal A prod_k cos(omega_k t - phi_k), A > 0, for every d of the
/// form IV.1.9? Exactly when w = A exp(-(phi_0 i_0 + ... + phi_n i_n)): the idempotent
/// components z_p all have modulus A, and z_p = A e^(-i Phi_p) with
/// Phi_p = phi_0 + sum_k s_k(p) phi_k, s_k(p) = +-1 the sign of i_k's component p; i.e.
/// z_p z_q = z_p' z_q' whenever the sign vectors of p, q and p', q' agree outside two
/// positions k, l and p, q carry (+,+), (-,-) there, p', q' (+,-), (-,+) (multiplicative:
/// no branch of arg is chosen). Each equality is decided by the scalar zero test: yes,
/// no, or unknown (never guessed). When yes: A and phi_0 .. phi_n (phi_k for k >= 1
/// determined modulo pi, as cos(x - phi - pi) = -cos(x - phi); the representative
/// with -pi/2 < phi_k <= pi/2 is given and phi_0 absorbs the sign).
struct amplitude_modulation {
    truth holds = truth::unknown;
    GiNaC::ex amplitude;
    std::vector<GiNaC::ex> phases;
    std::string report;  ///< which condition fails or is undecided; or the form found
};
amplitude_modulation amplitude_modulated(const multicomplex& A, const coeffs& w);

}  // namespace symrep::signals
