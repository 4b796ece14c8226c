// symrep/output/formats.h -- output formats other than the canonical text:
// LaTeX, C code, Python/NumPy code and JSON string literals (formats.cpp).
//
// LaTeX sums follow the canonical term order of the printer (canonical_terms);
// products sort their factors by their LaTeX text, vectors last; so the output
// does not depend on GiNaC's internal (creation-order) ordering.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "symrep/algebra/element.h"

namespace symrep::output {

/// LaTeX of an expression: sums in the canonical term order, products with their
/// factors sorted, vectors bold (\boldsymbol{r}_0), cross/dot as \times/\cdot,
/// norms \|w\|, matrices as pmatrix.
std::string latex_ex(const GiNaC::ex& e);
/// LaTeX of an element: the sum of coefficient times basis names.
std::string latex_element(const element& w);
/// C code (double arithmetic, <math.h>) of a scalar expression; throws type_error
/// for expressions with abstract vectors (naming them).
std::string c_code(const GiNaC::ex& e);
/// Python code (NumPy functions as numpy.sin, ...) of a scalar expression.
std::string python_code(const GiNaC::ex& e);
/// A JSON string literal ("..." with \" \\ \n \uXXXX escapes).
std::string json_quote(const std::string& s);

}  // namespace symrep::output
