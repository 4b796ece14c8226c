// symrep/scalar/equality.cpp -- the three-valued zero decision (see equality.h).
#include "symrep/scalar/equality.h"

#include <cstdint>
#include <map>
#include <sstream>
#include <vector>

#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/scalar/scalar.h"

namespace symrep {

namespace {

/// The symbols of x, sorted by name (a deterministic order: GiNaC's own order follows creation).
std::vector<GiNaC::ex> symbols_by_name(const GiNaC::ex& x) {
    std::map<std::string, GiNaC::ex> found;
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it)) found.emplace(GiNaC::ex_to<GiNaC::symbol>(*it).get_name(), *it);
    std::vector<GiNaC::ex> out;
    for (auto& [n, s] : found) out.push_back(s);
    return out;
}

/// 64-bit FNV-1a of the printed expression: the seed of the witness points, so
/// that the same input tries the same points (output is deterministic).
std::uint64_t seed_of(const GiNaC::ex& x) {
    std::ostringstream os;
    os << x;
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : os.str()) h = (h ^ c) * 1099511628211ull;
    return h;
}

std::uint64_t next(std::uint64_t& s) {  // splitmix64
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// A rational num/den (1 <= num <= 29, 2 <= den <= 10), negative half the time unless positive.
GiNaC::numeric sample(std::uint64_t& s, bool positive) {
    const long num = long(next(s) % 29) + 1, den = long(next(s) % 9) + 2;
    GiNaC::numeric v(num, den);
    if (!positive && next(s) % 2) v = -v;
    return v;
}

}  // namespace

bool evaluate_numeric(const GiNaC::ex& x, long digits, GiNaC::numeric& out) {
    const long saved = GiNaC::Digits;
    GiNaC::Digits = digits;
    try {
        const GiNaC::ex v = GiNaC::evalf(x);
        GiNaC::Digits = saved;
        if (!GiNaC::is_a<GiNaC::numeric>(v)) return false;
        out = GiNaC::ex_to<GiNaC::numeric>(v);
        return true;
    } catch (const std::bad_alloc&) {
        GiNaC::Digits = saved;
        throw;
    } catch (const std::exception&) {
        GiNaC::Digits = saved;
        return false;
    }
}

namespace {

/// The magnitude of a symbol-free x at 40 digits: what its terms add up to without
/// cancellation (sums by the sum of their terms' magnitudes, products by the product, a
/// positive integer power by the power; anything else by its absolute value). 0 when it
/// cannot be evaluated.
GiNaC::numeric magnitude(const GiNaC::ex& x) {
    if (GiNaC::is_a<GiNaC::add>(x) || GiNaC::is_a<GiNaC::mul>(x)) {
        const bool sum = GiNaC::is_a<GiNaC::add>(x);
        GiNaC::numeric m = sum ? 0 : 1;
        for (std::size_t i = 0; i < x.nops(); ++i) m = sum ? m + magnitude(x.op(i)) : m * magnitude(x.op(i));
        return m;
    }
    if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_pos_integer())
        return GiNaC::pow(magnitude(x.op(0)), GiNaC::ex_to<GiNaC::numeric>(x.op(1)));
    GiNaC::numeric v;
    return evaluate_numeric(x, 40, v) ? GiNaC::abs(v) : GiNaC::numeric(0);
}

/// A nonzero value shown at two precisions: the same number to 20 digits, above 1e-25 of the
/// magnitude of x's terms (relative, so that a number of any size, 1e-270 sqrt(3) as much as
/// 1, is seen: an absolute floor of 1e-25 left the pivots of scenes with values of 1e-270
/// undecided, issue 27). Below 1e-25 of it and above 1e-60, at 80 and 160 digits.
bool nonzero_witness(const GiNaC::ex& x, GiNaC::numeric& value) {
    GiNaC::numeric a, b;
    if (!evaluate_numeric(x, 40, a) || !evaluate_numeric(x, 80, b)) return false;
    const GiNaC::numeric size = GiNaC::abs(b), scale = magnitude(x);
    const GiNaC::numeric e20 = GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(20)), e25 = GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(25));
    if (size.is_zero() || scale.is_zero()) return false;
    if (size * e25 < scale) {
        GiNaC::numeric c;
        if (size * GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(60)) < scale || !evaluate_numeric(x, 160, c)) return false;
        a = b, b = c;
    }
    if (GiNaC::abs(a - b) * e20 > size) return false;
    value = b;
    return true;
}

}  // namespace

namespace {

/// A factor that is a nonzero number exactly: a nonzero numeric, or a power of a positive
/// rational (sqrt(N), N^(-3/2)), which is positive whatever its size.
bool exactly_nonzero_factor(const GiNaC::ex& f) {
    if (GiNaC::is_a<GiNaC::numeric>(f)) return !f.is_zero();
    return GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::numeric>(f.op(0)) &&
           GiNaC::ex_to<GiNaC::numeric>(f.op(0)).is_rational() && GiNaC::ex_to<GiNaC::numeric>(f.op(0)).is_positive() &&
           GiNaC::is_a<GiNaC::numeric>(f.op(1)) && GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_rational();
}

}  // namespace

