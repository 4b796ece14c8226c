// symrep/output/printer.cpp -- canonical printing (see printer.h for the rules).
#include "symrep/output/printer.h"
#include "symrep/output/precedence.h"

#include "symrep/dual/dual.h"
#include "symrep/scalar/floats.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

namespace symrep::output {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

namespace {

std::string num_str(const GiNaC::numeric& x) {
    std::ostringstream os;
    os << x;
    return os.str();
}

std::string paren(const printed& p, int need) { return p.lvl < need ? "(" + p.text + ")" : p.text; }

printed pr(const ex& e);

std::string ginac_text(const ex& e) {
    std::ostringstream os;
    os << e;
    return os.str();
}

printed pr_product(const numeric& c, const std::vector<ex>& factors);

// Real numbers: exact integers and rationals, or floats.
printed pr_real(const numeric& x) {
    if (x.is_rational()) {
        std::string t = num_str(x);
        const bool neg = x.is_negative();
        if (x.is_integer()) return {t, neg ? l_product : l_atom};
        return {t, l_product};
    }
    return {float_text(x), x.is_negative() ? l_product : l_atom};  // the float model (scalar/floats.h)
}

printed pr_numeric(const numeric& x) {
    if (x.is_real()) return pr_real(x);
    const numeric re = x.real(), im = x.imag();
    auto imag_text = [](const numeric& v) -> std::string {  // v > 0
        if (v == 1) return "I";
        if (v.is_rational()) return pr_product(ex_to<numeric>(ex(v) * GiNaC::I), {}).text;
        return paren(pr_real(v), l_product) + "*I";
    };
    if (re.is_zero()) {
        if (im.is_rational()) {  // p*I/q, through the product printer
            if (im.is_negative()) return {"-" + pr_product(-x, {}).text, l_product};
            return pr_product(x, {});
        }
        if (im.is_negative()) return {"-" + imag_text(-im), l_product};
        return {imag_text(im), im == 1 ? l_atom : l_product};
    }
    const std::string r = pr_real(re).text;
    if (im.is_negative()) return {r + " - " + imag_text(-im), l_sum};
    return {r + " + " + imag_text(im), l_sum};
}

// Sign of a numeric coefficient for display: negative real part, or zero real
// part and negative imaginary part.
bool looks_negative(const numeric& c) {
    if (c.is_real()) return c.is_negative();
    return c.real().is_negative() || (c.real().is_zero() && c.imag().is_negative());
}

bool is_order(const ex& e) {
    return is_a<GiNaC::function>(e) && ex_to<GiNaC::function>(e).get_name() == "Order";
}

bool contains_order(const ex& e) {
    if (is_order(e)) return true;
    if (is_a<GiNaC::mul>(e))
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (is_order(e.op(i))) return true;
    return false;
}

// Total degree in the symbols (exponents may be rational); 0 for numbers and
// constants, functions count as degree 0.
numeric degree_of(const ex& e) {
    if (is_a<GiNaC::symbol>(e)) return 1;
    if (is_a<GiNaC::add>(e)) {
        numeric d = 0;
        bool first = true;
        for (std::size_t i = 0; i < e.nops(); ++i) {
            numeric t = degree_of(e.op(i));
            if (first || t > d) d = t;
            first = false;
        }
        return d;
    }
    if (is_a<GiNaC::mul>(e)) {
        numeric d = 0;
        for (std::size_t i = 0; i < e.nops(); ++i) d += degree_of(e.op(i));
        return d;
    }
    if (is_a<GiNaC::power>(e)) {
        const ex n = e.op(1);
        if (is_a<numeric>(n) && ex_to<numeric>(n).is_real()) return degree_of(e.op(0)) * ex_to<numeric>(n);
        return degree_of(e.op(0));
    }
    return 0;
}

printed pr_sum(const ex& e);

// A sum whose printed form starts with a minus sign ("-a + b").
bool leading_term_negative(const ex& sum) { return pr_sum(sum).text.rfind("-", 0) == 0; }

// f = sign * g with g a sum whose leading term is positive (or a power of one with
// an integer exponent); other factors are returned unchanged with sign 1.
ex sign_normalized(const ex& f, int& sign) {
    sign = 1;
    if (is_a<GiNaC::add>(f)) {
        if (!leading_term_negative(f)) return f;
        sign = -1;
        return -f;
    }
    if (is_a<GiNaC::power>(f) && is_a<GiNaC::add>(f.op(0)) && is_a<numeric>(f.op(1)) &&
        ex_to<numeric>(f.op(1)).is_integer() && leading_term_negative(f.op(0))) {
        if (ex_to<numeric>(f.op(1)).is_odd()) sign = -1;
        // held: GiNaC's own evaluation would move the sign back by its internal order
        return GiNaC::dynallocate<GiNaC::power>(-f.op(0), f.op(1)).setflag(GiNaC::status_flags::evaluated);
    }
    return f;
}

// A factor as base^exponent (exponent 1 for a factor that is not a power).
std::pair<ex, numeric> base_exponent(const ex& f) {
    if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_rational())
        return {f.op(0), ex_to<numeric>(f.op(1))};
    return {f, 1};
}

// sqrt(B) / (-B) and -1/sqrt(B) are the same product; GiNaC holds either, depending on the
// order in which it built the terms (which its hash order, and so the addresses of its type
// names, decide): a radical B^p (p not an integer, B a sum) and a factor (+-B)^n with an
// integer n are merged into B^(p + n). Returns true when the merge moved a sign (-1)^n
// into the coefficient.
bool merge_radical_bases(std::vector<ex>& factors) {
    bool flipped = false;
    for (std::size_t i = 0; i < factors.size(); ++i) {
        auto [B, p] = base_exponent(factors[i]);
        if (!is_a<GiNaC::add>(B) || p.is_integer()) continue;
        bool merged = false;
        for (std::size_t j = 0; j < factors.size(); ++j) {
            if (j == i) continue;
            const auto [C, n] = base_exponent(factors[j]);
            if (!is_a<GiNaC::add>(C) || !n.is_integer() || C.nops() != B.nops()) continue;
            if (GiNaC::expand(C + B).is_zero()) {
                if (n.is_odd()) flipped = !flipped;
            } else if (!GiNaC::expand(C - B).is_zero()) {
                continue;
            }
            p += n;
            factors.erase(factors.begin() + std::ptrdiff_t(j));
            if (j < i) --i;
            --j;
            merged = true;
        }
        if (merged)
            factors[i] = p.is_zero() ? ex(1)
                                     : GiNaC::dynallocate<GiNaC::power>(B, p).setflag(GiNaC::status_flags::evaluated);
    }
    factors.erase(std::remove_if(factors.begin(), factors.end(), [](const ex& f) { return f.is_equal(1); }),
                  factors.end());
    return flipped;
}

// Splits a term into its numeric coefficient and its other factors.
void split_term(const ex& t, numeric& c, std::vector<ex>& rest) {
    c = 1;
    rest.clear();
    if (is_a<numeric>(t)) {
        c = ex_to<numeric>(t);
        return;
    }
    if (is_a<GiNaC::mul>(t)) {
        for (std::size_t i = 0; i < t.nops(); ++i) {
            const ex f = t.op(i);
            if (is_a<numeric>(f)) {
                c *= ex_to<numeric>(f);
            } else {
                // (x1 - x2)*t and -(x2 - x1)*t are the same product; GiNaC may hold
                // either, depending on the order it built terms in (memory addresses).
                // Print every sum factor with its leading term positive.
                int sign = 1;
                rest.push_back(sign_normalized(f, sign));
                if (sign < 0) c = -c;
            }
        }
        if (merge_radical_bases(rest)) c = -c;
        return;
    }
    rest.push_back(t);
}

bool negative_exponent(const ex& f) {
    if (!is_a<GiNaC::power>(f)) return false;
    const ex n = f.op(1);
    return is_a<numeric>(n) && ex_to<numeric>(n).is_real() && ex_to<numeric>(n).is_negative();
}

// c * prod(factors), c not "negative" (the caller prints the sign).
printed pr_product(const numeric& c, const std::vector<ex>& factors) {
    std::vector<std::string> num, den;
    for (const ex& f : factors) {
        if (negative_exponent(f)) {
            const ex b = GiNaC::pow(f.op(0), -f.op(1));
            den.push_back(paren(pr(b), l_power));
        } else {
            num.push_back(paren(pr(f), l_power));
        }
    }
    std::sort(num.begin(), num.end());
    std::sort(den.begin(), den.end());
    std::string coef_num, coef_den;
    bool coef_piece = false;
    if (!c.is_real() && c.real().is_zero() && c.imag().is_rational()) {
        // pure imaginary rational coefficient p*I/q: numbers first, then I
        const numeric p = c.imag().numer(), q = c.imag().denom();
        num.insert(num.begin(), "I");
        if (p != 1) num.insert(num.begin(), num_str(p));
        if (q != 1) den.insert(den.begin(), num_str(q));
        std::string n;
        for (std::size_t i = 0; i < num.size(); ++i) n += (i ? "*" : "") + num[i];
        if (den.empty()) return {n, num.size() == 1 ? l_atom : l_product};
        std::string d;
        for (std::size_t i = 0; i < den.size(); ++i) d += (i ? "*" : "") + den[i];
        if (den.size() > 1) d = "(" + d + ")";
        return {n + "/" + d, l_product};
    }
    if (c.is_rational()) {
        const numeric p = c.numer(), q = c.denom();
        if (p != 1 || num.empty()) coef_num = num_str(p);
        if (q != 1) coef_den = num_str(q);
    } else if (c != 1) {
        coef_num = paren(pr_numeric(c), l_power);
        coef_piece = true;
    }
    (void)coef_piece;
    if (!coef_num.empty()) num.insert(num.begin(), coef_num);
    if (!coef_den.empty()) den.insert(den.begin(), coef_den);
    std::string n;
    for (std::size_t i = 0; i < num.size(); ++i) n += (i ? "*" : "") + num[i];
    if (num.empty()) n = "1";
    if (den.empty()) {
        if (num.size() == 1 && factors.size() == 1 && coef_num.empty()) return pr(factors[0]);
        if (num.size() == 1 && factors.empty()) return pr_numeric(c);
        return {n, l_product};
    }
    std::string d;
    for (std::size_t i = 0; i < den.size(); ++i) d += (i ? "*" : "") + den[i];
    if (den.size() > 1) d = "(" + d + ")";
    return {n + "/" + d, l_product};
}

struct term_text {
    bool negative;
    std::string body;  // printed |term|
    // sort key
    bool is_order;
    numeric degree;
    bool symbolic;
    std::string monomial;
    std::map<std::string, numeric> powers;  // symbol name -> exponent
    std::size_t index = 0;                  // of the term in e
};

// Exponents of the symbols in a term (powers of symbols with numeric exponents).
void symbol_powers(const std::vector<ex>& factors, std::map<std::string, numeric>& out) {
    for (const ex& f : factors) {
        if (is_a<GiNaC::symbol>(f)) out[ex_to<GiNaC::symbol>(f).get_name()] += 1;
        else if (is_a<GiNaC::power>(f) && is_a<GiNaC::symbol>(f.op(0)) && is_a<numeric>(f.op(1)) &&
                 ex_to<numeric>(f.op(1)).is_real())
            out[ex_to<GiNaC::symbol>(f.op(0)).get_name()] += ex_to<numeric>(f.op(1));
    }
}

// Lexicographic order on exponent vectors, symbols taken alphabetically: returns
// -1 when a comes first (higher power of the first differing symbol), 1 when b does.
int lex_compare(const std::map<std::string, numeric>& a, const std::map<std::string, numeric>& b) {
    auto i = a.begin();
    auto j = b.begin();
    while (i != a.end() || j != b.end()) {
        std::string name;
        if (j == b.end() || (i != a.end() && i->first < j->first)) name = i->first;
        else name = j->first;
        const numeric ea = (i != a.end() && i->first == name) ? i->second : numeric(0);
        const numeric eb = (j != b.end() && j->first == name) ? j->second : numeric(0);
        if (ea != eb) return ea > eb ? -1 : 1;
        if (i != a.end() && i->first == name) ++i;
        if (j != b.end() && j->first == name) ++j;
    }
    return 0;
}

std::vector<term_text> sorted_terms(const ex& e) {
    std::vector<term_text> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex t = e.op(i);
        numeric c;
        std::vector<ex> rest;
        split_term(t, c, rest);
        term_text tt;
        tt.negative = looks_negative(c);
        const numeric a = tt.negative ? numeric(-c) : c;
        printed p = pr_product(a, rest);
        tt.body = p.lvl < l_product ? "(" + p.text + ")" : p.text;
        tt.is_order = contains_order(t);
        tt.degree = degree_of(t);
        tt.symbolic = has_symbol(t);
        tt.monomial = rest.empty() ? std::string() : pr_product(1, rest).text;
        symbol_powers(rest, tt.powers);
        tt.index = i;
        terms.push_back(std::move(tt));
    }
    std::sort(terms.begin(), terms.end(), [](const term_text& a, const term_text& b) {
        if (a.is_order != b.is_order) return b.is_order;
        if (a.degree != b.degree) return a.degree > b.degree;
        if (a.symbolic != b.symbolic) return a.symbolic;
        if (const int c = lex_compare(a.powers, b.powers)) return c < 0;
        if (a.monomial != b.monomial) return a.monomial < b.monomial;
        if (a.negative != b.negative) return !a.negative;
        return a.body < b.body;
    });
    return terms;
}

