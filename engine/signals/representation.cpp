// symrep/signals/representation.cpp -- see representation.h.
#include "symrep/signals/representation.h"

#include <cmath>
#include <map>
#include <sstream>

#include "symrep/algebra/exact_linear.h"
#include "symrep/algebra/multicomplex.h"
#include "symrep/algebra/polynomial_algebra.h"
#include "symrep/algebra/sobrero.h"
#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/polynomial_roots.h"
#include "symrep/scalar/scalar.h"
#include "symrep/signals/multicomplex_signals.h"
#include "symrep/signals/product.h"
#include "symrep/signals/sampling_numeric.h"

namespace symrep::signals {

using GiNaC::ex;

ex functional(const coeffs& lambda, const coeffs& x) {
    ex s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s += lambda[i] * x[i];
    return s;
}

namespace {

// lambda(x) = (K^-1 x)[n-1], K the matrix of the powers 1, d, ..., d^(n-1) (columns):
// the row with K^T lambda = e_(n-1).
coeffs power_basis_functional(const algebra& A, const coeffs& d) {
    const std::size_t n = A.dim();
    std::vector<coeffs> powers{A.unit()};
    for (std::size_t j = 1; j < n; ++j) powers.push_back(A.multiply(powers.back(), d));
    std::vector<std::vector<ex>> KT(n, std::vector<ex>(n));
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) KT[j][i] = powers[j][i];
    std::vector<ex> e(n, ex(0));
    e[n - 1] = 1;
    const auto l = solve_linear(KT, e);
    if (!l) throw algebra_error("signals: the powers of d are not a basis of " + A.name());
    return coeffs(l->begin(), l->end());
}


}  // namespace

std::string polynomial_text(const ex& p, const GiNaC::symbol& X) {
    const ex e = GiNaC::expand(p);
    if (!e.is_polynomial(X)) return message_text(e, text_limit::signal_report);
    std::string out;
    for (int k = e.degree(X); k >= 0; --k) {
        const ex c = e.coeff(X, k);
        if (c.is_zero()) continue;
        std::string mono = k == 0 ? "" : k == 1 ? X.get_name() : X.get_name() + "^" + std::to_string(k);
        std::string coef = message_text(c, text_limit::signal_report);
        bool negative = false;
        if (GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_real() &&
            GiNaC::ex_to<GiNaC::numeric>(c) < 0) {
            negative = true;
            coef = message_text(-c, text_limit::signal_report);
        } else if (GiNaC::is_a<GiNaC::add>(c)) {
            coef = "(" + coef + ")";
        }
        std::string term = mono.empty() ? coef : coef == "1" ? mono : coef + "*" + mono;
        if (out.empty()) out = negative ? "-" + term : term;
        else out += (negative ? " - " : " + ") + term;
    }
    return out.empty() ? "0" : out;
}

// (Thm II.1.1, Cor. II.1.1)
representation represent_on(algebra_ptr A, const coeffs& d) {
    A->check_size(d, "representation");
    // a product of signals (signals/product.h): its own functional, d need not generate
    if (const auto* T = dynamic_cast<const tensor_algebra*>(A.get())) {
        if (!algebra::equal(d, T->operator_d()))
            throw algebra_error("signals: on " + A->name() + " the operator is d_A (x) 1 + 1 (x) d_B, "
                                "the one of the product representation");
        representation R;
        R.A = A;
        R.d = d;
        R.p = A->minpoly(d, R.X);
        R.lambda = T->functional();
        return R;
    }
    representation R;
    R.A = A;
    R.d = d;
    R.p = A->minpoly(d, R.X);
    const int deg = R.p.degree(R.X);
    if (deg != int(A->dim()))
        throw algebra_error("signals: d does not generate " + A->name() + ": its minimal polynomial " +
                            polynomial_text(R.p, R.X) + " has degree " + std::to_string(deg) + " < " +
                            std::to_string(A->dim()) +
                            ", so the signals it represents satisfy an equation of that lower order "
                            "(Cor. II.1.1) and Psi is not one-to-one");
    // on P_n the coordinate of v^(n-1) whatever d is (the algebra's own nondegenerate form):
    // then Psi^-1 with d and with exp(h d) share lambda, and the samples of Psi^-1(w) are
    // the sequence of the same w with the shift exp(h d) (Thm II.3.4)
    if (dynamic_cast<const polynomial_algebra*>(A.get())) {
        R.lambda = coeffs(A->dim(), GiNaC::ex(0));
        R.lambda.back() = 1;
    } else if (const auto* S = dynamic_cast<const sobrero*>(A.get())) {
        // (IV.1.2.17-18, corrected) Re of the coordinate of eps^n: (x, y) -> Re[x y]_n is
        // nondegenerate (the lowest coefficient of x against conj of it times eps^(n-k))
        R.lambda = coeffs(A->dim(), GiNaC::ex(0));
        R.lambda[S->n()] = 1;
    } else if (dynamic_cast<const multicomplex*>(A.get())) {
        // (IV.1.16, corrected) the coordinate of 1: scal(x y) is nondegenerate (e_m^2 = +-1)
        R.lambda = coeffs(A->dim(), GiNaC::ex(0));
        R.lambda[0] = 1;
    } else {
        R.lambda = power_basis_functional(*A, d);
    }
    return R;
}

