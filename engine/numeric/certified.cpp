// symrep/numeric/certified.cpp -- see certified.h.
#include "symrep/numeric/certified.h"

#include <cln/exception.h>
#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "symrep/core/error.h"
#include "symrep/numeric/reference.h"

namespace symrep::num {

namespace {

/// A bound that this precision cannot give (a divisor or logarithm argument whose
/// error interval reaches 0, an exponential of an argument known to +-1/2 only).
struct need_more_precision {};

struct bounded_value {
    cln::cl_F v, e;  // value and a bound on |v - exact|
};

class bounded_walk {
public:
    explicit bounded_walk(long digits) : f_(cln::float_format(digits)) {
        zero_ = cln::cl_float(0, f_);
        one_ = cln::cl_float(1, f_);
        const long p = long(cln::float_digits(one_));
        u_ = cln::scale_float(one_, 1 - p);     // one ulp of 1: any correctly or faithfully rounded operation
        ferr_ = cln::scale_float(one_, 4 - p);  // 16 ulp: CLN's transcendental functions
    }

    bounded_value eval(const GiNaC::ex& x) {
        auto it = memo_.find(x);
        if (it != memo_.end()) return it->second;
        bounded_value r = eval_uncached(x);
        memo_.emplace(x, r);
        return r;
    }

    const cln::cl_F& zero() const { return zero_; }

private:
    cln::float_format_t f_;
    cln::cl_F zero_, one_, u_, ferr_;
    std::unordered_map<GiNaC::ex, bounded_value, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> memo_;

    cln::cl_F fl(const cln::cl_RA& q) const { return cln::cl_float(q, f_); }
    cln::cl_F abs(const cln::cl_F& x) const { return cln::abs(x); }
    cln::cl_F max0(const cln::cl_F& x) const { return cln::minusp(x) ? zero_ : x; }
    cln::cl_F min(const cln::cl_F& a, const cln::cl_F& b) const { return a < b ? a : b; }
    /// an upper bound of e^x - 1 for 0 <= x < 1/2: x/(1 - x)
    cln::cl_F expm1_bound(const cln::cl_F& x) const {
        if (!(x < cln::scale_float(one_, -1))) throw need_more_precision{};
        return x / (one_ - x) * (one_ + 4 * u_);
    }

    bounded_value add(const bounded_value& a, const bounded_value& b) const {
        const cln::cl_F v = a.v + b.v;
        return {v, a.e + b.e + u_ * abs(v)};
    }
    bounded_value mul(const bounded_value& a, const bounded_value& b) const {
        const cln::cl_F v = a.v * b.v;
        return {v, abs(a.v) * b.e + abs(b.v) * a.e + a.e * b.e + u_ * abs(v)};
    }
    bounded_value div(const bounded_value& a, const bounded_value& b) const {
        if (cln::zerop(b.v) && cln::zerop(b.e)) throw domain_error("division by zero");
        if (!(b.e < abs(b.v))) throw need_more_precision{};
        const cln::cl_F v = a.v / b.v;
        // |a/b - a'/b'| <= (|a/b| eb + ea) / (|b| - eb)
        return {v, (abs(v) * b.e + a.e) / (abs(b.v) - b.e) * (one_ + 4 * u_) + u_ * abs(v)};
    }
    bounded_value power_int(bounded_value base, cln::cl_I n) const {
        const bool negative = cln::minusp(n);
        if (negative) n = -n;
        bounded_value r{one_, zero_};
        bool first = true;
        while (!cln::zerop(n)) {
            if (cln::oddp(n)) {
                r = first ? base : mul(r, base);
                first = false;
            }
            n = cln::ash(n, -1);
            if (!cln::zerop(n)) base = mul(base, base);
        }
        return negative ? div({one_, zero_}, r) : r;
    }
    bounded_value sqrt(const bounded_value& a) const {
        if (cln::minusp(a.v)) throw not_certifiable("the square root of a negative number");
        const cln::cl_F v = cln::sqrt(a.v);
        cln::cl_F e = zero_;
        if (!cln::zerop(a.e)) {
            // |sqrt(a') - sqrt(a)| = |a' - a| / (sqrt(a') + sqrt(a)) <= sqrt(|a' - a|)
            e = cln::sqrt(a.e);
            const cln::cl_F low = a.v - a.e;
            if (cln::plusp(low)) e = min(e, a.e / (v + cln::sqrt(low)));
        }
        return {v, e + u_ * v};
    }
    /// The argument's error plus an ulp of it beyond |a| = 1 (argument reduction).
    cln::cl_F reduced_error(const bounded_value& a) const {
        return abs(a.v) > one_ ? a.e + u_ * abs(a.v) : a.e;
    }
    bounded_value exp(const bounded_value& a) const {
        cln::cl_F v;
        try {
            v = cln::exp(a.v);
        } catch (const cln::runtime_exception&) {
            // beyond CLN's exponent range (exp(-1e300)): 0, within exp(a + ea) < 2^(-2^40)
            // when a + ea < -2^41. Not the least positive float as the bound: a product of
            // it with any number below 1 would underflow in turn ((exp(-10^300) - 1)/10^300)
            const cln::cl_F huge_exponent = cln::scale_float(one_, 41);
            if (!(a.v + reduced_error(a) < -huge_exponent)) throw;
            return {zero_, cln::scale_float(one_, -cln::ash(cln::cl_I(1), 40))};
        }
        return {v, abs(v) * expm1_bound(reduced_error(a)) + ferr_ * abs(v)};
    }
    bounded_value log(const bounded_value& a) const {
        if (cln::minusp(a.v)) throw not_certifiable("the logarithm of a negative number");
        if (cln::zerop(a.v) && cln::zerop(a.e)) throw domain_error("log(0)");
        const cln::cl_F low = a.v - a.e;
        if (!cln::plusp(low)) throw need_more_precision{};
        const cln::cl_F v = cln::ln(a.v);
        const cln::cl_F rho = a.e / a.v;  // |log a' - log a| <= -log(1 - rho) <= rho / (1 - rho)
        return {v, rho / (one_ - rho) * (one_ + 4 * u_) + ferr_ * abs(v) + u_};
    }

