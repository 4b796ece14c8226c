// tests/robustness_findings.h -- inputs on which the robustness run
// (test_robustness.cpp) found a runaway or a sanitizer report. Each is fixed in
// the engine; test_robustness.cpp runs them all through its watched workers
// (under the sanitizers in the sanitized build), test_bad_input.cpp checks their
// messages.
#pragma once

namespace symrep::test {

/// log of a Sobrero element whose first coordinate is a polynomial in 8
/// variables: normal() with a multivariate gcd ran for minutes in one call.
inline constexpr const char* sobrero_polynomial_log =
    "S := sobrero(2); p := (X^4 - 4*X^3*f0 + 6*X^2*f0^2 - 2*X^2*f1^2 - 2*X^2*f2^2 - 2*X^2*f3^2 - 4*X*f0^3 + "
    "4*X*f0*f1^2 + 4*X*f0*f2^2 + 4*X*f0*f3^2 - 8*X*f1*f2*f3 + f0^4 - 2*f0^2*f1^2 - 2*f0^2*f2^2 - 2*f0^2*f3^2 + "
    "8*f0*f1*f2*f3 + f1^4 - 2*f1^2*f2^2 - 2*f1^2*f3^2 + f2^4 - 2*f2^2*f3^2 + f3^4); "
    "w := element(S, [p*F0/m, a1, a2, b0, b1, b2]); log(-w)";

/// factor() of the determinant of such an element: 20 s in one call.
inline constexpr const char* sobrero_polynomial_factor =
    "a0 := (X^3 - X^2*x - 2*X^2*y + 2*X*x*y + X*y^2 - x*y^2)*F0/m; "
    "w := element(sobrero(2), [a0, a1, a2, b0, b1, b2]); factor(det(w))";

/// The minimal polynomial of a multicomplex element with polynomial
/// coefficients: a product of factors multiplied out for minutes.
inline constexpr const char* multicomplex_polynomial_minpoly =
    "p := (a + b + c + d + f)^3; minpoly(element(multicomplex(2), [p, p + 1, p - 1, 2*p, p^2, 1, 2, 3]), X)";

/// All of them, and the inputs that leaked (0 to a complex power, a matrix plus a
/// number, an element compared with a matrix, a float power out of range, a
/// substitution that divides by zero: GiNaC lost the power or the sum it had
/// allocated when eval() threw).
inline constexpr const char* robustness_findings[] = {
    sobrero_polynomial_log, sobrero_polynomial_factor, multicomplex_polynomial_minpoly, "0^I", "0^(-1+I)", "0^0",
    "matrix([[1, 2], [3, 4]]) + 1", "1 - matrix([[1, 2], [3, 4]])", "2*M0 + 1e-3", "(x + 1) - M0^2", "M4 := canonical_matrix(r0/u0); M4 + 1e-3", "expect(u0 == matrix([[1, 2], [3, 4]]))",
    "binomial(M0, 3)", "I - (M0 < 1)", "(M0 = 1) - 3/4", "expect(0.5 = M0)", "expect((M0 = 1) == (M0 = 2))",
    "1e-3^10^30", "old := digits(5); (1e-3^5)^(-5); digits(old)", "subs(1/(t - 1), [t = 1])", "eval(1/t, t = 0)",
};

}  // namespace symrep::test
