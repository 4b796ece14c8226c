// symrep -- the command-line program.
//
//   symrep FILE...          run scripts in one session
//   symrep -e 'STATEMENTS'  run statements (may be repeated, mixed with files)
//   symrep < FILE           read statements from standard input (not a terminal)
//   symrep                  interactive prompt (standard input a terminal)
//   symrep --doc            print the Markdown function reference
// Exit status: 0 when every statement succeeded, 1 otherwise, 2 on bad usage.
#include <sys/personality.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "syntax/lexer.h"
#include "symrep/version.h"
#include "interactive.h"

namespace {

const char* usage_text =
    "usage: symrep [options] [FILE...]\n"
    "\n"
    "Runs symrep scripts in one session. With no FILE and no -e, reads statements\n"
    "from standard input (an interactive prompt when it is a terminal).\n"
    "\n"
    "options:\n"
    "  -e STATEMENTS   run STATEMENTS (may be given several times, in order with FILEs)\n"
    "  --format FMT    how results are shown: text (default), latex, json (one JSON\n"
    "                  object per result on stdout, per error on stderr)\n"
    "  --echo          print each statement (\"> \" and its source text) before its result\n"
    "  --stop-on-error stop at the first failed statement (exit status 1)\n"
    "  --time-limit S  stop a statement that runs longer than S seconds (an error; the run goes on)\n"
    "  --max-statement N  the longest statement read, in bytes (default 16777216); longer: an error\n"
    "  --no-caret      error reports without the source line and caret\n"
    "  --unicode       print cross and scalar products of vectors as w \u00d7 r, w \u00b7 r\n"
    "  --ascii         print them as w x r, w . r (the default, except at an interactive\n"
    "                  prompt on a terminal in a UTF-8 locale)\n"
    "  --doc           print the Markdown reference of all functions and exit\n"
    "  --version       print the version and exit\n"
    "  --help          print this help and exit\n"
    "\n"
    "Errors are reported on standard error as FILE:LINE:COL: error: MESSAGE, then the\n"
    "source line with a caret under the column; the run continues with the next\n"
    "statement (unless --stop-on-error). Exit status 1 if any statement failed.\n";

/// True when the character type locale of the environment (LC_ALL, else
/// LC_CTYPE, else LANG: the first that is set and not empty) is UTF-8.
bool utf8_locale() {
    for (const char* var : {"LC_ALL", "LC_CTYPE", "LANG"}) {
        const char* v = std::getenv(var);
        if (!v || !*v) continue;
        std::string s(v);
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s.find("utf-8") != std::string::npos || s.find("utf8") != std::string::npos;
    }
    return false;
}

/// The interactive prompt: repl/interactive.cpp.
int interactive(symrep::lang::session& s) { return symrep::repl::interactive(s); }

}  // namespace

namespace {
// GiNaC seeds the hash value of every object with the address of its type's name
// (GiNaC's hash_seed.h), so under address-space randomization the internal order of
// the terms of a sum changes from run to run, and with it the shape GiNaC's normal()
// and gcd give a polynomial (collected in k in one run, in w0 in the next). The
// printer sorts terms, but cannot undo a different shape: the program runs itself
// once more without randomization, so that the same input prints the same bytes.
// Where the system refuses (a sandbox without personality()), it goes on as it is.
void run_without_address_randomization(char** argv) {
    const int current = ::personality(0xffffffff);
    if (current == -1 || (current & ADDR_NO_RANDOMIZE)) return;
    if (::personality(static_cast<unsigned long>(current) | ADDR_NO_RANDOMIZE) == -1) return;
    ::execv("/proc/self/exe", argv);  // returns only on failure: go on randomized
    ::personality(static_cast<unsigned long>(current));
}
}  // namespace

