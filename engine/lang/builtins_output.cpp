// symrep/lang/builtins_output.cpp -- the script builtins of output: latex,
// ccode, pycode, digits and notation (on output/formats.h).
#include <string>
#include <vector>

#include "symrep/lang/builtins.h"
#include "symrep/lang/print_value.h"
#include "symrep/output/formats.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;
using output::c_code;
using output::python_code;

namespace {

/// The components of a vector literal (3x1 or 1x3 matrix), or nothing.
std::vector<ex> components(const ex& e) {
    std::vector<ex> c;
    if (is_a<GiNaC::matrix>(e)) {
        const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
        if (m.cols() == 1 || m.rows() == 1)
            for (unsigned i = 0; i < m.nops(); ++i) c.push_back(m.op(i));
    }
    return c;
}

/// The expression of a value for ccode/pycode: an expression, or a list of
/// expressions (a vector given by components).
std::vector<ex> code_operands(const value& v, const builtin& b, bool& is_vec) {
    is_vec = false;
    std::vector<ex> out;
    if (v.is_list()) {
        is_vec = true;
        for (const value& x : v.as_list()) {
            if (!x.is_ex()) throw type_error(b.name + ": the list must hold expressions, not " + x.a_kind());
            out.push_back(x.as_ex());
        }
        return out;
    }
    if (!v.is_ex()) throw type_error(b.name + ": expects an expression or a list of them, not " + v.a_kind() +
                                     " (usage: " + b.signature + ")");
    std::vector<ex> c = components(v.as_ex());
    if (!c.empty() && is_a<GiNaC::matrix>(v.as_ex())) {
        is_vec = true;
        return c;
    }
    return {v.as_ex()};
}

value builtin_latex(const builtin&, const std::vector<value>& args, context&) {
    return value(latex_value(args[0]));
}

/// ccode/pycode: the code of an expression, or of the entries of a list or vector literal
/// between `open` and `close`, separated by commas.
value code_of(const builtin& b, const value& v, std::string (*code)(const ex&), const char* open, const char* close) {
    bool vec = false;
    const std::vector<ex> es = code_operands(v, b, vec);
    if (!vec) return value(code(es[0]));
    std::string s = open;
    for (std::size_t i = 0; i < es.size(); ++i) s += (i ? ", " : "") + code(es[i]);
    return value(s + close);
}

value builtin_ccode(const builtin& b, const std::vector<value>& args, context&) {
    return code_of(b, args[0], c_code, "{", "}");
}

value builtin_pycode(const builtin& b, const std::vector<value>& args, context&) {
    return code_of(b, args[0], python_code, "numpy.array([", "])");
}

value builtin_digits(const builtin& b, const std::vector<value>& args, context&) {
    const long old = GiNaC::Digits;
    if (!args.empty()) GiNaC::Digits = arg_int(args, 0, b, 1, 100000);
    return value(ex(numeric(old)));
}

value builtin_notation(const builtin& b, const std::vector<value>& args, context&) {
    const auto name = [](notation n) { return n == notation::unicode ? "unicode" : "ascii"; };
    const notation old = vector_notation();
    if (!args.empty()) {
        const std::string& n = arg_string(args, 0, b);
        if (n == "unicode") set_vector_notation(notation::unicode);
        else if (n == "ascii") set_vector_notation(notation::ascii);
        else
            throw domain_error(b.name + ": the notation is \"unicode\" or \"ascii\", not \"" + n +
                               "\"");
    }
    return value(std::string(name(old)));
}

}  // namespace

void register_output_builtins(registry& r) {
    add_builtins(r, "Output", {
        {"latex", "latex(e)",
         "LaTeX of a value as a string: sums in the canonical term order, vectors bold "
         "(\\boldsymbol{r}_0), cross and dot products as \\times and \\cdot, norms \\|w\\|, elements as sums "
         "of coefficient times basis names. print(latex(e)) shows it without quotes.",
         "", "print(latex(x^2/2 + sqrt(y)))", 1, 1, builtin_latex},
        {"ccode", "ccode(e)",
         "C/C++ code (double arithmetic, <math.h> functions, M_PI) of a scalar expression, as a string; "
         "a list or vector literal gives a brace initializer {c0, c1, c2}. Abstract vectors must be given "
         "components first (subs(e, w = [w1, w2, w3])).",
         "", "print(ccode(sin(x)^2 + x/3))", 1, 1, builtin_ccode},
        {"pycode", "pycode(e)",
         "Python code (NumPy: numpy.sin, numpy.pi, ...) of a scalar expression, as a string; a list or "
         "vector literal gives numpy.array([c0, c1, c2]). Abstract vectors must be given components first.",
         "", "print(pycode(sin(x)^2 + x/3))", 1, 1, builtin_pycode},
        {"digits", "digits(n)",
         "Sets the number of decimal digits of floats (evalf, float literals, their printing) and returns "
         "the previous setting; digits() returns the current one. Exact rationals stay exact. "
         "Digits := n does the same.",
         "", "old := digits(30); evalf(pi); digits(old)", 0, 1, builtin_digits},
        {"notation", "notation(\"unicode\" | \"ascii\")",
         "Sets how cross and scalar products of vectors print, for the rest of the session, and returns "
         "the previous setting: \"ascii\" writes w x r and w . r, \"unicode\" writes w \u00d7 r and "
         "w \u00b7 r (U+00D7, U+00B7; the language reads both notations). notation() returns the current one (the symrep program "
         "starts in unicode at an interactive prompt in a UTF-8 locale, in ascii otherwise; --unicode and "
         "--ascii choose).",
         "", "vector w, r; old := notation(\"unicode\"); w x (w x r); notation(old)", 0, 1, builtin_notation},
    });
}

}  // namespace symrep::lang
