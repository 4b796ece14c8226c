// symrep/lang/builtins_core.cpp -- the generic builtins (section "Core"):
// printing, substitution, calculus, numeric evaluation, elementary functions,
// lists, matrices, scripts and help.
#include <climits>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iostream>

#include "symrep/scalar/scalar.h"
#include "symrep/lang/builtins.h"
#include "symrep/vector/vector.h"
#include "symrep/numeric/reference.h"
#include "symrep/lang/interpreter.h"
#include "symrep/output/printer.h"
#include "symrep/lang/print_value.h"
#include "symrep/core/expression_size.h"

namespace symrep::lang {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;
using args_t = std::vector<value>;

namespace {

const char* const core = "Core";
/// Applies f to an expression, to each coordinate of an element, and recursively
/// to the entries of a list.
template <class F> value map_value(const value& v, const builtin& b, F&& f) {
    if (v.is_ex()) return value(ex(f(v.as_ex())));
    if (v.is_element()) return v.as_element().map_coeffs([&](const ex& x) { return ex(f(x)); });
    if (v.is_list()) {
        list out;
        for (const value& x : v.as_list()) out.push_back(map_value(x, b, f));
        return out;
    }
    throw type_error(b.name + ": argument 1 must be an expression, element or list, not " + v.a_kind() +
                     " (usage: " + b.signature + ")");
}

bool contains_matrix(const ex& e) {
    if (is_a<GiNaC::matrix>(e)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (contains_matrix(e.op(i))) return true;
    return false;
}

/// Scalar functions (sin, exp, ...) have no meaning on a matrix here.
void no_matrix(const builtin& b, const ex& x) {
    if (contains_matrix(x))
        throw type_error(b.name + ": not defined on a matrix (it applies to expressions, and entry by entry to "
                                  "lists)");
}

/// degree/ldegree/coeff read exponents as machine integers: refuse larger ones
/// instead of letting them wrap around.
void check_int_exponents(const builtin& b, const ex& e) {
    if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer() &&
        abs(ex_to<numeric>(e.op(1))) > numeric(INT_MAX)) {
        std::ostringstream os;
        os << b.name << ": the exponent " << e.op(1) << " is too large (the limit is 2^31 - 1)";
        throw size_error(os.str());
    }
    for (std::size_t i = 0; i < e.nops(); ++i) check_int_exponents(b, e.op(i));
}

/// An integer argument of factorial/binomial: exact results of larger ones would
/// take hours and gigabytes.
constexpr long max_combinatorial_argument = 100000;
void check_combinatorial(const char* who, const char* what, const ex& x) {
    if (is_a<numeric>(x) && ex_to<numeric>(x).is_rational() &&
        abs(ex_to<numeric>(x)) > numeric(max_combinatorial_argument)) {
        std::ostringstream os;
        os << who << ": " << what << " " << x << " is too large (the limit is " << max_combinatorial_argument
           << " in absolute value)";
        throw size_error(os.str());
    }
}

/// Substitution list from `x = 1` or `[x = 1, y = 2]`.
GiNaC::lst relations(const value& v, const builtin& b, std::size_t i) {
    GiNaC::lst l;
    auto one = [&](const value& r) {
        if (!r.is_ex() || !is_a<GiNaC::relational>(r.as_ex()) ||
            !r.as_ex().info(GiNaC::info_flags::relation_equal))
            throw type_error(b.name + ": argument " + std::to_string(i + 1) +
                             " must be an equation x = a or a list of them (usage: " + b.signature + ")");
        l.append(r.as_ex());
    };
    if (v.is_list())
        for (const value& r : v.as_list()) one(r);
    else
        one(v);
    return l;
}

GiNaC::matrix arg_matrix(const args_t& a, std::size_t i, const builtin& b) {
    const ex& e = arg_ex(a, i, b);
    if (!is_a<GiNaC::matrix>(e))
        throw type_error(b.name + ": argument " + std::to_string(i + 1) + " must be a matrix (usage: " +
                         b.signature + ")");
    return ex_to<GiNaC::matrix>(e);
}

value matrix_from(const list& rows, const builtin& b) {
    if (rows.empty()) throw type_error(b.name + ": a matrix needs at least one row");
    std::size_t ncols = 0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        if (!rows[r].is_list()) throw type_error(b.name + ": row " + std::to_string(r) + " is not a list");
        if (r == 0) ncols = rows[r].as_list().size();
        if (rows[r].as_list().size() != ncols || ncols == 0)
            throw type_error(b.name + ": all rows must have the same, non-zero length");
    }
    GiNaC::matrix m(rows.size(), ncols);
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < ncols; ++c) {
            const value& x = rows[r].as_list()[c];
            if (!x.is_ex()) throw type_error(b.name + ": entry [" + std::to_string(r) + "][" + std::to_string(c) +
                                             "] must be an expression, not " + x.a_kind());
            m(r, c) = x.as_ex();
        }
    return ex(m);
}

