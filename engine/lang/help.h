// symrep/lang/help.h -- the help and the completion of the front-ends: the interactive
// prompt (repl/), the Python module and the Jupyter kernel show the same text and offer
// the same names.
#pragma once

#include <string>
#include <vector>

#include "symrep/lang/interpreter.h"

namespace symrep::lang {

/// The help on one builtin, as `help NAME` and `?NAME` show it: signature and section,
/// summary, the thesis equation and an example, one per line. nullopt-like: an empty
/// string when there is no builtin of that name (see unknown_builtin_message).
std::string help_text(const registry& r, const std::string& name);

/// "no function named 'NAME'; did you mean A, B?" (or "(help lists all functions)").
std::string unknown_builtin_message(const registry& r, const std::string& name);

/// The names a word starting with `prefix` may complete to, sorted and unique: the
/// builtins, the session's variables and the keywords (vector, positive, true, false, pi,
/// I); at the start of a line also the prompt's commands help, quit, exit when `commands`.
std::vector<std::string> completions(const session& s, const std::string& prefix, bool commands = false);

}  // namespace symrep::lang
