// symrep/lang/builtins_frames.h -- the builtins of frames that rotate and translate
// (builtins_frames.cpp; mechanics/moving_frame.h, [CS21] Thms 11-12).
#pragma once

#include "symrep/lang/builtins.h"

namespace symrep::lang {

/// check(P, s) of a problem seen from a moving frame whose solution is a reduction object (psi
/// numeric): [CS21] Thm 11 proved for this problem and an arbitrary psi (prove_moving_frame).
value check_moving_frame(const builtin& b, const mechanics::cauchy_problem& P, context& c);

}  // namespace symrep::lang