/// The body of the elementary functions: f on an expression, entry by entry on a list.
value builtin_elementary(const builtin& b, const args_t& a, const std::function<ex(const ex&)>& f) {
    if (a[0].is_element())
        throw type_error(b.name + ": not defined on algebra elements (exp and log are)");
    const std::string nm = b.name;
    return map_value(a[0], b, [&](const ex& x) {
        no_matrix(b, x);
        // sin(1e300): GiNaC would evaluate at once with the float's ~20 digits, noise once
        // |x| outgrows them; the decimal the float writes, reduced exactly (issue 13)
        if ((nm == "sin" || nm == "cos" || nm == "tan") && GiNaC::is_a<numeric>(x) &&
            GiNaC::ex_to<numeric>(x).is_real() && !GiNaC::ex_to<numeric>(x).is_rational() &&
            GiNaC::abs(GiNaC::ex_to<numeric>(x)) >= numeric(10000000000L))
            return num::round_digits(num::evalf_reduced(f(num::decimal_floats_of(x)), GiNaC::Digits),
                                     GiNaC::Digits);
        return f(x);
    });
}

/// The row of the elementary function `name`, x -> f(x), "The `what` of x".
builtin_declaration elementary(const char* name, const char* what, const std::string& example,
                               std::function<ex(const ex&)> f) {
    return {name, std::string(name) + "(x)", std::string("The ") + what + " of x (elementwise on lists).", "",
            example, 1, 1,
            [f = std::move(f)](const builtin& b, const args_t& a, context&) { return builtin_elementary(b, a, f); }};
}

/// |c y| = |c| |y| for a number c (GiNaC keeps abs(-x) and abs(2*x) as they are).
ex absolute_value(const ex& x) {
    if (GiNaC::is_a<GiNaC::mul>(x) && GiNaC::is_a<numeric>(x.op(x.nops() - 1))) {
        const numeric c = ex_to<numeric>(x.op(x.nops() - 1));
        return GiNaC::abs(c) * GiNaC::abs(x / c);
    }
    return GiNaC::abs(x);
}

ex checked_factorial(const ex& x) {
    check_combinatorial("factorial", "the argument", x);
    return GiNaC::factorial(x);
}

value builtin_seq(const builtin& b, const args_t& a, context&) {
    const value& body = a[0];
    const GiNaC::symbol& k = arg_symbol(a, 1, b);
    list out;
    auto at = [&](const ex& kv) {
        GiNaC::lst s{k == kv};
        return map_value(body, b, [&](const ex& x) { return subs_checked(x, s); });
    };
    if (a.size() == 3) {
        for (const value& v : arg_list(a, 2, b)) {
            if (!v.is_ex()) throw type_error(b.name + ": the values of " + k.get_name() + " must be expressions");
            out.push_back(at(v.as_ex()));
        }
        return out;
    }
    const long lo = arg_int(a, 2, b, -1000000000L, 1000000000L);
    const long hi = arg_int(a, 3, b, -1000000000L, 1000000000L);
    if (hi - lo > 10000000) throw size_error(b.name + ": more than 10^7 values asked for");
    for (long i = lo; i <= hi; ++i) out.push_back(at(i));
    return out;
}

value sum_values(const list& l, const builtin& b) {
    if (l.empty()) return ex(0);
    value acc = l[0];
    for (std::size_t i = 1; i < l.size(); ++i) acc = binary_op("+", acc, l[i]);
    (void)b;
    return acc;
}

