// symrep/mechanics/quasi_polynomial.h -- quasi-polynomials in one variable t:
// finite sums of c t^k e^{a t} cos(b t) and c t^k e^{a t} sin(b t), with exact
// (possibly symbolic) c, a, b, and their closed-form calculus: derivative,
// antiderivative from 0, product and convolution (f * g)(t) = int_0^t f(tau) g(t - tau) dtau
// (thesis VI.1.22, 25, 30-38).
//
// Representation. Internally every term is a complex exponential monomial
//     (cr + i ci) t^k e^{(lr + i li) t},
// with the real and imaginary parts kept as an explicit pair (cplx<ex>, as in the
// algebra layer), so that symbolic parameters never meet GiNaC's I. A real
// function such as cos(b t) is the pair (1/2) e^{i b t} + (1/2) e^{-i b t}. Terms
// with the same k and the same exponent (the difference normalizes to 0) are
// combined, and terms whose coefficient normalizes to 0 are dropped (lazily: see
// normalize() below), so the form is canonical: t^k e^{lambda t} for distinct (k, lambda) are linearly
// independent, hence a quasi-polynomial is the zero function iff is_zero().
// Complex-valued quasi-polynomials are allowed (the solver needs them on the
// complex idempotent component); real() / imag() / conj() split them.
//
// Symbols. All symbols appearing in c, a, b are read as REAL (use
// GiNaC::realsymbol or possymbol; a plain GiNaC::symbol is accepted but its real
// part is then taken to be itself). The variable t must not occur in c, a, b.
//
// Generic reading (documented assumption). Integration of t^k e^{lambda t} uses
// the finite sum with 1/lambda^{j+1} whenever lambda = a + i b does not normalize
// to exactly 0; for symbolic a, b (e.g. b = w1 - w2) the result holds for the
// generic values, i.e. where a + i b != 0. When lambda is exactly 0 (after
// normalization), the exact formula t^{k+1}/(k+1) is used instead, so no division
// by zero ever happens. The same rule decides resonance in convolutions:
// exponents that coincide exactly give the secular terms t^{m+n+1} e^{mu t}.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/scalar/cplx.h"

namespace symrep::mechanics {

using cex = cplx<GiNaC::ex>;

/// One complex exponential monomial c t^k e^{lambda t}.
struct qp_term {
    cex c;
    unsigned k = 0;
    cex lambda;
};

class quasi_polynomial {
public:
    /// The zero function.
    quasi_polynomial() = default;
    /// The constant c (real, may be symbolic; must not contain t).
    static quasi_polynomial constant(const GiNaC::ex& c, const GiNaC::ex& t);
    /// c t^k e^{lambda t} for complex c and lambda (pairs of real expressions).
    static quasi_polynomial monomial(const cex& c, unsigned k, const cex& lambda, const GiNaC::ex& t);
    /// c t^k e^{a t} cos(b t) (real).
    static quasi_polynomial cos_term(const GiNaC::ex& c, unsigned k, const GiNaC::ex& a,
                                     const GiNaC::ex& b, const GiNaC::ex& t);
    /// c t^k e^{a t} sin(b t) (real).
    static quasi_polynomial sin_term(const GiNaC::ex& c, unsigned k, const GiNaC::ex& a,
                                     const GiNaC::ex& b, const GiNaC::ex& t);
    /// Recognizes a quasi-polynomial in t: sums and products of t, constants,
    /// non-negative integer powers, exp, cos, sin, cosh, sinh of arguments
    /// linear in t (alpha t + beta, beta allowed: cos(b t + phi) is expanded).
    /// Throws domain_error naming the offending sub-expression otherwise
    /// (1/t, t^(1/2), exp(t^2), log(t), cos(t)/t, ...), size_error for an
    /// integer power above 4096 of an expression in t.
    static quasi_polynomial from_ex(const GiNaC::ex& e, const GiNaC::ex& t);

    /// The variable t (kept as an ex, so that a realsymbol is not sliced).
    const GiNaC::ex& variable() const { return t_; }
    const std::vector<qp_term>& terms() const {
        normalize();
        return terms_;
    }
    /// True iff the function is identically zero (canonical form, see above).
    bool is_zero() const {
        normalize();
        return terms_.empty();
    }
    /// True iff the imaginary part is identically zero.
    bool is_real() const;

