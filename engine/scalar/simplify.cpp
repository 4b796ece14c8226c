// symrep/scalar/simplify.cpp -- tidy, trigonometric signs, arctangents, exp and log of scalars (scalar.h).
#include "symrep/scalar/scalar.h"
#include "symrep/scalar/small_primes.h"
#include "symrep/scalar/equality.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

GiNaC::ex trig_of_arctangents(const GiNaC::ex& e) {
    // one pass to see whether there is anything to do (tidy() calls this on every result)
    bool any = false;
    for (auto it = e.preorder_begin(); it != e.preorder_end() && !any; ++it)
        any = GiNaC::is_the_function<GiNaC::atan2_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::atan_SERIAL>(*it);
    if (!any) return e;
    struct rewrite : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            const bool s = GiNaC::is_the_function<GiNaC::sin_SERIAL>(y), c = GiNaC::is_the_function<GiNaC::cos_SERIAL>(y),
                       t = GiNaC::is_the_function<GiNaC::tan_SERIAL>(y);
            if (!s && !c && !t) return y;
            GiNaC::ex a = y.op(0), sign = 1;
            if (GiNaC::is_a<GiNaC::mul>(a) && a.nops() == 2 && a.op(1).is_equal(-1)) {  // sin(-u) = -sin(u)
                a = a.op(0);
                sign = c ? 1 : -1;
            }
            GiNaC::ex num, den;  // the tangent of the angle a is num/den, with den > 0 or num/den real
            if (GiNaC::is_the_function<GiNaC::atan2_SERIAL>(a)) {
                num = a.op(0);
                den = a.op(1);
            } else if (GiNaC::is_the_function<GiNaC::atan_SERIAL>(a) && !a.op(0).has(GiNaC::I)) {
                num = a.op(0);
                den = 1;
            } else {
                return y;
            }
            if (t) return sign * num / den;
            const GiNaC::ex r = GiNaC::sqrt(GiNaC::expand(num * num + den * den));
            return sign * (s ? num : den) / r;
        }
    } f;
    return f(e);
}

bool has_symbol(const GiNaC::ex& x) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) return true;
    return false;
}

std::vector<GiNaC::ex> symbols_by_name(const std::vector<GiNaC::ex>& xs) {
    std::vector<GiNaC::ex> out;
    for (const GiNaC::ex& x : xs)
        for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it) &&
                std::none_of(out.begin(), out.end(), [&](const GiNaC::ex& o) { return o.is_equal(*it); }))
                out.push_back(*it);
    std::sort(out.begin(), out.end(), [](const GiNaC::ex& a, const GiNaC::ex& b) {
        return GiNaC::ex_to<GiNaC::symbol>(a).get_name() < GiNaC::ex_to<GiNaC::symbol>(b).get_name();
    });
    return out;
}

std::pair<GiNaC::numeric, GiNaC::ex> split_numeric_factor(const GiNaC::ex& term) {
    GiNaC::numeric c = 1;
    GiNaC::ex rest = 1;
    for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++j) {
        const GiNaC::ex x = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
        if (GiNaC::is_a<GiNaC::numeric>(x)) c *= GiNaC::ex_to<GiNaC::numeric>(x);
        else rest *= x;
    }
    return {c, rest};
}

bool has_function_call(const GiNaC::ex& x) {
    if (GiNaC::is_a<GiNaC::function>(x)) return true;
    for (std::size_t k = 0; k < x.nops(); ++k)
        if (has_function_call(x.op(k))) return true;
    return false;
}

bool has_negative_sign(const GiNaC::ex& a) {
    if (GiNaC::is_a<GiNaC::numeric>(a)) return GiNaC::ex_to<GiNaC::numeric>(a).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(a))
        for (std::size_t k = 0; k < a.nops(); ++k)
            if (GiNaC::is_a<GiNaC::numeric>(a.op(k)))
                return GiNaC::ex_to<GiNaC::numeric>(a.op(k)).is_negative();
    return false;
}

