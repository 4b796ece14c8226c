// symrep/lang/operators.cpp -- the operators of the language on values: arithmetic, vector products, comparison (negate, binary_op, values_equal).
#include "symrep/lang/interpreter.h"
#include "symrep/core/interrupt.h"
#include "symrep/lang/statement_clock.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "symrep/dual/dual.h"
#include "symrep/scalar/floats.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/syntax/parser.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"
#include "symrep/lang/print_value.h"
#include "symrep/output/formats.h"

namespace symrep::lang {

using output::json_quote;
using output::print_ex;

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

namespace {

std::string article(const value& v) { return v.a_kind(); }

const char* verb(const std::string& op) {
    if (op == "+") return "add";
    if (op == "-") return "subtract";
    if (op == "*") return "multiply";
    if (op == "/") return "divide";
    if (op == "^") return "raise";
    if (op == "=") return "equate";
    return "compare";
}

[[noreturn]] void bad_operands(const std::string& op, const value& a, const value& b) {
    std::string msg = std::string("cannot ") + verb(op) + " " + article(a);
    if (op == "^") msg += " to the power " + article(b);
    else if (op == "/") msg += " by " + article(b);
    else if (op == "-") msg = "cannot subtract " + article(b) + " from " + article(a);
    else msg += " and " + article(b);
    throw type_error(msg + " (operator '" + op + "')");
}

// An operation with a matrix operand must give a matrix: 2^m, m^x and the like
// have no meaning here (GiNaC would keep them as unevaluated products or powers
// that cannot even be printed).
ex finish(const ex& e, const ex& a, const ex& b, const std::string& op) {
    if (!is_a<GiNaC::matrix>(a) && !is_a<GiNaC::matrix>(b)) return e;
    const ex r = e.evalm();
    if (r.is_zero() && (op == "+" || op == "-") && is_a<GiNaC::matrix>(a) && is_a<GiNaC::matrix>(b)) {
        // M - M: GiNaC cancels the two equal terms to the number 0 before evalm()
        const GiNaC::matrix& m = ex_to<GiNaC::matrix>(a);
        return GiNaC::matrix(m.rows(), m.cols());
    }
    if (!is_a<GiNaC::matrix>(r)) {
        if (op == "^" && is_a<GiNaC::matrix>(b))
            throw type_error("a matrix cannot be an exponent (operator '^')");
        if (op == "^")
            throw type_error("a matrix can only be raised to an integer power, not " + print_ex(b) +
                             " (operator '^')");
        throw type_error("cannot combine a matrix with " +
                         std::string(is_a<GiNaC::matrix>(a) ? print_ex(b) : print_ex(a)) + " (operator '" + op +
                         "')");
    }
    return r;
}

/// Integer exponents of non-numeric bases (x^k, (2*x)^k, m^k) are limited to this.
constexpr long max_symbolic_exponent = 100000;

/// The largest bit length of the rational numbers in e (0 when there are none).
long max_numeric_bits(const ex& e) {
    if (is_a<numeric>(e)) {
        const numeric& x = ex_to<numeric>(e);
        if (!x.is_rational()) return 64;
        return std::max(x.numer().int_length(), x.denom().int_length());
    }
    long m = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) m = std::max(m, max_numeric_bits(e.op(i)));
    return m;
}

/// The numeric term of e: e itself if a number, the number GiNaC keeps last in a sum, else 0.
numeric numeric_term(const ex& e) {
    if (is_a<numeric>(e)) return ex_to<numeric>(e);
    if (is_a<GiNaC::add>(e) && e.nops() > 0 && is_a<numeric>(e.op(e.nops() - 1))) return ex_to<numeric>(e.op(e.nops() - 1));
    return 0;
}

ex ex_binary(const std::string& op, const ex& a, const ex& b) {
    // a relation between matrices (m = 1) takes no arithmetic: GiNaC would apply it to both sides
    for (const ex* r : {&a, &b})
        if (is_a<GiNaC::relational>(*r) && has_matrix(*r))
            throw type_error("cannot " + std::string(verb(op)) + " a relation between matrices (operator '" + op +
                             "')");
    if ((op == "+" || op == "-") && is_a<GiNaC::matrix>(a) != is_a<GiNaC::matrix>(b)) {
        // said here, not by GiNaC: add::eval throws for a matrix plus a number and loses the sum it allocated
        const ex& other = is_a<GiNaC::matrix>(a) ? b : a;
        if (is_a<numeric>(other) && !other.is_zero())
            throw type_error("a matrix cannot be added to a number here (use a multiple of the identity matrix)");
        if (!other.is_zero())
            throw type_error("cannot combine a matrix with " + print_ex(other) + " (operator '" + op + "')");
    }
    if ((op == "+" || op == "-") && (has_matrix(a) || has_matrix(b)) &&
        !(op == "+" ? numeric_term(a) + numeric_term(b) : numeric_term(a) - numeric_term(b)).is_zero())
        // 2*M + 1, (x + 1) + M: the same, for sums that hold a matrix (add::eval would throw and leak)
        throw type_error("a matrix cannot be added to a number here (use a multiple of the identity matrix)");
    if (op == "+") return finish(a + b, a, b, op);
    if (op == "-") return finish(a - b, a, b, op);
    if (op == "*") return finish(a * b, a, b, op);
    if (op == "/") {
        if (b.is_zero()) throw domain_error("division by zero");
        return finish(a / b, a, b, op);
    }
    if (op == "^") {
        if (a.is_zero() && is_a<numeric>(b)) {
            // said here, not by GiNaC: power::eval throws for these and loses the power it allocated
            const numeric re = ex_to<numeric>(b).real();
            if (re.is_negative())
                throw domain_error(ex_to<numeric>(b).is_real()
                                       ? "division by zero: 0 raised to a negative power"
                                       : "division by zero: 0 raised to a power with a negative real part");
            if (re.is_zero())
                throw domain_error(b.is_zero() ? "0^0 is undefined"
                                               : "0^" + print_ex(b) + " is undefined (0 raised to an imaginary power)");
        }
        if (is_a<numeric>(a) && is_a<numeric>(b) && !a.is_zero() &&
            (!ex_to<numeric>(a).is_crational() || !ex_to<numeric>(b).is_crational())) {
            // floating point, computed by CLN here: GiNaC's power::eval would do the same, but when
            // the result is beyond the range of the floats of the precision (an overflow, an
            // underflow) it throws and loses the power it allocated
            return ex(ex_to<numeric>(a).power(ex_to<numeric>(b)));
        }
        if (is_a<numeric>(a) && is_a<numeric>(b) && ex_to<numeric>(a).is_rational() &&
            ex_to<numeric>(b).is_integer()) {
            // exact powers of numbers: refuse results of more than ~10^7 bits
            const numeric& x = ex_to<numeric>(a);
            const numeric k = abs(ex_to<numeric>(b));
            const numeric bits = numeric(std::max(x.numer().int_length(), x.denom().int_length()));
            if (k > numeric(10000000) || k * bits > numeric(10000000))
                throw size_error("the exact power " + print_ex(a) + "^" + print_ex(b) +
                                 " would have more than 10^7 bits");
        }
        if (!is_a<numeric>(a) && is_a<numeric>(b) && ex_to<numeric>(b).is_integer()) {
            // integer powers of symbolic bases and matrices: bound the exponent, and the
            // size of the numbers the power of the base's numeric factors would have
            const numeric k = abs(ex_to<numeric>(b));
            if (k > numeric(max_symbolic_exponent))
                throw size_error("the power " + print_ex(b) + " of " +
                                 (is_a<GiNaC::matrix>(a) ? std::string("a matrix") : print_ex(a)) +
                                 " is too large: integer exponents of symbolic bases and matrices are limited to "
                                 "10^5 in absolute value");
            if (k * numeric(max_numeric_bits(a)) > numeric(10000000))
                throw size_error("the power " + print_ex(b) + " of " + print_ex(a) +
                                 " would hold numbers of more than 10^7 bits");
        }
        return finish(GiNaC::pow(a, b), a, b, op);
    }
    throw type_error("unknown operator " + op);
}

long integer_exponent(const value& b) {
    if (!b.is_ex() || !is_a<numeric>(b.as_ex()) || !ex_to<numeric>(b.as_ex()).is_integer())
        throw type_error("the power of an element must be an integer, not " +
                         (b.is_ex() ? print_ex(b.as_ex()) : article(b)));
    const numeric k = ex_to<numeric>(b.as_ex());
    if (abs(k) > numeric(max_symbolic_exponent))
        throw size_error("the power " + print_ex(k) + " of an element is too large: element powers are limited to "
                         "10^5 in absolute value");
    return k.to_long();
}

value list_map2(const std::string& op, const list& a, const list& b) {
    if (a.size() != b.size())
        throw type_error("cannot " + std::string(verb(op)) + " lists of different lengths (" +
                         std::to_string(a.size()) + " and " + std::to_string(b.size()) + ")");
    list r;
    r.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) r.push_back(binary_op(op, a[i], b[i]));
    return r;
}

