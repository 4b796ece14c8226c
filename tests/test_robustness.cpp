// tests/test_robustness.cpp -- random and mutated input lines fed to the
// evaluator: no crash, no sanitizer report, no exception escaping the session,
// and no input running past a hard wall-clock bound (a runaway statement must be
// stopped by the session's time limit, with a message). docs/testing.md.
//
// Inputs come from a small grammar of the language (numbers, symbols, operators,
// lists, calls of every builtin with arguments of the kinds their signatures
// name, vectors) and from the lines of examples/*.symrep and of the builtins'
// examples, as they are or mutated by deleting, inserting, duplicating and
// swapping characters; a few inputs join two lines. They run in worker processes
// (fork; a fresh session every `chunk` inputs, set up by the quick example
// scripts), which tell the parent through a pipe which input they start. The
// parent kills a worker that spends more than `bound` seconds on one input (a
// runaway: one long GiNaC call that no in-process limit reaches) and records a
// worker that dies (a crash, an uncaught exception, or an AddressSanitizer/UBSan
// report: the sanitized build aborts on the first one) or whose leak check fails;
// each is a test failure naming the input, and the run goes on with a new worker.
//
// The default run (10000 inputs) is part of the test suite; SYMREP_FUZZ_LINES=N
// sets the number of inputs and SYMREP_FUZZ_SEED another seed (the inputs of a
// run are a prefix of those of a longer run with the same seed);
// SYMREP_FUZZ_DUMP=FILE writes them to FILE, SYMREP_FUZZ_REPLAY=FIRST:K reruns
// inputs FIRST..K in-process (as a failure message says). The long run under
// -DSYMREP_SANITIZE=ON is `bash build.sh fuzz [N]`.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "core/interrupt.h"
#include "robustness_findings.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
// Defaults of the sanitized build (ASAN_OPTIONS still overrides them):
// allocator_may_return_null: an allocation larger than the machine gives throws
// std::bad_alloc (reported by the session as "out of memory") as in the normal
// build, instead of ending the process; hard_rss_limit_mb ends a worker whose
// memory runs away (it is then reported as a crash at its input). Leaks are
// checked by each worker once its session is gone (__lsan_do_recoverable_leak_check),
// not at the exit of the test program.
extern "C" const char* __asan_default_options() {
    return "allocator_may_return_null=1:hard_rss_limit_mb=6000:detect_leaks=1:leak_check_at_exit=0:print_suppressions=0";
}
// The one suppression: CLN allocates a string for its default print flags when
// it is loaded (cl_prin_globals_init_helper) and LeakSanitizer reports it as
// lost. CLN is built without frame pointers, so the stacks of its allocations
// end in libcln and cannot name that function without the slow unwinder (15
// times slower); the suppression therefore names the library. Allocations made
// by symrep's own code (operator new in engine/) have symrep frames and stay checked.
extern "C" const char* __lsan_default_suppressions() { return "leak:libcln.so\n"; }
#endif

using namespace symrep::lang;

