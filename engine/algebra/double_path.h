// symrep/algebra/double_path.h -- which operands of an exact algebra take its
// double-precision path (multicomplex_d, walsh_d, walsh_complex_d).
//
// Operands take the double path when every coordinate is a real number and one
// of them is a float (1.5, not 3/2: floats say the user computes in floats), or,
// in a float-only algebra (an order above the exact limit, below the double
// path's), when every coordinate is a number. Symbolic coordinates in a
// float-only algebra are refused with a size_error naming the exact limit.
// Results of the double path come back as float coordinates (0 stays exact 0).
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "symrep/algebra/algebra.h"

namespace symrep::double_path {

/// True when `operands` take the double path (above); `exact` says whether the
/// algebra named `algebra_name` has exact coordinates at its order,
/// `max_exact` is its exact limit (for the message), `what` the operation.
bool takes(std::initializer_list<const coeffs*> operands, bool exact, const std::string& algebra_name,
           unsigned max_exact, const char* what);

/// Throws size_error: `what` needs exact coordinates, and `algebra_name` is float-only.
[[noreturn]] void refuse_exact(const std::string& algebra_name, unsigned max_exact, const char* what);

/// x is a real number (exact or float).
bool is_real_number(const GiNaC::ex& x);

/// The coordinates (all real numbers) as doubles.
std::vector<double> to_doubles(const coeffs& c);
/// Doubles as float coordinates (0 as the exact 0).
coeffs from_doubles(const std::vector<double>& v);

}  // namespace symrep::double_path
