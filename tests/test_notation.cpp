// tests/test_notation.cpp -- the two notations of the vector products: ascii
// (w x r, w . r) and unicode (w × r, w · r). The printer in both notations, the
// same term order in both, the lexer reading × · ⋅ and the bars |w|, the round
// trip parse(print(e)) == e, the notation() builtin, and the options --unicode /
// --ascii of the symrep program (the interactive default: test_interactive.cpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "lang/interpreter.h"
#include "syntax/lexer.h"
#include "output/printer.h"
#include "test_util.h"
#include "vector/vector.h"
#include "lang/print_value.h"

namespace {

using symrep::notation;
using symrep::lang::session;
using symrep::lang::tok;
using symrep::lang::value;

const std::string cross_sign = "\xC3\x97";  // ×
const std::string dot_sign = "\xC2\xB7";    // ·

/// s with every × replaced by x and every · by .
std::string to_ascii(std::string s) {
    for (const auto& [u, a] : {std::pair{cross_sign, std::string("x")}, std::pair{dot_sign, std::string(".")}})
        for (std::size_t p = s.find(u); p != std::string::npos; p = s.find(u, p + a.size())) s.replace(p, u.size(), a);
    return s;
}

/// Sets the process-wide notation for one test and puts the previous one back.
struct notation_scope {
    notation saved = symrep::vector_notation();
    explicit notation_scope(notation n) { symrep::set_vector_notation(n); }
    ~notation_scope() { symrep::set_vector_notation(saved); }
};

/// A session with the vectors of the thesis's problems declared.
struct vector_session {
    std::ostringstream out, err;
    session s{out, err};
    vector_session() { s.evaluate("vector a, b, c, d, w, g, r0, v0; positive w0"); }
    GiNaC::ex ex(const std::string& text) {
        const value v = s.evaluate(text);
        EXPECT_TRUE(v.is_ex()) << text;
        return v.is_ex() ? v.as_ex() : GiNaC::ex(0);
    }
};

// Expressions whose text has many terms and factors to order: results of
// solve, rewrite, vector_series, rotation_operator, triple products (printed
// a . (b x c): the thesis's [a, b, c] would read back as a list).
const std::vector<std::string> corpus = {
    "a x (b x c)",
    "(a . c)*b - (a . b)*c + w x (w x r0)",
    "norm(w)^2*r0 + (r0 . w)*w - 2*((a x b) . (c x d))*g",
    "rotation_operator(w, t, r0)",
    "solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))",
    "solve(ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0))",
    "rewrite(a x (b x (c x d)))",
    "vector_series(rotation_operator(w, t, r0), w, 3)",
    "sin(norm(w)*t)/norm(w)*(w x g) + (g . w)*t^2*w/2",
    "(a . b)^2/norm(a x b)^3 - norm(a + 2*b)",
    // a scene: literals in the terms, t^2*[0, 0, -10]/2 + ...
    "solve(ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0), [w = [0, 0, 1], g = [0, 0, -10]])",
    "w + [1, 2, 3] - 2*t*[0, 0, 1] + r0 x [1, 0, 0]",
    "triple(a, b, c)^2 - 3*triple(c, b, a)*t + triple(a, b x c, d)",
};

TEST(Notation, PrinterWritesTheProductsInEitherNotation) {
    vector_session v;
    const GiNaC::ex e = v.ex("a x (b x c) + (a . b)*c");
    EXPECT_EQ(symrep::to_string(e, notation::ascii), "(a x (b x c)) + (a . b)*c");
    EXPECT_EQ(symrep::to_string(e, notation::unicode), "(a × (b × c)) + (a · b)*c");
    EXPECT_EQ(symrep::to_string(v.ex("norm(w)^2*(w . r0)"), notation::unicode), "(r0 · w)*|w|^2");
    {
        notation_scope u(notation::unicode);
        EXPECT_EQ(symrep::output::print_ex(v.ex("w x r0")), "-(r0 × w)");
        // a problem prints its equation in the notation too
        EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("ode(r' + w x r = 0, r(0) = r0)")),
                  "ode(-(r × w) + r' = 0, r(0) = r0)");
    }
    EXPECT_EQ(symrep::output::print_ex(v.ex("w x r0")), "-(r0 x w)");
}

