// symrep/scalar/equality.h -- the three-valued decision "is this scalar 0?".
//
// The exact zero test (is_zero_scalar, scalar.h) proves identities; when it
// does not, the difference may still be 0 (an identity it does not know) or
// not. decide_zero() says which it can show:
//   - yes:     proved 0 by the exact zero test;
//   - no:      a witness: a point (values for the symbols, chosen by a fixed
//              pseudo-random sequence seeded by the expression, respecting
//              declared positivity) where the value, evaluated at 40 and at 80
//              digits, is the same nonzero number to 20 digits and larger than
//              10^-25 in size: an expression that is nonzero at a point is not
//              identically 0;
//   A number (no symbols: a rational or a float, of any size) is decided at once: no
//   when it is not 0 (1/10^30 is not 0).
//   - unknown: neither. The language reports this as undecided, never as
//              "different" (docs/language.md, "Equality").
// An evaluation that is not numeric, or that fails (a pole, log(0)), is no
// witness; the point is skipped.
#pragma once

#include <string>

#include <ginac/ginac.h>

namespace symrep {

enum class truth { yes, no, unknown };

struct zero_decision {
    truth is_zero = truth::unknown;
    GiNaC::exmap point;  ///< for `no`: the witness point (symbol -> value; empty without symbols)
    GiNaC::ex value;     ///< for `no`: the value there (a float)
};

/// x evaluated with `digits` decimal digits (GiNaC::Digits restored); false when that is not
/// a number or the evaluation fails (a pole, log(0)).
bool evaluate_numeric(const GiNaC::ex& x, long digits, GiNaC::numeric& out);

/// (three-valued zero test) Decides whether x is identically 0.
zero_decision decide_zero(const GiNaC::ex& x);

/// True when x is proved identically 0 (the exact zero test, else decide_zero's yes); false
/// means "not proved", never "nonzero".
bool proved_zero(const GiNaC::ex& x);

/// The point of a decision as text: "at x = 3/2, y = -1/3" ("" without symbols).
std::string witness_text(const zero_decision& d);

/// For a decision that divides by x, takes it as a pivot or counts it as an
/// independent direction: false when x is proved 0; true when x is a nonzero
/// number or a constant seen nonzero (a witness), or when x has symbols and is
/// not proved 0 (the generic reading of the algebra and solver layers, valid for
/// all but special values of the symbols). A constant neither proved 0 nor seen
/// nonzero (an identity among radicals or cosines the zero test does not know)
/// throws domain_error "cannot decide whether ... is 0" naming `what`: taking it
/// as nonzero could give a wrong answer.
bool is_nonzero_generic(const GiNaC::ex& x, const std::string& what);

/// A quick look before an exact zero test, for the solver's inner loops: the value of
/// x at one point (every symbol a positive rational in [1.1, 2.9] fixed by its name:
/// the same point for every expression, consistent with the positivity GiNaC's
/// simplifications assume) at 20 and at 40 digits. `ok` is false where that is not
/// a number (a pole, an unevaluated function).
struct point_value {
    bool ok = false;
    GiNaC::numeric low, high;  ///< at 20 and at 40 digits
};
point_value value_at_generic_point(const GiNaC::ex& x);
/// That point for the symbols of x (all but `except`, a variable such as t, when given): each
/// symbol at (1100 + h mod 1800)/1000, h the 64-bit FNV-1a hash of its name.
GiNaC::exmap generic_point(const GiNaC::ex& x, const GiNaC::ex& except = GiNaC::ex());

/// True when a - b is seen nonzero at the point: at 40 digits larger than 10^-12
/// and the same to 10 digits at 20 digits. An identity a = b (anything the exact
/// zero test proves, radicals taken on any branch) evaluates to rounding noise
/// there, so a true never contradicts a proof; false says nothing (test exactly).
bool seen_different(const point_value& a, const point_value& b);

}  // namespace symrep
