// symrep/transforms/signal_transform.cpp -- see signal_transform.h.
#include "symrep/transforms/signal_transform.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "symrep/core/error.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/scalar/scalar.h"
#include "symrep/signals/representation.h"
#include "symrep/transforms/distribution.h"

namespace symrep::transforms {

using GiNaC::ex;

bool is_quasi_polynomial(const ex& f, const GiNaC::symbol& t) {
    if (f.is_zero()) return true;
    if (has_impulse(f) || f.has(GiNaC::step(GiNaC::wild(0)))) return false;
    try {
        const GiNaC::symbol X("X");
        signals::annihilator(f, t, X);
        return true;
    } catch (const domain_error&) {
        return false;
    }
}

namespace {

// An interval of t; an end is infinite or a real number.
struct interval {
    bool lo_inf = false, hi_inf = true;
    GiNaC::numeric lo = 0, hi = 0;  ///< the ends as numbers (for ordering and quadrature)
    ex lo_x = 0, hi_x = 0;          ///< the same ends exactly (pi stays pi)
};

bool same(const interval& a, const interval& b) {
    return a.lo_inf == b.lo_inf && a.hi_inf == b.hi_inf && (a.lo_inf || a.lo == b.lo) && (a.hi_inf || a.hi == b.hi);
}

std::string end_text(bool inf, const ex& x, bool upper) {
    return inf ? (upper ? "oo" : "-oo") : message_text(x, text_limit::fragment);
}

std::string interval_text(const interval& I) {
    return "[" + end_text(I.lo_inf, I.lo_x, false) + ", " + end_text(I.hi_inf, I.hi_x, true) + "]";
}

struct piece {
    interval I;
    ex h;
};

GiNaC::numeric real_number(const ex& x, const ex& term, const char* what) {
    const ex v = GiNaC::is_a<GiNaC::numeric>(x) ? x : x.evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
        throw domain_error(std::string("transform: the ") + what + " in " + message_text(term, text_limit::report) +
                           " is not a real number (the pieces of a signal are cut at numeric times)");
    return GiNaC::is_a<GiNaC::numeric>(x) ? GiNaC::ex_to<GiNaC::numeric>(x) : GiNaC::ex_to<GiNaC::numeric>(v);
}

// The terms of f (expanded) with their step() factors read as intervals within `base`.
std::vector<piece> pieces_of(const ex& f, const GiNaC::symbol& t, const interval& base) {
    std::vector<piece> out;
    const ex e = GiNaC::expand(f);
    const auto one_term = [&](const ex& term) {
        interval I = base;
        ex rest = 1;
        const bool product = GiNaC::is_a<GiNaC::mul>(term);
        for (std::size_t i = 0, n = product ? term.nops() : 1; i < n; ++i) {
            ex x = product ? term.op(i) : term;
            if (GiNaC::is_a<GiNaC::power>(x) && is_ex_the_function(x.op(0), GiNaC::step) &&
                x.op(1).info(GiNaC::info_flags::posint))
                x = x.op(0);  // step^n = step
            if (!is_ex_the_function(x, GiNaC::step) || !x.op(0).has(t)) {
                if (x.has(GiNaC::step(GiNaC::wild(0))) && x.has(t))
                    throw domain_error("transform: the factor " + message_text(x, text_limit::report) +
                                       " holds step() inside another function or power; a signal is cut into "
                                       "pieces by factors step(alpha*t + beta)");
                rest *= x;
                continue;
            }
            const ex arg = x.op(0).expand();
            if (!arg.is_polynomial(t) || arg.degree(t) != 1)
                throw domain_error("transform: the argument of " + message_text(x, text_limit::report) +
                                   " is not linear in t");
            const GiNaC::numeric alpha = real_number(arg.coeff(t, 1), x, "coefficient of t");
            const GiNaC::numeric beta = real_number(arg.coeff(t, 0), x, "constant");
            if (alpha.is_zero()) throw domain_error("transform: step of a constant in " + message_text(term));
            const GiNaC::numeric b = -beta / alpha;
            const ex bx = tidy(-arg.coeff(t, 0) / arg.coeff(t, 1));
            if (alpha.is_positive()) {
                if (I.lo_inf || b > I.lo) I.lo = b, I.lo_x = bx, I.lo_inf = false;
            } else {
                if (I.hi_inf || b < I.hi) I.hi = b, I.hi_x = bx, I.hi_inf = false;
            }
        }
        if (!I.lo_inf && !I.hi_inf && !(I.lo < I.hi)) return;  // an empty piece
        for (piece& p : out)
            if (same(p.I, I)) {
                p.h += rest;
                return;
            }
        out.push_back({I, rest});
    };
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) one_term(e.op(i));
    else if (!e.is_zero())
        one_term(e);
    // the partition of `base` by every end: on each cell the sum of the terms covering it (so that
    // 3 (1 - t/2) (1 - step(t - 2)) is 0 on [2, oo), not two divergent pieces), equal neighbours merged
    using cut_t = std::pair<GiNaC::numeric, ex>;
    std::vector<cut_t> cuts;
    for (const piece& p : out) {
        if (!p.I.lo_inf) cuts.push_back({p.I.lo, p.I.lo_x});
        if (!p.I.hi_inf) cuts.push_back({p.I.hi, p.I.hi_x});
    }
    std::sort(cuts.begin(), cuts.end(), [](const cut_t& a, const cut_t& b) { return a.first < b.first; });
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](const cut_t& a, const cut_t& b) { return a.first == b.first; }),
               cuts.end());
    std::vector<interval> cells;
    {
        interval c = base;
        for (const cut_t& x : cuts) {
            if ((!c.lo_inf && !(x.first > c.lo)) || (!base.hi_inf && !(x.first < base.hi))) continue;
            interval left = c;
            left.hi_inf = false;
            left.hi = x.first;
            left.hi_x = x.second;
            cells.push_back(left);
            c.lo_inf = false;
            c.lo = x.first;
            c.lo_x = x.second;
        }
        cells.push_back(c);
    }
    const auto covers = [](const interval& big, const interval& small) {
        const bool lo = big.lo_inf || (!small.lo_inf && !(small.lo < big.lo));
        const bool hi = big.hi_inf || (!small.hi_inf && !(small.hi > big.hi));
        return lo && hi;
    };
    std::vector<piece> merged;
    for (const interval& c : cells) {
        ex h = 0;
        for (const piece& p : out)
            if (covers(p.I, c)) h += p.h;
        h = tidy(GiNaC::expand(h));
        if (h.is_zero()) continue;
        if (!merged.empty() && !merged.back().I.hi_inf && !c.lo_inf && merged.back().I.hi == c.lo &&
            is_zero_scalar(tidy(GiNaC::expand(merged.back().h - h)))) {
            merged.back().I.hi_inf = c.hi_inf;
            merged.back().I.hi = c.hi;
            merged.back().I.hi_x = c.hi_x;
            continue;
        }
        merged.push_back({c, h});
    }
    return merged;
}

