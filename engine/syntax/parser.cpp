// symrep/syntax/parser.cpp
#include "symrep/syntax/parser.h"

#include <cstring>

namespace symrep::lang {

parser::parser(const std::string& text, std::string file, int first_line)
    : toks_(tokenize(text, first_line)), file_(std::move(file)) {}

const token& parser::peek(std::size_t k) const {
    const std::size_t i = pos_ + k;
    return i < toks_.size() ? toks_[i] : toks_.back();
}
const token& parser::get() {
    const token& t = peek();
    if (pos_ + 1 < toks_.size()) ++pos_;
    return t;
}
bool parser::is_op(const char* op, std::size_t k) const {
    const token& t = peek(k);
    return t.kind == tok::op && t.text == op;
}

namespace {
std::string describe(const token& t) {
    switch (t.kind) {
        case tok::number: return "number " + t.text;
        case tok::ident: return "name '" + t.text + "'";
        case tok::string: return "a string";
        case tok::result: return "'" + t.text + "'";
        case tok::op: return "'" + t.text + "'";
        case tok::separator: return t.text == ";" ? "';'" : "end of line";
        case tok::error: return t.text;
        case tok::end: return "end of input";
    }
    return "?";
}
}  // namespace

void parser::fail(const token& t, const std::string& msg) const {
    if (t.kind == tok::error) throw syntax_error(t.text, {file_, t.line, t.column});
    throw syntax_error(msg, {file_, t.line, t.column});
}

void parser::expect_op(const char* op, const char* what) {
    if (!is_op(op)) fail(peek(), std::string("expected '") + op + "' " + what + ", found " + describe(peek()));
    get();
}

node_ptr parser::make(node::kind_t k, const token& t, std::string text) const {
    auto n = std::make_unique<node>();
    n->kind = k;
    n->text = std::move(text);
    n->line = t.line;
    n->column = t.column;
    return n;
}

bool parser::at_end() const {
    std::size_t k = pos_;
    while (k < toks_.size() && toks_[k].kind == tok::separator) ++k;
    return k >= toks_.size() || toks_[k].kind == tok::end;
}

node_ptr parser::next_statement() {
    depth_ = 0;
    assigned_.clear();
    while (peek().kind == tok::separator) get();
    if (peek().kind == tok::end) return nullptr;
    begin_ = {peek().line, peek().column};
    node_ptr s;
    if (peek().kind == tok::ident && (peek().text == "vector" || peek().text == "positive") &&
        peek(1).kind == tok::ident) {
        s = declaration();
    } else if (peek().kind == tok::ident && is_op(":=", 1)) {
        const token& name = get();
        assigned_ = name.text;
        const token& op = get();
        s = make(node::assign, op, name.text);
        s->line = name.line;
        s->column = name.column;
        s->kids.push_back(expr());
    } else {
        s = expr();
    }
    const token& t = peek();
    end_ = {t.line, t.column};
    if (t.kind == tok::separator) {
        get();
    } else if (t.kind != tok::end) {
        if (t.kind == tok::op && t.text == ":=")
            fail(t, "':=' assigns to a name only");
        fail(t, "unexpected " + describe(t) + " after the end of a statement");
    }
    return s;
}

void parser::recover() {
    while (peek().kind != tok::separator && peek().kind != tok::end) get();
    if (peek().kind == tok::separator) get();
}

node_ptr parser::expr() {
    node_ptr a = sum();
    static const char* rels[] = {"=", "==", "!=", "<", ">", "<=", ">="};
    for (const char* r : rels) {
        if (is_op(r)) {
            const token& op = get();
            node_ptr n = make(node::binary, op, r);
            n->kids.push_back(std::move(a));
            n->kids.push_back(sum());
            for (const char* r2 : rels)
                if (is_op(r2)) fail(peek(), std::string("relations do not chain: put parentheses around one side of '") + r2 + "'");
            return n;
        }
    }
    return a;
}

// Sums and products are flat chains (not left-deep trees), so that a long
// sum needs no deep recursion to evaluate or to destroy.
node_ptr parser::sum() {
    node_ptr a = product();
    if (!is_op("+") && !is_op("-")) return a;
    node_ptr n = make(node::chain, peek());
    n->kids.push_back(std::move(a));
    while (is_op("+") || is_op("-")) {
        const token& op = get();
        n->text += op.text;
        n->op_pos.emplace_back(op.line, op.column);
        n->kids.push_back(product());
    }
    n->line = n->op_pos[0].first;
    n->column = n->op_pos[0].second;
    return n;
}

node_ptr parser::product() {
    node_ptr a = vector_product();
    if (!is_op("*") && !is_op("/")) return a;
    node_ptr n = make(node::chain, peek());
    n->kids.push_back(std::move(a));
    while (is_op("*") || is_op("/")) {
        const token& op = get();
        n->text += op.text;
        n->op_pos.emplace_back(op.line, op.column);
        n->kids.push_back(vector_product());
    }
    return n;
}

// a x b and a . b bind tighter than * and /, and group to the right, so that
// w x w x r reads w x (w x r) as in the thesis. The name x is the cross
// product only between two operands (where no name could stand); the sign
// U+00D7 is the cross product wherever it stands (a · b is the lexer's ".").
node_ptr parser::vector_product() {
    node_ptr a = unary();
    const token& t = peek();
    const bool sign = is_op("\xC3\x97");
    const bool cross = sign || (t.kind == tok::ident && t.text == "x");
    if (!cross && !is_op(".")) return a;
    if (cross && !sign) {
        const token& u = peek(1);
        const bool operand = u.kind == tok::ident || u.kind == tok::number ||
                             (u.kind == tok::op && (u.text == "(" || u.text == "["));
        if (!operand) return a;
    }
    const token& op = get();
    node_ptr n = make(node::binary, op, cross ? "x" : ".");
    n->kids.push_back(std::move(a));
    if (++depth_ > 2000) fail(peek(), "expression nested too deeply (more than 2000 levels)");
    n->kids.push_back(vector_product());
    --depth_;
    return n;
}

// vector a, b, c   /   vector w(t)   /   positive w0, g
node_ptr parser::declaration() {
    const token& kw = get();
    node_ptr n = make(node::declare, kw, kw.text);
    for (;;) {
        const token& name = peek();
        if (name.kind != tok::ident)
            fail(name, "expected a name to declare after '" + kw.text + "', found " + describe(name));
        if (name.text.find('\'') != std::string::npos)
            fail(name, "cannot declare '" + name.text + "': primes name derivatives");
        get();
        n->kids.push_back(make(node::ident, name, name.text));
        // vector w(t): a vector function of t, left unspecified (its derivative is w')
        if (kw.text == "vector" && is_op("(")) {
            get();
            const token& var = peek();
            if (var.kind != tok::ident || var.text != "t")
                fail(var, "a declared vector function depends on t: vector " + name.text + "(t)");
            get();
            if (!is_op(")")) fail(peek(), "expected ')' after 'vector " + name.text + "(t'");
            get();
            n->kids.back()->kids.push_back(make(node::ident, var, var.text));
        }
        if (!is_op(",")) break;
        get();
    }
    return n;
}

node_ptr parser::unary() {
    struct guard {
        int& d;
        explicit guard(int& x) : d(x) { ++d; }
        ~guard() { --d; }
    } g(depth_);
    if (depth_ > 2000) fail(peek(), "expression nested too deeply (more than 2000 levels)");
    if (is_op("-") || is_op("+")) {
        const token& op = get();
        node_ptr n = make(node::unary, op, op.text);
        n->kids.push_back(unary());
        return n;
    }
    return power();
}

node_ptr parser::power() {
    node_ptr a = postfix();
    if (is_op("^")) {
        const token& op = get();
        node_ptr n = make(node::binary, op, "^");
        n->kids.push_back(std::move(a));
        n->kids.push_back(unary());  // right associative; allows 2^-1
        return n;
    }
    return a;
}

node_ptr parser::postfix() {
    node_ptr a = primary();
    int chained = 0;
    while (is_op("[")) {
        if (++chained > 2000) fail(peek(), "too many indices in a row (more than 2000)");
        const token& op = get();
        node_ptr n = make(node::index, op);
        n->kids.push_back(std::move(a));
        n->kids.push_back(expr());
        expect_op("]", "to close the index");
        a = std::move(n);
    }
    return a;
}

node_ptr parser::primary() {
    const token& t = peek();
    switch (t.kind) {
        case tok::number: get(); return make(node::number, t, t.text);
        case tok::string: get(); return make(node::string, t, t.text);
        case tok::result: get(); return make(node::result, t, t.text);
        case tok::ident: {
            get();
            if (t.text == "true" || t.text == "false") return make(node::boolean, t, t.text);
            if (!is_op("(")) return make(node::ident, t, t.text);
            get();
            node_ptr n = make(node::call, t, t.text);
            if (!is_op(")")) {
                for (;;) {
                    n->kids.push_back(expr());
                    if (is_op(",")) { get(); continue; }
                    break;
                }
            }
            expect_op(")", ("to close the call of " + t.text).c_str());
            return n;
        }
        case tok::op:
            if (t.text == "(") {
                get();
                node_ptr e = expr();
                expect_op(")", "to close '('");
                return e;
            }
            if (t.text == "|") {
                // |e|: the printed form of norm(e) (and abs of a scalar). Where an
                // operand ends, '|' closes the bars: |a|*|b|, ||a|*b|.
                get();
                node_ptr n = make(node::unary, t, "|");
                n->kids.push_back(sum());
                expect_op("|", "to close |...|");
                return n;
            }
            if (t.text == "[") {
                get();
                node_ptr n = make(node::list, t);
                if (!is_op("]")) {
                    for (;;) {
                        n->kids.push_back(expr());
                        if (is_op(",")) { get(); continue; }
                        break;
                    }
                }
                expect_op("]", "to close the list");
                return n;
            }
            fail(t, "unexpected " + describe(t) + ", expected an expression");
        case tok::separator:
        case tok::end:
            fail(t, "unexpected " + describe(t) + ", expected an expression");
        case tok::error:
            fail(t, t.text);
    }
    fail(t, "unexpected token");
}

std::vector<node_ptr> parse_program(const std::string& text, const std::string& file) {
    parser p(text, file);
    std::vector<node_ptr> out;
    while (!p.at_end()) {
        node_ptr s = p.next_statement();
        if (s) out.push_back(std::move(s));
    }
    return out;
}

}  // namespace symrep::lang
