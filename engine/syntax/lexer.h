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
std::vector<token> tokenize(const std::string& text);

/// True while the text has an open '(' or '[' or an unterminated string, i.e. an
/// interactive reader should ask for another line before running it.
bool needs_more_input(const std::string& text);

}  // namespace symrep::lang