value builtin_print(const builtin&, const args_t& a, context& c) {
    for (std::size_t i = 0; i < a.size(); ++i) c.out() << (i ? " " : "") << print_value(a[i], false);
    c.out() << "\n";
    return value();
}

value builtin_subs(const builtin& b, const args_t& a, context&) {
    const GiNaC::lst s = relations(a[1], b, 1);
    return map_value(a[0], b, [&](const ex& x) {
        // vectors given by components: [1, 0, 0]*t + [0, 1, 0] becomes one literal
        const ex y = subs_checked(x, s);
        return !has_matrix(y) || GiNaC::is_a<GiNaC::matrix>(y) ? y
                                                                                      : y.evalm();
    });
}

value builtin_expand(const builtin& b, const args_t& a, context&) {
    return map_value(a[0], b, [&](const ex& x) {
        guard_expansion(x, b.name.c_str(), false);
        return GiNaC::expand(x);
    });
}

value builtin_normal(const builtin& b, const args_t& a, context&) {
    return map_value(a[0], b, [&](const ex& x) {
        guard_expansion(x, b.name.c_str(), true);
        return GiNaC::normal(x);
    });
}

value builtin_simplify(const builtin& b, const args_t& a, context&) {
    return map_value(a[0], b, [&](const ex& x) {
        guard_expansion(x, b.name.c_str(), true);
        return simplify_scalar(x);
    });
}

value builtin_factor(const builtin& b, const args_t& a, context&) {
    return map_value(a[0], b, [&](const ex& x) {
        guard_expansion(x, b.name.c_str(), true);
        return GiNaC::factor(GiNaC::normal(x));
    });
}

value builtin_collect(const builtin& b, const args_t& a, context&) {
    const ex x = arg_ex(a, 1, b);
    return map_value(a[0], b, [&](const ex& e) {
        guard_expansion(e, b.name.c_str(), false);
        return GiNaC::collect(GiNaC::expand(e), x);
    });
}

value builtin_diff(const builtin& b, const args_t& a, context&) {
    const GiNaC::symbol& x = arg_symbol(a, 1, b);
    const long n = a.size() > 2 ? arg_int(a, 2, b, 0, 1000) : 1;
    if (a[0].is_reduction()) {  // a solution by reduction (VI.3): its derivative in t is r'
        reduction red = a[0].as_reduction();
        if (!x.is_equal(ex_to<GiNaC::symbol>(red.solution->problem->t)))
            throw type_error(b.name + ": a solution by reduction depends on " +
                             output::print_ex(red.solution->problem->t) + " only");
        red.derivative += int(n);
        if (red.derivative > 1)
            throw type_error(b.name + ": a solution by reduction has its first derivative only, not higher ones");
        return value(red);
    }
    return map_value(a[0], b, [&](const ex& e) {
        guard_terms(expression_nodes(e) * double(n), b.name.c_str());
        // a vector declared as a function of x (vector r(t)) differentiates to r'
        // (diff_t); GiNaC's own diff holds every vector constant
        bool timed = false;
        for (const ex& v : vector_symbols(e)) timed = timed || !diff_t(v, x).is_zero();
        if (!timed) return e.diff(x, static_cast<unsigned>(n));
        ex d = e;
        for (long k = 0; k < n; ++k) d = diff_t(d, x);
        return d;
    });
}

value builtin_series(const builtin& b, const args_t& a, context&) {
    const ex& e = arg_ex(a, 0, b);
    const GiNaC::lst rel = relations(a[1], b, 1);
    if (rel.nops() != 1 || !is_a<GiNaC::symbol>(rel.op(0).op(0)))
        throw type_error(b.name + ": argument 2 must be one equation x = a with a symbol x (usage: " +
                         b.signature + ")");
    const long n = arg_int(a, 2, b, 0, 1000);
    const ex s = e.series(rel.op(0), static_cast<int>(n));
    if (is_a<GiNaC::pseries>(s)) return value(ex_to<GiNaC::pseries>(s).convert_to_poly(false));
    return value(s);
}

value builtin_coeff(const builtin& b, const args_t& a, context&) {
    const ex x = arg_ex(a, 1, b);
    const long n = arg_int(a, 2, b, -1000000, 1000000);
    check_int_exponents(b, arg_ex(a, 0, b));
    return value(GiNaC::expand(arg_ex(a, 0, b)).coeff(x, static_cast<int>(n)));
}

