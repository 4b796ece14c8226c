// symrep/algebra/polynomial_structure.cpp -- Thm III.4.1 and the power basis (III.4.4).
#include "symrep/algebra/polynomial_structure.h"

#include <cstdlib>

#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep {

using GiNaC::ex;

// 1, d, ..., d^{n-1} independent (Cor. II.1.1: minimal polynomial of degree n).
bool is_generator(const algebra& A, const coeffs& d) {
    A.check_size(d, "generator test");
    const std::size_t n = A.dim();
    krylov_basis K(n);
    coeffs pw = A.unit();
    for (std::size_t k = 0; k < n; ++k) {
        if (K.add(pw)) return false;
        if (k + 1 < n) pw = A.multiply(pw, d);
    }
    return true;
}

namespace {

// Integer points of the box [-R, R]^n in order of growing R (R = 1, 2, ...),
// enumerated as base-(2R+1) digits.
bool search_box(const algebra& A, std::size_t budget, generator_search& out) {
    const std::size_t n = A.dim();
    for (long R = 1; R <= 8; ++R) {
        const long base = 2 * R + 1;
        std::vector<long> digit(n, 0);
        while (true) {
            coeffs d(n);
            bool on_shell = false;  // points inside the previous box were already tried
            for (std::size_t k = 0; k < n; ++k) {
                const long c = digit[k] - R;
                if (std::labs(c) == R) on_shell = true;
                d[k] = c;
            }
            if (on_shell) {
                if (out.candidates >= budget) return false;
                ++out.candidates;
                if (is_generator(A, d)) {
                    out.generator = d;
                    return true;
                }
            }
            std::size_t k = 0;
            while (k < n && ++digit[k] == base) digit[k++] = 0;
            if (k == n) break;
        }
    }
    return false;
}

}  // namespace

// Thm III.4.1: an element with minimal polynomial of degree n makes A_n polynomial.
generator_search find_generator(const algebra& A, std::size_t max_candidates, bool decide) {
    const std::size_t n = A.dim();
    generator_search out;
    auto found = [&](coeffs d, const std::string& how) {
        out.status = generator_search::verdict::polynomial;
        out.generator = std::move(d);
        out.reason = "the " + how + " has a minimal polynomial of degree " + std::to_string(n) +
                     " = dim, so " + A.name() + " is polynomial (Thm III.4.1)";
        return out;
    };
    // 1a. basis elements
    for (std::size_t k = 0; k < n && out.candidates < max_candidates; ++k) {
        ++out.candidates;
        coeffs d = A.basis_vector(k);
        if (is_generator(A, d)) return found(d, "basis element " + A.basis_name(k));
    }
    // 1b. Vandermonde combinations sum_k s^k eps_k, s = 2, -2, 3, -3, ...
    for (long m = 0; out.candidates < max_candidates; ++m) {
        const long s = (m % 2 ? -1 : 1) * (2 + m / 2);
        coeffs d(n);
        ex c = 1;
        for (std::size_t k = 0; k < n; ++k, c = c * s) d[k] = c;
        ++out.candidates;
        if (is_generator(A, d)) return found(d, "element sum_k (" + std::to_string(s) + ")^k eps_k");
    }
    if (decide) {
        // 2. exact decision: is N/N^2 a cyclic A/N-module (N the nilradical)?
        const std::vector<coeffs> N = nilradical(A);
        krylov_basis K(n);
        for (const coeffs& a : N)
            for (const coeffs& b : N) K.add(A.multiply(a, b));  // a basis of N^2
        const std::size_t dimN2 = K.size();
        coeffs u = A.zero();
        for (std::size_t l = 0; l < N.size(); ++l) {
            const GiNaC::symbol y("y" + std::to_string(l));
            u = algebra::add(u, algebra::scale(y, N[l]));
        }
        for (std::size_t j = 0; j < n && K.size() < N.size(); ++j)
            K.add(A.multiply(A.basis_vector(j), u));
        if (K.size() < N.size()) {
            out.status = generator_search::verdict::not_polynomial;
            out.reason = "the nilradical N of " + A.name() + " has dimension " +
                         std::to_string(N.size()) + " and N^2 dimension " + std::to_string(dimN2) +
                         ", but N/N^2 is not a cyclic A/N-module (a local factor has a maximal ideal m "
                         "with dim m/m^2 >= 2), so no element has a minimal polynomial of degree " +
                         std::to_string(n) + " and the algebra is not polynomial (Thm III.4.1)";
            return out;
        }
        if (search_box(A, out.candidates + 20000, out))
            return found(out.generator, "integer element found by the box search");
        out.status = generator_search::verdict::polynomial;
        out.generator.clear();
        out.reason = A.name() + " is polynomial (N/N^2 is a cyclic A/N-module), but no integer "
                     "generator was found after " + std::to_string(out.candidates) + " candidates";
        return out;
    }
    out.reason = "no element with a minimal polynomial of degree " + std::to_string(n) +
                 " found after " + std::to_string(out.candidates) +
                 " candidates (the structural test was not run), so the question stays open";
    return out;
}