value list_scale(const std::string& op, const value& s, const list& l, bool list_left) {
    list r;
    r.reserve(l.size());
    for (const value& x : l) r.push_back(list_left ? binary_op(op, x, s) : binary_op(op, s, x));
    return r;
}

bool both_real_numbers(const ex& a, const ex& b, numeric& x, numeric& y) {
    ex ea = a, eb = b;
    if (!is_a<numeric>(ea) && ea.info(GiNaC::info_flags::real) && !has_symbol(ea)) ea = ea.evalf();
    if (!is_a<numeric>(eb) && eb.info(GiNaC::info_flags::real) && !has_symbol(eb)) eb = eb.evalf();
    if (!is_a<numeric>(ea) || !is_a<numeric>(eb)) return false;
    x = ex_to<numeric>(ea);
    y = ex_to<numeric>(eb);
    return x.is_real() && y.is_real();
}

}  // namespace

// ---------------------------------------------------------------------------
// value arithmetic

value negate(const value& a) {
    if (a.is_ex()) {
        const ex& e = a.as_ex();
        return is_a<GiNaC::matrix>(e) ? ex((-e).evalm()) : ex(-e);
    }
    if (a.is_element()) return -a.as_element();
    if (a.is_list()) {
        list r;
        for (const value& x : a.as_list()) r.push_back(negate(x));
        return r;
    }
    throw type_error("cannot negate " + article(a));
}