representation polynomial_representation(const ex& p, const GiNaC::symbol& X) {
    const auto P = polynomial_algebra::make(p, X);
    representation R;
    R.A = P;
    R.d = P->generator();
    R.p = p.subs(X == R.X);
    R.lambda = coeffs(P->dim(), ex(0));
    R.lambda.back() = 1;  // the power basis is the basis: lambda = the coordinate of v^(n-1)
    return R;
}

// Psi^-1(w) = lambda(w exp(d t))
ex signal_of(const representation& R, const coeffs& w, const ex& t) {
    R.A->check_size(w, "signal");
    coeffs e;
    const auto* M = dynamic_cast<const multicomplex*>(R.A.get());
    const auto c = M ? carriers_of(*M, R.d) : std::nullopt;
    if (c)
        e = exp_product_form(*M, *c, t);  // (IV.1.15) products of the carriers' cosines and sines
    else
        e = R.A->exp(R.d, t);
    // lambda(w e) = sum_k e_k lambda(w b_k): w times the basis (numbers) instead of w times exp(d t)
    // (coordinates that are functions of t: the product's reduction expanded them)
    ex s = 0;
    for (std::size_t k = 0; k < e.size(); ++k)
        if (!e[k].is_zero()) s += e[k] * functional(R.lambda, R.A->multiply(w, R.A->basis_vector(k)));
    return tidy(s);
}

namespace {

// f in the solution space: the residual p(op) f (op = D or the shift E) proved 0, else refused
// with the residual seen nonzero, or as undecided (never taken as 0).
void require_solution(const representation& R, const ex& f, const ex& residual, const char* op) {
    if (is_zero_scalar(residual)) return;
    const zero_decision z = decide_zero(residual);
    if (z.is_zero == truth::no)
        throw domain_error("signals: " + message_text(f, text_limit::signal_report) + " is not a solution of p(" + op +
                           ") f = 0 for p = " + polynomial_text(R.p, R.X) + " (p(" + op +
                           ") f = " + message_text(residual, text_limit::signal_report) + ", not 0 " + witness_text(z) +
                           "), so it is not represented on " + R.A->name());
    if (z.is_zero == truth::unknown)
        throw domain_error("signals: cannot decide whether " + message_text(f, text_limit::signal_report) +
                           " solves p(" + op + ") f = 0 for p = " + polynomial_text(R.p, R.X) + " (p(" + op +
                           ") f = " + message_text(residual, text_limit::signal_report) +
                           " is neither proved 0 nor seen nonzero)");
}

// The element w with lambda(w d^j) = value[j], j < n (f^(j)(0) or f(j)).
coeffs element_with_values(const representation& R, const std::vector<ex>& value) {
    const std::size_t n = R.A->dim();
    std::vector<std::vector<ex>> M(n, std::vector<ex>(n));
    coeffs dj = R.A->unit();
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < n; ++i) M[j][i] = functional(R.lambda, R.A->multiply(R.A->basis_vector(i), dj));
        dj = R.A->multiply(dj, R.d);
    }
    const auto w = solve_linear(M, value);
    if (!w) throw algebra_error("signals: the form lambda(x y) is degenerate on " + R.A->name());
    coeffs out;
    for (const ex& x : *w) out.push_back(tidy(x));
    return out;
}

}  // namespace

