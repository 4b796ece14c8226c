// symrep/lang/builtins_dual.cpp -- script functions of dual numbers and dual vectors
// (dual/dual.h, issue 31 item 1): dual(a, b) = a + eps*b, primal(x), dual_part(x).
// The constant eps itself is read by evaluate.cpp, and every operation on dual
// quantities is reduced modulo eps^2 by operators.cpp (binary_op, reduce_dual).
#include "symrep/dual/dual.h"
#include "symrep/lang/builtins.h"
#include "symrep/lang/interpreter.h"
#include "symrep/output/printer.h"

namespace symrep::lang {

namespace {

/// Argument i as an expression; a list [x, y, z] is the vector literal.
GiNaC::ex dual_operand(const std::vector<value>& args, std::size_t i, const builtin& b) {
    if (is_triple(args[i])) return as_literal(args[i]);
    return arg_ex(args, i, b);
}

value builtin_dual(const builtin& b, const std::vector<value>& args, context&) {
    const GiNaC::ex a = dual_operand(args, 0, b), d = dual_operand(args, 1, b);
    for (std::size_t i = 0; i < 2; ++i) {
        const GiNaC::ex& x = i ? d : a;
        if (dual::has_dual_unit(x))
            throw type_error(b.name + ": argument " + std::to_string(i + 1) + " (" + output::print_ex(x) +
                             ") holds eps: both parts must be free of the dual unit (usage: " + b.signature + ")");
    }
    try {
        return value(dual::make_dual(a, d));
    } catch (const type_error&) {
        throw type_error(b.name + ": the parts " + output::print_ex(a) + " and " + output::print_ex(d) +
                         " must both be scalars or both be vectors (usage: " + b.signature + ")");
    }
}

value builtin_primal(const builtin& b, const std::vector<value>& args, context&) {
    return value(dual::primal(dual_operand(args, 0, b)));
}

value builtin_dual_part(const builtin& b, const std::vector<value>& args, context&) {
    return value(dual::dual_part(dual_operand(args, 0, b)));
}

}  // namespace

void register_dual_builtins(registry& r) {
    add_builtins(r, "Dual numbers", {
        {"dual", "dual(a, b)",
         "The dual number or dual vector a + eps*b (eps the dual unit, eps^2 = 0): a and b free of eps, both "
         "scalars or both vectors. The same as writing a + eps*b.",
         "[CB14] (dual numbers)", "dual(x, y)\ndual([1, 0, 0], [0, 0, 1])", 2, 2, builtin_dual},
        {"primal", "primal(x)",
         "The primal part p of the dual quantity x = p + eps*d (x at eps = 0, after the reduction modulo "
         "eps^2); x itself when it holds no eps.",
         "[CB14] (dual numbers)", "primal(sin(x + eps*y))", 1, 1, builtin_primal},
        {"dual_part", "dual_part(x)",
         "The dual part d of the dual quantity x = p + eps*d (the coefficient of eps after the reduction "
         "modulo eps^2, where f(a + eps*b) = f(a) + eps*b*f'(a)); 0 when x holds no eps.",
         "[CB14] (dual numbers)", "dual_part(sin(x + eps*y))", 1, 1, builtin_dual_part},
    });
}

}  // namespace symrep::lang
