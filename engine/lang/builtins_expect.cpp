// symrep/lang/builtins_expect.cpp -- the assertions of derivation scripts, expect and
// expect_near (section "Checks"). They are the language's own: equality as == decides it
// (values_equal), numbers as floats. The check of a solution of a problem, check(P, s),
// and its numeric sibling verify belong to mechanics and are in builtins_mechanics.cpp.
//
// Every result a derivation script prints should be checked where it is
// derived: `expect(w * inverse(w) == one(A))` fails the statement (and so the
// run's exit status) when the identity does not hold. The tests run the scripts
// in examples/ and require exit status 0, so each expect() is a test.
#include <cmath>
#include <complex>
#include <sstream>

#include "symrep/scalar/scalar.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/interpreter.h"

namespace symrep::lang {

namespace {

// True when v asserts something that holds: a boolean true, or a relation
// lhs = rhs whose sides are equal as by == (values_equal: their difference
// normalizes to 0; matrices entry by entry, vectors by components).
bool holds(const value& v, const builtin& b) {
    if (v.is_bool()) return v.as_bool();
    if (v.is_ex() && GiNaC::is_a<GiNaC::relational>(v.as_ex())) {
        const GiNaC::ex& r = v.as_ex();
        if (!GiNaC::ex_to<GiNaC::relational>(r).info(GiNaC::info_flags::relation_equal))
            throw type_error(b.name + ": only equations a = b can be checked, not inequalities");
        return values_equal(value(r.lhs()), value(r.rhs()));
    }
    throw type_error(b.name + ": argument 1 must be a boolean (a == b) or an equation (a = b), not " +
                     v.a_kind());
}

std::complex<double> to_complex(const GiNaC::ex& e, const builtin& b, int argno) {
    const GiNaC::ex x = GiNaC::evalf(e);
    if (!GiNaC::is_a<GiNaC::numeric>(x)) {
        std::ostringstream os;
        os << b.name << ": argument " << argno << " must evaluate to a number, but is " << e;
        throw type_error(os.str());
    }
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(x);
    return {n.real().to_double(), n.imag().to_double()};
}

double to_double(const GiNaC::ex& e, const builtin& b, int argno) {
    const std::complex<double> z = to_complex(e, b, argno);
    if (z.imag() != 0) {
        std::ostringstream os;
        os << b.name << ": argument " << argno << " must evaluate to a real number, but is " << e;
        throw type_error(os.str());
    }
    return z.real();
}

// The numbers of a value, in order: an expression (a number or a matrix), a list
// (recursively) or an element (its coordinates). `shape` records the structure
// so that two values of different shapes are not compared.
void numbers_of(const value& v, const builtin& b, int argno, std::vector<std::complex<double>>& out,
                std::string& shape) {
    if (v.is_list()) {
        shape += "[";
        for (const value& x : v.as_list()) numbers_of(x, b, argno, out, shape);
        shape += "]";
    } else if (v.is_element()) {
        shape += "e" + std::to_string(v.as_element().dim());
        for (std::size_t k = 0; k < v.as_element().dim(); ++k) out.push_back(to_complex(v.as_element()[k], b, argno));
    } else if (v.is_ex() && GiNaC::is_a<GiNaC::matrix>(v.as_ex())) {
        const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(v.as_ex());
        shape += "m" + std::to_string(m.rows()) + "x" + std::to_string(m.cols());
        for (unsigned i = 0; i < m.rows(); ++i)
            for (unsigned j = 0; j < m.cols(); ++j) out.push_back(to_complex(m(i, j), b, argno));
    } else if (v.is_ex()) {
        shape += "n";
        out.push_back(to_complex(v.as_ex(), b, argno));
    } else {
        throw type_error(b.name + ": argument " + std::to_string(argno) +
                         " must be a number, a list of numbers, a matrix or an element, not " +
                         v.a_kind());
    }
}

value builtin_expect(const builtin& b, const std::vector<value>& args, context&) {
    if (holds(args[0], b)) return {};
    std::string msg = "expectation failed";
    if (args.size() > 1) msg += ": " + arg_string(args, 1, b);
    throw error(msg);
}

value builtin_expect_near(const builtin& b, const std::vector<value>& args, context&) {
    std::vector<std::complex<double>> x, y;
    std::string sx, sy;
    numbers_of(args[0], b, 1, x, sx);
    numbers_of(args[1], b, 2, y, sy);
    const double tol = to_double(arg_ex(args, 2, b), b, 3);
    if (sx != sy)
        throw type_error(b.name + ": arguments 1 and 2 have different shapes (" +
                         std::to_string(x.size()) + " and " + std::to_string(y.size()) + " numbers)");
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (std::abs(x[i] - y[i]) <= tol) continue;
        std::ostringstream os;
        os.precision(17);
        os << "expectation failed: ";
        if (x.size() > 1) os << "entry " << i << ": ";
        auto put = [&](std::complex<double> z) {
            if (z.imag() == 0) os << z.real();
            else os << z.real() << (z.imag() < 0 ? " - " : " + ") << std::abs(z.imag()) << "*I";
        };
        os << "|";
        put(x[i]);
        os << " - ";
        put(y[i]);
        os << "| = " << std::abs(x[i] - y[i]) << " > " << tol;
        throw error(os.str());
    }
    return {};
}

}  // namespace

void register_expect_builtins(registry& r) {
    add_builtins(r, "Checks", {
        {"expect", "expect(condition [, message])",
         "Checks a condition: a boolean such as `a == b` (exact, mathematical equality) or an "
         "equation `a = b` (holds when a - b simplifies to 0). Prints nothing when it holds; "
         "otherwise the statement fails with the message, so the script exits with status 1.",
         "", "expect((x + 1)^2 == x^2 + 2*x + 1, \"binomial square\")", 1, 2, builtin_expect},
        {"expect_near", "expect_near(a, b, tolerance)",
         "Checks that two numeric values differ by at most `tolerance` in absolute value (evaluated "
         "in floating point; complex numbers by modulus). a and b may also be lists, matrices or "
         "elements of the same shape, compared entry by entry; fails the statement otherwise, "
         "naming the first entry that differs.",
         "", "expect_near(evalf(pi), 355/113, 1e-6)", 3, 3, builtin_expect_near},
    });
}

}  // namespace symrep::lang
