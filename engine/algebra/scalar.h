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
#include <sstream>
#include <string>
#include <ginac/ginac.h>

namespace symrep {

/// Exact zero test: true when the expression normalizes to 0.
inline bool is_zero_scalar(const GiNaC::ex& x) { return x.is_zero() || GiNaC::normal(x).is_zero(); }
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
    const GiNaC::ex e = GiNaC::expand(x);
    return has_function_call(e) ? GiNaC::expand(normalize_trig_signs(e)) : GiNaC::normal(e);
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

/// Scalar from an integer, for both paths.
template <class T> T from_int(long k) { return T(k); }
template <> inline GiNaC::ex from_int<GiNaC::ex>(long k) { return GiNaC::ex(GiNaC::numeric(k)); }

/// One over 2^n, exact or double.
template <class T> T inv_pow2(unsigned n) { return std::ldexp(1.0, -int(n)); }
template <> inline GiNaC::ex inv_pow2<GiNaC::ex>(unsigned n) {
    return GiNaC::ex(GiNaC::numeric(1) / GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(n)));
}

}  // namespace symrep
