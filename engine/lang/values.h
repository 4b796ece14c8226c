// symrep/lang/values.h -- numeric values for symbols, shared by eval, verify and the plots.
//
//   [w = [0, 0, 1], phi = 0.85, w0 = sqrt(9.81/67), ...]
//
// read_values() reads such a list (vectors as [x, y, z], scalars as expressions; a
// value may use the others); put_values_limit() puts them into an expression
// (vectors by components, giving a 3x1 matrix for a vector expression) and takes
// the exact limit where the values make a closed form divide by zero (w = 0 in
// sin(|w| t)/|w|, a double root, a resonance; scalar/limit.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/lang/builtins.h"

namespace symrep::lang {

using vmap = std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>;

struct data_values {
    vmap vectors;            ///< vector symbol -> [x, y, z]
    GiNaC::exmap scalars;    ///< scalar symbol -> value
};

/// Reads argument `argno` (0-based, for messages) of builtin b: a relation name = value or a list of them.
data_values read_values(const value& v, const builtin& b, std::size_t argno);
/// e with every value put in: vectors by components, then scalars (a 3x1 matrix for a vector e).
GiNaC::ex put_values(const GiNaC::ex& e, const data_values& d);
/// d with every floating-point number in its values replaced by the exact
/// rational of the decimal it prints as (scalar/floats.h: 0.7 -> 7/10; for evaluation:
/// GiNaC would otherwise round at once, e.g. 1 - cos(1e-12) to 0 at 20 digits, when the
/// values are put in).
data_values exact_values(data_values d);
/// put_values, or where that divides by zero, the limit as the values approach those given
/// (scalar/limit.h), the value of the symbol `held` (eval's time) staying as given;
/// domain_error beginning with singular_values_message, naming the denominator that
/// vanishes and why, where that limit is not established.
GiNaC::ex put_values_limit(const GiNaC::ex& e, const data_values& d, const GiNaC::ex& held = 0);
/// The beginning of put_values_limit's refusals.
inline constexpr const char* singular_values_message = "the closed form is singular at these values";
/// A denominator of e (the base of a negative power) that the values make 0, printed;
/// "" when none is found. For the messages at a singular point.
std::string vanishing_denominator(const GiNaC::ex& e, const data_values& d);
/// The entries of a matrix (row by row), or {c} for a scalar.
std::vector<GiNaC::ex> components(const GiNaC::ex& c);
/// evalf(x) as a double; type_error naming b and `what` when x is not a real number.
double to_double(const GiNaC::ex& x, const builtin& b, const std::string& what);

/// A Cauchy problem of order M with its values put in, as the first-order
/// system y' = F(t, y) that verify() integrates: the state is x, x', ...,
/// x^(M-1) by components (symbols y0, y1, ...), F is (x', ..., x^(M-1),
/// x^(M) solved from the equation), the initial state comes from the
/// problem's own initial values.
struct first_order_system {
    std::vector<GiNaC::ex> state;    ///< the state symbols
    std::vector<GiNaC::ex> rhs;      ///< their derivatives, in t, the state and no other symbol left by d
    std::vector<double> initial;     ///< the state at t = 0
};
/// Builds it; domain_error (naming b) when the equation cannot be solved for
/// the highest derivative at these values, type_error when a value is missing.
first_order_system first_order(const mechanics::cauchy_problem& P, const data_values& d, const builtin& b);

}  // namespace symrep::lang
