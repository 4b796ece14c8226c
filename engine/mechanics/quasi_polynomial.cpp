// symrep/mechanics/quasi_polynomial.cpp -- closed-form calculus of quasi-polynomials.
//
// Formulas (lambda = a + i b, exactly non-zero unless stated):
//   int_0^t tau^k e^{lambda tau} dtau
//       = e^{lambda t} sum_{j=0}^{k} (-1)^j k!/(k-j)! t^{k-j} / lambda^{j+1}  -  (-1)^k k!/lambda^{k+1},
//   lambda = 0 exactly:  t^{k+1}/(k+1);
//   (tau^m e^{lambda tau}) * (tau^n e^{mu tau})
//       = e^{mu t} sum_{i=0}^{n} C(n,i) (-1)^i t^{n-i} int_0^t tau^{m+i} e^{(lambda-mu) tau} dtau
//   (binomial expansion of (t - tau)^n), so resonance lambda = mu is the lambda = 0 case
//   of the integral and produces the secular powers of t exactly.
#include "symrep/mechanics/quasi_polynomial.h"

#include <algorithm>

#include "symrep/scalar/equality.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

ex binomial(unsigned n, unsigned i) { return GiNaC::binomial(GiNaC::numeric(n), GiNaC::numeric(i)); }

// Complex power z^n (n >= 0).
cex cpow(const cex& z, unsigned n) {
    cex r(ex(1), ex(0));
    for (unsigned i = 0; i < n; ++i) r = tidy_cex(r * z);
    return r;
}

// Real and imaginary part of an expression free of t. Symbols are read as real;
// complex numerics (3 + 2 I) are split exactly.
bool has_complex_number(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::numeric>(*it) && !GiNaC::ex_to<GiNaC::numeric>(*it).is_real()) return true;
    return false;
}

cex split(const ex& e) {
    // symbols are real: without a complex number e is its real part, kept as it is (normalize()
    // tidies the coefficients once, when the form is read)
    if (!has_complex_number(e)) return {e, ex(0)};
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
        return {GiNaC::real(n), GiNaC::imag(n)};
    }
    if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::constant>(e)) return {e, ex(0)};
    if (GiNaC::is_a<GiNaC::add>(e)) {
        cex r(ex(0), ex(0));
        for (std::size_t i = 0; i < e.nops(); ++i) r += split(e.op(i));
        return tidy_cex(r);
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        cex r(ex(1), ex(0));
        for (std::size_t i = 0; i < e.nops(); ++i) r = r * split(e.op(i));
        return tidy_cex(r);
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer()) {
        const cex b = split(e.op(0));
        if (b.im.is_zero()) return {e, ex(0)};
        const long n = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_long();
        const cex p = cpow(b, unsigned(n < 0 ? -n : n));
        return n < 0 ? inverse_cex(p, "a negative power") : p;
    }
    // functions and other atoms holding a complex number
    return {tidy(GiNaC::real_part(e)), tidy(GiNaC::imag_part(e))};
}

bool contains(const ex& e, const ex& t) { return e.has(t); }

constexpr long max_power = 4096;

}  // namespace

bool is_zero_cex(const cex& z) { return is_zero_scalar(z.re) && is_zero_scalar(z.im); }

cex tidy_cex(const cex& z) { return {tidy(z.re), tidy(z.im)}; }

cex inverse_cex(const cex& z, const char* where) {
    if (is_zero_cex(z))
        throw domain_error(std::string("division by an exact zero in ") + where);
    const ex n = tidy(z.norm2());
    // a constant |z|^2 neither proved 0 nor seen nonzero is refused, not divided by
    if (!is_nonzero_generic(n, std::string("division in ") + where))
        throw domain_error(std::string("division by an exact zero in ") + where);
    return {tidy(z.re / n), tidy(-z.im / n)};
}

// --- construction --------------------------------------------------------------

