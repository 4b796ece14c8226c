// symrep/algebra/expression_size.h -- estimates of the work of GiNaC's normal(),
// expand(), factor(), determinants and derivatives, and the guard that refuses
// the calls that would run away.
//
// Such a GiNaC call runs to its end once made: the time limit of a statement
// (check_interrupt, io/error.h) is seen only between calls. A product of sums,
// a power of a sum, a fraction whose gcd has many variables of high degree can
// keep one call busy for minutes, so the places that make these calls on
// expressions the user gave first ask guard_terms() with an estimate of the
// work, counted in terms multiplied out (about 10^6 a second): it polls the time
// limit, refuses what cannot end within the time the statement has left, and
// refuses more than 10^8 terms in any case. The estimates are upper bounds of
// the kind below, cheap (one pass over the expression) and coarse.
#pragma once

#include <ginac/ginac.h>

namespace symrep {

/// An upper bound of the number of terms of e multiplied out: sums add, products
/// multiply, a power k > 0 of a sum of m terms gives C(k + m - 1, m - 1) terms;
/// function calls and other powers are one term each, and their arguments are
/// counted as expansions of their own. With `fractions`, the work of normal(),
/// which brings e to one fraction over the lcm of the denominators (negative
/// integer powers) and cancels a gcd: the terms of that numerator and
/// denominator, or the dense size prod_v (deg_v + 1) of the denominator in its
/// variables when larger (GiNaC's multivariate gcd works variable by variable).
/// Saturates at 1e30; an expression tree of more than 10^7 nodes counts as 1e30.
double expanded_terms(const GiNaC::ex& e, bool fractions);

/// The work of factor(e): normal() first, then multivariate factorization, whose
/// cost grows with the dense size prod_v (deg_v + 1) of e (50 units each).
double factor_work(const GiNaC::ex& e);

/// An upper bound of the terms of det(m) (charpoly: of det(m - X I)): the
/// product over the rows of the terms of their entries (the numbers of a row
/// count as one term together).
double determinant_terms(const GiNaC::matrix& m, bool charpoly);

/// The nodes of the expression tree of e, a subexpression counted as often as it
/// occurs (the work of a pass over e, such as diff); saturates at 1e30.
double expression_nodes(const GiNaC::ex& e);

/// Largest estimate guard_terms accepts, time limit or not.
constexpr double max_expanded_terms = 1e8;
/// Estimated terms per second guard_terms counts on when a time limit is set
/// (GiNaC multiplies out about 10^6 terms a second on one core).
constexpr double expanded_terms_per_second = 1e6;

/// The guard: polls the time limit (check_interrupt); throws size_error "WHAT:
/// the expression is too large (an estimated N terms to multiply out; the limit
/// is 10^8)" when n > max_expanded_terms; and, when the running statement has a
/// time limit (deadline_ticks), throws symrep::error "time limit: WHAT would not
/// end within the statement's time limit ..." when n terms at
/// expanded_terms_per_second would not be done in the time left.
void guard_terms(double n, const char* what);
/// guard_terms(expanded_terms(e, fractions), what); `fractions`: before normal().
void guard_expansion(const GiNaC::ex& e, const char* what, bool fractions);
/// GiNaC::expand(e), guarded.
GiNaC::ex guarded_expand(const GiNaC::ex& e, const char* what);

}  // namespace symrep
