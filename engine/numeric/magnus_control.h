// symrep/numeric/magnus_control.h -- the step control of the sixth-order Magnus integrators on
// a matrix Lie group, shared by rotation_tensor (SO(3), rotation_tensor.h) and se3_tensor
// (SE(3), se3.h): Q' = -Omega(t) Q, Q(0) = I, at sorted times.
//
// Each step multiplies Q by the exponential of one Magnus twist, so Q stays in the group to
// rounding whatever the step. The local error is estimated by comparing one step E1 with two
// half steps E2 (Richardson: E2 is off by about |E1 - E2| / (2^6 - 1)) in the group's norm, and
// kept below rel_tol per unit time over [0, max(t_end, 1)]. The estimate is trusted only while
// |E1 - E2| stands above rounding (8 ulps): below that the step is kept as it is (an estimate
// made of rounding noise would move it at random). The first step, 0.1/|Omega(0)| (or t_end/16),
// is long enough for a reliable estimate, from which err ~ C h^7 gives the step for the
// tolerance. The steps tile [0, t] exactly (each is the difference of two representable times).
//
// A Group provides
//   using element = ...;                      the group element (a 3x3 matrix, a rigid motion)
//   element step(double t, double h);         exp of the Magnus twist over [t, t + h]
//   double distance(const element& one, const element& two, const element& Q);   |E1 - E2|
//   void advance(element& Q, const element& E);   Q <- E Q, then back onto the group
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/core/progress.h"

namespace symrep::num {

/// What the messages and the bounds of one integrator are.
struct magnus_control {
    const char* who;        ///< "rotation_tensor": the beginning of each message
    const char* field;      ///< "the angular velocity": what may be not smooth
    const char* thing;      ///< "w(t)": "a very long time for this w(t), or a w(t) that is not smooth"
    const char* progress;   ///< the progress task's name
    double rel_tol;         ///< global relative tolerance (per unit time: rel_tol / max(t_end, 1))
    double max_step;        ///< 0: no bound besides the span
    std::size_t max_steps;  ///< error beyond this many accepted steps
};

/// Q at each of `times` (sorted, finite, >= 0, checked by the caller), from Q(0) = Q0; `rate0` is
/// |Omega(0)| (the first step), `steps` counts the accepted steps.
template <class Group>
std::vector<typename Group::element> magnus_integrate(Group& group, typename Group::element Q,
                                                      const std::vector<double>& times, double rate0,
                                                      const magnus_control& c, std::size_t& steps) {
    std::vector<typename Group::element> out;
    out.reserve(times.size());
    if (times.empty()) return out;
    const double span = std::max(times.back(), 1.0);
    const double tol = c.rel_tol / span;  // per unit time: the global error stays near rel_tol
    double t = 0.0;
    double h = std::min(0.1 / std::max(rate0, 1e-300), std::max(times.back(), 1e-300) / 16.0);
    if (c.max_step > 0) h = std::min(h, c.max_step);
    const double noise = 8 * std::numeric_limits<double>::epsilon();
    progress_task task(c.progress, times.back());
    for (const double target : times) {
        while (t < target) {
            check_interrupt();
            const bool last = h >= target - t;
            const double t_next = last ? target : t + h;  // the steps tile [0, t] exactly
            const double step = t_next - t;
            const typename Group::element E1 = group.step(t, step);
            const typename Group::element E2 = group.step(t + step / 2, step / 2) * group.step(t, step / 2);
            const double diff = group.distance(E1, E2, Q);
            const double err = diff / 63.0;  // Richardson: the half steps are off by about |E1 - E2| / (2^6 - 1)
            const double allowed = tol * step;
            const bool reliable = diff > noise;
            if (!reliable || err <= allowed) {
                group.advance(Q, E2);
                t = t_next;
                task.report(t);
                if (++steps > c.max_steps)
                    throw error(std::string(c.who) + ": more than " + std::to_string(c.max_steps) +
                                " steps to reach t = " + std::to_string(target) + " (a very long time for this " +
                                c.thing + ", or a " + c.thing + " that is not smooth)");
            } else if (step <= 1e-10 * std::max(1.0, t)) {
                throw error(std::string(c.who) + ": " + c.field + " is not smooth near t = " + std::to_string(t) +
                            " (the step fell below 1e-10 of t)");
            }
            if (reliable) {
                const double next = step * std::clamp(0.9 * std::pow(allowed / err, 1.0 / 6.0), 0.2, 4.0);
                if (!last || err > allowed) h = next;
            }
            if (c.max_step > 0) h = std::min(h, c.max_step);
        }
        out.push_back(Q);
    }
    task.finish();
    return out;
}

}  // namespace symrep::num
