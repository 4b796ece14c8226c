// tests/test_robustness.cpp -- random and mutated input lines fed to the
// evaluator: no crash, no exception escaping the session, every statement
// within a time bound (a runaway one is stopped by the session's time limit).
//
// Lines come from a small grammar of the language (numbers, symbols, operators,
// lists, calls of every builtin with random arguments, vectors) and from the
// lines of examples/*.symrep mutated by deleting, inserting, duplicating and
// swapping characters and tokens. The default run is small enough for the test
// suite; SYMREP_FUZZ_LINES=100000 gives the long run (also meant for a build
// with -DSYMREP_SANITIZE=ON, where AddressSanitizer and UBSan abort on a report).
// Known: the long run reaches single GiNaC calls (normal() of a large rational
// function) that no time limit inside the process can cut short; a process-level
// watchdog is still to come (issue 4), so the long run is not yet part of CI.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/interpreter.h"

using namespace symrep::lang;

namespace {

struct generator {
    std::mt19937 gen;
    std::vector<std::string> builtins, example_lines;
    explicit generator(unsigned seed) : gen(seed) {
        registry r;
        register_all_builtins(r);
        for (const builtin* b : r.all())
            if (b->name != "load" && b->name != "load_rules" && b->name != "plot" && b->name != "trajectory" &&
                b->name != "hodograph")  // no files: the run must not write or read at random
                builtins.push_back(b->name);
        for (const auto& e : std::filesystem::directory_iterator(std::string(SYMREP_SOURCE_DIR) + "/examples")) {
            std::ifstream f(e.path());
            for (std::string l; std::getline(f, l);)
                if (!l.empty() && l[0] != '#' && l.find("load") == std::string::npos &&
                    l.find("plot") == std::string::npos && l.find("trajectory") == std::string::npos &&
                    l.find("hodograph") == std::string::npos)
                    example_lines.push_back(l);
        }
    }
    std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(gen); }
    std::string atom() {
        static const char* atoms[] = {"0", "1", "-2", "3/4", "0.5", "1e-3", "x", "y", "t", "w", "r0", "pi", "I",
                                      "A", "u", "\"s\"", "[]", "[1, 2, 3]", "true", "%", "10^30"};
        return atoms[pick(sizeof atoms / sizeof *atoms)];
    }
    std::string expr(int depth) {
        if (depth <= 0) return atom();
        switch (pick(7)) {
            case 0: return atom();
            case 1: {
                static const char* ops[] = {" + ", " - ", "*", "/", "^", " x ", " . ", " = ", " == ", " < "};
                return "(" + expr(depth - 1) + ops[pick(10)] + expr(depth - 1) + ")";
            }
            case 2: return "-" + expr(depth - 1);
            case 3: return "[" + expr(depth - 1) + ", " + expr(depth - 1) + "]";
            case 4: return expr(depth - 1) + "[" + std::to_string(pick(4)) + "]";
            default: {
                std::string s = builtins[pick(builtins.size())] + "(";
                const std::size_t n = pick(4);
                for (std::size_t i = 0; i < n; ++i) s += (i ? ", " : "") + expr(depth - 1);
                return s + ")";
            }
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
        switch (pick(4)) {
            case 0: return expr(1 + int(pick(4)));
            case 1: return "u := " + expr(1 + int(pick(3)));
            case 2: return example_lines.empty() ? expr(2) : example_lines[pick(example_lines.size())];
            default: return example_lines.empty() ? expr(2) : mutate(example_lines[pick(example_lines.size())]);
        }
    }
};

}  // namespace

TEST(Robustness, RandomAndMutatedLinesNeverCrashOrRunAway) {
    const char* env = std::getenv("SYMREP_FUZZ_LINES");
    const long lines = env ? std::max(1L, std::atol(env)) : 3000;
    const double limit = 2.0;  // seconds per statement (session time limit)
    const double bound = 20.0;  // wall time any one batch may take: the limit plus a long GiNaC call
    generator g(20261124);
    std::ostringstream out, err;
    session s(out, err);
    s.options().time_limit = limit;
    s.evaluate("vector w, r0; A := multicomplex(1); u := element(A, [1, 2, 3, 4])");
    long done = 0, batches = 0;
    double worst = 0;
    while (done < lines) {
        // a batch of 20 lines in one run_string, as a script would give them
        std::string text;
        for (int i = 0; i < 20 && done < lines; ++i, ++done) text += g.line() + "\n";
        const auto t0 = std::chrono::steady_clock::now();
        EXPECT_NO_THROW(s.run_string(text, "fuzz.sr")) << text;
        const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        worst = std::max(worst, dt);
        EXPECT_LT(dt, bound) << "a batch took " << dt << " s:\n" << text;
        ++batches;
        out.str("");
        err.str("");
    }
    EXPECT_EQ(done, lines);
    RecordProperty("worst_batch_seconds", std::to_string(worst));
    EXPECT_GT(s.failures(), 0);  // the mutated lines do produce errors, and they were reported
}
