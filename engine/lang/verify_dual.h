// symrep/lang/verify_dual.h -- verify(P, s, values, T, ...) for a problem in the dual unit eps
// (the dual Poisson-Darboux problem, mechanics/dual_darboux.h; issue 31 item 3).
//
// x^ = x + eps y: the closed form's (or the numeric solution's) two parts (six components: x, y, z of the primal part,
// then of the dual part) against a Boost.Odeint integration of P itself, read as the real
// system of its two parts: E(x^, x^') reduced modulo eps^2, both parts 0, solved for x' and y'.
#pragma once

#include <ginac/ginac.h>

#include "symrep/lang/builtins.h"
#include "symrep/lang/values.h"
#include "symrep/mechanics/cauchy_problem.h"
#include "symrep/numeric/integrate.h"
#include "symrep/numeric/verify.h"

namespace symrep::lang {

/// The comparison; prints a line as verify does and returns the largest relative difference.
value verify_dual(const mechanics::cauchy_problem& P, const GiNaC::ex& s, const data_values& d, double T, std::size_t n,
                  const num::integration_options& opt, const builtin& b, context& c);

/// The same for a numeric solution (a twist without a closed form: Magnus on SE(3),
/// mechanics::dual_darboux_states): `s` gives the six components at the sample times.
value verify_dual(const mechanics::cauchy_problem& P, const num::sampled_function& s, const data_values& d, double T,
                  std::size_t n, const num::integration_options& opt, const builtin& b, context& c);

}  // namespace symrep::lang