// Psi(f): lambda(w d^k) = f^(k)(0), k < n, after p(D) f = 0 is proved.
coeffs element_of(const representation& R, const ex& f, const GiNaC::symbol& t) {
    const std::size_t n = R.A->dim();
    std::vector<ex> derivative{f};
    for (std::size_t k = 1; k <= n; ++k) derivative.push_back(derivative.back().diff(t));
    ex residual = 0;
    const ex p = GiNaC::expand(R.p);
    for (std::size_t k = 0; k <= n; ++k) residual += p.coeff(R.X, int(k)) * derivative[k];
    require_solution(R, f, tidy(residual), "D");
    std::vector<ex> at0;
    for (std::size_t k = 0; k < n; ++k) at0.push_back(tidy(derivative[k].subs(t == 0)));
    return element_with_values(R, at0);
}

namespace {

// f with cos, sin, cosh, sinh written as exponentials.
ex exponential_form(const ex& f) {
    struct rewrite : GiNaC::map_function {
        ex operator()(const ex& x) override {
            const ex y = x.map(*this);
            if (GiNaC::is_a<GiNaC::function>(y)) {
                const std::string name = GiNaC::ex_to<GiNaC::function>(y).get_name();
                const ex u = y.op(0);
                if (name == "cos") return (GiNaC::exp(GiNaC::I * u) + GiNaC::exp(-GiNaC::I * u)) / 2;
                if (name == "sin") return (GiNaC::exp(GiNaC::I * u) - GiNaC::exp(-GiNaC::I * u)) / (2 * GiNaC::I);
                if (name == "cosh") return (GiNaC::exp(u) + GiNaC::exp(-u)) / 2;
                if (name == "sinh") return (GiNaC::exp(u) - GiNaC::exp(-u)) / 2;
            }
            return y;
        }
    } r;
    return r(f);
}

bool is_exp(const ex& x) {
    return GiNaC::is_a<GiNaC::function>(x) && GiNaC::ex_to<GiNaC::function>(x).get_name() == "exp";
}

[[noreturn]] void not_quasi_polynomial(const ex& f, const ex& part, const GiNaC::symbol& t) {
    throw domain_error("signals: " + message_text(f, text_limit::signal_report) + " is not a quasi-polynomial in " +
                       t.get_name() + ": its part " + message_text(part, text_limit::signal_report) + " is not c " +
                       t.get_name() + "^k exp(a " + t.get_name() + ") cos(b " + t.get_name() + ") / sin(b " +
                       t.get_name() + ") with a, b, c free of " + t.get_name());
}

// One term c t^k e^(lambda t) of the expanded exponential form: (c, k, lambda).
struct monomial {
    ex c;
    unsigned k;
    ex lambda;
};

monomial read_term(const ex& f, const ex& term, const GiNaC::symbol& t) {
    monomial m{1, 0, 0};
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++i) {
        const ex x = GiNaC::is_a<GiNaC::mul>(term) ? term.op(i) : term;
        if (!x.has(t)) {
            m.c *= x;
        } else if (x.is_equal(t)) {
            m.k += 1;
        } else if (GiNaC::is_a<GiNaC::power>(x) && x.op(0).is_equal(t) && x.op(1).info(GiNaC::info_flags::posint)) {
            m.k += GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_int();
        } else if (is_exp(x) || (GiNaC::is_a<GiNaC::power>(x) && is_exp(x.op(0)) &&
                                 x.op(1).info(GiNaC::info_flags::integer))) {
            const ex u = GiNaC::expand(is_exp(x) ? x.op(0) : x.op(0).op(0) * x.op(1));
            if (!u.is_polynomial(t) || u.degree(t) > 1) not_quasi_polynomial(f, x, t);
            const ex a = u.coeff(t, 1), rest = u.coeff(t, 0);
            if (a.has(t) || rest.has(t)) not_quasi_polynomial(f, x, t);
            m.lambda += a;
            m.c *= GiNaC::exp(rest);
        } else {
            not_quasi_polynomial(f, x, t);
        }
    }
    return m;
}