value builtin_degree(const builtin& b, const args_t& a, context&) {
    check_int_exponents(b, arg_ex(a, 0, b));
    return value(ex(GiNaC::expand(arg_ex(a, 0, b)).degree(arg_ex(a, 1, b))));
}

value builtin_ldegree(const builtin& b, const args_t& a, context&) {
    check_int_exponents(b, arg_ex(a, 0, b));
    return value(ex(GiNaC::expand(arg_ex(a, 0, b)).ldegree(arg_ex(a, 1, b))));
}

value builtin_numer(const builtin& b, const args_t& a, context&) {
    return value(GiNaC::numer(arg_ex(a, 0, b)));
}

value builtin_denom(const builtin& b, const args_t& a, context&) {
    return value(GiNaC::denom(arg_ex(a, 0, b)));
}

value builtin_lhs(const builtin& b, const args_t& a, context&) {
    const ex& e = arg_ex(a, 0, b);
    if (!is_a<GiNaC::relational>(e)) throw type_error(b.name + ": argument 1 must be a relation");
    return value(e.op(0));
}

value builtin_rhs(const builtin& b, const args_t& a, context&) {
    const ex& e = arg_ex(a, 0, b);
    if (!is_a<GiNaC::relational>(e)) throw type_error(b.name + ": argument 1 must be a relation");
    return value(e.op(1));
}

value builtin_solve(const builtin& b, const args_t& a, context& c) {
    if (a[0].is_problem()) return a.size() == 1 ? solve_problem(a[0]) : solve_scene(b, a, c);
    if (a.size() != 2)
        throw type_error(b.name + ": with one argument, solve needs a problem made by ode(...), not " +
                         a[0].a_kind() +
                         " (usage: " + b.signature + ")");
    const GiNaC::lst eqs = relations(a[0], b, 0);
    GiNaC::lst vars;
    if (a[1].is_list()) {
        for (std::size_t i = 0; i < a[1].as_list().size(); ++i) {
            const value& v = a[1].as_list()[i];
            if (!v.is_ex() || !is_a<GiNaC::symbol>(v.as_ex()))
                throw type_error(b.name + ": argument 2 must be a list of symbols");
            vars.append(v.as_ex());
        }
    } else {
        vars.append(arg_symbol(a, 1, b));
    }
    const ex sol = GiNaC::lsolve(eqs, vars);
    list out;
    if (sol.nops() == 0 && vars.nops() > 0)
        throw domain_error(b.name + ": the system has no solution");
    for (std::size_t i = 0; i < sol.nops(); ++i) out.push_back(sol.op(i));
    return value(out);
}

value builtin_evalf(const builtin& b, const args_t& a, context&) {
    if (a.size() == 1) {
        const long digits = GiNaC::Digits;
        return map_value(a[0], b, [digits](const ex& x) {
            const ex v = num::evalf_reduced(x, digits);
            // only where the precision had to be raised: the usual floats otherwise
            return num::reduction_digits(num::exact_floats_of(x)) > 0 ? num::round_digits(v, digits)
                                                                     : x.evalf();
        });
    }
    const long digits = arg_int(a, 1, b, 1, 100000);
    return map_value(a[0], b, [digits](const ex& x) {
        return num::round_digits(num::evalf_reduced(x, digits), digits);
    });
}

value builtin_atan2(const builtin& b, const args_t& a, context&) {
    no_matrix(b, arg_ex(a, 0, b));
    no_matrix(b, arg_ex(a, 1, b));
    return value(GiNaC::atan2(arg_ex(a, 0, b), arg_ex(a, 1, b)));
}

value builtin_binomial(const builtin& b, const args_t& a, context&) {
    no_matrix(b, arg_ex(a, 0, b));
    no_matrix(b, arg_ex(a, 1, b));
    check_combinatorial("binomial", "n =", arg_ex(a, 0, b));
    check_combinatorial("binomial", "k =", arg_ex(a, 1, b));
    return value(GiNaC::binomial(arg_ex(a, 0, b), arg_ex(a, 1, b)));
}

