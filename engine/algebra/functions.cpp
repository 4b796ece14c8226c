// symrep/algebra/functions.cpp -- functions of an element by one general method:
// Hermite interpolation on the roots of the minimal polynomial.
//
// For w with minimal polynomial q (Cor. II.1.1), f(w) = p(w) where p is the real
// polynomial of degree < deg q that agrees with f to order m-1 at every root of
// multiplicity m (then f(w) - p(w) is divisible by q(w) = 0, II.1.12). The roots
// come from GiNaC's factorization of q over Q (symbolic coefficients allowed):
// linear factors give real roots, quadratic factors give a real pair or a
// complex pair a +- i b; at a complex pair the real conditions are
// Re, Im of p^{(j)}(a + i b) = f^{(j)}(a + i b). exp(w t) (Thm II.2.3) and log(w)
// are the two instances.
//
// Closed forms are refused (closed_form_error) for an irreducible factor of
// degree > 2 and for a quadratic factor whose discriminant has no decidable
// sign. Symbolic coefficients are read generically: a discriminant such as
// -4 a^2 (a a real symbol) is taken as negative, a pivot such as a - 1 as
// non-zero; the result then holds for the generic values of the symbols.
#include <map>
#include <sstream>

#include "algebra/algebra.h"
#include "scalar/cplx.h"
#include "algebra/exact_linear.h"
#include "scalar/scalar.h"
#include "core/error.h"

namespace symrep {

using GiNaC::ex;

namespace {

struct root {
    ex re, im;         // im == 0 for a real root; a complex pair is stored once (im != 0)
    unsigned mult;
    ex factor;         // the irreducible factor of q it comes from (for messages)
};

std::string str(const ex& e) { return message_text(e); }

bool has_free_symbols(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) return true;
    return false;
}

// Sign of an exact real expression: +1, -1, 0, or 2 when undecidable.
int sign_of(const ex& x) {
    const ex e = tidy(x);
    if (e.is_zero()) return 0;
    if (e.info(GiNaC::info_flags::positive)) return 1;
    if (e.info(GiNaC::info_flags::negative)) return -1;
    if (!has_free_symbols(e)) {
        const ex v = GiNaC::evalf(e);
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
            const GiNaC::numeric nv = GiNaC::ex_to<GiNaC::numeric>(v);
            if (nv.is_positive()) return 1;
            if (nv.is_negative()) return -1;
        }
        return 2;
    }
    // generic reading: a non-zero expression known to be >= 0 (e.g. a^2 for a
    // real symbol) is taken as positive
    if (e.info(GiNaC::info_flags::nonnegative)) return 1;
    if ((-e).info(GiNaC::info_flags::nonnegative)) return -1;
    return 2;
}

// Replaces the non-rational atoms of e (functions such as log(2) or exp(t),
// constants such as Pi, non-integer powers such as sqrt(2)) by temporary
// symbols, recording symbol -> atom in back, so that e becomes a polynomial
// over Q(symbols) that factor() understands.
ex atomize(const ex& e, std::map<ex, ex, GiNaC::ex_is_less>& seen, GiNaC::exmap& back) {
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e)) return e;
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e) ||
        (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
         GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer())) {
        GiNaC::exvector ops;
        for (std::size_t i = 0; i < e.nops(); ++i) ops.push_back(atomize(e.op(i), seen, back));
        if (GiNaC::is_a<GiNaC::add>(e)) return GiNaC::add(ops);
        if (GiNaC::is_a<GiNaC::mul>(e)) return GiNaC::mul(ops);
        return GiNaC::pow(ops[0], ops[1]);
    }
    auto it = seen.find(e);
    if (it != seen.end()) return it->second;
    const GiNaC::symbol s;
    seen.emplace(e, s);
    back[s] = e;
    return s;
}