int main(int argc, char** argv) {
    run_without_address_randomization(argv);
    std::vector<std::pair<bool, std::string>> jobs;  // (is_code, text/path)
    symrep::lang::output_options opts;
    opts.caret = true;
    int unicode = -1;  // --unicode: 1, --ascii: 0, neither: -1 (chosen below)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--format" || a.rfind("--format=", 0) == 0) {
            std::string f;
            if (a == "--format") {
                if (i + 1 >= argc) {
                    std::cerr << "symrep: --format needs an argument (text, latex or json)\n" << usage_text;
                    return 2;
                }
                f = argv[++i];
            } else {
                f = a.substr(9);
            }
            if (f == "text") opts.format = symrep::lang::output_options::text;
            else if (f == "latex") opts.format = symrep::lang::output_options::latex;
            else if (f == "json") opts.format = symrep::lang::output_options::json;
            else {
                std::cerr << "symrep: unknown format '" << f << "' (text, latex or json)\n" << usage_text;
                return 2;
            }
            continue;
        }
        if (a == "--echo") {
            opts.echo = true;
            continue;
        }
        if (a == "--stop-on-error") {
            opts.stop_on_error = true;
            continue;
        }
        if (a == "--time-limit") {
            char* end = nullptr;
            const double v = i + 1 < argc ? std::strtod(argv[i + 1], &end) : -1;
            if (i + 1 >= argc || end == argv[i + 1] || *end || !(v > 0) || v > 1e9) {
                std::cerr << "symrep: --time-limit needs a positive number of seconds\n" << usage_text;
                return 2;
            }
            opts.time_limit = v;
            ++i;
            continue;
        }
        if (a == "--max-statement") {
            char* end = nullptr;
            const long long v = i + 1 < argc ? std::strtoll(argv[i + 1], &end, 10) : -1;
            if (i + 1 >= argc || end == argv[i + 1] || *end || v < 1) {
                std::cerr << "symrep: --max-statement needs a positive number of bytes\n" << usage_text;
                return 2;
            }
            opts.max_statement = static_cast<std::size_t>(v);
            ++i;
            continue;
        }
        if (a == "--unicode" || a == "--ascii") {
            unicode = a == "--unicode";
            continue;
        }
        if (a == "--no-caret") {
            opts.caret = false;
            continue;
        }
        if (a == "--help" || a == "-h") {
            std::cout << usage_text;
            return 0;
        }
        if (a == "--version") {
            std::cout << "symrep " SYMREP_VERSION "\n";
            return 0;
        }
        if (a == "--doc") {
            symrep::lang::registry r;
            symrep::lang::register_all_builtins(r);
            std::cout << symrep::lang::reference_markdown(r);
            return 0;
        }
        if (a == "-e") {
            if (i + 1 >= argc) {
                std::cerr << "symrep: -e needs an argument\n" << usage_text;
                return 2;
            }
            jobs.emplace_back(true, argv[++i]);
            continue;
        }
        if (a.size() > 1 && a[0] == '-') {
            std::cerr << "symrep: unknown option " << a << "\n" << usage_text;
            return 2;
        }
        jobs.emplace_back(false, a);
    }
    std::ios::sync_with_stdio(true);
    const bool prompt = jobs.empty() && isatty(STDIN_FILENO);
    // Scripts and pipes print ASCII (deterministic in every locale) unless asked;
    // a person at a UTF-8 terminal sees the thesis's signs.
    if (unicode < 0) unicode = prompt && isatty(STDOUT_FILENO) && utf8_locale();
    symrep::set_vector_notation(unicode ? symrep::notation::unicode : symrep::notation::ascii);
    symrep::lang::session s(std::cout, std::cerr);
    s.options() = opts;
    const auto progress = symrep::repl::terminal_progress();  // a progress line when stderr is a terminal
    if (jobs.empty()) {
        if (prompt) return interactive(s);
        s.run_stream(std::cin, "<stdin>");  // statement by statement: each answer as soon as it is ready
        return s.failures() ? 1 : 0;
    }
    for (const auto& [code, text] : jobs) {
        if (s.stopped()) break;
        if (code) s.run_string(text, "<command line>");
        else s.run_file(text);
    }
    std::cout.flush();
    return s.failures() ? 1 : 0;
}
