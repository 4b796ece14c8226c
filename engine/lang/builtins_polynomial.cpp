// symrep/lang/builtins_polynomial.cpp -- builtins for general algebras given by
// structure constants (II.1.2), polynomial algebras P_n (II.1 completion of Thm
// II.1.2), the fundamental system of Thm II.2.3 and Theorem III.4.1.
#include <functional>
#include <string>
#include <vector>

#include "symrep/algebra/polynomial_algebra.h"
#include "symrep/algebra/polynomial_structure.h"
#include "symrep/algebra/structure_algebra.h"
#include "symrep/lang/builtins.h"
#include "symrep/numeric/reference.h"

namespace symrep::lang {

namespace {

const char* const section = "General and polynomial algebras";

std::string entry(std::size_t i, std::size_t j) {
    return "gamma[" + std::to_string(i) + "][" + std::to_string(j) + "]";
}

// gamma as a list of n lists of n lists of n expressions.
std::vector<std::vector<coeffs>> read_table(const std::vector<value>& args, const builtin& b) {
    const list& rows = arg_list(args, 0, b);
    const std::size_t n = rows.size();
    if (n == 0) throw type_error(b.name + ": the table gamma is empty (usage: " + b.signature + ")");
    std::vector<std::vector<coeffs>> g(n, std::vector<coeffs>(n));
    for (std::size_t i = 0; i < n; ++i) {
        if (!rows[i].is_list() || rows[i].as_list().size() != n)
            throw type_error(b.name + ": gamma[" + std::to_string(i) + "] must be a list of " +
                             std::to_string(n) + " products (one per basis element), not " +
                             (rows[i].is_list() ? "a list of " + std::to_string(rows[i].as_list().size())
                                                : rows[i].a_kind()));
        const list& row = rows[i].as_list();
        for (std::size_t j = 0; j < n; ++j) {
            if (!row[j].is_list() || row[j].as_list().size() != n)
                throw type_error(b.name + ": " + entry(i, j) + " (the coordinates of e" +
                                 std::to_string(i) + "*e" + std::to_string(j) + ") must be a list of " +
                                 std::to_string(n) + " expressions");
            for (const value& x : row[j].as_list()) {
                if (!x.is_ex())
                    throw type_error(b.name + ": " + entry(i, j) + " holds " + x.a_kind() +
                                     "; coordinates must be expressions");
                g[i][j].push_back(x.as_ex());
            }
        }
    }
    return g;
}

element element_of(const algebra_ptr& A, coeffs c) { return element(A, std::move(c)); }

value builtin_algebra_from_table(const builtin& b, const std::vector<value>& args, context&) {
    auto g = read_table(args, b);
    std::vector<std::string> names;
    if (args.size() > 1) {
        const list& l = arg_list(args, 1, b);
        for (std::size_t k = 0; k < l.size(); ++k) {
            if (!l[k].is_string())
                throw type_error(b.name + ": basis name " + std::to_string(k) +
                                 " must be a string, not " + l[k].a_kind());
            names.push_back(l[k].as_string());
        }
    }
    std::string nm = args.size() > 2 ? arg_string(args, 2, b) : std::string();
    return algebra_ptr(structure_algebra::make(std::move(g), std::move(names), std::move(nm)));
}

value builtin_polynomial_algebra(const builtin& b, const std::vector<value>& args, context&) {
    // a float is the exact binary rational it denotes (as in the numeric layer): factor()
    // and gcd() work over the rationals
    const GiNaC::ex p = num::exact_floats_of(arg_ex(args, 0, b));
    const GiNaC::symbol& X = arg_symbol(args, 1, b);
    return algebra_ptr(polynomial_algebra::make(p, X));
}

value builtin_frobenius_matrix(const builtin& b, const std::vector<value>& args, context&) {
    const algebra_ptr& A = arg_algebra(args, 0, b);
    auto P = std::dynamic_pointer_cast<const polynomial_algebra>(A);
    if (!P)
        throw type_error("frobenius_matrix: argument 1 must be a polynomial algebra made by "
                         "polynomial_algebra(p, X), not " + A->name() +
                         " (use canonical_matrix(d) for any element)");
    return GiNaC::ex(P->frobenius_matrix());
}

value builtin_find_generator(const builtin& b, const std::vector<value>& args, context&) {
    const algebra_ptr& A = arg_algebra(args, 0, b);
    generator_search s = find_generator(*A);
    if (s.status == generator_search::verdict::not_polynomial)
        throw algebra_error("find_generator: " + s.reason);
    if (s.generator.empty()) throw closed_form_error("find_generator: " + s.reason);
    return element_of(A, std::move(s.generator));
}

value builtin_is_polynomial(const builtin& b, const std::vector<value>& args, context&) {
    return is_polynomial(*arg_algebra(args, 0, b));
}

value builtin_power_basis_change(const builtin& b, const std::vector<value>& args, context&) {
    const algebra_ptr& A = arg_algebra(args, 0, b);
    coeffs d;
    if (args.size() > 1) {
        const element& e = arg_element(args, 1, b);
        if (e.parent().name() != A->name())
            throw algebra_error("power_basis_change: d belongs to " + e.parent().name() +
                                ", not to " + A->name());
        d = e.coefficients();
    } else {
        generator_search s = find_generator(*A);
        if (s.status == generator_search::verdict::not_polynomial)
            throw algebra_error("power_basis_change: " + s.reason);
        if (s.generator.empty()) throw closed_form_error("power_basis_change: " + s.reason);
        d = std::move(s.generator);
    }
    return GiNaC::ex(change_of_basis_to_power_basis(*A, d));
}

value builtin_fundamental_system(const builtin& b, const std::vector<value>& args, context&) {
    const element& d = arg_element(args, 0, b);
    const GiNaC::symbol& t = arg_symbol(args, 1, b);
    const std::vector<GiNaC::ex> f = fundamental_system(d.parent(), d.coefficients(), t);
    return list(f.begin(), f.end());
}

}  // namespace

void register_polynomial_builtins(registry& r) {
    add_builtins(r, section, {
        {"algebra_from_table", "algebra_from_table(gamma [, names [, name]])",
         "The commutative, associative, unital algebra with structure constants gamma: gamma[i][j] "
         "(indices from 0) is the list of coordinates of e_i*e_j. The table is checked (a non-commutative pair, a "
         "non-associative triple or a missing unit is named); the unit is found by solving a linear "
         "system and need not be e_0. Optional basis names (list of strings) and algebra name.",
         "(II.1.2)", "algebra_from_table([[[1,0],[0,1]],[[0,1],[-1,0]]], [\"1\", \"i\"])",
         1, 3, builtin_algebra_from_table},
        {"polynomial_algebra", "polynomial_algebra(p, X)",
         "The polynomial algebra P_n = R[X]/(p) for a monic polynomial p of degree n >= 1 (rational "
         "or symbolic coefficients; a float is read as the exact binary rational it denotes), with the cyclic "
         "basis 1, v, ..., v^(n-1) and p(v) = 0.",
         "(II.1 completion of Thm II.1.2)", "polynomial_algebra(X^3 - 2*X + 1, X)", 2, 2, builtin_polynomial_algebra},
        {"frobenius_matrix", "frobenius_matrix(A)",
         "The Frobenius (companion) matrix of the polynomial algebra A = polynomial_algebra(p, X): "
         "ones on the superdiagonal, last row -a_n ... -a_1. It equals canonical_matrix(v) with row j "
         "holding the coordinates of v*v^j.",
         "(II.1 completion of Thm II.1.2)", "frobenius_matrix(polynomial_algebra(X^2 + 1, X))",
         1, 1, builtin_frobenius_matrix},
        {"find_generator", "find_generator(A)",
         "An element d of A whose minimal polynomial has degree n = dim A, so that 1, d, ..., d^(n-1) "
         "is a basis and A is polynomial. Searches the basis elements, then fixed integer "
         "combinations, then decides exactly (N/N^2 cyclic over A/N, N the nilradical); an error "
         "explains when A is not polynomial or no integer generator was found.",
         "Thm III.4.1", "find_generator(polynomial_algebra(X^2 + 1, X))", 1, 1, builtin_find_generator},
        {"is_polynomial", "is_polynomial(A)",
         "True iff A is a polynomial algebra, i.e. some element has a minimal polynomial of degree "
         "dim A; decided exactly: the nilradical N must have N/N^2 cyclic over A/N.",
         "Thm III.4.1", "is_polynomial(algebra_from_table([[[1,0],[0,1]],[[0,1],[0,0]]]))",
         1, 1, builtin_is_polynomial},
        {"power_basis_change", "power_basis_change(A [, d])",
         "The matrix M with [d^0, ..., d^(n-1)]^T = M [e_1, ..., e_n]^T: row k holds the coordinates "
         "of d^k. It is the Wronskian of exp(d t) at t = 0 and is invertible iff d generates A. "
         "Without d, the generator of find_generator(A) is used.",
         "(III.4.4)", "power_basis_change(polynomial_algebra(X^2 + 1, X))", 1, 2, builtin_power_basis_change},
        {"fundamental_system", "fundamental_system(d, t)",
         "The list f_1(t), ..., f_n(t) with exp(d t) = sum_j f_j(t) e_j. When the minimal polynomial "
         "q of d has degree n, they form a fundamental system of q(D) f = 0.",
         "Thm II.2.3", "fundamental_system(find_generator(polynomial_algebra(X^2 + 1, X)), t)",
         2, 2, builtin_fundamental_system},
    });
}

}  // namespace symrep::lang