// ---------------------------------------------------------------- exact: quasi-polynomials

// E_a(d) = int_a^oo h(t) e^(-d t) dt = e^(-a d) q_a(d) p(d)^-1 (the analytic continuation; see the
// header). zero_divisor_error when p(d) is singular.
coeffs tail_integral(const algebra_ptr& A, const coeffs& d, const ex& h, const GiNaC::symbol& t, const ex& a) {
    if (h.is_zero()) return A->zero();
    const GiNaC::symbol X("X");
    const ex p = signals::annihilator(h, t, X);
    const auto R = signals::polynomial_representation(p, X);
    coeffs w = signals::element_of(R, h, t);
    if (!a.is_zero()) w = R.A->multiply(w, R.A->exp(R.d, a));  // h(t + a) = Psi^-1(w e^(v a))
    coeffs qd = A->zero(), pd = A->zero(), dj = A->unit();
    const int n = p.degree(X);
    for (int j = 0; j <= n; ++j) {
        if (j < int(w.size())) qd = algebra::add(qd, algebra::scale(w[std::size_t(j)], dj));
        pd = algebra::add(pd, algebra::scale(p.coeff(X, j), dj));
        if (j < n) dj = A->multiply(dj, d);
    }
    coeffs v = A->multiply(qd, A->inverse(pd));
    if (!a.is_zero()) {
        const GiNaC::symbol u("u");
        coeffs shift = A->exp(algebra::scale(-1, d), u);
        for (ex& y : shift) y = y.subs(u == a);
        v = A->multiply(v, shift);
    }
    return v;
}