namespace {

std::string text_of(const GiNaC::ex& e) {
    std::ostringstream os;
    os << e;
    return os.str();
}

/// The text of a monomial whose factors are sorted by their own text (GiNaC's
/// order of factors follows hash values, which differ between runs).
std::string monomial_text(const GiNaC::ex& m) {
    std::vector<std::string> f;
    if (GiNaC::is_a<GiNaC::mul>(m))
        for (std::size_t i = 0; i < m.nops(); ++i) f.push_back(text_of(m.op(i)));
    else
        f.push_back(text_of(m));
    std::sort(f.begin(), f.end());
    std::string s;
    for (const std::string& x : f) s += (s.empty() ? "" : "*") + x;
    return s;
}

/// The sign of u in a form that depends only on the mathematics: the sign of the
/// coefficient of the leading monomial of expand(u) (highest total degree, then
/// the smallest text), so that (x2 - x1) t and -(x1 - x2) t get the same answer.
bool canonical_negative(const GiNaC::ex& u) {
    const GiNaC::ex e = GiNaC::expand(u);
    if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).is_negative();
    bool found = false, negative = false;
    int best_degree = 0;
    std::string best_text;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const GiNaC::ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        GiNaC::numeric c = 1;
        GiNaC::ex rest = term;
        if (GiNaC::is_a<GiNaC::numeric>(term)) {
            c = GiNaC::ex_to<GiNaC::numeric>(term);
            rest = 1;
        } else if (GiNaC::is_a<GiNaC::mul>(term)) {
            const GiNaC::ex last = term.op(term.nops() - 1);
            if (GiNaC::is_a<GiNaC::numeric>(last)) {
                c = GiNaC::ex_to<GiNaC::numeric>(last);
                rest = term / last;
            }
        }
        int deg = 0;  // the number of symbol occurrences: the total degree for monomials
        for (auto it = rest.preorder_begin(); it != rest.preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it)) ++deg;
        const std::string t = monomial_text(rest);
        if (!found || deg > best_degree || (deg == best_degree && t < best_text)) {
            found = true;
            best_degree = deg;
            best_text = t;
            negative = c.is_negative() || (!c.is_real() && c.real().is_negative());
        }
    }
    return negative;
}

}  // namespace

GiNaC::ex normalize_trig_signs(const GiNaC::ex& e) {
    struct trig_sign : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (GiNaC::is_a<GiNaC::function>(y) && y.nops() == 1 && canonical_negative(y.op(0))) {
                const std::string f = GiNaC::ex_to<GiNaC::function>(y).get_name();
                if (f == "cos") return GiNaC::cos(-y.op(0));
                if (f == "sin") return -GiNaC::sin(-y.op(0));
            }
            return y;
        }
    } m;
    return m(e);
}

namespace {

/// True when x holds a power of a rational number with a non-integer exponent (sqrt(12)).
bool has_rational_radical(const GiNaC::ex& x) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(0)) &&
            GiNaC::is_a<GiNaC::numeric>(it->op(1)) && !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_integer())
            return true;
    return false;
}

/// n = a^2 b with b free of the squares of primes below 2^16; the larger cofactor over the
/// coprime base of the expression's radicands (`bases`, refine_cofactors), its squares taken
/// out (without a base: out only when it is a perfect square itself).
void square_part(GiNaC::numeric n, GiNaC::numeric& a, GiNaC::numeric& b, const cofactor_bases& bases) {
    a = 1;
    b = 1;
    const small_factorization f = small_prime_factors(n);
    for (const auto& [p, k] : f.factors) {
        const GiNaC::numeric pp(p);
        for (int i = 0; i + 1 < k; i += 2) a *= pp;
        if (k % 2) b *= pp;
    }
    n = f.cofactor;
    if (n > 1 && !bases.empty()) {
        // a product of the cofactors: over their (pairwise coprime) base
        std::set<GiNaC::numeric, numeric_less> roots;
        for (const auto& [c, over] : bases)
            for (const auto& [q, k] : over) roots.insert(q);
        GiNaC::numeric rest = n, inside = 1, outside = 1;
        for (const GiNaC::numeric& q : roots) {
            long k = 0;
            while (GiNaC::irem(rest, q).is_zero()) {
                rest = GiNaC::iquo(rest, q);
                ++k;
            }
            for (long i = 0; i + 1 < k; i += 2) outside *= q;
            if (k % 2) inside *= q;
        }
        if (rest == 1) {
            a *= outside;
            b *= inside;
            return;
        }
    }
    const GiNaC::numeric r = GiNaC::isqrt(n);
    if (r * r == n) a *= r;
    else b *= n;
}

}  // namespace

