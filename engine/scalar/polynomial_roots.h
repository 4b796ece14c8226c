// symrep/scalar/polynomial_roots.h -- the roots of a polynomial in radicals, from its
// factorization over the rationals: the one home of the quadratic formula and of Cardano's
// form of a cubic's roots (algebra/functions.cpp, signals/representation.cpp and
// mechanics/operator_ode.cpp use it).
//
// A polynomial q in X with exact coefficients (numbers, symbols, constants such as pi,
// radicals, function values such as log(2): the non-rational atoms go through factor() as
// temporary symbols) is factored over Q(atoms). An irreducible factor of degree
//   1 gives its root,
//   2 a real pair a +- s or a complex pair a +- i b (the quadratic formula),
//   3 Cardano's form (one real root and a pair, or three real roots as cosines),
// and a factor of degree >= 4 (which has no closed form usable here; Ferrari's quartic
// formula is not used) is refused with closed_form_error naming its degree.
//
// The square root of a pair is sign-free: sqrt(4 b^2) = 2 b for a real symbol b, whatever the
// sign of b (the pair a +- b, or a +- i b, is the same set of roots for either sign), so that
// the closed forms of exp, cos and sin of the roots carry b, not sqrt(b^2). Of the two signs
// the one positive at a fixed generic point is taken (deterministic output).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

namespace symrep {

/// Sign of an exact real expression: +1, -1, 0, or 2 when undecided. Constants are decided
/// numerically (evalf); with free symbols, an expression known >= 0 (a^2 for a real symbol a)
/// and not 0 is read as positive (the generic reading of the algebra layer).
int sign_generic(const GiNaC::ex& x);

/// True when e contains a power with a non-integer numeric exponent (a radical: sqrt(2), u^(1/3)).
bool has_radical(const GiNaC::ex& e);

/// e with its non-rational atoms (functions such as log(2), constants such as pi, non-integer
/// powers such as sqrt(2)) replaced by temporary symbols (recorded in `back`, reused through
/// `seen`), so that e is a polynomial over Q(symbols) that GiNaC's factor() understands.
GiNaC::ex atomize(const GiNaC::ex& e, std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& seen, GiNaC::exmap& back);
/// f (a product, as factor() returns it) as its factors with multiplicities.
std::vector<std::pair<GiNaC::ex, unsigned>> factors_of(const GiNaC::ex& f);

/// The irreducible factors of q over Q(atoms) that contain X, each monic in X, with their
/// multiplicities (constant content dropped). The order is that of GiNaC's factor().
struct polynomial_factor {
    GiNaC::ex f;
    unsigned multiplicity;
};
std::vector<polynomial_factor> rational_factors(const GiNaC::ex& q, const GiNaC::symbol& X);

/// sqrt(x) with the square factors of x taken out without their sign (see above): exact on
/// numbers (sqrt(-4) = 2 I, sqrt(8) = 2 sqrt(2)) and on squares of polynomials.
GiNaC::ex sign_free_sqrt(const GiNaC::ex& x);

/// The sign of a quadratic's discriminant: sign_generic, and where that is undecided the generic
/// reading of a square: disc = -(a square of an expression free of radicals and of I), such as
/// -4 (w0 - W)^2, is negative, disc = such a square positive (the square's base read non-zero);
/// 2 when still undecided.
int discriminant_sign(const GiNaC::ex& disc);

/// A root re + i im (im == 0: real); a complex pair re +- i im is stored once.
struct polynomial_root {
    GiNaC::ex re, im;
    unsigned multiplicity;
    GiNaC::ex factor;  ///< the irreducible factor it is a root of (monic)
};

/// The roots of a monic irreducible factor f of degree 1, 2 or 3 (quadratic formula, Cardano),
/// each with multiplicity m (a quadratic with discriminant 0 gives one root of multiplicity 2 m).
/// closed_form_error, naming `where`, for a degree >= 4 or for a discriminant whose sign cannot
/// be decided (then neither form can be chosen). With `undecided_as_pair`, a quadratic whose
/// discriminant has an undecided sign gives the pair a +- i sqrt(-disc)/2 (the callers whose
/// results are even in the root and analytic in disc, so that the form holds for either sign:
/// cos(i x) = cosh(x); only the double root disc = 0 is excluded).
std::vector<polynomial_root> factor_roots(const GiNaC::ex& f, const GiNaC::symbol& X, unsigned m,
                                          const std::string& where, bool undecided_as_pair = false);

/// Every root of q: factor_roots of each rational factor. closed_form_error as there.
std::vector<polynomial_root> roots_in_radicals(const GiNaC::ex& q, const GiNaC::symbol& X, const std::string& where);

}  // namespace symrep
