// tests/test_transcripts.cpp -- transcript tests: script in, values out.
//
// Every tests/transcripts/NAME.symrep is one test case, Transcripts/Run.NAME. It
// is run by the symrep program as a user would run it,
//     symrep --echo NAME.symrep 2>&1
// in a fresh copy of tests/transcripts/ (so that the files it writes and the
// files it load()s sit next to it), and the output must be exactly NAME.out:
// each statement as "> SOURCE", then its value, what print() writes, and the
// error report with the caret where a statement fails. The exit status must be
// 1 when NAME.out holds an error report and 0 otherwise. The line verify()
// prints is compared with its difference, where it occurs and the timings
// masked (`<difference> (<where>)`, `; <timings>`: they depend on the machine;
// a transcript tests the value verify returns instead, as in
// `verify(...) < 1e-9`). A comment
//     # file: NAME png|svg
// in the script asks for a file NAME, written by the script, holding a PNG
// (its signature) or an SVG picture (an <svg element).
//
// The expected outputs are committed and were checked by hand or by an
// independent computation (the comments of each script say how), not only
// recorded: tests/transcripts/README.md explains how to add one. With the
// environment variable SYMREP_WRITE_TRANSCRIPTS=1 the test writes the output
// into NAME.out instead of comparing it (then check the diff value by value).
// Transcripts.EveryBuiltinIsCalled fails when a builtin of the registry is
// called by no transcript, so a new builtin needs one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "syntax/parser.h"
#include "test_support.h"
#include "test_util.h"

