// symrep/algebra/polynomial_structure.h -- Theorem III.4.1: when is A_n a
// polynomial algebra, and the change of basis to a power basis (III.4.1-4).
//
// A_n is polynomial (A_n = R[X]/(p)) iff some element d has a minimal
// polynomial of degree n (Thm III.4.1; conversely v in R[X]/(p) has minimal
// polynomial p). find_generator searches for such d:
//   1. the basis elements eps_k, then the integer combinations
//      sum_k c_k eps_k with c_k = s^k, s = 2, -2, 3, -3, ... (a fixed
//      Vandermonde sequence), up to max_candidates in all;
//   2. if none works (and `decide`), an exact structural test. The nilradical
//      N is the radical of the trace form Tr([eps_i eps_j]) (characteristic 0),
//      A/N = R^r x C^c, and A = prod of local factors (A_i, m_i) with residue
//      field k_i in {R, C}. A is polynomial iff every m_i/m_i^2 has
//      k_i-dimension <= 1, i.e. iff N/N^2 is a cyclic A/N-module: a u in N with
//      A u + N^2 = N. This is decided with u = sum_l y_l n_l for symbols y_l
//      (the rank is maximal for generic y). If N/N^2 is not cyclic, NO element
//      generates A and the algebra is proved non-polynomial (e.g.
//      R[x,y]/(x,y)^2, where N/N^2 = span(x, y) over A/N = R). If it is
//      cyclic, integer points of a growing box are tried until one generates.
// Otherwise the verdict is "unknown" with the number of candidates tried.
// With symbolic structure constants every test holds for generic values.
#pragma once

#include <cstddef>
#include <string>

#include "symrep/algebra/algebra.h"

namespace symrep {

struct generator_search {
    enum class verdict { polynomial, not_polynomial, unknown };
    verdict status = verdict::unknown;
    coeffs generator;           ///< d with minimal polynomial of degree n (status polynomial)
    std::size_t candidates = 0; ///< number of elements tried
    std::string reason;         ///< one sentence explaining the verdict
};

/// Thm III.4.1: searches for an element whose minimal polynomial has degree n = dim A.
generator_search find_generator(const algebra& A, std::size_t max_candidates = 64,
                                bool decide = true);

/// The nilradical N of A (II.1: the nilpotent elements), as a basis of
/// coordinate vectors: the radical of the trace form (a, b) -> Tr [a b].
std::vector<coeffs> nilradical(const algebra& A);

/// True iff A is polynomial; throws closed_form_error when the search of
/// find_generator can decide neither way.
bool is_polynomial(const algebra& A);

/// True iff 1, d, ..., d^{n-1} are linearly independent (minimal polynomial of degree n).
bool is_generator(const algebra& A, const coeffs& d);

/// (III.4.4) the matrix M with [d^0, ..., d^{n-1}]^T = M [eps]: row k holds the
/// coordinates of d^k. Throws algebra_error if d does not generate A (det M = 0).
GiNaC::matrix change_of_basis_to_power_basis(const algebra& A, const coeffs& d);

/// Thm II.2.3 / (III.4.1): the functions f_j(t) with exp(d t) = sum_j f_j(t) eps_j.
/// They form a fundamental system of q(D) f = 0 when d generates A.
std::vector<GiNaC::ex> fundamental_system(const algebra& A, const coeffs& d, const GiNaC::symbol& t);

/// (III.4.2-4) the Wronskian form of the same matrix: M_kj = f_j^{(k)}(0).
GiNaC::matrix wronskian_at_zero(const algebra& A, const coeffs& d);

}  // namespace symrep
