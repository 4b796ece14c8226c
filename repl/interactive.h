// symrep/repl/interactive.h -- the interactive prompt of the symrep program.
#pragma once

#include <memory>

#include "core/progress.h"

namespace symrep::lang {
class session;
}

namespace symrep::repl {

/// Runs the interactive prompt on the terminal (GNU readline) until quit, exit
/// or Ctrl-D; returns the exit status (1 if any statement failed). See
/// "Interactive use" in docs/language.md.
int interactive(symrep::lang::session& s);

/// The program's progress line (core/progress.h, terminal_progress_sink): installed for the
/// main thread while the result lives, only when standard error is a terminal, so that output
/// to files and pipes stays byte-identical. A long operation (verify, integrate, ...) that runs
/// longer than a second shows "\r verify  42% (3.1 s)" on standard error, erased at its end.
/// SYMREP_PROGRESS_DELAY=SECONDS changes the second (the tests use 0).
std::unique_ptr<symrep::progress_scope> terminal_progress();

}  // namespace symrep::repl
