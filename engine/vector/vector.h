// symrep/vector/vector.h -- coordinate-free 3-vectors (thesis Ch. VI).
//
// vector/ holds abstract vectors, cross, dot and triple products, their
// canonical form and their printing in the thesis's notation. It includes
// core/ and scalar/ (docs/architecture.md).
//
// Representation
// --------------
// * An abstract vector is a GiNaC::realsymbol that is registered as a vector in
//   a process-wide registry (vector_symbol("w") creates it, or returns the one
//   already registered under that name; register_vector() marks an existing
//   realsymbol, e.g. one of the interpreter's symbols, as a vector). Scalars
//   are all expressions that contain no vector.
// * A vector literal (components [x, y, z]) is a 3x1 GiNaC::matrix; make it
//   with vector_literal(x, y, z). Only 3x1 matrices are vectors.
// * cross(a, b), dot(a, b) and the triple product [a, b, c] are GiNaC functions
//   (printed by GiNaC as cross(a,b), dot(a,b), triple(a,b,c); use to_string()
//   for the thesis notation). Their eval rules, run whenever GiNaC builds the
//   expression, are cheap: zero argument (0 or [0, 0, 0]) -> 0, linearity over sums, scalar
//   factors pulled out, cross(a, a) = 0, dot(a, a x b) = 0, a fixed argument
//   order for two vector symbols (by name: cross(b, a) -> -cross(a, b),
//   dot(b, a) -> dot(a, b), triple sorted with the permutation sign, 0 on a
//   repeated vector), and literal x literal computed by components. Deeper
//   identities (BAC-CAB, Lagrange, Gram) belong to canonical().
// * norm(a) = sqrt(dot(a, a)), printed |a|; dot(a, a) prints |a|^2.
// * The zero vector is the number 0 (GiNaC collapses a x a, 0*w, w - w to 0):
//   0 is accepted wherever a vector is expected.
// * Time dependence: vector_function("r", t) registers r as a vector that
//   depends on the real symbol t. Its derivatives are again registered vector
//   symbols named r', r'', ... (derivative(r) returns r', created on demand,
//   themselves depending on t). diff_t(e, t) is the total time derivative:
//   vectors not declared as functions of t are constants. GiNaC's own
//   e.diff(x) is the partial derivative with all vectors held constant.
//
// Canonical form and equality
// ---------------------------
// canonical(e) rewrites a vector expression as  sum s_i v_i + sum s_ij (v_i x v_j)
// (v_i vector symbols or literals, i < j by name) and a scalar expression as a
// polynomial/rational function of the atoms v_i . v_j and [v_i, v_j, v_k],
// products of two triple products replaced by Gram determinants; coefficients
// are expanded and normalized. In 3-D this form is NOT unique for four or more
// vectors ([a,b,c] d = (a.d) b x c + (b.d) c x a + (c.d) a x b), so it is used
// for printing and as a fast zero test, while equal(a, b) decides equality
// exactly: it substitutes fresh symbolic components for every abstract vector
// in a - b and tests each component with GiNaC's normal() (after two fast
// paths: a random integer point that gives a non-zero rational proves a != b;
// canonical(a - b) == 0 proves a == b; see docs/vectors.md). That test is a
// decision procedure for rational expressions in the components; with other
// functions (sin, exp, ...) of vector data it is only as strong as normal().
#pragma once

#include <map>
#include <string>
#include <vector>
#include <ginac/ginac.h>

#include "symrep/scalar/equality.h"