namespace {

namespace fs = std::filesystem;

const fs::path transcripts_dir = fs::path(SYMREP_SOURCE_DIR) / "tests" / "transcripts";

/// The NAMEs of tests/transcripts/NAME.symrep, sorted.
std::vector<std::string> transcript_names() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(transcripts_dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".symrep") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// A copy of tests/transcripts/ in a new temporary folder, removed at the end.
struct scratch_copy {
    fs::path path;
    scratch_copy() {
        std::string t = ::testing::TempDir() + "/symrep_transcript_XXXXXX";
        if (!mkdtemp(t.data())) return;
        path = t;
        std::error_code ec;
        fs::copy(transcripts_dir, path, fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
        if (ec) path.clear();
    }
    ~scratch_copy() {
        std::error_code ec;
        if (!path.empty()) fs::remove_all(path, ec);
    }
};

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// The output with the machine-dependent numbers of verify()'s report masked.
std::string masked(const std::string& out) {
    static const std::regex difference(R"(^(verify: max relative difference )\S+ \([^)]*\))");
    std::istringstream in(out);
    std::string r, line;
    while (std::getline(in, line)) {
        if (line.rfind("verify: ", 0) == 0) {
            line = std::regex_replace(line, difference, "$1<difference> (<where>)");
            line = line.substr(0, line.find("; ")) + "; <timings>";
        }
        r += line + "\n";
    }
    if (!out.empty() && out.back() != '\n') r.pop_back();
    return r;
}

using symrep::test::lines_of;

/// The lines that differ, in order: "- " expected only, "+ " actual only, with
/// one line of context (a longest common subsequence of the lines).
std::string line_diff(const std::string& expected, const std::string& actual) {
    const std::vector<std::string> a = lines_of(expected), b = lines_of(actual);
    std::vector<std::vector<int>> L(a.size() + 1, std::vector<int>(b.size() + 1, 0));
    for (std::size_t i = a.size(); i-- > 0;)
        for (std::size_t j = b.size(); j-- > 0;)
            L[i][j] = a[i] == b[j] ? L[i + 1][j + 1] + 1 : std::max(L[i + 1][j], L[i][j + 1]);
    std::vector<std::string> d;  // "  ", "- ", "+ " lines
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        if (i < a.size() && j < b.size() && a[i] == b[j]) d.push_back("  " + a[i++]), ++j;
        else if (i < a.size() && (j == b.size() || L[i + 1][j] >= L[i][j + 1])) d.push_back("- " + a[i++]);
        else d.push_back("+ " + b[j++]);
    }
    std::string out;
    for (std::size_t k = 0; k < d.size(); ++k) {
        const auto changed = [&](std::size_t m) { return m < d.size() && d[m][0] != ' '; };
        if (changed(k) || changed(k + 1) || (k > 0 && changed(k - 1))) out += d[k] + "\n";
    }
    return out;
}

class Run : public ::testing::TestWithParam<std::string> {};

TEST_P(Run, OutputIsTheTranscript) {
    const std::string name = GetParam();
    const std::string script = symrep::test::slurp((transcripts_dir / (name + ".symrep")).string());
    const std::string expected = symrep::test::slurp((transcripts_dir / (name + ".out")).string());
    scratch_copy dir;
    ASSERT_FALSE(dir.path.empty()) << "cannot copy " << transcripts_dir;
    const symrep::test::cli_result r =
        symrep::test::run_symrep("--echo " + shell_quote(name + ".symrep"), nullptr, dir.path.string(), true);
    const std::string out = masked(r.out);
    const char* write = std::getenv("SYMREP_WRITE_TRANSCRIPTS");
    if (write && std::string(write) == "1") {
        std::ofstream((transcripts_dir / (name + ".out")).string(), std::ios::binary) << out;
        GTEST_SKIP() << "wrote tests/transcripts/" << name << ".out: check every value in it";
    }
    ASSERT_FALSE(expected.empty()) << "tests/transcripts/" << name << ".out is missing or empty";
    EXPECT_TRUE(out == expected) << "tests/transcripts/" << name << ".out differs from the output (- expected, "
                                 << "+ actual):\n" << line_diff(expected, out);
    const bool failures = expected.find(": error: ") != std::string::npos;
    EXPECT_EQ(r.status, failures ? 1 : 0) << r.out;
    static const std::regex file_line(R"(#\s*file:\s*(\S+)\s+(png|svg)\s*(?:\n|$))");
    for (std::sregex_iterator m(script.begin(), script.end(), file_line), end; m != end; ++m) {
        const std::string file = (*m)[1], kind = (*m)[2];
        const std::string bytes = symrep::test::slurp((dir.path / file).string());
        const bool ok = kind == "png" ? bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0 : bytes.find("<svg") != std::string::npos;
        EXPECT_TRUE(ok) << name << ": " << file << " is missing or not a" << (kind == "png" ? " PNG" : "n SVG")
                        << " picture";
    }
}

INSTANTIATE_TEST_SUITE_P(Transcripts, Run, ::testing::ValuesIn(transcript_names()),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                             std::string n = p.param;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

TEST(Transcripts, EveryScriptHasItsOutput) {
    const std::vector<std::string> names = transcript_names();
    EXPECT_GE(names.size(), 10u);
    for (const std::string& n : names)
        EXPECT_TRUE(fs::exists(transcripts_dir / (n + ".out"))) << "tests/transcripts/" << n << ".out is missing";
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(transcripts_dir, ec)) {
        if (e.path().extension() == ".out") {
            EXPECT_TRUE(fs::exists(transcripts_dir / (e.path().stem().string() + ".symrep")))
                << e.path() << " has no script";
        }
    }
}

// Every builtin of the registry is called by some transcript.
TEST(Transcripts, EveryBuiltinIsCalled) {
    std::set<std::string> called;
    for (const std::string& n : transcript_names()) {
        const std::string file = (transcripts_dir / (n + ".symrep")).string();
        for (const auto& s : symrep::lang::parse_program(symrep::test::slurp(file), file))
            symrep::test::called_names(*s, called);
    }
    symrep::lang::registry reg;
    symrep::lang::register_all_builtins(reg);
    std::string missing;
    for (const symrep::lang::builtin* b : reg.all())
        if (!called.count(b->name)) missing += " " + b->name;
    EXPECT_EQ(missing, "") << "builtins called by no transcript in tests/transcripts/ (add one, see its README.md)";
}

}  // namespace