    bounded_value function(const GiNaC::ex& x) {
        const std::string name = GiNaC::ex_to<GiNaC::function>(x).get_name();
        if (x.nops() != 1) throw not_certifiable("function " + name);
        const bounded_value a = eval(x.op(0));
        if (name == "exp") return exp(a);
        if (name == "log") return log(a);
        if (name == "abs") return {abs(a.v), a.e};
        if (name == "sin" || name == "cos") {
            const cln::cos_sin_t cs = cln::cos_sin(a.v);
            const cln::cl_F c = cln::the<cln::cl_F>(cs.cos), s = cln::the<cln::cl_F>(cs.sin);
            const cln::cl_F ae = reduced_error(a);
            const cln::cl_F v = name == "sin" ? s : c;
            const cln::cl_F derivative = min(one_, abs(name == "sin" ? c : s) + ae);
            return {v, derivative * ae + ferr_ * abs(v)};
        }
        if (name == "tan") {
            const cln::cl_F v = cln::tan(a.v);
            const cln::cl_F ae = reduced_error(a);
            // tan' = 1 + tan^2; no pole within the error interval while (1 + v^2) ae < 1/4
            const cln::cl_F d = (one_ + v * v) * ae;
            if (!(d < cln::scale_float(one_, -2))) throw need_more_precision{};
            const cln::cl_F vmax = abs(v) + 2 * d;
            return {v, (one_ + vmax * vmax) * ae + ferr_ * abs(v)};
        }
        if (name == "atan") {
            const cln::cl_F v = cln::the<cln::cl_F>(cln::atan(a.v));
            const cln::cl_F m = max0(abs(a.v) - a.e);
            return {v, a.e / (one_ + m * m) + ferr_ * abs(v)};
        }
        if (name == "sinh") {
            const cln::cl_F v = cln::sinh(a.v);
            return {v, cln::cosh(abs(a.v) + a.e) * a.e + ferr_ * abs(v)};
        }
        if (name == "cosh") {
            const cln::cl_F v = cln::cosh(a.v);
            return {v, cln::sinh(abs(a.v) + a.e) * a.e + ferr_ * abs(v)};
        }
        if (name == "tanh") {
            const cln::cl_F v = cln::tanh(a.v);
            const cln::cl_F m = cln::tanh(max0(abs(a.v) - a.e));
            return {v, (one_ - m * m) * a.e + ferr_ * abs(v)};
        }
        throw not_certifiable("function " + name);
    }

