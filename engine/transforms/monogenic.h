// symrep/transforms/monogenic.h -- monogenicity of a function of the algebra variable
// (thesis Thm V.2.1 with V.2.18-21, Thm V.3.1 with V.3.19).
//
// F, an element whose coordinates are functions of the coordinates of the variable
// d = c + sum_x x b_x (x the symbols of d, b_x = dd/dx constant elements), is monogenic in d
// when its differential is an algebra multiple of dd: F wedge dd = 0 (V.2.20, V.3.19), i.e.
// dF/dx = F'(d) b_x for every x. With a variable r whose direction b_r is invertible this is
// the system of generalized Cauchy-Riemann conditions
//     b_r dF/dx = b_x dF/dr   for every other x                (V.2.21: i0 dF/domega_k = i_k dF/domega_0)
// each coordinate proved 0 by the exact zero test (or shown nonzero at a witness point).
// Over sobrero(n) with d = x + eps + j w (V.3.7) the conditions are j dF/dx = dF/dw (the complex
// Cauchy-Riemann equations), and with a symbolic eps coefficient e also dF/de = eps dF/dx.
#pragma once

#include <string>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/equality.h"

namespace symrep::transforms {

struct monogenicity {
    truth holds = truth::unknown;  ///< yes: every condition proved; no: one shown false
    std::string report;            ///< the conditions, each with its outcome
};

/// The conditions above for F(d). domain_error when d is not affine in its symbols, has no
/// symbol, or no symbol has an invertible direction.
monogenicity monogenic(const algebra_ptr& A, const coeffs& F, const coeffs& d);

}  // namespace symrep::transforms
