// symrep/lang/builtins_frames.cpp -- motion seen from a frame that rotates and translates
// ([CS21] Thms 11-12; mechanics/moving_frame.h, docs/rigid_body.md section 4).
//
//   P0 := ode(x'' = g, x(0) = x0, x'(0) = u0)     the problem in the frozen inertial frame
//   P := moving_frame(P0, w, o)                    seen from the frame (w, origin path o(t))
//   s := solve(P)                                   r = R (psi - o)
//   check(P, s)                                     exact;  verify(P, s, values, T): numeric
#include "symrep/lang/builtins_frames.h"
#include "symrep/lang/interpreter.h"
#include "symrep/lang/values.h"
#include "symrep/mechanics/moving_frame.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Vectors and mechanics";

ex frame_vector(const args_t& a, std::size_t i, const builtin& b, const char* what) {
    if (is_triple(a[i])) return as_literal(a[i]);
    const ex& e = arg_ex(a, i, b);
    if (!e.is_zero() && !is_vector(e))
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " (" + what + ") must be a vector, not " +
                         output::print_ex(e) + " (usage: " + b.signature + ")");
    return e;
}

value builtin_moving_frame(const builtin& b, const args_t& a, context&) {
    if (!a[0].is_problem())
        throw type_error(b.name + ": argument 1 must be the inertial problem made by ode(...), not " + a[0].a_kind() +
                         " (usage: " + b.signature + ")");
    const ex w = frame_vector(a, 1, b, "the frame's angular velocity w(t)");
    const ex o = a.size() > 2 ? frame_vector(a, 2, b, "the path o(t) of the frame's origin") : ex(0);
    try {
        return value(mechanics::moving_frame_problem(a[0].problem_pointer(), w, o));
    } catch (const domain_error& e) {
        const std::string m = e.what();
        throw domain_error(m.rfind("moving_frame", 0) == 0 ? m : b.name + ": " + m);
    }
}

}  // namespace

value check_moving_frame(const builtin& b, const mechanics::cauchy_problem& P, context& c) {
    zero_decision z;
    try {
        z = mechanics::prove_moving_frame(P, *mechanics::moving_frame_of(P));
    } catch (const domain_error& e) {
        throw domain_error(b.name + ": " + e.what());
    }
    if (z.is_zero == truth::unknown)
        throw domain_error(b.name + ": cannot decide whether the residual of " + P.name + " = R (psi - o) is R times "
                           "the inertial residual of psi (the zero test does not prove it, and no point was found "
                           "where it is not)");
    if (z.is_zero == truth::no) {
        c.out() << "check: the residual of " << P.name << " = R (psi - o) differs from R times the inertial "
                << "residual of psi " << witness_text(z) << "\n";
        return value(false);
    }
    c.out() << "check: exact for every psi: the residual of " << P.name << " = R (psi - o) is R times the inertial "
            << "residual of psi ([CS21] Thm 11), and the initial values are the inertial ones carried into the "
            << "frame; psi itself is the inertial problem's numeric solution\n";
    return value(true);
}

void register_frames_builtins(registry& r) {
    add_builtins(
        r, section,
        {
            {"moving_frame", "moving_frame(P, w, o)",
             "The problem P, stated in an inertial frame (ode(x'' = ..., x(0) = X0, x'(0) = V0): gravity, a charge "
             "in E and B, Kepler about the origin ...), seen from a frame that turns with the angular velocity w(t) "
             "(its components in the frame) and whose origin moves along o(t) (a path in the inertial frame, which "
             "is the frame frozen at t = 0; o may be left out: 0). The result is the problem in the frame, "
             "m (r'' + 2 w x r' + w' x r + w x (w x r) + A) = R F, A = R o'' the origin's acceleration seen in the "
             "frame, r(0) = X0 - o(0), r'(0) = V0 - o'(0) - w(0) x r(0); solve gives r = R (psi - o), psi the "
             "inertial solution and R' = -W R: in closed form for a constant w, a fixed direction and a regular "
             "precession when psi is (a reduction object, evaluated by eval and verify, for Kepler). check(P, s) "
             "proves it, verify(P, s, values, T) integrates the frame's equation.",
             "[CS21] Thms 11-12; (VI.3.117, VI.3.132)",
             "vector g, x0, u0\nP := moving_frame(ode(x'' = g, x(0) = x0, x'(0) = u0), [0, 0, 1], [t^2, 0, 0])\n"
             "s := solve(P)\ncheck(P, s)",
             2, 3, builtin_moving_frame},
        });
}

}  // namespace symrep::lang
