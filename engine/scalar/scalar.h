// symrep/scalar/scalar.h -- the exact scalar layer: the two coefficient types of
// symrep and what every floor above needs to treat them alike.
//
// This folder is the ground of all mathematics in symrep. Exact arithmetic
// uses GiNaC::ex (CLN rationals, algebraic numbers, symbols); the fast numeric
// path uses double. Here live the exact zero test (zero_test.cpp), the
// simplification of coefficients (tidy, simplify.cpp), radicals and
// arctangents written as algebraic functions, and exp/log of scalars. Family
// code that is written once as a template over T calls only the functions
// below (plus +,-,*,/ and the elementary functions found by argument-dependent
// lookup: exp, log, cos, sin, sqrt, atan2), so that one implementation serves
// both paths. It includes only core/ (docs/architecture.md).
#pragma once

#include <optional>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>
#include <ginac/ginac.h>

#include "symrep/core/error.h"

namespace symrep {

/// Logarithms of products of powers of positive rationals, and such powers,
/// written over primes: log(c b^e) -> log(c) + e log(b), 8^(1/2) -> 2 2^(1/2), log(p1^k1 ... / q1^l1 ...) -> k1 log(p1) + ... - l1 log(q1) - ...
/// (prime factors below 2^16 are split off; the larger cofactors of e are written over one
/// coprime base, scalar/small_primes.h, so that sqrt(3 P) and sqrt(3 P q^2) meet for large P, q).
/// Two sums of such logarithms are equal iff their expanded forms agree, so the
/// zero test sees log(16)/2 = log(4) = 2 log(2).
GiNaC::ex expand_rational_logs(const GiNaC::ex& e);

/// True when e contains tan, sinh, cosh or tanh.
bool has_tan_or_hyperbolic(const GiNaC::ex& e);

/// True when exponentials of e can meet each other: two different exp(...), or
/// one exp of a sum (exp(x)*exp(y) = exp(x + y) is then seen through Y_m below).
bool has_related_exponentials(const GiNaC::ex& e);

/// sin and cos (and tan) of linear combinations written through exponentials:
/// with one symbol X_m standing for e^(i m) per monomial m of the arguments,
/// sin(sum c_k m_k) = (E - 1/E)/(2i), cos = (E + 1/E)/2, E = prod X_{m_k}^{c_k}.
/// A trigonometric polynomial in such arguments is 0 iff this rational function
/// in the X_m is 0, so the zero test sees the addition theorems (sin((a + b) t)
/// = ...). Likewise sinh, cosh, tanh with symbols Y_m standing for e^m, and
/// exp(u) = prod Y_{m_k}^{c_k} when the expression has a hyperbolic function
/// or exponentials that can meet (has_related_exponentials)
/// (cosh(x)^2 - sinh(x)^2 = 1, cosh(x) = (e^x + e^-x)/2).
GiNaC::ex trig_exponential_form(const GiNaC::ex& e);

/// e with each odd power sqrt(b)^k of a non-numeric b written q_b^k, q_b a real
/// symbol per base (`roots`: base and symbol, in order of appearance: a root
/// comes after the roots inside its base). With `rational_bases`, square roots of
/// rational numbers (sqrt(5) inside sqrt(3 + sqrt(5))) become symbols too.
struct square_roots_as_symbols {
    GiNaC::ex e;
    std::vector<std::pair<GiNaC::ex, GiNaC::realsymbol>> roots;
};
square_roots_as_symbols with_square_roots_as_symbols(const GiNaC::ex& e, bool rational_bases = false);

/// Zero test of a rational function of symbols and square roots of non-numeric
/// expressions: each sqrt(b) becomes a symbol q_b, and the numerator is reduced
/// modulo q_b^2 - b (normal() alone treats sqrt(b) as an unrelated atom, so that
/// sqrt(b)^2 - b would not cancel once it is split over a fraction). Nested roots
/// (sqrt((sqrt(u^2 + v^2) - u)/2) of a complex quadratic's roots) are reduced
/// outermost first, with square roots of rational numbers as symbols too.
/// True only when the reduced numerator is 0 (a proof); false is "not proved".
bool is_zero_modulo_square_roots(const GiNaC::ex& e);

/// True when e contains b^(k/2), k odd, with b not a number.
bool has_symbolic_square_root(const GiNaC::ex& e);

/// sin, cos and tan of atan2(y, x) and of atan(z) as algebraic functions:
/// cos(atan2(y, x)) = x/sqrt(x^2 + y^2), sin(atan2(y, x)) = y/sqrt(x^2 + y^2),
/// tan(atan2(y, x)) = y/x; cos(atan(z)) = 1/sqrt(1 + z^2), sin(atan(z)) =
/// z/sqrt(1 + z^2) (identities for real arguments, which atan2 has). exp of
/// the logarithm of an element (III.1.58: log |z| + i arg z) then gives back its
/// coordinates. The sum under the root is expanded, as log_modulus writes it, so
/// that sqrt(x^2 + y^2) meets the modulus it came from.
GiNaC::ex trig_of_arctangents(const GiNaC::ex& e);

/// expand(e) with every sin(u)^2 written 1 - cos(u)^2 (GiNaC's algebraic substitution: sin(u)^4 too):
/// cos(1)^2 + sin(1)^2 becomes 1.
GiNaC::ex sines_squared_as_cosines(const GiNaC::ex& e);

/// atan2(y, x) for real constants y, x (no symbols) as an exact angle where one is proved:
/// u with x sin(u) - y cos(u) = 0 (the exact zero test) and x cos(u) + y sin(u) > 0 (at 40
/// digits, clear of 0), -pi < u <= pi (at 40 digits), u a rational multiple of pi (denominator
/// <= 60) or the argument of a cos or sin in x or y: atan2(sqrt(3)/2, 1/2) = pi/3,
/// atan2(sin(1), cos(1)) = 1. Otherwise atan2(y, x) unchanged (never a guess).
GiNaC::ex atan2_exact(const GiNaC::ex& y, const GiNaC::ex& x);

/// Exact zero test: true when the expression normalizes to 0 (logarithms and
/// powers of rational numbers are compared over primes, sin, cos, tan and the
/// hyperbolic functions through exponentials, and square roots of expressions
/// as algebraic symbols, when plain normalization does not decide).
bool is_zero_scalar(const GiNaC::ex& x);

/// e.subs(s) (s: a relation, a list of them, or an exmap), with a division by
/// zero said before GiNaC evaluates it: GiNaC's power::eval throws for 0^(-k)
/// and loses the power it allocated. Powers are checked innermost first.
template <class S>
GiNaC::ex subs_checked(const GiNaC::ex& e, const S& s) {
    for (auto it = e.postorder_begin(); it != e.postorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
            !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).real().is_positive() && it->op(0).subs(s).is_zero())
            throw domain_error("division by zero");
    return e.subs(s);
}

