// symrep/syntax/parser.h -- recursive-descent parser of the symrep language.
//
// syntax/ turns text into syntax trees: tokens (lexer.h), the tree (ast.h) and
// this parser. It knows nothing of what a statement means, so that the rule
// files (rules/) can read their patterns with it; the meaning is lang/'s. It
// includes only core/ (docs/architecture.md).
//
//   program    := statement { separator statement }
//   statement  := IDENT ':=' expr | expr | (empty)
//   expr       := sum [ ('=' | '==' | '!=' | '<' | '>' | '<=' | '>=') sum ]
//   sum        := product { ('+' | '-') product }
//   product    := unary { ('*' | '/') unary }
//   unary      := ('-' | '+') unary | power
//   power      := postfix [ '^' unary ]            (right associative: a^b^c = a^(b^c))
//   postfix    := primary { '[' expr ']' }
//   primary    := NUMBER | STRING | RESULT (% %% %N) | IDENT | IDENT '(' [ expr {',' expr} ] ')'
//               | '(' expr ')' | '[' [ expr {',' expr} ] ']'
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "symrep/syntax/ast.h"
#include "symrep/core/error.h"
#include "symrep/syntax/lexer.h"

namespace symrep::lang {

class parser {
public:
    /// `file` is the name used in error locations; `first_line` the number of
    /// the text's first line (a statement read from the middle of a stream).
    parser(const std::string& text, std::string file, int first_line = 1);
    /// True when all statements have been read.
    bool at_end() const;
    /// The next statement (nullptr for an empty statement). Throws syntax_error;
    /// after a throw, call recover() to skip to the next statement.
    node_ptr next_statement();
    /// Skips the rest of a broken statement (up to and including its separator).
    void recover();
    /// Where the last statement returned by next_statement() starts (its first
    /// token) and ends (its separator or the end of the text): line, column.
    std::pair<int, int> statement_begin() const { return begin_; }
    std::pair<int, int> statement_end() const { return end_; }
    /// The name assigned by the last statement that next_statement() began
    /// (`NAME := ...`), also when it threw; empty for other statements.
    const std::string& assigned_name() const { return assigned_; }

private:
    const token& peek(std::size_t k = 0) const;
    const token& get();
    bool is_op(const char* op, std::size_t k = 0) const;
    void expect_op(const char* op, const char* what);
    [[noreturn]] void fail(const token& t, const std::string& msg) const;
    node_ptr make(node::kind_t k, const token& t, std::string text = {}) const;
    node_ptr expr();
    node_ptr sum();
    node_ptr product();
    node_ptr vector_product();
    node_ptr declaration();
    node_ptr unary();
    node_ptr power();
    node_ptr postfix();
    node_ptr primary();

    std::vector<token> toks_;
    std::size_t pos_ = 0;
    int depth_ = 0;  ///< nesting of unary/primary, limited to keep the stack safe
    std::string file_;
    std::pair<int, int> begin_{1, 1}, end_{1, 1};
    std::string assigned_;
};

/// Parses a whole text; throws the first syntax_error.
std::vector<node_ptr> parse_program(const std::string& text, const std::string& file);

}  // namespace symrep::lang