namespace {

/// Lines that name files (the run must not write or read at random).
bool names_files(const std::string& l) {
    for (const char* f : {"load", "plot", "trajectory", "hodograph"})
        if (l.find(f) != std::string::npos) return true;
    return false;
}

struct generator {
    std::mt19937 gen;
    std::vector<const builtin*> builtins;
    std::vector<std::string> example_lines;  // lines of examples/*.symrep and the builtins' examples
    std::vector<std::string> example_exprs;  // those of them that are one expression (arguments of calls)
    std::string setup;                       // statements every worker runs first
    registry reg;
    explicit generator(unsigned seed) : gen(seed) {
        register_all_builtins(reg);
        std::vector<std::filesystem::path> files;
        for (const auto& e : std::filesystem::directory_iterator(std::string(SYMREP_SOURCE_DIR) + "/examples"))
            files.push_back(e.path());
        std::sort(files.begin(), files.end());  // the same inputs whatever the directory order
        for (const auto& p : files) {
            std::ifstream f(p);
            for (std::string l; std::getline(f, l);)
                if (!l.empty() && l[0] != '#' && !names_files(l)) example_lines.push_back(l);
        }
        // Quick scripts make the setup of every worker, so that the lines taken from them
        // find their variables (i0, d, g, E, ...) defined. In this order they run in a
        // fraction of a second (charges.symrep before sobrero.symrep makes a0 a polynomial
        // and the statements of the second slow: the inputs explore that).
        for (const char* name : {"algebras", "multicomplex", "sobrero", "walsh", "charges", "rotating_frame"}) {
            std::ifstream f(std::string(SYMREP_SOURCE_DIR) + "/examples/" + name + ".symrep");
            for (std::string l; std::getline(f, l);)
                if (!l.empty() && l[0] != '#' && !names_files(l)) setup += l + "\n";
        }
        for (const builtin* b : reg.all()) {
            if (names_files(b->name)) continue;
            builtins.push_back(b);
            std::istringstream ex(b->example);
            for (std::string l; std::getline(ex, l);)
                if (!l.empty() && !names_files(l)) example_lines.push_back(l);
        }
        for (const std::string& l : example_lines)
            if (l.find(":=") == std::string::npos && l.find(';') == std::string::npos && l.find('#') == std::string::npos &&
                l.rfind("vector", 0) != 0 && l.rfind("positive", 0) != 0)
                example_exprs.push_back(l);
    }
    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(gen); }
    std::string atom() {
        // numbers, symbols, and the values of prepare()
        static const char* atoms[] = {"0", "1", "2", "5", "-2", "3/4", "0.5", "1e-3", "x", "y", "t", "X", "w", "r0",
                                      "pi", "I", "A", "u", "M", "P", "A0", "u0", "M0", "P0", "S0", "W0", "\"s\"",
                                      "[]", "[1, 2, 3]", "true", "%", "10^30"};
        return atoms[pick(sizeof atoms / sizeof *atoms)];
    }
    /// An argument for the parameter named `param` in a builtin's signature
    /// ("minpoly(w, X)": an element, then a symbol), mostly of the kind it names.
    std::string argument(const std::string& param, int depth) {
        auto one_of = [&](std::initializer_list<const char*> l) { return std::string(l.begin()[pick(l.size())]); };
        if (pick(4) == 0 || param.empty()) return expr(depth - 1);
        switch (param[0]) {
            case 'w': case 'u': case 'v': case 'z':
                return one_of({"u", "u0", "element(A0, [x, 0, 1, y])", "generating_element(S0)", "basis(W0, 1)",
                               "(u0 + basis(A0, 1))", "element(multicomplex(2), [1, 0, 2, 0, 0, 1, 0, 3])"});
            case 'A': return one_of({"A", "A0", "S0", "W0", "multicomplex(2)", "walsh_complex(1)",
                                     "polynomial_algebra(X^3 - 2*X + 1, X)"});
            case 'X': case 'x': case 't': return one_of({"X", "x", "t"});
            case 'n': case 'k': case 'p': case 'i': case 'j': return one_of({"0", "1", "2", "3", "-1"});
            case 'm': return one_of({"M", "M0", "matrix([[1, x], [0, 2]])", "canonical_matrix(u0)"});
            case 'P': return one_of({"P", "P0"});
            default: return expr(depth - 1);
        }
    }
    std::string call(int depth) {
        const builtin& b = *builtins[pick(builtins.size())];
        // the parameter names of the signature: "f(a, b [, c])" -> a, b, c
        std::vector<std::string> params;
        const std::size_t open = b.signature.find('('), close = b.signature.find(')');
        if (open != std::string::npos && close != std::string::npos && close > open) {
            std::istringstream in(b.signature.substr(open + 1, close - open - 1));
            for (std::string p; std::getline(in, p, ',');) {
                p.erase(std::remove_if(p.begin(), p.end(), [](char c) { return c == ' ' || c == '[' || c == ']'; }), p.end());
                params.push_back(p);
            }
        }
        // mostly a count of arguments the builtin takes; sometimes any count
        const std::size_t hi = std::min(b.max_args, b.min_args + 2);
        const std::size_t n = pick(8) == 0 ? pick(4) : b.min_args + pick(hi - b.min_args + 1);
        std::string s = b.name + "(";
        for (std::size_t i = 0; i < n; ++i) s += (i ? ", " : "") + argument(i < params.size() ? params[i] : "", depth);
        return s + ")";
    }
    std::string expr(int depth) {
        if (depth <= 0) return pick(8) == 0 && !example_exprs.empty() ? example_exprs[pick(example_exprs.size())] : atom();
        switch (pick(8)) {
            case 0: return atom();
            case 1: {
                static const char* ops[] = {" + ", " - ", "*", "/", "^", " x ", " . ", " = ", " == ", " < "};
                return "(" + expr(depth - 1) + ops[pick(10)] + expr(depth - 1) + ")";
            }
            case 2: return "-" + expr(depth - 1);
            case 3: return "[" + expr(depth - 1) + ", " + expr(depth - 1) + "]";
            case 4: return pick(4) ? call(depth) : expr(depth - 1) + "[" + std::to_string(pick(4)) + "]";
            case 5: return example_exprs.empty() ? atom() : example_exprs[pick(example_exprs.size())];
            default: return call(depth);
        }
    }
    std::string mutate(std::string l) {
        static const std::string alphabet = "()[],.+-*/^=:;\"'x0123456789abcwtI% \n#";
        const std::size_t k = 1 + pick(4);
        for (std::size_t i = 0; i < k && !l.empty(); ++i) {
            const std::size_t p = pick(l.size());
            switch (pick(4)) {
                case 0: l.erase(p, 1 + pick(3)); break;
                case 1: l.insert(p, 1, alphabet[pick(alphabet.size())]); break;
                case 2: l.insert(p, l.substr(p, pick(8))); break;
                default: std::swap(l[p], l[pick(l.size())]);
            }
        }
        return l;
    }
    std::string line() {
        static const char* names[] = {"u", "w", "A", "P", "M", "v"};
        switch (pick(4)) {
            case 0: return expr(1 + int(pick(4)));
            case 1: return std::string(names[pick(6)]) + " := " + expr(1 + int(pick(3)));
            case 2: return example_lines[pick(example_lines.size())];
            default: return mutate(example_lines[pick(example_lines.size())]);
        }
    }
    /// One input: a line, or (one in 16) two lines run together.
    std::string input() { return pick(16) == 0 ? line() + "\n" + line() : line(); }
};