quasi_polynomial quasi_polynomial::constant(const ex& c, const GiNaC::ex& t) {
    if (contains(c, t))
        throw domain_error("quasi_polynomial::constant: " + message_text(c) + " depends on " + message_text(t));
    quasi_polynomial q(t);
    q.add_term({split(c), 0, cex(ex(0), ex(0))});
    return q;
}

quasi_polynomial quasi_polynomial::monomial(const cex& c, unsigned k, const cex& lambda,
                                            const GiNaC::ex& t) {
    if (contains(c.re, t) || contains(c.im, t) || contains(lambda.re, t) || contains(lambda.im, t))
        throw domain_error("quasi_polynomial::monomial: coefficient or exponent depends on " + message_text(t));
    quasi_polynomial q(t);
    q.add_term({tidy_cex(c), k, tidy_cex(lambda)});
    return q;
}

quasi_polynomial quasi_polynomial::cos_term(const ex& c, unsigned k, const ex& a, const ex& b,
                                            const GiNaC::ex& t) {
    const ex h = c / 2;
    return monomial({h, 0}, k, {a, b}, t) + monomial({h, 0}, k, {a, -b}, t);
}

quasi_polynomial quasi_polynomial::sin_term(const ex& c, unsigned k, const ex& a, const ex& b,
                                            const GiNaC::ex& t) {
    // sin = (e^{ib} - e^{-ib}) / (2i), 1/(2i) = -i/2
    const ex h = c / 2;
    return monomial({0, -h}, k, {a, b}, t) + monomial({0, h}, k, {a, -b}, t);
}

namespace {

// e^{alpha t + beta} for complex alpha, beta free of t.
quasi_polynomial exp_linear(const cex& alpha, const cex& beta, const GiNaC::ex& t) {
    const ex m = GiNaC::exp(beta.re);
    const cex c = beta.im.is_zero() ? cex(m, ex(0))
                                    : cex(m * GiNaC::cos(beta.im), m * GiNaC::sin(beta.im));
    return quasi_polynomial::monomial(c, 0, alpha, t);
}

}  // namespace

quasi_polynomial quasi_polynomial::from_ex(const ex& e0, const GiNaC::ex& t) {
    if (!GiNaC::is_a<GiNaC::symbol>(t))
        throw domain_error("quasi_polynomial: the variable " + message_text(t) + " is not a symbol");
    const ex e = e0;
    if (!contains(e, t)) return constant(e, t);
    if (GiNaC::is_a<GiNaC::symbol>(e)) return monomial({1, 0}, 1, {0, 0}, t);  // e == t
    if (GiNaC::is_a<GiNaC::add>(e)) {
        quasi_polynomial r(t);
        for (std::size_t i = 0; i < e.nops(); ++i) r = r + from_ex(e.op(i), t);
        return r;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
        quasi_polynomial r = constant(1, t);
        for (std::size_t i = 0; i < e.nops(); ++i) r = r * from_ex(e.op(i), t);
        return r;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
        const ex n = e.op(1);
        if (!contains(n, t) && GiNaC::is_a<GiNaC::numeric>(n) &&
            GiNaC::ex_to<GiNaC::numeric>(n).is_nonneg_integer()) {
            const GiNaC::numeric nn = GiNaC::ex_to<GiNaC::numeric>(n);
            if (nn > GiNaC::numeric(max_power))
                throw size_error("quasi-polynomial: the power " + message_text(e) + " exceeds the limit " +
                                 std::to_string(max_power) + " on exponents expanded here");
            const quasi_polynomial b = from_ex(e.op(0), t);
            quasi_polynomial r = constant(1, t);
            for (long i = 0; i < nn.to_long(); ++i) r = r * b;
            return r;
        }
        throw domain_error("not a quasi-polynomial in " + message_text(t) + ": the power " + message_text(e) +
                           " is not a non-negative integer power of a quasi-polynomial");
    }
    if (GiNaC::is_a<GiNaC::function>(e) && e.nops() == 1) {
        const std::string f = GiNaC::ex_to<GiNaC::function>(e).get_name();
        const ex u = GiNaC::expand(e.op(0));
        if (f == "exp" || f == "cos" || f == "sin" || f == "cosh" || f == "sinh") {
            if (!u.is_polynomial(t) || u.degree(t) > 1 || contains(u.coeff(t, 1), t) ||
                contains(u.coeff(t, 0), t))
                throw domain_error("not a quasi-polynomial in " + message_text(t) + ": the argument of " +
                                   message_text(e) + " is not linear in " + message_text(t));
            const cex al = split(u.coeff(t, 1)), be = split(u.coeff(t, 0));
            const cex ial(-al.im, al.re), ibe(-be.im, be.re);
            if (f == "exp") return exp_linear(al, be, t);
            if (f == "cosh") return ex(1) / 2 * (exp_linear(al, be, t) + exp_linear(-al, -be, t));
            if (f == "sinh") return ex(1) / 2 * (exp_linear(al, be, t) - exp_linear(-al, -be, t));
            if (f == "cos") return ex(1) / 2 * (exp_linear(ial, ibe, t) + exp_linear(-ial, -ibe, t));
            // sin u = (e^{iu} - e^{-iu}) / (2i)
            return cex(ex(0), ex(-1) / 2) * (exp_linear(ial, ibe, t) - exp_linear(-ial, -ibe, t));
        }
    }
    throw domain_error("not a quasi-polynomial in " + message_text(t) + ": cannot read " + message_text(e) +
                       " as a sum of c t^k e^(a t) cos(b t), c t^k e^(a t) sin(b t)");
}

