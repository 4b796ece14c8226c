// symrep/io/printer.h -- the canonical, deterministic printer.
//
// GiNaC orders the terms of sums and the factors of products by hash values
// that depend on the order in which symbols were created, so its own output can
// differ between runs of the same script. This printer walks the expression and
// sorts terms and factors by a key that depends only on the mathematics:
//   * sums: total degree descending, then the printed text of the monomial
//     (Order(...) terms of series last); negative terms are shown as `a - b`;
//   * products: the numeric coefficient first, then factors sorted by their
//     printed base and exponent; negative powers become a denominator (`x/(2*y)`);
//   * exact rationals stay exact (`3/4`), floats use GiNaC's decimal form,
//     complex numbers are `a + b*I`; power 1/2 is `sqrt(x)`;
//   * matrices print as `matrix([[a, b], [c, d]])`, relations as `a = b`.
// Elements print as sum_k c_k*basis_name(k), zero coordinates skipped.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "io/value.h"

namespace symrep::lang {

/// Canonical text of an expression.
std::string print_ex(const GiNaC::ex& e);
/// Canonical text of an element: "2 + 3*i0 - i0*i1" (basis name "1" is omitted).
std::string print_element(const element& w);
/// Canonical text of any value. Strings are quoted (with \" and \\ escapes) when
/// `quote_strings`, as in the echo of an expression statement and inside lists;
/// print() shows top-level strings raw. `nothing` prints as the empty string.
std::string print_value(const value& v, bool quote_strings = true);

/// The terms of a sum in the order print_ex shows them ({e} for a non-sum).
std::vector<GiNaC::ex> canonical_terms(const GiNaC::ex& e);
/// A term as its numeric coefficient c and its other factors, every sum factor
/// with its leading term positive (the sign moved into c), as print_ex shows it.
void split_coefficient(const GiNaC::ex& term, GiNaC::numeric& c, std::vector<GiNaC::ex>& rest);

// --- other output formats (engine/io/output.cpp) ------------------------------
/// LaTeX of an expression: sums in the canonical term order, products with their
/// factors sorted, vectors bold (\boldsymbol{r}_0), cross/dot as \times/\cdot,
/// norms \|w\|, matrices as pmatrix.
std::string latex_ex(const GiNaC::ex& e);
/// LaTeX of any value (elements: sum of coefficient times basis names; lists in brackets).
std::string latex_value(const value& v);
/// C code (double arithmetic, <math.h>) of a scalar expression; throws type_error
/// for expressions with abstract vectors (naming them).
std::string c_code(const GiNaC::ex& e);
/// Python code (NumPy functions as numpy.sin, ...) of a scalar expression.
std::string python_code(const GiNaC::ex& e);
/// A JSON string literal ("..." with \" \\ \n \uXXXX escapes).
std::string json_quote(const std::string& s);

}  // namespace symrep::lang