// The unicode text is the ascii text with the two signs replaced: the same terms
// and factors in the same order (the printer sorts by the ascii text).
TEST(Notation, BothNotationsOrderTermsAlike) {
    vector_session v;
    for (const std::string& text : corpus) {
        const GiNaC::ex e = v.ex(text);
        const std::string a = symrep::to_string(e, notation::ascii);
        const std::string u = symrep::to_string(e, notation::unicode);
        EXPECT_NE(u.find(cross_sign), std::string::npos) << text << " -> " << u;
        EXPECT_EQ(u.find(" x "), std::string::npos) << u;
        EXPECT_EQ(to_ascii(u), a) << text;
    }
}

// What the printer writes reads back as the same value, in both notations.
TEST(Notation, PrintedTextReadsBackAsTheSameValue) {
    for (const notation n : {notation::unicode, notation::ascii}) {
        notation_scope scope(n);
        vector_session v;
        for (const std::string& text : corpus) {
            const GiNaC::ex e = v.ex(text);
            const std::string printed = symrep::output::print_ex(e);
            const GiNaC::ex back = v.ex(printed);
            EXPECT_TRUE(symrep::equal(e, back)) << text << "\n printed: " << printed;
            // reading may only combine literal arithmetic (t^2*[0, 0, -10]/2 -> [0, 0, -5*t^2]):
            // from then on the text is a fixed point
            const std::string again = symrep::output::print_ex(back);
            EXPECT_EQ(symrep::output::print_ex(v.ex(again)), again) << text;
            if (printed.find('[') == std::string::npos) {
                EXPECT_EQ(again, printed) << text;
            }
        }
    }
}

// A literal term in a vector sum: [1, 2, 3] + v0 was refused ("cannot combine a
// matrix with v0"), so printed solutions with literals did not read back.
TEST(Notation, LiteralTermsInVectorSums) {
    vector_session v;
    EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("[1, 2, 3] + r0")), "[1, 2, 3] + r0");
    EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("r0 - t*[0, 0, 2]")), "-[0, 0, 2*t] + r0");
    EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("eval([1, 2, 3] + r0, [r0 = [1, 1, 1]])")), "[2.0, 3.0, 4.0]");
    EXPECT_EQ(symrep::test::what_of([&] { v.s.evaluate("matrix([[1], [2]]) + r0"); }),
              "a 2x1 matrix is not a vector (vector literals are 3x1)");
}

TEST(Notation, LexerReadsTheUnicodeSigns) {
    const auto t = symrep::lang::tokenize("a × b · c ⋅ d");
    ASSERT_EQ(t.size(), 8u);
    EXPECT_EQ(t[1].kind, tok::op);
    EXPECT_EQ(t[1].text, cross_sign);
    EXPECT_EQ(t[3].text, ".");
    EXPECT_EQ(t[5].text, ".");
    // columns count characters, not bytes
    EXPECT_EQ(t[2].column, 5);
    EXPECT_EQ(t[6].column, 13);
    vector_session v;
    EXPECT_TRUE(symrep::equal(v.ex("w × (w × r0) + (g · w)*w"), v.ex("w x (w x r0) + (g . w)*w")));
    EXPECT_TRUE(symrep::equal(v.ex("a×b"), v.ex("a x b")));
    EXPECT_TRUE(symrep::equal(v.ex("w ⋅ g"), v.ex("w . g")));
}

TEST(Notation, OtherCharactersAreClearErrors) {
    auto first_error = [](const std::string& text) {
        for (const auto& k : symrep::lang::tokenize(text))
            if (k.kind == tok::error) return k.text + " at " + std::to_string(k.column);
        return std::string("no error");
    };
    EXPECT_EQ(first_error("1 + é"), "unexpected character 'é' at 5");
    EXPECT_EQ(first_error("1 + \xff"), "unexpected character byte 255 at 5");
    EXPECT_EQ(first_error("\xC3"), "unexpected character byte 195 at 1");      // truncated
    EXPECT_EQ(first_error("\xE0\x80\x80"), "unexpected character byte 224 at 1");  // overlong
    std::ostringstream out, err;
    session s(out, err);
    EXPECT_EQ(s.run_string("1 ∧ 2\n", "u.sr"), 1);
    EXPECT_EQ(err.str(), "u.sr:1:3: error: syntax error: unexpected character '∧'\n");
}

