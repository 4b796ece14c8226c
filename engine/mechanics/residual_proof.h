// symrep/mechanics/residual_proof.h -- the zero proofs that check() (cauchy_problem.h,
// solution_check.cpp) tries on the residual of a candidate solution before it compares
// components. Each says true only when it has proved the residual 0; false means "not proved"
// (never "nonzero"): the caller then decides otherwise.
//
// - In the algebra of K = w x (issue 15.2; VI.1.21-22, 26-38): s read exactly as
//       s = sum_v [ c0_v(t) v + c1_v(t) K v + c2_v(t) K^2 v ]
//   over the vector symbols v of the problem's data (K^2 v = w (w . v) - |w|^2 v), each c_k a
//   quasi-polynomial in t, and the residual  sum_m A_m(K) s^(m) - sum_j q_j K^(k_j) F_j
//   computed on those coefficients (quasi_polynomial arithmetic, K^3 = -|w|^2 K), each
//   coefficient decided by the scalar zero test; the initial values likewise.
// - Coordinate-free on quasi-polynomial coefficients: each coefficient of the residual's
//   canonical form, with |v| a positive symbol and the other dot and triple products
//   independent symbols, a quasi-polynomial in t that is the zero function.
// - With integral objects (the solutions of fixed_axis.h): integrals over the same range
//   merged by linearity, bound variables renamed by depth, sin and cos of each argument as
//   sin and cos of one symbol; coordinate-free first, then by components.
#pragma once

#include <ginac/ginac.h>

#include "symrep/mechanics/cauchy_problem.h"

namespace symrep::mechanics {

namespace operator_check {

/// What the check in the algebra of K proved: the residual 0, the initial values right.
struct proof {
    bool residual = false, initial = false;
};

/// The proof in the algebra of K of s for P (see above). Nothing proved (both false) for a
/// free term kept as a Duhamel integral (operator_form::general), for a
/// scalar problem, a fixed-axis, turning-frame or velocity reading, or an s not read so.
proof prove(const cauchy_problem& P, const GiNaC::ex& s);

}  // namespace operator_check

/// A vector residual r proved 0 coordinate-free, its coefficients quasi-polynomials in t.
bool quasi_polynomial_residual_zero(const GiNaC::ex& r, const GiNaC::ex& t);

/// A vector residual with integral objects proved 0: coordinate-free, else by components
/// (fresh real symbols for the components of each vector).
bool integral_residual_zero(const GiNaC::ex& r);

}  // namespace symrep::mechanics
