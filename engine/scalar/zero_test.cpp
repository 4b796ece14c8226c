// symrep/scalar/zero_test.cpp -- the exact zero test and the forms it reduces to (scalar.h).
#include "symrep/scalar/scalar.h"
#include "symrep/scalar/small_primes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

namespace {


}  // namespace

namespace {

GiNaC::ex rational_logs_over_primes(const GiNaC::ex& e, bool symbolic_exponents) {
    struct expand_logs : GiNaC::map_function {
        cofactor_bases refined;
        bool symbolic = false;  ///< also r^u for a non-numeric u: (1/3)^k = 3^(-k), 6^k = 2^k 3^k
        const std::vector<std::pair<GiNaC::numeric, long>>& over_bases(const GiNaC::numeric& c) {
            auto it = refined.find(c);
            if (it == refined.end()) it = refined.emplace(c, std::vector<std::pair<GiNaC::numeric, long>>{{c, 1}}).first;
            return it->second;
        }
        GiNaC::ex log_of_integer(const GiNaC::numeric& N) {
            GiNaC::ex out = 0;
            const small_factorization f = small_prime_factors(N);
            for (const auto& [p, k] : f.factors) out += k * GiNaC::log(GiNaC::ex(p));
            if (f.cofactor > 1)
                for (const auto& [b, k] : over_bases(f.cofactor)) out += k * GiNaC::log(GiNaC::ex(b));
            return out;
        }
        GiNaC::ex power_of_integer(const GiNaC::numeric& N, const GiNaC::ex& q) {
            GiNaC::ex out = 1;
            const small_factorization f = small_prime_factors(N);
            for (const auto& [p, k] : f.factors) out *= GiNaC::pow(GiNaC::ex(p), k * q);
            if (f.cofactor > 1)
                for (const auto& [b, k] : over_bases(f.cofactor)) out *= GiNaC::pow(GiNaC::ex(b), k * q);
            return out;
        }
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            // r^q, r a positive rational, q a non-integer rational: over primes
            if (GiNaC::is_a<GiNaC::power>(y) && is_positive_rational(y.op(0)) &&
                GiNaC::is_a<GiNaC::numeric>(y.op(1)) && GiNaC::ex_to<GiNaC::numeric>(y.op(1)).is_rational() &&
                !GiNaC::ex_to<GiNaC::numeric>(y.op(1)).is_integer()) {
                const GiNaC::numeric r = GiNaC::ex_to<GiNaC::numeric>(y.op(0));
                return power_of_integer(r.numer(), y.op(1)) / power_of_integer(r.denom(), y.op(1));
            }
            if (symbolic && GiNaC::is_a<GiNaC::power>(y) && is_positive_rational(y.op(0)) && !y.op(0).is_equal(1) &&
                !GiNaC::is_a<GiNaC::numeric>(y.op(1))) {
                const GiNaC::numeric r = GiNaC::ex_to<GiNaC::numeric>(y.op(0));
                // times q^(-u), not divided by q^u: GiNaC keeps 1/3^k apart from 3^(-k)
                return power_of_integer(r.numer(), y.op(1)) * power_of_integer(r.denom(), -y.op(1));
            }
            if (!GiNaC::is_a<GiNaC::function>(y) || y.nops() != 1 ||
                GiNaC::ex_to<GiNaC::function>(y).get_name() != "log")
                return y;
            // the argument as a product of factors b^k, b a positive rational, k rational
            const GiNaC::ex a = y.op(0);
            GiNaC::ex out = 0;
            for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::mul>(a) ? a.nops() : 1); ++i) {
                GiNaC::ex b = GiNaC::is_a<GiNaC::mul>(a) ? a.op(i) : a, k = 1;
                if (GiNaC::is_a<GiNaC::power>(b) && GiNaC::is_a<GiNaC::numeric>(b.op(1)) &&
                    GiNaC::ex_to<GiNaC::numeric>(b.op(1)).is_rational()) {
                    k = b.op(1);
                    b = b.op(0);
                }
                if (!is_positive_rational(b)) return y;
                const GiNaC::numeric r = GiNaC::ex_to<GiNaC::numeric>(b);
                out += k * (log_of_integer(r.numer()) - log_of_integer(r.denom()));
            }
            return out;
        }
    } m;
    m.refined = refine_cofactors(e);
    m.symbolic = symbolic_exponents;
    return m(e);
}

}  // namespace

