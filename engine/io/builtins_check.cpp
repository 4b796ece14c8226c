// symrep/io/builtins_check.cpp -- self-checks inside derivation scripts.
//
// Every result a derivation script prints should be checked where it is
// derived: `expect(w * inverse(w) == one(A))` fails the statement (and so the
// run's exit status) when the identity does not hold. The tests run the scripts
// in examples/ and require exit status 0, so each expect() is a test.
#include <cmath>
#include <sstream>

#include "algebra/scalar.h"
#include "io/builtins.h"

namespace symrep::lang {

namespace {

// True when v asserts something that holds: a boolean true, or a relation
// lhs = rhs whose difference normalizes to 0.
bool holds(const value& v, const builtin& b) {
    if (v.is_bool()) return v.as_bool();
    if (v.is_ex() && GiNaC::is_a<GiNaC::relational>(v.as_ex())) {
        const GiNaC::ex& r = v.as_ex();
        if (!GiNaC::ex_to<GiNaC::relational>(r).info(GiNaC::info_flags::relation_equal))
            throw type_error(b.name + ": only equations a = b can be checked, not inequalities");
        return is_zero_scalar(r.lhs() - r.rhs());
    }
    throw type_error(b.name + ": argument 1 must be a boolean (a == b) or an equation (a = b), not " +
                     std::string(v.kind() == "expression" ? "an " : "a ") + v.kind());
}

double to_double(const GiNaC::ex& e, const builtin& b, int argno) {
    const GiNaC::ex x = GiNaC::evalf(e);
    if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real()) {
        std::ostringstream os;
        os << b.name << ": argument " << argno << " must evaluate to a real number, but is " << e;
        throw type_error(os.str());
    }
    return GiNaC::ex_to<GiNaC::numeric>(x).to_double();
}

}  // namespace

void register_check_builtins(registry& r) {
    r.add({"expect", "expect(condition [, message])",
           "Checks a condition: a boolean such as `a == b` (exact, mathematical equality) or an "
           "equation `a = b` (holds when a - b simplifies to 0). Prints nothing when it holds; "
           "otherwise the statement fails with the message, so the script exits with status 1.",
           "", "expect((x + 1)^2 == x^2 + 2*x + 1, \"binomial square\")", "Checks", 1, 2,
           [](const std::vector<value>& args, context&) -> value {
               builtin b{"expect", "expect(condition [, message])", "", "", "", "", 1, 2, {}};
               if (holds(args[0], b)) return {};
               std::string msg = "expectation failed";
               if (args.size() > 1) msg += ": " + arg_string(args, 1, b);
               throw error(msg);
           }});
    r.add({"expect_near", "expect_near(a, b, tolerance)",
           "Checks that two numeric expressions differ by at most `tolerance` in absolute value "
           "(evaluated in floating point); fails the statement otherwise, naming both values.",
           "", "expect_near(evalf(pi), 355/113, 1e-6)", "Checks", 3, 3,
           [](const std::vector<value>& args, context&) -> value {
               builtin b{"expect_near", "expect_near(a, b, tolerance)", "", "", "", "", 3, 3, {}};
               const double x = to_double(arg_ex(args, 0, b), b, 1);
               const double y = to_double(arg_ex(args, 1, b), b, 2);
               const double tol = to_double(arg_ex(args, 2, b), b, 3);
               if (std::abs(x - y) <= tol) return {};
               std::ostringstream os;
               os.precision(17);
               os << "expectation failed: |" << x << " - " << y << "| = " << std::abs(x - y)
                  << " > " << tol;
               throw error(os.str());
           }});
}

}  // namespace symrep::lang