// The worker's messages to the parent: {kind, value} pairs of 32-bit words.
enum message : std::uint32_t {
    starting = 1,  // input #value
    stopped = 2,   // value statements were stopped by the time limit (sent at the end)
    finished = 3,  // value statements failed (the last message)
    ended = 4,     // the worker ran the inputs up to #value (exclusive): it stopped after an interruption
};
constexpr double time_limit = 1.0;  // seconds per statement (the session's time limit)
constexpr double bound = 10.0;      // seconds any one input may take before its worker is killed
constexpr std::size_t chunk = 1000;  // inputs per worker

void send(int fd, std::uint32_t kind, std::uint32_t v) {
    const std::uint32_t m[2] = {kind, v};
    if (write(fd, m, sizeof m) != sizeof m) _exit(4);
}

/// The inputs of a run, and the statements each worker runs before them.
struct corpus {
    std::vector<std::string> inputs;
    std::string setup;
};

/// A session as the workers have it: the time limit, a few values the inputs use.
void prepare(session& s, const std::string& setup) {
    s.options().time_limit = time_limit;
    // A, u, M and P are assigned again by the inputs; the names ending in 0 seldom are
    s.evaluate("vector w, r0; A := multicomplex(1); u := element(A, [1, 2, 3, 4]); M := matrix([[1, 2], [3, 4]]); "
               "P := ode(r'' + 4*r = 0, r(0) = r0, r'(0) = 0); A0 := A; u0 := u; M0 := M; P0 := P; "
               "S0 := sobrero(1); W0 := walsh(2)");
    s.run_string(setup, "setup.sr");
}

