// symrep/scalar/polynomial_roots.cpp -- see polynomial_roots.h.
#include "symrep/scalar/polynomial_roots.h"

#include <map>

#include "symrep/core/error.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"

namespace symrep {

using GiNaC::ex;

bool has_radical(const ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
            !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_integer())
            return true;
    return false;
}

namespace {

// b or -b, whichever is positive at the generic point (b itself when that is not decided):
// the sign of a square root's factor does not depend on GiNaC's term order.
ex canonical_sign(const ex& b) {
    const point_value v = value_at_generic_point(b);
    if (v.ok && v.high.is_real() && v.high.is_negative()) return -b;
    return b;
}

// sqrt of a polynomial over Q(atoms): the integer content's square part and the square
// factors out, without their sign.
ex sqrt_polynomial(const ex& e) {
    const ex ee = GiNaC::expand(e);
    if (GiNaC::is_a<GiNaC::numeric>(ee)) return GiNaC::sqrt(ee);  // exact: sqrt(-4) = 2 I, sqrt(8) = 2 sqrt(2)
    GiNaC::exmap back;
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    const ex f = GiNaC::factor(GiNaC::expand(atomize(ee, seen, back)));
    ex out = 1, numeric_part = 1, rest = 1;
    for (const auto& [b, m] : factors_of(f)) {
        if (GiNaC::is_a<GiNaC::numeric>(b)) {
            numeric_part *= GiNaC::pow(b, m);
            continue;
        }
        if (m / 2) out *= GiNaC::pow(canonical_sign(b.subs(back)), m / 2);
        if (m % 2) rest *= b;
    }
    // a negative content stays under the root: sqrt(u^2 + v^2) must not become
    // I sqrt(-u^2 - v^2) when factor() chose the other sign
    if (GiNaC::ex_to<GiNaC::numeric>(numeric_part).is_negative()) {
        numeric_part = -numeric_part;
        rest = -rest;
    }
    return GiNaC::sqrt(numeric_part) * out * GiNaC::sqrt(GiNaC::expand(rest.subs(back)));
}

// The roots of the monic irreducible cubic f = X^3 + a X^2 + b X + c (Cardano).
// With X = y - a/3 it is y^3 + p y + q, of discriminant -(4 p^3 + 27 q^2):
// * negative: one real root y1 = u - p/(3 u), u the real cube root of
//   -q/2 - sign(q) sqrt(q^2/4 + p^3/27) (the side without cancellation, u != 0),
//   and the pair of y^2 + y1 y + y1^2 + p: -y1/2 +- i sqrt(3)/2 (u + p/(3 u));
// * positive (three real roots, casus irreducibilis; then p < 0):
//   y_k = 2 sqrt(-p/3) cos(theta/3 - 2 pi k/3), theta = acos(3 q/(2 p) sqrt(-3/p)).
// An undecidable sign (of the discriminant, or of q) is refused like a quadratic's.
std::vector<polynomial_root> cubic_roots(const ex& f, const GiNaC::symbol& X, unsigned m, const std::string& where) {
    const ex a = f.coeff(X, 2), b = f.coeff(X, 1), c = f.coeff(X, 0);
    const ex p = tidy(b - a * a / 3), q = tidy(2 * a * a * a / 27 - a * b / 3 + c), shift = tidy(-a / 3);
    const ex disc = tidy(-(4 * p * p * p + 27 * q * q));
    const int sd = sign_generic(disc);
    auto undecided = [&](const ex& what, const char* name) {
        return closed_form_error(where + ": the sign of the " + name + " " + message_text(what) +
                                 " of the cubic factor " + message_text(f) +
                                 " cannot be decided, so Cardano's form of its roots cannot be chosen");
    };
    if (sd == 2) throw undecided(disc, "discriminant");
    if (sd < 0) {
        const int sq = q.is_zero() ? -1 : sign_generic(q);
        if (sq == 2) throw undecided(q, "constant term of the depressed cubic");
        // u^3 = -q/2 - sign(q) sqrt(D0): |u|^3 = |q|/2 + sqrt(D0) > 0, sign(u) = -sign(q)
        const ex D0 = tidy(q * q / 4 + p * p * p / 27);
        const ex u = (sq > 0 ? -1 : 1) * GiNaC::pow(tidy(GiNaC::abs(q) / 2 + GiNaC::sqrt(D0)), GiNaC::numeric(1, 3));
        // the roots w^k u - p/(3 w^k u), w = e^(2 pi i/3): the pair's imaginary part is
        // sqrt(3)/2 (u + p/(3 u)) (3 y1^2 + 4 p = 3 (u + p/(3 u))^2), its sign free
        // (not normalized: normal() would split the cube root's base into several radicals)
        const ex y1 = u - p / (3 * u);
        const ex im = GiNaC::sqrt(ex(3)) / 2 * (u + p / (3 * u));
        return {{(y1 + shift).expand(), ex(0), m, f}, {(-y1 / 2 + shift).expand(), im.expand(), m, f}};
    }
    // three distinct real roots (disc = 0 would make f reducible over Q)
    const ex r = 2 * GiNaC::sqrt(tidy(-p / 3));
    const ex theta = GiNaC::acos(tidy(3 * q / (2 * p) * GiNaC::sqrt(tidy(-3 / p))));
    std::vector<polynomial_root> out;
    for (int k = 0; k < 3; ++k)
        out.push_back({tidy(r * GiNaC::cos(theta / 3 - 2 * k * GiNaC::Pi / 3) + shift), ex(0), m, f});
    return out;
}

}  // namespace