    bounded_value eval_uncached(const GiNaC::ex& x) {
        using namespace GiNaC;
        if (is_a<GiNaC::numeric>(x)) {
            const GiNaC::numeric& n = ex_to<GiNaC::numeric>(x);
            if (!n.is_real()) throw not_certifiable("a complex number");
            const cln::cl_RA q = n.is_rational() ? cln::the<cln::cl_RA>(n.to_cl_N())
                                                 : cln::rational(cln::the<cln::cl_R>(n.to_cl_N()));
            const cln::cl_F v = fl(q);
            return {v, cln::rational(v) == q ? zero_ : u_ * abs(v)};
        }
        if (is_a<constant>(x)) {
            cln::cl_F v;
            if (x.is_equal(Pi)) v = cln::pi(f_);
            else if (x.is_equal(Euler)) v = cln::eulerconst(f_);
            else if (x.is_equal(Catalan)) v = cln::catalanconst(f_);
            else throw not_certifiable("constant");
            return {v, ferr_ * v};
        }
        if (is_a<GiNaC::add>(x)) {
            bounded_value r = eval(x.op(0));
            for (std::size_t i = 1; i < x.nops(); ++i) r = add(r, eval(x.op(i)));
            return r;
        }
        if (is_a<GiNaC::mul>(x)) {
            bounded_value r = eval(x.op(0));
            for (std::size_t i = 1; i < x.nops(); ++i) {
                const ex& y = x.op(i);
                // b^(-k): a division by b^k, not a multiplication by its rounded reciprocal
                if (is_a<power>(y) && is_a<GiNaC::numeric>(y.op(1)) && ex_to<GiNaC::numeric>(y.op(1)).is_integer() &&
                    ex_to<GiNaC::numeric>(y.op(1)).is_negative())
                    r = div(r, power_of(y.op(0), -ex_to<GiNaC::numeric>(y.op(1))));
                else
                    r = mul(r, eval(y));
            }
            return r;
        }
        if (is_a<power>(x)) {
            const ex& b = x.op(0);
            const ex& k = x.op(1);
            if (is_a<GiNaC::numeric>(k) && ex_to<GiNaC::numeric>(k).is_rational())
                return power_of(b, ex_to<GiNaC::numeric>(k));
            return general_power(eval(b), eval(k));
        }
        if (is_a<GiNaC::function>(x)) return function(x);
        throw not_certifiable("not a number");
    }

    /// b^k for a rational k: integers by repeated multiplication, halves by sqrt.
    bounded_value power_of(const GiNaC::ex& b, const GiNaC::numeric& k) {
        const cln::cl_RA q = cln::the<cln::cl_RA>(k.to_cl_N());
        const cln::cl_I num = cln::numerator(q), den = cln::denominator(q);
        if (den == 1) return power_int(eval(b), num);
        if (den == 2) return power_int(sqrt(eval(b)), num);
        return general_power(eval(b), {fl(q), cln::rational(fl(q)) == q ? zero_ : u_ * abs(fl(q))});
    }

    /// b^x = exp(x log b) for b > 0.
    bounded_value general_power(const bounded_value& b, const bounded_value& x) {
        if (!cln::plusp(b.v)) throw not_certifiable("a power of a number that is not positive");
        const bounded_value l = log(b);
        return exp(mul(x, l));
    }
};

double to_double(const cln::cl_F& v) {
    if (cln::zerop(v)) return 0.0;
    const cln::cl_F a = cln::abs(v);
    const double s = cln::minusp(v) ? -1.0 : 1.0;
    if (cln::float_exponent(a) > 1024) return s * std::numeric_limits<double>::infinity();
    if (cln::float_exponent(a) < -1080) return s * 0.0;
    if (cln::float_exponent(a) < -1000)
        return std::ldexp(cln::double_approx(cln::scale_float(v, 1000)), -1000);  // subnormal
    return cln::double_approx(v);
}

/// An upper bound of e as a double: rounded up, the smallest subnormal for a nonzero e below it.
double bound_to_double(const cln::cl_F& e) {
    if (cln::zerop(e)) return 0.0;
    const double d = to_double(e) * (1 + 0x1p-50);
    return d > 0 ? std::max(d, std::numeric_limits<double>::denorm_min()) : std::numeric_limits<double>::denorm_min();
}

}  // namespace

certified_result certified_double(const GiNaC::ex& e, double rel_tol, int max_digits) {
    const GiNaC::ex x = exact_floats_of(e);
    certified_result out;
    for (int digits = 30; digits <= std::max(30, max_digits); digits *= 2) {
        try {
            bounded_walk walk(digits);
            const bounded_value r = walk.eval(x);
            out.value = to_double(r.v);
            out.bound = bound_to_double(r.e);
            out.digits = digits;
            const cln::cl_F tol = cln::cl_float(rel_tol, walk.zero());
            // accepted: within rel_tol, or the whole error interval below 2^-1080 (0 as a double)
            const bool tiny = cln::zerop(cln::abs(r.v) + r.e) || cln::float_exponent(cln::abs(r.v) + r.e) < -1080;
            if (r.e <= tol * cln::abs(r.v) || tiny) {
                if (tiny) {
                    out.value = 0.0;
                    out.bound = cln::zerop(cln::abs(r.v) + r.e) ? 0.0 : std::numeric_limits<double>::denorm_min();
                }
                out.proved = true;
                return out;
            }
        } catch (const need_more_precision&) {
            out.bound = std::numeric_limits<double>::infinity();
        } catch (const cln::floating_point_exception&) {
            throw not_certifiable("a floating-point exception (overflow)");
        }
    }
    return out;
}

}  // namespace symrep::num
