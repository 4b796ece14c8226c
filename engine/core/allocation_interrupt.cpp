// symrep/core/allocation_interrupt.cpp -- operator new that interrupts.
//
// A call into GiNaC (normal() of a fraction whose gcd has many variables, the
// expansion of a large product, factor()) runs to its end once made; the
// engine's check_interrupt() is seen only between such calls. But GiNaC
// allocates all the time (every expression node is made by operator new), so
// the replaceable global operator new is where a computation can be stopped
// anywhere: while a statement of the language runs (interruptible_allocations),
// it throws symrep::allocation_interrupted (a std::bad_alloc, which every
// allocation site must let through) once Ctrl-C was pressed
// (interrupt_flag) or, polled every 1024 allocations, the statement's deadline
// (deadline_ticks) has passed. After throwing it stays quiet for the next 2^17
// allocations of the thread, so that the code that reports the interruption can
// allocate; if something swallowed the exception and computes on, it throws
// again.
//
// The engine library does not contain this file (a library must not replace
// the global operator new of the programs that link it): the symrep program and
// the test programs link it as an object (CMakeLists.txt); others may.
// Allocation goes to malloc/free, as libstdc++'s default does; only the
// non-aligned forms are replaced (the aligned ones keep their own pair).
#include <cstdlib>
#include <new>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"

namespace {

thread_local unsigned long allocations = 0;
thread_local unsigned long quiet_until = 0;

constexpr unsigned long deadline_poll_mask = 1023;
constexpr unsigned long quiet_allocations = 1ul << 17;

void poll_interruption() {
    if (symrep::interruptible_allocations() == 0) return;  // outside a statement of the language
    ++allocations;
    if (allocations < quiet_until) return;
    if (symrep::interrupt_flag().load(std::memory_order_relaxed)) {
        quiet_until = allocations + quiet_allocations;
        ++symrep::allocation_interruptions();
        throw symrep::allocation_interrupted("interrupted");
    }
    if ((allocations & deadline_poll_mask) != 0) return;
    const long long d = symrep::deadline_ticks().load(std::memory_order_relaxed);
    if (d != 0 && std::chrono::steady_clock::now().time_since_epoch().count() > d) {
        quiet_until = allocations + quiet_allocations;
        ++symrep::allocation_interruptions();
        throw symrep::allocation_interrupted("time limit: the statement ran longer than its time limit (--time-limit)");
    }
}

void* allocate(std::size_t n) {
    if (n == 0) n = 1;
    for (;;) {
        if (void* p = std::malloc(n)) return p;
        std::new_handler h = std::get_new_handler();
        if (!h) throw std::bad_alloc();
        h();
    }
}

void* allocate_nothrow(std::size_t n) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}

}  // namespace

void* operator new(std::size_t n) {
    poll_interruption();
    return allocate(n);
}
void* operator new[](std::size_t n) {
    poll_interruption();
    return allocate(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return allocate_nothrow(n); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return allocate_nothrow(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
