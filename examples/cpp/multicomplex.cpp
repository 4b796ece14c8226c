// examples/cpp/multicomplex.cpp -- exact arithmetic in the multicomplex algebra through
// symrep's C++ API (docs/library.md; thesis III.1).
//
// The multicomplex algebra (x)C^{n+1} = C_0 (x) C_1 (x) ... (x) C_n has the imaginary units
// i0, ..., in (i_k^2 = -1) and the natural binary basis e_p = i0^p0 i1^p1 ... (III.1.4). Every
// element splits over 2^n orthogonal idempotents e_p as w = sum_p (a_p + i0 b_p) e_p (III.1.39),
// and products, inverses and exp act on the components a_p + I b_p one by one. The program
//   1. builds multicomplex(1) (order 4, C (x) C) and checks its units;
//   2. takes w = 1 + 2 i1 + 3 i0 + 4 i0 i1, its components, its inverse (w * w^-1 = 1 exactly),
//      its minimal polynomial (m(w) = 0) and exp(w t) (d/dt exp(w t) = w exp(w t), exp(0) = 1);
//   3. meets a zero divisor (1 + i0 i1): the inverse throws symrep::zero_divisor_error;
//   4. inverts an element of multicomplex(2) (order 8).
// Coordinates are GiNaC expressions: exact rationals, radicals, symbols. It prints what it finds
// and exits with 1 when a check fails (2 on an unexpected error of the engine).
//
// Build: see CMakeLists.txt next to this file (find_package(symrep), symrep::engine).
#include <cstddef>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include <symrep/algebra/element.h>       // symrep::element: arithmetic, inverse, exp, minpoly
#include <symrep/algebra/multicomplex.h>  // symrep::multicomplex: the algebra and its idempotent basis
#include <symrep/core/error.h>            // symrep::error, zero_divisor_error
#include <symrep/output/printer.h>        // output::print_element, output::print_ex

using GiNaC::ex;
using symrep::element;
using symrep::output::print_element;
using symrep::output::print_ex;

namespace {

int failures = 0;

void report(const std::string& what, bool ok) {
    std::cout << (ok ? "ok    " : "FAILED") << "  " << what << "\n";
    if (!ok) ++failures;
}

}  // namespace

int main() {
    try {
        // --- 1. the algebra C (x) C --------------------------------------------------------------
        const auto A = symrep::multicomplex::make(1);  // std::shared_ptr<const multicomplex>
        const element one = element::one(A);
        const element i0(A, A->imag_unit(0)), i1(A, A->imag_unit(1));
        std::cout << A->name() << ": dimension " << A->dim() << ", basis";
        for (std::size_t k = 0; k < A->dim(); ++k) std::cout << " " << A->basis_name(k);
        std::cout << "\n";
        report("i0^2 = i1^2 = -1 and (i0*i1)^2 = 1", i0 * i0 == -one && i1 * i1 == -one && (i0 * i1).pow(2) == one);

        // --- 2. an element, its components, inverse, minimal polynomial and exponential ----------
        const element w = one + 2 * i1 + 3 * i0 + 4 * (i0 * i1);
        std::cout << "w = " << print_element(w) << "\n";

        // w = sum_p (a_p + i0 b_p) e_p (III.1.39): the components c_p = a_p + I b_p
        const std::vector<ex> c = A->idempotent_components(w.coefficients());
        element rebuilt = 0 * one;
        for (std::size_t p = 0; p < c.size(); ++p) {
            const element e_p(A, A->idempotent(p));
            std::cout << "  e_" << p << " = " << print_element(e_p) << ", c_" << p << " = " << print_ex(c[p]) << "\n";
            rebuilt = rebuilt + (GiNaC::real_part(c[p]) * one + GiNaC::imag_part(c[p]) * i0) * e_p;
        }
        report("w = sum_p (a_p + i0 b_p) e_p", rebuilt == w);

        const element winv = w.inverse();  // (III.1.57): componentwise 1/c_p
        std::cout << "inverse(w) = " << print_element(winv) << "\n";
        report("w * inverse(w) = 1", w * winv == one);

        const GiNaC::realsymbol X("X"), t("t");
        const ex m = w.minpoly(X);  // (III.1.59-60): prod_p (X^2 - 2 a_p X + a_p^2 + b_p^2), distinct factors
        std::cout << "minpoly(w, X) = " << print_ex(m) << "\n";
        report("minpoly(w)(w) = 0", w.evaluate(m, X) == 0 * one);

        const element E = w.exp(t);  // (III.1.45-52): e^(a_p t) (cos(b_p t) + i0 sin(b_p t)) per component
        std::cout << "exp(w t) = " << print_element(E) << "\n";
        const element dE = E.map_coeffs([&](const ex& x) { return x.diff(t); });
        const element E0 = E.map_coeffs([&](const ex& x) { return x.subs(t == 0); });
        report("d/dt exp(w t) = w exp(w t) and exp(w 0) = 1", dE == w * E && E0 == one);

        // --- 3. a zero divisor -----------------------------------------------------------------------
        // (1 + i0 i1)(1 - i0 i1) = 1 - (i0 i1)^2 = 0: no inverse, and the engine says which
        // idempotent components vanish (III.1.55).
        const element d = one + i0 * i1;
        try {
            (void)d.inverse();
            report("inverse(1 + i0*i1) is refused", false);
        } catch (const symrep::zero_divisor_error& e) {
            std::cout << "inverse(" << print_element(d) << "): " << e.what() << "\n";
            report("inverse(1 + i0*i1) is refused, vanishing components " + std::to_string(e.ranks.size()),
                   !e.ranks.empty());
        }

        // --- 4. multicomplex(2), order 8 ---------------------------------------------------------------
        const auto B = symrep::multicomplex::make(2);
        const element z(B, {1, 0, 2, 0, 0, 1, 0, 3});
        const element zinv = z.inverse();
        std::cout << "z = " << print_element(z) << " in " << B->name() << "\n";
        std::cout << "inverse(z) = " << print_element(zinv) << "\n";
        report("z * inverse(z) = 1 in " + B->name(), z * zinv == element::one(B));
    } catch (const symrep::error& e) {
        // every failure the engine reports is a symrep::error with a complete message
        std::cerr << "multicomplex: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "multicomplex: " << e.what() << "\n";
        return 2;
    }
    std::cout << (failures == 0 ? "all checks passed\n" : std::to_string(failures) + " check(s) FAILED\n");
    return failures == 0 ? 0 : 1;
}
