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

#include "algebra/algebra.h"
#include "scalar/cplx.h"
#include "scalar/polynomial_roots.h"
#include "algebra/exact_linear.h"
#include "scalar/scalar.h"
#include "core/error.h"

namespace symrep {

using GiNaC::ex;

namespace {

using root = polynomial_root;

std::string str(const ex& e) { return message_text(e); }

int sign_of(const ex& x) { return sign_generic(x); }

// The roots of q (monic in X) with multiplicities, from its factorization over Q
// (scalar/polynomial_roots.h: the quadratic formula and Cardano's form).
std::vector<root> roots_of(const ex& q, const GiNaC::symbol& X, const std::string& where) {
    return roots_in_radicals(q, X, where);
}

// e with each power of a non-integer exponent m/k written R^m, R a real symbol standing for
// base^(1/k), and each function call (exp, cos, ...) a real symbol (recorded in back:
// symbol -> value).
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
        simple = simple && r.multiplicity == 1;
    }
    if (cubic && !simple) {
        // Hermite's conditions on Cardano's radicals: a linear system that does not finish in
        // minutes; refused at once
        for (const root& r : roots)
            if (r.factor.degree(X) == 3 && r.multiplicity > 1)
                throw closed_form_error(where + ": the cubic factor " + str(r.factor) + " of the minimal polynomial " +
                                        "is repeated (multiplicity " + std::to_string(r.multiplicity) +
                                        "); Hermite interpolation on Cardano's radicals is not done here");
    }
    if (cubic && simple) {
        // (II.1.12) with simple roots, Lagrange's form: p(X) = sum_z f(z) (q(X)/(X - z))/q'(z),
        // a pair a +- i b once as 2 Re. Each term stays as small as its root (Cardano's
        // radicals, cos(theta/3 - 2 pi k/3)), where the general linear system mixes them all.
        // The radicals and functions of the roots (Cardano's cube root, sqrt(3), cos(theta/3))
        // are temporary real symbols while q'(z) and q(X)/(X - z) are formed: normal() then
        // works on rational functions of a few symbols instead of nested radicals (seconds
        // instead of minutes for a cubic times a quadratic); they go back at the end.
        GiNaC::exmap back;
        std::map<ex, ex, GiNaC::ex_is_less> seen;
        std::vector<ex> qc(N + 1);
        for (int k = 0; k <= N; ++k) qc[k] = q.coeff(X, k);
        std::vector<ex> c(N, ex(0));
        for (const root& r : roots) {
            const cplx<ex> z(radicals_as_symbols(r.re, seen, back), radicals_as_symbols(r.im, seen, back));
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
            f.value(r.re, r.im, 0, fre, fim);  // at the root itself (log decides its sign there)
            fre = radicals_as_symbols(fre, seen, back);
            fim = radicals_as_symbols(fim, seen, back);
            // the term f(z) g_k(z), g_k = b_k/q'(z): the numbers g_k tidied one by one, f(z)
            // (a symbol) kept outside (one fraction of all terms would cost minutes)
            const ex den = tidy(dq.re * dq.re + dq.im * dq.im);
            for (int k = 0; k < N; ++k) {
                const ex gre = tidy((bq[k].re * dq.re + bq[k].im * dq.im) / den);
                const ex gim = tidy((bq[k].im * dq.re - bq[k].re * dq.im) / den);
                const ex term = fre * gre - fim * gim;  // Re(f(z) g_k(z))
                c[k] += r.im.is_zero() ? term : 2 * term;
            }
        }
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
        for (unsigned j = 0; j < r.multiplicity; ++j) {
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
