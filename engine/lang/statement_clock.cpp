// symrep/lang/statement_clock.cpp -- the statement clock and error translation (see statement_clock.h).
#include "symrep/lang/statement_clock.h"

#include <new>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"

namespace symrep::lang {
extern const char* const out_of_memory_message;
const char* const out_of_memory_message =
    "out of memory: the result is too large for this machine (the statement was abandoned)";

std::string clear_message(const std::string& m) {
    struct known {
        const char* raw;
        const char* clear;
    };
    static const known table[] = {
        {"pow(0,0) is undefined", "0^0 is undefined"},
        {"singular matrix", "the matrix is singular"},
        {"numeric::factorial(): argument must be integer >= 0",
         "factorial: the argument must be an integer >= 0"},
        {"log(0)", "log(0) is undefined"},
        {"floating point overflow", "floating-point overflow (a number too large for floating point)"},
        {"floating point underflow", "floating-point underflow (a number too small for floating point)"},
        {"division by zero", "division by zero"},
        {"sum of non-commutative objects has non-zero numeric term",
         "a matrix cannot be added to a number here (use a multiple of the identity matrix)"},
        {"Not a 32-bit integer", "a number is too large here (it must fit in 32 bits)"},
        {"Not a 64-bit integer", "a number is too large here (it must fit in 64 bits)"},
    };
    for (const known& k : table)
        if (m.find(k.raw) != std::string::npos) return k.clear;
    // tan_eval(): simple pole, tanh_eval(): ..., the poles GiNaC finds while evaluating
    const std::size_t pole = m.find("_eval(): simple pole");
    if (pole != std::string::npos && pole > 0 && m.find_first_of(" :") > pole)
        return m.substr(0, pole) + ": the argument is a pole (the value is infinite)";
    return m;
}

statement_clock::statement_clock(double limit, std::chrono::steady_clock::time_point& start)
    : previous_(deadline_ticks().load()) {
    ++interruptible_allocations();  // core/allocation_interrupt.cpp may stop GiNaC calls from here on
    start = std::chrono::steady_clock::now();
    if (limit > 0)
        deadline_ticks().store((start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                            std::chrono::duration<double>(limit)))
                                   .time_since_epoch()
                                   .count());
}

statement_clock::~statement_clock() {
    deadline_ticks().store(previous_);
    --interruptible_allocations();
}

std::string message_of(const std::exception& e) {
    if (dynamic_cast<const symrep::error*>(&e)) return e.what();
    if (const auto* b = dynamic_cast<const std::bad_alloc*>(&e))
        return allocation_failure_message(*b, out_of_memory_message);
    return clear_message(e.what());
}

}  // namespace symrep::lang
