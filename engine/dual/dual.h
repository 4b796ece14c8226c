// symrep/dual/dual.h -- dual numbers and dual vectors, coordinate-free.
//
// A dual number is a + eps b with eps^2 = 0 (eps != 0): the algebra R[X]/(X^2),
// the polynomial algebra of the characteristic polynomial X^2 (Ch. III;
// algebra/polynomial_algebra.h computes in it by structure constants). Here a
// dual quantity is an ordinary GiNaC expression in one distinguished real
// symbol, the dual unit dual_unit() (named "eps", TeX \varepsilon), kept
// reduced modulo eps^2: reduce(e) = primal(e) + eps dual_part(e). So every
// floor above handles dual scalars and dual vectors (a + eps b with a, b
// vector expressions of vector/vector.h) as the expressions it already has:
// printing, substitution, the canonical form and equality work part by part.
//
// The dual extension of a function (Study, Clifford; Condurache & Burlacu 2014):
//     f(a + eps b) = f(a) + eps b f'(a),
// and for several arguments f(a + eps b) = f(a) + eps sum_i b_i d_i f(a).
// reduce() applies it to every node of the tree: sums part by part, products by
// the product rule, cross/dot/triple products multilinearly, vector literals by
// components, and any other function through its partial derivatives (GiNaC's
// diff). That is the transference principle made mechanical: an identity of
// real vectors built from these operations holds for dual vectors.
//
// Division needs an invertible primal part: 1/(a + eps b) = 1/a - eps b/a^2;
// a pure dual number eps b (a = 0) is a zero divisor (eps * eps = 0), and the
// reduction throws zero_divisor_error rather than guess. A primal part that the
// zero test cannot decide throws domain_error ("cannot decide ...").
#pragma once

#include <ginac/ginac.h>

namespace symrep::dual {

/// The dual unit eps (eps^2 = 0): one real symbol for the whole process, named
/// "eps" (TeX "\varepsilon"). Expressions in it are dual quantities.
const GiNaC::ex& dual_unit();
/// True when e contains the dual unit.
bool has_dual_unit(const GiNaC::ex& e);

/// The two parts of a dual quantity e = p + eps d, both free of eps.
struct dual_parts {
    GiNaC::ex primal;
    GiNaC::ex dual;
};
/// The parts of e modulo eps^2 (the dual extension of every function, above).
/// zero_divisor_error when e divides by, or takes a function at a singular
/// point of, a pure dual quantity (1/eps, log(eps b)); domain_error when a primal
/// divisor cannot be decided nonzero.
dual_parts parts(const GiNaC::ex& e);
/// primal + eps dual, with both parts left as parts() gives them. A relation,
/// a list or a matrix is reduced side by side, item by item, entry by entry.
GiNaC::ex reduce(const GiNaC::ex& e);
/// The primal part (eps = 0 after reduction).
GiNaC::ex primal(const GiNaC::ex& e);
/// The dual part (the coefficient of eps after reduction).
GiNaC::ex dual_part(const GiNaC::ex& e);
/// a + eps b (a, b free of eps; both scalars or both vectors; 0 counts as either).
/// Two vector literals give one literal with dual components ([1, eps, 0]).
GiNaC::ex make_dual(const GiNaC::ex& a, const GiNaC::ex& b);

/// Dual products of dual vectors, reduced: (a + eps a') x (b + eps b') =
/// a x b + eps (a x b' + a' x b), likewise for the dot and the triple product.
GiNaC::ex dual_cross(const GiNaC::ex& a, const GiNaC::ex& b);
GiNaC::ex dual_dot(const GiNaC::ex& a, const GiNaC::ex& b);
GiNaC::ex dual_triple(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c);

/// Exact equality of two dual quantities, part by part (vector/vector.h equal()).
bool dual_equal(const GiNaC::ex& a, const GiNaC::ex& b);

}  // namespace symrep::dual
