// symrep/syntax/lexer.h -- tokens of the symrep language.
//
// The lexer turns the whole text into tokens at once. Newlines become statement
// separators only outside brackets, so a statement continues on the next line
// while a '(' or '[' is open. Malformed input (a stray character, an unterminated
// string) becomes an `error` token that the parser reports when it reaches it, so
// that errors are reported in source order with the statements around them.
#pragma once

#include <string>
#include <vector>

namespace symrep::lang {

enum class tok {
    number,      ///< 12, 3.5, 1e-3 (text in `text`)
    ident,       ///< names: letters, digits, '_' (not first digit), then primes: r, r', r''
    string,      ///< "..." (unescaped text in `text`)
    op,          ///< + - * / ^ ( ) [ ] , . | := = == != < > <= >= and U+00D7 (the cross product 'x' is an
                 ///< ident; U+00B7 and U+22C5 give the op ".")
    result,      ///< a previous result: % (the last), %% (the one before), %3 (numbered)
    separator,   ///< newline or ';' outside brackets
    error,       ///< malformed input; message in `text`
    end,         ///< end of input
};

struct token {
    tok kind = tok::end;
    std::string text;
    int line = 1;
    int column = 1;
};

/// Splits text into tokens; never throws (malformed input gives tok::error tokens).
/// `first_line` is the line number of the text's first line (a statement read
/// from the middle of a stream). A UTF-8 byte order mark at the very start of
/// the text (first_line 1) is skipped.
///
/// Recovery from an unclosed bracket: while a '(' or '[' is open, a line whose
/// first token starts a statement (`NAME :=`, or `vector`/`positive` followed
/// by a name: text that can never continue an expression) ends the broken
/// statement: an error token naming the open bracket, then a separator, and the
/// line is read as a new statement.
std::vector<token> tokenize(const std::string& text, int first_line = 1);

/// True when the line (from `pos` on) starts a statement in the sense above.
bool starts_statement(const std::string& text, std::size_t pos = 0);

/// Follows, line by line, whether the lines read so far end a statement: no
/// '(' or '[' open (with the recovery rule above), no '\' continuation. Used by
/// the stream reader (lang/interpreter.cpp) to run each statement as soon as it ends.
class line_tracker {
public:
    /// Takes one line (without its '\n').
    void feed(const std::string& line);
    /// True when the lines fed so far are complete statements.
    bool complete() const { return depth_ == 0 && !continued_; }
    void reset() { depth_ = 0; continued_ = false; }

private:
    int depth_ = 0;
    bool continued_ = false;
};

/// True while the text has an open '(' or '[' or an unterminated string, i.e. an
/// interactive reader should ask for another line before running it.
bool needs_more_input(const std::string& text);

}  // namespace symrep::lang
