// symrep/algebra/functions.cpp -- functions of an element by one general method:
// Hermite interpolation on the roots of the minimal polynomial.
//
// For w with minimal polynomial q (Cor. II.1.1), f(w) = p(w) where p is the real
// polynomial of degree < deg q that agrees with f to order m-1 at every root of
// multiplicity m (then f(w) - p(w) is divisible by q(w) = 0, II.1.12). The roots
// come from the factorization of q over Q (scalar/polynomial_roots.h; symbolic
// coefficients allowed): linear factors give real roots, quadratic factors a real
// pair or a complex pair a +- i b, cubic factors Cardano's form; at a complex pair
// the real conditions are
// Re, Im of p^{(j)}(a + i b) = f^{(j)}(a + i b). exp(w t) (Thm II.2.3) and log(w)
// are the two instances.
//
// Closed forms are refused (closed_form_error) for an irreducible factor of
// degree > 3 and for a quadratic or cubic factor whose discriminant has no
// decidable sign. Symbolic coefficients are read generically: a discriminant such as
// -4 a^2 (a a real symbol) is taken as negative, a pivot such as a - 1 as
// non-zero; the result then holds for the generic values of the symbols.
#include <map>
#include <sstream>

#include "symrep/algebra/algebra.h"
#include "symrep/scalar/cplx.h"
#include "symrep/scalar/polynomial_roots.h"
#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep {

using GiNaC::ex;

namespace {

using root = polynomial_root;

// The roots of q (monic in X) with multiplicities, from its factorization over Q
// (scalar/polynomial_roots.h: the quadratic formula and Cardano's form).
std::vector<root> roots_of(const ex& q, const GiNaC::symbol& X, const std::string& where) {
    return roots_in_radicals(q, X, where);
}

// e with each power of a non-integer exponent m/k written R^m, R a real symbol standing for
// base^(1/k), and each function call (exp, cos, ...) a real symbol (recorded in back:
// symbol -> value). Not atomize (scalar/polynomial_roots.h), which it resembles: here the
// symbols are real, constants such as pi stay, and base^(m/k) keeps its power m of one symbol
// per base^(1/k), so that the powers of one radical meet.
ex radicals_as_symbols(const ex& e, std::map<ex, ex, GiNaC::ex_is_less>& seen, GiNaC::exmap& back) {
    const auto symbol_for = [&](const ex& x) -> ex {
        auto it = seen.find(x);
        if (it != seen.end()) return it->second;
        const GiNaC::realsymbol R;
        seen.emplace(x, R);
        back[R] = x;
        return R;
    };
    if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::constant>(e)) return e;
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1))) {
        const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
        if (n.is_integer()) return GiNaC::pow(radicals_as_symbols(e.op(0), seen, back), e.op(1));
        if (n.is_rational()) return GiNaC::pow(symbol_for(GiNaC::pow(e.op(0), GiNaC::numeric(1, n.denom().to_int()))),
                                               n.numer());
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
        GiNaC::exvector ops;
        for (std::size_t i = 0; i < e.nops(); ++i) ops.push_back(radicals_as_symbols(e.op(i), seen, back));
        if (GiNaC::is_a<GiNaC::add>(e)) return GiNaC::add(ops);
        return GiNaC::mul(ops);
    }
    return symbol_for(e);
}

}  // namespace