// --- canonical form --------------------------------------------------------------

void quasi_polynomial::add_term(const qp_term& u) {
    if (u.c.re.is_zero() && u.c.im.is_zero()) return;
    raw_ = true;
    // an exponent already here as it is spelled (the usual case in sums and products of
    // normalized quasi-polynomials) needs no tidying
    for (auto& v : terms_)
        if (v.k == u.k && v.lambda.re.is_equal(u.lambda.re) && v.lambda.im.is_equal(u.lambda.im)) {
            v.c = v.c + u.c;
            return;
        }
    const cex lambda = tidy_cex(u.lambda);
    for (auto& v : terms_)
        if (v.k == u.k && v.lambda.re.is_equal(lambda.re) && v.lambda.im.is_equal(lambda.im)) {
            v.c = v.c + u.c;
            return;
        }
    terms_.push_back({u.c, u.k, lambda});
}

std::vector<qp_term> quasi_polynomial::merged_terms() const {
    std::vector<qp_term> out;
    // exponents equal but spelled differently (the tidied forms are not unique with radicals):
    // each exponent's value at one point first, so that only exponents that agree there go
    // to the exact test modulo square roots (all pairs did: most of the reduced Foucault time)
    // (computed when first needed: most exponents are the same expression or none is near)
    struct values {
        bool known = false;
        point_value re, im;
    };
    std::vector<values> at;
    auto value_of = [](values& v, const qp_term& u) -> const values& {
        if (!v.known) v = {true, value_at_generic_point(u.lambda.re), value_at_generic_point(u.lambda.im)};
        return v;
    };
    for (const qp_term& u : terms_) {
        values here;
        std::size_t same = 0;
        for (; same < out.size(); ++same) {
            const qp_term& v = out[same];
            if (v.k != u.k) continue;
            if (v.lambda.re.is_equal(u.lambda.re) && v.lambda.im.is_equal(u.lambda.im)) break;
            const cex d = v.lambda - u.lambda;
            if (!has_symbolic_square_root(d.re) && !has_symbolic_square_root(d.im)) {
                if (is_zero_cex(d)) break;  // rational: the exact test is cheap
                continue;
            }
            const values &a = value_of(at[same], v), &b = value_of(here, u);
            if (seen_different(a.re, b.re) || seen_different(a.im, b.im)) continue;
            if (is_zero_cex(d)) break;
        }
        if (same < out.size()) {
            out[same].c = out[same].c + u.c;
        } else {
            out.push_back(u);
            at.push_back(here);
        }
    }
    return out;
}