/// The worker: runs inputs[first, last) in a fresh session and exits (status 0;
/// 3 when the leak check of the sanitized build found a leak). An input that was
/// stopped inside a GiNaC call (operator new threw, core/allocation_interrupt.cpp)
/// ends the worker after it, and a leak is then status 6: GiNaC is not exception
/// safe everywhere (add::recombine_pair_to_ex, for one, loses the object it has
/// just made), so such a leak may be GiNaC's; the parent reruns the inputs before
/// that one to see whether they leak by themselves.
[[noreturn]] void worker(const corpus& c, std::size_t first, std::size_t last, int fd) {
#if !defined(__SANITIZE_ADDRESS__)
    // a memory runaway becomes std::bad_alloc ("out of memory") rather than a machine out of memory
    const rlimit mem{std::size_t(6) << 30, std::size_t(6) << 30};
    setrlimit(RLIMIT_AS, &mem);
#endif
    int failures = 0, timed_out = 0;
    {
        std::ostringstream out, err;
        session s(out, err);
        prepare(s, c.setup);
        const int before = s.failures();  // those of the setup
        for (std::size_t i = first; i < last; ++i) {
            send(fd, starting, std::uint32_t(i));
            try {
                s.run_string(c.inputs[i], "fuzz.sr");
            } catch (const std::exception& e) {
                std::cerr << "input #" << i << ": an exception escaped the session: " << e.what() << "\n";
                _exit(5);
            } catch (...) {
                std::cerr << "input #" << i << ": an exception escaped the session\n";
                _exit(5);
            }
            const std::string reports = err.str();
            for (std::size_t p = reports.find("error: time limit"); p != std::string::npos;
                 p = reports.find("error: time limit", p + 1))
                ++timed_out;
            out.str("");
            err.str("");
            if (symrep::allocation_interruptions().load() != 0) {
                send(fd, ended, std::uint32_t(i + 1));
                break;
            }
        }
        failures = s.failures() - before;
    }
    send(fd, stopped, std::uint32_t(timed_out));
    send(fd, finished, std::uint32_t(failures));
    int status = 0;
#if defined(__SANITIZE_ADDRESS__)
    if (__lsan_do_recoverable_leak_check()) status = symrep::allocation_interruptions().load() != 0 ? 6 : 3;
#endif
    close(fd);
    _exit(status);
}

struct finding {
    std::size_t first;  // the first input of the worker (its session saw inputs first..index)
    std::size_t index;
    std::string what;
    bool unfinished;  // the input did not run to its end (a crash or a runaway; not a leak)
};

struct run_result {
    std::vector<finding> findings;
    std::size_t completed = 0;  // inputs that finished within the bound
    long failures = 0;          // statements that failed (with an error message)
    long stopped = 0;           // of them, stopped by the time limit
    std::vector<std::size_t> interrupted_leaks;  // inputs stopped inside GiNaC that left GiNaC's objects unreachable
    std::vector<std::pair<double, std::size_t>> slowest;  // (seconds, input), slowest first
};

