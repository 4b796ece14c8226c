// symrep/core/expression_size.h -- estimates of the size of what GiNaC's
// normal(), expand(), factor(), determinants and derivatives would build, and
// the guard that refuses what cannot fit in memory.
//
// Such a GiNaC call runs to its end once made. Time is not its problem here: the
// programs link core/allocation_interrupt.cpp, whose operator new stops any
// computation at Ctrl-C or at the statement's time limit. Memory is: a power of
// a sum of many terms, a product of large sums, a determinant of large entries
// can ask for more terms than the machine holds, and be killed by the system
// before any allocation fails. So the places that make these calls on
// expressions the user gave first ask guard_terms() with an estimate of the
// terms multiplied out: it polls check_interrupt() and refuses more than 10^8
// terms with a size_error. The estimates are upper bounds of the kind below,
// cheap (one pass over the expression) and coarse.
#pragma once

#include <ginac/ginac.h>

#include <vector>

namespace symrep {

/// An upper bound of the number of terms of e multiplied out: sums add, products
/// multiply, a power k > 0 of a sum of m terms gives C(k + m - 1, m - 1) terms;
/// function calls and other powers are one term each, and their arguments are
/// counted as expansions of their own. With `fractions`, what normal() builds:
/// e over the lcm of its denominators (negative integer powers), the terms of
/// that numerator and of the denominator. Saturates at 1e30; an expression tree
/// of more than 10^7 nodes counts as 1e30.
double expanded_terms(const GiNaC::ex& e, bool fractions);

/// An upper bound of the terms of the product of `factors` multiplied out: the
/// smaller of the bound of expanded_terms on the product and, when every factor
/// is a polynomial with rational (or complex rational) coefficients in symbols
/// x_1..x_k, the monomial count prod_j (sum_i deg_{x_j} f_i + 1) (a product of
/// 2^n quadratics in X has 2^(n+1) + 1 terms, not 3^(2^n)).
double product_terms(const std::vector<GiNaC::ex>& factors);

/// An upper bound of the terms of det(m) (charpoly: of det(m - X I)): the
/// product over the rows of the terms of their entries (the numbers of a row
/// count as one term together).
double determinant_terms(const GiNaC::matrix& m, bool charpoly);

/// The nodes of the expression tree of e, a subexpression counted as often as it
/// occurs (the work of a pass over e, such as diff); saturates at 1e30.
double expression_nodes(const GiNaC::ex& e);

/// Largest estimate guard_terms accepts, time limit or not.
constexpr double max_expanded_terms = 1e8;
/// The guard: polls check_interrupt(), and throws size_error "WHAT: the
/// expression is too large (an estimated N terms to multiply out; the limit is
/// 10^8)" when n > max_expanded_terms.
void guard_terms(double n, const char* what);
/// guard_terms(expanded_terms(e, fractions), what); `fractions`: before normal().
void guard_expansion(const GiNaC::ex& e, const char* what, bool fractions);
/// GiNaC::expand(e), guarded.
GiNaC::ex guarded_expand(const GiNaC::ex& e, const char* what);

}  // namespace symrep