void quasi_polynomial::normalize() const {
    if (!raw_) return;
    std::vector<qp_term> out = merged_terms();
    terms_.clear();
    static const point_value zero = value_at_generic_point(0);
    for (qp_term& u : out) {
        if (proved_zero_by_denominators(u.c.re) && proved_zero_by_denominators(u.c.im)) continue;
        u.c = tidy_cex(u.c);
        // with radicals, seen nonzero at the point spares the exact test modulo square roots
        // (most coefficients are not 0); without, that test is cheap
        const bool radicals = has_symbolic_square_root(u.c.re) || has_symbolic_square_root(u.c.im);
        if ((radicals && (seen_different(value_at_generic_point(u.c.re), zero) ||
                          seen_different(value_at_generic_point(u.c.im), zero))) ||
            !is_zero_cex(u.c))
            terms_.push_back(std::move(u));
    }
    raw_ = false;
}

void quasi_polynomial::adopt_variable(const quasi_polynomial& o) {
    if (!o.has_t_) return;
    if (!has_t_) {
        t_ = o.t_;
        has_t_ = true;
        return;
    }
    if (!t_.is_equal(o.t_))
        throw domain_error("quasi-polynomials in different variables " + message_text(t_) + " and " +
                           message_text(o.t_) + " combined");
}

bool quasi_polynomial::is_real() const { return imag().is_zero(); }

quasi_polynomial quasi_polynomial::conj() const {
    quasi_polynomial r = *this;
    r.terms_.clear();
    for (const auto& u : terms_) r.add_term({u.c.conj(), u.k, u.lambda.conj()});
    return r;
}

quasi_polynomial quasi_polynomial::real() const { return ex(1) / 2 * (*this + conj()); }

quasi_polynomial quasi_polynomial::imag() const {
    return cex(ex(0), ex(-1) / 2) * (*this - conj());
}

namespace {

// Chooses s = sigma * b with sigma = +-1 so that b and -b give the same s.
ex canonical_frequency(const ex& b, int& sigma) {
    const ex s = GiNaC::expand(b), m = GiNaC::expand(-b);
    sigma = 1;
    if (has_negative_sign(s)) { sigma = -1; return m; }
    if (has_negative_sign(m)) return s;
    if (GiNaC::is_a<GiNaC::add>(s)) {
        int neg = 0, n = int(s.nops());
        for (int i = 0; i < n; ++i) neg += has_negative_sign(s.op(i)) ? 1 : 0;
        if (2 * neg > n) { sigma = -1; return m; }
        if (2 * neg < n) return s;
    }
    if (m.compare(s) < 0) { sigma = -1; return m; }
    return s;
}

}  // namespace

GiNaC::ex quasi_polynomial::to_ex() const {
    normalize();
    return real_form(terms_, true);
}

GiNaC::ex quasi_polynomial::to_ex_untidied() const {
    return raw_ ? real_form(merged_terms(), false) : real_form(terms_, true);
}

