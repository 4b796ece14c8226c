// tests/test_util.h -- small helpers shared by the test files: exact equality of
// expressions with both sides in the failure message (same), the message of an
// expected exception, and running the symrep program (SYMREP_BINARY).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <ginac/ginac.h>
#include <gtest/gtest.h>

#include "scalar/scalar.h"

namespace symrep::test {

/// An expression as a failure message shows it (long ones cut: the head is what helps).
inline std::string shown(const GiNaC::ex& e) {
    std::ostringstream o;
    o << e;
    std::string s = o.str();
    if (s.size() > 2000) s = s.substr(0, 2000) + " ... (" + std::to_string(s.size()) + " characters)";
    return s;
}

/// Exact equality of two expressions, for EXPECT_TRUE(same(a, b)) and EXPECT_FALSE(same(a, b)):
/// a - b expanded, tidied and proved 0 by the engine's exact zero test (is_zero_scalar,
/// scalar/scalar.h; it never guesses, so "not same" means "not proved equal"). Either way
/// the message shows both sides, and on failure their difference.
inline ::testing::AssertionResult same(const GiNaC::ex& a, const GiNaC::ex& b) {
    const GiNaC::ex d = symrep::tidy(GiNaC::expand(a - b));
    if (symrep::is_zero_scalar(d)) return ::testing::AssertionSuccess() << shown(a) << " equals " << shown(b);
    return ::testing::AssertionFailure() << "not proved equal:\n  left:  " << shown(a) << "\n  right: " << shown(b)
                                         << "\n  left - right: " << shown(d);
}

/// Coordinate by coordinate (elements of an algebra, vectors): the sizes, then same() of each.
inline ::testing::AssertionResult same(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b) {
    if (a.size() != b.size())
        return ::testing::AssertionFailure() << "sizes differ: " << a.size() << " and " << b.size();
    for (std::size_t k = 0; k < a.size(); ++k)
        if (auto r = same(a[k], b[k]); !r) return ::testing::AssertionFailure() << "coordinate " << k << ": " << r.message();
    return ::testing::AssertionSuccess() << "all " << a.size() << " coordinates equal";
}

/// Entry by entry: the shapes, then same() of each entry.
inline ::testing::AssertionResult same(const GiNaC::matrix& a, const GiNaC::matrix& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols())
        return ::testing::AssertionFailure() << "shapes differ: " << a.rows() << "x" << a.cols() << " and " << b.rows()
                                             << "x" << b.cols();
    for (unsigned r = 0; r < a.rows(); ++r)
        for (unsigned c = 0; c < a.cols(); ++c)
            if (auto x = same(a(r, c), b(r, c)); !x)
                return ::testing::AssertionFailure() << "entry (" << r << ", " << c << "): " << x.message();
    return ::testing::AssertionSuccess() << "all " << a.rows() * a.cols() << " entries equal";
}

/// The symbol called `name` inside e (a script's t, W ...), or 0 if there is none.
inline GiNaC::ex symbol_named(const GiNaC::ex& e, const std::string& name) {
    for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && GiNaC::ex_to<GiNaC::symbol>(*it).get_name() == name) return *it;
    return 0;
}

/// The what() of the exception f throws, or "<no exception>".
inline std::string what_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "<no exception>";
}

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

/// The lines of s, without their '\n'.
inline std::vector<std::string> lines_of(const std::string& s) {
    std::vector<std::string> v;
    std::istringstream in(s);
    for (std::string l; std::getline(in, l);) v.push_back(l);
    return v;
}

struct cli_result {
    std::string out, err;
    int status = -1;  ///< -1: killed by a signal
};

#ifdef SYMREP_BINARY
/// Runs `args` (shell syntax) with the symrep binary; stdin from `input` if given, else /dev/null.
/// With `cwd`, in that folder; with `merge_stderr`, standard error goes into `out` too (err stays empty).
inline cli_result run_symrep(const std::string& args, const std::string* input = nullptr,
                             const std::string& cwd = "", bool merge_stderr = false) {
    // Unique file names: ctest runs the tests in parallel processes.
    static int counter = 0;
    const std::string base = ::testing::TempDir() + "/symrep_cli_" + std::to_string(getpid()) + "_" +
                             std::to_string(counter++);
    const std::string err_path = base + "_err.txt";
    std::string cmd = (cwd.empty() ? std::string() : "cd '" + cwd + "' && ") + "'" + SYMREP_BINARY + "' " + args +
                      (merge_stderr ? std::string(" 2>&1") : " 2>'" + err_path + "'");
    if (input) {
        const std::string in_path = base + "_in.txt";
        std::ofstream(in_path, std::ios::binary) << *input;
        cmd += " <'" + in_path + "'";
    } else {
        cmd += " </dev/null";
    }
    cli_result r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
    const int st = pclose(p);
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.err = slurp(err_path);
    return r;
}
#endif

}  // namespace symrep::test