/// Runs inputs[first, last) in one worker process, watched; returns where to go on.
std::size_t watch_worker(const corpus& c, std::size_t first, std::size_t last, run_result& r) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        close(fds[0]);
        worker(c, first, last, fds[1]);
    }
    close(fds[1]);
    struct closer {
        int fd;
        ~closer() { close(fd); }
    } reading{fds[0]};
    std::size_t current = first;  // the input the worker is running
    std::size_t end = last;       // where the worker stopped
    bool started = false, done = false;
    auto t0 = std::chrono::steady_clock::now();
    std::string buffer;
    for (;;) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (started && elapsed > bound) {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
            std::ostringstream os;
            os << "ran away: no answer after " << bound << " s (time limit " << time_limit << " s per statement)";
            r.findings.push_back({first, current, os.str(), true});
            return current + 1;
        }
        pollfd p{fds[0], POLLIN, 0};
        const int ms = started ? std::max(1, int((bound - elapsed) * 1000) + 1) : 1000;
        const int k = poll(&p, 1, ms);
        if (k < 0 && errno != EINTR) throw std::runtime_error("poll failed");
        if (k <= 0) continue;
        char data[512];
        const ssize_t got = read(fds[0], data, sizeof data);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;  // end of file: the worker has ended
        buffer.append(data, std::size_t(got));
        while (buffer.size() >= 8) {
            std::uint32_t m[2];
            std::copy(buffer.data(), buffer.data() + 8, reinterpret_cast<char*>(m));
            buffer.erase(0, 8);
            const auto now = std::chrono::steady_clock::now();
            if (started) {
                r.slowest.emplace_back(std::chrono::duration<double>(now - t0).count(), current);
                std::sort(r.slowest.rbegin(), r.slowest.rend());
                if (r.slowest.size() > 10) r.slowest.pop_back();
                ++r.completed;
            }
            if (m[0] == starting) {
                current = m[1];
                started = true;
            } else if (m[0] == ended) {
                end = m[1];
                started = false;
            } else {
                (m[0] == stopped ? r.stopped : r.failures) += m[1];
                started = false;
                done = m[0] == finished;
            }
            t0 = now;
        }
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (done && WIFEXITED(status) && WEXITSTATUS(status) == 0) return end;
    if (done && WIFEXITED(status) && WEXITSTATUS(status) == 6) {
        // a leak after input #end - 1 was stopped inside GiNaC: the inputs before it
        // again, without it, tell whether they leak by themselves (their counts are not added again)
        r.interrupted_leaks.push_back(end - 1);
        run_result again;
        for (std::size_t next = first; next < end - 1;) next = watch_worker(c, next, end - 1, again);
        r.findings.insert(r.findings.end(), again.findings.begin(), again.findings.end());
        r.interrupted_leaks.insert(r.interrupted_leaks.end(), again.interrupted_leaks.begin(),
                                   again.interrupted_leaks.end());
        return end;
    }
    std::ostringstream os;
    if (done && WIFEXITED(status) && WEXITSTATUS(status) == 3)
        os << "leak: LeakSanitizer found memory no longer reachable after inputs #" << first << "..#" << last - 1
           << " (report above)";
    else if (WIFSIGNALED(status))
        os << "crashed: the worker died by signal " << WTERMSIG(status) << " (" << strsignal(WTERMSIG(status)) << ")";
    else
        os << "crashed: the worker exited with status " << WEXITSTATUS(status)
           << " (a sanitizer report, or an exception that escaped: see above)";
    r.findings.push_back({first, current, os.str(), !done});
    return done ? last : current + 1;
}

/// Runs every input through worker processes (see the top of the file): one
/// per `chunk` inputs, and a new one after an input that killed its worker.
run_result run_all(const corpus& c) {
    run_result r;
    for (std::size_t from = 0; from < c.inputs.size(); from += chunk) {
        const std::size_t last = std::min(c.inputs.size(), from + chunk);
        for (std::size_t next = from; next < last;) next = watch_worker(c, next, last, r);
    }
    return r;
}

/// SYMREP_FUZZ_REPLAY=FIRST:K: runs inputs FIRST..K in this process, as the
/// worker that met input K ran them, without the watchdog (under a debugger,
/// say), printing the slow ones and the output of the last.
void replay(const corpus& c, const std::string& range) {
    const std::size_t colon = range.find(':');
    const std::size_t first = std::stoul(range.substr(0, colon));
    const std::size_t k = colon == std::string::npos ? first : std::stoul(range.substr(colon + 1));
    ASSERT_LT(k, c.inputs.size()) << "SYMREP_FUZZ_REPLAY: input " << k << " is beyond SYMREP_FUZZ_LINES";
    std::ostringstream out, err;
    session s(out, err);
    prepare(s, c.setup);
    for (std::size_t i = first; i <= k; ++i) {
        out.str("");
        err.str("");
        const auto t0 = std::chrono::steady_clock::now();
        s.run_string(c.inputs[i], "fuzz.sr");
        const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (dt > 0.5 || i == k) std::cout << "#" << i << " (" << dt << " s): " << c.inputs[i] << "\n";
    }
    std::cout << out.str() << err.str();
}