GiNaC::ex quasi_polynomial::real_form(const std::vector<qp_term>& terms, bool tidied) const {
    // tidied terms: their sum over one fraction (no gcd of the expanded products); raw ones:
    // one tidy of the sum (the terms were never brought to lowest terms)
    const auto fraction = [tidied](const ex& c) {
        if (const auto s = sum_of_fractions(c)) return *s;
        return tidied ? one_fraction(c) : tidy(c);
    };
    // one coefficient per real function t^k e^(a t) cos(b t), t^k e^(a t) sin(b t) (the terms of
    // lambda and its conjugate meet), each normalized once: not the whole sum expanded
    struct basis {
        unsigned k;
        ex a, b;
        ex cos_re = 0, sin_re = 0, cos_im = 0, sin_im = 0;
    };
    std::vector<basis> bs;
    for (const auto& u : terms) {
        int sg = 1;
        const ex b = canonical_frequency(u.lambda.im, sg);
        auto it = std::find_if(bs.begin(), bs.end(), [&](const basis& x) {
            return x.k == u.k && x.a.is_equal(u.lambda.re) && x.b.is_equal(b);
        });
        if (it == bs.end()) {
            bs.push_back({u.k, u.lambda.re, b});
            it = bs.end() - 1;
        }
        // c e^(i sg b t) = c (cos + i sg sin)
        it->cos_re += u.c.re;
        it->sin_re -= sg * u.c.im;
        it->cos_im += u.c.im;
        it->sin_im += sg * u.c.re;
    }
    ex re = 0, im = 0;
    for (const basis& x : bs) {
        const ex base = GiNaC::pow(t_, x.k) * GiNaC::exp(x.a * t_);
        const ex cs = x.b.is_zero() ? ex(1) : GiNaC::cos(x.b * t_), sn = GiNaC::sin(x.b * t_);
        re += base * (fraction(x.cos_re) * cs + (x.b.is_zero() ? ex(0) : fraction(x.sin_re) * sn));
        im += base * (fraction(x.cos_im) * cs + (x.b.is_zero() ? ex(0) : fraction(x.sin_im) * sn));
    }
    return im.is_zero() ? re : re + GiNaC::I * im;
}

cex quasi_polynomial::at_zero() const { return tidy_cex(at_zero_untidied()); }

cex quasi_polynomial::at_zero_untidied() const {
    // the sum of the t^0 coefficients, raw or normalized alike (no need to normalize first)
    cex r(ex(0), ex(0));
    for (const auto& u : terms_)
        if (u.k == 0) r += u.c;
    return r;
}

quasi_polynomial quasi_polynomial::derivative() const {
    quasi_polynomial r = *this;
    r.terms_.clear();
    for (const auto& u : terms_) {
        if (u.k > 0) r.add_term({ex(u.k) * u.c, u.k - 1, u.lambda});
        r.add_term({u.c * u.lambda, u.k, u.lambda});
    }
    return r;
}

namespace {

cex expand_cex(const cex& z) { return {GiNaC::expand(z.re), GiNaC::expand(z.im)}; }

// The terms of int_0^t tau^k e^(lambda tau) dtau with 1/lambda^(j+1) kept as
// conj(lambda)^(j+1) / |lambda|^(2(j+1)), the power of |lambda|^2 not expanded: the sums of
// such terms are brought to their form once, per function of t (real_form), and normal()
// of every power expanded (|lambda|^2)^(j+1) (60 % of a derivation with t^3 e^(-k t) forcing).
std::vector<qp_term> integral_monomial_terms(unsigned k, const cex& lambda) {
    if (is_zero_cex(lambda)) return {{cex(ex(1) / (k + 1), 0), k + 1, cex(0, 0)}};
    const char* where = "int_0^t tau^k e^(lambda tau) dtau";
    // 1/lambda = conj(lambda)/n: n = |lambda|^2, or b for lambda = i b, or a for lambda = a
    const bool imaginary = is_zero_scalar(lambda.re), real = is_zero_scalar(lambda.im);
    const ex n = real ? tidy(lambda.re) : imaginary ? tidy(lambda.im) : tidy(lambda.norm2());
    if (!is_nonzero_generic(n, std::string("division in ") + where))
        throw domain_error(std::string("division by an exact zero in ") + where);
    const cex conj_lambda = real ? cex(1, 0) : imaginary ? cex(0, -1) : expand_cex(lambda.conj());
    std::vector<qp_term> out;
    cex p = conj_lambda;  // conj(lambda)^(j+1)
    ex ff = 1;            // k!/(k-j)!
    for (unsigned j = 0; j <= k; ++j) {
        const ex s = (j % 2 == 0 ? ex(1) : ex(-1)) * ff * GiNaC::pow(n, -int(j + 1));
        const cex c(s * p.re, s * p.im);
        out.push_back({c, k - j, lambda});
        if (j == k) out.push_back({-c, 0, cex(0, 0)});
        ff = ff * ex(k - j);
        p = expand_cex(p * conj_lambda);
    }
    return out;
}

}  // namespace