// int over [lo, hi] (lo finite) of h e^(-d t), exact; the convergence of an infinite upper end
// decided (refused when it diverges), a condition kept in `conditions`.
coeffs finite_start_integral(const algebra_ptr& A, const coeffs& d, const ex& h, const GiNaC::symbol& t,
                             const ex& lo, bool hi_inf, const ex& hi, std::string& conditions,
                             truth& converges, const std::string& where) {
    coeffs v = tail_integral(A, d, h, t, lo);
    if (!hi_inf) return algebra::sub(v, tail_integral(A, d, h, t, hi));
    const algebra_transform c = convergence_of(A, d, h, t);
    if (c.converges == truth::no)
        throw domain_error("transform: the integral of the piece " + message_text(h, text_limit::report) + " on " +
                           where + " diverges (" + c.report.substr(0, c.report.find(';')) + ")");
    if (c.converges == truth::unknown) {
        converges = truth::unknown;
        conditions += (conditions.empty() ? "" : "; ") + c.report;
    }
    return v;
}

// ---------------------------------------------------------------- exact: Gaussians on the line

// Re and Im of x, its symbols real (the engine's convention), as tidy does them.
ex re_of(const ex& x) { return tidy(GiNaC::real_part(x.expand())); }
ex im_of(const ex& x) { return tidy(GiNaC::imag_part(x.expand())); }

// cos, sin, cosh, sinh written with exp
ex exponential_form(const ex& h) {
    using GiNaC::wild;
    const ex I = GiNaC::I;
    GiNaC::exmap m;
    m[GiNaC::cos(wild(0))] = (GiNaC::exp(I * wild(0)) + GiNaC::exp(-I * wild(0))) / 2;
    m[GiNaC::sin(wild(0))] = (GiNaC::exp(I * wild(0)) - GiNaC::exp(-I * wild(0))) / (2 * I);
    m[GiNaC::cosh(wild(0))] = (GiNaC::exp(wild(0)) + GiNaC::exp(-wild(0))) / 2;
    m[GiNaC::sinh(wild(0))] = (GiNaC::exp(wild(0)) - GiNaC::exp(-wild(0))) / 2;
    return GiNaC::expand(h.subs(m));
}

// One term c t^k e^(Q(t)) of h; false when the term is not of this form.
struct gaussian_term {
    ex c, Q;
    unsigned k = 0;
};
// The term c t^k e^(Q(t)) (Q expanded; exp(x)^n read as e^(n x)); nothing when the term is
// not of this form.
std::optional<gaussian_term> read_gaussian_term(const ex& term, const GiNaC::symbol& t) {
    gaussian_term g;
    g.c = 1;
    g.Q = 0;
    const bool product = GiNaC::is_a<GiNaC::mul>(term);
    for (std::size_t i = 0, n = product ? term.nops() : 1; i < n; ++i) {
        const ex x = product ? term.op(i) : term;
        if (!x.has(t)) g.c *= x;
        else if (x.is_equal(t)) g.k += 1;
        else if (GiNaC::is_a<GiNaC::power>(x) && x.op(0).is_equal(t) && x.op(1).info(GiNaC::info_flags::posint))
            g.k += unsigned(GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_int());
        else if (is_ex_the_function(x, GiNaC::exp))
            g.Q += x.op(0);
        else if (GiNaC::is_a<GiNaC::power>(x) && is_ex_the_function(x.op(0), GiNaC::exp) &&
                 x.op(1).info(GiNaC::info_flags::integer))
            g.Q += x.op(1) * x.op(0).op(0);
        else
            return std::nullopt;
    }
    g.Q = GiNaC::expand(g.Q);
    if (!g.Q.is_polynomial(t)) return std::nullopt;
    return g;
}

