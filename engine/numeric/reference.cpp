// symrep/numeric/reference.cpp -- see reference.h.
#include "symrep/numeric/reference.h"
#include "symrep/numeric/quadrature.h"
#include "symrep/numeric/certified.h"
#include "symrep/scalar/floats.h"

#include <cln/float.h>
#include <cln/complex.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "symrep/core/error.h"
#include "symrep/scalar/scalar.h"
#include "symrep/scalar/limit.h"

namespace symrep::num {

GiNaC::numeric exact_rational(double x) {
    if (!std::isfinite(x)) throw domain_error("reference: input is not a finite number");
    if (x == 0) return 0;
    // x = m 2^(e - 53) with m an integer below 2^53 (frexp: no cl_DF, which refuses subnormals)
    int e = 0;
    const double f = std::frexp(x, &e);
    const cln::cl_I m = cln::cl_I(static_cast<long long>(std::ldexp(f, 53)));
    const long k = long(e) - 53;
    const cln::cl_RA v = k >= 0 ? cln::cl_RA(cln::ash(m, k)) : cln::cl_RA(m / cln::ash(cln::cl_I(1), -k));
    return GiNaC::numeric(cln::cl_N(v));
}

GiNaC::numeric from_double(double x) {
    if (!std::isfinite(x)) throw domain_error("reference: input is not a finite number");
    if (x == 0 || std::abs(x) >= std::numeric_limits<double>::min()) return GiNaC::numeric(x);
    const cln::cl_RA v = cln::the<cln::cl_RA>(exact_rational(x).to_cl_N());
    return GiNaC::numeric(cln::cl_N(cln::cl_float(v, cln::float_format(std::max(long(GiNaC::Digits), 16L)))));
}

namespace {


/// Floating-point numbers inside an expression (e.g. 7.2921e-5 read from a
/// script, a float of ~20 digits) replaced by the exact rationals they denote.
/// Without this, CLN would compute every operation involving them to their
/// own precision only (its float contagion rule), whatever Digits says.
struct exact_floats : GiNaC::map_function {
    GiNaC::ex operator()(const GiNaC::ex& e) override {
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (n.is_rational()) return e;
            const cln::cl_N z = n.to_cl_N();
            const cln::cl_R re = cln::realpart(z), im = cln::imagpart(z);
            return GiNaC::numeric(cln::complex(cln::rational(re), cln::rational(im)));
        }
        return e.map(*this);
    }
};

/// r rounded to long double through two doubles (hi + lo); beyond the double
/// range: +-infinity or 0, as double arithmetic would give.
long double to_long_double(const cln::cl_R& r) {
    if (cln::zerop(r)) return 0.0L;
    static const cln::cl_RA largest = cln::rational(cln::cl_DF(std::numeric_limits<double>::max()));
    static const cln::cl_RA smallest_normal = cln::recip(cln::expt_pos(cln::cl_I(2), 1022L));
    static const cln::cl_RA smallest = cln::recip(cln::expt_pos(cln::cl_I(2), 1074L));
    const cln::cl_R a = cln::abs(r);
    if (a > largest) return cln::minusp(r) ? -HUGE_VALL : HUGE_VALL;
    if (a < smallest) return 0.0L;
    if (a < smallest_normal) return static_cast<long double>(cln::double_approx(cln::rational(r)));
    const double hi = cln::double_approx(r);
    const cln::cl_R rest = r - cln::rational(cln::cl_DF(hi));
    const double lo = cln::abs(rest) < smallest_normal ? 0.0 : cln::double_approx(rest);
    return static_cast<long double>(hi) + lo;
}

}  // namespace

// the decimal each float prints as (scalar/floats.h)
GiNaC::ex decimal_floats_of(const GiNaC::ex& e) { return floats_as_decimals(e); }

GiNaC::ex exact_floats_of(const GiNaC::ex& e) {
    exact_floats f;
    return f(e);
}

long reduction_digits(const GiNaC::ex& e) {
    long extra = 0;
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
        if (!GiNaC::is_a<GiNaC::function>(*it)) continue;
        for (std::size_t i = 0; i < it->nops(); ++i) {
            const GiNaC::ex a = it->op(i);
            if (!GiNaC::is_a<GiNaC::numeric>(a) && !a.info(GiNaC::info_flags::numeric)) {
                bool symbol_free = true;
                for (auto j = a.preorder_begin(); j != a.preorder_end() && symbol_free; ++j)
                    symbol_free = !GiNaC::is_a<GiNaC::symbol>(*j);
                if (!symbol_free) continue;
            }
            // the magnitude only: 30 digits give it (nested functions are bounded or their
            // own arguments are counted)
            GiNaC::ex v;
            {
                const digits_scope scope(30 + extra);
                v = exact_floats_of(a).evalf();
            }
            if (!GiNaC::is_a<GiNaC::numeric>(v)) continue;
            const GiNaC::numeric x = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(v));
            if (x.is_zero() || x < 1) continue;
            // log10 from the binary exponent (exact enough, no overflow for 1e100000)
            const cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
            const long bits = cln::integer_length(cln::floor1(r));
            extra = std::max(extra, long(std::ceil(double(bits) * 0.30103)) + 1);
        }
    }
    return extra;
}

