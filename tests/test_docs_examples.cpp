// tests/test_docs_examples.cpp -- the symrep examples of the docs run, and print what the docs say.
//
// Every fenced code block of docs/*.md in the symrep language runs (docs/testing.md, "Examples in
// the docs"): a block whose fence names no language (the site highlights it as symrep:
// docs/conf.py) or names `symrep`. The words after the language are flags: `continued` runs the
// block in the session of the page's previous symrep block (it uses its names), `norun` shows
// it without running it (it needs a file the reader writes). A block of another language names
// it at the fence (```sh, ```text, ```cpp, ```python: tests/python/test_docs_site.py runs the
// Python ones).
//
// In a block, a statement followed by `# => TEXT` must print exactly TEXT (the echo of an
// expression statement, one line), and `# => error: TEXT` must fail with an error whose message
// contains TEXT; every other statement must succeed (the lines between two marked lines run as
// one piece of script, so a statement may continue over lines). docs/language.md is generated
// from language.prose.md (read that instead) and `symrep --doc` (whose examples test_cli.cpp
// runs). The blocks run in a scratch directory: a picture a block draws is not written into the
// source tree.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
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

struct code_block {
    int line = 0;          // the line of the opening fence
    std::string language;  // the first word of the fence's info string
    bool continued = false, norun = false;
    std::vector<example_line> lines;
};

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The fenced code blocks of one file.
std::vector<code_block> code_blocks(const std::string& path) {
    std::ifstream in(path);
    std::vector<code_block> out;
    code_block block;
    bool inside = false;
    std::string text;
    for (int n = 1; std::getline(in, text); ++n) {
        const std::string t = trim(text);
        if (t.rfind("```", 0) == 0) {
            if (inside) {
                out.push_back(block);
            } else {
                block = code_block{};
                block.line = n;
                std::istringstream info(t.substr(3));
                info >> block.language;
                for (std::string flag; info >> flag;) {
                    if (flag == "continued") block.continued = true;
                    else if (flag == "norun") block.norun = true;
                    else ADD_FAILURE() << path << ":" << n << ": unknown flag '" << flag << "' of a code block";
                }
            }
            inside = !inside;
            continue;
        }
        if (!inside || t.empty() || t[0] == '#') continue;
        example_line l;
        l.line = n;
        const auto m = text.find("# =>");
        if (m != std::string::npos) {
            l.marked = true;
            l.statement = trim(text.substr(0, m));
            l.expected = trim(text.substr(m + 4));
        } else {
            l.statement = text;
        }
        block.lines.push_back(l);
    }
    return out;
}

struct page_session {
    std::ostringstream out, err;
    session s{out, err};
};

}  // namespace

TEST(DocsExamples, EverySymrepBlockRunsAndPrintsWhatTheDocsSay) {
    const std::filesystem::path docs = std::filesystem::path(SYMREP_SOURCE_DIR) / "docs";
    const std::filesystem::path scratch = std::filesystem::temp_directory_path() / "symrep_docs_examples";
    std::filesystem::create_directories(scratch);
    std::size_t checked = 0, blocks = 0;
    for (const auto& f : std::filesystem::directory_iterator(docs)) {
        if (f.path().extension() != ".md" || f.path().filename() == "language.md") continue;
        const std::string file = f.path().filename().string();
        std::unique_ptr<page_session> ps;
        for (const code_block& block : code_blocks(f.path().string())) {
            if (!block.language.empty() && block.language != "symrep") continue;
            if (block.norun) continue;
            ++blocks;
            EXPECT_TRUE(!block.continued || ps) << file << ":" << block.line << ": 'continued' without a block before";
            if (!block.continued || !ps) {
                ps = std::make_unique<page_session>();
                ps->s.set_base_directory(scratch.string());
            }
            session& s = ps->s;
            // runs text as one piece; returns the status
            auto run = [&](const std::string& text, int line) {
                ps->out.str("");
                ps->err.str("");
                return s.run_string(text, file + ":" + std::to_string(line));
            };
            std::string piece;
            int piece_line = 0;
            auto flush = [&] {
                if (piece.empty()) return;
                EXPECT_EQ(run(piece, piece_line), 0) << file << ":" << piece_line << ":\n" << piece << "\n" << ps->err.str()
                                                     << "(a block meant to fail marks the line: # => error: TEXT)";
                piece.clear();
            };
            for (const example_line& l : block.lines) {
                if (!l.marked) {
                    if (piece.empty()) piece_line = l.line;
                    piece += l.statement + "\n";
                    continue;
                }
                flush();
                ++checked;
                const std::string where = file + ":" + std::to_string(l.line);
                const int status = run(l.statement, l.line);
                if (l.expected.rfind("error:", 0) == 0) {
                    EXPECT_NE(status, 0) << where << ": " << l.statement << " did not fail";
                    EXPECT_NE(ps->err.str().find(trim(l.expected.substr(6))), std::string::npos)
                        << where << ": " << l.statement << "\n" << ps->err.str();
                } else {
                    EXPECT_EQ(status, 0) << where << ": " << l.statement << "\n" << ps->err.str();
                    EXPECT_EQ(trim(ps->out.str()), l.expected) << where << ": " << l.statement;
                }
            }
            flush();
        }
    }
    std::filesystem::remove_all(scratch);
    EXPECT_GE(checked, 20u) << "the docs lost their checked examples";
    EXPECT_GE(blocks, 20u) << "the docs lost their symrep examples";
}