printed pr_sum(const ex& e) {
    const std::vector<term_text> terms = sorted_terms(e);
    std::string s;
    for (std::size_t i = 0; i < terms.size(); ++i) {
        if (i == 0) s += terms[i].negative ? "-" : "";
        else s += terms[i].negative ? " - " : " + ";
        s += terms[i].body;
    }
    return {s, l_sum};
}

std::string relation_op(const ex& e) {
    if (e.info(GiNaC::info_flags::relation_equal)) return " = ";
    if (e.info(GiNaC::info_flags::relation_not_equal)) return " != ";
    if (e.info(GiNaC::info_flags::relation_less)) return " < ";
    if (e.info(GiNaC::info_flags::relation_less_or_equal)) return " <= ";
    if (e.info(GiNaC::info_flags::relation_greater)) return " > ";
    if (e.info(GiNaC::info_flags::relation_greater_or_equal)) return " >= ";
    return " ? ";
}

printed pr(const ex& e) {
    if (is_a<numeric>(e)) return pr_numeric(ex_to<numeric>(e));
    if (is_a<GiNaC::symbol>(e)) return {ex_to<GiNaC::symbol>(e).get_name(), l_atom};
    if (is_a<GiNaC::constant>(e)) {
        std::string n = ginac_text(e);
        if (n == "Pi") n = "pi";
        return {n, l_atom};
    }
    if (is_a<GiNaC::add>(e)) return pr_sum(e);
    if (is_a<GiNaC::mul>(e)) {
        numeric c;
        std::vector<ex> rest;
        split_term(e, c, rest);
        if (looks_negative(c)) {
            printed p = pr_product(-c, rest);
            return {"-" + paren(p, l_product), l_product};
        }
        return pr_product(c, rest);
    }
    if (is_a<GiNaC::power>(e)) {
        int sign = 1;
        const ex g = sign_normalized(e, sign);
        if (sign < 0) return {"-" + paren(pr(g), l_product), l_product};
        if (!g.is_equal(e)) return pr(g);
        const ex b = e.op(0), n = e.op(1);
        if (n == GiNaC::ex(1) / 2) return {"sqrt(" + pr(b).text + ")", l_atom};
        if (negative_exponent(e)) return pr_product(1, {e});
        return {paren(pr(b), l_atom) + "^" + paren(pr(n), l_atom), l_power};
    }
    if (is_a<GiNaC::function>(e)) {
        std::string s = ex_to<GiNaC::function>(e).get_name() + "(";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + pr(e.op(i)).text;
        return {s + ")", l_atom};
    }
    if (is_a<GiNaC::relational>(e))
        return {paren(pr(e.op(0)), l_sum) + relation_op(e) + paren(pr(e.op(1)), l_sum), l_relation};
    if (is_a<GiNaC::matrix>(e)) {
        const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
        std::string s = "matrix([";
        for (unsigned r = 0; r < m.rows(); ++r) {
            s += r ? ", [" : "[";
            for (unsigned c = 0; c < m.cols(); ++c) s += (c ? ", " : "") + pr(m(r, c)).text;
            s += "]";
        }
        return {s + "])", l_atom};
    }
    if (is_a<GiNaC::lst>(e)) {
        std::string s = "[";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + pr(e.op(i)).text;
        return {s + "]", l_atom};
    }
    if (is_a<GiNaC::pseries>(e)) return pr(ex_to<GiNaC::pseries>(e).convert_to_poly(false));
    return {ginac_text(e), l_relation};
}


}  // namespace