/// Double zero test with an absolute tolerance (callers scale it to the data).
inline bool is_zero_scalar(double x, double tol = 0.0) { return std::abs(x) <= tol; }

/// True when x contains a symbol (a free parameter, the variable t, ...); false for numbers,
/// constants such as pi and expressions made of them.
bool has_symbol(const GiNaC::ex& x);

/// The distinct symbols of the expressions xs, sorted by name (a deterministic order).
std::vector<GiNaC::ex> symbols_by_name(const std::vector<GiNaC::ex>& xs);

/// A term (a product, or a single factor) split as c rest: c the product of its numeric
/// factors, rest the product of the others in their order (1 when there are none).
std::pair<GiNaC::numeric, GiNaC::ex> split_numeric_factor(const GiNaC::ex& term);

/// True when x contains a function call (exp, cos, log, ...).
bool has_function_call(const GiNaC::ex& x);

/// True when a is a number < 0 or a product with a numeric factor < 0 (-5*t).
bool has_negative_sign(const GiNaC::ex& a);

/// cos(-u) -> cos(u), sin(-u) -> -sin(u), everywhere in e (GiNaC leaves
/// cos(-5*t) alone, so that cos(5*t) and cos(-5*t) would not combine).
GiNaC::ex normalize_trig_signs(const GiNaC::ex& e);

