// symrep/rules/rules.cpp -- rule files, the matcher and the rewriter.
#include "symrep/rules/rules.h"
#include "symrep/core/interrupt.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>

#include "symrep/scalar/scalar.h"
#include "symrep/syntax/parser.h"
#include "symrep/vector/vector.h"

namespace symrep::rules {

using GiNaC::ex;
using GiNaC::is_a;

namespace {

bool is_fn(const ex& e, unsigned serial) {
    return is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_serial() == serial;
}
bool is_cross_ex(const ex& e) { return is_fn(e, vcross_SERIAL::serial); }
bool is_dot_ex(const ex& e) { return is_fn(e, vdot_SERIAL::serial); }
bool is_triple_ex(const ex& e) { return is_fn(e, vtriple_SERIAL::serial); }

// is_vector without the exception for ill-formed input (which no variable matches)
std::optional<bool> vector_valued(const ex& e) {
    try {
        return is_vector(e);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

bool same_value(const ex& x, const ex& y) {
    if (x.is_equal(y)) return true;
    const ex d = x - y;
    if (d.is_zero()) return true;
    try {
        return canonical(d).is_zero();
    } catch (const std::exception&) {
        return false;
    }
}

// ------------------------------------------------------------------ matcher
// Continuation-passing backtracking: k receives the bindings and the sign f
// (p = f e) of a successful partial match and says whether the whole match
// succeeded; alternatives (swapped arguments, permutations) are tried in turn.
using cont = std::function<bool(bindings&, const ex&)>;

bool match_k(const pattern& p, const ex& e, bindings& b, const cont& k);

// Matches ps[i..] against es[perm[i..]] (all permutations when `any_order`),
// multiplying the signs; for sums every term must have the same sign.
bool match_list(const std::vector<pattern>& ps, const std::vector<ex>& es, std::vector<bool>& used, std::size_t i,
                bool any_order, bool sum, const ex& acc, bindings& b, const cont& k) {
    if (i == ps.size()) return k(b, acc);
    for (std::size_t j = 0; j < es.size(); ++j) {
        if (used[j] || (!any_order && j != i)) continue;
        used[j] = true;
        const bool ok = match_k(ps[i], es[j], b, [&](bindings& b2, const ex& f) {
            ex acc2;
            if (sum) {
                if (i > 0 && !f.is_equal(acc)) return false;
                acc2 = f;
            } else {
                acc2 = acc * f;
            }
            return match_list(ps, es, used, i + 1, any_order, sum, acc2, b2, k);
        });
        used[j] = false;
        if (ok) return true;
    }
    return false;
}

std::vector<ex> operands(const ex& e) {
    std::vector<ex> v;
    for (std::size_t i = 0; i < e.nops(); ++i) v.push_back(e.op(i));
    return v;
}

bool match_k(const pattern& p, const ex& e, bindings& b, const cont& k) {
    switch (p.kind) {
        case pattern::var: {
            auto it = b.find(p.name);
            if (it != b.end()) return same_value(it->second, e) && k(b, 1);
            const auto v = vector_valued(e);
            if (!v) return false;
            if (p.type == var_type::vector ? (!*v || e.is_zero()) : *v) return false;
            b.emplace(p.name, e);
            if (k(b, 1)) return true;
            b.erase(p.name);
            return false;
        }
        case pattern::number:
            return is_a<GiNaC::numeric>(e) && e.is_equal(p.num) && k(b, 1);
        case pattern::add:
        case pattern::mul: {
            const bool sum = p.kind == pattern::add;
            if (sum ? !is_a<GiNaC::add>(e) : !is_a<GiNaC::mul>(e)) return false;
            if (e.nops() != p.kids.size()) return false;
            const std::vector<ex> es = operands(e);
            std::vector<bool> used(es.size(), false);
            return match_list(p.kids, es, used, 0, true, sum, 1, b, k);
        }
        case pattern::power: {
            if (!is_a<GiNaC::power>(e)) return false;
            const ex expo = e.op(1);
            return match_k(p.kids[0], e.op(0), b, [&](bindings& b2, const ex& f) {
                return match_k(p.kids[1], expo, b2, [&](bindings& b3, const ex& g) {
                    if (!g.is_equal(1)) return false;
                    if (f.is_equal(1)) return k(b3, 1);
                    // f = -1: (-e)^n = (-1)^n e^n for an integer n only
                    if (!is_a<GiNaC::numeric>(expo) || !GiNaC::ex_to<GiNaC::numeric>(expo).is_integer()) return false;
                    return k(b3, GiNaC::ex_to<GiNaC::numeric>(expo).is_even() ? ex(1) : ex(-1));
                });
            });
        }
        case pattern::cross:
        case pattern::dot: {
            const bool cr = p.kind == pattern::cross;
            if (cr ? !is_cross_ex(e) : !is_dot_ex(e)) return false;
            const std::vector<ex> es = operands(e);
            for (int swap = 0; swap < 2; ++swap) {
                const std::vector<ex> order = swap ? std::vector<ex>{es[1], es[0]} : es;
                std::vector<bool> used(2, false);
                const ex sign = (cr && swap) ? -1 : 1;
                if (match_list(p.kids, order, used, 0, false, false, sign, b, k)) return true;
            }
            return false;
        }
        case pattern::triple: {
            if (!is_triple_ex(e)) return false;
            const std::vector<ex> es = operands(e);
            static const int perms[6][4] = {{0, 1, 2, 1}, {1, 2, 0, 1}, {2, 0, 1, 1},
                                            {1, 0, 2, -1}, {0, 2, 1, -1}, {2, 1, 0, -1}};
            for (const auto& q : perms) {
                const std::vector<ex> order{es[q[0]], es[q[1]], es[q[2]]};
                std::vector<bool> used(3, false);
                if (match_list(p.kids, order, used, 0, false, false, ex(q[3]), b, k)) return true;
            }
            return false;
        }
    }
    return false;
}

// ------------------------------------------------------------------ parsing
using symrep::lang::node;

struct side_parser {
    const std::map<std::string, var_type>& vars;
    std::string file;
    int line;
    std::size_t offset;  // column of the side's first character - 1

    [[noreturn]] void fail(const node& n, const std::string& msg) const {
        throw syntax_error(msg, {file, line, int(offset) + n.column});
    }
    pattern make(pattern::kind_t k, const node& n) const {
        pattern p;
        p.kind = k;
        p.line = line;
        p.column = int(offset) + n.column;
        return p;
    }
    pattern times(const pattern& a, const pattern& b, const node& n) const {
        pattern p = make(pattern::mul, n);
        p.kids = {a, b};
        return p;
    }
    pattern num(const ex& v, const node& n) const {
        pattern p = make(pattern::number, n);
        p.num = v;
        return p;
    }

    pattern convert(const node& n) const {
        switch (n.kind) {
            case node::number: {
                pattern p = make(pattern::number, n);
                const bool is_float = n.text.find_first_of(".eE") != std::string::npos;
                p.num = is_float ? ex(GiNaC::numeric(n.text.c_str()).evalf()) : ex(GiNaC::numeric(n.text.c_str()));
                return p;
            }
            case node::ident: {
                auto it = vars.find(n.text);
                if (it == vars.end())
                    fail(n, "'" + n.text + "' is not a pattern variable (declare it with 'vector " + n.text +
                                "' or 'scalar " + n.text + "' before the rule)");
                pattern p = make(pattern::var, n);
                p.name = n.text;
                p.type = it->second;
                return p;
            }
            case node::unary: {
                pattern a = convert(*n.kids[0]);
                return n.text == "-" ? times(num(-1, n), a, n) : a;
            }
            case node::chain: {
                const bool sum = n.text[0] == '+' || n.text[0] == '-';
                pattern p = make(sum ? pattern::add : pattern::mul, n);
                p.kids.push_back(convert(*n.kids[0]));
                for (std::size_t i = 0; i < n.text.size(); ++i) {
                    pattern k = convert(*n.kids[i + 1]);
                    if (n.text[i] == '-') k = times(num(-1, n), k, n);
                    if (n.text[i] == '/') {
                        pattern q = make(pattern::power, n);
                        q.kids = {k, num(-1, n)};
                        k = q;
                    }
                    p.kids.push_back(k);
                }
                return p;
            }
            case node::binary: {
                pattern::kind_t k;
                if (n.text == "x") k = pattern::cross;
                else if (n.text == ".") k = pattern::dot;
                else if (n.text == "^") k = pattern::power;
                else fail(n, "'" + n.text + "' cannot be used in a rule (only + - * / ^ x . and the functions "
                                "cross, dot, triple, norm)");
                pattern p = make(k, n);
                p.kids = {convert(*n.kids[0]), convert(*n.kids[1])};
                return p;
            }
            case node::call: {
                const std::size_t want = n.text == "triple" ? 3 : (n.text == "norm" ? 1 : 2);
                if (n.text != "triple" && n.text != "norm" && n.text != "cross" && n.text != "dot")
                    fail(n, "unknown function '" + n.text + "' in a rule (rules know cross, dot, triple, norm)");
                if (n.kids.size() != want)
                    fail(n, n.text + " takes " + std::to_string(want) + " argument" + (want == 1 ? "" : "s") +
                                ", got " + std::to_string(n.kids.size()));
                std::vector<pattern> args;
                for (const auto& k : n.kids) args.push_back(convert(*k));
                if (n.text == "norm") {  // |a| = (a . a)^(1/2), as GiNaC holds it
                    pattern d = make(pattern::dot, n);
                    d.kids = {args[0], args[0]};
                    pattern p = make(pattern::power, n);
                    p.kids = {d, num(GiNaC::numeric(1, 2), n)};
                    return p;
                }
                pattern p = make(n.text == "triple" ? pattern::triple : n.text == "cross" ? pattern::cross
                                                                                          : pattern::dot,
                                 n);
                p.kids = std::move(args);
                return p;
            }
            default:
                fail(n, "a rule side must be an expression of vectors and scalars (no strings, lists, indices, "
                        "assignments or relations)");
        }
    }

    pattern parse(const std::string& text) const {
        std::vector<lang::node_ptr> st;
        try {
            st = lang::parse_program(text, file);
        } catch (const syntax_error& e) {
            throw syntax_error(e.what(), {file, line, int(offset) + e.where.column});
        }
        if (st.size() != 1) {
            if (st.empty()) throw syntax_error("a rule side is empty", {file, line, int(offset) + 1});
            fail(*st[1], "a rule side must be one expression");
        }
        return convert(*st[0]);
    }
};

void collect_vars(const pattern& p, std::map<std::string, const pattern*>& out) {
    if (p.kind == pattern::var) out.emplace(p.name, &p);
    for (const pattern& k : p.kids) collect_vars(k, out);
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

bool is_name(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// Builds both sides with fresh symbols and checks that they are equal.
void check_rule(const rule& r) {
    std::map<std::string, const pattern*> vars;
    collect_vars(r.lhs, vars);
    bindings fresh;
    for (const auto& [name, p] : vars) {
        GiNaC::realsymbol s(name);
        if (p->type == var_type::vector) register_vector(s);
        fresh[name] = s;
    }
    const std::string at = r.where.file + ":" + std::to_string(r.where.line);
    ex l, rr;
    try {
        l = instantiate(r.lhs, fresh);
        rr = instantiate(r.rhs, fresh);
    } catch (const std::exception& e) {
        throw syntax_error("rule at " + at + " is ill-typed: " + e.what(), r.where);
    }
    bool holds = false;
    std::string why;
    try {
        holds = symrep::equal(l, rr);
    } catch (const std::exception& e) {
        why = std::string(": ") + e.what();
    }
    if (!holds)
        throw syntax_error("rule at " + at + " does not hold: " + symrep::to_string(l) + " is not " + symrep::to_string(rr) + why,
                           r.where);
}

}  // namespace

// ---------------------------------------------------------------- public API
std::string to_string(const pattern& p) {
    auto list = [&](const char* sep) {
        std::string s;
        for (std::size_t i = 0; i < p.kids.size(); ++i) s += (i ? sep : "") + to_string(p.kids[i]);
        return s;
    };
    switch (p.kind) {
        case pattern::var: return p.name;
        case pattern::number: {
            std::ostringstream os;
            os << p.num;
            return os.str();
        }
        case pattern::add: return "(" + list(" + ") + ")";
        case pattern::mul: return "(" + list("*") + ")";
        case pattern::power: return "(" + list("^") + ")";
        case pattern::cross: return "(" + list(" x ") + ")";
        case pattern::dot: return "(" + list(" . ") + ")";
        case pattern::triple: return "triple(" + list(", ") + ")";
    }
    return "?";
}

std::optional<std::pair<bindings, ex>> match(const pattern& p, const ex& e) {
    bindings b;
    std::optional<std::pair<bindings, ex>> out;
    match_k(p, e, b, [&](bindings& done, const ex& f) {
        out.emplace(done, f);
        return true;
    });
    return out;
}

std::optional<partial_match> match_partial(const pattern& p, const ex& e) {
    const bool sum = p.kind == pattern::add;
    if ((p.kind != pattern::add && p.kind != pattern::mul) || (sum ? !is_a<GiNaC::add>(e) : !is_a<GiNaC::mul>(e)) ||
        e.nops() <= p.kids.size()) {
        auto m = match(p, e);
        if (!m) return std::nullopt;
        return partial_match{std::move(m->first), m->second, sum ? ex(0) : ex(1)};
    }
    // some terms (factors) of e match the pattern's, the others are kept
    const std::vector<ex> es = operands(e);
    std::vector<bool> used(es.size(), false);
    bindings b;
    std::optional<partial_match> out;
    match_list(p.kids, es, used, 0, true, sum, 1, b, [&](bindings& done, const ex& f) {
        ex rest = sum ? ex(0) : ex(1);
        for (std::size_t j = 0; j < es.size(); ++j)
            if (!used[j]) rest = sum ? rest + es[j] : rest * es[j];
        out = partial_match{done, f, rest};
        return true;
    });
    return out;
}

ex instantiate(const pattern& p, const bindings& b) {
    switch (p.kind) {
        case pattern::var: {
            auto it = b.find(p.name);
            if (it == b.end()) throw type_error("the pattern variable '" + p.name + "' is not bound");
            return it->second;
        }
        case pattern::number: return p.num;
        case pattern::add: {
            ex s = 0;
            for (const pattern& k : p.kids) s += instantiate(k, b);
            (void)is_vector(s);  // vector + scalar: type_error
            return s;
        }
        case pattern::mul: {
            ex s = 1;
            for (const pattern& k : p.kids) s *= instantiate(k, b);
            (void)is_vector(s);  // vector * vector
            return s;
        }
        case pattern::power: {
            const ex s = GiNaC::pow(instantiate(p.kids[0], b), instantiate(p.kids[1], b));
            (void)is_vector(s);
            return s;
        }
        case pattern::cross: return cross(instantiate(p.kids[0], b), instantiate(p.kids[1], b));
        case pattern::dot: return dot(instantiate(p.kids[0], b), instantiate(p.kids[1], b));
        case pattern::triple:
            return triple(instantiate(p.kids[0], b), instantiate(p.kids[1], b), instantiate(p.kids[2], b));
    }
    throw type_error("unknown pattern");
}

std::vector<rule> parse_rules(const std::string& text, const std::string& file) {
    std::vector<rule> out;
    std::map<std::string, var_type> vars;
    std::istringstream in(text);
    std::string raw;
    int line = 0;
    while (std::getline(in, raw)) {
        ++line;
        std::string body = raw, comment;
        if (const auto h = raw.find('#'); h != std::string::npos) {
            body = raw.substr(0, h);
            comment = trim(raw.substr(h + 1));
        }
        // statements separated by ';'
        std::size_t start = 0;
        while (start <= body.size()) {
            std::size_t end = body.find(';', start);
            if (end == std::string::npos) end = body.size();
            const std::string stmt = body.substr(start, end - start);
            const std::size_t lead = stmt.find_first_not_of(" \t\r");
            if (lead != std::string::npos) {
                const std::size_t col0 = start + lead;  // 0-based column of the statement
                const std::string s = trim(stmt);
                const auto arrow = stmt.find("->");
                const std::string kw = s.substr(0, s.find_first_of(" \t"));
                if (arrow == std::string::npos && (kw == "vector" || kw == "scalar") && s.size() > kw.size()) {
                    std::size_t pos = col0 + kw.size();
                    const std::string names = body.substr(pos, end - pos);
                    std::size_t q = 0;
                    while (q <= names.size()) {
                        std::size_t c = names.find(',', q);
                        if (c == std::string::npos) c = names.size();
                        const std::string nm = trim(names.substr(q, c - q));
                        const std::size_t ncol = pos + q + names.substr(q, c - q).find_first_not_of(" \t") + 1;
                        if (!is_name(nm))
                            throw syntax_error("expected a variable name after '" + kw + "', found '" + nm + "'",
                                               {file, line, int(nm.empty() ? pos + q + 1 : ncol)});
                        if (nm == "x")
                            throw syntax_error("'x' is the cross product and cannot be a pattern variable",
                                               {file, line, int(ncol)});
                        vars[nm] = kw == "vector" ? var_type::vector : var_type::scalar;
                        q = c + 1;
                    }
                } else {
                    if (arrow == std::string::npos)
                        throw syntax_error("expected a rule 'left -> right' or a declaration 'vector a, b' / "
                                           "'scalar s', found '" + s + "'",
                                           {file, line, int(col0 + 1)});
                    rule r;
                    r.text = s;
                    r.where = {file, line, int(col0 + 1)};
                    r.name = comment.empty() ? "rule " + std::to_string(out.size() + 1) : comment;
                    side_parser lp{vars, file, line, start};
                    r.lhs = lp.parse(stmt.substr(0, arrow));
                    side_parser rp{vars, file, line, start + arrow + 2};
                    r.rhs = rp.parse(stmt.substr(arrow + 2));
                    if (r.lhs.kind == pattern::var || r.lhs.kind == pattern::number)
                        throw syntax_error("the left side of a rule must not be a lone variable or number",
                                           {file, line, r.lhs.column});
                    std::map<std::string, const pattern*> lv, rv;
                    collect_vars(r.lhs, lv);
                    collect_vars(r.rhs, rv);
                    for (const auto& [name, p] : rv)
                        if (!lv.count(name))
                            throw syntax_error("the right side uses '" + name +
                                                   "', which the left side does not bind",
                                               {file, line, p->column});
                    check_rule(r);
                    out.push_back(std::move(r));
                }
            }
            start = end + 1;
        }
    }
    return out;
}

std::size_t rule_set::load_file(const std::string& path) {
    namespace fs = std::filesystem;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw domain_error("cannot open rule file '" + path + "'");
    std::error_code ec;
    const std::string key = fs::weakly_canonical(fs::path(path), ec).string();
    if (files_.count(key)) return 0;
    std::stringstream ss;
    ss << in.rdbuf();
    std::vector<rule> r = parse_rules(ss.str(), path);
    const std::size_t n = r.size();
    add(std::move(r));
    files_.insert(key);
    return n;
}

void rule_set::add(std::vector<rule> r) {
    for (rule& x : r) rules_.push_back(std::move(x));
}

namespace {

struct rewriter {
    const std::vector<rule>& rules;
    std::size_t max_steps;
    rewrite_result& res;

    ex pass(const ex& e) {
        ex x = e;
        if (e.nops() > 0 && !is_a<GiNaC::symbol>(e)) {
            struct mapper : GiNaC::map_function {
                rewriter* self;
                explicit mapper(rewriter* s) : self(s) {}
                ex operator()(const ex& y) override { return self->pass(y); }
            } m(this);
            x = e.map(m);
        }
        if (res.bound_hit) return x;
        for (const rule& r : rules) {
            auto found = match_partial(r.lhs, x);
            if (!found) continue;
            check_interrupt();
            if (res.steps >= max_steps) {
                res.bound_hit = true;
                return x;
            }
            ++res.steps;
            res.last = &r;
            // x = (matched part) op rest, lhs(b) = f * matched part, lhs = rhs, f = +-1
            const ex part = found->sign * instantiate(r.rhs, found->b);
            return r.lhs.kind == pattern::add ? part + found->rest
                   : r.lhs.kind == pattern::mul ? part * found->rest
                                                : part;
        }
        return x;
    }
};

}  // namespace

rewrite_result rule_set::rewrite(const ex& e, std::size_t max_steps) const {
    rewrite_result res;
    res.result = e;
    rewriter rw{rules_, max_steps, res};
    for (;;) {
        const std::size_t before = res.steps;
        res.result = rw.pass(res.result);
        if (res.bound_hit || res.steps == before) break;
    }
    return res;
}

std::string default_rules_dir() {
    if (const char* d = std::getenv("SYMREP_RULES_DIR"); d && *d) return d;
    // the source tree's rules/ (the build tree's programs and tests), else the installed copy
    const std::string source = std::string(SYMREP_SOURCE_DIR) + "/rules";
    if (std::filesystem::is_directory(source)) return source;
    return SYMREP_RULES_INSTALL_DIR;
}

const rule_set& default_rules() {
    static std::mutex mu;
    static std::map<std::string, rule_set> cache;  // by folder
    const std::string dir = default_rules_dir();
    std::lock_guard<std::mutex> lock(mu);
    auto it = cache.find(dir);
    if (it != cache.end()) return it->second;
    rule_set s;
    s.load_file((std::filesystem::path(dir) / "vector.rules").string());
    return cache.emplace(dir, std::move(s)).first->second;
}

}  // namespace symrep::rules