GiNaC::ex expand_rational_logs(const GiNaC::ex& e) { return rational_logs_over_primes(e, false); }

bool has_tan_or_hyperbolic(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_the_function<GiNaC::tan_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::sinh_SERIAL>(*it) ||
            GiNaC::is_the_function<GiNaC::cosh_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::tanh_SERIAL>(*it))
            return true;
    return false;
}

bool has_related_exponentials(const GiNaC::ex& e) {
    GiNaC::ex first;  // a copy: *it lives in the iterator's stack, which moves as it advances
    bool seen = false;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!GiNaC::is_the_function<GiNaC::exp_SERIAL>(*it)) continue;
        if (GiNaC::is_a<GiNaC::add>(it->op(0))) return true;
        if (seen && !first.is_equal(*it)) return true;
        first = *it;
        seen = true;
    }
    return false;
}

namespace {

/// A term of a trigonometric argument as c m: m a monomial (1 for a rational number), c a number.
std::pair<GiNaC::ex, GiNaC::ex> monomial_and_coefficient(const GiNaC::ex& term) {
    if (GiNaC::is_a<GiNaC::numeric>(term)) return {1, term};
    if (GiNaC::is_a<GiNaC::mul>(term) && GiNaC::is_a<GiNaC::numeric>(term.op(term.nops() - 1))) {
        const GiNaC::ex c = term.op(term.nops() - 1);
        return {term / c, c};
    }
    return {term, 1};
}

/// Real: GiNaC says so, or a constant whose value is a real number (sqrt(2)/3, which GiNaC's
/// info flags do not call real).
bool is_real_argument(const GiNaC::ex& z) {
    if (z.info(GiNaC::info_flags::real)) return true;
    if (has_symbol(z)) return false;
    const GiNaC::ex v = GiNaC::evalf(z);
    return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real();
}

bool is_trig_or_exponential(const GiNaC::ex& y) {
    return GiNaC::is_a<GiNaC::function>(y) && y.nops() == 1 &&
           (GiNaC::is_the_function<GiNaC::sin_SERIAL>(y) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(y) ||
            GiNaC::is_the_function<GiNaC::tan_SERIAL>(y) || GiNaC::is_the_function<GiNaC::sinh_SERIAL>(y) ||
            GiNaC::is_the_function<GiNaC::cosh_SERIAL>(y) || GiNaC::is_the_function<GiNaC::tanh_SERIAL>(y) ||
            GiNaC::is_the_function<GiNaC::exp_SERIAL>(y));
}

}  // namespace