value builtin_exp(const builtin& b, const args_t& a, context&) {
    if (a[0].is_element()) {
        const ex t = a.size() > 1 ? arg_ex(a, 1, b) : ex(1);
        return a[0].as_element().exp(t);
    }
    if (a.size() > 1) throw type_error(b.name + ": the second argument t is only for elements (usage: " +
                                       b.signature + ")");
    return map_value(a[0], b, [&](const ex& x) {
        no_matrix(b, x);
        return GiNaC::exp(x);
    });
}

value builtin_log(const builtin& b, const args_t& a, context&) {
    if (a[0].is_element()) return a[0].as_element().log();
    return map_value(a[0], b, [&](const ex& x) {
        no_matrix(b, x);
        return GiNaC::log(x);
    });
}

value builtin_det(const builtin& b, const args_t& a, context&) {
    if (a[0].is_element()) return a[0].as_element().determinant();
    const GiNaC::matrix m = arg_matrix(a, 0, b);
    if (m.rows() != m.cols()) throw type_error(b.name + ": the matrix is not square");
    guard_terms(determinant_terms(m, false), "det");
    return tidy(m.determinant());
}

value builtin_matrix(const builtin& b, const args_t& a, context&) {
    return matrix_from(arg_list(a, 0, b), b);
}

value builtin_transpose(const builtin& b, const args_t& a, context&) {
    return value(ex(arg_matrix(a, 0, b).transpose()));
}

value builtin_rank(const builtin& b, const args_t& a, context&) {
    const GiNaC::matrix m = arg_matrix(a, 0, b);
    guard_terms(determinant_terms(m, false), "rank");
    return value(ex(static_cast<long>(m.rank())));
}

value builtin_length(const builtin& b, const args_t& a, context&) {
    if (a[0].is_list()) return static_cast<int>(a[0].as_list().size());
    if (a[0].is_string()) return static_cast<int>(a[0].as_string().size());
    if (a[0].is_element()) return static_cast<int>(a[0].as_element().dim());
    throw type_error(b.name + ": argument 1 must be a list, string or element (usage: " + b.signature + ")");
}

value builtin_sum(const builtin& b, const args_t& a, context& c) {
    if (a.size() == 1) return sum_values(arg_list(a, 0, b), b);
    if (a.size() == 2) throw type_error(b.name + ": expects 1, 3 or 4 arguments (usage: " + b.signature + ")");
    return sum_values(builtin_seq(b, a, c).as_list(), b);
}

value builtin_range(const builtin& b, const args_t& a, context&) {
    long lo = 0, hi = 0;
    if (a.size() == 1) hi = arg_int(a, 0, b, 0, 10000000) - 1;
    else { lo = arg_int(a, 0, b, -10000000, 10000000); hi = arg_int(a, 1, b, -10000000, 10000000); }
    list out;
    for (long i = lo; i <= hi; ++i) out.push_back(ex(i));
    return value(out);
}

value builtin_append(const builtin& b, const args_t& a, context&) {
    list out = arg_list(a, 0, b);
    for (std::size_t i = 1; i < a.size(); ++i) out.push_back(a[i]);
    return value(out);
}

value builtin_type(const builtin&, const args_t& a, context&) {
    return value(a[0].kind());
}

value builtin_load(const builtin& b, const args_t& a, context& c) {
    auto* s = dynamic_cast<session*>(&c);
    if (!s) throw type_error(b.name + ": not available here");
    if (s->load_depth() >= 64) throw size_error(b.name + ": more than 64 nested loads");
    const std::string path = arg_string(a, 0, b);
    const std::string full = s->resolve_path(path);
    std::error_code ec;
    if (std::filesystem::is_directory(full, ec))
        throw domain_error(b.name + ": '" + full + "' is a directory, not a script");
    std::ifstream probe(full);
    if (!probe) throw domain_error(b.name + ": cannot open file '" + full + "'");
    s->run_file(path);
    return value();
}