// sqrt(12) = 2 sqrt(3), sqrt(26) sqrt(34) = 2 sqrt(221), sqrt(1/2) = sqrt(2)/2: the
// half-integer powers of positive rationals in each product made one c sqrt(b),
// b a square-free integer.
GiNaC::ex canonical_radicals(const GiNaC::ex& e) {
    struct radicals : GiNaC::map_function {
        cofactor_bases bases;
        static bool half_power(const GiNaC::ex& f) {
            if (!GiNaC::is_a<GiNaC::power>(f) || !GiNaC::is_a<GiNaC::numeric>(f.op(0)) ||
                !GiNaC::is_a<GiNaC::numeric>(f.op(1)))
                return false;
            const GiNaC::numeric& b = GiNaC::ex_to<GiNaC::numeric>(f.op(0));
            const GiNaC::numeric& k = GiNaC::ex_to<GiNaC::numeric>(f.op(1));
            return b.is_rational() && b.is_positive() && !k.is_integer() && (2 * k).is_integer();
        }
        std::optional<GiNaC::ex> combine(const std::vector<GiNaC::ex>& factors) {
            GiNaC::ex rest = 1;
            GiNaC::numeric S = 1, outside = 1;  // the product is outside * S^(1/2) * rest
            bool any = false;
            for (const GiNaC::ex& f : factors) {
                if (!half_power(f)) {
                    rest *= f;
                    continue;
                }
                any = true;
                const GiNaC::numeric b = GiNaC::ex_to<GiNaC::numeric>(f.op(0));
                const GiNaC::numeric k2 = 2 * GiNaC::ex_to<GiNaC::numeric>(f.op(1));  // odd
                const GiNaC::numeric whole = (k2 - 1) / 2;                          // b^(k2/2) = b^whole sqrt(b)
                outside *= GiNaC::pow(b, whole);
                S *= b;
            }
            if (!any) return std::nullopt;
            const GiNaC::numeric P = S.numer(), Q = S.denom();
            GiNaC::numeric a, sq;
            square_part(P * Q, a, sq, bases);  // sqrt(P/Q) = sqrt(P Q)/Q = a sqrt(sq)/Q
            return rest * outside * a / Q * GiNaC::sqrt(GiNaC::ex(sq));
        }
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (GiNaC::is_a<GiNaC::mul>(y)) {
                std::vector<GiNaC::ex> f;
                for (std::size_t i = 0; i < y.nops(); ++i) f.push_back(y.op(i));
                const std::optional<GiNaC::ex> c = combine(f);
                return c ? *c : y;
            }
            if (half_power(y)) return *combine({y});
            return y;
        }
    } m;
    m.bases = refine_cofactors(e);
    return m(e);
}

namespace {
/// A power with a negative or non-numeric exponent anywhere in e.
bool has_denominator(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it)) {
            const GiNaC::ex& k = it->op(1);
            if (!GiNaC::is_a<GiNaC::numeric>(k) || GiNaC::ex_to<GiNaC::numeric>(k).is_negative()) return true;
        }
    return false;
}
}  // namespace

GiNaC::ex tidy(const GiNaC::ex& x) {
    guard_expansion(x, "simplification", false);
    // radicals of rationals in one form: sqrt(12) is 2 sqrt(3), so that it meets sqrt(3)
    const GiNaC::ex r = has_rational_radical(x) ? canonical_radicals(x) : x;
    const GiNaC::ex e = GiNaC::expand(trig_of_arctangents(r));
    if (has_function_call(e)) return GiNaC::expand(normalize_trig_signs(e));
    guard_expansion(e, "simplification", true);
    // an expanded polynomial in its atoms (no negative or symbolic power anywhere, roots of
    // polynomials included) is already in normal form: normal() would only rebuild it
    // (most of the solver's time went to that on the exponents and coefficients)
    if (!has_denominator(e)) return e;
    return GiNaC::normal(e);
}

