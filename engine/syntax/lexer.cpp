// symrep/syntax/lexer.cpp
#include "symrep/syntax/lexer.h"

#include <cctype>

namespace symrep::lang {

namespace {

struct scanner {
    const std::string& s;
    std::size_t i = 0;
    int line = 1, col = 1;
    explicit scanner(const std::string& t) : s(t) {}
    bool done() const { return i >= s.size(); }
    char peek(std::size_t k = 0) const { return i + k < s.size() ? s[i + k] : '\0'; }
    // Columns count characters: the continuation bytes of UTF-8 do not advance them.
    char get() {
        char c = s[i++];
        if (c == '\n') { ++line; col = 1; }
        else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) { ++col; }
        return c;
    }
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The length of the UTF-8 sequence starting at s[i], or 0 if the bytes there
// are not one (a lone continuation byte, a truncated or overlong sequence).
std::size_t utf8_length(const std::string& s, std::size_t i) {
    const auto b = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
    const unsigned c = b(0);
    const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((b(k) & 0xC0) != 0x80) return 0;
    if ((c == 0xE0 && b(1) < 0xA0) || (c == 0xF0 && b(1) < 0x90) || (c == 0xF4 && b(1) > 0x8F)) return 0;
    return n;
}

}  // namespace

bool starts_statement(const std::string& s, std::size_t i) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    if (i >= s.size() || !ident_start(s[i])) return false;
    const std::size_t a = i;
    while (i < s.size() && ident_char(s[i])) ++i;
    const std::string name = s.substr(a, i - a);
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    if (i + 1 < s.size() && s[i] == ':' && s[i + 1] == '=') return true;
    return (name == "vector" || name == "positive") && i > a + name.size() && i < s.size() && ident_start(s[i]);
}

void line_tracker::feed(const std::string& line) {
    if (depth_ > 0 && starts_statement(line)) depth_ = 0;
    bool comment = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '#') { comment = true; break; }
        if (c == '"') {
            for (++i; i < line.size() && line[i] != '"'; ++i)
                if (line[i] == '\\') ++i;
            continue;
        }
        if (c == '(' || c == '[') ++depth_;
        else if ((c == ')' || c == ']') && depth_ > 0) --depth_;
        else if (c == ';') depth_ = 0;
    }
    std::size_t n = line.size();
    if (n > 0 && line[n - 1] == '\r') --n;
    continued_ = !comment && n > 0 && line[n - 1] == '\\';
}