// (re, im) of an expression whose symbols are real: the numeric factors split.
std::pair<ex, ex> real_imag(const ex& z) {
    const ex e = GiNaC::expand(z);
    ex re = 0, im = 0;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        const auto [n, rest] = split_numeric_factor(term);
        re += n.real() * rest;
        im += n.imag() * rest;
    }
    return {re, im};
}

}  // namespace

std::vector<exponent> exponents_of(const ex& f, const GiNaC::symbol& t) {
    const ex e = GiNaC::expand(exponential_form(f));
    // (lambda, k) -> coefficient, lambdas compared exactly
    std::vector<std::pair<ex, std::map<unsigned, ex>>> by_lambda;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const monomial m = read_term(f, GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e, t);
        const ex lambda = tidy(m.lambda);
        auto it = by_lambda.begin();
        for (; it != by_lambda.end(); ++it)
            if (is_zero_scalar(tidy(it->first - lambda))) break;
        if (it == by_lambda.end()) {
            by_lambda.push_back({lambda, {}});
            it = by_lambda.end() - 1;
        }
        it->second[m.k] += m.c;
    }
    std::vector<exponent> out;
    for (const auto& [lambda, powers] : by_lambda) {
        unsigned top = 0;
        bool any = false;
        for (const auto& [k, c] : powers)
            if (!is_zero_scalar(tidy(c))) {  // not proved 0: kept (an annihilator, maybe not the least)
                top = k;
                any = true;
            }
        if (any) out.push_back({lambda, top + 1});
    }
    return out;
}

// ((X - a)^2 + b^2)^m for each conjugate pair, (X - a)^m for a real lambda.
ex annihilator(const ex& f, const GiNaC::symbol& t, const GiNaC::symbol& X) {
    const std::vector<exponent> es = exponents_of(f, t);
    if (es.empty())
        throw domain_error("signals: the signal is 0, which every algebra represents by 0; no least "
                           "equation of positive order");
    std::vector<bool> used(es.size(), false);
    ex q = 1;
    for (std::size_t i = 0; i < es.size(); ++i) {
        if (used[i]) continue;
        used[i] = true;
        const auto [a, b] = real_imag(es[i].lambda);
        unsigned m = es[i].multiplicity;
        if (is_zero_scalar(tidy(b))) {
            q *= GiNaC::pow(X - a, m);
            continue;
        }
        for (std::size_t j = i + 1; j < es.size(); ++j) {  // the conjugate a - I b
            if (used[j]) continue;
            if (is_zero_scalar(tidy(es[j].lambda - (a - GiNaC::I * b)))) {
                used[j] = true;
                m = std::max(m, es[j].multiplicity);
            }
        }
        q *= GiNaC::pow(GiNaC::pow(X - a, 2) + GiNaC::pow(b, 2), m);
    }
    return GiNaC::expand(q);
}

std::vector<ex> sequence_of(const representation& R, const coeffs& w, long first, std::size_t count) {
    R.A->check_size(w, "sequence");
    coeffs step = R.d;
    long start = first;
    if (first < 0) step = R.A->inverse(R.d);  // zero_divisor_error when d is not invertible
    coeffs at = R.A->power(step, static_cast<unsigned long>(first < 0 ? -first : first));
    std::vector<ex> out;
    for (std::size_t i = 0; i < count; ++i) {
        out.push_back(tidy(functional(R.lambda, R.A->multiply(w, at))));
        ++start;
        at = start <= 0 ? R.A->power(step, static_cast<unsigned long>(-start)) : R.A->multiply(at, R.d);
        if (start == 0) at = R.A->unit();
    }
    return out;
}

// d^k: z^k and its derivatives k (k-1) ... (k-j+1) z^(k-j) on the roots (as exp).
coeffs power(const representation& R, const ex& k) {
    scalar_function f;
    f.name = "power";
    f.value = [k](const ex& re, const ex& im, unsigned j, ex& out_re, ex& out_im) {
        ex falling = 1;
        for (unsigned i = 0; i < j; ++i) falling *= (k - i);
        if (im.is_zero()) {
            if (re.is_zero()) throw domain_error("d^k for a symbolic k: d has the root 0 (d is a zero divisor)");
            out_re = tidy(falling * GiNaC::pow(re, k - j));
            out_im = 0;
            return;
        }
        // (re + i im)^(k - j) = rho^(k-j) (cos((k-j) theta) + i sin((k-j) theta))
        // |rho|^2 with sin(u)^2 = 1 - cos(u)^2: the ratio e^(i c) of cos(c k) has modulus 1
        const ex rho = GiNaC::sqrt(tidy(sines_squared_as_cosines(re * re + im * im))), theta = atan2_exact(im, re);
        out_re = falling * GiNaC::pow(rho, k - j) * GiNaC::cos((k - j) * theta);
        out_im = falling * GiNaC::pow(rho, k - j) * GiNaC::sin((k - j) * theta);
    };
    return R.A->apply_function(R.d, f);
}