// The roots of an irreducible monic cubic f = X^3 + a X^2 + b X + c (Cardano).
// With X = y - a/3 it is y^3 + p y + q, of discriminant -(4 p^3 + 27 q^2):
// * negative: one real root y1 = u - p/(3 u), u the real cube root of
//   -q/2 - sign(q) sqrt(q^2/4 + p^3/27) (the side without cancellation, u != 0),
//   and the pair of y^2 + y1 y + y1^2 + p: -y1/2 +- i sqrt(3 y1^2 + 4 p)/2;
// * positive (three real roots, casus irreducibilis; then p < 0):
//   y_k = 2 sqrt(-p/3) cos(theta/3 - 2 pi k/3), theta = acos(3 q/(2 p) sqrt(-3/p)).
// An undecidable sign (of the discriminant, or of q) is refused like a quadratic's.
std::vector<root> cubic_roots(const ex& f, const GiNaC::symbol& X, unsigned m, const std::string& where) {
    const ex a = f.coeff(X, 2), b = f.coeff(X, 1), c = f.coeff(X, 0);
    const ex p = tidy(b - a * a / 3), q = tidy(2 * a * a * a / 27 - a * b / 3 + c), shift = tidy(-a / 3);
    const ex disc = tidy(-(4 * p * p * p + 27 * q * q));
    const int sd = sign_of(disc);
    auto undecided = [&](const ex& what, const char* name) {
        return closed_form_error(where + ": the sign of the " + name + " " + str(what) + " of the cubic factor " +
                                 str(f) + " of the minimal polynomial cannot be decided, so Cardano's form of "
                                 "its roots cannot be chosen");
    };
    if (sd == 2) throw undecided(disc, "discriminant");
    if (sd < 0) {
        const int sq = q.is_zero() ? -1 : sign_of(q);
        if (sq == 2) throw undecided(q, "constant term of the depressed cubic");
        // u^3 = -q/2 - sign(q) sqrt(D0): |u|^3 = |q|/2 + sqrt(D0) > 0, sign(u) = -sign(q)
        const ex D0 = tidy(q * q / 4 + p * p * p / 27);
        const ex u = (sq > 0 ? -1 : 1) * GiNaC::pow(tidy(GiNaC::abs(q) / 2 + GiNaC::sqrt(D0)), GiNaC::numeric(1, 3));
        const ex y1 = tidy(canonical_radicals(u - p / (3 * u)));
        const ex im = tidy(canonical_radicals(GiNaC::sqrt(tidy(3 * y1 * y1 + 4 * p)) / 2));
        return {{tidy(y1 + shift), ex(0), m, f}, {tidy(-y1 / 2 + shift), im, m, f}};
    }
    // three distinct real roots (disc = 0 would make f reducible over Q)
    const ex r = 2 * GiNaC::sqrt(tidy(-p / 3));
    const ex theta = GiNaC::acos(tidy(3 * q / (2 * p) * GiNaC::sqrt(tidy(-3 / p))));
    std::vector<root> out;
    for (int k = 0; k < 3; ++k)
        out.push_back({tidy(r * GiNaC::cos(theta / 3 - 2 * k * GiNaC::Pi / 3) + shift), ex(0), m, f});
    return out;
}

// The roots of q (monic in X) with multiplicities, from its factorization over Q.
std::vector<root> roots_of(const ex& q, const GiNaC::symbol& X, const std::string& where) {
    // Non-polynomial atoms of the coefficients (log(2), Pi, sqrt(2), exp(t) ...)
    // become temporary symbols so that factor() can work over Q(symbols).
    GiNaC::exmap repl;
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    const ex qp = atomize(GiNaC::expand(q), seen, repl);
    // factor() works over Z: clear the denominators first
    ex fq = GiNaC::factor(GiNaC::expand(GiNaC::numer(GiNaC::normal(qp))));
    std::vector<std::pair<ex, unsigned>> factors;
    auto take = [&](const ex& f) {
        if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_pos_integer())
            factors.emplace_back(f.op(0), GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int());
        else
            factors.emplace_back(f, 1u);
    };
    if (GiNaC::is_a<GiNaC::mul>(fq))
        for (std::size_t i = 0; i < fq.nops(); ++i) take(fq.op(i));
    else
        take(fq);
    std::vector<root> roots;
    for (auto& [f0, m] : factors) {
        const ex fr = GiNaC::expand(f0.subs(repl));
        if (!fr.has(X)) continue;  // constant content
        const int d = fr.degree(X);
        // monic, so that the imaginary part b = sqrt(-disc)/2 of a pair is positive
        // and the closed forms do not depend on the sign factor() chose
        ex f = 0;
        const ex lc = fr.coeff(X, d);
        for (int k = 0; k <= d; ++k) f += tidy(fr.coeff(X, k) / lc) * GiNaC::pow(X, k);
        if (d == 1) {
            roots.push_back({tidy(-f.coeff(X, 0) / f.coeff(X, 1)), ex(0), m, f});
        } else if (d == 2) {
            const ex c2 = f.coeff(X, 2), c1 = f.coeff(X, 1), c0 = f.coeff(X, 0);
            const ex disc = tidy(c1 * c1 - 4 * c2 * c0);
            const ex a = tidy(-c1 / (2 * c2));
            switch (sign_of(disc)) {
                case 0: roots.push_back({a, ex(0), 2 * m, f}); break;
                case 1: {
                    const ex s = GiNaC::sqrt(disc) / (2 * c2);
                    roots.push_back({tidy(a + s), ex(0), m, f});
                    roots.push_back({tidy(a - s), ex(0), m, f});
                    break;
                }
                case -1: roots.push_back({a, tidy(GiNaC::sqrt(-disc) / (2 * c2)), m, f}); break;
                default:
                    throw closed_form_error(where + ": the sign of the discriminant " + str(disc) +
                                            " of the factor " + str(f) +
                                            " of the minimal polynomial cannot be decided, so its "
                                            "roots are neither known real nor known complex");
            }
        } else if (d == 3) {
            for (const root& r : cubic_roots(f, X, m, where)) roots.push_back(r);
        } else {
            throw closed_form_error(where + ": the minimal polynomial " + str(q) +
                                    " has the irreducible factor " + str(f) + " of degree " +
                                    std::to_string(d) +
                                    " > 2; its roots have no closed form usable here");
        }
    }
    return roots;
}