zero_decision decide_zero(const GiNaC::ex& x) {
    zero_decision d;
    if (GiNaC::is_a<GiNaC::numeric>(x)) {  // a number (1/10^30, a float): decided exactly, whatever its size
        d.is_zero = x.is_zero() ? truth::yes : truth::no;
        if (!x.is_zero()) d.value = x;
        return d;
    }
    // a constant c r y with c, r nonzero numbers (a rational, sqrt of a positive rational) is 0
    // exactly when y is: decided on y, whose value is not scaled down to below the witness's
    // floor by c (the pivots of a scene with the exact rationals of doubles are 1e-28 sqrt(...)).
    // Expressions with symbols keep their witness points (seeded by the whole expression).
    if (GiNaC::is_a<GiNaC::mul>(x) && symbols_by_name(x).empty()) {
        GiNaC::ex scale = 1, rest = 1;
        for (std::size_t i = 0; i < x.nops(); ++i)
            (exactly_nonzero_factor(x.op(i)) ? scale : rest) *= x.op(i);
        if (!scale.is_equal(1)) {
            if (GiNaC::is_a<GiNaC::numeric>(rest)) {  // every factor a nonzero number
                d.is_zero = truth::no;
                GiNaC::numeric v;
                if (evaluate_numeric(x, 40, v)) d.value = v;
                return d;
            }
            d = decide_zero(rest);
            if (d.is_zero == truth::no) {
                GiNaC::numeric c;
                d.value = evaluate_numeric(scale, 40, c) ? GiNaC::ex(c * GiNaC::ex_to<GiNaC::numeric>(d.value))
                                                         : d.value;
            }
            return d;
        }
    }
    if (is_zero_scalar(x)) {
        d.is_zero = truth::yes;
        return d;
    }
    const std::vector<GiNaC::ex> syms = symbols_by_name(x);
    std::uint64_t s = seed_of(x);
    const int tries = syms.empty() ? 1 : 8;
    for (int k = 0; k < tries; ++k) {
        check_interrupt();
        GiNaC::exmap point;
        for (const GiNaC::ex& v : syms) point[v] = sample(s, v.info(GiNaC::info_flags::positive));
        GiNaC::ex at;
        try {
            at = syms.empty() ? x : subs_checked(x, point);
        } catch (const symrep::error&) {
            continue;  // a pole at this point
        } catch (const std::bad_alloc&) {
            throw;
        } catch (const std::exception&) {
            continue;
        }
        GiNaC::numeric value;
        if (nonzero_witness(at, value)) {
            d.is_zero = truth::no;
            d.point = point;
            d.value = value;
            return d;
        }
    }
    return d;
}

std::string witness_text(const zero_decision& d) {
    if (d.point.empty()) return "";
    std::map<std::string, std::string> byname;
    for (const auto& [k, v] : d.point) {
        std::ostringstream os;
        os << v;
        byname[GiNaC::ex_to<GiNaC::symbol>(k).get_name()] = os.str();
    }
    std::string out = "at ";
    bool first = true;
    for (const auto& [n, v] : byname) {
        out += (first ? "" : ", ") + n + " = " + v;
        first = false;
    }
    return out;
}

GiNaC::exmap generic_point(const GiNaC::ex& x, const GiNaC::ex& except) {
    GiNaC::exmap point;
    for (auto it = x.preorder_begin(); it != x.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && !it->is_equal(except) && !point.count(*it)) {
            const std::string& name = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
            std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the name
            for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
            point[*it] = GiNaC::numeric(long(1100 + h % 1800), 1000);
        }
    return point;
}

point_value value_at_generic_point(const GiNaC::ex& x) {
    point_value out;
    const GiNaC::exmap point = generic_point(x);
    GiNaC::ex at;
    try {
        at = point.empty() ? x : x.subs(point, GiNaC::subs_options::no_pattern);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
        return out;  // a pole at this point
    }
    out.ok = evaluate_numeric(at, 20, out.low) && evaluate_numeric(at, 40, out.high);
    return out;
}

bool seen_different(const point_value& a, const point_value& b) {
    if (!a.ok || !b.ok) return false;
    const GiNaC::numeric high = a.high - b.high, low = a.low - b.low;
    const GiNaC::numeric size = GiNaC::abs(high);
    static const GiNaC::numeric floor("1e-12");
    static const GiNaC::numeric agree("1e-10");
    return size > floor && GiNaC::abs(low - high) <= agree * size;
}

bool is_nonzero_generic(const GiNaC::ex& x, const std::string& what) {
    if (GiNaC::is_a<GiNaC::numeric>(x)) return !x.is_zero();
    if (is_zero_scalar(x)) return false;
    if (has_symbol(x)) return true;  // generic reading
    const zero_decision d = decide_zero(x);
    if (d.is_zero == truth::yes) return false;
    if (d.is_zero == truth::no) return true;
    const std::string text = message_text(x);  // cut at text_limit::message
    throw domain_error(what + ": cannot decide whether " + text +
                       " is 0 (not proved 0, and not seen nonzero at 80 digits); taking it as nonzero could "
                       "give a wrong answer");
}

bool proved_zero(const GiNaC::ex& x) {
    if (x.is_zero() || is_zero_scalar(x)) return true;
    return decide_zero(x).is_zero == truth::yes;
}

}  // namespace symrep
