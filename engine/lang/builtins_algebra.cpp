// symrep/lang/builtins_algebra.cpp -- builtins on algebras and their elements
// (section "Algebras and elements"), written against the virtual interface of
// `algebra` only, so that every family's fast paths are used automatically.
#include <algorithm>
#include <climits>
#include <cstdint>

#include "symrep/scalar/scalar.h"
#include "symrep/lang/builtins.h"
#include "symrep/output/printer.h"
#include "symrep/core/expression_size.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using output::print_ex;

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using args_t = std::vector<value>;

namespace {

const char* const section = "Algebras and elements";

list ex_list(const std::vector<ex>& c) {
    list l(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) l[k].v.emplace<GiNaC::ex>(c[k]);
    return l;
}

GiNaC::matrix as_matrix(const value& v, const builtin& b) {
    const ex& e = v.as_ex();
    if (!is_a<GiNaC::matrix>(e))
        throw type_error(b.name + ": argument 1 must be an algebra element or a matrix (usage: " + b.signature + ")");
    const GiNaC::matrix& m = ex_to<GiNaC::matrix>(e);
    if (m.rows() != m.cols()) throw type_error(b.name + ": the matrix is not square");
    return m;
}

value builtin_element(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    std::vector<ex> c = arg_ex_list(a, 1, b);
    if (c.size() != A->dim())
        throw algebra_error(b.name + ": " + A->name() + " has dimension " + std::to_string(A->dim()) +
                            ", but " + std::to_string(c.size()) + " coordinates were given");
    for (std::size_t k = 0; k < c.size(); ++k)  // coordinates are scalars: no vector, matrix or relation
        if (!vector_symbols(c[k]).empty() || has_matrix(c[k]) || GiNaC::is_a<GiNaC::relational>(c[k]))
            throw type_error(b.name + ": coordinate " + std::to_string(k) + " must be a scalar, not " +
                             (GiNaC::is_a<GiNaC::relational>(c[k]) ? "a relation" : "a vector") + " (" +
                             output::print_ex(c[k]) + ")");
    return value(element(A, coeffs(c.begin(), c.end())));
}

value builtin_basis(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    const long k = arg_int(a, 1, b, 0, static_cast<long>(A->dim()) - 1);
    return value(element::basis(A, static_cast<std::size_t>(k)));
}

value builtin_one(const builtin& b, const args_t& a, context&) {
    return value(element::one(arg_algebra(a, 0, b)));
}

value builtin_coords(const builtin& b, const args_t& a, context&) {
    return value(ex_list(arg_element(a, 0, b).coefficients()));
}

value builtin_dim(const builtin& b, const args_t& a, context&) {
    if (a[0].is_element()) return static_cast<int>(a[0].as_element().dim());
    return static_cast<int>(arg_algebra(a, 0, b)->dim());
}

value builtin_algebra_of(const builtin& b, const args_t& a, context&) {
    return value(arg_element(a, 0, b).parent_ptr());
}

value builtin_inverse(const builtin& b, const args_t& a, context&) {
    if (a[0].is_element()) return a[0].as_element().inverse();
    (void)arg_ex(a, 0, b);
    const GiNaC::matrix m = as_matrix(a[0], b);
    guard_terms(determinant_terms(m, false), "inverse");
    if (is_zero_scalar(m.determinant())) throw domain_error(b.name + ": the matrix is singular");
    return ex(m.inverse());
}

value builtin_charpoly(const builtin& b, const args_t& a, context&) {
    const GiNaC::symbol& X = arg_symbol(a, 1, b);
    if (a[0].is_element()) return a[0].as_element().charpoly(X);
    const GiNaC::matrix m = as_matrix(arg_ex(a, 0, b), b);
    guard_terms(determinant_terms(m, true), "charpoly");
    return GiNaC::expand((m.rows() % 2 ? -1 : 1) * m.charpoly(X));
}

value builtin_minpoly(const builtin& b, const args_t& a, context&) {
    return value(arg_element(a, 0, b).minpoly(arg_symbol(a, 1, b)));
}

value builtin_canonical_matrix(const builtin& b, const args_t& a, context&) {
    return value(ex(arg_element(a, 0, b).canonical_matrix()));
}

value builtin_is_zero_divisor(const builtin& b, const args_t& a, context&) {
    return value(arg_element(a, 0, b).is_zero_divisor());
}

value builtin_evaluate(const builtin& b, const args_t& a, context&) {
    const ex& p = arg_ex(a, 0, b);
    const GiNaC::symbol& X = arg_symbol(a, 1, b);
    return value(arg_element(a, 2, b).evaluate(p, X));
}

value builtin_structure_constants(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    if (A->dim() > 64) throw size_error(b.name + ": the table of " + A->name() + " has more than 64^2 entries");
    list rows;
    for (std::size_t i = 0; i < A->dim(); ++i) {
        list row;
        for (std::size_t j = 0; j < A->dim(); ++j) row.push_back(ex_list(A->basis_product(i, j)));
        rows.push_back(row);
    }
    return value(rows);
}

value builtin_idempotent(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    const std::size_t n = A->idempotent_count();
    if (n == 0) return value(element(A, A->idempotent(0)));  // the algebra's own error
    const long p = arg_int(a, 1, b, 0, static_cast<long>(n) - 1);
    return value(element(A, A->idempotent(static_cast<std::size_t>(p))));
}

value builtin_idempotents(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    const std::size_t n = A->idempotent_count();
    if (n == 0) (void)A->idempotent(0);  // throws the algebra's explanation
    if (n > algebra::max_dense_dim)
        throw size_error(b.name + ": " + A->name() + " has " + std::to_string(n) +
                         " idempotents of dimension " + std::to_string(A->dim()) +
                         "; the list is limited to " + std::to_string(algebra::max_dense_dim) +
                         " (use idempotent(A, p) for one of them)");
    list l;
    for (std::size_t p = 0; p < n; ++p) l.push_back(element(A, A->idempotent(p)));
    return value(l);
}

value builtin_components(const builtin& b, const args_t& a, context&) {
    const element& w = arg_element(a, 0, b);
    return value(ex_list(w.parent().idempotent_components(w.coefficients())));
}

value builtin_from_components(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    return value(element(A, A->from_idempotent_components(arg_ex_list(a, 1, b))));
}

value builtin_zero_divisor_ranks(const builtin& b, const args_t& a, context&) {
    const element& w = arg_element(a, 0, b);
    list l;
    for (std::size_t p : w.parent().zero_divisor_ranks(w.coefficients())) l.push_back(ex(static_cast<long>(p)));
    return value(l);
}

value builtin_semiexponential(const builtin& b, const args_t& a, context&) {
    const element& w = arg_element(a, 0, b);
    auto [rho, theta] = w.parent().semiexponential(w.coefficients());
    return value(list{element(w.parent_ptr(), rho), element(w.parent_ptr(), theta)});
}

value builtin_is_special_type(const builtin& b, const args_t& a, context&) {
    const element& w = arg_element(a, 0, b);
    bool strict = true;
    if (a.size() > 1) {
        if (!a[1].is_bool()) throw type_error(b.name + ": argument 2 must be true or false (usage: " +
                                              b.signature + ")");
        strict = a[1].as_bool();
    }
    return value(w.parent().is_special_type(w.coefficients(), strict));
}

value builtin_special_type_decomposition(const builtin& b, const args_t& a, context&) {
    const element& w = arg_element(a, 0, b);
    list l;
    for (const coeffs& c : w.parent().special_type_decomposition(w.coefficients()))
        l.push_back(element(w.parent_ptr(), c));
    return value(l);
}

value builtin_generating_element(const builtin& b, const args_t& a, context&) {
    const algebra_ptr& A = arg_algebra(a, 0, b);
    std::vector<ex> params;
    if (a.size() > 1) params = arg_ex_list(a, 1, b);
    const coeffs d = A->generating_element(params);
    // numeric parameters: check that d generates A (its minimal polynomial has
    // degree dim A); symbolic ones are the caller's responsibility
    const bool numeric_params = std::all_of(params.begin(), params.end(), [](const ex& p) {
        return is_a<GiNaC::numeric>(GiNaC::evalf(p));
    });
    if (!params.empty() && numeric_params && A->dim() <= algebra::max_dense_dim) {
        const GiNaC::symbol X("X");
        const int deg = A->minpoly(d, X).degree(X);
        if (deg != static_cast<int>(A->dim())) {
            std::string ps;
            for (const ex& p : params) ps += (ps.empty() ? "" : ", ") + print_ex(p);
            throw domain_error(b.name + ": the parameters [" + ps + "] do not give a generating element of " +
                               A->name() + ": the minimal polynomial of d has degree " +
                               std::to_string(deg) + ", not " + std::to_string(A->dim()) + " = dim " +
                               A->name() + " (choose parameters that make the characteristic polynomial "
                               "minimal)");
        }
    }
    return value(element(A, d));
}

}  // namespace