bool gaussian_terms(const ex& h, const GiNaC::symbol& t, std::vector<gaussian_term>& out) {
    const ex e = exponential_form(h);
    const auto one = [&](const ex& term) {
        const auto g = read_gaussian_term(term, t);
        if (!g || g->Q.degree(t) != 2) return false;
        out.push_back(*g);
        return true;
    };
    if (GiNaC::is_a<GiNaC::add>(e)) {
        for (std::size_t i = 0; i < e.nops(); ++i)
            if (!one(e.op(i))) return false;
        return true;
    }
    return one(e);
}

coeffs gaussian_integral(const algebra_ptr& A, const coeffs& d, const std::vector<gaussian_term>& terms,
                         const GiNaC::symbol& t) {
    const GiNaC::symbol z("z"), b("b");
    ex G = 0;
    for (const gaussian_term& g : terms) {
        const ex alpha = tidy(-g.Q.coeff(t, 2));
        GiNaC::numeric av;
        const bool positive = alpha.info(GiNaC::info_flags::positive) ||
                              (evaluate_numeric(alpha, 30, av) && av.is_real() && av.is_positive());
        if (!positive)
            throw domain_error("transform: cannot decide whether e^(" + message_text(g.Q, text_limit::report) +
                               ") decays: the coefficient of t^2 is not shown negative");
        ex term = GiNaC::sqrt(GiNaC::Pi / alpha) * GiNaC::exp(GiNaC::pow(b - z, 2) / (4 * alpha));
        for (unsigned j = 0; j < g.k; ++j) term = term.diff(b);
        G += g.c * GiNaC::exp(g.Q.coeff(t, 0)) * term.subs(b == g.Q.coeff(t, 1));
    }
    scalar_function F;
    F.name = "the Gaussian integral";
    F.value = [G, z](const ex& re, const ex& im, unsigned j, ex& out_re, ex& out_im) {
        ex g = G;
        for (unsigned i = 0; i < j; ++i) g = g.diff(z);
        g = GiNaC::expand(g.subs(z == re + GiNaC::I * im));
        out_re = 0;
        out_im = 0;
        const auto one = [&](const ex& term) {
            ex rest = 1, arg = 0;
            const bool product = GiNaC::is_a<GiNaC::mul>(term);
            for (std::size_t i = 0, n = product ? term.nops() : 1; i < n; ++i) {
                const ex x = product ? term.op(i) : term;
                if (is_ex_the_function(x, GiNaC::exp)) arg += x.op(0);
                else rest *= x;
            }
            const ex rr = re_of(rest), ri = im_of(rest), Re = re_of(arg), Im = im_of(arg);
            out_re += GiNaC::exp(Re) * (rr * GiNaC::cos(Im) - ri * GiNaC::sin(Im));
            out_im += GiNaC::exp(Re) * (rr * GiNaC::sin(Im) + ri * GiNaC::cos(Im));
        };
        if (GiNaC::is_a<GiNaC::add>(g))
            for (std::size_t i = 0; i < g.nops(); ++i) one(g.op(i));
        else
            one(g);
        out_re = tidy(out_re);
        out_im = tidy(out_im);
    };
    coeffs v = A->apply_function(d, F);
    for (ex& y : v) y = tidy(y);
    return v;
}

// ---------------------------------------------------------------- quadrature

bool numeric_coefficients(const coeffs& d, coeffs& out) {
    out.clear();
    for (const ex& x : d) {
        const ex v = GiNaC::evalf(x);
        if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return false;
        out.push_back(v);
    }
    return true;
}