// A list of three expressions used with vectors is the literal [x, y, z].
bool is_triple(const value& v) {
    return v.is_list() && v.as_list().size() == 3 &&
           std::all_of(v.as_list().begin(), v.as_list().end(), [](const value& e) { return e.is_ex(); });
}
ex as_literal(const value& v) {
    const list& l = v.as_list();
    return vector_literal(l[0].as_ex(), l[1].as_ex(), l[2].as_ex());
}
namespace {
bool is_vector_ex(const value& v) { return v.is_ex() && !vector_symbols(v.as_ex()).empty(); }
/// A vector by its components (what solve(P, values) and eval give): a 3x1 matrix.
bool is_column3(const value& v) {
    if (!v.is_ex() || !is_a<GiNaC::matrix>(v.as_ex())) return false;
    const GiNaC::matrix& m = ex_to<GiNaC::matrix>(v.as_ex());
    return m.rows() == 3 && m.cols() == 1;
}
}  // namespace
ex vector_operand(const std::string& op, const value& v, const char* side) {
    if (v.is_ex()) return v.as_ex();
    if (is_triple(v)) return as_literal(v);
    throw type_error("the " + std::string(side) + " operand of '" + op + "' must be a vector, not " + article(v));
}

namespace {

/// A printed expression cut to about 200 characters for a message.
std::string shortened(const std::string& s) {
    if (s.size() <= 200) return s;
    return s.substr(0, 120) + " ... " + s.substr(s.size() - 60) + " (" + std::to_string(s.size()) + " characters)";
}

/// The decision for one scalar difference, with the text of what is undecided.
equality decide(const ex& diff) {
    const zero_decision d = decide_zero(diff);
    equality e;
    e.result = d.is_zero;
    if (d.is_zero == truth::unknown) e.undecided = print_ex(diff);
    if (d.is_zero == truth::no) e.witness = witness_text(d);
    return e;
}

/// All of several decisions: no if one is no, unknown if one is unknown, yes otherwise.
equality all_of(const std::vector<equality>& parts) {
    equality out;
    out.result = truth::yes;
    for (const equality& p : parts) {
        if (p.result == truth::no) return p;
        if (p.result == truth::unknown && out.result == truth::yes) out = p;
    }
    return out;
}

equality known(bool b) {
    equality e;
    e.result = b ? truth::yes : truth::no;
    return e;
}

/// Vectors by components (vector/vector.h decide_zero_vector).
equality decide_vectors(const ex& x, const ex& y) {
    const zero_decision d = decide_zero_vector(x - y);
    equality e;
    e.result = d.is_zero;
    if (d.is_zero == truth::unknown) e.undecided = print_ex(x - y);
    if (d.is_zero == truth::no) e.witness = witness_text(d);
    return e;
}

}  // namespace

