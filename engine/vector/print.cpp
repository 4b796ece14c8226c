// symrep/vector/print.cpp -- to_string(): vector and scalar expressions in the
// thesis notation, with a deterministic term and factor order.
//
// GiNaC orders the terms of a sum and the factors of a product by hash values
// and symbol serial numbers, which depend on creation order; here sums are
// ordered by their vector monomial and then by text, products by text with the
// vector factor last. Terms of a vector sum with the same vector monomial are
// printed together: (a + b)*w.
//
// The cross and dot products are written `a x b`, `a . b` or, in the unicode
// notation, `a × b`, `a · b`. Every comparison of printed texts below goes
// through text_less, which reads the two Unicode signs as their ASCII letters,
// so both notations put terms and factors in the same order.
#include <algorithm>
#include <sstream>

#include "symrep/vector/vector.h"
#include "symrep/vector/vector_internal.h"

namespace symrep {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::ex_to;
using namespace detail;

namespace {

notation g_notation = notation::ascii;  ///< vector_notation()
notation g_current = notation::ascii;   ///< of the to_string call running

const char* const cross_utf8 = "\xC3\x97";  // U+00D7 MULTIPLICATION SIGN
const char* const dot_utf8 = "\xC2\xB7";    // U+00B7 MIDDLE DOT

std::string cross_sign() { return g_current == notation::unicode ? std::string(" ") + cross_utf8 + " " : " x "; }
std::string dot_sign() { return g_current == notation::unicode ? std::string(" ") + dot_utf8 + " " : " . "; }

// The ASCII text of a text printed in the unicode notation.
std::string ascii_text(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.compare(i, 2, cross_utf8) == 0) {
            out += 'x';
            ++i;
        } else if (s.compare(i, 2, dot_utf8) == 0) {
            out += '.';
            ++i;
        } else {
            out += s[i];
        }
    }
    return out;
}

// The order of printed texts: that of their ASCII notation.
bool text_less(const std::string& a, const std::string& b) {
    if (g_current == notation::ascii) return a < b;
    return ascii_text(a) < ascii_text(b);
}
struct text_order {
    bool operator()(const std::string& a, const std::string& b) const { return text_less(a, b); }
};

std::string str(const ex& e);

std::string ginac_text(const ex& e) {
    std::ostringstream os;
    os << e;
    return os.str();
}

bool is_norm_sq(const ex& e) { return is_dot(e) && e.op(0).is_equal(e.op(1)); }

// Printed without parentheses as a factor of a product or an operand of x / .
bool is_simple(const ex& e) {
    if (is_a<GiNaC::symbol>(e) || is_a<GiNaC::matrix>(e) || is_a<GiNaC::constant>(e)) return true;
    if (is_a<GiNaC::numeric>(e)) {
        const auto& n = ex_to<GiNaC::numeric>(e);
        return n.is_integer() && !n.is_negative();
    }
    if (is_norm_sq(e)) return true;
    if (is_a<GiNaC::function>(e)) return !is_cross(e) && !is_dot(e) && !is_triple(e);
    if (is_a<GiNaC::power>(e))
        return !(is_a<GiNaC::numeric>(e.op(1)) && ex_to<GiNaC::numeric>(e.op(1)).is_negative());
    return false;
}

std::string factor_text(const ex& e) { return is_simple(e) ? str(e) : "(" + str(e) + ")"; }

// |a|
std::string operand_norm(const ex& a) { return "|" + str(a) + "|"; }

std::string power_text(const ex& base, const ex& expo) {
    if (is_norm_sq(base)) {  // |a|^(2k)
        const ex n = 2 * expo;
        const std::string a = operand_norm(base.op(0));
        if (n.is_equal(1)) return a;
        if (is_a<GiNaC::numeric>(n) && ex_to<GiNaC::numeric>(n).is_pos_integer()) return a + "^" + str(n);
        return a + "^(" + str(n) + ")";
    }
    if (expo.is_equal(GiNaC::numeric(1, 2))) return "sqrt(" + str(base) + ")";
    std::string b = str(base);
    if (!is_simple(base) || is_a<GiNaC::power>(base) || is_norm_sq(base)) b = "(" + b + ")";
    if (is_a<GiNaC::numeric>(expo) && ex_to<GiNaC::numeric>(expo).is_pos_integer()) return b + "^" + str(expo);
    return b + "^(" + str(expo) + ")";
}


std::vector<std::string> add_terms(const ex& e);
std::string join_terms(const std::vector<std::string>& terms);

std::string toggle_sign(const std::string& t) { return t.rfind("-", 0) == 0 ? t.substr(1) : "-" + t; }

