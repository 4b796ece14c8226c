// symrep/core/interrupt.h -- interruption and the statement deadline.
//
// Long computations stop cleanly when the user presses Ctrl-C or a statement
// runs past its time limit: the engine's own loops call check_interrupt(), and
// inside library calls (GiNaC's expand, normal, factor) the operator new of
// core/allocation_interrupt.cpp throws allocation_interrupted. Both report
// through symrep::error texts ("interrupted", "time limit: ...").
#pragma once

#include <atomic>
#include <chrono>
#include <new>

#include "symrep/core/error.h"

namespace symrep {

/// The interruption request (Ctrl-C at the interactive prompt sets it from a
/// signal handler). Long loops of the engine call check_interrupt(); the
/// language evaluator checks it at every syntax node. Whoever sets it clears
/// it before running new work.
inline std::atomic<bool>& interrupt_flag() {
    static std::atomic<bool> flag{false};
    return flag;
}
/// The time limit of the running statement: steady_clock ticks since its epoch
/// (0: none). The language session sets it per statement (--time-limit).
inline std::atomic<long long>& deadline_ticks() {
    static std::atomic<long long> ticks{0};
    return ticks;
}
/// Throws symrep::error("interrupted") while an interruption is requested, and
/// symrep::error("time limit ...") once the statement's deadline has passed.
inline void check_interrupt() {
    if (interrupt_flag().load(std::memory_order_relaxed)) throw error("interrupted");
    const long long d = deadline_ticks().load(std::memory_order_relaxed);
    if (d != 0 && std::chrono::steady_clock::now().time_since_epoch().count() > d)
        throw error("time limit: the statement ran longer than its time limit (--time-limit)");
}

/// The interruption of a computation inside a library call (GiNaC's normal(),
/// expand(), factor(), ... run to their end once made, and see no
/// check_interrupt()): thrown by operator new (core/allocation_interrupt.cpp, which
/// programs link to get it) once an interruption is requested or the deadline
/// has passed. A std::bad_alloc, so that every allocation site lets it through;
/// what() is the message ("interrupted" or "time limit: ..."). The language
/// reports it as that message, never as "out of memory".
class allocation_interrupted : public std::bad_alloc {
public:
    explicit allocation_interrupted(const char* message) noexcept : message_(message) {}
    const char* what() const noexcept override { return message_; }

private:
    const char* message_;  // a string literal: throwing allocates nothing
};

/// Nonzero while the language evaluates a statement (the statement clock of
/// lang/statement_clock.cpp): only then does operator new throw allocation_interrupted,
/// so that code outside a statement (the REPL's own work, a library user's) never
/// sees it. Per thread, as GiNaC's computations are.
inline int& interruptible_allocations() {
    thread_local int depth = 0;
    return depth;
}

/// How many times operator new (core/allocation_interrupt.cpp) has thrown
/// allocation_interrupted in this process. GiNaC is not exception safe
/// everywhere: an interruption may leave a few of its objects unreachable (the
/// robustness test reads this to tell those leaks from others).
inline std::atomic<long>& allocation_interruptions() {
    static std::atomic<long> n{0};
    return n;
}

/// The message of an allocation failure: the interruption's, or out_of_memory.
inline const char* allocation_failure_message(const std::bad_alloc& e, const char* out_of_memory) {
    return dynamic_cast<const allocation_interrupted*>(&e) ? e.what() : out_of_memory;
}

}  // namespace symrep