TEST(Notation, BarsAreTheNormOfAVectorAndTheAbsoluteValueOfAScalar) {
    vector_session v;
    EXPECT_TRUE(symrep::equal(v.ex("|w|"), v.ex("norm(w)")));
    EXPECT_TRUE(symrep::equal(v.ex("|a|*|b| + |a x b|^2"), v.ex("norm(a)*norm(b) + norm(a x b)^2")));
    EXPECT_TRUE(symrep::equal(v.ex("||a|*b - c|"), v.ex("norm(norm(a)*b - c)")));
    EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("|[3, 4, 12]|")), "13");
    EXPECT_EQ(symrep::lang::print_value(v.s.evaluate("|-2/3|")), "2/3");
    std::ostringstream out, err;
    session s(out, err);
    EXPECT_EQ(s.run_string("|\"s\"|\n|1 + 2\n", "n.sr"), 2);
    EXPECT_EQ(err.str(),
              "n.sr:1:1: error: |...| needs a vector or a scalar expression, not a string\n"
              "n.sr:2:7: error: syntax error: expected '|' to close |...|, found end of line\n");
}

TEST(Notation, BuiltinSwitchesAndTheSessionRestores) {
    notation_scope scope(notation::ascii);
    {
        std::ostringstream out, err;
        session s(out, err);
        EXPECT_EQ(s.run_string("vector a, b\nnotation()\nnotation(\"unicode\")\na x b\nnotation()\n"
                               "notation(\"ascii\")\na x b\nnotation(\"greek\")\nnotation(1)\n",
                               "n.sr"),
                  2);
        EXPECT_EQ(out.str(), "\"ascii\"\n\"ascii\"\na × b\n\"unicode\"\n\"unicode\"\na x b\n");
        EXPECT_EQ(err.str(),
                  "n.sr:8:1: error: notation: the notation is \"unicode\" or \"ascii\", not \"greek\"\n"
                  "n.sr:9:1: error: notation: argument 1 must be a string, not an expression (usage: "
                  "notation(\"unicode\" | \"ascii\"))\n");
        s.evaluate("notation(\"unicode\")");
        EXPECT_EQ(symrep::vector_notation(), notation::unicode);
    }
    EXPECT_EQ(symrep::vector_notation(), notation::ascii);  // like Digits, per session
}

#ifdef SYMREP_BINARY
TEST(Notation, CommandLineOptions) {
    using symrep::test::run_symrep;
    const std::string code = " -e 'vector w, r; w x (w x r); (w . r)*w'";
    const auto ascii = run_symrep(code);
    EXPECT_EQ(ascii.out, "-(w x (r x w))\n(r . w)*w\n");
    const auto unicode = run_symrep("--unicode" + code);
    EXPECT_EQ(unicode.status, 0) << unicode.err;
    EXPECT_EQ(unicode.out, "-(w × (r × w))\n(r · w)*w\n");
    EXPECT_EQ(run_symrep("--unicode --ascii" + code).out, ascii.out);  // the last one counts
    // scripts and pipes stay ascii in a UTF-8 locale: the output of a script is the same everywhere
    const std::string saved = std::getenv("LC_ALL") ? std::getenv("LC_ALL") : "";
    setenv("LC_ALL", "C.UTF-8", 1);
    EXPECT_EQ(run_symrep(code).out, ascii.out);
    const std::string piped = "vector w, r\nw x r\n";
    EXPECT_EQ(run_symrep("", &piped).out, "-(r x w)\n");
    if (saved.empty()) unsetenv("LC_ALL");
    else setenv("LC_ALL", saved.c_str(), 1);
    // what --unicode prints reads back
    const auto back = run_symrep("--unicode -e 'vector w, r; w × (w × r) + |w|^2*r == (w · r)*w'");
    EXPECT_EQ(back.out, "true\n") << back.err;
    EXPECT_NE(run_symrep("--help").out.find("--unicode"), std::string::npos);
}

// Columns count characters: the echo of a statement and the caret under an
// error are right after × and ·, which take two bytes each.
TEST(Notation, EchoAndCaretCountCharacters) {
    const auto r = symrep::test::run_symrep("--echo -e 'vector a, b; a × b == a x b; 1 + nosuch(a · b)'", nullptr, "",
                                            true);
    EXPECT_EQ(r.out,
              "> vector a, b\n> a × b == a x b\ntrue\n> 1 + nosuch(a · b)\n"
              "<command line>:1:34: error: unknown function 'nosuch' (help() lists all functions)\n"
              "    vector a, b; a × b == a x b; 1 + nosuch(a · b)\n"
              "                                     ^\n");
}
#endif

}  // namespace