GiNaC::ex trig_exponential_form(const GiNaC::ex& e) {
    struct to_exp : GiNaC::map_function {
        std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> X, Y;
        // per monomial m, the lcm L_m of the denominators of its rational coefficients in all the
        // arguments: X_m stands for e^(i m / L_m), so that cos(t/2) meets cos(t) and cos(1/2)
        // meets cos(1) (the rational numbers as the monomial 1)
        std::map<GiNaC::ex, GiNaC::numeric, GiNaC::ex_is_less> L;
        bool exponentials = false;  ///< also write exp(u) through the Y_m
        /// GiNaC knows cos(c pi) and sin(c pi) in radicals for every multiple of pi in the arguments:
        /// each e^(i c pi) is then its own algebraic number (nested radicals of one base e^(i pi/L),
        /// such as sin(pi/12) = sqrt(1 - cos(pi/12)^2), would hide their relations)
        bool pi_values_known = true;
        void collect(const GiNaC::ex& e) {
            for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
                if (!is_trig_or_exponential(*it)) continue;
                const GiNaC::ex u = GiNaC::expand(it->op(0));
                if (u.has(GiNaC::I)) continue;
                for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(u) ? u.nops() : 1); ++i) {
                    const auto [m, c] = monomial_and_coefficient(GiNaC::is_a<GiNaC::add>(u) ? u.op(i) : u);
                    if (!GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) continue;
                    auto at = L.emplace(m, GiNaC::numeric(1)).first;
                    at->second = GiNaC::lcm(at->second, GiNaC::ex_to<GiNaC::numeric>(c).denom());
                    if (m.is_equal(GiNaC::Pi)) {
                        const GiNaC::ex z = GiNaC::cos(c * GiNaC::Pi) + GiNaC::I * GiNaC::sin(c * GiNaC::Pi);
                        if (z.has(GiNaC::cos(GiNaC::wild())) || z.has(GiNaC::sin(GiNaC::wild()))) pi_values_known = false;
                    }
                }
            }
        }
        // e^(i pi/L) in radicals, sin(pi/L) = sqrt(1 - cos(pi/L)^2) (L > 1); 0 where GiNaC does not know
        // cos(pi/L) in radicals
        static GiNaC::ex unit_root(const GiNaC::numeric& L) {
            const GiNaC::ex cs = GiNaC::cos(GiNaC::Pi / L);
            if (cs.has(GiNaC::cos(GiNaC::wild()))) return 0;
            return cs + GiNaC::I * GiNaC::sqrt(GiNaC::expand(1 - cs * cs));
        }
        GiNaC::numeric denominator_of(const GiNaC::ex& m) const {
            const auto it = L.find(m);
            return it == L.end() ? GiNaC::numeric(1) : it->second;
        }
        // prod over the terms c m of u of V_m^(c L_m) (V_m standing for e^(k m / L_m)), a
        // non-rational numeric term c0 kept as the number e^(k c0)
        GiNaC::ex power(const GiNaC::ex& u, std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& V, const GiNaC::ex& k) {
            GiNaC::ex E = 1;
            for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(u) ? u.nops() : 1); ++i) {
                const GiNaC::ex whole = GiNaC::is_a<GiNaC::add>(u) ? u.op(i) : u;
                if (GiNaC::is_a<GiNaC::numeric>(whole) && !GiNaC::ex_to<GiNaC::numeric>(whole).is_rational()) {
                    E *= GiNaC::exp(k * whole);  // a float phase: kept as a number
                    continue;
                }
                auto [term, c] = monomial_and_coefficient(whole);
                const GiNaC::numeric Lm = denominator_of(term);
                if (term.is_equal(GiNaC::Pi) && k.is_equal(GiNaC::I)) {
                    // e^(i c pi) is an algebraic number: exact where GiNaC knows cos and sin of c pi
                    // (c with denominator 1, 2, 3, 4, 6, ...), so that sin(pi - x) meets sin(x)
                    // one base e^(i pi/L) for all the multiples of pi where GiNaC knows cos(pi/L): the
                    // phases k pi/5 and 2 pi/5 then meet as powers of one algebraic number
                    if (!pi_values_known && GiNaC::is_a<GiNaC::numeric>(c) && (c * Lm).info(GiNaC::info_flags::integer) &&
                        Lm > 1) {
                        const GiNaC::ex base = unit_root(Lm);
                        if (!base.is_zero()) {
                            E *= GiNaC::pow(base, c * Lm);
                            continue;
                        }
                    }
                    const GiNaC::ex cs = GiNaC::cos(c * GiNaC::Pi);
                    GiNaC::ex sn = GiNaC::sin(c * GiNaC::Pi);
                    if (!cs.has(GiNaC::cos(GiNaC::wild())) && sn.has(GiNaC::sin(GiNaC::wild())) &&
                        GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) {
                        // GiNaC knows cos(pi/5), not sin(pi/5): sin(c pi) = +-sqrt(1 - cos(c pi)^2), the
                        // sign that of sin on (0, pi) or (pi, 2 pi) by c mod 2 (c not an integer here)
                        const GiNaC::numeric cn = GiNaC::ex_to<GiNaC::numeric>(c);
                        const GiNaC::numeric r = cn - 2 * GiNaC::iquo(cn.numer(), 2 * cn.denom());
                        const bool positive = (r > 0 && r < 1) || (r > -2 && r < -1);
                        sn = (positive ? 1 : -1) * GiNaC::sqrt(GiNaC::expand(1 - cs * cs));
                    }
                    const GiNaC::ex z = cs + GiNaC::I * sn;
                    if (!z.has(GiNaC::cos(GiNaC::wild())) && !z.has(GiNaC::sin(GiNaC::wild()))) {
                        E *= z;
                        continue;
                    }
                }
                if (k.is_equal(GiNaC::I) && GiNaC::is_a<GiNaC::numeric>(c) &&
                    GiNaC::ex_to<GiNaC::numeric>(c).is_integer() && Lm == 1) {
                    // e^(i atan z) = (1 + i z)/sqrt(1 + z^2) and e^(i atan2(y, x)) = (x + i y)/sqrt(x^2 + y^2)
                    // for real z, x, y: cos(pi - atan(2)) meets -1/sqrt(5)
                    if (GiNaC::is_the_function<GiNaC::atan_SERIAL>(term) && is_real_argument(term.op(0))) {
                        const GiNaC::ex z = term.op(0);
                        E *= GiNaC::pow((1 + GiNaC::I * z) / GiNaC::sqrt(GiNaC::expand(1 + z * z)), c);
                        continue;
                    }
                    if (GiNaC::is_the_function<GiNaC::atan2_SERIAL>(term) && is_real_argument(term.op(0)) &&
                        is_real_argument(term.op(1))) {
                        const GiNaC::ex y = term.op(0), x = term.op(1);
                        E *= GiNaC::pow((x + GiNaC::I * y) / GiNaC::sqrt(GiNaC::expand(x * x + y * y)), c);
                        continue;
                    }
                }
                auto it = V.find(term);
                if (it == V.end()) it = V.emplace(term, GiNaC::realsymbol()).first;  // a formal variable
                E *= GiNaC::pow(it->second, c * Lm);
            }
            return E;
        }
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (!GiNaC::is_a<GiNaC::function>(y) || y.nops() != 1) return y;
            const GiNaC::ex u = GiNaC::expand(y.op(0));
            if (u.has(GiNaC::I)) return y;
            if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(y) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(y) ||
                GiNaC::is_the_function<GiNaC::tan_SERIAL>(y)) {
                const GiNaC::ex E = power(u, X, GiNaC::I), s = (E - 1 / E) / (2 * GiNaC::I), c = (E + 1 / E) / 2;
                return GiNaC::is_the_function<GiNaC::sin_SERIAL>(y) ? s
                       : GiNaC::is_the_function<GiNaC::cos_SERIAL>(y) ? c : s / c;
            }
            const bool sh = GiNaC::is_the_function<GiNaC::sinh_SERIAL>(y), ch = GiNaC::is_the_function<GiNaC::cosh_SERIAL>(y),
                       th = GiNaC::is_the_function<GiNaC::tanh_SERIAL>(y);
            if (!sh && !ch && !th && !(exponentials && GiNaC::is_the_function<GiNaC::exp_SERIAL>(y))) return y;
            const GiNaC::ex H = power(u, Y, 1), s = (H - 1 / H) / 2, c = (H + 1 / H) / 2;
            return sh ? s : ch ? c : th ? s / c : H;
        }
    } f;
    f.exponentials = has_tan_or_hyperbolic(e) || has_related_exponentials(e);
    f.collect(e);
    return f(e);
}

