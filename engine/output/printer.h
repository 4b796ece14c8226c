// symrep/output/printer.h -- the canonical, deterministic printer.
//
// The output folder turns results into text: the canonical printer here, the
// other formats (LaTeX, C, Python, JSON strings: formats.h) and gnuplot plots
// (plot.h). It prints expressions and algebra elements; the language's values
// are printed by lang/print_value.h on top of it. It includes core, scalar,
// algebra and vector (docs/architecture.md).
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

#include "symrep/algebra/element.h"

namespace symrep::output {

/// Canonical text of an expression.
std::string print_ex(const GiNaC::ex& e);
/// Canonical text of an element: "2 + 3*i0 - i0*i1" (basis name "1" is omitted).
std::string print_element(const element& w);
/// A string literal as the language writes it: "..." with \" \\ \n \t escapes.
std::string quote_string(const std::string& s);
/// True when e holds an abstract vector (printed in the notation of vector/vector.h).
bool involves_vectors(const GiNaC::ex& e);

/// The terms of a sum in the order print_ex shows them ({e} for a non-sum).
std::vector<GiNaC::ex> canonical_terms(const GiNaC::ex& e);
/// A term as its numeric coefficient c and its other factors, every sum factor
/// with its leading term positive (the sign moved into c), as print_ex shows it.
void split_coefficient(const GiNaC::ex& term, GiNaC::numeric& c, std::vector<GiNaC::ex>& rest);

}  // namespace symrep::output