std::vector<token> tokenize(const std::string& text, int first_line) {
    std::vector<token> out;
    scanner sc(text);
    sc.line = first_line;
    if (first_line == 1 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) sc.i = 3;  // a UTF-8 byte order mark
    struct opened { char c; int line, column; };
    std::vector<opened> open;  // the open brackets
    auto push = [&](tok k, std::string t, int l, int c) { out.push_back({k, std::move(t), l, c}); };
    while (!sc.done()) {
        const char c = sc.peek();
        const int l = sc.line, co = sc.col;
        if (c == '#') {
            while (!sc.done() && sc.peek() != '\n') sc.get();
            continue;
        }
        if (c == '\n' || c == ';') {
            sc.get();
            if (c == '\n' && !open.empty() && starts_statement(text, sc.i)) {
                // recovery: the next line starts a statement, so the bracket is not closed
                const opened o = open.back();
                push(tok::error,
                     std::string("'") + o.c + "' opened at line " + std::to_string(o.line) + ", column " +
                         std::to_string(o.column) +
                         " is not closed (the next line starts a new statement)",
                     l, co);
                open.clear();
            }
            if (c == ';' || open.empty()) {
                // ';' inside brackets is a separator too: it ends the broken statement.
                if (c == ';') open.clear();
                push(tok::separator, c == ';' ? ";" : "\\n", l, co);
            }
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') { sc.get(); continue; }
        if (c == '\\' && (sc.peek(1) == '\n' || (sc.peek(1) == '\r' && sc.peek(2) == '\n'))) {
            // explicit line continuation
            sc.get();
            while (sc.peek() != '\n') sc.get();
            sc.get();
            continue;
        }
        if (digit(c) || (c == '.' && digit(sc.peek(1)))) {
            std::string t;
            while (digit(sc.peek())) t += sc.get();
            if (sc.peek() == '.' && digit(sc.peek(1))) {
                t += sc.get();
                while (digit(sc.peek())) t += sc.get();
            } else if (sc.peek() == '.' && !ident_start(sc.peek(1))) {
                t += sc.get();  // "3." is a decimal
            }
            if ((sc.peek() == 'e' || sc.peek() == 'E') &&
                (digit(sc.peek(1)) || ((sc.peek(1) == '-' || sc.peek(1) == '+') && digit(sc.peek(2))))) {
                t += sc.get();
                if (sc.peek() == '-' || sc.peek() == '+') t += sc.get();
                while (digit(sc.peek())) t += sc.get();
            }
            push(tok::number, t, l, co);
            continue;
        }
        if (ident_start(c)) {
            std::string t;
            while (ident_char(sc.peek())) t += sc.get();
            while (sc.peek() == '\'') t += sc.get();  // r', r'': derivatives (VI)
            push(tok::ident, t, l, co);
            continue;
        }
        if (c == '"') {
            sc.get();
            std::string t;
            bool closed = false, bad = false;
            while (!sc.done()) {
                char d = sc.get();
                if (d == '"') { closed = true; break; }
                if (d == '\n') { bad = true; break; }
                if (d == '\\') {
                    if (sc.done()) break;
                    char e = sc.get();
                    if (e == 'n') t += '\n';
                    else if (e == 't') t += '\t';
                    else if (e == '"' || e == '\\') t += e;
                    else { t += '\\'; t += e; }
                    continue;
                }
                t += d;
            }
            if (!closed || bad) {
                push(tok::error, "unterminated string", l, co);
                if (bad) push(tok::separator, "\\n", sc.line - 1, 1);
            } else {
                push(tok::string, t, l, co);
            }
            continue;
        }
        if (static_cast<unsigned char>(c) >= 0x80) {
            // the Unicode signs of the products (notation("unicode") prints them):
            // U+00D7 (x) is the cross product, U+00B7 and U+22C5 the scalar product
            const std::size_t len = utf8_length(text, sc.i);
            const std::string ch = text.substr(sc.i, len ? len : 1);
            for (std::size_t k = 0; k < ch.size(); ++k) sc.get();
            if (ch == "\xC3\x97") push(tok::op, ch, l, co);
            else if (ch == "\xC2\xB7" || ch == "\xE2\x8B\x85") push(tok::op, ".", l, co);
            else if (len) push(tok::error, "unexpected character '" + ch + "'", l, co);
            else push(tok::error, "unexpected character byte " + std::to_string(static_cast<unsigned char>(c)), l, co);
            continue;
        }
        sc.get();
        const char n = sc.peek();
        auto two = [&](const char* t) { sc.get(); push(tok::op, t, l, co); };
        if (c == '%') {  // %, %%, %N: previous results
            std::string t = "%";
            if (n == '%') t += sc.get();
            else while (digit(sc.peek())) t += sc.get();
            push(tok::result, t, l, co);
            continue;
        }
        if (c == ':' && n == '=') { two(":="); continue; }
        if (c == '=' && n == '=') { two("=="); continue; }
        if (c == '!' && n == '=') { two("!="); continue; }
        if (c == '<' && n == '=') { two("<="); continue; }
        if (c == '>' && n == '=') { two(">="); continue; }
        switch (c) {
            case '(': case '[': open.push_back({c, l, co}); push(tok::op, std::string(1, c), l, co); break;
            case ')': case ']': if (!open.empty()) open.pop_back(); push(tok::op, std::string(1, c), l, co); break;
            case '+': case '-': case '*': case '/': case '^': case ',': case '=': case '<': case '>': case '.':
            case '|':
                push(tok::op, std::string(1, c), l, co);
                break;
            default: {
                std::string shown = std::isprint(static_cast<unsigned char>(c))
                                        ? std::string("'") + c + "'"
                                        : "byte " + std::to_string(static_cast<unsigned char>(c));
                push(tok::error, "unexpected character " + shown, l, co);
            }
        }
    }
    push(tok::end, "", sc.line, sc.col);
    return out;
}

bool needs_more_input(const std::string& text) {
    line_tracker t;
    std::size_t a = 0;
    for (;;) {
        const std::size_t b = text.find('\n', a);
        t.feed(text.substr(a, b == std::string::npos ? std::string::npos : b - a));
        if (b == std::string::npos) break;
        a = b + 1;
    }
    return !t.complete();
}

}  // namespace symrep::lang
