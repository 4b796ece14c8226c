// tests/test_docs_examples.cpp -- the examples of the docs run and print what the docs say.
//
// The marked form (docs/testing.md, "Examples in the docs"): inside a fenced code block of
// docs/*.md, a statement followed by `# => TEXT` must print exactly TEXT (the echo of an
// expression statement, one line), and `# => error: TEXT` must fail with an error whose message
// contains TEXT. Every other line of such a block (an assignment, `vector w`, ...) runs too, in
// order, in one session per block; blank lines and whole-line comments are skipped. Blocks without
// a marker are prose and are not run. docs/language.md is generated from language.prose.md (read
// that instead) and `symrep --doc` (whose examples test_cli.cpp runs).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lang/interpreter.h"

using namespace symrep::lang;

namespace {

struct example_line {
    int line = 0;
    std::string statement, expected;
    bool marked = false;
};

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The marked blocks of one file.
std::vector<std::vector<example_line>> marked_blocks(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<example_line>> out;
    std::vector<example_line> block;
    bool inside = false, marked = false;
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
        if (trim(text).rfind("```", 0) == 0) {
            if (inside && marked) out.push_back(block);
            inside = !inside;
            block.clear();
            marked = false;
            continue;
        }
        if (!inside) continue;
        const std::string t = trim(text);
        if (t.empty() || t[0] == '#') continue;
        example_line l;
        l.line = n;
        const auto m = text.find("# =>");
        if (m != std::string::npos) {
            l.marked = marked = true;
            l.statement = trim(text.substr(0, m));
            l.expected = trim(text.substr(m + 4));
        } else {
            l.statement = t;
        }
        block.push_back(l);
    }
    return out;
}

}  // namespace

TEST(DocsExamples, MarkedExamplesPrintWhatTheDocsSay) {
    const std::filesystem::path docs = std::filesystem::path(SYMREP_SOURCE_DIR) / "docs";
    std::size_t checked = 0;
    for (const auto& f : std::filesystem::directory_iterator(docs)) {
        if (f.path().extension() != ".md" || f.path().filename() == "language.md") continue;
        for (const auto& block : marked_blocks(f.path().string())) {
            std::ostringstream out, err;
            session s(out, err);
            s.set_base_directory(SYMREP_SOURCE_DIR);
            for (const example_line& l : block) {
                out.str("");
                err.str("");
                const std::string where = f.path().filename().string() + ":" + std::to_string(l.line);
                const int status = s.run_string(l.statement, where);
                if (!l.marked) {
                    EXPECT_EQ(status, 0) << where << ": " << l.statement << "\n" << err.str();
                    continue;
                }
                ++checked;
                if (l.expected.rfind("error:", 0) == 0) {
                    EXPECT_NE(status, 0) << where << ": " << l.statement << " did not fail";
                    EXPECT_NE(err.str().find(trim(l.expected.substr(6))), std::string::npos)
                        << where << ": " << l.statement << "\n" << err.str();
                } else {
                    EXPECT_EQ(status, 0) << where << ": " << l.statement << "\n" << err.str();
                    EXPECT_EQ(trim(out.str()), l.expected) << where << ": " << l.statement;
                }
            }
        }
    }
    EXPECT_GE(checked, 20u) << "the docs lost their checked examples";
}
