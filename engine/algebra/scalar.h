// symrep/algebra/scalar.h -- the two coefficient types of symrep and what the
// algebra code needs to treat them alike.
//
// Exact arithmetic uses GiNaC::ex (CLN rationals, algebraic numbers, symbols);
// the fast numeric path uses double. Family code that is written once as a
// template over T calls only the functions below (plus +,-,*,/ and the
// elementary functions found by argument-dependent lookup: exp, log, cos, sin,
// sqrt, atan2), so that one implementation serves both paths.
#pragma once

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include <ginac/ginac.h>

#include "algebra/expression_size.h"
#include "io/error.h"

namespace symrep {

/// Logarithms of products of powers of positive rationals, and such powers,
/// written over primes: log(c b^e) -> log(c) + e log(b), 8^(1/2) -> 2 2^(1/2), log(p1^k1 ... / q1^l1 ...) -> k1 log(p1) + ... - l1 log(q1) - ...
/// (prime factors below 2^16 are split off; a larger cofactor stays one atom).
/// Two sums of such logarithms are equal iff their expanded forms agree, so the
/// zero test sees log(16)/2 = log(4) = 2 log(2).
inline GiNaC::ex expand_rational_logs(const GiNaC::ex& e) {
    struct expand_logs : GiNaC::map_function {
        static GiNaC::ex log_of_integer(GiNaC::numeric N) {
            GiNaC::ex out = 0;
            for (long p = 2; p < 65536 && N > 1; ++p) {
                if (GiNaC::numeric(p) * p > N) break;
                int k = 0;
                while (GiNaC::irem(N, p).is_zero()) { N = GiNaC::iquo(N, p); ++k; }
                if (k) out += k * GiNaC::log(GiNaC::ex(p));
            }
            if (N > 1) out += GiNaC::log(GiNaC::ex(N));
            return out;
        }
        static bool is_positive_rational(const GiNaC::ex& x) {
            return GiNaC::is_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_rational() &&
                   GiNaC::ex_to<GiNaC::numeric>(x).is_positive();
        }
        static GiNaC::ex power_of_integer(GiNaC::numeric N, const GiNaC::ex& q) {
            GiNaC::ex out = 1;
            for (long p = 2; p < 65536 && N > 1; ++p) {
                if (GiNaC::numeric(p) * p > N) break;
                int k = 0;
                while (GiNaC::irem(N, p).is_zero()) { N = GiNaC::iquo(N, p); ++k; }
                if (k) out *= GiNaC::pow(GiNaC::ex(p), k * q);
            }
            if (N > 1) out *= GiNaC::pow(GiNaC::ex(N), q);
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
    return m(e);
}

/// True when e contains tan, sinh, cosh or tanh.
inline bool has_tan_or_hyperbolic(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_the_function<GiNaC::tan_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::sinh_SERIAL>(*it) ||
            GiNaC::is_the_function<GiNaC::cosh_SERIAL>(*it) || GiNaC::is_the_function<GiNaC::tanh_SERIAL>(*it))
            return true;
    return false;
}

/// True when exponentials of e can meet each other: two different exp(...), or
/// one exp of a sum (exp(x)*exp(y) = exp(x + y) is then seen through Y_m below).
inline bool has_related_exponentials(const GiNaC::ex& e) {
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

/// sin and cos (and tan) of linear combinations written through exponentials:
/// with one symbol X_m standing for e^(i m) per monomial m of the arguments,
/// sin(sum c_k m_k) = (E - 1/E)/(2i), cos = (E + 1/E)/2, E = prod X_{m_k}^{c_k}.
/// A trigonometric polynomial in such arguments is 0 iff this rational function
/// in the X_m is 0, so the zero test sees the addition theorems (sin((a + b) t)
/// = ...). Likewise sinh, cosh, tanh with symbols Y_m standing for e^m, and
/// exp(u) = prod Y_{m_k}^{c_k} when the expression has a hyperbolic function
/// or exponentials that can meet (has_related_exponentials)
/// (cosh(x)^2 - sinh(x)^2 = 1, cosh(x) = (e^x + e^-x)/2).
inline GiNaC::ex trig_exponential_form(const GiNaC::ex& e) {
    struct to_exp : GiNaC::map_function {
        std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> X, Y;
        bool exponentials = false;  ///< also write exp(u) through the Y_m
        // prod over the terms c m of u of V_m^c, times e^(k c0) for a numeric term c0
        GiNaC::ex power(const GiNaC::ex& u, std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less>& V, const GiNaC::ex& k) {
            GiNaC::ex E = 1;
            for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(u) ? u.nops() : 1); ++i) {
                GiNaC::ex term = GiNaC::is_a<GiNaC::add>(u) ? u.op(i) : u, c = 1;
                if (GiNaC::is_a<GiNaC::numeric>(term)) {  // a constant phase: keep it as a number
                    E *= GiNaC::exp(k * term);
                    continue;
                }
                if (GiNaC::is_a<GiNaC::mul>(term) && GiNaC::is_a<GiNaC::numeric>(term.op(term.nops() - 1))) {
                    c = term.op(term.nops() - 1);
                    term = term / c;
                }
                auto it = V.find(term);
                if (it == V.end()) it = V.emplace(term, GiNaC::realsymbol()).first;  // a formal variable
                E *= GiNaC::pow(it->second, c);
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
    return f(e);
}

/// e with each odd power sqrt(b)^k of a non-numeric b written q_b^k, q_b a real
/// symbol per base (`roots`: base and symbol, in order of appearance).
struct square_roots_as_symbols {
    GiNaC::ex e;
    std::vector<std::pair<GiNaC::ex, GiNaC::realsymbol>> roots;
};
inline square_roots_as_symbols with_square_roots_as_symbols(const GiNaC::ex& e) {
    struct roots : GiNaC::map_function {
        std::vector<std::pair<GiNaC::ex, GiNaC::realsymbol>> q;  // base, symbol (a real root)
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (!GiNaC::is_a<GiNaC::power>(y) || GiNaC::is_a<GiNaC::numeric>(y.op(0)) ||
                !GiNaC::is_a<GiNaC::numeric>(y.op(1)))
                return y;
            const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(y.op(1)) * 2;
            if (!k.is_integer() || k.is_even()) return y;
            for (const auto& [b, s] : q)
                if (b.is_equal(y.op(0))) return GiNaC::pow(s, k);
            q.emplace_back(y.op(0), GiNaC::realsymbol());
            return GiNaC::pow(q.back().second, k);
        }
    } r;
    const GiNaC::ex z = r(e);
    return {z, r.q};
}

/// Zero test of a rational function of symbols and square roots of non-numeric
/// expressions: each sqrt(b) becomes a symbol q_b, and the numerator is reduced
/// modulo q_b^2 - b (normal() alone treats sqrt(b) as an unrelated atom, so that
/// sqrt(b)^2 - b would not cancel once it is split over a fraction).
inline bool is_zero_modulo_square_roots(const GiNaC::ex& e) {
    const square_roots_as_symbols r = with_square_roots_as_symbols(e);
    const GiNaC::ex& z = r.e;
    if (r.roots.empty()) return false;
    try {
        const GiNaC::ex n = GiNaC::expand(GiNaC::numer(GiNaC::normal(z)));
        // complex coefficients (I): the real and the imaginary part vanish separately
        std::vector<GiNaC::ex> parts{n};
        if (n.has(GiNaC::I)) parts = {GiNaC::real_part(n), GiNaC::imag_part(n)};
        for (GiNaC::ex part : parts) {
            GiNaC::exmap atoms;  // functions and other non-polynomial parts as symbols
            part = GiNaC::expand(part).to_polynomial(atoms);
            for (const auto& [b, s] : r.roots) {
                // s^2 = N/D: the base may be a fraction (q^2 |B|^2/m^2 + ...), whose 1/m
                // to_polynomial would make an unrelated atom; N and D are made polynomials
                // apart, and the remainder has coefficients in the fractions of the rest
                const GiNaC::ex nd = GiNaC::normal(b).numer_denom();
                const GiNaC::ex base = nd.op(1).is_equal(1) ? b.to_polynomial(atoms)
                                                            : nd.op(0).to_polynomial(atoms) / nd.op(1).to_polynomial(atoms);
                part = GiNaC::expand(GiNaC::rem(part, GiNaC::pow(s, 2) - base, s, false));
            }
            if (!GiNaC::normal(part).is_zero()) return false;
        }
        return true;
    } catch (const std::exception&) {
        return false;  // not decided: not proved zero
    }
}

/// True when e contains b^(k/2), k odd, with b not a number.
inline bool has_symbolic_square_root(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && !GiNaC::is_a<GiNaC::numeric>(it->op(0)) &&
            GiNaC::is_a<GiNaC::numeric>(it->op(1))) {
            const GiNaC::numeric k = GiNaC::ex_to<GiNaC::numeric>(it->op(1)) * 2;
            if (k.is_integer() && k.is_odd()) return true;
        }
    return false;
}

/// sin, cos and tan of atan2(y, x) and of atan(z) as algebraic functions:
/// cos(atan2(y, x)) = x/sqrt(x^2 + y^2), sin(atan2(y, x)) = y/sqrt(x^2 + y^2),
/// tan(atan2(y, x)) = y/x; cos(atan(z)) = 1/sqrt(1 + z^2), sin(atan(z)) =
/// z/sqrt(1 + z^2) (identities for real arguments, which atan2 has). exp of
/// the logarithm of an element (III.1.58: log |z| + i arg z) then gives back its
/// coordinates. The sum under the root is expanded, as log_modulus writes it, so
/// that sqrt(x^2 + y^2) meets the modulus it came from.
inline GiNaC::ex trig_of_arctangents(const GiNaC::ex& e) {
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

/// Exact zero test: true when the expression normalizes to 0 (logarithms and
/// powers of rational numbers are compared over primes, sin, cos, tan and the
/// hyperbolic functions through exponentials, and square roots of expressions
/// as algebraic symbols, when plain normalization does not decide).
inline bool is_zero_scalar(const GiNaC::ex& x) {
    if (x.is_zero()) return true;
    guard_expansion(x, "zero test", true);
    const GiNaC::ex y = expand_rational_logs(trig_of_arctangents(x));
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
    const GiNaC::ex z = trig_exponential_form(y);
    guard_expansion(z, "zero test", true);
    return GiNaC::normal(z).is_zero() || is_zero_modulo_square_roots(z);
}

/// e.subs(s) (s: a relation, a list of them, or an exmap), with a division by
/// zero said before GiNaC evaluates it: GiNaC's power::eval throws for 0^(-k)
/// and loses the power it allocated. Powers are checked innermost first.
template <class S>
GiNaC::ex subs_checked(const GiNaC::ex& e, const S& s) {
    for (auto it = e.postorder_begin(); it != e.postorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::power>(*it) && GiNaC::is_a<GiNaC::numeric>(it->op(1)) &&
            !GiNaC::ex_to<GiNaC::numeric>(it->op(1)).real().is_positive() && it->op(0).subs(s).is_zero())
            throw domain_error("division by zero");
    return e.subs(s);
}

/// Double zero test with an absolute tolerance (callers scale it to the data).
inline bool is_zero_scalar(double x, double tol = 0.0) { return std::abs(x) <= tol; }

/// True when x contains a function call (exp, cos, log, ...).
inline bool has_function_call(const GiNaC::ex& x) {
    if (GiNaC::is_a<GiNaC::function>(x)) return true;
    for (std::size_t k = 0; k < x.nops(); ++k)
        if (has_function_call(x.op(k))) return true;
    return false;
}

/// True when a is a number < 0 or a product with a numeric factor < 0 (-5*t).
inline bool has_negative_sign(const GiNaC::ex& a) {
    if (GiNaC::is_a<GiNaC::numeric>(a)) return GiNaC::ex_to<GiNaC::numeric>(a).is_negative();
    if (GiNaC::is_a<GiNaC::mul>(a))
        for (std::size_t k = 0; k < a.nops(); ++k)
            if (GiNaC::is_a<GiNaC::numeric>(a.op(k)))
                return GiNaC::ex_to<GiNaC::numeric>(a.op(k)).is_negative();
    return false;
}

/// cos(-u) -> cos(u), sin(-u) -> -sin(u), everywhere in e (GiNaC leaves
/// cos(-5*t) alone, so that cos(5*t) and cos(-5*t) would not combine).
inline GiNaC::ex normalize_trig_signs(const GiNaC::ex& e) {
    struct trig_sign : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            const GiNaC::ex y = x.map(*this);
            if (GiNaC::is_a<GiNaC::function>(y) && y.nops() == 1 && has_negative_sign(y.op(0))) {
                const std::string f = GiNaC::ex_to<GiNaC::function>(y).get_name();
                if (f == "cos") return GiNaC::cos(-y.op(0));
                if (f == "sin") return -GiNaC::sin(-y.op(0));
            }
            return y;
        }
    } m;
    return m(e);
}

/// Bring an exact coefficient to its simplest stored form: rational functions of
/// symbols are expanded and normalized (one fraction, common factors cancelled);
/// expressions with function calls, such as the closed forms of exp(w t), are only
/// expanded, so that they stay sums of exponentials and trigonometric terms instead
/// of becoming one fraction over exp(...). Identity for doubles.
inline GiNaC::ex tidy(const GiNaC::ex& x) {
    guard_expansion(x, "simplification", false);
    const GiNaC::ex e = GiNaC::expand(trig_of_arctangents(x));
    if (has_function_call(e)) return GiNaC::expand(normalize_trig_signs(e));
    guard_expansion(e, "simplification", true);
    return GiNaC::normal(e);
}
inline double tidy(double x) { return x; }

/// An expression as text for an error message, cut to about `max` characters
/// (a message that quotes a 10 000-character minimal polynomial helps nobody).
inline std::string message_text(const GiNaC::ex& e, std::size_t max = 160) {
    std::ostringstream os;
    os << e;
    std::string s = os.str();
    if (s.size() > max)
        s = s.substr(0, max / 2) + " ... " + s.substr(s.size() - max / 4) + " (" +
            std::to_string(s.size()) + " characters)";
    return s;
}

/// log |a + i b|: exact as log(a^2 + b^2)/2, so that the logarithms of one
/// number combine (log(26)/2, never log(sqrt(26))); double through hypot, which
/// does not overflow.
inline GiNaC::ex log_modulus(const GiNaC::ex& a, const GiNaC::ex& b) {
    return GiNaC::log(tidy(a * a + b * b)) / 2;
}
inline double log_modulus(double a, double b) { return std::log(std::hypot(a, b)); }

/// e^x, exact with the terms c log(y) of x taken out as y^c, so that exp(log w)
/// gives back rational coordinates (GiNaC leaves exp(log(2)/2) unevaluated);
/// std::exp on the double path.
inline GiNaC::ex exp_scalar(const GiNaC::ex& x) {
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
inline double exp_scalar(double x) { return std::exp(x); }

/// Scalar from an integer, for both paths.
template <class T> T from_int(long k) { return T(k); }
template <> inline GiNaC::ex from_int<GiNaC::ex>(long k) { return GiNaC::ex(GiNaC::numeric(k)); }

/// One over 2^n, exact or double.
template <class T> T inv_pow2(unsigned n) { return std::ldexp(1.0, -int(n)); }
template <> inline GiNaC::ex inv_pow2<GiNaC::ex>(unsigned n) {
    return GiNaC::ex(GiNaC::numeric(1) / GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(n)));
}

}  // namespace symrep