value builtin_help(const builtin& b, const args_t& a, context& c) {
    auto* s = dynamic_cast<session*>(&c);
    if (!s) throw type_error(b.name + ": not available here");
    if (a.empty()) {
        std::string section;
        for (const builtin* f : s->builtins().all()) {
            if (f->section != section) {
                section = f->section;
                c.out() << section << ":\n";
            }
            c.out() << "  " << f->signature << "\n";
        }
        return value();
    }
    const std::string& name = arg_string(a, 0, b);
    const builtin* f = s->builtins().find(name);
    if (!f) throw type_error(b.name + ": no function named '" + name + "'");
    c.out() << f->signature << "\n  " << f->summary << "\n";
    if (!f->equation.empty()) c.out() << "  Thesis: " << f->equation << "\n";
    if (!f->example.empty()) c.out() << "  Example: " << f->example << "\n";
    return value();
}

}  // namespace

void register_core_builtins(registry& r) {
    add_builtins(r, core, {
        {"print", "print(a, b, ...)",
         "Prints its arguments on one line, separated by spaces (strings without quotes); returns nothing.",
         "", "print(\"x^2 =\", x^2)", 0, any_number, builtin_print},
        {"subs", "subs(e, [x = a, ...])",
         "Substitutes expressions for symbols (all at once) in an expression, element, or list; one equation may be "
         "given without brackets.",
         "", "subs(x^2 + y, [x = 2, y = 1])", 2, 2, builtin_subs},
        {"expand", "expand(e)",
         "Multiplies out products and powers of sums.",
         "", "expand((x + 1)^3)", 1, 1, builtin_expand},
        {"normal", "normal(e)",
         "Brings a rational expression to the normal form numerator/denominator with common factors cancelled.",
         "", "normal((x^2 - 1)/(x - 1))", 1, 1, builtin_normal},
        {"simplify", "simplify(e)",
         "Simplifies an expression: rational expressions to one normalized fraction, radicals and logarithms "
         "of rationals over primes (sqrt(2)*sqrt(8) is 4, sqrt(12) is 2*sqrt(3)), trigonometric and "
         "hyperbolic identities that the zero test proves (cos(p)^2 + sin(p)^2 is 1); at least what == "
         "decides (docs/language.md, \"Equality\").",
         "", "simplify(1/x + 1/y)", 1, 1, builtin_simplify},
        {"factor", "factor(e)",
         "Factors a polynomial (or the numerator and denominator of a rational "
         "expression) over the rationals.",
         "", "factor(x^2 - 1)", 1, 1, builtin_factor},
        {"collect", "collect(e, x)",
         "Collects the terms of a polynomial by powers of x.",
         "", "collect(a*x + b*x + x^2, x)", 2, 2, builtin_collect},
        {"diff", "diff(e, x [, n])",
         "The n-th derivative (default 1) of an expression, of each coordinate of an element, or of each entry "
         "of a list, with respect to the symbol x. Of a solution by reduction (VI.3) in t: r' (as s').",
         "", "diff(sin(x)*x, x)", 2, 3, builtin_diff},
        {"series", "series(e, x = a, n)",
         "Truncated power series of e around x = a, with terms up to (x - a)^(n-1) and an Order((x - a)^n) term.",
         "", "series(exp(x), x = 0, 4)", 3, 3, builtin_series},
        {"coeff", "coeff(e, x, n)",
         "The coefficient of x^n in the expanded polynomial e.",
         "", "coeff((x + 2)^3, x, 1)", 3, 3, builtin_coeff},
        {"degree", "degree(e, x)",
         "The degree of the expanded polynomial e in x.",
         "", "degree(x^3 + x*y^5, x)", 2, 2, builtin_degree},
        {"ldegree", "ldegree(e, x)",
         "The lowest degree of x in the expanded polynomial e.",
         "", "ldegree(x^3 + x^2, x)", 2, 2, builtin_ldegree},
        {"numer", "numer(e)",
         "The numerator of the normal form of e.",
         "", "numer((x + 1)/(x - 1))", 1, 1, builtin_numer},
        {"denom", "denom(e)",
         "The denominator of the normal form of e.",
         "", "denom((x + 1)/(x - 1))", 1, 1, builtin_denom},
        {"lhs", "lhs(a = b)",
         "The left-hand side of a relation.",
         "", "lhs(x + 1 = y)", 1, 1, builtin_lhs},
        {"rhs", "rhs(a = b)",
         "The right-hand side of a relation.",
         "", "rhs(x + 1 = y)", 1, 1, builtin_rhs},
        {"solve", "solve([equations], [x, y, ...])  |  solve(P)  |  solve(P, values)",
         "Solves a system of linear equations for the given symbols; returns the list of solutions [x = ..., ...]. "
         "With a problem P made by ode(...), returns its exact solution x(t) in coordinate-free form: "
         "sum over the data vectors P of c0(t) P + c1(t) w x P + c2(t) w x (w x P), derived in the algebra of "
         "K = w x (R + C, idempotents (w . x) w/|w|^2 and -w x (w x x)/|w|^2). "
         "With values (as for eval: [w = [0, 0, W], g = [a, b, 0], w0 = 0], symbolic or numeric), solves the "
         "scene in its smallest exact model: terms that vanish for the values are dropped, each data vector "
         "P gets the algebra of its local minimal polynomial (X if w x P = 0, X^2 + |w|^2 if w . P = 0), "
         "only the scalar problems needed are solved; prints the model, the method and why (lines "
         "'solve: ...'), and returns the solution with the values put in, equal to solve(P) with them. "
         "A rotating-frame problem whose w(t) turns, or with a nonlinear central field (VI.3), gives the "
         "reduction r = F_(-w)(psi) = Q psi (Thm VI.3.2.1) as an object, evaluated by eval and verify. The dual "
         "Poisson-Darboux problem m (x' + Omega x x) = 0 (Omega = w + eps v, docs/rigid_body.md section 3) is "
         "closed for a constant twist, a fixed screw axis and a regular screw precession; any other twist gives "
         "x = Q^ x(0) with Q^ numeric (Magnus on SE(3)) as an object, evaluated by eval and verify.",
         "(VI.1.13-15), (VI.1.26-38), (VI.1.81), (II.1.23-24)", "solve([x + y = 3, x - y = 1], [x, y])",
         1, 2, builtin_solve},
        {"evalf", "evalf(e [, digits])",
         "Numeric value of e (of each coordinate of an element, of each entry of a list) with the given number of "
         "significant decimal digits (default: the current `digits`, GiNaC's 17). The arguments of functions are "
         "reduced exactly: the precision is raised by the size of each argument (cos(2*10^300) is computed with "
         "the 300 more digits of its argument and of pi that its reduction modulo 2 pi needs), and floats are "
         "taken as the exact binary numbers they denote. With digits D, every number is printed with D "
         "significant digits.",
         "", "evalf(pi, 30)", 1, 2, builtin_evalf},
        {"atan2", "atan2(y, x)",
         "The angle of the point (x, y), in (-pi, pi].",
         "", "atan2(1, -1)", 2, 2, builtin_atan2},
        {"binomial", "binomial(n, k)",
         "The binomial coefficient n choose k.",
         "", "binomial(5, 2)", 2, 2, builtin_binomial},
        {"exp", "exp(x) / exp(w [, t])",
         "The exponential of an expression; for an algebra element w, the closed form of exp(w t) in the algebra "
         "(t defaults to 1).",
         "Thm II.2.3", "exp(element(multicomplex(0), [0, 1]), t)", 1, 2, builtin_exp},
        {"log", "log(x) / log(w)",
         "The natural logarithm of an expression; for an algebra element w, a logarithm u of w in the algebra "
         "(exp(u) = w); a zero divisor has none.",
         "(III.1.55, III.1.72-76)", "coords(log(element(multicomplex(0), [0, 1])))", 1, 1, builtin_log},
        {"det", "det(m) / det(w)",
         "The determinant of a square matrix, or of the canonical matrix [w] of an algebra element.",
         "(II.1.21)", "det(matrix([[1, 2], [3, 4]]))", 1, 1, builtin_det},
        {"matrix", "matrix([[a, b], [c, d]])",
         "A matrix from the list of its rows.",
         "", "matrix([[1, 2], [3, 4]]) * matrix([[0, 1], [1, 0]])", 1, 1, builtin_matrix},
        {"transpose", "transpose(m)",
         "The transpose of a matrix.",
         "", "transpose(matrix([[1, 2], [3, 4]]))", 1, 1, builtin_transpose},
        {"rank", "rank(m)",
         "The rank of a matrix.",
         "", "rank(matrix([[1, 2], [2, 4]]))", 1, 1, builtin_rank},
        {"length", "length(l)",
         "The number of entries of a list, characters of a string, or coordinates of an element.",
         "", "length([a, b, c])", 1, 1, builtin_length},
        {"seq", "seq(e, k, a, b) / seq(e, k, [values])",
         "The list of the values of e for k = a, a+1, ..., b (integers), or for k in a list (like Maxima's "
         "makelist). e is evaluated once for each value, with the variable k bound to it (a variable k of the "
         "same name is restored afterwards), so seq(diff(x^3, x, k), k, 0, 2) works.",
         "", "seq(k^2, k, 0, 4)", 3, 4, builtin_seq},
        {"sum", "sum(l) / sum(e, k, a, b)",
         "The sum of the entries of a list (expressions or elements of one algebra), or of e for k = a..b.",
         "", "sum([1, 2, 3]) + sum(1/k^2, k, 1, 3)", 1, 4, builtin_sum},
        {"range", "range(n) / range(a, b)",
         "The list of integers 0..n-1, or a..b.",
         "", "range(5)", 1, 2, builtin_range},
        {"append", "append(l, x, ...)",
         "The list l with the further arguments added at its end.",
         "", "append([1, 2], 3)", 2, any_number, builtin_append},
        {"type", "type(x)",
         "The kind of a value as a string: \"nothing\", \"boolean\", \"expression\", \"string\", \"list\", "
         "\"algebra\" or \"element\".",
         "", "type([1, 2])", 1, 1, builtin_type},
        {"load", "load(\"file\")",
         "Runs another script in the same session (variables are shared). A relative path is relative to the "
         "folder of the running script (or the working directory). Failures inside it are reported and counted "
         "like any other.",
         "", "load(\"examples/hello.symrep\")", 1, 1, builtin_load},
        {"help", "help() / help(\"name\")",
         "Prints the documentation of a function, or the list of all functions.",
         "", "help(\"diff\")", 0, 1, builtin_help},
        elementary("sqrt", "square root", "sqrt(8)", [](const ex& x) { return GiNaC::sqrt(x); }),
        elementary("sin", "sine", "sin(pi/6)", [](const ex& x) { return GiNaC::sin(x); }),
        elementary("cos", "cosine", "cos(pi/3)", [](const ex& x) { return GiNaC::cos(x); }),
        elementary("tan", "tangent", "tan(pi/4)", [](const ex& x) { return GiNaC::tan(x); }),
        elementary("asin", "arc sine", "asin(1)", [](const ex& x) { return GiNaC::asin(x); }),
        elementary("acos", "arc cosine", "acos(0)", [](const ex& x) { return GiNaC::acos(x); }),
        elementary("atan", "arc tangent", "atan(1)", [](const ex& x) { return GiNaC::atan(x); }),
        elementary("sinh", "hyperbolic sine", "sinh(0)", [](const ex& x) { return GiNaC::sinh(x); }),
        elementary("cosh", "hyperbolic cosine", "cosh(0)", [](const ex& x) { return GiNaC::cosh(x); }),
        elementary("tanh", "hyperbolic tangent", "tanh(0)", [](const ex& x) { return GiNaC::tanh(x); }),
        elementary("abs", "absolute value", "abs(-3/4)", absolute_value),
        elementary("step", "Heaviside step function (1 for x > 0, 0 for x < 0, 1/2 at 0)", "step(-2)",
                   [](const ex& x) { return GiNaC::step(x); }),
        elementary("sign", "sign function (1 for x > 0, -1 for x < 0, 0 at 0), written 2 step(x) - 1", "sign(-2)",
                   [](const ex& x) { return 2 * GiNaC::step(x) - 1; }),
        elementary("real_part", "real part", "real_part(2 + 3*I)", [](const ex& x) { return GiNaC::real_part(x); }),
        elementary("imag_part", "imaginary part", "imag_part(2 + 3*I)",
                   [](const ex& x) { return GiNaC::imag_part(x); }),
        elementary("conjugate", "complex conjugate", "conjugate(2 + 3*I)",
                   [](const ex& x) { return GiNaC::conjugate(x); }),
        elementary("factorial", "factorial", "factorial(10)", checked_factorial),
    });
}

bool has_matrix(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::matrix>(*it)) return true;
    return false;
}

}  // namespace symrep::lang
