// symrep/lang/builtins_multicomplex.cpp -- the builtins specific to the
// multicomplex algebra (x)C^{n+1} (thesis III.1). The generic functions
// (element, inverse, exp, log, charpoly, minpoly, semiexponential, ...) are
// registered in builtins_algebra.cpp and dispatch to multicomplex's overrides.
#include <climits>

#include "symrep/algebra/multicomplex.h"
#include "symrep/algebra/multicomplex_indexing.h"
#include "symrep/lang/builtins.h"

namespace symrep::lang {

namespace {

const char* const section = "Multicomplex algebra";

const multicomplex& arg_multicomplex(const std::vector<value>& args, std::size_t i, const builtin& b) {
    const algebra_ptr& A = arg_algebra(args, i, b);
    const auto* M = dynamic_cast<const multicomplex*>(A.get());
    if (!M)
        throw type_error(b.name + ": argument " + std::to_string(i + 1) +
                         " must be a multicomplex algebra, not " + A->name() + " (usage: " +
                         b.signature + ")");
    return *M;
}

// n in 0..62 and k in 0..2^{n+1}-1 for the index maps.
std::pair<unsigned, std::size_t> arg_order_index(const std::vector<value>& args, const builtin& b) {
    const long n = arg_int(args, 0, b, 0, 62);
    const long kmax = static_cast<long>((std::size_t{2} << n) - 1);
    const long k = arg_int(args, 1, b, 0, kmax);
    return {static_cast<unsigned>(n), static_cast<std::size_t>(k)};
}

value builtin_multicomplex(const builtin& b, const std::vector<value>& args, context&) {
    const long n = arg_int(args, 0, b, 0, LONG_MAX);
    // make() throws size_error naming the limit for n > max_order.
    return algebra_ptr(multicomplex::make(static_cast<unsigned>(std::min<long>(n, UINT_MAX))));
}

value builtin_imag_unit(const builtin& b, const std::vector<value>& args, context&) {
    const multicomplex& M = arg_multicomplex(args, 0, b);
    const long k = arg_int(args, 1, b, 0, M.order());
    return element(args[0].as_algebra(), M.imag_unit(static_cast<unsigned>(k)));
}

value builtin_gray(const builtin& b, const std::vector<value>& args, context&) {
    const auto [n, k] = arg_order_index(args, b);
    return GiNaC::ex(GiNaC::numeric(static_cast<long>(multicomplex_gray(n, k))));
}

value builtin_gray_basis(const builtin& b, const std::vector<value>& args, context&) {
    const multicomplex& M = arg_multicomplex(args, 0, b);
    const long k = arg_int(args, 1, b, 0, static_cast<long>(M.dim() - 1));
    return element(args[0].as_algebra(), M.gray_basis(static_cast<std::size_t>(k)));
}

value builtin_sigma(const builtin& b, const std::vector<value>& args, context&) {
    const auto [n, k] = arg_order_index(args, b);
    return GiNaC::ex(multicomplex_sigma(n, k));
}

}  // namespace

void register_multicomplex_builtins(registry& r) {
    add_builtins(r, section, {
        {"multicomplex", "multicomplex(n)",
         "The multicomplex algebra (x)C^{n+1} = C_0 (x) ... (x) C_n of order 2^{n+1}, with exact "
         "coefficients and the natural binary basis e_p = i0^{p_0} ... in^{p_n} (p_0 the most "
         "significant bit, so i0 = e_{2^n} and i_k = e_{2^{n-k}}). Exact for n <= 10; elements with "
         "float coordinates (1.5, not 3/2) are computed in double precision (products, inverse, exp, log, "
         "zero divisors; one fast Walsh-Hadamard transform), and for 10 < n <= the machine's limit "
         "(about 24) the algebra is double-precision only: numeric coordinates, results in floats.",
         "(III.1.2), (III.1.4), (III.1.7)", "A := multicomplex(2)", 1, 1, builtin_multicomplex},
        {"imag_unit", "imag_unit(A, k)",
         "The imaginary unit i_k (k = 0..n) of the multicomplex algebra A = multicomplex(n): "
         "i_k^2 = -1, i_k = e_{2^{n-k}}.",
         "(III.1.1), (III.1.4)", "imag_unit(multicomplex(2), 1)", 2, 2, builtin_imag_unit},
        {"gray", "gray(n, k)",
         "The bit-reversed Gray code g(k) of k = 0..2^{n+1}-1: with k = (k_0 ... k_n)_2, "
         "g(k) = (kb_0 ... kb_n)_2, kb_0 = k_n, kb_p = k_{n-p} xor k_{n-p+1}. g(k) has an even "
         "number of one bits exactly for k < 2^n.",
         "(III.1.10)-(III.1.12)", "gray(2, 5)", 2, 2, builtin_gray},
        {"gray_basis", "gray_basis(A, k)",
         "The Gray basis element v_k = e_{g(k)} of A = multicomplex(n), k = 0..2^{n+1}-1: "
         "u_k = gray_basis(A, k) and j_k = gray_basis(A, 2^n + k) for k < 2^n, with u_k^2 = 1 and "
         "j_k^2 = -1.",
         "(III.1.13)-(III.1.14)", "gray_basis(multicomplex(1), 2)", 2, 2, builtin_gray_basis},
        {"sigma", "sigma(n, k)",
         "The sign sigma(k) = (-1)^floor(|g(k)|/2) (|g(k)| the number of one bits of the Gray "
         "digits of k), so that i0^{|g(k)|} = sigma(k) or sigma(k) i0; it fills the matrices sigma "
         "and sigma' of the change of basis S.",
         "(III.1.23)-(III.1.24), (III.1.31)-(III.1.33)", "sigma(2, 5)", 2, 2, builtin_sigma},
    });
}

}  // namespace symrep::lang