ex sequence_formula(const representation& R, const coeffs& w, const GiNaC::symbol& k) {
    R.A->check_size(w, "sequence");
    return tidy(functional(R.lambda, R.A->multiply(w, power(R, k))));
}

namespace {

// One term of a sequence: c k^j rho^k with rho = (re, im).
struct ratio_term {
    ex c;
    unsigned j;
    ex re, im;
};

[[noreturn]] void not_a_sequence(const ex& f, const ex& part, const GiNaC::symbol& k) {
    const std::string n = k.get_name();
    throw domain_error("signals: " + message_text(f, text_limit::signal_report) + " is not a sequence of the form c " +
                       n + "^j a^" + n + " exp(b " + n + ") cos(c " + n + ") / sin(c " + n + ") in " + n +
                       ": its part " + message_text(part, text_limit::signal_report) + " is not (a, b, c free of " + n +
                       ")");
}

// f as a sum of c k^j rho^k: cos and sin of c k split into the ratios e^(+-i c).
std::vector<ratio_term> ratio_terms(const ex& f, const GiNaC::symbol& k) {
    std::vector<ratio_term> terms;
    const ex e = GiNaC::expand(f);
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        std::vector<ratio_term> parts{{ex(1), 0, ex(1), ex(0)}};
        for (std::size_t n = 0; n < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++n) {
            const ex x = GiNaC::is_a<GiNaC::mul>(term) ? term.op(n) : term;
            auto times = [&](const ex& c, unsigned dj, const ex& re, const ex& im) {
                for (auto& u : parts) {
                    const ex r = u.re * re - u.im * im, m = u.re * im + u.im * re;
                    u = {u.c * c, u.j + dj, r, m};
                }
            };
            if (!x.has(k)) {
                times(x, 0, 1, 0);
            } else if (x.is_equal(k)) {
                times(1, 1, 1, 0);
            } else if (GiNaC::is_a<GiNaC::power>(x) && x.op(0).is_equal(k) &&
                       x.op(1).info(GiNaC::info_flags::posint)) {
                times(1, unsigned(GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_int()), 1, 0);
            } else if (GiNaC::is_a<GiNaC::power>(x) && !x.op(0).has(k)) {  // a^(c k + e)
                const ex u = GiNaC::expand(x.op(1));
                if (!u.is_polynomial(k) || u.degree(k) != 1) not_a_sequence(f, x, k);
                times(GiNaC::pow(x.op(0), u.coeff(k, 0)), 0, GiNaC::pow(x.op(0), u.coeff(k, 1)), 0);
            } else if (GiNaC::is_a<GiNaC::function>(x)) {
                const std::string name = GiNaC::ex_to<GiNaC::function>(x).get_name();
                const ex u = GiNaC::expand(x.op(0));
                if (!u.is_polynomial(k) || u.degree(k) != 1) not_a_sequence(f, x, k);
                const ex b = u.coeff(k, 1), rest = u.coeff(k, 0);
                if (name == "exp") {
                    times(GiNaC::exp(rest), 0, GiNaC::exp(b), 0);
                } else if (name == "cos" || name == "sin") {
                    // cos(b k + r) = (e^(i r) e^(i b k) + e^(-i r) e^(-i b k))/2, sin likewise / i
                    std::vector<ratio_term> split;
                    for (const auto& p0 : parts) {
                        for (int sg : {1, -1}) {
                            ratio_term q = p0;
                            const ex cr = GiNaC::cos(rest), sr = GiNaC::sin(rest) * sg;
                            // c * (cos r + i sg sin r)/2 (cos) or /(2 i sg)... kept as a complex coefficient:
                            // c' = c * e^(i sg r) / 2 for cos, c * e^(i sg r) / (2 i sg) for sin
                            const ex coef = (cr + GiNaC::I * sr) / 2 / (name == "cos" ? ex(1) : GiNaC::I * sg);
                            const ex r = q.re * GiNaC::cos(b) - q.im * sg * GiNaC::sin(b);
                            const ex m = q.re * sg * GiNaC::sin(b) + q.im * GiNaC::cos(b);
                            q = {q.c * coef, q.j, r, m};
                            split.push_back(q);
                        }
                    }
                    parts = split;
                } else {
                    not_a_sequence(f, x, k);
                }
            } else {
                not_a_sequence(f, x, k);
            }
        }
        for (auto& u : parts) terms.push_back({u.c, u.j, tidy(u.re), tidy(u.im)});
    }
    return terms;
}

}  // namespace

