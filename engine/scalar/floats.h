// symrep/scalar/floats.h -- the one model of floats (docs/language.md, "Floats").
//
// A float literal (0.1, 1e-30) is the decimal read at the working precision
// D = `digits` (GiNaC::Digits, 17 at start): a binary float of CLN's format for
// D digits, which carries a few guard bits beyond D. A float of that format is
// worth its value rounded to D significant digits: it prints as that decimal
// (trailing zeros dropped, so 0.1*0.1 prints 0.01 and digits(40) prints at most
// 40 digits), and `==` compares that decimal exactly. A float of another format
// (evalf(e, n) with n != D, a float made before `digits` changed, a double from
// the numeric paths) is worth the shortest decimal that reads back to it at its
// own precision (CLN's printing): evalf(pi, 30) prints its 30 digits.
#pragma once

#include <string>

#include <ginac/ginac.h>

namespace symrep {

/// The real float x rounded to `digits` significant decimal digits and read back at that
/// precision (CLN prints it as the decimal of at most `digits` digits); rationals and 0 unchanged.
GiNaC::numeric round_float_digits(const GiNaC::numeric& x, long digits);

/// The text of the real float x (model above): at the working precision its D-digit decimal,
/// trailing zeros dropped, written as CLN writes floats (fixed for 0.001 <= |x| < 10^7: 0.01,
/// 100.0; otherwise 1.25E-7, 1.1805916207174113E21); another format: CLN's own text.
std::string float_text(const GiNaC::numeric& x);

/// The exact rational (or complex rational) value of the decimal x prints as: 0.1 -> 1/10,
/// 0.1*0.1 -> 1/100 at the working precision, 1e300 -> 10^300. Rationals unchanged.
GiNaC::numeric float_decimal(const GiNaC::numeric& x);

/// e with every float replaced by float_decimal of it (the exact values `==` compares).
GiNaC::ex floats_as_decimals(const GiNaC::ex& e);

/// True when e holds a float (a numeric that is not rational, or whose real or imaginary part is not).
bool has_float(const GiNaC::ex& e);

}  // namespace symrep