// Falling factorial k (k-1) ... (k-j+1).
long falling(long k, unsigned j) {
    long r = 1;
    for (unsigned i = 0; i < j; ++i) r *= (k - long(i));
    return r;
}

}  // namespace

// Hermite interpolation on the roots of the minimal polynomial (II.1.12, Cor. II.1.1).
coeffs algebra::apply_function(const coeffs& w, const scalar_function& f) const {
    check_size(w, f.name.c_str());
    const GiNaC::symbol X("X");
    const ex q = minpoly(w, X);
    const int N = q.degree(X);
    const std::string where = f.name + " in " + name();
    const std::vector<root> roots = roots_of(q, X, where);
    bool cubic = false, simple = true;
    for (const root& r : roots) {
        cubic = cubic || r.factor.degree(X) == 3;
        simple = simple && r.mult == 1;
    }
    if (cubic && simple) {
        // (II.1.12) with simple roots, Lagrange's form: p(X) = sum_z f(z) (q(X)/(X - z))/q'(z),
        // a pair a +- i b once as 2 Re. Each term stays as small as its root (Cardano's
        // radicals, cos(theta/3 - 2 pi k/3)), where the general linear system mixes them all.
        std::vector<ex> qc(N + 1);
        for (int k = 0; k <= N; ++k) qc[k] = q.coeff(X, k);
        std::vector<ex> c(N, ex(0));
        for (const root& r : roots) {
            const cplx<ex> z(r.re, r.im);
            // b_{N-1} = 1, b_{k-1} = q_k + z b_k (synthetic division); q'(z) by Horner
            std::vector<cplx<ex>> bq(N, cplx<ex>(ex(0), ex(0)));
            bq[N - 1] = cplx<ex>(ex(1), ex(0));
            for (int k = N - 1; k > 0; --k) {
                const cplx<ex> nb = z * bq[k] + cplx<ex>(qc[k], ex(0));
                bq[k - 1] = cplx<ex>(tidy(nb.re), tidy(nb.im));
            }
            cplx<ex> dq(ex(0), ex(0));
            for (int k = N; k >= 1; --k) {
                const cplx<ex> nd = dq * z + cplx<ex>(ex(k) * qc[k], ex(0));
                dq = cplx<ex>(tidy(nd.re), tidy(nd.im));
            }
            ex fre, fim;
            f.value(r.re, r.im, 0, fre, fim);
            // f(z)/q'(z)
            const ex den = tidy(dq.re * dq.re + dq.im * dq.im);
            const cplx<ex> w0(tidy((fre * dq.re + fim * dq.im) / den), tidy((fim * dq.re - fre * dq.im) / den));
            for (int k = 0; k < N; ++k) {
                const cplx<ex> term = w0 * bq[k];
                c[k] += r.im.is_zero() ? term.re : 2 * term.re;
            }
        }
        ex p = 0;
        for (int k = 0; k < N; ++k) p += tidy(c[k]) * GiNaC::pow(X, k);
        coeffs out = evaluate_polynomial(p, X, w);
        for (auto& x : out) x = tidy(x);
        return out;
    }
    // conditions: rows of A (coefficients of c_0..c_{N-1}) and right-hand sides
    std::vector<std::vector<ex>> A;
    std::vector<ex> b;
    for (const root& r : roots) {
        // powers z^p of z = re + i im, p = 0..N-1
        std::vector<cplx<ex>> zp{cplx<ex>(ex(1), ex(0))};
        const cplx<ex> z(r.re, r.im);
        for (int p = 1; p < N; ++p) {
            cplx<ex> nz = zp.back() * z;
            zp.emplace_back(tidy(nz.re), tidy(nz.im));
        }
        for (unsigned j = 0; j < r.mult; ++j) {
            ex fre, fim;
            f.value(r.re, r.im, j, fre, fim);
            std::vector<ex> row_re(N, ex(0)), row_im(N, ex(0));
            for (int k = int(j); k < N; ++k) {  // p^{(j)}(z) = sum_k c_k k!/(k-j)! z^{k-j}
                const long ff = falling(k, j);
                row_re[k] = ff * zp[k - j].re;
                row_im[k] = ff * zp[k - j].im;
            }
            A.push_back(std::move(row_re));
            b.push_back(fre);
            if (!r.im.is_zero()) {
                A.push_back(std::move(row_im));
                b.push_back(fim);
            }
        }
    }
    auto c = solve_linear(std::move(A), std::move(b));
    if (!c)
        throw closed_form_error(where + ": the Hermite interpolation conditions at the roots of " +
                                str(q) + " are singular (roots not distinct for these values)");
    ex p = 0;
    for (int k = 0; k < N; ++k) p += (*c)[k] * GiNaC::pow(X, k);
    coeffs r = evaluate_polynomial(p, X, w);
    for (auto& x : r) x = tidy(x);
    return r;
}