GiNaC::ex evalf_reduced(const GiNaC::ex& e, long digits) {
    const GiNaC::ex x = exact_floats_of(e);
    const digits_scope scope(digits + reduction_digits(x) + 10);
    return x.evalf();
}

long decimal_exponent(const GiNaC::numeric& x) {
    const cln::cl_RA a = cln::abs(cln::rational(cln::the<cln::cl_R>(x.to_cl_N())));
    const long bits = long(cln::integer_length(cln::numerator(a))) - long(cln::integer_length(cln::denominator(a)));
    return long(std::floor(double(bits) * 0.30103));
}

namespace {

struct rounder : GiNaC::map_function {
    long digits;
    GiNaC::numeric round(const GiNaC::numeric& n) const { return round_float_digits(n, digits); }
    GiNaC::ex operator()(const GiNaC::ex& e) override {
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
            const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
            if (n.is_rational()) return e;
            if (n.is_real()) return round(n);
            return round(n.real()) + GiNaC::I * round(n.imag());
        }
        return e.map(*this);
    }
};

}  // namespace

GiNaC::ex round_digits(const GiNaC::ex& e, long digits) {
    rounder f;
    f.digits = digits;
    return f(e);
}

GiNaC::numeric evaluate_real(const GiNaC::ex& e, int digits) {
    // the arguments of periodic functions reduced exactly (cos(2*10^300) needs 300 more digits)
    const digits_scope scope(digits + reduction_digits(e));
    const GiNaC::ex v = exact_floats_of(e).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
        throw domain_error("reference: not a real number: " + message_text(v));
    return GiNaC::ex_to<GiNaC::numeric>(v);
}

double accurate_double(const GiNaC::ex& e, int max_digits) {
    // integral objects by quadrature first (GiNaC's evalf of one is good to 1e-8 only)
    const GiNaC::ex x = exact_floats_of(integrals_as_numbers(e));
    // with a proved error bound (numeric/certified.h): two precisions that agree prove
    // nothing where the closed form cancels ((1 - cos(w))/w^2 is 0 at 40, 80, 160 digits
    // for w = 1e-100)
    try {
        const certified_result r = certified_double(x, 0x1p-60, max_digits);
        if (r.proved) return r.value;
        throw domain_error("cannot evaluate to double precision: the closed form cancels more digits than " +
                           std::to_string(max_digits) + " at these values (or is 0 without a proof of it)");
    } catch (const not_certifiable&) {
        // a complex intermediate value or a function without a bound here: increasing
        // precisions until two agree, which a cancellation beyond them would fool
    }
    cln::cl_R previous = 0;
    double result = 0;
    for (int digits = 30; digits <= std::max(30, max_digits); digits *= 2) {
        const cln::cl_R now = cln::the<cln::cl_R>(evaluate_real(x, digits).to_cl_N());
        result = static_cast<double>(to_long_double(now));
        if (digits > 30) {
            if (cln::zerop(now)) {
                if (cln::zerop(previous) && digits >= 120) break;
            } else if (cln::abs(now - previous) <= cln::abs(now) * cln::recip(cln::expt_pos(cln::cl_I(2), 60L))) {
                break;
            }
        }
        previous = now;
    }
    return result;
}

GiNaC::ex value_at(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs, const std::vector<double>& point) {
    if (point.size() != inputs.size())
        throw type_error("reference: " + std::to_string(point.size()) + " values for " +
                         std::to_string(inputs.size()) + " inputs");
    GiNaC::exmap at;
    for (std::size_t i = 0; i < inputs.size(); ++i) at[inputs[i]] = exact_rational(point[i]);
    // floats made exact before the substitution, which would round float * input at once
    const GiNaC::ex x = exact_floats_of(e);
    try {
        return x.subs(at, GiNaC::subs_options::no_pattern);
    } catch (const error&) {
        throw;
    } catch (const std::exception& why) {
        if (!is_division_by_zero(why)) throw;
    }
    // 0/0 at the point (w = 0 in 1/|w|^2 terms, a resonance w0 = nu in
    // 1/(w0^2 - nu^2)): the value of the continuous extension, the limit as the
    // inputs approach the point (scalar/limit.h)
    try {
        return limit_at_point(inputs.size(), [&](const std::vector<GiNaC::ex>& off) {
            GiNaC::exmap near;
            for (std::size_t i = 0; i < inputs.size(); ++i) near[inputs[i]] = at[inputs[i]] + off[i];
            return x.subs(near, GiNaC::subs_options::no_pattern);
        });
    } catch (const domain_error& why) {
        throw domain_error(std::string("reference: no value at this point (") + why.what() + ")");
    }
}

std::vector<long double> reference_eval(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                                        const std::vector<double>& point, int digits) {
    if (point.size() != inputs.size())
        throw type_error("reference: " + std::to_string(point.size()) + " values for " +
                         std::to_string(inputs.size()) + " inputs");
    if (digits < 20 || digits > 10000) throw domain_error("reference: digits must be in 20 .. 10000");
    std::vector<long double> out;
    out.reserve(outputs.size());
    for (const GiNaC::ex& e : outputs) {
        const GiNaC::numeric v = evaluate_real(value_at(e, inputs, point), digits);
        const cln::cl_R r = cln::the<cln::cl_R>(v.to_cl_N());
        out.push_back(to_long_double(r));
    }
    return out;
}

}  // namespace symrep::num
