// tests/test_cli.cpp -- the symrep program end to end (popen of SYMREP_BINARY),
// the generated reference in docs/language.md, and the examples of every builtin.
#include <gtest/gtest.h>

#include "test_util.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "lang/interpreter.h"
#include "syntax/parser.h"
#include "test_support.h"

using namespace symrep::lang;

namespace {

using result = symrep::test::cli_result;
using symrep::test::slurp;

result run(const std::string& args, const std::string* input = nullptr) {
    return symrep::test::run_symrep(args, input);
}

}  // namespace

TEST(Cli, Version) {
    result r = run("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "symrep " SYMREP_VERSION "\n");
}

TEST(Cli, Help) {
    result r = run("--help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("usage: symrep"), std::string::npos);
    EXPECT_NE(r.out.find("--doc"), std::string::npos);
    result bad = run("--bogus");
    EXPECT_EQ(bad.status, 2);
}

TEST(Cli, CommandLineStatements) {
    result r = run("-e 'a := 2; a^10' -e 'expand((x + 1)^2)'");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "1024\nx^2 + 2*x + 1\n");
    EXPECT_EQ(r.err, "");
}

TEST(Cli, ErrorInTheMiddleOfAScript) {
    const std::string path = ::testing::TempDir() + "/symrep_cli_script.sr";
    std::ofstream(path) << "1 + 1\n2 * nosuch(1)\n3 + 3\n";
    result r = run("'" + path + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "2\n6\n");
    EXPECT_EQ(r.err.rfind(path + ":2:5: error: unknown function 'nosuch'", 0), 0u) << r.err;
}

TEST(Cli, StdinPipe) {
    const std::string input = "x := 3\nx^2\n1/0\n[1,\n 2]\n";
    result r = run("", &input);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "9\n[1, 2]\n");
    EXPECT_EQ(r.err.rfind("<stdin>:3:2: error: division by zero", 0), 0u) << r.err;
    const std::string ok = "print(\"fine\")\n";
    result r2 = run("", &ok);
    EXPECT_EQ(r2.status, 0);
    EXPECT_EQ(r2.out, "fine\n");
}

TEST(Cli, CommandLineErrorFormat) {
    result r = run("-e '1 +* 2'");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err.rfind("<command line>:1:4: error: syntax error:", 0), 0u) << r.err;
    result m = run("/nonexistent/none.sr");
    EXPECT_EQ(m.status, 1);
    EXPECT_NE(m.err.find("error: cannot open"), std::string::npos);
}

TEST(Cli, LanguageDocContainsTheReference) {
    result r = run("--doc");
    EXPECT_EQ(r.status, 0);
    ASSERT_GT(r.out.size(), 1000u);
    registry reg;
    register_all_builtins(reg);
    EXPECT_EQ(r.out, reference_markdown(reg));
    const std::string doc = slurp(std::string(SYMREP_SOURCE_DIR) + "/docs/language.md");
    EXPECT_NE(doc.find(r.out), std::string::npos)
        << "docs/language.md is out of date: regenerate its reference part with `symrep --doc`";
}

// Every builtin's example runs without error. Examples that call functions not
// registered in this build (the algebra families' constructors, before they are
// integrated) are skipped and listed.
TEST(Cli, EveryBuiltinExampleRuns) {
    registry reg;
    register_all_builtins(reg);
    std::vector<std::string> skipped;
    std::size_t ran = 0;
    for (const builtin* b : reg.all()) {
        ASSERT_FALSE(b->example.empty()) << b->name << " has no example";
        ASSERT_FALSE(b->signature.empty()) << b->name;
        ASSERT_FALSE(b->summary.empty()) << b->name;
        std::set<std::string> names;
        for (const auto& s : parse_program(b->example, "<example>")) symrep::test::called_names(*s, names);
        EXPECT_TRUE(names.count(b->name)) << "the example of " << b->name << " does not call it";
        std::string missing;
        for (const auto& n : names)
            if (!reg.find(n)) missing += (missing.empty() ? "" : ", ") + n;
        if (!missing.empty()) {
            skipped.push_back(b->name + " (needs " + missing + ")");
            continue;
        }
        std::ostringstream out, err;
        session s(out, err);
        s.set_base_directory(SYMREP_SOURCE_DIR);
        EXPECT_EQ(s.run_string(b->example, "<example of " + b->name + ">"), 0) << err.str();
        ++ran;
    }
    EXPECT_GT(ran, 40u);
    std::string list;
    for (const auto& s : skipped) list += "  " + s + "\n";
    std::cout << "[ examples ] ran " << ran << ", skipped " << skipped.size()
              << (skipped.empty() ? "" : ":\n" + list);
}

// Two processes creating the symbols in opposite orders print the same text.
TEST(Cli, OutputIsDeterministicAcrossProcesses) {
    const std::string body = "expand((a + b + c)^3 - a*c); expand((c - a)^2*(b + 1)); [c*b*a, (c + a)^2]";
    result r1 = run("-e 'q := [a, b, c]; " + body + "'");
    result r2 = run("-e 'q := [c, b, a]; w := expand((z + y)^4); " + body + "'");
    EXPECT_EQ(r1.status, 0);
    EXPECT_EQ(r1.out, r2.out);
    EXPECT_NE(r1.out.find("a^3 + 3*a^2*b + 3*a^2*c"), std::string::npos) << r1.out;
}
