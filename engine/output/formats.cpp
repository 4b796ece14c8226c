// symrep/output/formats.cpp -- LaTeX, C, Python and JSON output (see formats.h).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>
#include <set>
#include <regex>
#include <sstream>

#include "symrep/output/formats.h"

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"

#include "symrep/output/printer.h"
#include "symrep/output/precedence.h"
#include "symrep/scalar/floats.h"
#include "symrep/vector/vector.h"

namespace symrep::output {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

namespace {

std::string num_text(const numeric& x) {
    if (x.is_real() && !x.is_rational()) return float_text(x);  // the float model (scalar/floats.h)
    std::ostringstream os;
    os << x;
    return os.str();
}

bool is_fn(const ex& e, const char* name) {
    return is_a<GiNaC::function>(e) && ex_to<GiNaC::function>(e).get_name() == name;
}

// ---------------------------------------------------------------------------
// LaTeX

const std::set<std::string>& greek() {
    static const std::set<std::string> g = {
        "alpha", "beta",  "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta",   "theta", "vartheta",
        "iota",  "kappa", "lambda", "mu",   "nu",      "xi",         "pi",   "rho",   "sigma", "tau",
        "upsilon", "phi", "varphi", "chi",  "psi",     "omega",      "Gamma", "Delta", "Theta", "Lambda",
        "Xi",    "Pi",    "Sigma", "Phi",   "Psi",     "Omega"};
    return g;
}

/// A name as LaTeX: greek letters as \alpha, a trailing number as a subscript
/// (x1 -> x_{1}), primes kept, longer names upright (\mathrm{name}); `bold`
/// wraps the letter part in \boldsymbol.
std::string latex_name(const std::string& name, bool bold = false) {
    std::string n = name, primes;
    while (!n.empty() && n.back() == '\'') {
        primes += '\'';
        n.pop_back();
    }
    std::string digits;
    std::size_t k = n.size();
    while (k > 0 && std::isdigit(static_cast<unsigned char>(n[k - 1]))) --k;
    if (k > 0 && k < n.size()) {
        digits = n.substr(k);
        n = n.substr(0, k);
    }
    std::string sub;
    const std::size_t us = n.find('_');
    if (digits.empty() && us != std::string::npos && us > 0 && us + 1 < n.size()) {
        sub = n.substr(us + 1);
        n = n.substr(0, us);
    } else {
        sub = digits;
    }
    std::string base;
    if (n == "eps") base = "\\varepsilon";
    else if (greek().count(n)) base = "\\" + n;
    else if (n.size() == 1) base = n;
    else {
        std::string esc;
        for (char c : n) esc += (c == '_') ? std::string("\\_") : std::string(1, c);
        base = "\\mathrm{" + esc + "}";
    }
    if (bold) base = "\\boldsymbol{" + base + "}";
    if (!sub.empty()) base += sub.size() == 1 ? "_" + sub : "_{" + sub + "}";
    return base + primes;
}

printed lx(const ex& e);

std::string lparen(const printed& o, int need) {
    return o.lvl < need ? "\\left(" + o.text + "\\right)" : o.text;
}

bool negative_numeric(const numeric& c) {
    if (c.is_real()) return c.is_negative();
    return c.real().is_negative() || (c.real().is_zero() && c.imag().is_negative());
}

printed lx_numeric(const numeric& x) {
    if (x.is_rational()) {
        const bool neg = x.is_negative();
        const numeric a = neg ? numeric(-x) : x;
        std::string t = a.is_integer() ? num_text(a) : "\\frac{" + num_text(a.numer()) + "}{" + num_text(a.denom()) + "}";
        if (neg) return {"-" + t, l_sum};
        return {t, a.is_integer() ? l_atom : l_product};
    }
    if (x.is_real()) {
        // a float in scientific form, 1.767E-5 (CLN may mark the exponent with another
        // letter), typesets as 1.767 \cdot 10^{-5}, every digit kept
        const std::string t = num_text(x);
        static const std::regex sci("(-?[0-9]+(?:\\.[0-9]*)?)[EeDdLlFfSs]\\+?(-?)0*([0-9]+)");
        std::smatch m;
        if (std::regex_match(t, m, sci)) {
            const std::string e = m[3].str() == "0" ? std::string("0") : m[2].str() + m[3].str();
            return {m[1].str() + " \\cdot 10^{" + e + "}", x.is_negative() ? l_sum : l_product};
        }
        return {t, x.is_negative() ? l_sum : l_atom};
    }
    const printed re = lx_numeric(x.real()), im = lx_numeric(x.imag());
    std::string imag = x.imag() == 1 ? "i" : x.imag() == -1 ? "-i" : im.text + " i";
    if (x.real().is_zero()) return {imag, l_product};
    if (imag.rfind("-", 0) == 0) return {re.text + " - " + imag.substr(1), l_sum};
    return {re.text + " + " + imag, l_sum};
}

std::string join_factors(const std::vector<std::string>& fs) {
    std::string s;
    for (std::size_t i = 0; i < fs.size(); ++i) {
        if (i) s += (std::isdigit(static_cast<unsigned char>(fs[i][0])) || fs[i][0] == '-') ? " \\cdot " : " ";
        s += fs[i];
    }
    return s;
}

bool is_vector_factor(const ex& f) {
    try {
        return is_vector(f);
    } catch (const std::exception&) {
        return false;
    }
}

// c * prod(factors) with c > 0 (the caller handles the sign).
printed lx_product(const numeric& c, const std::vector<ex>& factors) {
    std::vector<std::string> num, den, vec;
    std::string den_bare, num_bare;  // the text of a lone factor without parentheses (a sum alone in \frac)
    std::size_t num_factors = 0;
    for (const ex& f : factors) {
        if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_real() &&
            ex_to<numeric>(f.op(1)).is_negative() && !is_ex_the_function(f.op(0), vdot)) {
            const printed o = lx(GiNaC::pow(f.op(0), -f.op(1)));
            den.push_back(lparen(o, l_power));
            den_bare = o.text;
        } else if (is_vector_factor(f)) {
            vec.push_back(lparen(lx(f), l_power));
        } else {
            const printed o = lx(f);
            num.push_back(lparen(o, l_power));
            num_bare = o.text;
            ++num_factors;
        }
    }
    std::sort(num.begin(), num.end());
    std::sort(den.begin(), den.end());
    num.insert(num.end(), vec.begin(), vec.end());
    if (c.is_rational()) {
        if (c.numer() != 1 || (num.empty())) num.insert(num.begin(), num_text(c.numer()));
        if (c.denom() != 1) den.insert(den.begin(), num_text(c.denom()));
    } else if (c != 1) {  // a leading float 1.5 \cdot 10^{-5} needs no parentheses
        num.insert(num.begin(), c.is_real() ? lx_numeric(c).text : lparen(lx_numeric(c), l_power));
    }
    if (den.empty()) {
        if (num.size() == 1 && factors.size() == 1 && c == 1) return lx(factors[0]);
        return {join_factors(num), num.size() == 1 ? l_power : l_product};
    }
    const std::string top = num.empty() ? std::string("1")
                            : num_factors == 1 && num.size() == 1 && vec.empty() && c.is_rational() && c.numer() == 1 ? num_bare
                                                                                             : join_factors(num);
    return {"\\frac{" + top + "}{" + (den.size() == 1 && c.denom() == 1 ? den_bare : join_factors(den)) + "}",
            l_product};
}


printed lx_sum(const ex& e) {
    std::string s;
    bool first = true;
    for (const ex& t : canonical_terms(e)) {
        numeric c;
        std::vector<ex> rest;
        split_coefficient(t, c, rest);
        const bool neg = negative_numeric(c);
        printed body = lx_product(neg ? numeric(-c) : c, rest);
        const std::string b = body.lvl <= l_sum ? "\\left(" + body.text + "\\right)" : body.text;
        if (first) s += neg ? "-" + b : b;
        else s += (neg ? " - " : " + ") + b;
        first = false;
    }
    return {s, l_sum};
}

std::string fn_name(const std::string& n) {
    static const std::set<std::string> std_fns = {"sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh", "tanh",
                                                  "coth", "exp", "log", "arcsin", "arccos", "arctan"};
    static const std::map<std::string, std::string> renamed = {
        {"asin", "\\arcsin"}, {"acos", "\\arccos"}, {"atan", "\\arctan"}, {"ln", "\\ln"}};
    if (std_fns.count(n)) return "\\" + n;
    if (auto it = renamed.find(n); it != renamed.end()) return it->second;
    if (n.size() == 1) return n;
    std::string esc;
    for (char c : n) esc += (c == '_') ? std::string("\\_") : std::string(1, c);
    return "\\operatorname{" + esc + "}";
}

std::string vec_operand(const ex& a) {
    const printed o = lx(a);
    if (is_ex_the_function(a, vcross) || (is_ex_the_function(a, vdot) && !a.op(0).is_equal(a.op(1)))) return "\\left(" + o.text + "\\right)";
    return lparen(o, l_power);
}

// A dual quantity p + eps d grouped as p + \varepsilon d (print_ex's dual_text in LaTeX).
std::optional<printed> lx_dual(const ex& e) {
    dual::dual_parts p;
    try {
        p = dual::parts(e);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (p.dual.is_zero()) return lx(p.primal);
    ex d = p.dual;
    bool negative = false;
    if (!is_a<GiNaC::add>(d)) {
        numeric c;
        std::vector<ex> rest;
        split_coefficient(d, c, rest);
        if (negative_numeric(c)) {
            negative = true;
            d = -d;
        }
    }
    std::string body;
    if (d.is_equal(1)) body = "\\varepsilon";
    else if (is_a<numeric>(d)) body = lx_product(ex_to<numeric>(d), {dual::dual_unit()}).text;
    else {
        const printed q = lx(d);
        const bool wrap = q.lvl <= l_sum || (q.lvl < l_power && (involves_vectors(d) || is_vector_literal(d)));
        if (wrap) body = "\\varepsilon \\left(" + q.text + "\\right)";
        else body = (std::isdigit(static_cast<unsigned char>(q.text[0])) ? "\\varepsilon \\cdot " : "\\varepsilon ") + q.text;
    }
    if (p.primal.is_zero()) return printed{(negative ? "-" : "") + body, negative ? l_sum : l_product};
    return printed{lx(p.primal).text + (negative ? " - " : " + ") + body, l_sum};
}

printed lx(const ex& e) {
    if (is_a<numeric>(e)) return lx_numeric(ex_to<numeric>(e));
    if (e.is_equal(dual::dual_unit())) return {"\\varepsilon", l_atom};
    if ((is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e) || is_a<GiNaC::power>(e) || is_a<GiNaC::function>(e)) &&
        dual::has_dual_unit(e))
        if (const std::optional<printed> r = lx_dual(e)) return *r;
    if (is_a<GiNaC::symbol>(e)) return {latex_name(ex_to<GiNaC::symbol>(e).get_name(), is_vector_symbol(e)), l_atom};
    if (is_a<GiNaC::constant>(e)) {
        std::ostringstream os;
        e.print(GiNaC::print_latex(os));
        return {os.str(), l_atom};
    }
    if (is_a<GiNaC::add>(e)) return lx_sum(e);
    if (is_a<GiNaC::mul>(e)) {
        numeric c;
        std::vector<ex> rest;
        split_coefficient(e, c, rest);
        if (negative_numeric(c)) return {"-" + lparen(lx_product(-c, rest), l_product), l_sum};
        return lx_product(c, rest);
    }
    if (is_a<GiNaC::power>(e)) {
        const ex b = e.op(0), n = e.op(1);
        if (is_ex_the_function(b, vdot) && b.op(0).is_equal(b.op(1))) {  // |a|^(2n)
            const std::string a = "\\|" + lx(b.op(0)).text + "\\|";
            const ex k = 2 * n;
            if (k.is_equal(1)) return {a, l_atom};
            return {a + "^{" + lx(k).text + "}", l_power};
        }
        if (n.is_equal(GiNaC::numeric(1, 2))) return {"\\sqrt{" + lx(b).text + "}", l_atom};
        if (is_a<numeric>(n) && ex_to<numeric>(n).is_real() && ex_to<numeric>(n).is_negative())
            return lx_product(1, {e});
        return {lparen(lx(b), l_atom) + "^{" + lx(n).text + "}", l_power};
    }
    if (is_ex_the_function(e, vcross)) return {vec_operand(e.op(0)) + " \\times " + vec_operand(e.op(1)), l_product};
    if (is_ex_the_function(e, vdot)) {
        if (e.op(0).is_equal(e.op(1))) return {"\\|" + lx(e.op(0)).text + "\\|^{2}", l_power};
        return {vec_operand(e.op(0)) + " \\cdot " + vec_operand(e.op(1)), l_product};
    }
    if (is_ex_the_function(e, vtriple))
        return {"\\left[" + lx(e.op(0)).text + ", " + lx(e.op(1)).text + ", " + lx(e.op(2)).text + "\\right]", l_atom};
    if (is_fn(e, "abs")) return {"\\left|" + lx(e.op(0)).text + "\\right|", l_atom};
    if (is_a<GiNaC::function>(e)) {
        std::string s = fn_name(ex_to<GiNaC::function>(e).get_name()) + "\\left(";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + lx(e.op(i)).text;
        return {s + "\\right)", l_atom};
    }
    if (is_a<GiNaC::relational>(e)) {
        std::string op = " = ";
        if (e.info(GiNaC::info_flags::relation_not_equal)) op = " \\neq ";
        else if (e.info(GiNaC::info_flags::relation_less)) op = " < ";
        else if (e.info(GiNaC::info_flags::relation_less_or_equal)) op = " \\leq ";
        else if (e.info(GiNaC::info_flags::relation_greater)) op = " > ";
        else if (e.info(GiNaC::info_flags::relation_greater_or_equal)) op = " \\geq ";
        return {lx(e.op(0)).text + op + lx(e.op(1)).text, l_relation};
    }
    if (is_a<GiNaC::matrix>(e)) {
        const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
        std::string s = "\\begin{pmatrix}";
        for (unsigned r = 0; r < m.rows(); ++r) {
            s += r ? " \\\\ " : " ";
            for (unsigned c = 0; c < m.cols(); ++c) s += (c ? " & " : "") + lx(m(r, c)).text;
        }
        return {s + " \\end{pmatrix}", l_atom};
    }
    if (is_a<GiNaC::lst>(e)) {
        std::string s = "\\left[";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + lx(e.op(i)).text;
        return {s + "\\right]", l_atom};
    }
    if (is_a<GiNaC::pseries>(e)) return lx(ex_to<GiNaC::pseries>(e).convert_to_poly(false));
    std::ostringstream os;
    e.print(GiNaC::print_latex(os));
    return {os.str(), l_relation};
}

/// A basis name of an algebra ("i0*i1", "eps^2", "j*eps") as LaTeX.
std::string latex_basis(const std::string& name) {
    std::string s;
    std::size_t start = 0;
    while (start <= name.size()) {
        std::size_t star = name.find('*', start);
        if (star == std::string::npos) star = name.size();
        std::string part = name.substr(start, star - start);
        std::string expo;
        if (const std::size_t h = part.find('^'); h != std::string::npos) {
            expo = part.substr(h + 1);
            part = part.substr(0, h);
        }
        if (!s.empty()) s += " ";
        s += latex_name(part);
        if (!expo.empty()) s += "^{" + expo + "}";
        start = star + 1;
    }
    return s;
}

}  // namespace

