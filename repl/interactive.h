// symrep/repl/interactive.h -- the interactive prompt of the symrep program.
#pragma once

namespace symrep::lang {
class session;
}

namespace symrep::repl {

/// Runs the interactive prompt on the terminal (GNU readline) until quit, exit
/// or Ctrl-D; returns the exit status (1 if any statement failed). See
/// "Interactive use" in docs/language.md.
int interactive(symrep::lang::session& s);

}  // namespace symrep::repl