ex sequence_annihilator(const ex& f, const GiNaC::symbol& k, const GiNaC::symbol& X) {
    const std::vector<ratio_term> terms = ratio_terms(f, k);
    // (re, im) -> (j -> coefficient)
    std::vector<std::pair<std::pair<ex, ex>, std::map<unsigned, ex>>> by;
    for (const auto& u : terms) {
        auto it = by.begin();
        for (; it != by.end(); ++it)
            if (is_zero_scalar(tidy(it->first.first - u.re)) && is_zero_scalar(tidy(it->first.second - u.im))) break;
        if (it == by.end()) {
            by.push_back({{u.re, u.im}, {}});
            it = by.end() - 1;
        }
        it->second[u.j] += u.c;
    }
    struct mode {
        ex re, im;
        unsigned m;
    };
    std::vector<mode> modes;
    for (const auto& [rho, powers] : by) {
        unsigned top = 0;
        bool any = false;
        for (const auto& [j, c] : powers)
            if (!is_zero_scalar(tidy(c))) {
                top = j;
                any = true;
            }
        if (!any) continue;
        if (is_zero_scalar(rho.first) && is_zero_scalar(rho.second))
            throw domain_error("signals: " + message_text(f, text_limit::signal_report) +
                               " has a part with ratio 0 (0^k), not a solution of a "
                               "difference equation for every k");
        modes.push_back({rho.first, rho.second, top + 1});
    }
    if (modes.empty())
        throw domain_error("signals: the sequence is 0, which every algebra represents by 0; no least "
                           "equation of positive order");
    // pairs merged as in annihilator(), but on the ratios' parts (re, im) as read from the
    // sequence, with the quadratic factor X^2 - 2 re X + |rho|^2 in its expanded form
    std::vector<bool> used(modes.size(), false);
    ex q = 1;
    for (std::size_t i = 0; i < modes.size(); ++i) {
        if (used[i]) continue;
        used[i] = true;
        unsigned m = modes[i].m;
        if (is_zero_scalar(tidy(modes[i].im))) {
            q *= GiNaC::pow(X - modes[i].re, m);
            continue;
        }
        for (std::size_t j = i + 1; j < modes.size(); ++j)
            if (!used[j] && is_zero_scalar(tidy(modes[j].re - modes[i].re)) &&
                is_zero_scalar(tidy(modes[j].im + modes[i].im))) {
                used[j] = true;
                m = std::max(m, modes[j].m);
            }
        q *= GiNaC::pow(X * X - 2 * modes[i].re * X + tidy(modes[i].re * modes[i].re + modes[i].im * modes[i].im), m);
    }
    return GiNaC::expand(q);
}

coeffs sequence_element(const representation& R, const ex& f, const GiNaC::symbol& k) {
    const std::size_t n = R.A->dim();
    ex residual = 0;
    const ex p = GiNaC::expand(R.p);
    for (std::size_t i = 0; i <= n; ++i) residual += p.coeff(R.X, int(i)) * f.subs(k == k + int(i));
    require_solution(R, f, tidy(GiNaC::expand(residual)), "E");
    std::vector<ex> values;
    for (std::size_t j = 0; j < n; ++j) values.push_back(tidy(f.subs(k == int(j))));
    return element_with_values(R, values);
}

namespace {

std::vector<ex> symbols_in(const ex& x) {
    std::vector<ex> out;
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) out.push_back(*it);
    return out;
}

