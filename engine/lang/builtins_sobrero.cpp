// symrep/lang/builtins_sobrero.cpp -- script functions of the generalized Sobrero
// algebra S (III.2): the algebra and its distinguished elements j and eps. The
// generic functions (element, inverse, exp, log, charpoly, minpoly, semiexponential,
// is_special_type, special_type_decomposition, generating_element, ...) dispatch to
// the overrides of class sobrero and are registered with the generic algebra builtins.
#include <memory>

#include "symrep/algebra/sobrero.h"
#include "symrep/lang/builtins.h"
#include "symrep/signals/sobrero_subalgebra.h"

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

value builtin_sobrero_subalgebra(const builtin& b, const std::vector<value>& args, context&) {
    const element& w = arg_element(args, 0, b);
    const auto place = signals::sobrero_subalgebra(w.parent(), w.coefficients());
    list names;
    for (const auto& s : place.subalgebras) names.push_back(value(s));
    return list{value(names), value(GiNaC::ex(place.signal_order)), value(place.report)};
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
        {"sobrero_subalgebra", "sobrero_subalgebra(w)",
         "Where the element w of a Sobrero algebra sobrero(n) lies, as a representation of signals with "
         "d = delta + eps + j omega (omega != 0): [subalgebras, order, report], subalgebras those of R, C, P "
         "(IV.1.2.7) and eps^n C holding w, order = 2 (n + 1 - k0) the order of the least equation of the "
         "signal Psi^-1(w), w in eps^k0 S. The second-order signals A e^(delta t) cos(omega t - phi) are "
         "represented in eps^n C, not in R or C as IV.1.2.31-35 print (true only for n = 0; FORMULAS.md).",
         "(IV.1.2.7, 26-37 corrected)", "sobrero_subalgebra(represent(exp(-t)*cos(2*t), t, -1 + "
         "sobrero_eps(sobrero(1)) + 2*sobrero_j(sobrero(1))))", 1, 1, builtin_sobrero_subalgebra},
    });
}

}  // namespace symrep::lang
