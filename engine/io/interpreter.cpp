// symrep/io/interpreter.cpp
#include "io/interpreter.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "algebra/scalar.h"
#include "io/parser.h"
#include "io/printer.h"
#include "vector/vector.h"

namespace symrep::lang {

namespace {
const char* const out_of_memory_message =
    "out of memory: the result is too large for this machine (the statement was abandoned)";

/// Known messages of GiNaC and CLN, said in the terms of the language.
std::string clear_message(const std::string& m) {
    struct known {
        const char* raw;
        const char* clear;
    };
    static const known table[] = {
        {"pow(0,0) is undefined", "0^0 is undefined"},
        {"singular matrix", "the matrix is singular"},
        {"numeric::factorial(): argument must be integer >= 0",
         "factorial: the argument must be an integer >= 0"},
        {"log(0)", "log(0) is undefined"},
        {"floating point overflow", "floating-point overflow (a number too large for floating point)"},
        {"floating point underflow", "floating-point underflow (a number too small for floating point)"},
        {"division by zero", "division by zero"},
        {"sum of non-commutative objects has non-zero numeric term",
         "a matrix cannot be added to a number here (use a multiple of the identity matrix)"},
        {"Not a 32-bit integer", "a number is too large here (it must fit in 32 bits)"},
        {"Not a 64-bit integer", "a number is too large here (it must fit in 64 bits)"},
    };
    for (const known& k : table)
        if (m.find(k.raw) != std::string::npos) return k.clear;
    // tan_eval(): simple pole, tanh_eval(): ..., the poles GiNaC finds while evaluating
    const std::size_t pole = m.find("_eval(): simple pole");
    if (pole != std::string::npos && pole > 0 && m.find_first_of(" :") > pole)
        return m.substr(0, pole) + ": the argument is a pole (the value is infinite)";
    return m;
}

/// The clock of a statement: sets `start` to now and, for a time limit > 0, the
/// deadline that the engine's long loops and guards see through check_interrupt()
/// (io/error.h), and lets operator new throw allocation_interrupted
/// (io/allocation_interrupt.cpp), until destroyed.
class statement_clock {
public:
    statement_clock(double limit, std::chrono::steady_clock::time_point& start)
        : previous_(deadline_ticks().load()) {
        ++interruptible_allocations();  // io/allocation_interrupt.cpp may stop GiNaC calls from here on
        start = std::chrono::steady_clock::now();
        if (limit > 0)
            deadline_ticks().store((start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                std::chrono::duration<double>(limit)))
                                       .time_since_epoch()
                                       .count());
    }
    ~statement_clock() {
        deadline_ticks().store(previous_);
        --interruptible_allocations();
    }
    statement_clock(const statement_clock&) = delete;
    statement_clock& operator=(const statement_clock&) = delete;

private:
    long long previous_;
};

/// The message to show for an exception: symrep's own verbatim, others translated.
std::string message_of(const std::exception& e) {
    if (dynamic_cast<const symrep::error*>(&e)) return e.what();
    if (const auto* b = dynamic_cast<const std::bad_alloc*>(&e))
        return allocation_failure_message(*b, out_of_memory_message);
    return clear_message(e.what());
}

}  // namespace

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