void register_algebra_builtins(registry& r) {
    add_builtins(r, section, {
        {"element", "element(A, [c0, c1, ...])",
         "The element sum_k c_k eps_k of the algebra A, from its coordinates in the basis of A (one per basis "
         "element, dim(A) in all).",
         "(II.1.1)", "element(multicomplex(1), [1, 2, 3, 4])", 2, 2, builtin_element},
        {"basis", "basis(A, k)",
         "The basis element eps_k of A (k = 0 .. dim(A) - 1).",
         "(II.1.1)", "basis(multicomplex(1), 2)", 2, 2, builtin_basis},
        {"one", "one(A)",
         "The identity element of A.",
         "", "one(multicomplex(1))", 1, 1, builtin_one},
        {"coords", "coords(w)",
         "The list of the coordinates of w in the basis of its algebra.",
         "(II.1.1)", "coords(element(multicomplex(1), [1, 2, 0, 0]) * element(multicomplex(1), [3, 4, 0, 0]))",
         1, 1, builtin_coords},
        {"dim", "dim(A) / dim(w)",
         "The dimension of an algebra (of the algebra of an element) over R.",
         "", "dim(multicomplex(2))", 1, 1, builtin_dim},
        {"algebra_of", "algebra_of(w)",
         "The algebra an element belongs to.",
         "", "algebra_of(basis(multicomplex(1), 1))", 1, 1, builtin_algebra_of},
        {"inverse", "inverse(w) / inverse(m)",
         "The inverse of an algebra element (an error naming the vanishing components for a zero divisor), or of "
         "an invertible square matrix.",
         "(II.1.22, III.1.57)", "inverse(element(multicomplex(1), [1, 2, 3, 4]))", 1, 1, builtin_inverse},
        {"charpoly", "charpoly(w, X) / charpoly(m, X)",
         "The monic characteristic polynomial det(X I - [w]) of an element (of a square matrix) in the symbol X.",
         "(II.1.20)", "charpoly(element(multicomplex(1), [1, 2, 0, 0]), X)", 2, 2, builtin_charpoly},
        {"minpoly", "minpoly(w, X)",
         "The monic minimal polynomial of w in the symbol X.",
         "(Cor. II.1.1)", "minpoly(element(multicomplex(1), [1, 0, 1, 0]), X)", 2, 2, builtin_minpoly},
        {"canonical_matrix", "canonical_matrix(w)",
         "The canonical matrix [w] of w: row j holds the coordinates of w eps_j.",
         "(II.1.3-4)", "canonical_matrix(element(multicomplex(0), [a, b]))", 1, 1, builtin_canonical_matrix},
        {"is_zero_divisor", "is_zero_divisor(w)",
         "true when w is a zero divisor, i.e. det [w] = 0.",
         "(II.1.22)", "is_zero_divisor(element(multicomplex(1), [1, 0, 0, 1]))", 1, 1, builtin_is_zero_divisor},
        {"evaluate", "evaluate(p, X, w)",
         "The polynomial p in the symbol X evaluated at the element w: p(w).",
         "(Cor. II.1.1)", "evaluate(X^2 + 1, X, basis(multicomplex(1), 2))", 3, 3, builtin_evaluate},
        {"structure_constants", "structure_constants(A)",
         "The structure constants of A: entry [i][j] is the coordinate list of eps_i eps_j.",
         "(II.1.2)", "structure_constants(multicomplex(0))", 1, 1, builtin_structure_constants},
        {"idempotent", "idempotent(A, p)",
         "The orthogonal idempotent e_p of the idempotent basis of A.",
         "(III.1.15, III.3.7)", "idempotent(multicomplex(1), 0)", 2, 2, builtin_idempotent},
        {"idempotents", "idempotents(A)",
         "The list of the orthogonal idempotents e_p of A.",
         "(III.1.15, III.3.7)", "idempotents(multicomplex(1))", 1, 1, builtin_idempotents},
        {"components", "components(w)",
         "The components c_p of w = sum_p c_p e_p in the idempotent basis (complex a_p + I b_p in the "
         "multicomplex algebra and W*, real in W).",
         "(III.1.39, III.3.24, III.3.61)", "components(element(multicomplex(1), [1, 2, 3, 4]))",
         1, 1, builtin_components},
        {"from_components", "from_components(A, [c0, c1, ...])",
         "The element of A with the given idempotent components (inverse of components).",
         "(III.1.39, III.3.24, III.3.61)", "from_components(multicomplex(1), [1 + I, 2 - I])",
         2, 2, builtin_from_components},
        {"zero_divisor_ranks", "zero_divisor_ranks(w)",
         "The ranks p whose idempotent components c_p of w vanish; empty iff w is not a zero divisor.",
         "(III.1.55, III.3.31)", "zero_divisor_ranks(element(multicomplex(1), [1, 0, 0, 1]))",
         1, 1, builtin_zero_divisor_ranks},
        {"semiexponential", "semiexponential(w)",
         "The semiexponential form, as the list [rho, theta] of elements. Multicomplex: w = rho exp(theta), rho = sum r_p e_p (the moduli of the idempotent components) and theta = sum i0 phi_p e_p (their arguments). Sobrero: w = sum_k A_k exp(j phi_k) eps^k, coordinate by coordinate, rho = sum A_k eps^k with A_k = sqrt(a_k^2 + b_k^2) and theta = sum j phi_k eps^k with phi_k = atan2(b_k, a_k) in [0, 2 pi) (there w is not rho exp(theta)).",
         "(III.1.72-76, III.2.16-18)", "semiexponential(element(multicomplex(1), [1, 2, 3, 4]))",
         1, 1, builtin_semiexponential},
        {"is_special_type", "is_special_type(w [, strict])",
         "true when w is of special type; strict = false (default true) admits real coefficients of either sign "
         "where the family distinguishes them (Sobrero).",
         "(III.1.77-78, III.2.19-20)", "is_special_type(element(multicomplex(1), [0, 0, 3, 0]))",
         1, 2, builtin_is_special_type},
        {"special_type_decomposition", "special_type_decomposition(w)",
         "A decomposition of w into a list of special-type elements whose sum is w.",
         "(Thm III.1.3.1, Thm III.2.2.1)", "special_type_decomposition(element(multicomplex(1), [1, 2, 3, 4]))",
         1, 1, builtin_special_type_decomposition},
        {"generating_element", "generating_element(A [, [params]])",
         "A generating element of A (its powers span A) with the family's parameters (omega_k, alpha/beta, "
         "alpha_k); without parameters the family's default choice.",
         "(III.4.2 a-c)", "generating_element(multicomplex(1))", 1, 2, builtin_generating_element},
    });
}

}  // namespace symrep::lang