// The decay of h at +oo (sign +1) or -oo (-1): h = sum c t^k e^(Q(t)) (exp form) with one
// leading term -a t^m of every Q, m even >= 2 or of the right parity, a > 0: the log-envelope
// max over terms of Re Q(t) + k log|t| + log|c| (Re Q's leading part governs).
struct decay {
    bool ok = false;
    bool grows = false;  ///< every term grows like e^(a |t|^m), m >= 2, a > 0: the integral diverges for every d
    std::vector<gaussian_term> terms;
};
decay decay_of(const ex& h, const GiNaC::symbol& t, int sign) {
    decay out;
    const ex e = exponential_form(h);
    std::vector<gaussian_term> terms;
    std::size_t growing = 0, count = 0;
    const auto one = [&](const ex& term) {
        ++count;
        const auto read = read_gaussian_term(term, t);
        if (!read) return false;
        const gaussian_term& g = *read;
        const int m = g.Q.degree(t);
        if (m < 2) return false;
        GiNaC::numeric lead;
        if (!evaluate_numeric(re_of(g.Q.coeff(t, m)), 30, lead) || !lead.is_real()) return false;
        // the leading part of Re Q at sign*oo: lead * sign^m * |t|^m, negative needed
        const bool negative = (m % 2 == 0 || sign > 0) ? lead.is_negative() : lead.is_positive();
        const bool positive = (m % 2 == 0 || sign > 0) ? lead.is_positive() : lead.is_negative();
        if (positive) ++growing;
        if (!negative) return false;
        terms.push_back(g);
        return true;
    };
    bool all = true;  // every term looked at: `grows` needs all of them
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) all = one(e.op(i)) && all;
    else
        all = one(e);
    out.ok = all && !terms.empty();
    out.grows = count > 0 && growing == count;
    out.terms = terms;
    return out;
}

// log of the envelope sum_terms |c| |t|^k e^(Re Q(t)) e^(sigma |t|) at t (double)
double log_envelope(const decay& D, const GiNaC::symbol& t, double sigma, double x) {
    double total = 0;
    for (const gaussian_term& g : D.terms) {
        GiNaC::numeric c, q;
        if (!evaluate_numeric(GiNaC::abs(g.c), 20, c) || !evaluate_numeric(re_of(g.Q).subs(t == GiNaC::numeric(x)), 20, q))
            return HUGE_VAL;
        total += c.to_double() * std::pow(std::abs(x), double(g.k)) * std::exp(q.to_double() + sigma * std::abs(x));
    }
    return total > 0 ? std::log(total) : -HUGE_VAL;
}

struct quadrature_result {
    coeffs value;
    double error = 0;
    std::string how;
};

