// symrep/transforms/laplace.cpp -- see laplace.h.
#include "symrep/transforms/laplace.h"

#include <algorithm>
#include <sstream>

#include "symrep/algebra/polynomial_algebra.h"
#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/polynomial_roots.h"
#include "symrep/scalar/scalar.h"
#include "symrep/signals/representation.h"

namespace symrep::transforms {

using GiNaC::ex;

namespace {

// (f causal quasi-polynomial) Lf(s) = q(s)/p(s) from f = Psi^-1(w) on P_p, not checked
ex laplace_raw(const ex& f, const GiNaC::symbol& t, const ex& s) {
    if (f.is_zero()) return 0;
    const GiNaC::symbol X("X");
    const ex p = signals::annihilator(f, t, X);
    const auto R = signals::polynomial_representation(p, X);
    const coeffs w = signals::element_of(R, f, t);
    ex q = 0;
    for (std::size_t j = 0; j < w.size(); ++j) q += w[j] * GiNaC::pow(s, j);
    // lowest terms, the denominator factored over the rationals ((s + 3)^3, not its expansion)
    const ex nd = GiNaC::normal(q / p.subs(X == s)).numer_denom();
    return nd.op(0) / GiNaC::factor(nd.op(1));
}

struct rational {
    ex q, p;  ///< p monic in s, deg q < deg p
};

rational proper_rational(const ex& F, const GiNaC::symbol& s, const GiNaC::symbol& t) {
    if (F.has(t))
        throw domain_error("inverse_laplace: F contains " + message_text(t, text_limit::report) +
                           "; it must be a function of " + message_text(s, text_limit::report));
    const ex nd = GiNaC::normal(F).numer_denom();
    const ex num = nd.op(0).expand(), den = nd.op(1).expand();
    if (!num.is_polynomial(s) || !den.is_polynomial(s))
        throw domain_error("inverse_laplace: F is not a rational function of " + message_text(s, text_limit::report) +
                           " (only those are transforms of quasi-polynomials)");
    if (den.degree(s) < 1 || num.degree(s) >= den.degree(s))
        throw domain_error("inverse_laplace: F is not proper (numerator of degree " +
                           std::to_string(num.degree(s)) + ", denominator of degree " +
                           std::to_string(den.degree(s)) +
                           "): its polynomial part is the transform of derivatives of the Dirac delta, not of a signal");
    const ex lc = den.lcoeff(s);
    return {tidy((num / lc).expand()), tidy((den / lc).expand())};
}

// Psi^-1(q(v)) on P_p, not checked
ex inverse_raw(const rational& r, const GiNaC::symbol& s, const GiNaC::symbol& t) {
    const GiNaC::symbol X("X");
    const ex p = r.p.subs(s == X);
    const auto R = signals::polynomial_representation(p, X);
    coeffs w(R.A->dim(), ex(0));
    for (std::size_t j = 0; j < w.size(); ++j) w[j] = r.q.coeff(s, int(j));
    return signals::signal_of(R, w, t);
}

void require_same(const ex& a, const ex& b, const std::string& what) {
    const ex diff = tidy((a - b).expand());
    if (is_zero_scalar(diff)) return;
    const zero_decision z = decide_zero(diff);
    if (z.is_zero == truth::yes) return;
    throw algebra_error(what + ": the check by the inverse transform failed (" +
                        message_text(diff, text_limit::report) +
                        (z.is_zero == truth::no ? " is not 0)" : " is not proved 0)"));
}

ex real_part_of(const ex& x) { return tidy(GiNaC::real_part(x.expand())); }

// x at `digits` digits with each symbol but t at a fixed rational in [1.1, 2.9] (by its name).
bool value_at(const ex& x, const GiNaC::symbol& t, long digits, GiNaC::numeric& out) {
    const GiNaC::exmap point = generic_point(x, t);
    return evaluate_numeric(point.empty() ? x : x.subs(point, GiNaC::subs_options::no_pattern), digits, out);
}

// The check of an inverse whose exponents are Cardano's radicals (a cubic factor of p), where
// laplace(f) would have to simplify nested cube roots: f is the transform's inverse iff
// p(D) f = 0 and f^(k)(0) = c_k for k < n, c_k the coefficients of F = sum_k c_k s^-(k+1)
// (c_k = q_(n-1-k) - sum_(i=1..k) p_(n-i) c_(k-i), p monic). Both are checked at 50 digits:
// the initial values exactly known, the residual p(D) f at t = 1/3 and t = 1 (symbols at a
// fixed rational point), each to 10^-30 relative to its size.
void require_same_numerically(const rational& r, const ex& f, const GiNaC::symbol& s, const GiNaC::symbol& t) {
    const int n = r.p.degree(s);
    std::vector<ex> c;
    for (int k = 0; k < n; ++k) {
        ex ck = r.q.coeff(s, n - 1 - k);
        for (int i = 1; i <= k; ++i) ck -= r.p.coeff(s, n - i) * c[std::size_t(k - i)];
        c.push_back(tidy(ck));
    }
    // f with its constants at 60 digits (t kept): the derivatives of the short numeric form,
    // not of the radicals
    ex fN;
    {
        const GiNaC::exmap point = generic_point(f, t);  // as value_at
        const long saved = GiNaC::Digits;
        GiNaC::Digits = 60;
        try {
            fN = GiNaC::evalf(point.empty() ? f : f.subs(point, GiNaC::subs_options::no_pattern));
        } catch (...) {
            GiNaC::Digits = saved;
            throw;
        }
        GiNaC::Digits = saved;
    }
    std::vector<ex> D{fN};
    for (int k = 1; k <= n; ++k) D.push_back(GiNaC::diff(D.back(), t));
    const GiNaC::numeric tol("1e-30");
    const auto fail = [&](const std::string& what) {
        throw algebra_error("inverse_laplace: the numeric check (50 digits) of the inverse " +
                            message_text(f, text_limit::report) + " failed: " + what);
    };
    for (int k = 0; k < n; ++k) {
        GiNaC::numeric v, want;
        if (!value_at(D[std::size_t(k)].subs(t == 0), t, 50, v) || !value_at(c[std::size_t(k)], t, 50, want))
            fail("f^(" + std::to_string(k) + ")(0) is not a number");
        if (GiNaC::abs(v - want) > tol * std::max(GiNaC::numeric(1), GiNaC::abs(want)))
            fail("f^(" + std::to_string(k) + ")(0) is not " + message_text(c[std::size_t(k)], text_limit::report));
    }
    for (const GiNaC::numeric& t0 : {GiNaC::numeric(1, 3), GiNaC::numeric(1)}) {
        GiNaC::numeric residual = 0, size = 1;
        for (int k = 0; k <= n; ++k) {
            GiNaC::numeric pk, dk;
            if (!value_at(r.p.coeff(s, k), t, 50, pk) || !value_at(D[std::size_t(k)].subs(t == t0), t, 50, dk))
                fail("p(D) f is not a number at t = " + message_text(t0, text_limit::report));
            residual += pk * dk;
            size += GiNaC::abs(pk * dk);
        }
        if (GiNaC::abs(residual) > tol * size) fail("p(D) f is not 0 at t = " + message_text(t0, text_limit::report));
    }
}

}  // namespace

ex laplace(const ex& f, const GiNaC::symbol& t, const ex& s) {
    const ex F = laplace_raw(f, t, s);
    if (F.is_zero()) return F;
    if (GiNaC::is_a<GiNaC::symbol>(s)) {
        const GiNaC::symbol& ss = GiNaC::ex_to<GiNaC::symbol>(s);
        require_same(inverse_raw(proper_rational(F, ss, t), ss, t), f, "laplace");
    }
    return F;
}

ex inverse_laplace(const ex& F, const GiNaC::symbol& s, const GiNaC::symbol& t) {
    if (F.is_zero()) return 0;
    const rational r = proper_rational(F, s, t);
    // the roots of p in radicals: rational factors of degree <= 3 (scalar/polynomial_roots.h);
    // a factor of higher degree is refused before anything is formed
    bool cubic = false;
    for (const auto& g : rational_factors(r.p, s)) {
        const int d = g.f.degree(s);
        if (d > 3)
            throw closed_form_error("inverse_laplace: the denominator has the irreducible factor " +
                                    signals::polynomial_text(g.f, s) +
                                    " of degree " + std::to_string(d) +
                                    " over the rationals; its roots have no closed form here (only factors of "
                                    "degree 1, 2 and 3 are solved: Cardano for 3)");
        if (d == 3 && g.multiplicity > 1)
            throw closed_form_error("inverse_laplace: the denominator has the cubic factor " +
                                    signals::polynomial_text(g.f, s) + " repeated (multiplicity " +
                                    std::to_string(g.multiplicity) +
                                    "); Cardano's roots are used for simple cubic factors only");
        cubic = cubic || d == 3;
    }
    const ex f = inverse_raw(r, s, t);
    if (cubic) require_same_numerically(r, f, s, t);
    else require_same(laplace_raw(f, t, s), F, "inverse_laplace");
    return f;
}

namespace {

// int_0^oo g(t) dt = L[g](0) for a quasi-polynomial g = f1 f2 (`what` names the function and
// `name` the integrand in the messages): each exponent's real part shown negative, else divergent
// or undecided (said, never assumed); the first offender by printed form, so the message does not
// depend on GiNaC's term order
ex integral_of_product(const ex& g, const GiNaC::symbol& t, const std::string& what, const std::string& name) {
    const ex f2 = tidy(GiNaC::expand(g));
    if (f2.is_zero()) return 0;
    std::string bad, undecided;
    for (const auto& e : signals::exponents_of(f2, t)) {
        const ex re = real_part_of(e.lambda);
        GiNaC::numeric v;
        const bool constant = GiNaC::is_a<GiNaC::numeric>(re.evalf());
        const bool known = constant && evaluate_numeric(re, 40, v) && v.is_real();
        if (re.info(GiNaC::info_flags::negative) || (known && v < 0 && !is_zero_scalar(re))) continue;
        const std::string x = message_text(e.lambda, text_limit::report);
        std::string& slot = (is_zero_scalar(re) || (known && v > 0)) ? bad : undecided;
        if (slot.empty() || x < slot) slot = x;
    }
    if (!bad.empty())
        throw domain_error(what + ": the integral of " + name + " diverges (" + name + " has the exponent " + bad +
                           ", whose real part is not negative)");
    if (!undecided.empty())
        throw domain_error(what + ": cannot decide whether the integral of " + name + " converges: the exponent " +
                           undecided + " of " + name +
                           " is not shown to have a negative real part (declare the parameters positive)");
    const GiNaC::symbol s("s");
    return tidy(laplace_raw(f2, t, s).subs(s == 0));
}

}  // namespace

ex energy(const ex& f, const GiNaC::symbol& t) { return integral_of_product(f * f, t, "energy", "f^2"); }

ex inner_product(const ex& f1, const ex& f2, const GiNaC::symbol& t) {
    return integral_of_product(f1 * f2, t, "inner_product", "f*g");
}

algebra_transform transform(const algebra_ptr& A, const coeffs& d, const ex& f, const GiNaC::symbol& t) {
    A->check_size(d, "transform");
    algebra_transform out;
    if (f.is_zero()) {
        out.value = coeffs(A->dim(), ex(0));
        out.converges = truth::yes;
        out.report = "the transform of 0 is 0";
        return out;
    }
    const GiNaC::symbol X("X");
    const ex p = signals::annihilator(f, t, X);
    const auto R = signals::polynomial_representation(p, X);
    const coeffs w = signals::element_of(R, f, t);
    // q(d) p(d)^-1
    coeffs qd(A->dim(), ex(0)), pd(A->dim(), ex(0)), dj = A->unit();
    const int n = p.degree(X);
    for (int j = 0; j <= n; ++j) {
        if (j < int(w.size())) qd = A->add(qd, A->scale(w[std::size_t(j)], dj));
        pd = A->add(pd, A->scale(p.coeff(X, j), dj));
        if (j < n) dj = A->multiply(dj, d);
    }
    coeffs inv;
    try {
        inv = A->inverse(pd);
    } catch (const zero_divisor_error&) {
        throw domain_error("transform: p(d) = 0 on some idempotent component, for p = " +
                           signals::polynomial_text(p, X) +
                           " the least equation of the signal: an eigenvalue of d is an exponent of the signal, "
                           "where its transform has a pole");
    }
    out.value = A->multiply(qd, inv);
    for (ex& x : out.value) x = tidy(x);
    const algebra_transform c = convergence_of(A, d, f, t);
    out.converges = c.converges;
    out.report = c.report;
    return out;
}

algebra_transform convergence_of(const algebra_ptr& A, const coeffs& d, const ex& f, const GiNaC::symbol& t) {
    algebra_transform out;
    // convergence: Re r < Re mu for the exponents r of f and the eigenvalues mu of d (the
    // exponents of exp(d t)'s coordinates)
    std::vector<ex> mus;
    for (const ex& c : A->exp(d, t))
        for (const auto& e : signals::exponents_of(c, t)) {
            bool seen = false;
            for (const ex& m : mus) seen = seen || is_zero_scalar(tidy(m - e.lambda));
            if (!seen) mus.push_back(e.lambda);
        }
    // in the order of their printed forms: the report does not depend on GiNaC's term order
    std::sort(mus.begin(), mus.end(), [](const ex& x, const ex& y) {
        return message_text(x, text_limit::report) < message_text(y, text_limit::report);
    });
    out.converges = truth::yes;
    std::string conditions;
    for (const auto& r : signals::exponents_of(f, t))
        for (const ex& mu : mus) {
            const ex x = real_part_of(r.lambda - mu);
            const bool constant = GiNaC::is_a<GiNaC::numeric>(x.evalf());
            GiNaC::numeric v;
            const bool known = constant && evaluate_numeric(x, 40, v) && v.is_real();
            if (known && v < GiNaC::numeric(-1, 1000000000) * GiNaC::numeric(1, 1000000000)) continue;  // < -1e-18
            if (is_zero_scalar(x) || (known && v > 0 && !(v < GiNaC::numeric(1, 1000000000) * GiNaC::numeric(1, 1000000000)))) {
                out.converges = truth::no;
                out.report = "the integral diverges: the exponent " + message_text(r.lambda, text_limit::report) +
                             " of the signal and the eigenvalue " + message_text(mu, text_limit::report) +
                             " of d have Re(r - mu) = " + message_text(x, text_limit::report) +
                             " >= 0; the value is the analytic continuation q(d) p(d)^-1";
                return out;
            }
            out.converges = truth::unknown;
            const std::string c = message_text(x, text_limit::report) + " < 0";
            if (conditions.find(c) == std::string::npos) conditions += (conditions.empty() ? "" : ", ") + c;
        }
    out.report = out.converges == truth::yes
                     ? "converges: Re r < Re mu for every exponent r of the signal and eigenvalue mu of d"
                     : "converges where " + conditions + " (otherwise the value is the analytic continuation)";
    return out;
}

algebra_transform transform_two_sided(const algebra_ptr& A, const coeffs& d, const ex& f, const ex& g,
                                      const GiNaC::symbol& t) {
    const algebra_transform right = transform(A, d, f, t);
    const algebra_transform left = transform(A, algebra::scale(-1, d), g.subs(t == -t), t);
    algebra_transform out;
    out.value = algebra::add(right.value, left.value);
    for (ex& x : out.value) x = tidy(x);
    if (right.converges == truth::no || left.converges == truth::no)
        out.converges = truth::no;
    else if (right.converges == truth::yes && left.converges == truth::yes)
        out.converges = truth::yes;
    else
        out.converges = truth::unknown;
    out.report = "t >= 0: " + right.report + "; t < 0 (g(-u) at -d): " + left.report;
    return out;
}

}  // namespace symrep::transforms
