// symrep/core/error.h -- the typed exceptions of the engine.
//
// core/ is the ground floor: what every other folder needs and nothing of
// mathematics. It holds the errors (this header), interruption and the
// statement deadline (interrupt.h), the operator new that stops library calls
// (allocation_interrupt.cpp, linked by programs) and the guards on the size of
// expressions (expression_size.h). It includes no other folder of engine/
// (docs/architecture.md).
//
// Every failure the user can cause (bad input, a zero divisor where an inverse
// is asked for, a size that does not fit in memory, ...) is reported by throwing
// one of these types. The message is complete and user-facing: the REPL and the
// script runner print it verbatim after "FILE:LINE:COL: error: ". Library users
// catch symrep::error (or a subclass) and get the same text from what().
#pragma once

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

/// A defect of the engine, never of the input: a result it derived that its own test
/// shows wrong (solve() of a Cauchy problem checks its solution at a point before it
/// returns it, mechanics/solution_witness.h). The message names the problem and what was
/// seen; the result is withheld, never printed.
class internal_error : public error {
public:
    using error::error;
};

}  // namespace symrep