/// Bring an exact coefficient to its simplest stored form: rational functions of
/// symbols are expanded and normalized (one fraction, common factors cancelled);
/// expressions with function calls, such as the closed forms of exp(w t), are only
/// expanded, so that they stay sums of exponentials and trigonometric terms instead
/// of becoming one fraction over exp(...). Identity for doubles.
GiNaC::ex tidy(const GiNaC::ex& x);

/// A sum of fractions as one fraction over the product of their denominators' factors, each
/// polynomial factor (a sum, up to its sign) taken as an opaque symbol while normalizing: the
/// numerators are combined exactly (a zero sum gives 0), but a factor shared by the numerator
/// and a denominator is not searched for (no multivariate gcd of the expanded products, which
/// cost seconds on the solver's denominators (lambda_i - lambda_j)^m). Expressions with
/// function calls as tidy().
GiNaC::ex one_fraction(const GiNaC::ex& x);

/// A rational function of symbols as a sum of reduced fractions, one per product of
/// polynomial denominator factors (each factor a sum, identified up to its sign): the terms
/// over the same factors are added, and each such numerator is divided by its factors while
/// they divide it. No common denominator of different factors is formed (its numerator is
/// the product of all the others: the solver's coefficients over (lambda_i - mu_j)^m grew
/// 3x longer and cost 20x more that way). With three groups or more the result is checked
/// against 0 at a rational point. nullopt (the caller forms one fraction, exactly) when x is
/// not a rational function of symbols, has fewer than three groups (one fraction is as short
/// and as cheap), or vanishes at the point (it may be 0: only a full normal form decides).
std::optional<GiNaC::ex> sum_of_fractions(const GiNaC::ex& x);

/// True when x, a rational function of symbols, is proved 0 by its terms over the same
/// polynomial denominator factors (any powers: over their common denominator) summing to 0
/// group by group. False says nothing (the groups may cancel only together): the caller's
/// full test decides. Cheap where the terms of a sum cancel factor by factor, as the residuals
/// of the solver's closed forms do.
bool proved_zero_by_denominators(const GiNaC::ex& x);

/// c in Q(...)[q]/(q^2 - A) for its one square root q = sqrt(A) (any expression A):
/// (M1 + M2 q)/D, denominators rationalized by the conjugate, each part normalized; without a
/// root one fraction; with several, c unchanged (square_root_field.cpp). With rational_bases,
/// square roots of rationals count as roots too (as with_square_roots_as_symbols).
GiNaC::ex in_square_root_field(const GiNaC::ex& c, bool rational_bases = false);
/// Each coefficient of the functions of t in c (t^k, exp, sin, cos of t) brought into the
/// field of its square root (in_square_root_field), then summed: a canonical form of a
/// quasi-polynomial whose coefficients hold one square root, whatever form the solver's
/// pivots left them in.
GiNaC::ex simplified_square_roots(const GiNaC::ex& c, const GiNaC::ex& t, bool rational_bases = false);
/// c in the number field of its square roots of rational numbers, Q(sqrt(b_1), ..., sqrt(b_k))
/// over its other atoms (symbols, functions, other roots): the roots as symbols q_i, numerator and
/// denominator reduced modulo q_i^2 - b_i, the denominator freed of each q_i in turn by its
/// conjugate, then one fraction. With the b_i over primes (expand_rational_logs) this is the
/// canonical form the zero test works in: (3 + 2 sqrt(2))/(2 + sqrt(2))^2 -> 1/2. c unchanged
/// without such roots, with more than max_roots of them, or where a conjugate product is 0.
GiNaC::ex in_square_roots_field(const GiNaC::ex& c, std::size_t max_roots = 6);