bool has_symbolic(const ex& e) {
    if (is_a<GiNaC::symbol>(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_symbolic(e.op(i))) return true;
    return false;
}

// An operation with a matrix operand must give a matrix: 2^m, m^x and the like
// have no meaning here (GiNaC would keep them as unevaluated products or powers
// that cannot even be printed).
ex finish(const ex& e, const ex& a, const ex& b, const std::string& op) {
    if (!is_a<GiNaC::matrix>(a) && !is_a<GiNaC::matrix>(b)) return e;
    const ex r = e.evalm();
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
        throw size_error("the power " + num_str(k) + " of an element is too large: element powers are limited to "
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
    if (!is_a<numeric>(ea) && ea.info(GiNaC::info_flags::real) && !has_symbolic(ea)) ea = ea.evalf();
    if (!is_a<numeric>(eb) && eb.info(GiNaC::info_flags::real) && !has_symbolic(eb)) eb = eb.evalf();
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

namespace {
// A list of three expressions used with vectors is the literal [x, y, z].
bool is_triple(const value& v) {
    return v.is_list() && v.as_list().size() == 3 &&
           std::all_of(v.as_list().begin(), v.as_list().end(), [](const value& e) { return e.is_ex(); });
}
ex as_literal(const value& v) {
    const list& l = v.as_list();
    return vector_literal(l[0].as_ex(), l[1].as_ex(), l[2].as_ex());
}
bool is_vector_ex(const value& v) { return v.is_ex() && !vector_symbols(v.as_ex()).empty(); }
/// A vector by its components (what solve(P, values) and eval give): a 3x1 matrix.
bool is_column3(const value& v) {
    if (!v.is_ex() || !is_a<GiNaC::matrix>(v.as_ex())) return false;
    const GiNaC::matrix& m = ex_to<GiNaC::matrix>(v.as_ex());
    return m.rows() == 3 && m.cols() == 1;
}
ex vector_operand(const std::string& op, const value& v, const char* side) {
    if (v.is_ex()) return v.as_ex();
    if (is_triple(v)) return as_literal(v);
    throw type_error("the " + std::string(side) + " operand of '" + op + "' must be a vector, not " + article(v));
}
}  // namespace

bool values_equal(const value& a, const value& b) {
    if (a.is_ex() && b.is_ex()) {
        const ex& x = a.as_ex();
        const ex& y = b.as_ex();
        if (!is_a<GiNaC::matrix>(x) && !is_a<GiNaC::matrix>(y) && (has_matrix(x) || has_matrix(y)))
            return x.is_equal(y);  // matrices inside relations and the like: never subtracted from numbers
        if (is_vector_ex(a) || is_vector_ex(b)) return symrep::equal(x, y);  // exact, by components
        if (is_a<GiNaC::matrix>(x) || is_a<GiNaC::matrix>(y)) {
            if (!is_a<GiNaC::matrix>(x) || !is_a<GiNaC::matrix>(y)) return false;
            const auto& m = ex_to<GiNaC::matrix>(x);
            const auto& n = ex_to<GiNaC::matrix>(y);
            if (m.rows() != n.rows() || m.cols() != n.cols()) return false;
            for (unsigned i = 0; i < m.rows(); ++i)
                for (unsigned j = 0; j < m.cols(); ++j)
                    if (!is_zero_scalar(m(i, j) - n(i, j))) return false;
            return true;
        }
        if (is_a<GiNaC::relational>(x) || is_a<GiNaC::relational>(y)) {
            if (!is_a<GiNaC::relational>(x) || !is_a<GiNaC::relational>(y)) return false;
            using F = GiNaC::info_flags;
            for (unsigned f : {F::relation_equal, F::relation_not_equal, F::relation_less,
                               F::relation_less_or_equal, F::relation_greater, F::relation_greater_or_equal})
                if (x.info(f) != y.info(f)) return false;
            return is_zero_scalar(x.op(0) - y.op(0)) && is_zero_scalar(x.op(1) - y.op(1));
        }
        return is_zero_scalar(x - y);
    }
    if (a.is_element() && b.is_element()) {
        if (a.as_element().parent().name() != b.as_element().parent().name()) return false;
        return a.as_element() == b.as_element();
    }
    if (a.is_element() && b.is_ex())  // never one holding a matrix (an element of matrices cannot be formed)
        return !has_matrix(b.as_ex()) &&
               a.as_element() == element::scalar(a.as_element().parent_ptr(), b.as_ex());
    if (a.is_ex() && b.is_element()) return values_equal(b, a);
    if (a.is_list() && b.is_list()) {
        const list& x = a.as_list();
        const list& y = b.as_list();
        if (x.size() != y.size()) return false;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (!values_equal(x[i], y[i])) return false;
        return true;
    }
    if (a.is_bool() && b.is_bool()) return a.as_bool() == b.as_bool();
    if (a.is_string() && b.is_string()) return a.as_string() == b.as_string();
    if (a.is_algebra() && b.is_algebra()) return a.as_algebra()->name() == b.as_algebra()->name();
    if (a.is_none() && b.is_none()) return true;
    return false;
}


value binary_op(const std::string& op, const value& a, const value& b) {
    // vectors (thesis Ch. VI): a x b, a . b; [x, y, z] next to a vector is a literal
    if (op == "x" || op == ".") {
        const ex u = vector_operand(op, a, "left"), v = vector_operand(op, b, "right");
        return op == "x" ? cross(u, v) : dot(u, v);
    }
    if ((op == "+" || op == "-" || op == "=") && (((is_vector_ex(a) || is_column3(a)) && is_triple(b)) ||
                                                  (is_triple(a) && (is_vector_ex(b) || is_column3(b)))))
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

// ---------------------------------------------------------------------------
// session

session::session(std::ostream& out, std::ostream& err)
    : out_(&out), err_(&err), digits_at_start_(GiNaC::Digits), notation_at_start_(symrep::vector_notation()) {
    register_all_builtins(reg_);
}
session::session() : session(std::cout, std::cerr) {}
session::~session() {  // Digits := n and notation(...) are per session
    GiNaC::Digits = digits_at_start_;
    symrep::set_vector_notation(notation_at_start_);
}

GiNaC::ex session::symbol(const std::string& name) {
    auto it = symbols_.find(name);
    if (it != symbols_.end()) return it->second;
    // Script symbols are real: the algebras of symrep are real algebras, and
    // real_part/conjugate of expressions in them must simplify.
    GiNaC::ex s = GiNaC::realsymbol(name);
    symbols_.emplace(name, s);
    return s;
}

void session::set(const std::string& name, value v) { vars_[name] = std::move(v); }

const value* session::get(const std::string& name) const {
    auto it = vars_.find(name);
    return it == vars_.end() ? nullptr : &it->second;
}

std::string session::resolve_path(const std::string& path) const {
    namespace fs = std::filesystem;
    fs::path p(path);
    if (p.is_absolute()) return path;
    const std::string& dir = dirs_.empty() ? base_dir_ : dirs_.back();
    if (dir.empty()) return path;
    return (fs::path(dir) / p).string();
}

namespace {

/// The text of line `line` (1-based) of `text`, without its newline.
std::string line_of(const std::string& text, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        start = text.find('\n', start);
        if (start == std::string::npos) return {};
        ++start;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    return text.substr(start, end - start);
}

bool utf8_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

/// Byte offset of (line, column) in text (both 1-based; columns count
/// characters, as the lexer does: UTF-8 continuation bytes do not), clamped to
/// the text.
std::size_t offset_of(const std::string& text, int line, int column) {
    std::size_t p = 0;
    for (int l = 1; l < line; ++l) {
        p = text.find('\n', p);
        if (p == std::string::npos) return text.size();
        ++p;
    }
    for (int c = 1; c < column && p < text.size() && text[p] != '\n'; ++c)
        for (++p; p < text.size() && utf8_continuation(text[p]);) ++p;
    return p;
}

std::string trimmed(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r\n;");
    if (a == std::string::npos) return {};
    const std::size_t b = s.find_last_not_of(" \t\r\n;");
    return s.substr(a, b - a + 1);
}

}  // namespace

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

void session::report(const source_location& where, const std::string& msg) {
    ++failures_;
    if (opts_.stop_on_error) stopped_ = true;
    if (opts_.format == output_options::json) {
        *err_ << "{\"error\": " << json_quote(msg) << ", \"file\": " << json_quote(where.file)
              << ", \"line\": " << where.line << ", \"column\": " << where.column << "}\n";
        err_->flush();
        return;
    }
    *err_ << where.file << ":" << where.line << ":" << where.column << ": error: " << msg << "\n";
    if (opts_.caret) {
        auto it = sources_.find(where.file);
        if (it != sources_.end() && where.line >= 1) {
            std::string l = line_of(it->second, where.line);
            if (!l.empty() && l.back() == '\r') l.pop_back();
            if (!l.empty() && where.column >= 1 && static_cast<std::size_t>(where.column) <= l.size() + 1) {
                std::string pad;  // one blank per character before the column (tabs kept)
                for (std::size_t i = 0; i < offset_of(l, 1, where.column); ++i)
                    if (!utf8_continuation(l[i])) pad += l[i] == '\t' ? '\t' : ' ';
                *err_ << "    " << l << "\n    " << pad << "^\n";
            }
        }
    }
    err_->flush();
}

int session::run_file(const std::string& path) {
    if (stopped_) return 0;
    const std::string full = resolve_path(path);
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(full, ec)) {
        report({path, 1, 1}, "cannot run '" + full + "': it is a directory, not a script");
        return 1;
    }
    std::ifstream in(full, std::ios::binary);
    if (!in) {
        report({path, 1, 1}, "cannot open file '" + full + "'");
        return 1;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    std::string dir = fs::path(full).parent_path().string();
    dirs_.push_back(dir);
    int failed = 0;
    try {
        // top-level files keep the name they were given; loaded files show
        // the resolved path, so that the report says where they are
        failed = run_string(ss.str(), dirs_.size() > 1 ? full : path);
    } catch (...) {
        dirs_.pop_back();
        throw;
    }
    dirs_.pop_back();
    return failed;
}

int session::run_string(const std::string& text, const std::string& name) {
    const int before = failures_;
    if (stopped_) return 0;
    parser p(text, name);
    files_.push_back(name);
    sources_[name] = text;
    while (!p.at_end() && !stopped_) {
        node_ptr s;
        try {
            s = p.next_statement();
        } catch (const syntax_error& e) {
            report(e.where, std::string("syntax error: ") + e.what());
            p.recover();
            continue;
        }
        if (!s) continue;
        const source_location here{name, s->line, s->column};
        if (opts_.echo) {
            const auto [bl, bc] = p.statement_begin();
            const auto [el, ec] = p.statement_end();
            const std::size_t a = offset_of(text, bl, bc);
            std::size_t b = offset_of(text, el, ec);
            if (b <= a) b = text.find('\n', a) == std::string::npos ? text.size() : text.find('\n', a);
            *out_ << "> " << trimmed(text.substr(a, b - a)) << "\n";
        }
        try {
            exec(*s, true);
        } catch (const script_error& e) {
            report(e.where, e.what());
        } catch (const std::bad_alloc& e) {
            report(here, allocation_failure_message(e, out_of_memory_message));
        } catch (const symrep::error& e) {
            report(here, e.what());
        } catch (const std::exception& e) {
            report(here, clear_message(e.what()));
        } catch (...) {
            report(here, "unknown internal error");
        }
    }
    files_.pop_back();
    out_->flush();
    return failures_ - before;
}

value session::evaluate(const std::string& text) {
    parser p(text, "<evaluate>");
    files_.push_back("<evaluate>");
    value last;
    try {
        while (!p.at_end()) {
            node_ptr s;
            try {
                s = p.next_statement();
            } catch (const syntax_error& e) {
                throw script_error(std::string("syntax error: ") + e.what(), e.where, std::current_exception());
            }
            if (!s) continue;
            if (s->kind == node::assign) {
                exec(*s, false);
                last = *get(s->text);
            } else if (s->kind == node::declare) {
                exec(*s, false);
                last = value();
            } else {
                const statement_clock clock(opts_.time_limit, statement_start_);
                last = eval(*s);
            }
        }
    } catch (...) {
        files_.pop_back();
        throw;
    }
    files_.pop_back();
    return last;
}

// vector a, b: a and b are vectors from now on (thesis Ch. VI);
// positive k: k is a positive real symbol from now on (earlier expressions keep
// the real symbol they were built with).
void session::declare(const node& n) {
    for (const auto& k : n.kids) {
        if (get(k->text))
            throw script_error("cannot declare '" + k->text + "': it is a variable (assigned with :=)",
                               {files_.empty() ? "<string>" : files_.back(), k->line, k->column});
        if (n.text == "vector") {
            register_vector(symbol(k->text));
        } else {
            if (is_vector_symbol(symbol(k->text)))
                throw script_error("cannot declare '" + k->text + "' positive: it is a vector",
                                   {files_.empty() ? "<string>" : files_.back(), k->line, k->column});
            symbols_[k->text] = GiNaC::possymbol(k->text);
        }
    }
}

// ode(EQUATION, x(0) = X0, x'(0) = X1, ...): the unknown x is a function of t;
// it is a vector when an initial value is. The equation is evaluated with x,
// x', ... bound to the unknown and its derivatives.
value session::ode_form(const node& n) {
    const std::string usage = " (usage: ode(x'' + a x' + b x = f, x(0) = x0, x'(0) = v0))";
    auto where = [&](const node& k) {
        return source_location{files_.empty() ? "<string>" : files_.back(), k.line, k.column};
    };
    if (n.kids.size() < 2) throw type_error("ode: expects an equation and initial conditions" + usage);
    const node& eq = *n.kids[0];
    if (eq.kind != node::binary || eq.text != "=")
        throw script_error("ode: the first argument must be an equation lhs = rhs" + usage, where(eq));
    mechanics::cauchy_problem P;
    std::vector<bool> seen;
    std::vector<value> init;
    for (std::size_t i = 1; i < n.kids.size(); ++i) {
        const node& c = *n.kids[i];
        if (c.kind != node::binary || c.text != "=" || c.kids[0]->kind != node::call || c.kids[0]->kids.size() != 1)
            throw script_error("ode: argument " + std::to_string(i + 1) + " must be an initial condition such as " +
                                   "x(0) = x0 or x'(0) = v0" + usage, where(c));
        const std::string& f = c.kids[0]->text;
        std::size_t k = 0;  // the number of primes
        while (k < f.size() && f[f.size() - 1 - k] == '\'') ++k;
        const std::string base = f.substr(0, f.size() - k);
        if (P.name.empty()) P.name = base;
        if (base != P.name)
            throw script_error("ode: initial conditions for two functions, " + P.name + " and " + base, where(c));
        const value t0 = eval(*c.kids[0]->kids[0]);
        if (!t0.is_ex() || !t0.as_ex().is_zero())
            throw script_error("ode: initial conditions are given at t = 0", where(*c.kids[0]->kids[0]));
        if (k >= seen.size()) { seen.resize(k + 1, false); init.resize(k + 1); }
        if (seen[k]) throw script_error("ode: " + f + "(0) is given twice", where(c));
        seen[k] = true;
        init[k] = eval(*c.kids[1]);
    }
    for (std::size_t k = 0; k < seen.size(); ++k)
        if (!seen[k])
            throw type_error("ode: the initial condition " + P.name + std::string(k, '\'') + "(0) is missing" + usage);
    P.t = symbol("t");
    if (P.name == "t") throw type_error("ode: the unknown cannot be named t (t is the independent variable)");
    for (const value& v : init)
        if (!v.is_ex() && !is_triple(v))
            throw type_error("ode: an initial value must be an expression or a vector, not " + article(v));
    P.is_vector = false;
    for (const value& v : init)
        if ((v.is_ex() && is_vector(v.as_ex())) || v.is_list()) P.is_vector = true;
    for (const value& v : init) {
        const ex e = v.is_list() ? vector_operand("ode", v, "initial") : v.as_ex();
        if (P.is_vector && !e.is_zero() && !is_vector(e))
            throw type_error("ode: the initial values mix vectors and scalars: " + print_ex(e));
        P.initial.push_back(e);
    }
    const std::size_t M = init.size();
    // a derivative of higher order than the conditions allow is an error at its place
    std::function<void(const node&)> scan = [&](const node& k) {
        if (k.kind == node::ident && k.text.size() > P.name.size() + M && k.text.rfind(P.name, 0) == 0 &&
            k.text.find_first_not_of('\'', P.name.size()) == std::string::npos)
            throw script_error("ode: " + k.text + " appears, but " + std::to_string(M) + " initial condition" +
                                   (M == 1 ? "" : "s") + " make an equation of order " + std::to_string(M),
                               where(k));
        for (const auto& c : k.kids) scan(*c);
    };
    scan(eq);
    // The unknown and its derivatives (the order is the number of conditions),
    // bound as x, x', ... while the equation is evaluated.
    auto build = [&](bool vector) {
        P.is_vector = vector;
        P.unknowns.clear();
        if (vector) {
            GiNaC::ex x = GiNaC::realsymbol(P.name);
            register_vector_function(x, P.t);
            P.unknowns.push_back(x);
            for (std::size_t m = 1; m <= M; ++m) P.unknowns.push_back(derivative(P.unknowns.back()));
        } else {
            for (std::size_t m = 0; m <= M; ++m) P.unknowns.push_back(GiNaC::realsymbol(P.unknown_name(m)));
        }
        std::map<std::string, std::optional<value>> saved;
        for (std::size_t m = 0; m <= M; ++m) {
            const std::string nm = P.unknown_name(m);
            const value* old = get(nm);
            saved[nm] = old ? std::optional<value>(*old) : std::nullopt;
            vars_[nm] = value(P.unknowns[m]);
        }
        auto restore = [&] {
            for (auto& [nm, v] : saved) {
                if (v) vars_[nm] = *v;
                else vars_.erase(nm);
            }
        };
        value lhs, rhs;
        try {
            lhs = eval(*eq.kids[0]);
            rhs = eval(*eq.kids[1]);
        } catch (...) {
            restore();
            throw;
        }
        restore();
        const value E = binary_op("-", lhs, rhs);
        if (!E.is_ex())
            throw script_error("ode: the equation must be between expressions, not " + article(lhs) + " and " +
                                   article(rhs), where(eq));
        P.expression = E.as_ex();
        if (vector && !E.as_ex().is_zero() && !is_vector(E.as_ex()))
            throw script_error("ode: the equation is scalar but the initial values are vectors", where(eq));
    };
    // initial values that are all 0 leave the kind open: a vector if the equation is one
    const bool open = !P.is_vector && std::all_of(P.initial.begin(), P.initial.end(), [](const ex& e) { return e.is_zero(); });
    if (open) {
        try {
            build(true);
        } catch (const std::exception&) {
            build(false);
        }
    } else {
        build(P.is_vector);
    }
    // read once, now: errors point at ode(...), and solve() uses the result
    P.reduced = std::make_shared<const mechanics::operator_form>(mechanics::reduce(P));
    return value(std::make_shared<const mechanics::cauchy_problem>(std::move(P)));
}

void session::exec(const node& stmt, bool echo) {
    const statement_clock clock(opts_.time_limit, statement_start_);
    if (stmt.kind == node::declare) {
        declare(stmt);
        return;
    }
    if (stmt.kind == node::assign) {
        value v = eval(*stmt.kids[0]);
        if (v.is_none())
            throw script_error("cannot assign nothing to '" + stmt.text + "': the right side has no value",
                               {files_.empty() ? "<string>" : files_.back(), stmt.line, stmt.column});
        if (stmt.text == "Digits") {
            // Digits := n sets the precision of floats (evalf, float literals)
            if (!v.is_ex() || !is_a<numeric>(v.as_ex()) || !ex_to<numeric>(v.as_ex()).is_pos_integer() ||
                ex_to<numeric>(v.as_ex()) > 100000)
                throw script_error("Digits must be a positive integer (at most 100000), not " +
                                       (v.is_ex() ? print_ex(v.as_ex()) : article(v)),
                                   {files_.empty() ? "<string>" : files_.back(), stmt.line, stmt.column});
            GiNaC::Digits = ex_to<numeric>(v.as_ex()).to_long();
        }
        set(stmt.text, std::move(v));
        return;
    }
    value v = eval(stmt);
    if (!echo || v.is_none()) return;
    results_.push_back(v);
    switch (opts_.format) {
        case output_options::text:
            if (labels_) *out_ << "%" << results_.size() << " = ";
            *out_ << print_value(v, true) << "\n";
            break;
        case output_options::latex: *out_ << latex_value(v) << "\n"; break;
        case output_options::json:
            *out_ << "{\"file\": " << json_quote(files_.empty() ? "<string>" : files_.back())
                  << ", \"line\": " << stmt.line << ", \"kind\": " << json_quote(v.kind())
                  << ", \"value\": " << json_quote(print_value(v, false)) << "}\n";
            break;
    }
}

std::atomic<bool>& interrupt_requested() { return symrep::interrupt_flag(); }

std::vector<std::string> session::variable_names() const {
    std::vector<std::string> names;
    for (const auto& [k, v] : vars_) names.push_back(k);
    return names;
}

value session::eval(const node& n) {
    if (interrupt_requested().load(std::memory_order_relaxed))
        throw script_error("interrupted", {files_.empty() ? "<string>" : files_.back(), n.line, n.column});
    if (opts_.time_limit > 0 && (++ticks_ & 63) == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - statement_start_).count() > opts_.time_limit) {
        std::ostringstream os;
        os << "time limit: the statement ran longer than " << opts_.time_limit << " s (--time-limit)";
        throw script_error(os.str(), {files_.empty() ? "<string>" : files_.back(), n.line, n.column});
    }
    try {
        return eval_inner(n);
    } catch (const script_error&) {
        throw;
    } catch (const allocation_interrupted& e) {  // Ctrl-C or the time limit, inside a library call
        throw script_error(e.what(), {files_.empty() ? "<string>" : files_.back(), n.line, n.column},
                           std::make_exception_ptr(symrep::error(e.what())));
    } catch (const std::bad_alloc&) {
        throw script_error(out_of_memory_message, {files_.empty() ? "<string>" : files_.back(), n.line, n.column},
                           std::make_exception_ptr(size_error(out_of_memory_message)));
    } catch (const symrep::error& e) {
        throw script_error(e.what(), {files_.empty() ? "<string>" : files_.back(), n.line, n.column},
                           std::current_exception());
    } catch (const std::exception& e) {
        throw script_error(clear_message(e.what()), {files_.empty() ? "<string>" : files_.back(), n.line, n.column},
                           std::current_exception());
    } catch (...) {
        throw script_error("unknown internal error", {files_.empty() ? "<string>" : files_.back(), n.line, n.column},
                           std::current_exception());
    }
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> d(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t prev = d[0];
        d[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cur = d[j];
            d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
            prev = cur;
        }
    }
    return d[b.size()];
}

/// Float literals: 1e999999999 would make CLN work for hours.
void check_float_exponent(const std::string& text) {
    const std::size_t e = text.find_first_of("eE");
    if (e == std::string::npos) return;
    std::size_t i = e + 1;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    while (i < text.size() && text[i] == '0') ++i;
    const std::string digits = text.substr(i);
    if (digits.size() > 6 || (!digits.empty() && std::stol(digits) > 100000))
        throw size_error("the exponent of the number " + text + " is too large (the limit is 10^5 in absolute value)");
}

long index_value(const value& v, std::size_t size) {
    if (!v.is_ex() || !is_a<numeric>(v.as_ex()) || !ex_to<numeric>(v.as_ex()).is_integer())
        throw type_error("an index must be an integer, not " + (v.is_ex() ? print_ex(v.as_ex()) : article(v)));
    const numeric k = ex_to<numeric>(v.as_ex());
    if (k.is_negative() || k >= numeric(static_cast<long>(size)))
        throw type_error("index " + num_str(k) + " out of range: valid indices are 0.." +
                         (size == 0 ? std::string("(none, it is empty)") : std::to_string(size - 1)));
    return k.to_long();
}

}  // namespace

std::vector<std::string> similar_builtin_names(const registry& r, const std::string& name, std::size_t limit) {
    std::vector<std::pair<std::size_t, std::string>> near;
    for (const builtin* c : r.all()) {
        const std::size_t d = edit_distance(name, c->name);
        const bool prefix = name.size() >= 3 && c->name.rfind(name, 0) == 0;
        if (d <= std::max<std::size_t>(1, name.size() / 3) || prefix) near.emplace_back(prefix ? 0 : d, c->name);
    }
    std::sort(near.begin(), near.end());
    std::vector<std::string> out;
    for (std::size_t i = 0; i < near.size() && i < limit; ++i) out.push_back(near[i].second);
    return out;
}

value session::call(const node& n) {
    const builtin* b = reg_.find(n.text);
    if (!b) {
        const std::vector<std::string> near = similar_builtin_names(reg_, n.text);
        std::string msg = "unknown function '" + n.text + "'";
        if (!near.empty()) {
            msg += "; did you mean ";
            for (std::size_t i = 0; i < near.size(); ++i) msg += (i ? ", " : "") + near[i];
            msg += "?";
        } else {
            msg += " (help() lists all functions)";
        }
        throw type_error(msg);
    }
    if (b->name == "ode") return ode_form(n);
    // seq(e, k, ...) and sum(e, k, ...) evaluate e once per value of k (so that
    // seq(diff(f, x, k), k, 0, 3) sees k as a number, not as a symbol).
    if ((b->name == "seq" || b->name == "sum") && (n.kids.size() == 3 || n.kids.size() == 4) &&
        n.kids[1]->kind == node::ident)
        return iterate(*b, n);
    std::vector<value> args;
    args.reserve(n.kids.size());
    for (const auto& k : n.kids) args.push_back(eval(*k));
    if (args.size() < b->min_args || args.size() > b->max_args) {
        std::string expected;
        if (b->min_args == b->max_args) expected = std::to_string(b->min_args);
        else if (b->max_args == SIZE_MAX) expected = "at least " + std::to_string(b->min_args);
        else expected = std::to_string(b->min_args) + " to " + std::to_string(b->max_args);
        throw type_error(b->name + ": expects " + expected + " argument" + (expected == "1" ? "" : "s") +
                         ", got " + std::to_string(args.size()) + " (usage: " + b->signature + ")");
    }
    return b->fn(args, *this);
}

value session::iterate(const builtin& b, const node& n) {
    const std::string& k = n.kids[1]->text;
    list values;
    if (n.kids.size() == 3) {
        value l = eval(*n.kids[2]);
        if (!l.is_list())
            throw type_error(b.name + ": argument 3 must be a list of values for " + k + " (usage: " + b.signature + ")");
        values = l.as_list();
    } else {
        const std::vector<value> a{value(), value(), eval(*n.kids[2]), eval(*n.kids[3])};
        const long lo = arg_int(a, 2, b, -1000000000L, 1000000000L);
        const long hi = arg_int(a, 3, b, -1000000000L, 1000000000L);
        if (hi - lo > 10000000) throw size_error(b.name + ": more than 10^7 values asked for");
        for (long i = lo; i <= hi; ++i) values.push_back(ex(i));
    }
    // k is bound as a variable while e is evaluated, then restored.
    std::optional<value> saved;
    if (const value* old = get(k)) saved = *old;
    auto restore = [&] {
        if (saved) vars_[k] = *saved;
        else vars_.erase(k);
    };
    list out;
    try {
        for (const value& kv : values) {
            vars_[k] = kv;
            out.push_back(eval(*n.kids[0]));
        }
    } catch (...) {
        restore();
        throw;
    }
    restore();
    if (b.name == "seq") return out;
    if (out.empty()) return ex(0);
    value acc = out[0];
    for (std::size_t i = 1; i < out.size(); ++i) acc = binary_op("+", acc, out[i]);
    return acc;
}

value session::eval_inner(const node& n) {
    switch (n.kind) {
        case node::number: {
            const bool is_float = n.text.find_first_of(".eE") != std::string::npos;
            if (!is_float) return ex(numeric(n.text.c_str()));
            check_float_exponent(n.text);
            return ex(numeric(n.text.c_str()).evalf());
        }
        case node::string: return n.text;
        case node::boolean: return n.text == "true";
        case node::ident: {
            if (const value* v = get(n.text)) return *v;
            if (n.text == "pi") return ex(GiNaC::Pi);
            if (n.text == "I") return ex(GiNaC::I);
            if (n.text == "Euler") return ex(GiNaC::Euler);
            if (n.text == "Catalan") return ex(GiNaC::Catalan);
            return ex(symbol(n.text));
        }
        case node::result: {
            const std::size_t count = results_.size();
            std::size_t k = 0;  // 1-based number of the result asked for
            if (n.text == "%" || n.text == "%%") {
                const std::size_t back = n.text == "%" ? 1 : 2;
                if (count < back)
                    throw type_error(n.text + " has no value yet: " + n.text +
                                     (back == 1 ? " is the last printed result" : " is the result before the last") +
                                     ", and " + (count == 0 ? "none has" : "only one has") + " been printed");
                k = count + 1 - back;
            } else {
                const std::string digits = n.text.substr(1);
                if (digits.size() > 18 || std::stoull(digits) == 0 || std::stoull(digits) > count)
                    throw type_error("no result " + n.text + ": " +
                                     (count == 0 ? std::string("none has been printed yet")
                                                 : "the results so far are %1.." + std::string("%") + std::to_string(count)));
                k = std::stoull(digits);
            }
            return results_[k - 1];
        }
        case node::unary: {
            value a = eval(*n.kids[0]);
            if (n.text == "|") {  // |a|: the norm sqrt(a . a) of a vector, the absolute value of a scalar
                if (is_triple(a)) return value(norm(as_literal(a)));  // |[3, 4, 12]|
                if (a.is_ex() && is_vector(a.as_ex())) return value(norm(a.as_ex()));
                if (a.is_ex() && !is_a<GiNaC::relational>(a.as_ex()) && !is_a<GiNaC::matrix>(a.as_ex()))
                    return value(GiNaC::abs(a.as_ex()));
                throw type_error("|...| needs a vector or a scalar expression, not " + article(a));
            }
            if (n.text == "+") {
                if (a.is_ex() || a.is_element() || a.is_list()) return a;
                throw type_error("unary '+' needs a number, expression, element or list, not " + article(a));
            }
            return negate(a);
        }
        case node::binary: {
            value a = eval(*n.kids[0]);
            value b = eval(*n.kids[1]);
            return binary_op(n.text, a, b);
        }
        case node::chain: {
            value acc = eval(*n.kids[0]);
            for (std::size_t i = 0; i < n.text.size(); ++i) {
                value b = eval(*n.kids[i + 1]);
                try {
                    acc = binary_op(std::string(1, n.text[i]), acc, b);
                } catch (const std::exception& e) {
                    throw script_error(message_of(e), {files_.empty() ? "<string>" : files_.back(), n.op_pos[i].first,
                                                  n.op_pos[i].second},
                                       std::current_exception());
                }
            }
            return acc;
        }
        case node::call: return call(n);
        case node::index: {
            value a = eval(*n.kids[0]);
            value k = eval(*n.kids[1]);
            if (a.is_list()) return a.as_list()[index_value(k, a.as_list().size())];
            if (a.is_element()) return a.as_element()[index_value(k, a.as_element().dim())];
            if (a.is_ex() && is_a<GiNaC::matrix>(a.as_ex())) {
                const auto& m = ex_to<GiNaC::matrix>(a.as_ex());
                const long r = index_value(k, m.rows());
                list row;
                for (unsigned c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
                return row;
            }
            if (a.is_ex() && is_a<GiNaC::lst>(a.as_ex())) return a.as_ex().op(index_value(k, a.as_ex().nops()));
            throw type_error("cannot index " + article(a) + " (indexing works on lists, elements and matrices)");
        }
        case node::list: {
            list l;
            l.reserve(n.kids.size());
            for (const auto& k : n.kids) {
                value v = eval(*k);
                if (v.is_none()) throw type_error("a list entry has no value");
                l.push_back(std::move(v));
            }
            return l;
        }
        case node::assign:
            throw type_error("an assignment ':=' is a statement, not an expression");
        case node::declare:
            throw type_error("a declaration is a statement, not an expression");
    }
    throw type_error("unknown syntax node");
}

}  // namespace symrep::lang
