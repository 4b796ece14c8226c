// symrep/lang/print_value.h -- the language's values as text and as LaTeX.
//
// Expressions and elements print through output/printer.h and output/formats.h;
// this adds the values only the language has: booleans, strings, lists,
// algebras and Cauchy problems.
#pragma once

#include <string>

#include "symrep/lang/value.h"

namespace symrep::lang {

/// Canonical text of any value. Strings are quoted (with \" and \\ escapes) when
/// `quote_strings`, as in the echo of an expression statement and inside lists;
/// print() shows top-level strings raw. `nothing` prints as the empty string.
std::string print_value(const value& v, bool quote_strings = true);
/// LaTeX of any value (elements: sum of coefficient times basis names; lists in brackets).
std::string latex_value(const value& v);

}  // namespace symrep::lang