// The non-rational atoms of e (functions such as log(2), constants such as pi, non-integer
// powers such as sqrt(2)) replaced by temporary symbols (symbol -> atom recorded in back), so
// that e is a polynomial over Q(symbols) that factor() understands.
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

// f as its factors with multiplicities (a power with a positive integer exponent split).
std::vector<std::pair<ex, unsigned>> factors_of(const ex& f) {
    std::vector<std::pair<ex, unsigned>> out;
    auto take = [&](const ex& u) {
        if (GiNaC::is_a<GiNaC::power>(u) && GiNaC::is_a<GiNaC::numeric>(u.op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(u.op(1)).is_pos_integer())
            out.emplace_back(u.op(0), unsigned(GiNaC::ex_to<GiNaC::numeric>(u.op(1)).to_int()));
        else
            out.emplace_back(u, 1u);
    };
    if (GiNaC::is_a<GiNaC::mul>(f))
        for (std::size_t i = 0; i < f.nops(); ++i) take(f.op(i));
    else
        take(f);
    return out;
}

int sign_generic(const ex& x) {
    const ex e = tidy(x);
    if (e.is_zero()) return 0;
    if (e.info(GiNaC::info_flags::positive)) return 1;
    if (e.info(GiNaC::info_flags::negative)) return -1;
    if (!has_symbol(e)) {
        const ex v = GiNaC::evalf(e);
        if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
            const GiNaC::numeric nv = GiNaC::ex_to<GiNaC::numeric>(v);
            if (nv.is_positive()) return 1;
            if (nv.is_negative()) return -1;
        }
        return 2;
    }
    // generic reading: a non-zero expression known to be >= 0 (e.g. a^2 for a real symbol)
    // is taken as positive
    if (e.info(GiNaC::info_flags::nonnegative)) return 1;
    if ((-e).info(GiNaC::info_flags::nonnegative)) return -1;
    return 2;
}

