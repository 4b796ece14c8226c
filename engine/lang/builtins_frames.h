// symrep/lang/builtins_frames.h -- the builtins of frames that rotate and translate
// (builtins_frames.cpp; mechanics/moving_frame.h, [CS21] Thms 11-12).
#pragma once

#include "symrep/lang/builtins.h"
#include "symrep/lang/values.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/numeric/integrate.h"
#include "symrep/numeric/verify.h"

namespace symrep::lang {

/// check(P, s) of a problem seen from a moving frame whose solution is a reduction object (psi
/// numeric): [CS21] Thm 11 proved for this problem and an arbitrary psi (prove_moving_frame).
value check_moving_frame(const builtin& b, const mechanics::cauchy_problem& P, context& c);

/// verify(P, s, values, T, ...) of a problem seen from a turning frame that carries vectors
/// (moving_frame_form::carried: R(t) has no closed form): r and r' of the reduction object against
/// Boost.Odeint on the frame's equation with R' = -W R, R(0) = I integrated beside it (its carried
/// R V are R times V): 15 equations, independent of Magnus and of psi's closed form.
value verify_carried_frame(const builtin& b, const mechanics::cauchy_problem& P, const mechanics::moving_frame_form& F,
                           const num::sampled_function& solution, const data_values& d, double T, std::size_t n,
                           const num::integration_options& opt, context& c);

}  // namespace symrep::lang
