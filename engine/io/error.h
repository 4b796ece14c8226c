// symrep/io/error.h -- the typed exceptions of the engine.
//
// Every failure the user can cause (bad input, a zero divisor where an inverse
// is asked for, a size that does not fit in memory, ...) is reported by throwing
// one of these types. The message is complete and user-facing: the REPL and the
// script runner print it verbatim after "FILE:LINE:COL: error: ". Library users
// catch symrep::error (or a subclass) and get the same text from what().
#pragma once

#include <atomic>
#include <new>
#include <chrono>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace symrep {

/// Base of every exception thrown by symrep on bad input or impossible requests.
class error : public std::runtime_error {
public:
    explicit error(const std::string& msg) : std::runtime_error(msg) {}
};

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
/// check_interrupt()): thrown by operator new (io/allocation_interrupt.cpp, which
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
/// io/interpreter.cpp): only then does operator new throw allocation_interrupted,
/// so that code outside a statement (the REPL's own work, a library user's) never
/// sees it. Per thread, as GiNaC's computations are.
inline int& interruptible_allocations() {
    thread_local int depth = 0;
    return depth;
}

/// How many times operator new (io/allocation_interrupt.cpp) has thrown
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

/// A position in a script: 1-based line and column.
struct source_location {
    std::string file;
    int line = 0;
    int column = 0;
};

/// Malformed script text (lexer/parser). Carries where it happened.
class syntax_error : public error {
public:
    syntax_error(const std::string& msg, source_location loc) : error(msg), where(std::move(loc)) {}
    source_location where;
};

/// Wrong argument count or type in a call, unknown name, and the like.
class type_error : public error {
public:
    using error::error;
};

/// An algebra that is not what was claimed (non-commutative table, wrong
/// dimension, elements of different algebras combined, ...).
class algebra_error : public error {
public:
    using error::error;
};

/// Inverse or logarithm of a zero divisor. `ranks` lists the vanishing
/// idempotent components (III.1.55, III.3.31), empty where the algebra has no
/// idempotent basis (the message then says why the element is a zero divisor).
class zero_divisor_error : public algebra_error {
public:
    zero_divisor_error(const std::string& msg, std::vector<std::size_t> r)
        : algebra_error(msg), ranks(std::move(r)) {}
    std::vector<std::size_t> ranks;
};

/// A value outside the domain of an operation (log in W of an element with a
/// non-positive root, a negative size, ...).
class domain_error : public error {
public:
    using error::error;
};

/// A request larger than this machine can hold; the message gives the limit.
class size_error : public error {
public:
    using error::error;
};

/// No closed form can be derived by the methods implemented (e.g. an
/// irreducible factor of degree > 2 in a minimal polynomial, whose roots have
/// no closed form in radicals that we could use).
class closed_form_error : public error {
public:
    using error::error;
};

}  // namespace symrep
