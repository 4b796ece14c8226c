// symrep/lang/statement_clock.h -- the clock of a statement and the translation
// of the errors that end one (internal to lang/).
//
// A statement runs under a statement_clock: it sets the deadline that
// check_interrupt() (core/interrupt.h) sees and lets operator new interrupt
// library calls. Whatever a statement throws is reported through message_of():
// symrep's own messages verbatim, GiNaC's and CLN's said in the language's terms.
#pragma once

#include <chrono>
#include <exception>
#include <string>

namespace symrep::lang {

/// The message of a statement abandoned for lack of memory.
extern const char* const out_of_memory_message;

/// Known messages of GiNaC and CLN, said in the terms of the language.
std::string clear_message(const std::string& m);

/// The message to show for an exception: symrep's own verbatim, others translated.
std::string message_of(const std::exception& e);

/// A message as the session reports it (session::report, lang/interpreter.cpp): each run
/// of more than 60 digits shortened to its ends and its count, control characters escaped.
/// The front-ends that raise errors themselves (the Python module) show the same bytes.
std::string reported_message(const std::string& message);

/// The clock of a statement: sets `start` to now and, for a time limit > 0, the
/// deadline that the engine's long loops and guards see through check_interrupt()
/// (core/interrupt.h), and lets operator new throw allocation_interrupted
/// (core/allocation_interrupt.cpp), until destroyed.
class statement_clock {
public:
    statement_clock(double limit, std::chrono::steady_clock::time_point& start);
    ~statement_clock();
    statement_clock(const statement_clock&) = delete;
    statement_clock& operator=(const statement_clock&) = delete;

private:
    long long previous_;
};

}  // namespace symrep::lang