GiNaC::ex one_fraction(const GiNaC::ex& x) {
    if (has_function_call(x)) return tidy(x);
    // the polynomial bases of negative powers, up to sign, as fresh symbols
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> bases;  // (expanded base, symbol)
    GiNaC::exmap to_symbol, back;
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::power>(*it) || !GiNaC::is_a<GiNaC::add>(it->op(0)) ||
            !GiNaC::is_a<GiNaC::numeric>(it->op(1)) || !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_negative())
            continue;
        const GiNaC::ex b = it->op(0);
        if (to_symbol.count(b)) continue;
        const GiNaC::ex e = GiNaC::expand(b);
        GiNaC::ex sym;
        for (const auto& [f, s] : bases) {
            if (f.is_equal(e)) sym = s;
            else if (GiNaC::expand(f + e).is_zero()) sym = -s;
            if (!sym.is_zero()) break;
        }
        if (sym.is_zero()) {
            sym = GiNaC::symbol();
            bases.push_back({e, sym});
            back[sym] = e;
        }
        to_symbol[b] = sym;
    }
    if (bases.empty()) return tidy(x);
    const GiNaC::ex y = GiNaC::normal(GiNaC::expand(x.subs(to_symbol, GiNaC::subs_options::no_pattern)));
    return y.subs(back, GiNaC::subs_options::no_pattern);
}

namespace {

// Only symbols, rationals, sums, products and integer powers: a rational function with rational
// coefficients (GiNaC's info_flags::rational_function also takes floats and I, which divide()
// and the exact expansions below must not meet).
bool is_rational_function_of_symbols(const GiNaC::ex& x) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it) {
        if (GiNaC::is_a<GiNaC::symbol>(*it) || GiNaC::is_a<GiNaC::add>(*it) || GiNaC::is_a<GiNaC::mul>(*it))
            continue;
        if (GiNaC::is_a<GiNaC::numeric>(*it)) {
            if (!GiNaC::ex_to<GiNaC::numeric>(*it).is_rational()) return false;
            continue;
        }
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
            GiNaC::ex_to<GiNaC::numeric>(it->op(1)).is_integer())
            continue;
        return false;
    }
    return true;
}

std::size_t node_count(const GiNaC::ex& x) {
    std::size_t n = 0;
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it) ++n;
    return n;
}

// The terms of an expanded rational function by their polynomial denominator factors: the
// factors (sums, expanded, identified up to sign) and, per product of their powers, the sum
// of the terms' other factors (numerators over monomial denominators).
struct denominator_groups {
    std::vector<GiNaC::ex> bases;
    std::map<std::map<std::size_t, int>, GiNaC::ex> groups;  // factor -> power: numerator
};

denominator_groups group_by_denominator(const GiNaC::ex& e) {
    denominator_groups out;
    auto& bases = out.bases;
    const auto add_term = [&](const GiNaC::ex& term) {
        GiNaC::ex num = 1;
        std::map<std::size_t, int> den;
        const auto factor = [&](const GiNaC::ex& f) {
            if (!GiNaC::is_a<GiNaC::power>(f) || !GiNaC::is_a<GiNaC::add>(f.op(0)) ||
                !GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_negative()) {
                num *= f;
                return;
            }
            const GiNaC::ex b = GiNaC::expand(f.op(0));
            const int k = -GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
            std::size_t i = 0;
            for (; i < bases.size(); ++i) {
                if (bases[i].is_equal(b)) break;
                if (GiNaC::expand(bases[i] + b).is_zero()) {
                    if (k % 2) num = -num;
                    break;
                }
            }
            if (i == bases.size()) bases.push_back(b);
            den[i] += k;
        };
        if (GiNaC::is_a<GiNaC::mul>(term))
            for (const auto& f : term) factor(f);
        else
            factor(term);
        out.groups[den] += num;
    };
    if (GiNaC::is_a<GiNaC::add>(e))
        for (const auto& term : e) add_term(term);
    else
        add_term(e);
    return out;
}

// Seen nonzero at the point of value_at_generic_point (scalar/equality.h): never true for a 0.
bool seen_nonzero(const GiNaC::ex& x) {
    static const point_value zero = value_at_generic_point(0);
    return seen_different(value_at_generic_point(x), zero);
}

}  // namespace