long env_number(const char* name, long fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::atol(v) : fallback;
}

}  // namespace

TEST(Robustness, RandomAndMutatedLinesNeverCrashOrRunAway) {
    const std::size_t n = std::size_t(std::max(1L, env_number("SYMREP_FUZZ_LINES", 10000)));
    const unsigned seed = unsigned(env_number("SYMREP_FUZZ_SEED", 20261124));
    generator g(seed);
    corpus c{{}, g.setup};
    std::vector<std::string>& inputs = c.inputs;
    for (std::size_t i = 0; i < n; ++i) inputs.push_back(g.input());
    if (const char* dump = std::getenv("SYMREP_FUZZ_DUMP")) {  // the inputs as a script, to read them
        std::ofstream f(dump);
        for (std::size_t i = 0; i < n; ++i) f << "# input " << i << "\n" << inputs[i] << "\n";
    }
    if (const char* range = std::getenv("SYMREP_FUZZ_REPLAY")) {
        replay(c, range);
        GTEST_SKIP() << "replayed inputs " << range;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const run_result r = run_all(c);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (const finding& f : r.findings)
        ADD_FAILURE() << "input #" << f.index << " (seed " << seed << ") " << f.what << ":\n"
                      << inputs[f.index] << "\n(rerun: SYMREP_FUZZ_LINES=" << n << " SYMREP_FUZZ_SEED=" << seed
                      << " SYMREP_FUZZ_REPLAY=" << f.first << ":" << f.index << ")";
    std::ostringstream summary;
    summary << n << " inputs (seed " << seed << ") in " << total << " s, " << r.failures
            << " statements failed with a message (" << r.stopped << " of them by the time limit of " << time_limit
            << " s), " << r.findings.size() << " findings";
    if (!r.interrupted_leaks.empty()) {
        summary << "; GiNaC's objects left unreachable by " << r.interrupted_leaks.size()
                << " interruptions inside GiNaC calls (the inputs before each ran again without it; a leak of theirs "
                   "is a finding):";
        for (std::size_t i : r.interrupted_leaks) summary << " #" << i;
    }
    summary << "; slowest:";
    for (const auto& [dt, i] : r.slowest) summary << "\n  " << dt << " s  #" << i << "  " << inputs[i];
    std::cout << summary.str() << "\n";
    RecordProperty("summary", summary.str());
    const auto unfinished = std::count_if(r.findings.begin(), r.findings.end(), [](const finding& f) { return f.unfinished; });
    EXPECT_EQ(r.completed + std::size_t(unfinished), n);  // every input ran to its end or was recorded
    EXPECT_GT(r.failures, 0);  // the mutated lines do produce errors, and they were reported
}

// The inputs of earlier findings (robustness_findings.h), through the same watched
// workers: no crash, no sanitizer report, each refused or stopped in time.
TEST(Robustness, EarlierFindingsStayFixed) {
    corpus c;
    for (const char* text : symrep::test::robustness_findings) c.inputs.push_back(text);
    const run_result r = run_all(c);
    for (const finding& f : r.findings) ADD_FAILURE() << f.what << ":\n" << c.inputs[f.index];
    EXPECT_EQ(r.completed, c.inputs.size());
    EXPECT_EQ(r.failures, long(c.inputs.size()));  // each one is an error with a message
    ASSERT_FALSE(r.slowest.empty());
    EXPECT_LT(r.slowest.front().first, 2 * time_limit + 3) << c.inputs[r.slowest.front().second];
}