/// Half-integer powers of positive rationals in each product made one
/// c sqrt(b), b a square-free integer: sqrt(12) = 2 sqrt(3), sqrt(26) sqrt(34) = 2 sqrt(221)
/// (square-free over the primes below 2^16; larger cofactors over the coprime base of e's
/// radicands, scalar/small_primes.h: sqrt(3 P q^2) = q sqrt(3 P) next to sqrt(3 P)).
GiNaC::ex canonical_radicals(const GiNaC::ex& e);

/// simplify(e) of the language: at least what the zero test decides (radicals and
/// logarithms of rationals over primes, trigonometric and hyperbolic identities
/// through the exponential form when it normalizes to a form without them,
/// arctangents inside sin/cos as algebraic functions), else normal(expand(e)).
GiNaC::ex simplify_scalar(const GiNaC::ex& x);
inline double tidy(double x) { return x; }

/// The lengths (characters) beyond which message_text cuts an expression, one per use:
namespace text_limit {
/// an expression that an error message names (message_text's default)
inline constexpr std::size_t message = 160;
/// a part of an expression quoted beside the whole it comes from (a coefficient, an argument):
/// shorter, so that the sentence around it stays readable
inline constexpr std::size_t fragment = 80;
/// an expression inside a report or an error of the transforms and of the multicomplex signals
/// (transforms, inverses, modulations: longer forms than an error's operand)
inline constexpr std::size_t report = 200;
/// the same in the representations and responses of signals/ (representation.cpp,
/// response.cpp); 300 rather than 200 by history only, kept so that outputs stay byte-identical
inline constexpr std::size_t signal_report = 300;
/// a text that names an object (a polynomial algebra's name): not cut in practice
inline constexpr std::size_t name = 100000;
}  // namespace text_limit

/// An expression as text for an error message, cut to about `max` characters
/// (a message that quotes a 10 000-character minimal polynomial helps nobody): its first
/// max/2 and last max/4 characters around " ... ", and its length. Printed by the message
/// printer below.
std::string message_text(const GiNaC::ex& e, std::size_t max = text_limit::message);

/// The printer of message_text. GiNaC's own output orders terms by hash values that depend
/// on the addresses of its type names (so on address randomization) and on the order in
/// which symbols were made: until a higher floor registers a canonical printer (the output
/// floor registers output::print_ex), messages print GiNaC's way.
using expression_printer = std::string (*)(const GiNaC::ex&);
void set_message_printer(expression_printer p);

/// log |a + i b|: exact as log(a^2 + b^2)/2, so that the logarithms of one
/// number combine (log(26)/2, never log(sqrt(26))); double through hypot, which
/// does not overflow.
GiNaC::ex log_modulus(const GiNaC::ex& a, const GiNaC::ex& b);
inline double log_modulus(double a, double b) { return std::log(std::hypot(a, b)); }

/// e^x, exact with the terms c log(y) of x taken out as y^c, so that exp(log w)
/// gives back rational coordinates (GiNaC leaves exp(log(2)/2) unevaluated);
/// std::exp on the double path.
GiNaC::ex exp_scalar(const GiNaC::ex& x);
inline double exp_scalar(double x) { return std::exp(x); }

/// The falling factorial k (k-1) ... (k-j+1) (1 for j = 0): the factor of the j-th derivative
/// of z^k, d^j/dz^j z^k = falling_factorial(k, j) z^(k-j).
inline long falling_factorial(long k, long j) {
    long r = 1;
    for (long i = 0; i < j; ++i) r *= (k - i);
    return r;
}

/// Scalar from an integer, for both paths.
template <class T> T from_int(long k) { return T(k); }
template <> inline GiNaC::ex from_int<GiNaC::ex>(long k) { return GiNaC::ex(GiNaC::numeric(k)); }

/// One over 2^n, exact or double.
template <class T> T inv_pow2(unsigned n) { return std::ldexp(1.0, -int(n)); }
template <> inline GiNaC::ex inv_pow2<GiNaC::ex>(unsigned n) {
    return GiNaC::ex(GiNaC::numeric(1) / GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(n)));
}

}  // namespace symrep