std::string latex_element(const element& w) {
    std::string s;
    for (std::size_t k = 0; k < w.dim(); ++k) {
        const ex c = w[k];
        if (c.is_zero() || GiNaC::normal(c).is_zero()) continue;
        const std::string name = w.parent().basis_name(k);
        std::string term;
        if (name == "1") {
            term = lx(c).text;
        } else if (c.is_equal(1)) {
            term = latex_basis(name);
        } else if (c.is_equal(-1)) {
            term = "-" + latex_basis(name);
        } else {
            const printed o = lx(c);
            if (is_a<GiNaC::add>(c)) {  // a sum of negative terms: - (a + b) name
                const printed m = lx(-c);
                if (o.text.rfind("-", 0) == 0 && m.text.rfind("-", 0) != 0)
                    term = "-\\left(" + m.text + "\\right) " + latex_basis(name);
                else
                    term = "\\left(" + o.text + "\\right) " + latex_basis(name);
            } else {
                term = o.text + " " + latex_basis(name);
            }
        }
        if (s.empty()) s = term;
        else if (term.rfind("-", 0) == 0) s += " - " + term.substr(1);
        else s += " + " + term;
    }
    return s.empty() ? "0" : s;
}

namespace {

// ---------------------------------------------------------------------------
// Code

/// The vector symbols in e, by name.
void vector_names(const ex& e, std::set<std::string>& out) {
    if (is_vector_symbol(e)) {
        std::ostringstream os;
        os << e;
        out.insert(os.str());
        return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) vector_names(e.op(i), out);
}

void check_codable(const ex& e, const char* fn) {
    if (involves_vectors(e)) {
        std::set<std::string> names;
        vector_names(e, names);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        std::string first = names.empty() ? "w" : *names.begin();
        throw type_error(std::string(fn) + ": the expression has abstract vectors (" + list +
                         "); give their components first, e.g. subs(e, " + first + " = [" + first + "1, " + first +
                         "2, " + first + "3])");
    }
    if (is_a<GiNaC::relational>(e))
        throw type_error(std::string(fn) + ": an equation has no code; give one side (lhs(e) or rhs(e))");
}

printed py(const ex& e);

// The code printer writes Python (NumPy) or, when c_style is set, C with double
// arithmetic. Sums follow the canonical term order, products sort their factors.
thread_local bool c_style = false;

std::string pparen(const printed& o, int need) { return o.lvl < need ? "(" + o.text + ")" : o.text; }

/// An integer literal: 3 in Python, 3.0 in C (no integer division).
std::string int_lit(const numeric& n) { return c_style ? num_text(n) + ".0" : num_text(n); }

printed py_numeric(const numeric& x) {
    if (x.is_integer()) return {int_lit(x), x.is_negative() ? l_sum : l_atom};
    if (x.is_rational()) return {int_lit(x.numer()) + "/" + int_lit(x.denom()), l_sum};
    if (x.is_real()) {
        std::string t = num_text(x);
        return {t, x.is_negative() ? l_sum : l_atom};
    }
    if (c_style) throw type_error("ccode: complex numbers have no C double code: " + num_text(x));
    return {"complex(" + py_numeric(x.real()).text + ", " + py_numeric(x.imag()).text + ")", l_atom};
}

std::string py_fn(const std::string& n) {
    static const std::set<std::string> same = {"sin", "cos", "tan", "sinh", "cosh", "tanh", "exp", "log", "sqrt"};
    if (c_style) {
        static const std::map<std::string, std::string> c = {
            {"asin", "asin"}, {"acos", "acos"}, {"atan", "atan"}, {"asinh", "asinh"}, {"acosh", "acosh"},
            {"atanh", "atanh"}, {"abs", "fabs"}, {"atan2", "atan2"}};
        if (auto it = c.find(n); it != c.end()) return it->second;
        if (same.count(n)) return n;
        throw type_error("ccode: the function " + n + " has no C equivalent here");
    }
    static const std::map<std::string, std::string> m = {
        {"asin", "arcsin"}, {"acos", "arccos"}, {"atan", "arctan"}, {"asinh", "arcsinh"},
        {"acosh", "arccosh"}, {"atanh", "arctanh"}, {"abs", "abs"}, {"atan2", "arctan2"}};
    if (auto it = m.find(n); it != m.end()) return "numpy." + it->second;
    if (same.count(n)) return "numpy." + n;
    throw type_error("pycode: the function " + n + " has no NumPy equivalent here");
}

printed py(const ex& e) {
    if (is_a<numeric>(e)) return py_numeric(ex_to<numeric>(e));
    if (is_a<GiNaC::symbol>(e)) {
        std::string n = ex_to<GiNaC::symbol>(e).get_name();
        std::string r;
        for (char c : n) r += c == '\'' ? std::string("_p") : std::string(1, c);
        return {r, l_atom};
    }
    if (is_a<GiNaC::constant>(e)) {
        if (e.is_equal(GiNaC::Pi)) return {c_style ? "M_PI" : "numpy.pi", l_atom};
        if (e.is_equal(GiNaC::Euler) && !c_style) return {"numpy.euler_gamma", l_atom};
        return {py_numeric(ex_to<numeric>(e.evalf())).text, l_atom};
    }
    if (is_a<GiNaC::add>(e)) {
        std::string s;
        for (const ex& t : canonical_terms(e)) {
            numeric c;
            std::vector<ex> rest;
            split_coefficient(t, c, rest);
            const bool neg = negative_numeric(c) && !s.empty();
            const printed o = py(neg ? ex(-t) : t);
            if (s.empty()) s = o.text;
            else s += (neg ? " - " : " + ") + pparen(o, neg ? l_product : l_sum);
        }
        return {s, l_sum};
    }
    if (is_a<GiNaC::mul>(e)) {
        numeric c;
        std::vector<ex> rest;
        split_coefficient(e, c, rest);
        std::vector<std::string> num, den;
        for (const ex& f : rest) {
            if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_real() &&
                ex_to<numeric>(f.op(1)).is_negative())
                den.push_back(pparen(py(GiNaC::pow(f.op(0), -f.op(1))), l_power));
            else
                num.push_back(pparen(py(f), l_product + 1));
        }
        std::sort(num.begin(), num.end());
        std::sort(den.begin(), den.end());
        const bool neg = negative_numeric(c);
        const numeric a = neg ? numeric(-c) : c;
        if (a.is_rational()) {
            if (a.numer() != 1 || num.empty()) num.insert(num.begin(), int_lit(a.numer()));
            if (a.denom() != 1) den.insert(den.begin(), int_lit(a.denom()));
        } else if (a != 1) {
            num.insert(num.begin(), pparen(py_numeric(a), l_power));
        }
        std::string s;
        for (std::size_t i = 0; i < num.size(); ++i) s += (i ? "*" : "") + num[i];
        if (c_style && num.empty()) s = "1.0";
        for (const auto& d : den) s += "/" + d;
        return {(neg ? "-" : "") + s, neg ? l_sum : l_product};
    }
    if (is_a<GiNaC::power>(e)) {
        const ex b = e.op(0), n = e.op(1);
        if (n.is_equal(GiNaC::numeric(1, 2))) return {std::string(c_style ? "sqrt(" : "numpy.sqrt(") + py(b).text + ")", l_atom};
        if (c_style) return {"pow(" + py(b).text + ", " + py(n).text + ")", l_atom};
        // ** binds tighter than unary minus: (-2)**2, x**(-1)
        return {pparen(py(b), l_atom) + "**" + pparen(py(n), l_atom), l_power};
    }
    if (is_a<GiNaC::function>(e)) {
        std::string s = py_fn(ex_to<GiNaC::function>(e).get_name()) + "(";
        for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + py(e.op(i)).text;
        return {s + ")", l_atom};
    }
    throw type_error(std::string(c_style ? "ccode" : "pycode") + ": cannot write " + print_ex(e) + " as code");
}

}  // namespace

std::string latex_ex(const ex& e) { return lx(e).text; }


std::string c_code(const ex& e) {
    check_codable(e, "ccode");
    c_style = true;
    try {
        std::string t = py(e).text;
        c_style = false;
        return t;
    } catch (...) {
        c_style = false;
        throw;
    }
}

std::string python_code(const ex& e) {
    check_codable(e, "pycode");
    return py(e).text;
}

std::string json_quote(const std::string& s) {
    std::string q = "\"";
    for (unsigned char c : s) {
        switch (c) {
            case '"': q += "\\\""; break;
            case '\\': q += "\\\\"; break;
            case '\n': q += "\\n"; break;
            case '\t': q += "\\t"; break;
            case '\r': q += "\\r"; break;
            case '\b': q += "\\b"; break;
            case '\f': q += "\\f"; break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    q += buf;
                } else {
                    q += static_cast<char>(c);
                }
        }
    }
    return q + "\"";
}

}  // namespace symrep::output