square_roots_as_symbols with_square_roots_as_symbols(const GiNaC::ex& e, bool rational_bases) {
    struct roots : GiNaC::map_function {
        bool rational = false;
        std::vector<std::pair<GiNaC::ex, GiNaC::realsymbol>> q;  // base, symbol (a real root)
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (!GiNaC::is_a<GiNaC::power>(y) || !GiNaC::is_a<GiNaC::numeric>(y.op(1))) return y;
            if (GiNaC::is_a<GiNaC::numeric>(y.op(0)) &&
                !(rational && GiNaC::ex_to<GiNaC::numeric>(y.op(0)).is_rational()))
                return y;
            const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(y.op(1)) * 2;
            if (!k.is_integer() || k.is_even()) return y;
            for (const auto& [b, s] : q)
                if (b.is_equal(y.op(0))) return GiNaC::pow(s, k);
            q.emplace_back(y.op(0), GiNaC::realsymbol());
            return GiNaC::pow(q.back().second, k);
        }
    } r;
    r.rational = rational_bases;
    const GiNaC::ex z = r(e);
    return {z, r.q};
}

namespace {

/// z (with the roots of r as symbols) is 0 modulo q_b^2 - b: true is a proof.
bool zero_modulo_roots(const square_roots_as_symbols& r, const GiNaC::ex& z) {
    try {
        const GiNaC::ex n = GiNaC::expand(GiNaC::numer(GiNaC::normal(z)));
        // complex coefficients (I): the real and the imaginary part vanish separately
        std::vector<GiNaC::ex> parts{n};
        if (n.has(GiNaC::I)) parts = {GiNaC::real_part(n), GiNaC::imag_part(n)};
        for (GiNaC::ex part : parts) {
            GiNaC::exmap atoms;  // functions and other non-polynomial parts as symbols
            part = GiNaC::expand(part).to_polynomial(atoms);
            // outermost first: a root's base holds only roots found before it
            for (auto it = r.roots.rbegin(); it != r.roots.rend(); ++it) {
                const auto& [b, s] = *it;
                if (!part.has(s)) continue;
                // s^2 = N/D: the base may be a fraction (q^2 |B|^2/m^2 + ...), whose 1/m
                // to_polynomial would make an unrelated atom; N and D are made polynomials
                // apart, and the remainder has coefficients in the fractions of the rest
                const GiNaC::ex nd = GiNaC::normal(b).numer_denom();
                const GiNaC::ex base = nd.op(1).is_equal(1) ? b.to_polynomial(atoms)
                                                            : nd.op(0).to_polynomial(atoms) / nd.op(1).to_polynomial(atoms);
                part = GiNaC::expand(GiNaC::rem(part, GiNaC::pow(s, 2) - base, s, false));
                // D may hold inner roots: their reduction needs a polynomial (D != 0)
                if (!nd.op(1).is_equal(1)) part = GiNaC::expand(GiNaC::numer(GiNaC::normal(part)));
            }
            if (!GiNaC::normal(part).is_zero()) return false;
        }
        return true;
    } catch (const std::exception&) {
        return false;  // not decided: not proved zero
    }
}

bool is_function_factor(const GiNaC::ex& f) {
    return GiNaC::is_a<GiNaC::function>(f) || (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::function>(f.op(0)));
}

/// The terms of the sum e grouped by their product of function factors (exp, sin,
/// cos, ... : the functions of t of a residual), the coefficients summed.
std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> by_function_factors(const GiNaC::ex& e) {
    std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> groups;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1); ++i) {
        const GiNaC::ex term = GiNaC::is_a<GiNaC::add>(e) ? e.op(i) : e;
        GiNaC::ex F = 1, c = 1;
        for (std::size_t j = 0; j < (GiNaC::is_a<GiNaC::mul>(term) ? term.nops() : 1); ++j) {
            const GiNaC::ex f = GiNaC::is_a<GiNaC::mul>(term) ? term.op(j) : term;
            (is_function_factor(f) ? F : c) *= f;
        }
        groups[F] += c;
    }
    return groups;
}

}  // namespace