quadrature_result quadrature(const algebra_ptr& A, const coeffs& d, const ex& h, const GiNaC::symbol& t,
                             const interval& I) {
    coeffs dn;
    if (!numeric_coefficients(d, dn))
        throw domain_error("transform: the integral of " + message_text(h, text_limit::report) + " on " +
                           interval_text(I) +
                           " has no closed form here; give d numeric coordinates to evaluate it by quadrature");
    if (!GiNaC::is_a<GiNaC::numeric>(GiNaC::evalf(h.subs(t == GiNaC::numeric(1, 3)))))
        throw domain_error("transform: the signal " + message_text(h, text_limit::report) +
                               " holds symbols other than t; give them values to evaluate the integral by quadrature");
    // sigma: the largest |Re mu| over the eigenvalues of d (the growth of e^(-d t))
    double sigma = 0;
    const coeffs E = A->exp(algebra::scale(-1, dn), t);
    for (const ex& c : E)
        for (const auto& e : signals::exponents_of(c, t)) {
            GiNaC::numeric r;
            if (evaluate_numeric(re_of(e.lambda), 20, r)) sigma = std::max(sigma, std::abs(r.to_double()));
        }
    double lo = I.lo_inf ? 0 : I.lo.to_double(), hi = I.hi_inf ? 0 : I.hi.to_double();
    double tail = 0;
    std::ostringstream how;
    how.precision(3);
    const auto cut = [&](int sign, double from) {
        const decay D = decay_of(h, t, sign);
        if (D.grows)
            throw domain_error("transform: the integral of " + message_text(h, text_limit::report) + " diverges at " +
                               std::string(sign > 0 ? "+oo" : "-oo") +
                               ": the signal grows like e^(a |t|^m) with m >= 2 and a > 0 there, faster than e^(-d t) "
                               "falls for any d");
        if (!D.ok)
            throw domain_error("transform: cannot decide whether the integral of " + message_text(h, text_limit::report) +
                               " converges at " + std::string(sign > 0 ? "+oo" : "-oo") +
                               " (decided for quasi-polynomials and for a decay e^(P(t)), P a polynomial of degree "
                               ">= 2 with leading term negative there)");
        // T: the envelope below 1e-20 and falling faster than e^(-|t|) from there on
        double T = std::max(1.0, std::abs(from) + 1);
        for (int i = 0; i < 400; ++i, T += 0.5) {
            const double x = sign * T, l = log_envelope(D, t, sigma, x);
            const double slope = (log_envelope(D, t, sigma, sign * (T + 1e-3)) - l) / 1e-3;
            if (l < std::log(1e-20) && slope < -1) {
                tail += std::exp(l) / -slope;  // int_T^oo e^(l + slope (u - T)) du, the envelope log-concave
                return sign * T;
            }
        }
        throw domain_error("transform: the integrand of " + message_text(h, text_limit::report) +
                           " does not fall below 1e-20 before |t| = 200; the quadrature is not attempted");
    };
    if (I.lo_inf) lo = cut(-1, I.hi_inf ? 0 : hi);
    if (I.hi_inf) hi = cut(+1, I.lo_inf ? 0 : lo);
    quadrature_result out;
    double scale = 0;
    for (std::size_t k = 0; k < E.size(); ++k) {
        const ex integrand = tidy(GiNaC::expand(h * E[k]));
        if (integrand.is_zero()) {
            out.value.push_back(0);
            continue;
        }
        const num::integral_value v = num::evaluate_integral(t, lo, hi, integrand);
        out.value.push_back(GiNaC::numeric(v.value));
        out.error = std::max(out.error, v.error + tail);
        scale = std::max(scale, v.scale);
    }
    if (!(out.error <= 1e-10 * std::max(1.0, scale)))
        throw domain_error("transform: the quadrature of " + message_text(h, text_limit::report) + " on " +
                           interval_text(I) + " did not reach its tolerance (estimate " +
                           std::to_string(out.error) + "); the integrand may be singular there");
    how << "by quadrature on [" << lo << ", " << hi << "]";
    out.how = how.str();
    return out;
}

// ---------------------------------------------------------------- one piece

struct piece_value {
    coeffs value;
    bool exact = true;
    double error = 0;
    std::string how;
};

piece_value integrate_piece(const algebra_ptr& A, const coeffs& d, const piece& P, const GiNaC::symbol& t,
                            std::string& conditions, truth& converges) {
    piece_value out;
    const interval& I = P.I;
    const std::string where = interval_text(I);
    if (is_quasi_polynomial(P.h, t)) {
        try {
            if (!I.lo_inf) {
                out.value = finite_start_integral(A, d, P.h, t, I.lo_x, I.hi_inf, I.hi_x, conditions, converges, where);
            } else if (!I.hi_inf) {  // int_-oo^b h(t) e^(-d t) dt = int_-b^oo h(-u) e^(d u) du
                out.value = finite_start_integral(A, algebra::scale(-1, d), P.h.subs(t == -t), t, -I.hi_x, true, 0,
                                                  conditions, converges, where);
            } else {  // the whole line: split at 0
                const coeffs r = finite_start_integral(A, d, P.h, t, 0, true, 0, conditions, converges, where);
                const coeffs l = finite_start_integral(A, algebra::scale(-1, d), P.h.subs(t == -t), t, 0, true, 0,
                                                       conditions, converges, where);
                out.value = algebra::add(r, l);
            }
            out.how = "exact on " + where;
            return out;
        } catch (const zero_divisor_error&) {
            // p(d) singular: the closed form e^(-a d) q_a(d) p(d)^-1 has a removable singularity
            // at this d (a finite piece) or a pole (an infinite one); quadrature below decides
            if (I.lo_inf || I.hi_inf)
                throw domain_error("transform: p(d) is singular for the piece " + message_text(P.h, text_limit::report) +
                                   " on " + where + ": an eigenvalue of d is an exponent of the signal, where the "
                                   "integral over an infinite range diverges");
        }
    } else if (I.lo_inf && I.hi_inf) {
        std::vector<gaussian_term> g;
        if (gaussian_terms(P.h, t, g)) {
            out.value = gaussian_integral(A, d, g, t);
            out.how = "exact on " + where + " (Gaussian integral)";
            return out;
        }
    }
    const quadrature_result q = quadrature(A, d, P.h, t, I);
    out.value = q.value;
    out.exact = false;
    out.error = q.error;
    out.how = q.how;
    return out;
}

}  // namespace

