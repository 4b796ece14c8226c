// symrep/vector/vector_internal.h -- helpers shared by the vector sources
// (not part of the public API).
#pragma once

#include <string>
#include <utility>
#include <ginac/ginac.h>

#include "symrep/vector/vector.h"

namespace symrep::detail {

std::string name_of(const GiNaC::ex& sym);
bool is_cross(const GiNaC::ex& e);
bool is_dot(const GiNaC::ex& e);
bool is_triple(const GiNaC::ex& e);
/// 1 for a vector, 0 for a scalar; throws type_error on an ill-formed expression.
int kind(const GiNaC::ex& e);
/// A vector symbol or a vector literal.
bool is_atom(const GiNaC::ex& e);
/// v = s * rest with s scalar and rest the vector factor.
std::pair<GiNaC::ex, GiNaC::ex> split_scalar(const GiNaC::ex& v);
GiNaC::ex comp(const GiNaC::ex& lit, unsigned i);

}  // namespace symrep::detail