// A product given as numeric coefficient and scalar factors, and the text of
// the vector factor if any (printed last among the numerator factors). Each
// factor is printed once (no exponential re-printing of nested sums).
std::string product_text(const GiNaC::numeric& coef_in, const std::vector<ex>& factors, std::string vec = "") {
    std::vector<std::string> num, den;
    GiNaC::numeric coef = coef_in;
    for (const ex& f : factors) {
        const bool int_pw = is_a<GiNaC::power>(f) && is_a<GiNaC::numeric>(f.op(1)) &&
                            ex_to<GiNaC::numeric>(f.op(1)).is_integer();
        const ex base = int_pw ? f.op(0) : f;
        if (is_a<GiNaC::add>(base) && !kind(base)) {
            // a scalar sum (or an integer power of one) whose text starts with
            // '-' is printed negated, so that the text does not depend on the
            // sign GiNaC picks by its internal order (text only: GiNaC would
            // restore its own choice in an expression)
            std::vector<std::string> terms = add_terms(base);
            GiNaC::numeric k = int_pw ? ex_to<GiNaC::numeric>(f.op(1)) : GiNaC::numeric(1);
            if (!terms.empty() && terms[0].rfind("-", 0) == 0) {
                for (auto& t : terms) t = toggle_sign(t);
                if (k.is_odd()) coef = -coef;
            }
            const std::string t = "(" + join_terms(terms) + ")";
            const bool in_den = k.is_negative();
            if (in_den) k = -k;
            (in_den ? den : num).push_back(k.is_equal(1) ? t : t + "^" + ginac_text(k));
            continue;
        }
        if (is_a<GiNaC::power>(f) && is_a<GiNaC::numeric>(f.op(1)) &&
            ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
            den.push_back(factor_text(GiNaC::pow(f.op(0), -f.op(1))));
        } else if (kind(f) && is_a<GiNaC::add>(f)) {
            // a vector sum: its sign normalized like a scalar sum's above
            std::vector<std::string> terms = add_terms(f);
            if (!terms.empty() && terms[0].rfind("-", 0) == 0) {
                for (auto& t : terms) t = toggle_sign(t);
                coef = -coef;
            }
            vec = "(" + join_terms(terms) + ")";
        } else if (kind(f)) {
            vec = factor_text(f);
        } else {
            num.push_back(factor_text(f));
        }
    }
    std::sort(num.begin(), num.end(), text_less);
    std::sort(den.begin(), den.end(), text_less);
    if (!vec.empty()) num.push_back(vec);
    const GiNaC::numeric p = coef.numer(), q = coef.denom();
    std::string sign;
    GiNaC::numeric ap = p;
    if (p.is_negative()) {
        sign = "-";
        ap = -p;
    }
    if (!ap.is_equal(1) || num.empty()) num.insert(num.begin(), ginac_text(ap));
    if (!q.is_equal(1)) den.insert(den.begin(), ginac_text(q));
    std::string s = sign;
    for (std::size_t i = 0; i < num.size(); ++i) s += (i ? "*" : "") + num[i];
    if (!den.empty()) {
        s += "/";
        if (den.size() == 1) s += den[0];
        else {
            s += "(";
            for (std::size_t i = 0; i < den.size(); ++i) s += (i ? "*" : "") + den[i];
            s += ")";
        }
    }
    return s;
}

// Splits a scalar into numeric coefficient and other factors.
void split_numeric(const ex& e, GiNaC::numeric& c, std::vector<ex>& fs) {
    c = 1;
    if (is_a<GiNaC::numeric>(e)) {
        c = ex_to<GiNaC::numeric>(e);
        return;
    }
    if (!is_a<GiNaC::mul>(e)) {
        fs.push_back(e);
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) {
        if (is_a<GiNaC::numeric>(e.op(i))) c *= ex_to<GiNaC::numeric>(e.op(i));
        else fs.push_back(e.op(i));
    }
}

std::string mul_text(const ex& e) {
    GiNaC::numeric c;
    std::vector<ex> fs;
    split_numeric(e, c, fs);
    return product_text(c, fs);
}

// A term of a sum: a bare cross or dot product gets parentheses, (a . b) + c.
std::string term_text(const ex& t) {
    return (is_cross(t) || is_triple(t) || (is_dot(t) && !is_norm_sq(t))) ? "(" + str(t) + ")" : str(t);
}