std::string quote_string(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        if (c == '\n') { q += "\\n"; continue; }
        if (c == '\t') { q += "\\t"; continue; }
        q += c;
    }
    return q + "\"";
}

// Vector expressions (thesis Ch. VI) print in the thesis notation of vector.h.
bool involves_vectors(const ex& e) {
    if (is_vector_symbol(e) || is_ex_the_function(e, vcross) || is_ex_the_function(e, vdot) ||
        is_ex_the_function(e, vtriple))
        return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (involves_vectors(e.op(i))) return true;
    return false;
}

namespace {
// A sum or product with a vector literal among its terms or factors (cos(t) [1, 1, 0] - sin(t) [0, 1, 0],
// as a solver builds it): a vector expression, printed in the vector notation, not as matrix(...).
bool holds_vector_literal(const ex& e) {
    if (!is_a<GiNaC::add>(e) && !is_a<GiNaC::mul>(e)) return false;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (is_vector_literal(e.op(i)) || holds_vector_literal(e.op(i))) return true;
    return false;
}
}  // namespace

namespace {
// Messages of the lower floors (scalar/scalar.h, message_text) print canonically too.
const bool message_printer_registered = (set_message_printer(&print_ex), true);
}  // namespace

namespace {

// A dual quantity p + eps d (dual/dual.h) grouped: the primal part first, then eps
// times the dual part, each in the canonical form; relations side by side, lists and
// matrices entry by entry. nullopt where e has no dual parts (printed as it is).
std::optional<std::string> dual_text(const ex& e) {
    if (is_a<GiNaC::relational>(e)) return print_ex(e.op(0)) + relation_op(e) + print_ex(e.op(1));
    if (is_a<GiNaC::lst>(e)) {
        std::string s = "[";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + print_ex(e.op(i));
        return s + "]";
    }
    if (is_vector_literal(e))  // [1, eps, 0], as the list it is written as
        return "[" + print_ex(e.op(0)) + ", " + print_ex(e.op(1)) + ", " + print_ex(e.op(2)) + "]";
    if (is_a<GiNaC::matrix>(e)) {
        const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
        std::string s = "matrix([";
        for (unsigned r = 0; r < m.rows(); ++r) {
            s += r ? ", [" : "[";
            for (unsigned c = 0; c < m.cols(); ++c) s += (c ? ", " : "") + print_ex(m(r, c));
            s += "]";
        }
        return s + "])";
    }
    dual::dual_parts p;
    try {
        p = dual::parts(e);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (p.dual.is_zero()) return print_ex(p.primal);
    ex d = p.dual;
    bool negative = false;
    if (!is_a<GiNaC::add>(d)) {
        numeric c;
        std::vector<ex> rest;
        split_term(d, c, rest);
        if (looks_negative(c)) {
            negative = true;
            d = -d;
        }
    }
    std::string body;
    numeric coefficient = 1;
    std::vector<ex> factors;
    if (!is_a<GiNaC::add>(d)) split_term(d, coefficient, factors);
    const bool has_literal = holds_vector_literal(d);
    if (d.is_equal(1)) body = "eps";
    else if (is_a<numeric>(d)) body = pr(dual::dual_unit() * d).text;  // 2*eps, eps/2
    else if (coefficient.is_integer() && !coefficient.is_zero() && !coefficient.is_equal(1) && !involves_vectors(d) &&
             !has_literal)
        body = pr(coefficient).text + "*eps*" + paren(pr(d / coefficient), l_product);  // 2*eps*x*y
    else if (involves_vectors(d) || has_literal)
        body = is_vector_symbol(d) || is_vector_literal(d) ? "eps*" + print_ex(d) : "eps*(" + print_ex(d) + ")";
    else body = "eps*" + paren(pr(d), l_product);
    if (p.primal.is_zero()) return (negative ? "-" : "") + body;
    return print_ex(p.primal) + (negative ? " - " : " + ") + body;
}

}  // namespace

std::string print_ex(const ex& e) {
    if (dual::has_dual_unit(e))
        if (const std::optional<std::string> s = dual_text(e)) return *s;
    // integral objects (a scalar Duhamel integral of mechanics/, int_0^t f dtau): the vector printer's notation
    const bool integral = std::any_of(e.preorder_begin(), e.preorder_end(),
                                      [](const ex& x) { return is_a<GiNaC::integral>(x); });
    if (!is_a<GiNaC::relational>(e) && (involves_vectors(e) || is_vector_literal(e) || integral))
        return symrep::to_string(e);
    if (holds_vector_literal(e)) {
        try {
            return symrep::to_string(e);
        } catch (const symrep::error&) {  // not a well-formed vector expression: printed as it is
        }
    }
    if (is_a<GiNaC::relational>(e) && (involves_vectors(e.op(0)) || involves_vectors(e.op(1))))
        return print_ex(e.op(0)) + " = " + print_ex(e.op(1));
    return pr(e).text;
}

void split_coefficient(const ex& term, numeric& c, std::vector<ex>& rest) { split_term(term, c, rest); }

std::vector<ex> canonical_terms(const ex& e) {
    if (!is_a<GiNaC::add>(e)) return {e};
    std::vector<ex> out;
    for (const term_text& t : sorted_terms(e)) out.push_back(e.op(t.index));
    return out;
}

std::string print_element(const element& w) {
    std::string s;
    bool first = true;
    for (std::size_t k = 0; k < w.dim(); ++k) {
        const ex& c0 = w[k];
        if (c0.is_zero() || GiNaC::normal(c0).is_zero()) continue;
        const std::string name = w.parent().basis_name(k);
        bool neg = false;
        ex c = c0;
        if (is_a<numeric>(c) && looks_negative(ex_to<numeric>(c))) neg = true;
        if (is_a<GiNaC::mul>(c)) {
            numeric cc;
            std::vector<ex> rest;
            split_term(c, cc, rest);
            neg = looks_negative(cc);
        }
        if (is_a<GiNaC::add>(c)) {  // a sum of negative terms prints as - (a + b)*name
            bool all_neg = true;
            for (std::size_t i = 0; i < c.nops() && all_neg; ++i) {
                numeric cc;
                std::vector<ex> rest;
                split_term(c.op(i), cc, rest);
                all_neg = looks_negative(cc);
            }
            neg = all_neg;
        }
        if (neg) c = -c;
        std::string body;
        if (name == "1") {
            printed p = pr(c);
            body = p.lvl < l_product ? "(" + p.text + ")" : p.text;
            if (p.lvl == l_sum && first && !neg) body = p.text;
        } else if (c == 1) {
            body = name;
        } else {
            body = paren(pr(c), l_product) + "*" + name;
        }
        if (first) s += neg ? "-" : "";
        else s += neg ? " - " : " + ";
        s += body;
        first = false;
    }
    return first ? "0" : s;
}

}  // namespace symrep::output
