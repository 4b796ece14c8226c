// tests/test_lexer_parser.cpp -- tokens, grammar, precedence, locations.
#include <gtest/gtest.h>

#include "syntax/lexer.h"
#include "syntax/parser.h"

using namespace symrep::lang;

namespace {
std::string sexpr(const node& n) {
    switch (n.kind) {
        case node::number: case node::ident: case node::boolean: case node::result: return n.text;
        case node::string: return "\"" + n.text + "\"";
        case node::unary: return "(" + n.text + " " + sexpr(*n.kids[0]) + ")";
        case node::binary: return "(" + n.text + " " + sexpr(*n.kids[0]) + " " + sexpr(*n.kids[1]) + ")";
        case node::chain: {
            std::string s = sexpr(*n.kids[0]);
            for (std::size_t i = 0; i < n.text.size(); ++i)
                s = "(" + std::string(1, n.text[i]) + " " + s + " " + sexpr(*n.kids[i + 1]) + ")";
            return s;
        }
        case node::index: return "(at " + sexpr(*n.kids[0]) + " " + sexpr(*n.kids[1]) + ")";
        case node::assign: return "(:= " + n.text + " " + sexpr(*n.kids[0]) + ")";
        case node::call: case node::list: case node::declare: {
            std::string s = n.kind == node::call ? "(" + n.text : n.kind == node::list ? "(list" : "(" + n.text;
            for (const auto& k : n.kids) s += " " + sexpr(*k);
            return s + ")";
        }
    }
    return "?";
}
std::string parse1(const std::string& t) {
    auto p = parse_program(t, "x");
    EXPECT_EQ(p.size(), 1u) << t;
    return p.empty() ? "" : sexpr(*p[0]);
}
}  // namespace

TEST(Lexer, TokensAndPositions) {
    auto t = tokenize("ab := 3.5 # comment\n  f(\"q\\\"x\")");
    ASSERT_GE(t.size(), 8u);
    EXPECT_EQ(t[0].kind, tok::ident);
    EXPECT_EQ(t[0].text, "ab");
    EXPECT_EQ(t[1].text, ":=");
    EXPECT_EQ(t[1].column, 4);
    EXPECT_EQ(t[2].kind, tok::number);
    EXPECT_EQ(t[2].text, "3.5");
    EXPECT_EQ(t[3].kind, tok::separator);
    EXPECT_EQ(t[4].text, "f");
    EXPECT_EQ(t[4].line, 2);
    EXPECT_EQ(t[4].column, 3);
    EXPECT_EQ(t[6].kind, tok::string);
    EXPECT_EQ(t[6].text, "q\"x");
}

TEST(Lexer, NewlinesInsideBracketsContinueTheStatement) {
    auto t = tokenize("f(1,\n 2)\n[3,\n4]");
    int seps = 0;
    for (const auto& k : t) seps += k.kind == tok::separator;
    EXPECT_EQ(seps, 1);
    EXPECT_TRUE(needs_more_input("f(1,"));
    EXPECT_TRUE(needs_more_input("[1, \"a"));
    EXPECT_FALSE(needs_more_input("f(1, 2) # (\n"));
}

// issue 13: the recovery rule for unclosed brackets, the stream reader's line
// tracker, statements read from the middle of a stream, the byte order mark
TEST(Lexer, UnclosedBracketEndsAtALineStartingAStatement) {
    EXPECT_TRUE(starts_statement("  y := 2"));
    EXPECT_TRUE(starts_statement("vector w, v"));
    EXPECT_TRUE(starts_statement("positive g"));
    EXPECT_FALSE(starts_statement("vector"));
    EXPECT_FALSE(starts_statement("  + y"));
    EXPECT_FALSE(starts_statement("y == 2"));
    auto t = tokenize("x := f(1,\ny := 2");
    ASSERT_GE(t.size(), 9u);
    EXPECT_EQ(t[6].kind, tok::error);
    EXPECT_EQ(t[6].text, "'(' opened at line 1, column 7 is not closed (the next line starts a new statement)");
    EXPECT_EQ(t[7].kind, tok::separator);
    EXPECT_EQ(t[8].text, "y");
    EXPECT_EQ(t[8].line, 2);
    EXPECT_FALSE(needs_more_input("x := f(1,\ny := 2"));
    EXPECT_TRUE(needs_more_input("x := f(1,\n  y + 2"));
    line_tracker lt;
    lt.feed("[1,");
    EXPECT_FALSE(lt.complete());
    lt.feed(" 2] # ) (");
    EXPECT_TRUE(lt.complete());
    lt.feed("1 + \\");
    EXPECT_FALSE(lt.complete());
    lt.feed("2");
    EXPECT_TRUE(lt.complete());
    lt.feed("\"(\" + (");
    EXPECT_FALSE(lt.complete());
}

