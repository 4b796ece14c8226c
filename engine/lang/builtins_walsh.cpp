// symrep/lang/builtins_walsh.cpp -- script functions of the Walsh algebra W and of
// its complex extension W* (III.3): the algebras, the generators u_k and i0. The
// generic functions (element, idempotent, components, inverse, exp, log, charpoly,
// minpoly, zero_divisor_ranks, generating_element, ...) dispatch to the overrides of
// classes walsh and walsh_complex and are registered with the generic algebra builtins.
#include <memory>

#include "symrep/algebra/walsh.h"
#include "symrep/algebra/walsh_complex.h"
#include "symrep/lang/builtins.h"

namespace symrep::lang {

namespace {

value builtin_walsh(const builtin& b, const std::vector<value>& args, context&) {
    return value(walsh::make(arg_int(args, 0, b, 0, 1L << 30)));
}

value builtin_walsh_complex(const builtin& b, const std::vector<value>& args, context&) {
    return value(walsh_complex::make(arg_int(args, 0, b, 0, 1L << 30)));
}

value builtin_walsh_generator(const builtin& b, const std::vector<value>& args, context&) {
    const algebra_ptr& A = arg_algebra(args, 0, b);
    if (auto W = std::dynamic_pointer_cast<const walsh>(A)) {
        const long k = arg_int(args, 1, b, 0, 1L << 30);
        return value(element(A, W->generator(std::size_t(k))));
    }
    if (auto C = std::dynamic_pointer_cast<const walsh_complex>(A)) {
        const long k = arg_int(args, 1, b, 0, 1L << 30);
        return value(element(A, C->generator(std::size_t(k))));
    }
    throw type_error(b.name + ": argument 1 must be walsh(n) or walsh_complex(n), "
                     "not " + A->name() + " (usage: " + b.signature + ")");
}

value builtin_walsh_i0(const builtin& b, const std::vector<value>& args, context&) {
    const algebra_ptr& A = arg_algebra(args, 0, b);
    auto C = std::dynamic_pointer_cast<const walsh_complex>(A);
    if (!C)
        throw type_error(b.name + ": argument 1 must be walsh_complex(n), not " +
                         A->name() + " (usage: " + b.signature +
                         "); W itself has no i0, see walsh_complex");
    return value(element(A, C->i0()));
}

}  // namespace

void register_walsh_builtins(registry& r) {
    add_builtins(r, "Walsh algebra", {
        {"walsh", "walsh(n)",
         "The Walsh algebra W of order 2^n (dyadic group algebra): basis w_p = "
         "u_0^p_0 ... u_(n-1)^p_(n-1), w_p w_q = w_(p xor q), p_0 the most significant "
         "bit (u_k = w_(2^(n-1-k))). Exact for n <= 16; elements with float coordinates (1.5, not 3/2) "
         "are computed in double precision, and for 16 < n <= 26 the algebra is double-precision only.",
         "(III.3.3, III.3.6)", "walsh(3)", 1, 1, builtin_walsh},
        {"walsh_complex", "walsh_complex(n)",
         "The complex extension W* of the Walsh algebra in real form, order 2^(n+1): "
         "basis w_p, i0*w_p, coordinates [a_0..a_(2^n-1), b_0..b_(2^n-1)]. Every "
         "non-zero-divisor has a logarithm here. Exact for n <= 15; elements with float coordinates are "
         "computed in double precision, and for 15 < n <= 25 the algebra is double-precision only.",
         "(III.3.45-53, III.3.64-67)", "log(element(walsh_complex(1), [-1, 0, 0, 0]))", 1, 1, builtin_walsh_complex},
        {"walsh_generator", "walsh_generator(A, k)",
         "The generator u_k (k = 0..n-1, u_k^2 = 1) of the Walsh algebra walsh(n) or "
         "of its complex extension walsh_complex(n).",
         "(III.3.1-3)", "walsh_generator(walsh(2), 0)", 2, 2, builtin_walsh_generator},
        {"walsh_i0", "walsh_i0(A)",
         "The imaginary unit i0 (i0^2 = -1) of the complex Walsh algebra "
         "A = walsh_complex(n).",
         "(III.3.51)", "walsh_i0(walsh_complex(2))", 1, 1, builtin_walsh_i0},
    });
}

}  // namespace symrep::lang