bool is_zero_modulo_square_roots(const GiNaC::ex& e) {
    const square_roots_as_symbols r = with_square_roots_as_symbols(e, true);
    if (r.roots.empty()) return false;
    // c_1 F_1 + c_2 F_2 + ..., F_k products of functions (the exp, sin, cos of t
    // of a residual): 0 when every c_k is; each is far smaller than the whole, whose
    // normal() spends its time in gcds over all the atoms at once
    const GiNaC::ex ez = GiNaC::expand(r.e);
    const auto groups = by_function_factors(ez);
    if (groups.size() > 1) {
        bool all = true;
        for (const auto& [F, c] : groups)
            if (!zero_modulo_roots(r, c)) {
                all = false;
                break;
            }
        if (all) return true;
    }
    return zero_modulo_roots(r, ez);
}

bool has_symbolic_square_root(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && !GiNaC::is_a<GiNaC::numeric>(it->op(0)) &&
            GiNaC::is_a<GiNaC::numeric>(it->op(1))) {
            const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(it->op(1)) * 2;
            if (k.is_integer() && k.is_odd()) return true;
        }
    return false;
}

namespace {

bool is_atan(const GiNaC::ex& u) { return GiNaC::is_the_function<GiNaC::atan_SERIAL>(u); }

bool is_integer_number(const GiNaC::ex& c) {
    return GiNaC::is_a<GiNaC::numeric>(c) && GiNaC::ex_to<GiNaC::numeric>(c).is_integer();
}

/// A real number given without symbols (1/5, sqrt(2)/3, ...).
bool is_real_constant(const GiNaC::ex& z) {
    if (has_symbol(z)) return false;
    const GiNaC::ex v = GiNaC::evalf(z);
    return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_real();
}

/// A sum of integer multiples of arctangents of real numbers and of a rational
/// multiple of pi, c_pi pi + sum c_j atan(z_j) (no symbols), is 0 exactly when
///   e^(i S) = e^(i c_pi pi) prod ((1 + i z_j)/sqrt(1 + z_j^2))^(c_j) = 1   (an algebraic identity)
/// and |S| < 2 pi (then S, a multiple of 2 pi, is 0). The first is decided by
/// the zero test on algebraic numbers, the second by a 30-digit evaluation
/// that only has to separate 0 from 2 pi. Answers true, or false when it does
/// not apply or does not prove it (never a claim that S is not 0).
bool is_zero_arctangent_sum(const GiNaC::ex& x) {
    const GiNaC::ex y = GiNaC::expand(x);
    GiNaC::ex E = 1;
    bool any = false;
    for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(y) ? y.nops() : 1); ++i) {
        GiNaC::ex term = GiNaC::is_a<GiNaC::add>(y) ? y.op(i) : y, c = 1;
        if (GiNaC::is_a<GiNaC::mul>(term) && GiNaC::is_a<GiNaC::numeric>(term.op(term.nops() - 1))) {
            c = term.op(term.nops() - 1);
            term = term / c;
        }
        if (!GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_rational()) return false;
        if (term.is_equal(GiNaC::Pi)) {
            const GiNaC::ex z = GiNaC::cos(c * GiNaC::Pi) + GiNaC::I * GiNaC::sin(c * GiNaC::Pi);
            if (z.has(GiNaC::cos(GiNaC::wild())) || z.has(GiNaC::sin(GiNaC::wild()))) return false;
            E *= z;
        } else if (is_atan(term) && is_integer_number(c) && is_real_constant(term.op(0))) {
            const GiNaC::ex z = term.op(0);
            E *= GiNaC::pow((1 + GiNaC::I * z) / GiNaC::sqrt(1 + z * z), c);
            any = true;
        } else {
            return false;
        }
    }
    if (!any) return false;
    if (!GiNaC::normal(expand_rational_logs(GiNaC::expand(E - 1))).is_zero()) return false;
    const GiNaC::ex v = GiNaC::evalf(x);
    return GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v)) < 1;
}