std::vector<polynomial_factor> rational_factors(const ex& q, const GiNaC::symbol& X) {
    GiNaC::exmap back;
    std::map<ex, ex, GiNaC::ex_is_less> seen;
    const ex qa = atomize(GiNaC::expand(q), seen, back);
    // factor() works over Z: clear the denominators first
    const ex fq = GiNaC::factor(GiNaC::expand(GiNaC::numer(GiNaC::normal(qa))));
    std::vector<polynomial_factor> out;
    for (const auto& [f0, m] : factors_of(fq)) {
        const ex fr = GiNaC::expand(f0.subs(back));
        if (!fr.has(X)) continue;  // constant content
        const int d = fr.degree(X);
        // monic, so that the closed forms do not depend on the sign factor() chose
        const ex lc = fr.coeff(X, d);
        ex f = 0;
        for (int k = 0; k <= d; ++k) f += tidy(fr.coeff(X, k) / lc) * GiNaC::pow(X, k);
        out.push_back({f, m});
    }
    return out;
}

ex sign_free_sqrt(const ex& x) {
    const ex n = GiNaC::normal(x);
    if (GiNaC::is_a<GiNaC::numeric>(n)) return GiNaC::sqrt(n);
    return tidy(canonical_radicals(sqrt_polynomial(GiNaC::numer(n)) / sqrt_polynomial(GiNaC::denom(n))));
}

int discriminant_sign(const ex& disc) {
    const int sign = sign_generic(disc);
    if (sign != 2) return sign;
    // generic reading: a (minus a) square of an expression free of radicals and of I,
    // such as -4 (w0 - W)^2, is read as negative (positive)
    const auto is_square = [](const ex& r) { return !has_radical(r) && !r.has(GiNaC::I); };
    if (is_square(sign_free_sqrt(tidy(-disc)))) return -1;
    if (is_square(sign_free_sqrt(disc))) return 1;
    return 2;
}

std::vector<polynomial_root> factor_roots(const ex& f, const GiNaC::symbol& X, unsigned m, const std::string& where,
                                          bool undecided_as_pair) {
    const int d = f.degree(X);
    if (d == 1) return {{tidy(-f.coeff(X, 0) / f.coeff(X, 1)), ex(0), m, f}};
    if (d == 2) {
        const ex c2 = f.coeff(X, 2), c1 = f.coeff(X, 1), c0 = f.coeff(X, 0);
        const ex disc = tidy(c1 * c1 - 4 * c2 * c0);
        const ex a = tidy(-c1 / (2 * c2));
        int sign = discriminant_sign(disc);
        if (sign == 2 && undecided_as_pair) sign = -1;
        switch (sign) {
            case 0: return {{a, ex(0), 2 * m, f}};
            case 1: {
                const ex s = tidy(sign_free_sqrt(disc) / (2 * c2));
                return {{tidy(a + s), ex(0), m, f}, {tidy(a - s), ex(0), m, f}};
            }
            case -1: return {{a, tidy(sign_free_sqrt(tidy(-disc)) / (2 * c2)), m, f}};
            default:
                throw closed_form_error(where + ": the sign of the discriminant " + message_text(disc) +
                                        " of the factor " + message_text(f) +
                                        " cannot be decided, so its roots are neither known real nor known complex");
        }
    }
    if (d == 3) return cubic_roots(f, X, m, where);
    throw closed_form_error(where + ": the irreducible factor " + message_text(f) + " has degree " +
                            std::to_string(d) + " > 3; its roots have no closed form here (only degrees 1, 2 and 3)");
}

std::vector<polynomial_root> roots_in_radicals(const ex& q, const GiNaC::symbol& X, const std::string& where) {
    const auto factors = rational_factors(q, X);
    // a factor of degree >= 4 is refused before any root is formed
    for (const auto& f : factors)
        if (f.f.degree(X) > 3) (void)factor_roots(f.f, X, f.multiplicity, where);
    std::vector<polynomial_root> roots;
    for (const auto& f : factors)
        for (const polynomial_root& r : factor_roots(f.f, X, f.multiplicity, where)) roots.push_back(r);
    return roots;
}

}  // namespace symrep