namespace {

// A sum or product of vector literals without vector symbols (what solve gives for literal data,
// -sin(a)*[0, 1, 0] + cos(a)*[1, 0, 0]) as the one literal it is; nothing for anything else. A
// literal and such a sum were compared as trees (a wrong false) and could not be subtracted.
std::optional<ex> literal_sum(const ex& e) {
    if (is_a<GiNaC::matrix>(e) || is_a<GiNaC::relational>(e) || !has_matrix(e) || !vector_symbols(e).empty())
        return std::nullopt;
    for (std::size_t i = 0; i < e.nops(); ++i)  // only vector literals inside (no 2x2 matrices)
        if (is_a<GiNaC::matrix>(e.op(i)) && !is_vector_literal(e.op(i))) return std::nullopt;
    try {
        const ex r = subs_components(e, {});
        if (is_vector_literal(r)) return r;
    } catch (const error&) {
    }
    return std::nullopt;
}

value as_one_literal(const value& v) {
    if (!v.is_ex()) return v;
    if (const auto r = literal_sum(v.as_ex())) return value(*r);
    return v;
}

}  // namespace

equality compare_values(const value& a0, const value& b0) {
    // both sides as literals where one of them is a vector by its components
    const bool literal = (a0.is_ex() && (literal_sum(a0.as_ex()) || is_vector_literal(a0.as_ex()))) ||
                         (b0.is_ex() && (literal_sum(b0.as_ex()) || is_vector_literal(b0.as_ex())));
    const value a = literal ? as_one_literal(a0) : a0, b = literal ? as_one_literal(b0) : b0;
    if (a.is_ex() && b.is_ex() && (dual::has_dual_unit(a.as_ex()) || dual::has_dual_unit(b.as_ex())) &&
        !is_a<GiNaC::relational>(a.as_ex()) && !is_a<GiNaC::relational>(b.as_ex()) && !has_matrix(a.as_ex()) &&
        !has_matrix(b.as_ex())) {
        // dual quantities (dual/dual.h): equal when their primal and their dual parts are
        const dual::dual_parts x = dual::parts(a.as_ex()), y = dual::parts(b.as_ex());
        return all_of({compare_values(value(x.primal), value(y.primal)), compare_values(value(x.dual), value(y.dual))});
    }
    if (a.is_ex() && b.is_ex()) {
        // floats as the decimals they print as, compared exactly (scalar/floats.h; docs/language.md, "Floats")
        const ex x = floats_as_decimals(a.as_ex());
        const ex y = floats_as_decimals(b.as_ex());
        // vectors and scalars of vectors, literals inside dot products too ((r0 . [0, 0, 1])
        // against ([0, 0, 1] . r0) was compared as trees and answered false): exact, by components
        if ((is_vector_ex(a) || is_vector_ex(b)) && !is_a<GiNaC::relational>(x) && !is_a<GiNaC::relational>(y))
            return decide_vectors(x, y);
        if (!is_a<GiNaC::matrix>(x) && !is_a<GiNaC::matrix>(y) && (has_matrix(x) || has_matrix(y)))
            return known(x.is_equal(y));  // matrices inside relations and the like: never subtracted from numbers
        if (is_a<GiNaC::matrix>(x) || is_a<GiNaC::matrix>(y)) {
            if (!is_a<GiNaC::matrix>(x) || !is_a<GiNaC::matrix>(y)) return known(false);
            const auto& m = ex_to<GiNaC::matrix>(x);
            const auto& n = ex_to<GiNaC::matrix>(y);
            if (m.rows() != n.rows() || m.cols() != n.cols()) return known(false);
            std::vector<equality> parts;
            for (unsigned i = 0; i < m.rows(); ++i)
                for (unsigned j = 0; j < m.cols(); ++j) parts.push_back(decide(m(i, j) - n(i, j)));
            return all_of(parts);
        }
        if (is_a<GiNaC::relational>(x) || is_a<GiNaC::relational>(y)) {
            if (!is_a<GiNaC::relational>(x) || !is_a<GiNaC::relational>(y)) return known(false);
            using F = GiNaC::info_flags;
            for (unsigned f : {F::relation_equal, F::relation_not_equal, F::relation_less,
                               F::relation_less_or_equal, F::relation_greater, F::relation_greater_or_equal})
                if (x.info(f) != y.info(f)) return known(false);
            return all_of({decide(x.op(0) - y.op(0)), decide(x.op(1) - y.op(1))});
        }
        return decide(x - y);
    }
    if (a.is_element() && b.is_element()) {
        const element& u = a.as_element();
        const element& v = b.as_element();
        if (u.parent().name() != v.parent().name()) return known(false);
        std::vector<equality> parts;
        for (std::size_t k = 0; k < u.dim(); ++k)
            parts.push_back(decide(floats_as_decimals(u[k]) - floats_as_decimals(v[k])));
        return all_of(parts);
    }
    if (a.is_element() && b.is_ex()) {  // never one holding a matrix (an element of matrices cannot be formed)
        if (has_matrix(b.as_ex())) return known(false);
        return compare_values(a, value(element::scalar(a.as_element().parent_ptr(), b.as_ex())));
    }
    if (a.is_ex() && b.is_element()) return compare_values(b, a);
    if (a.is_list() && b.is_list()) {
        const list& x = a.as_list();
        const list& y = b.as_list();
        if (x.size() != y.size()) return known(false);
        std::vector<equality> parts;
        for (std::size_t i = 0; i < x.size(); ++i) {
            parts.push_back(compare_values(x[i], y[i]));
            if (parts.back().result == truth::no) return parts.back();
        }
        return all_of(parts);
    }
    // a list [x, y, z] against a vector expression: the list is the literal
    if (a.is_list() && b.is_ex() && (is_vector_ex(b) || is_column3(b))) {
        try {
            return compare_values(value(vector_operand("==", a, "left")), b);
        } catch (const error&) {
            return known(false);  // not three scalars: not a vector
        }
    }
    if (a.is_ex() && b.is_list()) return compare_values(b, a);
    if (a.is_bool() && b.is_bool()) return known(a.as_bool() == b.as_bool());
    if (a.is_string() && b.is_string()) return known(a.as_string() == b.as_string());
    if (a.is_algebra() && b.is_algebra()) return known(a.as_algebra()->name() == b.as_algebra()->name());
    if (a.is_none() && b.is_none()) return known(true);
    return known(false);
}