// The printed terms of a sum, in the fixed order: vector terms grouped by
// their monomial (ordered by its text), then scalar terms by text without sign.
std::vector<std::string> add_terms(const ex& e) {
    struct group {
        ex mon;
        std::string text;  // the monomial, printed once
        ex coef;
    };
    std::map<std::string, group, text_order> groups;
    std::vector<std::string> scalars;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex t = e.op(i);
        if (kind(t)) {
            const auto [s0, v] = split_scalar(t);
            ex s = s0;
            std::string k;
            if (is_a<GiNaC::add>(v)) {
                // a vector sum as the factor: its sign normalized (leading term without
                // '-'), as GiNaC's choice follows its internal order
                std::vector<std::string> vt = add_terms(v);
                if (!vt.empty() && vt[0].rfind("-", 0) == 0) {
                    for (auto& x : vt) x = toggle_sign(x);
                    s = -s;
                }
                k = join_terms(vt);
            } else {
                k = str(v);
            }
            auto it = groups.find(k);
            if (it == groups.end()) groups.emplace(k, group{v, k, s});
            else it->second.coef += s;
        } else {
            scalars.push_back(term_text(t));
        }
    }
    std::vector<std::string> terms;
    for (auto& [k, g] : groups) {
        const ex& c = g.coef;
        if (c.is_zero()) continue;
        const bool bare_product = is_cross(g.mon) || is_triple(g.mon) || (is_dot(g.mon) && !is_norm_sq(g.mon));
        const std::string vt = is_simple(g.mon) ? g.text : "(" + g.text + ")";
        if (c.is_equal(1)) {
            terms.push_back(bare_product ? "(" + g.text + ")" : g.text);
        } else if (is_a<GiNaC::add>(c)) {
            terms.push_back("(" + str(c) + ")*" + vt);
        } else {
            GiNaC::numeric cn;
            std::vector<ex> fs;
            split_numeric(c, cn, fs);
            terms.push_back(product_text(cn, fs, vt));
        }
    }
    std::sort(scalars.begin(), scalars.end(), [](const std::string& a, const std::string& b) {
        const std::string x = a.rfind("-", 0) == 0 ? a.substr(1) : a;
        const std::string y = b.rfind("-", 0) == 0 ? b.substr(1) : b;
        return x != y ? text_less(x, y) : text_less(a, b);
    });
    terms.insert(terms.end(), scalars.begin(), scalars.end());
    return terms;
}

std::string join_terms(const std::vector<std::string>& terms) {
    if (terms.empty()) return "0";
    std::string s = terms[0];
    for (std::size_t i = 1; i < terms.size(); ++i)
        s += terms[i].rfind("-", 0) == 0 ? " - " + terms[i].substr(1) : " + " + terms[i];
    return s;
}

std::string add_text(const ex& e) { return join_terms(add_terms(e)); }

std::string str(const ex& e) {
    if (is_a<GiNaC::symbol>(e)) return ex_to<GiNaC::symbol>(e).get_name();
    if (is_a<GiNaC::numeric>(e)) return ginac_text(e);
    if (is_a<GiNaC::matrix>(e)) {
        const auto& m = ex_to<GiNaC::matrix>(e);
        std::string s = "[";
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) s += (i + j ? ", " : "") + str(m(i, j));
        return s + "]";
    }
    if (is_a<GiNaC::add>(e)) return add_text(e);
    if (is_a<GiNaC::mul>(e)) return mul_text(e);
    if (is_a<GiNaC::power>(e)) {
        if (is_a<GiNaC::numeric>(e.op(1)) && ex_to<GiNaC::numeric>(e.op(1)).is_negative())
            return product_text(1, {e});
        return power_text(e.op(0), e.op(1));
    }
    if (is_cross(e)) return factor_text(e.op(0)) + cross_sign() + factor_text(e.op(1));
    if (is_norm_sq(e)) return operand_norm(e.op(0)) + "^2";
    if (is_dot(e)) return factor_text(e.op(0)) + dot_sign() + factor_text(e.op(1));
    // [a, b, c] = a . (b x c), printed so that it reads back (a list [a, b, c] would not)
    if (is_triple(e))
        return factor_text(e.op(0)) + dot_sign() + "(" + factor_text(e.op(1)) + cross_sign() + factor_text(e.op(2)) + ")";
    // an integral object of a solution (mechanics/fixed_axis.h): int_a^b f dtau
    if (is_a<GiNaC::integral>(e))
        return "int_" + factor_text(e.op(1)) + "^" + factor_text(e.op(2)) + " " + factor_text(e.op(3)) + " d" +
               str(e.op(0));
    if (is_a<GiNaC::function>(e)) {
        std::string s = ex_to<GiNaC::function>(e).get_name() + "(";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + str(e.op(i));
        return s + ")";
    }
    return ginac_text(e);
}

}  // namespace

notation vector_notation() { return g_notation; }
void set_vector_notation(notation n) { g_notation = n; }

std::string to_string(const ex& e) { return to_string(e, g_notation); }

std::string to_string(const ex& e, notation n) {
    kind(e);  // reject ill-formed expressions with a typed error
    const notation saved = g_current;
    g_current = n;
    try {
        std::string s = str(e);
        g_current = saved;
        return s;
    } catch (...) {
        g_current = saved;
        throw;
    }
}

}  // namespace symrep