quasi_polynomial integral_monomial(unsigned k, const cex& lambda, const GiNaC::ex& t) {
    quasi_polynomial r = quasi_polynomial::constant(0, t);
    for (const qp_term& w : integral_monomial_terms(k, lambda)) r = r + quasi_polynomial::monomial(w.c, w.k, w.lambda, t);
    return r;
}

quasi_polynomial quasi_polynomial::antiderivative() const {
    quasi_polynomial r = *this;
    r.terms_.clear();
    for (const auto& u : terms_) r = r + u.c * integral_monomial(u.k, u.lambda, t_);
    return r;
}

quasi_polynomial quasi_polynomial::subs(const ex& sym, const ex& s) const {
    if (has_t_ && contains(s, t_))
        throw domain_error("quasi_polynomial::subs: the replacement " + message_text(s) + " depends on " +
                           message_text(t_));
    quasi_polynomial r = *this;
    r.terms_.clear();
    auto sb = [&](const ex& e) { return tidy(e.subs(sym == s)); };
    try {
        for (const auto& u : terms_)
            r.add_term({{sb(u.c.re), sb(u.c.im)}, u.k, {sb(u.lambda.re), sb(u.lambda.im)}});
    } catch (const symrep::error&) {
        throw;
    } catch (const std::exception& e) {
        // e.g. 1/(a^2 + b^2) at a = b = 0: a value excluded by the generic reading
        throw domain_error("quasi_polynomial::subs: " + message_text(sym) + " = " + message_text(s) +
                           " is a value excluded by the generic reading of this closed form (" + e.what() +
                           "); rebuild it from the specialized integrand instead");
    }
    return r;
}

// --- arithmetic ---------------------------------------------------------------------

quasi_polynomial quasi_polynomial::operator-() const { return ex(-1) * *this; }

quasi_polynomial operator+(const quasi_polynomial& f, const quasi_polynomial& g) {
    quasi_polynomial r = f;
    r.adopt_variable(g);
    for (const auto& u : g.terms_) r.add_term(u);
    return r;
}

quasi_polynomial operator-(const quasi_polynomial& f, const quasi_polynomial& g) { return f + (-g); }

quasi_polynomial operator*(const quasi_polynomial& f, const quasi_polynomial& g) {
    quasi_polynomial r = f;
    r.adopt_variable(g);
    r.terms_.clear();
    for (const auto& u : f.terms_)
        for (const auto& v : g.terms_) r.add_term({u.c * v.c, u.k + v.k, u.lambda + v.lambda});
    return r;
}

quasi_polynomial operator*(const cex& s, const quasi_polynomial& f) {
    quasi_polynomial r = f;
    r.terms_.clear();
    for (const auto& u : f.terms_) r.add_term({s * u.c, u.k, u.lambda});
    return r;
}

quasi_polynomial operator*(const ex& s, const quasi_polynomial& f) {
    if (f.has_t_ && contains(s, f.t_))
        throw domain_error("scalar factor " + message_text(s) + " depends on " + message_text(f.t_) +
                           "; multiply quasi-polynomials instead");
    return split(s) * f;
}

quasi_polynomial convolution(const quasi_polynomial& f, const quasi_polynomial& g) {
    quasi_polynomial r = f;
    r.adopt_variable(g);
    r.terms_.clear();
    for (const auto& u : f.terms_)
        for (const auto& v : g.terms_) {
            const cex c = u.c * v.c, d = tidy_cex(u.lambda - v.lambda);
            for (unsigned i = 0; i <= v.k; ++i) {
                const ex s = binomial(v.k, i) * (i % 2 == 0 ? 1 : -1);
                // int_0^t tau^(u.k + i) e^(d tau) dtau times s c t^(v.k - i) e^(v.lambda t)
                for (const qp_term& w : integral_monomial_terms(u.k + i, d))
                    r.add_term({s * c * w.c, w.k + v.k - i, w.lambda + v.lambda});
            }
        }
    return r;
}

}  // namespace symrep::mechanics
