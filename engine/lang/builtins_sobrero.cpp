// symrep/lang/builtins_sobrero.cpp -- script functions of the generalized Sobrero
// algebra S (III.2): the algebra and its distinguished elements j and eps. The
// generic functions (element, inverse, exp, log, charpoly, minpoly, semiexponential,
// is_special_type, special_type_decomposition, generating_element, ...) dispatch to
// the overrides of class sobrero and are registered with the generic algebra builtins.
#include <memory>

#include "algebra/sobrero.h"
#include "lang/builtins.h"

namespace symrep::lang {

namespace {

std::shared_ptr<const sobrero> sobrero_arg(const std::vector<value>& args, std::size_t i,
                                           const builtin& b) {
    const algebra_ptr& A = arg_algebra(args, i, b);
    auto S = std::dynamic_pointer_cast<const sobrero>(A);
    if (!S)
        throw type_error(b.name + ": argument " + std::to_string(i + 1) +
                         " must be a Sobrero algebra sobrero(n), not " + A->name() + " (usage: " +
                         b.signature + ")");
    return S;
}

value builtin_sobrero(const builtin& b, const std::vector<value>& args, context&) {
    return value(sobrero::make(arg_int(args, 0, b, 0, 1L << 30)));
}

value builtin_sobrero_j(const builtin& b, const std::vector<value>& args, context&) {
    auto S = sobrero_arg(args, 0, b);
    return value(element(S, S->j()));
}

value builtin_sobrero_eps(const builtin& b, const std::vector<value>& args, context&) {
    auto S = sobrero_arg(args, 0, b);
    return value(element(S, S->eps()));
}

}  // namespace

void register_sobrero_builtins(registry& r) {
    add_builtins(r, "Sobrero algebra", {
        {"sobrero", "sobrero(n)",
         "The generalized Sobrero algebra S = C (x) R[eps]/(eps^(n+1)) of order 2(n+1), "
         "with basis 1, eps, ..., eps^n, j, j*eps, ..., j*eps^n; coordinates "
         "[a_0..a_n, b_0..b_n] for w = sum (a_k + j b_k) eps^k. Exact for n <= 512; elements with float "
         "coordinates (1.5, not 3/2) take the double path for products, inverse, exp and zero divisors, "
         "and for 512 < n <= 4096 the algebra is double-precision only (no log there).",
         "(III.2.4-6)", "sobrero(2)", 1, 1, builtin_sobrero},
        {"sobrero_j", "sobrero_j(A)",
         "The complex unit j of the Sobrero algebra A (j^2 = -1).",
         "(III.2.1, III.2.4)", "sobrero_j(sobrero(2))", 1, 1, builtin_sobrero_j},
        {"sobrero_eps", "sobrero_eps(A)",
         "The nilpotent generator eps of the Sobrero algebra A (eps^(n+1) = 0; "
         "zero in sobrero(0)).",
         "(III.2.2-3)", "sobrero_eps(sobrero(2))", 1, 1, builtin_sobrero_eps},
    });
}

}  // namespace symrep::lang