// x at 40 digits (false when that is not a number); rounding in the imaginary part of a
// real constant dropped.
bool numeric_value(const ex& x, GiNaC::numeric& out) {
    if (!evaluate_numeric(x, 40, out)) return false;
    if (!out.is_real() && GiNaC::abs(out.imag()) < GiNaC::numeric(1, 1000000000) * GiNaC::abs(out))
        out = out.real();
    return true;
}

// The roots of p in radicals (scalar/polynomial_roots.h: rational factors of degree 1, 2 and
// 3), a complex pair as its two roots; false when a factor has roots not found (degree > 3,
// or a discriminant of undecided sign).
bool known_roots(const ex& p, const GiNaC::symbol& X, std::vector<ex>& roots) {
    bool all = true;
    for (const auto& f : rational_factors(p, X)) {
        std::vector<polynomial_root> rs;
        try {
            rs = factor_roots(f.f, X, 1, "sampling");
        } catch (const closed_form_error&) {
            all = false;
            continue;
        }
        for (const auto& r : rs) {
            if (r.im.is_zero()) {
                roots.push_back(r.re);
            } else {
                roots.push_back(tidy(r.re + GiNaC::I * r.im));
                roots.push_back(tidy(r.re - GiNaC::I * r.im));
            }
        }
    }
    return all;
}

// (Cor. II.3.5) q(l) = det(l I - exp(h [d])) from the roots of p: the eigenvalues of
// exp(h d) are e^(h r), r the roots of p with their multiplicities, so a real root r of
// multiplicity m gives (l - e^(h r))^m, a pair alpha +- i beta gives
// (l^2 - 2 e^(h alpha) cos(h beta) l + e^(2 h alpha))^m and the two real roots alpha +- gamma
// of a quadratic factor (l^2 - 2 e^(h alpha) cosh(h gamma) l + e^(2 h alpha))^m. False (q not
// formed) when p has a factor whose roots are not found: the caller then expands the
// determinant.
bool shift_charpoly(const ex& p, const GiNaC::symbol& X, const ex& h, const GiNaC::symbol& l, ex& q) {
    q = 1;
    for (const auto& f : rational_factors(p, X)) {
        std::vector<polynomial_root> rs;
        try {
            rs = factor_roots(f.f, X, f.multiplicity, "sampling");
        } catch (const closed_form_error&) {
            return false;
        }
        const ex m = rs.front().multiplicity;
        if (rs.size() == 2 && f.f.degree(X) == 2 && rs[0].im.is_zero() && rs[1].im.is_zero()) {
            const ex alpha = tidy((rs[0].re + rs[1].re) / 2), gamma = tidy((rs[0].re - rs[1].re) / 2);
            q *= GiNaC::pow(l * l - 2 * GiNaC::exp(tidy(h * alpha)) * GiNaC::cosh(tidy(h * gamma)) * l +
                                GiNaC::exp(tidy(2 * h * alpha)),
                            m);
            continue;
        }
        for (const auto& r : rs) {
            if (r.im.is_zero())
                q *= GiNaC::pow(l - GiNaC::exp(tidy(h * r.re)), r.multiplicity);
            else
                q *= GiNaC::pow(l * l - 2 * GiNaC::exp(tidy(h * r.re)) * GiNaC::cos(tidy(h * r.im)) * l +
                                    GiNaC::exp(tidy(2 * h * r.re)),
                                r.multiplicity);
        }
    }
    q = tidy(q.expand());
    return true;
}

}  // namespace

namespace {
// z as "u/pi" when z pi is free of pi (GiNaC would print 2*Pi^(-1)*h).
std::string over_pi(const ex& z) {
    const ex u = tidy(z * GiNaC::Pi);
    if (u.has(GiNaC::Pi)) return message_text(z, text_limit::signal_report);
    const std::string s = message_text(u, text_limit::signal_report);
    return (GiNaC::is_a<GiNaC::add>(u) ? "(" + s + ")" : s) + "/pi";
}
}  // namespace