bool proved_zero_by_denominators(const GiNaC::ex& x) {
    if (!is_rational_function_of_symbols(x)) return false;
    // most coefficients of a quasi-polynomial are not 0: one evaluation spares them the expansion
    // (normalize() then brings them to their form anyway)
    if (seen_nonzero(x)) return false;
    guard_expansion(x, "simplification", false);
    const denominator_groups d = group_by_denominator(GiNaC::expand(x));
    // The groups that share a factor, linked (union-find over the factors): each such component
    // over the product of the largest power of each of its factors, its numerator expanded (a
    // Laurent polynomial: monomial denominators) and divided by those powers. When every
    // component divides out, x is the sum of the quotients, a Laurent polynomial whose expanded
    // form is canonical: 0 proves x = 0. (Components over coprime factors cancel only that way;
    // a component that does not divide, or factors shared between components, end the attempt
    // with false: the caller's full test decides.)
    std::vector<std::size_t> parent(d.bases.size());
    for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
    const std::function<std::size_t(std::size_t)> root = [&](std::size_t i) {
        return parent[i] == i ? i : parent[i] = root(parent[i]);
    };
    for (const auto& g : d.groups)
        for (const auto& f : g.first) parent[root(f.first)] = root(g.first.begin()->first);
    constexpr std::size_t none = std::size_t(-1);  // the groups without a polynomial factor
    std::map<std::size_t, std::vector<const std::pair<const std::map<std::size_t, int>, GiNaC::ex>*>> components;
    for (const auto& g : d.groups) components[g.first.empty() ? none : root(g.first.begin()->first)].push_back(&g);
    GiNaC::ex total = 0;
    for (const auto& [key, members] : components) {
        std::map<std::size_t, int> most;
        for (const auto* g : members)
            for (const auto& [i, k] : g->first) most[i] = std::max(most[i], k);
        GiNaC::ex n = 0;
        for (const auto* g : members) {
            GiNaC::ex c = g->second;
            for (const auto& [i, k] : most) {
                const auto it = g->first.find(i);
                if (const int r = k - (it == g->first.end() ? 0 : it->second); r > 0) c *= GiNaC::pow(d.bases[i], r);
            }
            n += GiNaC::expand(c);
        }
        if (key == none || (n = GiNaC::expand(n)).is_zero()) {
            total += n;
            continue;
        }
        const GiNaC::ex nd = GiNaC::normal(n).numer_denom();  // the monomial denominator apart
        GiNaC::ex q = GiNaC::expand(nd.op(0));
        for (const auto& [i, k] : most)
            for (int j = 0; j < k; ++j)
                if (!GiNaC::divide(q, d.bases[i], q)) return false;
        total += GiNaC::expand(q / nd.op(1));
    }
    return GiNaC::expand(total).is_zero();
}

std::optional<GiNaC::ex> sum_of_fractions(const GiNaC::ex& x) {
    if (!is_rational_function_of_symbols(x)) return std::nullopt;
    guard_expansion(x, "simplification", false);
    const denominator_groups grouped = group_by_denominator(GiNaC::expand(x));
    const auto& bases = grouped.bases;
    const auto& groups = grouped.groups;
    if (groups.size() < 3) return std::nullopt;
    GiNaC::ex sum = 0;
    for (const auto& [den, numerator] : groups) {
        const GiNaC::ex nd = GiNaC::normal(numerator).numer_denom();  // monomial denominators
        GiNaC::ex N = GiNaC::expand(nd.op(0)), D = nd.op(1);
        if (N.is_zero()) continue;
        for (const auto& [i, k] : den) {
            int left = k;
            GiNaC::ex q;
            while (left > 0 && GiNaC::divide(N, bases[i], q)) {
                N = q;
                --left;
            }
            if (left > 0) D *= GiNaC::pow(bases[i], left);
        }
        sum += N / D;
    }
    // the groups may cancel across denominators: unless seen nonzero, x goes to the full test
    if (!seen_nonzero(sum)) return std::nullopt;
    // over a common denominator of low degree one fraction is cheap and often shorter
    // (1/((a + b) a) + 1/((a - b) a) - 2/a^2 is 2 b^2/(a^2 (a^2 - b^2))): the smaller wins
    int lcm_degree = 0;
    for (std::size_t i = 0; i < bases.size(); ++i) {
        int most = 0;
        for (const auto& g : groups)
            if (const auto it = g.first.find(i); it != g.first.end()) most = std::max(most, it->second);
        int degree = 0;
        for (auto it = bases[i].preorder_begin(); it != bases[i].preorder_end(); ++it)
            if (GiNaC::is_a<GiNaC::symbol>(*it)) degree = std::max(degree, bases[i].degree(*it));
        lcm_degree += most * std::max(degree, 1);
    }
    if (lcm_degree <= 8) {
        const GiNaC::ex one = GiNaC::normal(sum);
        if (node_count(one) <= node_count(sum)) return one;
    }
    return sum;
}