bool values_equal(const value& a, const value& b) {
    const equality e = compare_values(a, b);
    if (e.result == truth::unknown)
        throw domain_error("cannot decide whether the two sides are equal: their difference " +
                           shortened(e.undecided) +
                           " is not proved 0, and no point was found where it is not 0 (see docs/language.md, "
                           "\"Equality\")");
    return e.result == truth::yes;
}

namespace {
value plain_binary_op(const std::string& op, const value& a, const value& b);

/// True when v is or holds (in a list) an expression in the dual unit eps.
bool holds_dual(const value& v) {
    if (v.is_ex()) return dual::has_dual_unit(v.as_ex());
    if (v.is_list()) return std::any_of(v.as_list().begin(), v.as_list().end(), holds_dual);
    return false;
}
}  // namespace

value reduce_dual(const value& v) {
    if (v.is_ex()) return dual::has_dual_unit(v.as_ex()) ? value(dual::reduce(v.as_ex())) : v;
    if (v.is_list()) {
        const list& l = v.as_list();
        if (std::none_of(l.begin(), l.end(), [](const value& x) { return x.is_ex() && dual::has_dual_unit(x.as_ex()); }) &&
            std::none_of(l.begin(), l.end(), [](const value& x) { return x.is_list(); }))
            return v;
        list r;
        r.reserve(l.size());
        for (const value& x : l) r.push_back(reduce_dual(x));
        return r;
    }
    return v;
}