// (Thm II.3.4, II.3.26, Cor. II.3.5)
sampling sample(const representation& R, const ex& h, const GiNaC::symbol& l) {
    if (is_zero_scalar(h)) throw domain_error("sampling: the step h is 0");
    // a rational factor without roots in radicals: the numeric form (exp(h d) has no closed form)
    for (const auto& f : rational_factors(R.p, R.X))
        if (f.f.degree(R.X) > 3)
            return sample_numerically(R, h, l,
                                      "p has the irreducible factor " + polynomial_text(f.f, R.X) + " of degree " +
                                          std::to_string(f.f.degree(R.X)) + ", whose roots have no closed form");
    sampling s;
    s.shift = R.A->exp(R.d, h);
    for (auto& x : s.shift) x = tidy(x);
    if (!shift_charpoly(R.p, R.X, h, l, s.q)) s.q = R.A->charpoly(s.shift, l);
    std::vector<ex> r;
    const bool all = known_roots(R.p, R.X, r);
    // h (r - s) / (2 pi i) for each pair of distinct roots: a nonzero integer is aliasing
    std::vector<std::string> met, conditions;
    bool undecided = false;
    for (std::size_t i = 0; i < r.size(); ++i)
        for (std::size_t j = i + 1; j < r.size(); ++j) {
            if (is_zero_scalar(tidy(r[i] - r[j]))) continue;  // a repeated root
            const ex z = tidy(h * (r[i] - r[j]) / (2 * GiNaC::Pi * GiNaC::I));
            const std::string pair =
                message_text(r[i], text_limit::signal_report) + " and " + message_text(r[j], text_limit::signal_report);
            if (GiNaC::is_a<GiNaC::numeric>(z)) {
                if (GiNaC::ex_to<GiNaC::numeric>(z).is_integer()) met.push_back(pair);
            } else if (symbols_in(z).empty()) {  // a constant: the nearest integer, then exactly
                GiNaC::numeric v;
                if (!numeric_value(z, v)) {
                    undecided = true;
                    continue;
                }
                if (!v.is_real()) continue;  // a real part: |e^(h r)| != |e^(h s)|
                const double vd = v.to_double();
                if (!(std::abs(vd) < 1e12)) {
                    undecided = true;
                    continue;
                }
                const GiNaC::numeric m(static_cast<long>(std::llround(vd)));  // the nearest integer
                if (GiNaC::abs(v - m) > GiNaC::numeric(1, 1000000)) continue;  // not an integer
                if (!m.is_zero() && is_zero_scalar(tidy(z - m))) met.push_back(pair);
                else undecided = true;
            } else if (!z.has(GiNaC::I) && !h.info(GiNaC::info_flags::numeric)) {
                conditions.push_back(pair + " when " + over_pi(z) + " is a nonzero integer");
            } else if (!z.info(GiNaC::info_flags::numeric)) {
                // a numeric step with a symbolic difference of roots: decided only where the
                // real part of h (r - s) is seen nonzero
                const auto [re, im] = real_imag(z);
                const zero_decision d = decide_zero(tidy(im));
                if (d.is_zero == truth::no) continue;  // |e^(h r)| != |e^(h s)|
                if (d.is_zero == truth::unknown) undecided = true;
                else conditions.push_back(pair + " when " + over_pi(re) + " is a nonzero integer");
            }
        }
    std::ostringstream os;
    const int n = int(R.A->dim());
    if (!met.empty()) {
        s.aliasing = truth::yes;
        os << "aliasing at step " << message_text(h, text_limit::signal_report) << ": the roots ";
        for (std::size_t i = 0; i < met.size(); ++i) os << (i ? "; " : "") << met[i];
        os << " of p sample to the same e^(h r), so the samples span fewer than "
           << n << " dimensions";
    } else if (!all || undecided) {
        s.aliasing = truth::unknown;
        os << "aliasing at step " << message_text(h, text_limit::signal_report) << " not decided: "
           << (!all
                   ? "p has a rational factor whose roots are not found (degree > 3, or a discriminant of unknown sign)"
                   : "whether two roots sample to the same e^(h r) is neither proved nor disproved");
    } else if (!conditions.empty()) {
        s.aliasing = truth::no;
        os << "no aliasing for a generic step " << message_text(h, text_limit::signal_report)
           << "; aliasing exactly for the roots ";
        for (std::size_t i = 0; i < conditions.size(); ++i) os << (i ? "; " : "") << conditions[i];
    } else {
        s.aliasing = truth::no;
        os << "no aliasing at step " << message_text(h, text_limit::signal_report) << ": the " << n
           << " dimensions of the solution space stay " << n << " in the samples";
    }
    s.report = os.str();
    return s;
}

}  // namespace symrep::signals