algebra_transform transform_signal(const algebra_ptr& A, const coeffs& d, const ex& f, const GiNaC::symbol& t,
                                   const ex* g) {
    A->check_size(d, "transform");
    const bool plain_f = is_quasi_polynomial(f, t);
    const bool plain_g = g == nullptr || is_quasi_polynomial(*g, t);
    if (plain_f && plain_g) return g ? transform_two_sided(A, d, f, *g, t) : transform(A, d, f, t);

    const bool whole = g != nullptr && is_zero_scalar(tidy(GiNaC::expand(f - *g)));
    std::vector<impulse> impulses;
    std::vector<piece> pieces;
    {
        const split_signal sf = split_impulses(f, t);
        for (const impulse& x : sf.impulses) {
            if (whole) {
                impulses.push_back(x);
                continue;
            }
            impulses.push_back(x);  // positions before 0 are dropped by impulse_transform (causal)
        }
        interval I;
        I.lo_inf = whole;
        I.lo = 0;
        pieces = pieces_of(sf.regular, t, I);
    }
    coeffs value = whole ? impulse_transform(A, d, impulses, true) : impulse_transform(A, d, impulses, false);
    if (g != nullptr && !whole) {
        const split_signal sg = split_impulses(*g, t);
        for (const impulse& x : sg.impulses) {
            GiNaC::numeric a;
            if (!evaluate_numeric(x.a, 30, a) || !a.is_real())
                throw domain_error("transform: cannot decide whether the impulse of g at t = " +
                                   message_text(x.a, text_limit::report) + " lies in t < 0");
            if (a.is_zero())
                throw domain_error("transform: g (the signal for t < 0) has an impulse at t = 0; an impulse at 0 "
                                   "belongs to f");
            if (a.is_negative()) value = algebra::add(value, impulse_transform(A, d, {x}, true));
        }
        interval I;
        I.lo_inf = true;
        I.hi_inf = false;
        I.hi = 0;
        for (piece& p : pieces_of(sg.regular, t, I)) pieces.push_back(p);
    }
    algebra_transform out;
    out.converges = truth::yes;
    std::string conditions, how;
    double error = 0;
    bool exact = true;
    for (const piece& P : pieces) {
        const piece_value v = integrate_piece(A, d, P, t, conditions, out.converges);
        value = algebra::add(value, v.value);
        exact = exact && v.exact;
        error += v.error;
        if (how.find(v.how) == std::string::npos) how += (how.empty() ? "" : "; ") + v.how;
    }
    if (!impulses.empty()) how += std::string(how.empty() ? "" : "; ") + "impulses: c d^k e^(-a d) (V.2.33)";
    for (ex& y : value) y = tidy(y);
    out.value = value;
    std::ostringstream r;
    r.precision(2);
    if (exact) {
        r << (out.converges == truth::yes ? "exact, converges: " : "exact: ") << how;
        if (out.converges != truth::yes) r << "; " << conditions;
    } else {
        r << "numeric (" << how << "), error estimate " << std::scientific << std::max(error, 1e-300)
          << " per coordinate";
        if (out.converges != truth::yes) r << "; " << conditions;
    }
    out.report = r.str();
    return out;
}

}  // namespace symrep::transforms