TEST(Lexer, FirstLineAndByteOrderMark) {
    auto t = tokenize("\n  a", 40);
    ASSERT_GE(t.size(), 2u);
    EXPECT_EQ(t[1].line, 41);
    EXPECT_EQ(t[1].column, 3);
    auto b = tokenize("\xEF\xBB\xBF" "1");
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0].kind, tok::number);
    EXPECT_EQ(b[0].column, 1);
    auto later = tokenize("\xEF\xBB\xBF" "1", 2);  // only at the start of the text
    EXPECT_EQ(later[0].kind, tok::error);
}

TEST(Lexer, BadCharacterIsAnErrorToken) {
    auto t = tokenize("1 $ 2");
    EXPECT_EQ(t[1].kind, tok::error);
    EXPECT_EQ(t[1].column, 3);
}

TEST(Parser, Precedence) {
    EXPECT_EQ(parse1("1 + 2 * 3"), "(+ 1 (* 2 3))");
    EXPECT_EQ(parse1("1 - 2 - 3"), "(- (- 1 2) 3)");
    EXPECT_EQ(parse1("2 ^ 3 ^ 2"), "(^ 2 (^ 3 2))");
    EXPECT_EQ(parse1("-x ^ 2"), "(- (^ x 2))");
    EXPECT_EQ(parse1("2 ^ -1"), "(^ 2 (- 1))");
    EXPECT_EQ(parse1("a / b * c"), "(* (/ a b) c)");
    EXPECT_EQ(parse1("x + 1 = y * 2"), "(= (+ x 1) (* y 2))");
    EXPECT_EQ(parse1("a == b + 1"), "(== a (+ b 1))");
    EXPECT_EQ(parse1("(1 + 2) * 3"), "(* (+ 1 2) 3)");
}

TEST(Parser, CallsListsIndexingAssignment) {
    EXPECT_EQ(parse1("f(a, [1, 2], g())"), "(f a (list 1 2) (g))");
    EXPECT_EQ(parse1("l[0][1]"), "(at (at l 0) 1)");
    EXPECT_EQ(parse1("v := [1, \"s\"]"), "(:= v (list 1 \"s\"))");
    EXPECT_EQ(parse1("true"), "true");
    EXPECT_EQ(parse_program("1; 2\n3;;\n", "x").size(), 3u);
}

TEST(Parser, SyntaxErrorLocationAndRecovery) {
    parser p("1 +\n2 ) 3\nx := 4", "f.sr");
    try {
        p.next_statement();
        FAIL() << "no syntax error";
    } catch (const symrep::syntax_error& e) {
        EXPECT_EQ(e.where.file, "f.sr");
        EXPECT_EQ(e.where.line, 1);
        EXPECT_EQ(e.where.column, 4);
    }
    p.recover();
    EXPECT_THROW(p.next_statement(), symrep::syntax_error);  // "2 ) 3"
    p.recover();
    auto s = p.next_statement();
    ASSERT_TRUE(s);
    EXPECT_EQ(s->kind, node::assign);
    EXPECT_EQ(s->line, 3);
    EXPECT_TRUE(p.at_end());
}

TEST(Parser, RelationsDoNotChain) {
    EXPECT_THROW(parse_program("a = b = c", "x"), symrep::syntax_error);
    EXPECT_THROW(parse_program("f(1,", "x"), symrep::syntax_error);
    EXPECT_THROW(parse_program("\"open", "x"), symrep::syntax_error);
}

// Vectors (thesis Ch. VI): x and . bind tighter than * and group to the right;
// x is a name where no operand follows; primes belong to names; declarations.
TEST(Parser, VectorOperatorsPrimesAndDeclarations) {
    EXPECT_EQ(parse1("w x w x r"), "(x w (x w r))");
    EXPECT_EQ(parse1("2*w x r'"), "(* 2 (x w r'))");
    EXPECT_EQ(parse1("(w . g)*w"), "(* (. w g) w)");
    EXPECT_EQ(parse1("x*x"), "(* x x)");
    EXPECT_EQ(parse1("r'' + r"), "(+ r'' r)");
    EXPECT_EQ(parse1("vector a, b"), "(vector a b)");
    EXPECT_EQ(parse1("positive k"), "(positive k)");
    EXPECT_EQ(parse1("vector(1)"), "(vector 1)");  // a call, not a declaration
    EXPECT_THROW(parse_program("vector a'", "x"), symrep::syntax_error);
}