namespace {
expression_printer g_message_printer = nullptr;
}

void set_message_printer(expression_printer p) { g_message_printer = p; }

std::string message_text(const GiNaC::ex& e, std::size_t max) {
    std::string s;
    // the canonical printer may itself refuse e with a message that quotes e: GiNaC's text there
    static thread_local bool printing = false;
    if (g_message_printer && !printing) {
        printing = true;
        try {
            s = g_message_printer(e);
        } catch (const std::exception&) {
            s.clear();  // an expression the canonical printer refuses: GiNaC's text below
        }
        printing = false;
    }
    if (s.empty()) {
        std::ostringstream os;
        // the constant as the language writes it (GiNaC prints Pi, which reads back as a free symbol)
        static const GiNaC::symbol pi("pi");
        if (e.has(GiNaC::Pi)) os << e.subs(GiNaC::Pi == pi, GiNaC::subs_options::no_pattern);
        else os << e;
        s = os.str();
    }
    if (s.size() > max)
        s = s.substr(0, max / 2) + " ... " + s.substr(s.size() - max / 4) + " (" +
            std::to_string(s.size()) + " characters)";
    return s;
}

GiNaC::ex log_modulus(const GiNaC::ex& a, const GiNaC::ex& b) {
    return GiNaC::log(tidy(a * a + b * b)) / 2;
}

GiNaC::ex exp_scalar(const GiNaC::ex& x) {
    const auto is_log = [](const GiNaC::ex& u) {
        return GiNaC::is_a<GiNaC::function>(u) && GiNaC::ex_to<GiNaC::function>(u).get_name() == "log";
    };
    // over primes, so that 8^(1/2) comes back as 2*2^(1/2) and cancels against 2^(1/2)
    const GiNaC::ex e = GiNaC::expand(x.has(GiNaC::log(GiNaC::wild())) ? expand_rational_logs(x) : x);
    GiNaC::ex rest = 0, pre = 1;
    auto term = [&](const GiNaC::ex& u) {
        if (is_log(u)) {
            pre *= u.op(0);
            return;
        }
        if (GiNaC::is_a<GiNaC::mul>(u) && u.nops() == 2) {
            for (int i = 0; i < 2; ++i) {
                const GiNaC::ex a = u.op(i), b = u.op(1 - i);
                if (GiNaC::is_a<GiNaC::numeric>(b) && is_log(a)) {
                    pre *= GiNaC::pow(a.op(0), b);
                    return;
                }
            }
        }
        rest += u;
    };
    if (GiNaC::is_a<GiNaC::add>(e))
        for (std::size_t i = 0; i < e.nops(); ++i) term(e.op(i));
    else
        term(e);
    return pre * GiNaC::exp(rest);
}

namespace {

void collect_symbols(const GiNaC::ex& x, std::set<GiNaC::ex, GiNaC::ex_is_less>& out) {
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) out.insert(*it);
}

}  // namespace

// At least what the zero test decides: radicals and logarithms of rationals over
// primes (sqrt(2) sqrt(8) = 4), arctangents inside sin/cos/tan as algebraic
// functions, and trigonometric and hyperbolic polynomials through their
// exponential form when that form normalizes to an expression without the
// formal exponentials (cos(p)^2 + sin(p)^2 = 1).
GiNaC::ex simplify_scalar(const GiNaC::ex& x) {
    guard_expansion(x, "simplify", false);
    const GiNaC::ex y = expand_rational_logs(trig_of_arctangents(GiNaC::expand(x)));
    guard_expansion(y, "simplify", true);
    // the square roots of rationals in their number field: what the zero test decides, simplify reaches
    const GiNaC::ex plain = in_square_roots_field(GiNaC::normal(GiNaC::expand(y)));
    if (!y.has(GiNaC::sin(GiNaC::wild())) && !y.has(GiNaC::cos(GiNaC::wild())) && !has_tan_or_hyperbolic(y))
        return canonical_radicals(plain);
    const GiNaC::ex z = GiNaC::normal(expand_rational_logs(trig_exponential_form(y)));
    std::set<GiNaC::ex, GiNaC::ex_is_less> before, after;
    collect_symbols(y, before);
    collect_symbols(z, after);
    for (const GiNaC::ex& s : after)
        if (!before.count(s)) return canonical_radicals(plain);  // the formal exponentials remain
    if (z.has(GiNaC::I) && !y.has(GiNaC::I)) return canonical_radicals(plain);
    return canonical_radicals(in_square_roots_field(z));
}

