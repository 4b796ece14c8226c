// symrep/output/precedence.h -- the precedence levels of printed text, one scale for every
// printer of the output floor (the canonical printer, printer.cpp, and the LaTeX, C, Python and
// JSON formats, formats.cpp): a child whose level is below what its parent needs is put in
// parentheses.
#pragma once

#include <string>

namespace symrep::output {

enum level { l_relation = 0, l_sum = 1, l_product = 2, l_power = 3, l_atom = 4 };

/// A piece of printed text and the precedence level of its outermost operation.
struct printed {
    std::string text;
    int lvl;
};

}  // namespace symrep::output