// The arguments of sin and cos that are not polynomials in symbols (a(t) = |u| (t + sin t), the
// angle of a rotation at a variable rate, VI.2.10), each up to a numeric factor, as fresh real
// symbols: sin(2 a) -> sin(2 theta). Sound for a zero proof: an identity that holds for every
// theta holds at theta = a(t). Nothing when there is no such argument.
std::optional<GiNaC::ex> composite_trig_arguments_as_symbols(const GiNaC::ex& y) {
    struct replace : GiNaC::map_function {
        std::map<GiNaC::ex, GiNaC::realsymbol, GiNaC::ex_is_less> atoms;
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const bool s = GiNaC::is_the_function<GiNaC::sin_SERIAL>(x), c = GiNaC::is_the_function<GiNaC::cos_SERIAL>(x);
            if (!s && !c) return x.map(*this);
            const GiNaC::ex A = x.op(0);
            GiNaC::ex k = 1, B = A;
            if (GiNaC::is_a<GiNaC::mul>(A) && GiNaC::is_a<GiNaC::numeric>(A.op(A.nops() - 1))) {
                k = A.op(A.nops() - 1);
                B = A / k;
            }
            // B and -B are one variable: cos(-t - sin t) meets cos(t + sin t)
            if (const GiNaC::ex nB = GiNaC::expand(-B); nB.compare(B) < 0) {
                B = nB;
                k = -k;
            }
            GiNaC::lst syms;
            bool polynomial = true;
            for (auto it = B.preorder_begin(); it != B.preorder_end(); ++it) {
                if (GiNaC::is_a<GiNaC::symbol>(*it)) syms.append(*it);
                else if (GiNaC::is_a<GiNaC::function>(*it) || GiNaC::is_a<GiNaC::constant>(*it)) polynomial = false;
            }
            if (polynomial && B.is_polynomial(syms)) return x;
            auto at = atoms.find(B);
            if (at == atoms.end()) at = atoms.emplace(B, GiNaC::realsymbol()).first;
            return s ? GiNaC::sin(k * at->second) : GiNaC::cos(k * at->second);
        }
    } r;
    const GiNaC::ex z = r(y);
    if (r.atoms.empty()) return std::nullopt;
    return z;
}

}  // namespace