// Thm II.2.3: e^{w t} = sum_k w^k t^k / k!, by interpolation of f(lambda) = e^{lambda t}:
// f^{(j)}(a + i b) = t^j e^{a t} (cos bt + i sin bt).
coeffs algebra::exp(const coeffs& w, const ex& t) const {
    scalar_function f;
    f.name = "exp";
    f.value = [t](const ex& re, const ex& im, unsigned j, ex& out_re, ex& out_im) {
        const ex tj = GiNaC::pow(t, j) * exp_scalar(re * t);
        if (im.is_zero()) {
            out_re = tj;
            out_im = 0;
        } else {
            out_re = tj * GiNaC::cos(im * t);
            out_im = tj * GiNaC::sin(im * t);
        }
    };
    return apply_function(w, f);
}

// Principal logarithm: log(a + i b) = log|z| + i atan2(b, a); log^{(j)}(z) =
// (-1)^{j-1} (j-1)! / z^j. A root 0 makes w a zero divisor (II.1.22); a negative
// real root has no real logarithm.
coeffs algebra::log(const coeffs& w) const {
    scalar_function f;
    f.name = "log";
    const std::string nm = name();
    f.value = [nm](const ex& re, const ex& im, unsigned j, ex& out_re, ex& out_im) {
        if (im.is_zero()) {
            const int s = sign_of(re);
            if (s == 0)
                throw zero_divisor_error("log of a zero divisor in " + nm +
                                             ": 0 is a root of its minimal polynomial (II.1.22)",
                                         {});
            if (s == -1)
                throw domain_error("no real logarithm in " + nm + ": root " + str(re) +
                                   " of the minimal polynomial is negative");
            // s == 2 (symbolic): the result holds where the root is positive
            if (j == 0) out_re = GiNaC::log(re);
            else out_re = GiNaC::pow(-1, j - 1) * GiNaC::factorial(j - 1) / GiNaC::pow(re, j);
            out_im = 0;
            return;
        }
        if (j == 0) {
            out_re = GiNaC::log(re * re + im * im) / 2;
            out_im = GiNaC::atan2(im, re);
            return;
        }
        // 1/z^j = conj(z)^j / |z|^{2j}
        cplx<ex> zc(ex(1), ex(0));
        const cplx<ex> cz(re, -im);
        for (unsigned i = 0; i < j; ++i) zc = zc * cz;
        const ex scale = GiNaC::pow(-1, j - 1) * GiNaC::factorial(j - 1) /
                         GiNaC::pow(re * re + im * im, j);
        out_re = tidy(scale * zc.re);
        out_im = tidy(scale * zc.im);
    };
    return apply_function(w, f);
}

}  // namespace symrep
