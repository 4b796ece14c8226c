// symrep/transforms/parseval.h -- the hypercomplex Parseval relation and inner product
// (thesis V.2.40-49, Thm V.2.4) for causal quasi-polynomial signals.
//
// Time side: <f, g> = int_0^oo f g dt = L[f g](0), exact (laplace.h inner_product).
// Frequency side: (1/2 pi) int_R F(i w) conj G(i w) dw = (1/2 pi i) int_iR F(s) G(-s) ds (f, g
// real), and, closing the path to the left (F G(-s) = O(s^-2); the poles of G(-s) lie right of
// the axis when g decays), the sum of the residues of F(s) G(-s) at the poles of F -- the
// exponents lambda of f, with their multiplicities m:
//     Res = 1/(m-1)! (d/ds)^(m-1) [ q_f(s) G(-s) / prod_(mu != lambda) (s - mu)^(m_mu) ] at s = lambda,
// exact, and proved equal to the time side (`==` by the zero test).
// Over multicomplex(n) (V.2.44-46): with d = sum_k omega_k i_k, the conjugate of V.2.40-41 is
// the componentwise complex conjugation in the idempotent basis B* (read (41) in B*: e_p kept,
// i0 e_p negated), which in the basis B of (17) changes the sign of every generator, i_k -> -i_k
// (coordinate of i_S times (-1)^|S|); the printed (41) negates in B only the coordinates with
// i0, which maps e_p to the idempotent of the complementary index and does not give (44). So
// (T g)^* = T g(-d) for real g, the component p of T f (T g)^* is F(i Omega_p) conj G(i Omega_p),
// and (1/2 pi i0) int_A T f (T g)^* dd, integrated componentwise (V.2.37), is <f, g> times the
// unit: the algebra-valued Parseval relation (V.2.44-45, 49). parseval() proves each step
// exactly and evaluates the frequency integral by quadrature as a check.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/equality.h"

namespace symrep::transforms {

/// (V.2.40-41 read in B*) The conjugate of a multicomplex element: i_k -> -i_k for every
/// generator (componentwise complex conjugation in the idempotent basis). algebra_error for
/// another algebra.
coeffs hypercomplex_conjugate(const algebra_ptr& A, const coeffs& x);

/// (1/2 pi) int_R F(i w) conj G(i w) dw, F = L f, G = L g, by residues (see above). domain_error
/// when an exponent of f or g is not shown to have a negative real part (not in L2: named).
GiNaC::ex parseval_frequency_side(const GiNaC::ex& f, const GiNaC::ex& g, const GiNaC::symbol& t);

struct parseval_result {
    GiNaC::ex time_side;       ///< int_0^oo f g dt
    GiNaC::ex frequency_side;  ///< the residue sum
    coeffs element;            ///< (1/2 pi i0) int_A T f (T g)^* dd on the multicomplex algebra
    truth proved = truth::unknown;  ///< every identity below proved
    double quadrature = 0, quadrature_error = 0;  ///< the frequency integral by quadrature (numeric data)
    bool has_quadrature = false;
    std::string report;
};

/// (Thm V.2.4, V.2.44-49) The relation for f, g over A = multicomplex(n) (see above): the time
/// side, the frequency side by residues, their equality, (T g)^* = T g(-d), the components of
/// T f (T g)^* equal to F(i Omega_p) conj G(i Omega_p) (d = sum omega_k i_k symbolic), and,
/// for numeric data, the frequency integral by quadrature.
parseval_result parseval(const algebra_ptr& A, const GiNaC::ex& f, const GiNaC::ex& g, const GiNaC::symbol& t);

}  // namespace symrep::transforms