// Radical of the trace form: Tr [eps_i eps_j] = sum_k gamma_ijk Tr [eps_k].
std::vector<coeffs> nilradical(const algebra& A) {
    A.check_dense("nilradical");
    const std::size_t n = A.dim();
    std::vector<ex> tr(n);
    for (std::size_t k = 0; k < n; ++k) {
        const GiNaC::matrix L = A.canonical_matrix(A.basis_vector(k));
        ex s = 0;
        for (std::size_t i = 0; i < n; ++i) s += L(i, i);
        tr[k] = tidy(s);
    }
    std::vector<std::vector<ex>> T(n, std::vector<ex>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const coeffs g = A.basis_product(i, j);
            ex s = 0;
            for (std::size_t k = 0; k < n; ++k) s += g[k] * tr[k];
            T[i][j] = tidy(s);
        }
    return null_space(std::move(T));
}

bool is_polynomial(const algebra& A) {
    const generator_search s = find_generator(A);
    if (s.status == generator_search::verdict::unknown)
        throw closed_form_error("cannot decide whether " + A.name() + " is polynomial: " + s.reason);
    return s.status == generator_search::verdict::polynomial;
}

// (III.4.4) row k = coordinates of d^k.
GiNaC::matrix change_of_basis_to_power_basis(const algebra& A, const coeffs& d) {
    A.check_size(d, "power basis");
    A.check_dense("power basis");
    const std::size_t n = A.dim();
    GiNaC::matrix M(n, n);
    coeffs pw = A.unit();
    for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t j = 0; j < n; ++j) M(k, j) = pw[j];
        if (k + 1 < n) pw = A.multiply(pw, d);
    }
    if (is_zero_scalar(M.determinant()))
        throw algebra_error("the element does not generate " + A.name() +
                            ": its powers 1, d, ..., d^" + std::to_string(n - 1) +
                            " are linearly dependent, so they are no basis (III.4.4)");
    return M;
}

// Thm II.2.3: exp(d t) = sum_j f_j(t) eps_j.
std::vector<ex> fundamental_system(const algebra& A, const coeffs& d, const GiNaC::symbol& t) {
    return A.exp(d, t);
}

// (III.4.2-4) M_kj = f_j^{(k)}(0).
GiNaC::matrix wronskian_at_zero(const algebra& A, const coeffs& d) {
    A.check_dense("Wronskian");
    const GiNaC::symbol t("t");
    const std::vector<ex> f = fundamental_system(A, d, t);
    const std::size_t n = A.dim();
    GiNaC::matrix W(n, n);
    for (std::size_t j = 0; j < n; ++j) {
        ex g = f[j];
        for (std::size_t k = 0; k < n; ++k) {
            W(k, j) = tidy(g.subs(t == 0));
            if (k + 1 < n) g = g.diff(t);
        }
    }
    return W;
}

}  // namespace symrep
