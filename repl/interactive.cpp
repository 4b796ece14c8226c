// symrep/repl/interactive.cpp -- the interactive prompt (standard input a terminal).
//
//   * GNU readline line editing through its callback interface, so that Ctrl-C
//     at the prompt clears the line (and any unfinished multi-line input);
//   * history kept in $HOME/.symrep_history (at most 1000 lines, appended after
//     every line; a file that cannot be read or written is silently ignored);
//   * tab completion of builtin names, variables, commands, and file names
//     inside load("...");
//   * commands: help, help NAME, ?NAME, quit, exit (a line holding only the command);
//   * printed results are numbered "%3 = ..." (session::set_result_labels);
//   * Ctrl-C during a computation sets lang::interrupt_requested(): the session
//     stops at the next syntax node it evaluates. A single long GiNaC/CLN call is
//     not interruptible; pressing Ctrl-C three times quits the program.
#include "interactive.h"

#include <fcntl.h>
#include <sys/select.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <regex>
#include <streambuf>
#include <string>
#include <vector>

#include <readline/history.h>
#include <readline/readline.h>

#include "lang/help.h"
#include "lang/interpreter.h"
#include "symrep/version.h"
#include "syntax/lexer.h"

namespace symrep::repl {

namespace {

using symrep::lang::session;

constexpr int history_lines = 1000;

session* g_session = nullptr;
volatile std::sig_atomic_t g_prompt_interrupt = 0;  ///< Ctrl-C while reading a line
std::atomic<bool> g_computing{false};
std::atomic<int> g_presses{0};  ///< Ctrl-C presses during the current computation

void on_sigint(int) {
    if (!g_computing.load()) {
        g_prompt_interrupt = 1;
        return;
    }
    const int n = ++g_presses;
    lang::interrupt_requested().store(true);
    if (n == 2) {
        const char msg[] = "\nsymrep: still busy inside one library operation (not interruptible); "
                           "press Ctrl-C once more to quit symrep\n";
        [[maybe_unused]] ssize_t w = write(STDERR_FILENO, msg, sizeof msg - 1);
    } else if (n >= 3) {
        const char msg[] = "\nsymrep: quit\n";
        [[maybe_unused]] ssize_t w = write(STDERR_FILENO, msg, sizeof msg - 1);
        _exit(130);
    }
}

bool use_colour() {
    if (!isatty(STDOUT_FILENO) || !isatty(STDERR_FILENO)) return false;
    const char* no = std::getenv("NO_COLOR");
    if (no && *no) return false;
    const char* term = std::getenv("TERM");
    return term && *term && std::strcmp(term, "dumb") != 0;
}

/// Writes every line through to `dest` in red (error reports on the terminal).
class red_lines : public std::streambuf {
public:
    explicit red_lines(std::streambuf* dest) : dest_(dest) {}

protected:
    int overflow(int c) override {
        if (c == EOF) return 0;
        if (start_ && c != '\n') {
            dest_->sputn("\033[31m", 5);
            start_ = false;
        }
        if (c == '\n') {
            dest_->sputn("\033[0m", 4);
            start_ = true;
        }
        return dest_->sputc(static_cast<char>(c));
    }
    int sync() override { return dest_->pubsync(); }

private:
    std::streambuf* dest_;
    bool start_ = true;
};

// --- history ------------------------------------------------------------------

std::string history_path() {
    const char* home = std::getenv("HOME");
    if (!home || !*home) return {};
    return std::string(home) + "/.symrep_history";
}

void history_start(const std::string& path) {
    using_history();
    stifle_history(history_lines);
    if (path.empty()) return;
    (void)read_history(path.c_str());
    // append_history needs the file to exist
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
    if (fd >= 0) close(fd);
}

void history_add(const std::string& path, const std::string& line) {
    if (line.find_first_not_of(" \t") == std::string::npos) return;
    HIST_ENTRY* last = history_length > 0 ? history_get(history_base + history_length - 1) : nullptr;
    if (last && last->line && line == last->line) return;
    add_history(line.c_str());
    if (path.empty()) return;
    (void)append_history(1, path.c_str());
    (void)history_truncate_file(path.c_str(), history_lines);
}

// --- completion -----------------------------------------------------------------

std::vector<std::string> g_candidates;
std::size_t g_next = 0;

char* next_candidate(const char*, int state) {
    if (state == 0) g_next = 0;
    if (g_next >= g_candidates.size()) return nullptr;
    return strdup(g_candidates[g_next++].c_str());
}

/// True when the word being completed is the inside of the string of load("...").
bool in_load_string(int start) {
    if (start < 1 || rl_line_buffer[start - 1] != '"') return false;
    static const std::regex load_call(R"((^|[^A-Za-z0-9_])(load|load_rules)\s*\(\s*$)");
    return std::regex_search(std::string(rl_line_buffer, start - 1), load_call);
}

char** complete(const char* text, int start, int) {
    rl_attempted_completion_over = 1;  // never fall back to file names
    if (in_load_string(start)) {
        rl_completion_append_character = '\0';  // readline closes the quote itself
        return rl_completion_matches(text, rl_filename_completion_function);
    }
    if (start > 0 && rl_line_buffer[start - 1] == '"') return nullptr;  // other strings
    const std::string prefix(text);
    g_candidates = lang::completions(*g_session, prefix, start == 0);
    std::vector<std::string> functions;
    for (const auto& c : g_candidates)
        if (g_session->builtins().find(c)) functions.push_back(c);
    if (g_candidates.empty()) return nullptr;
    // a function name completes with its '(', a name with nothing after it
    rl_completion_append_character = g_candidates.size() == 1 && !functions.empty() ? '(' : '\0';
    if (g_candidates.size() == 1 && start == 0 &&
        (g_candidates[0] == "help" || g_candidates[0] == "quit" || g_candidates[0] == "exit"))
        rl_completion_append_character = ' ';
    // the declarations are followed by the names they declare: vector w, positive g
    if (g_candidates.size() == 1 && (g_candidates[0] == "vector" || g_candidates[0] == "positive"))
        rl_completion_append_character = ' ';
    return rl_completion_matches(text, next_candidate);
}

// --- reading a line -------------------------------------------------------------

enum class got { line, eof, interrupted };

std::string g_line;
bool g_done = false, g_eof = false;

void on_line(char* line) {
    if (!line) {
        g_eof = true;
    } else {
        g_line = line;
        std::free(line);
    }
    g_done = true;
    rl_callback_handler_remove();
}

got read_line(const std::string& prompt, std::string& out) {
    g_done = g_eof = false;
    g_prompt_interrupt = 0;
    rl_callback_handler_install(prompt.c_str(), on_line);
    sigset_t block, orig;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    while (!g_done) {
        sigprocmask(SIG_BLOCK, &block, &orig);
        if (g_prompt_interrupt) {
            sigprocmask(SIG_SETMASK, &orig, nullptr);
            g_prompt_interrupt = 0;
            // Ctrl-C at the prompt: drop the line, start afresh
            rl_free_line_state();
            rl_callback_sigcleanup();
            rl_replace_line("", 0);
            rl_point = rl_end = rl_mark = 0;
            rl_crlf();
            rl_callback_handler_remove();
            return got::interrupted;
        }
        fd_set fds;
        FD_ZERO(&fds);
        FD_SET(STDIN_FILENO, &fds);
        const int r = pselect(STDIN_FILENO + 1, &fds, nullptr, nullptr, nullptr, &orig);
        sigprocmask(SIG_SETMASK, &orig, nullptr);
        if (r < 0) {
            if (errno == EINTR) continue;
            rl_callback_handler_remove();
            return got::eof;
        }
        rl_callback_read_char();
    }
    if (g_eof) return got::eof;
    out = g_line;
    return got::line;
}

// --- commands ---------------------------------------------------------------------

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    const auto b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

void list_functions(session& s) {
    std::string section, line;
    auto flush = [&] {
        if (!line.empty()) std::cout << "  " << line << "\n";
        line.clear();
    };
    for (const auto* b : s.builtins().all()) {
        if (b->section != section) {
            flush();
            section = b->section;
            std::cout << section << ":\n";
        }
        if (!line.empty() && line.size() + 1 + b->name.size() > 76) flush();
        line += (line.empty() ? "" : " ") + b->name;
    }
    flush();
    std::cout << "help NAME or ?NAME shows one function; % is the last result, %% the one before, %N result N;\n"
                 "quit, exit or Ctrl-D leave; Ctrl-C interrupts a computation.\n";
}

void help_on(session& s, const std::string& name) {
    if (name == "help" || name == "quit" || name == "exit") {
        std::cout << (name == "help" ? "help lists the functions; help NAME or ?NAME shows one of them\n"
                                     : name + " leaves symrep (so does Ctrl-D)\n");
        return;
    }
    const std::string text = lang::help_text(s.builtins(), name);
    if (text.empty()) {
        std::cerr << lang::unknown_builtin_message(s.builtins(), name) << "\n";
        std::cerr.flush();
        return;
    }
    std::cout << text;
}

/// Handles a command line; false when the line is not a command.
bool command(session& s, const std::string& line, bool& quit) {
    const std::string t = trim(line);
    if (t == "quit" || t == "exit" || t == "quit()" || t == "exit()") {
        quit = true;
        return true;
    }
    if (t == "help") {
        list_functions(s);
        return true;
    }
    static const std::regex help_name(R"(^(?:help\s+|\?\s*)([A-Za-z_][A-Za-z0-9_]*)$)");
    std::smatch m;
    if (std::regex_match(t, m, help_name)) {
        help_on(s, m[1]);
        return true;
    }
    return false;
}

}  // namespace

std::unique_ptr<progress_scope> terminal_progress() {
    double delay = 1.0;
    if (const char* d = std::getenv("SYMREP_PROGRESS_DELAY")) {
        char* end = nullptr;
        const double v = std::strtod(d, &end);
        if (end != d && *end == '\0' && v >= 0) delay = v;
    }
    return progress_on_terminal(STDERR_FILENO, delay);
}

int interactive(session& s) {
    g_session = &s;
    const bool colour = use_colour();
    red_lines red(std::cerr.rdbuf());
    std::streambuf* cerr_buf = std::cerr.rdbuf();
    if (colour) std::cerr.rdbuf(&red);

    struct sigaction sa {};
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    struct sigaction old_sa {};
    sigaction(SIGINT, &sa, &old_sa);

    rl_readline_name = "symrep";
    // readline's own SIGINT handler would defer the signal until it reads the
    // next character, so that the keys typed after Ctrl-C could land on the old
    // line: only ours is installed, and read_line checks it before every character.
    rl_catch_signals = 0;
    rl_attempted_completion_function = complete;
    static char breaks[] = " \t\n\"\\'`@$><=;|&{}()[],+-*/^:.";
    rl_basic_word_break_characters = breaks;
    static char quotes[] = "\"";
    rl_completer_quote_characters = quotes;
    const std::string hist = history_path();
    history_start(hist);
    s.set_result_labels(true);

    if (colour)
        std::cout << "\033[1msymrep " SYMREP_VERSION "\033[0m";
    else
        std::cout << "symrep " SYMREP_VERSION;
    std::cout << " -- type help for the functions, ?NAME for one of them; quit or Ctrl-D to leave\n";
    std::cout.flush();

    const std::string prompt = colour ? "\001\033[1;34m\002> \001\033[0m\002" : "> ";
    const std::string more = colour ? "\001\033[1;34m\002... \001\033[0m\002" : "... ";
    std::string pending;
    for (;;) {
        std::string line;
        const got g = read_line(pending.empty() ? prompt : more, line);
        if (g == got::eof) break;
        if (g == got::interrupted) {
            pending.clear();
            continue;
        }
        history_add(hist, line);
        if (pending.empty()) {
            bool quit = false;
            if (command(s, line, quit)) {
                if (quit) break;
                continue;
            }
        }
        pending += line + "\n";
        if (lang::needs_more_input(pending)) continue;
        lang::interrupt_requested().store(false);
        g_presses = 0;
        g_computing = true;
        s.run_string(pending, "<stdin>");
        g_computing = false;
        lang::interrupt_requested().store(false);
        pending.clear();
        std::cout.flush();
    }
    std::cout << "\n";
    std::cout.flush();
    sigaction(SIGINT, &old_sa, nullptr);
    std::cerr.rdbuf(cerr_buf);
    s.set_result_labels(false);
    return s.failures() ? 1 : 0;
}

}  // namespace symrep::repl