namespace symrep {

// GiNaC functions behind cross/dot/triple; use the wrappers below, which check
// their arguments and report errors naming them.
DECLARE_FUNCTION_2P(vcross)
DECLARE_FUNCTION_2P(vdot)
DECLARE_FUNCTION_3P(vtriple)

// ---------------------------------------------------------------- registry
/// The vector symbol named `name`: created as a realsymbol and registered on
/// first use, the same symbol afterwards. Throws type_error on an empty name
/// or one with a blank, a comma, a bracket or ' (reserved for derivatives).
GiNaC::ex vector_symbol(const std::string& name);
/// Marks an existing GiNaC symbol (e.g. an interpreter's realsymbol) as a
/// vector; a no-op if it already is. Several symbols may carry the same name
/// (one per interpreter session, say): they are different vectors, and
/// vector_symbol(name) keeps returning its own one.
void register_vector(const GiNaC::ex& sym);
/// A vector symbol r depending on the real symbol t (see derivative()).
/// Throws type_error if r already depends on another variable or its name
/// contains ' (reserved for derivative symbols).
GiNaC::ex vector_function(const std::string& name, const GiNaC::ex& t);
/// register_vector(sym) and declares it a function of t (as vector_function).
void register_vector_function(const GiNaC::ex& sym, const GiNaC::ex& t);
/// The derivative symbol of a time-dependent vector symbol: r -> r', r' -> r''.
/// Throws type_error if r is not a vector function.
GiNaC::ex derivative(const GiNaC::ex& r);
/// True for a registered vector symbol.
bool is_vector_symbol(const GiNaC::ex& e);
/// True for a 3x1 GiNaC matrix (a vector literal).
bool is_vector_literal(const GiNaC::ex& e);
/// The literal [x, y, z].
GiNaC::ex vector_literal(const GiNaC::ex& x, const GiNaC::ex& y, const GiNaC::ex& z);

// ------------------------------------------------------------ constructors
/// a x b. Throws type_error naming the argument if one is a (non-zero) scalar.
GiNaC::ex cross(const GiNaC::ex& a, const GiNaC::ex& b);
/// a . b. Throws type_error naming the argument if one is a (non-zero) scalar.
GiNaC::ex dot(const GiNaC::ex& a, const GiNaC::ex& b);
/// [a, b, c] = a . (b x c).
GiNaC::ex triple(const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::ex& c);
/// |a| = sqrt(a . a).
GiNaC::ex norm(const GiNaC::ex& a);

// ---------------------------------------------------------------- analysis
/// True when e is vector-valued, false when scalar (0 counts as scalar).
/// Throws type_error on an ill-formed expression: vector + scalar, a product
/// of two vectors, a power or a function (sin, ...) of a vector.
bool is_vector(const GiNaC::ex& e);
/// The registered vector symbols occurring in e, sorted by name.
std::vector<GiNaC::ex> vector_symbols(const GiNaC::ex& e);

/// Total derivative d/dt (t a GiNaC symbol); vector functions of t
/// differentiate to their derivative symbols, other vectors are constant.
GiNaC::ex diff_t(const GiNaC::ex& e, const GiNaC::ex& t);

/// Substitutes vector expressions (usually literals) for vector symbols and
/// re-evaluates; symbols not in the map stay abstract. Throws type_error if a
/// key is not a vector symbol or a value is not a vector (0 allowed).
GiNaC::ex subs_vectors(const GiNaC::ex& e, const std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& m);

/// Component form: every vector symbol of e must be a key of m, mapped to a
/// literal (or a vector expression that becomes one). Returns a 3x1 matrix
/// (vector_literal) for a vector e, the scalar for a scalar e; components are
/// expanded but not otherwise simplified. Throws type_error naming a vector
/// symbol that is missing from m.
GiNaC::ex subs_components(const GiNaC::ex& e, const std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& m);

/// Canonical form (see above). Throws type_error on an ill-formed expression.
GiNaC::ex canonical(const GiNaC::ex& e);

/// One term of a canonical form: coefficient * monomial.
struct vector_term {
    GiNaC::ex monomial;     ///< a vector symbol, v_i x v_j (i < j by name), a literal; 1 for a scalar
    GiNaC::ex coefficient;  ///< a scalar, normalized
};
/// The terms of canonical(e) in a fixed order: vector symbols by name, then
/// cross products (by their factors' names), then one literal holding every
/// literal contribution. A scalar e gives one term with monomial 1 (none if
/// it is 0). canonical(e) is the sum of coefficient * monomial.
std::vector<vector_term> canonical_terms(const GiNaC::ex& e);

/// Exact equality of two vector (or two scalar) expressions by the component
/// test. Comparing a vector with a scalar other than 0 throws type_error.
bool equal(const GiNaC::ex& a, const GiNaC::ex& b);
/// Three-valued: is the vector (or scalar) d identically 0? yes (proved, as
/// equal), no (a witness point of the components v_1, v_2, v_3 of each vector
/// symbol v, scalar/equality.h), or unknown.
zero_decision decide_zero_vector(const GiNaC::ex& d);

/// How to_string writes the cross and the scalar product: `a x b`, `a . b`
/// (ascii) or `a × b`, `a · b` (unicode: U+00D7 and U+00B7, UTF-8 encoded;
/// the language reads both). The two texts differ only by these two signs:
/// terms and factors come in the same order.
enum class notation { ascii, unicode };
/// The notation of to_string(e): process-wide like GiNaC::Digits, ascii at
/// start (the symrep program sets it from --unicode/--ascii, the language by
/// notation("unicode"); a lang::session restores it when destroyed).
notation vector_notation();
void set_vector_notation(notation n);

/// Text in the thesis notation, deterministic (independent of GiNaC's term
/// order and of symbol creation order): a x (b x c), a . b, |w|, |w|^2, [a, b, c],
/// [1, 0, t] for a literal; products with '*', quotients with '/'. Cross and dot
/// are written in vector_notation().
std::string to_string(const GiNaC::ex& e);
/// The same text in the given notation.
std::string to_string(const GiNaC::ex& e, notation n);

}  // namespace symrep