namespace {

// Polynomials in X as coefficient lists (index = power).
using poly = std::vector<ex>;

poly poly_mul(const poly& a, const poly& b) {
    if (a.empty() || b.empty()) return {};
    poly c(a.size() + b.size() - 1, ex(0));
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
    for (ex& x : c) x = GiNaC::expand(x);
    return c;
}

// a mod F, F monic of degree d (the coefficients of a may hold functions of t: only the
// linear steps of the division, no normal()).
poly reduce_mod(poly a, const poly& F) {
    const std::size_t d = F.size() - 1;
    for (std::size_t k = a.size(); k-- > d;) {
        const ex lead = a[k];
        if (lead.is_zero()) continue;
        for (std::size_t i = 0; i <= d; ++i) a[k - d + i] = GiNaC::expand(a[k - d + i] - lead * F[i]);
    }
    a.resize(d, ex(0));
    return a;
}

// A^-1 mod F (F irreducible, A coprime to F): h with A h = 1 mod F, from the d x d system.
poly inverse_mod(const poly& A, const poly& F, const std::string& where) {
    const std::size_t d = F.size() - 1;
    std::vector<std::vector<ex>> M(d, std::vector<ex>(d, ex(0)));
    poly xj{ex(1)};
    for (std::size_t j = 0; j < d; ++j) {
        const poly col = reduce_mod(poly_mul(A, xj), F);
        for (std::size_t i = 0; i < d; ++i) M[i][j] = tidy(col[i]);
        xj.insert(xj.begin(), ex(0));
    }
    std::vector<ex> e(d, ex(0));
    e[0] = 1;
    const auto h = solve_linear(std::move(M), std::move(e));
    if (!h) throw closed_form_error(where + ": a factor of the minimal polynomial is not coprime to the rest");
    return *h;
}

poly coefficients_in(const ex& f, const GiNaC::symbol& X) {
    const ex e = GiNaC::expand(f);
    poly c(std::size_t(e.degree(X)) + 1, ex(0));
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = e.coeff(X, int(k));
    return c;
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

    // The interpolant of degree < n on the given roots (their multiplicities summing to n):
    // the linear system of Hermite's conditions Re, Im of p^{(j)}(z) = f^{(j)}(z).
    const auto hermite = [&](const std::vector<root>& rs, int n) {
        std::vector<std::vector<ex>> A;
        std::vector<ex> b;
        for (const root& r : rs) {
            // powers z^p of z = re + i im, p = 0..n-1
            std::vector<cplx<ex>> zp{cplx<ex>(ex(1), ex(0))};
            const cplx<ex> z(r.re, r.im);
            for (int p = 1; p < n; ++p) {
                cplx<ex> nz = zp.back() * z;
                zp.emplace_back(tidy(nz.re), tidy(nz.im));
            }
            for (unsigned j = 0; j < r.multiplicity; ++j) {
                ex fre, fim;
                f.value(r.re, r.im, j, fre, fim);
                std::vector<ex> row_re(n, ex(0)), row_im(n, ex(0));
                for (int k = int(j); k < n; ++k) {  // p^{(j)}(z) = sum_k c_k k!/(k-j)! z^{k-j}
                    const long ff = falling_factorial(k, j);
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
                                    message_text(q) + " are singular (roots not distinct for these values)");
        return *c;
    };

    std::vector<root> rest;
    std::vector<ex> cubics;  // the distinct cubic factors, each simple
    for (const root& r : roots) {
        if (r.factor.degree(X) != 3) {
            rest.push_back(r);
            continue;
        }
        if (r.multiplicity > 1)
            // Hermite's conditions on Cardano's radicals: refused at once
            throw closed_form_error(where + ": the cubic factor " + message_text(r.factor) +
                                    " of the minimal polynomial " + "is repeated (multiplicity " +
                                    std::to_string(r.multiplicity) +
                                    "); Hermite interpolation on Cardano's radicals is not done here");
        bool seen_factor = false;
        for (const ex& F : cubics) seen_factor = seen_factor || F.is_equal(r.factor);
        if (!seen_factor) cubics.push_back(r.factor);
    }
    if (cubics.empty()) {
        const std::vector<ex> c = hermite(roots, N);
        ex p = 0;
        for (int k = 0; k < N; ++k) p += c[k] * GiNaC::pow(X, k);
        coeffs r = evaluate_polynomial(p, X, w);
        for (auto& x : r) x = tidy(x);
        return r;
    }
    // (II.1.12) by the Chinese remainder theorem: q = G F_1 ... F_s with F_i the simple cubic
    // factors. p_G interpolates on the roots of G (the linear system above, no radicals of a
    // cubic in it); on each F, Lagrange's form p_F = sum_z f(z) (F(X)/(X - z))/F'(z), whose
    // coefficients b_k(z)/F'(z) are reduced modulo F to polynomials g_k of degree <= 2 in the
    // root (one exact form per factor, however the roots are written), a pair a +- i b once as
    // 2 Re; then p = p_M + M ((p_F - p_M) M^-1 mod F), M the modulus so far. The radicals and
    // functions of the roots (Cardano's cube root, sqrt(3), cos(theta/3)) are temporary real
    // symbols meanwhile (normal() then works on a few symbols instead of nested radicals); they
    // go back at the end.
    GiNaC::exmap back;
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    poly M{ex(1)}, P;
    {
        ex G = GiNaC::expand(q);
        for (const ex& F : cubics) G = GiNaC::quo(G, F, X);
        const int nG = G.degree(X);
        if (nG > 0) {
            P = hermite(rest, nG);
            for (ex& x : P) x = radicals_as_symbols(x, seen, back);
            M = coefficients_in(G, X);
        }
    }
    for (const ex& Fx : cubics) {
        const poly F = coefficients_in(Fx, X);
        // F(X)/(X - Z) = X^2 + (Z + F_2) X + (Z^2 + F_2 Z + F_1); H = 1/F'(Z) mod F
        const std::vector<poly> b{{F[1], F[2], ex(1)}, {F[2], ex(1)}, {ex(1)}};
        const poly H = inverse_mod({F[1], 2 * F[2], ex(3)}, F, where);
        std::vector<poly> g;
        for (const poly& bk : b) {
            poly gk = reduce_mod(poly_mul(bk, H), F);
            for (ex& x : gk) x = tidy(x);
            g.push_back(gk);
        }
        poly pF(3, ex(0));
        for (const root& r : roots) {
            if (!r.factor.is_equal(Fx)) continue;
            const cplx<ex> z(radicals_as_symbols(r.re, seen, back), radicals_as_symbols(r.im, seen, back));
            ex fre, fim;
            f.value(r.re, r.im, 0, fre, fim);
            const cplx<ex> fz(radicals_as_symbols(fre, seen, back), radicals_as_symbols(fim, seen, back));
            for (int k = 0; k < 3; ++k) {
                cplx<ex> gz(ex(0), ex(0)), zj(ex(1), ex(0));  // g_k(z) by its powers
                for (const ex& c : g[std::size_t(k)]) {
                    gz = gz + cplx<ex>(c, ex(0)) * zj;
                    zj = zj * z;
                }
                const cplx<ex> term = fz * gz;
                pF[std::size_t(k)] += GiNaC::expand(r.im.is_zero() ? term.re : 2 * term.re);
            }
        }
        // CRT: p = p_M + M ((p_F - p_M) M^-1 mod F)
        poly diff = pF;
        const poly PM = reduce_mod(P, F);
        for (std::size_t k = 0; k < diff.size() && k < PM.size(); ++k) diff[k] = diff[k] - PM[k];
        const poly D = reduce_mod(poly_mul(diff, inverse_mod(M, F, where)), F);
        const poly MD = poly_mul(M, D);
        P.resize(std::max(P.size(), MD.size()), ex(0));
        for (std::size_t k = 0; k < MD.size(); ++k) P[k] = GiNaC::expand(P[k] + MD[k]);
        M = poly_mul(M, F);
    }
    std::vector<ex> c(N, ex(0));
    for (std::size_t k = 0; k < P.size() && k < std::size_t(N); ++k) c[k] = P[k];
    coeffs out;
    if (is_power_basis_generator(w)) {  // the coordinates are the coefficients
        out.assign(c.begin(), c.end());
    } else {
        ex p = 0;
        for (int k = 0; k < N; ++k) p += c[k] * GiNaC::pow(X, k);
        out = evaluate_polynomial(p, X, w);
    }
    // the radicals' values put back as they are (tidy on the nested radicals would take
    // minutes and shorten nothing)
    for (auto& x : out) x = x.subs(back, GiNaC::subs_options::no_pattern);
    return out;
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
            const int s = sign_generic(re);
            if (s == 0)
                throw zero_divisor_error("log of a zero divisor in " + nm +
                                             ": 0 is a root of its minimal polynomial (II.1.22)",
                                         {});
            if (s == -1)
                throw domain_error("no real logarithm in " + nm + ": root " + message_text(re) +
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