bool is_zero_scalar(const GiNaC::ex& x) {
    if (x.is_zero()) return true;
    if (x.has(GiNaC::atan(GiNaC::wild())) && !has_symbol(x) && is_zero_arctangent_sum(x)) return true;
    guard_expansion(x, "zero test", true);
    // powers of rationals with symbolic exponents over primes too ((1/3)^k = 3^(-k))
    const GiNaC::ex y = rational_logs_over_primes(trig_of_arctangents(x), true);
    // square roots of expressions first as algebraic symbols: faster than normal(),
    // whose gcds over such atoms are slow, and complete where normal() is not
    if (has_symbolic_square_root(y)) {
        if (is_zero_modulo_square_roots(y)) return true;
    } else if (GiNaC::normal(y).is_zero()) {
        return true;
    }
    if (!y.has(GiNaC::sin(GiNaC::wild())) && !y.has(GiNaC::cos(GiNaC::wild())) && !has_tan_or_hyperbolic(y) &&
        !has_related_exponentials(y))
        return false;
    // radicals that the exponential form brings in (sqrt(34) from e^(i atan(5/3))) over primes too
    const GiNaC::ex z = expand_rational_logs(trig_exponential_form(y));
    guard_expansion(z, "zero test", true);
    if (GiNaC::normal(z).is_zero() || is_zero_modulo_square_roots(z)) return true;
    // (Thm VI.2.1.1, properties 5 and 7 at a variable rate) sin^2 a + cos^2 a = 1 for a composite a
    if (const auto s = composite_trig_arguments_as_symbols(y)) return is_zero_scalar(*s);
    return false;
}

}  // namespace symrep