GiNaC::ex sines_squared_as_cosines(const GiNaC::ex& e) {
    const GiNaC::wildcard u(0);
    return GiNaC::expand(GiNaC::expand(e).subs(GiNaC::pow(GiNaC::sin(u), 2) == 1 - GiNaC::pow(GiNaC::cos(u), 2),
                                               GiNaC::subs_options::algebraic));
}

GiNaC::ex atan2_exact(const GiNaC::ex& y, const GiNaC::ex& x) {
    const GiNaC::ex fallback = GiNaC::atan2(y, x);
    if (has_symbol(y) || has_symbol(x)) return fallback;
    GiNaC::numeric v;
    if (!evaluate_numeric(fallback, 40, v) || !v.is_real()) return fallback;
    std::vector<GiNaC::ex> candidates;
    // the rational multiple of pi nearest v/pi with a denominator <= 60 (continued fraction)
    GiNaC::numeric r;
    if (evaluate_numeric(fallback / GiNaC::Pi, 40, r) && r.is_real()) {
        GiNaC::numeric h0 = 0, h1 = 1, k0 = 1, k1 = 0, a = r;
        for (int i = 0; i < 12; ++i) {
            if (GiNaC::abs(a) > 1000000) break;  // the next denominator exceeds 60
            const GiNaC::numeric q(static_cast<long>(std::floor(a.to_double())));
            const GiNaC::numeric h = q * h1 + h0, k = q * k1 + k0;
            if (k > 60) break;
            candidates.push_back(h / k * GiNaC::Pi);
            h0 = h1; h1 = h; k0 = k1; k1 = k;
            if (a == q) break;
            a = 1 / (a - q);
        }
    }
    for (auto it = y.preorder_begin(); it != y.preorder_end(); ++it)
        if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(*it))
            candidates.push_back(it->op(0));
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(*it))
            candidates.push_back(it->op(0));
    const GiNaC::numeric pi = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(GiNaC::Pi));
    for (const GiNaC::ex& u : candidates) {
        GiNaC::numeric uv, radius;
        if (!evaluate_numeric(u, 40, uv) || !uv.is_real()) continue;
        if (GiNaC::abs(uv - v) > GiNaC::numeric(1, 1000000000)) continue;  // not this angle
        if (!(uv > -pi + GiNaC::numeric(1, 1000000000)) || uv > pi) continue;
        if (!evaluate_numeric(x * GiNaC::cos(u) + y * GiNaC::sin(u), 40, radius) || !radius.is_real() ||
            radius < GiNaC::numeric(1, 1000000000))
            continue;
        if (is_zero_scalar(GiNaC::expand(x * GiNaC::sin(u) - y * GiNaC::cos(u)))) return u;
        // y cos(u) = x sin(u) through their squares (sin(u)^2 = 1 - cos(u)^2) and their signs, both
        // clear of 0 at 40 digits: y = sqrt(1 - cos(2)^2) meets sin(2)
        GiNaC::numeric a, b;
        const GiNaC::ex ya = y * GiNaC::cos(u), xb = x * GiNaC::sin(u);
        if (!evaluate_numeric(ya, 40, a) || !evaluate_numeric(xb, 40, b) || !a.is_real() || !b.is_real() ||
            GiNaC::abs(a) < GiNaC::numeric(1, 1000000000) || (a > 0) != (b > 0))
            continue;
        if (is_zero_scalar(sines_squared_as_cosines(ya * ya - xb * xb))) return u;
    }
    return fallback;
}

}  // namespace symrep