    /// The real-form expression: sum of c t^k e^{a t} cos(b t) / sin(b t) terms.
    /// For a complex-valued quasi-polynomial returns re + I*im.
    GiNaC::ex to_ex() const;
    /// The same sum for a caller that brings each coefficient of a function of t to its own
    /// canonical form (the solver: in the field of its square root): exponents merged as in
    /// normalize(), the coefficients of each real function summed and put over one fraction
    /// (one_fraction), but not tidied term by term first. Equal to to_ex() as a function; a
    /// coefficient that is 0 only modulo square roots may be left as such (the caller's
    /// canonical form decides it).
    GiNaC::ex to_ex_untidied() const;
    /// Real and imaginary parts as quasi-polynomials ((f + conj f)/2, (f - conj f)/(2i)).
    quasi_polynomial real() const;
    quasi_polynomial imag() const;
    quasi_polynomial conj() const;

    /// Value at t = 0 (complex pair).
    cex at_zero() const;
    /// The same value as the raw sum of the t^0 coefficients (not tidied), for a caller that
    /// decides its zero itself.
    cex at_zero_untidied() const;
    /// d/dt.
    quasi_polynomial derivative() const;
    /// int_0^t f(tau) dtau, closed form (see the generic reading above).
    quasi_polynomial antiderivative() const;
    /// Substitutes s for a symbol in every c, a, b (s must not contain t). Throws
    /// domain_error when the value is excluded by the generic reading (a closed
    /// form with 1/(a^2 + b^2) at a = b = 0): build the quasi-polynomial from the
    /// specialized integrand instead, which takes the exact lambda = 0 branch.
    quasi_polynomial subs(const GiNaC::ex& sym, const GiNaC::ex& s) const;

    quasi_polynomial operator-() const;
    friend quasi_polynomial operator+(const quasi_polynomial& f, const quasi_polynomial& g);
    friend quasi_polynomial operator-(const quasi_polynomial& f, const quasi_polynomial& g);
    friend quasi_polynomial operator*(const quasi_polynomial& f, const quasi_polynomial& g);
    /// Multiplication by a real scalar (no t) or a complex scalar.
    friend quasi_polynomial operator*(const GiNaC::ex& s, const quasi_polynomial& f);
    friend quasi_polynomial operator*(const cex& s, const quasi_polynomial& f);

    /// (f * g)(t) = int_0^t f(tau) g(t - tau) dtau, closed form (VI.1.25).
    friend quasi_polynomial convolution(const quasi_polynomial& f, const quasi_polynomial& g);

private:
    quasi_polynomial(const GiNaC::ex& t) : t_(t), has_t_(true) {}
    void add_term(const qp_term& u);
    void adopt_variable(const quasi_polynomial& o);
    /// The canonical form (above) from the raw one: every coefficient tidied once, terms
    /// whose exponents are equal but spelled differently merged, zero terms dropped.
    void normalize() const;
    /// The terms with equal exponents merged (coefficients summed as they are).
    std::vector<qp_term> merged_terms() const;
    GiNaC::ex real_form(const std::vector<qp_term>& terms, bool tidied) const;
    GiNaC::ex t_;
    bool has_t_ = false;  // false only for the default-constructed zero
    // Arithmetic accumulates coefficients unsimplified (raw sums and products; exponents
    // tidied, terms of structurally equal exponents merged) and normalizes once, when the
    // form is read (terms, is_zero, to_ex, at_zero, ...): tidying every coefficient at
    // every addition cost 96 % of a derivation with t^d e^(-k t) forcing (issue 15).
    mutable std::vector<qp_term> terms_;
    mutable bool raw_ = false;
};

/// int_0^t tau^k e^{lambda tau} dtau as a quasi-polynomial in t (exact; lambda = 0
/// exactly gives t^{k+1}/(k+1)).
quasi_polynomial integral_monomial(unsigned k, const cex& lambda, const GiNaC::ex& t);

/// Exact test that a complex pair normalizes to 0.
bool is_zero_cex(const cex& z);
/// Tidied complex pair.
cex tidy_cex(const cex& z);
/// 1/z for z not normalizing to 0 (generic reading); throws domain_error when z is exactly 0.
cex inverse_cex(const cex& z, const char* where);

}  // namespace symrep::mechanics