// Every operation on dual quantities (expressions in the dual unit eps, dual/dual.h)
// is reduced modulo eps^2; a pure dual divisor is a zero divisor (eps * eps = 0).
value binary_op(const std::string& op, const value& a, const value& b) {
    const bool dual_b = b.is_ex() && dual::has_dual_unit(b.as_ex());
    if (!dual_b && !holds_dual(a) && !holds_dual(b)) return plain_binary_op(op, a, b);
    if ((op == "<" || op == ">" || op == "<=" || op == ">=") && a.is_ex() && b.is_ex())
        throw domain_error("cannot compare " + print_ex(a.as_ex()) + " and " + print_ex(b.as_ex()) + " by '" + op +
                           "': dual numbers are not ordered");
    if (op == "/" && dual_b && !has_matrix(b.as_ex()) && !is_a<GiNaC::relational>(b.as_ex()) &&
        !is_nonzero_generic(dual::primal(b.as_ex()), "the primal part of the divisor " + print_ex(b.as_ex())))
        throw zero_divisor_error("division by the dual number " + print_ex(b.as_ex()) +
                                     ": its primal part is 0, so it is a zero divisor (eps * eps = 0)",
                                 {});
    return reduce_dual(plain_binary_op(op, a, b));
}

namespace {

value plain_binary_op(const std::string& op, const value& a, const value& b) {
    // vectors (thesis Ch. VI): a x b, a . b; [x, y, z] next to a vector is a literal
    if (op == "x" || op == ".") {
        const ex u = vector_operand(op, a, "left"), v = vector_operand(op, b, "right");
        return op == "x" ? cross(u, v) : dot(u, v);
    }
    const auto vector_like = [](const value& v) {
        return is_vector_ex(v) || is_column3(v) || (v.is_ex() && literal_sum(v.as_ex()));
    };
    if ((op == "+" || op == "-" || op == "=") && ((vector_like(a) && is_triple(b)) || (is_triple(a) && vector_like(b))))
        return binary_op(op, a.is_list() ? value(as_literal(a)) : a, b.is_list() ? value(as_literal(b)) : b);
    if (op == "=" && a.is_ex() && is_triple(b))
        return ex(GiNaC::relational(a.as_ex(), as_literal(b), GiNaC::relational::equal));
    if (op == "=" && a.is_ex() && b.is_list() &&
        std::all_of(b.as_list().begin(), b.as_list().end(), [](const value& e) { return e.is_ex(); })) {
        GiNaC::lst l;  // t = [0, 1, 2, 5]: a list of values
        for (const value& e : b.as_list()) l.append(e.as_ex());
        return ex(GiNaC::relational(a.as_ex(), l, GiNaC::relational::equal));
    }
    if (op == "==") return values_equal(a, b);
    if (op == "!=") return !values_equal(a, b);
    if (op == "=") {
        if (a.is_ex() && b.is_ex()) return ex(GiNaC::relational(a.as_ex(), b.as_ex(), GiNaC::relational::equal));
        bad_operands(op, a, b);
    }
    if (op == "<" || op == ">" || op == "<=" || op == ">=") {
        if (!a.is_ex() || !b.is_ex() || has_matrix(a.as_ex()) || has_matrix(b.as_ex())) bad_operands(op, a, b);
        numeric x, y;
        if (both_real_numbers(a.as_ex(), b.as_ex(), x, y)) {
            if (op == "<") return x < y;
            if (op == ">") return x > y;
            if (op == "<=") return x <= y;
            return x >= y;
        }
        using R = GiNaC::relational;
        const R::operators o = op == "<" ? R::less : op == ">" ? R::greater : op == "<=" ? R::less_or_equal
                                                                                        : R::greater_or_equal;
        return ex(R(a.as_ex(), b.as_ex(), o));
    }
    // expressions
    if (a.is_ex() && b.is_ex() && (op == "+" || op == "-") && (is_vector_ex(a) || is_vector_ex(b)) &&
        (is_a<GiNaC::matrix>(a.as_ex()) || is_a<GiNaC::matrix>(b.as_ex()))) {
        // w + [1, 2, 3], 2*[0, 0, t] - r0: a vector sum with a literal term, as the
        // printer writes solutions (matrix arithmetic would refuse the abstract vector)
        // each side a vector first: GiNaC's sum of a matrix and a number throws, and loses the sum
        // (a 4x4 matrix of vector entries + 1e-3: the robustness run, input #47679 of seed 20261124)
        const bool va = is_vector(a.as_ex()), vb = is_vector(b.as_ex());  // both: each may be ill-formed
        if (!va || !vb)
            throw type_error(std::string("cannot ") + verb(op) + " a vector and a scalar (operator '" + op + "')");
        const ex r = op == "+" ? a.as_ex() + b.as_ex() : a.as_ex() - b.as_ex();
        (void)is_vector(r);  // [1, 2] + w: type_error
        return r;
    }
    if (a.is_ex() && b.is_ex() && (op == "+" || op == "-") &&
        (is_a<GiNaC::matrix>(a.as_ex()) != is_a<GiNaC::matrix>(b.as_ex()))) {
        // a literal and a sum of literals (a solution for literal data): one literal each
        const value x = as_one_literal(a), y = as_one_literal(b);
        if (is_a<GiNaC::matrix>(x.as_ex()) && is_a<GiNaC::matrix>(y.as_ex()))
            return ex_binary(op, x.as_ex(), y.as_ex());
    }
    if (a.is_ex() && b.is_ex()) {
        ex r = ex_binary(op, a.as_ex(), b.as_ex());
        if (is_vector_ex(a) || is_vector_ex(b)) (void)is_vector(r);  // w + 1, w*w, w^2: type_error
        return r;
    }
    // elements
    if (a.is_element() && b.is_element()) {
        const element& x = a.as_element();
        const element& y = b.as_element();
        if (op == "+") return x + y;
        if (op == "-") return x - y;
        if (op == "*") return x * y;
        if (op == "/") return x / y;
        bad_operands(op, a, b);
    }
    if (a.is_element() && b.is_ex()) {
        const element& x = a.as_element();
        const ex& s = b.as_ex();
        if (is_a<GiNaC::matrix>(s)) bad_operands(op, a, b);
        if (op == "+") return x + element::scalar(x.parent_ptr(), s);
        if (op == "-") return x - element::scalar(x.parent_ptr(), s);
        if (op == "*") return x * s;
        if (op == "/") {
            if (is_zero_scalar(s)) throw domain_error("division by zero");
            return x / s;
        }
        if (op == "^") return x.pow(integer_exponent(b));
    }
    if (a.is_ex() && b.is_element()) {
        const ex& s = a.as_ex();
        const element& y = b.as_element();
        if (is_a<GiNaC::matrix>(s)) bad_operands(op, a, b);
        if (op == "+") return element::scalar(y.parent_ptr(), s) + y;
        if (op == "-") return element::scalar(y.parent_ptr(), s) - y;
        if (op == "*") return s * y;
        if (op == "/") return s * y.inverse();
        bad_operands(op, a, b);
    }
    // lists
    if (a.is_list() && b.is_list() && (op == "+" || op == "-")) return list_map2(op, a.as_list(), b.as_list());
    if (a.is_list() && (b.is_ex() || b.is_element()) && (op == "*" || op == "/"))
        return list_scale(op, b, a.as_list(), true);
    if (b.is_list() && (a.is_ex() || a.is_element()) && op == "*") return list_scale(op, a, b.as_list(), false);
    if (a.is_list() && b.is_list() && op == "*")
        throw type_error("cannot multiply two lists (use matrix(...) for matrix products)");
    // strings
    if (a.is_string() && b.is_string() && op == "+") return a.as_string() + b.as_string();
    bad_operands(op, a, b);
}

}  // namespace

}  // namespace symrep::lang
