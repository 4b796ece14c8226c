// tests/test_util.h -- small helpers shared by the test files: the message of
// an expected exception, and running the symrep program (SYMREP_BINARY).
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

namespace symrep::test {

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
