// symrep/numeric/reference.h -- the exact value of a closed form at double
// inputs, to extended precision: the reference against which every double
// evaluation (compiled, stable, integrated) is measured.
//
// Each input double is taken as the exact binary rational it denotes (no
// decimal rounding), substituted into the expressions, and the result is
// evaluated by GiNaC/CLN with `digits` decimal digits. So the reference is the
// exact solution for the same binary inputs, the measure the speed-accuracy
// charts and the stability tests need: it separates the error of an
// evaluation method from the error of the inputs themselves.
//
// Cost: milliseconds per point (CLN software floats); for tests and charts,
// not for production evaluation.
#pragma once

#include <vector>

#include <ginac/ginac.h>

namespace symrep::num {

/// Sets GiNaC::Digits for one scope (restored when it ends, also by an exception).
struct digits_scope {
    long saved;
    explicit digits_scope(long d) : saved(GiNaC::Digits) { GiNaC::Digits = d; }
    ~digits_scope() { GiNaC::Digits = saved; }
    digits_scope(const digits_scope&) = delete;
    digits_scope& operator=(const digits_scope&) = delete;
};

/// The exact rational value of a double (finite, subnormals too; throws domain_error for
/// inf/nan).
GiNaC::numeric exact_rational(double x);

/// A double as a GiNaC number: GiNaC::numeric(x) (a double float), except below the
/// smallest normal double, which CLN's double floats do not hold (numeric(4.9e-324) throws
/// "floating-point underflow"): there the double's exact value as a long float at the working
/// precision (at least 16 digits, the smallest long float). A result
/// of eval of 1e-320 is that number, not an error (issue 27). Throws domain_error for inf/nan.
GiNaC::numeric from_double(double x);

/// e with every floating-point number in it replaced by the exact rational it
/// denotes (a float read from a script is a binary number of ~20 digits; CLN
/// would otherwise compute with no more digits than it has).
GiNaC::ex exact_floats_of(const GiNaC::ex& e);

/// The decimal digits that the arguments of the functions in e need beyond the
/// wanted ones: max over the symbol-free arguments a of functions (sin, cos, exp
/// ...) of log10|a| (0 when all are below 1). cos(2*10^300) needs 301 more
/// digits of its argument (and of pi) for its reduction modulo 2 pi to be exact
/// to the wanted digits: with 17 digits its value is noise. Floats in e are
/// taken as the exact binary numbers they denote.
long reduction_digits(const GiNaC::ex& e);

/// e evaluated (GiNaC evalf) with `digits` significant digits in every argument
/// reduction: Digits is raised by reduction_digits(e) plus a guard for the
/// evaluation, floats in e are taken as exact. The numbers in the result carry
/// the raised precision (round them for printing with round_digits).
GiNaC::ex evalf_reduced(const GiNaC::ex& e, long digits);

/// floor(log10 |x|) within 1 (from the bit lengths of the exact rational of x, so without
/// overflow or underflow at any size: 10^-5000 and 10^5000 too); x != 0, real.
long decimal_exponent(const GiNaC::numeric& x);

/// Every floating-point number in e rounded to `digits` significant decimal
/// digits (printed with at most that many).
GiNaC::ex round_digits(const GiNaC::ex& e, long digits);

/// e with every floating-point number in it replaced by the decimal rational it
/// prints as (its shortest decimal, the number a script wrote: 1e300 -> 10^300).
/// For times, where a long phase makes the difference between the decimal a user
/// wrote and its binary rounding visible (sin(1e300)).
GiNaC::ex decimal_floats_of(const GiNaC::ex& e);

/// The real value of a symbol-free expression with `digits` decimal digits
/// (CLN; floats in e taken as exact); domain_error when it is not a real number.
GiNaC::numeric evaluate_real(const GiNaC::ex& e, int digits);

/// The double nearest the exact value of a symbol-free expression (its
/// floats taken as exact): evaluated by CLN with 30, 60, 120 ... digits and a
/// proved error bound (numeric/certified.h) until the bound is 2^-60 relative.
/// Immune to the cancellation and long phases that a fixed-precision evalf
/// suffers ((1 - cos(x))/x^2 is 0 with 20 digits at x = 1e-12, and with 160 at
/// x = 1e-100). domain_error when it is not a real number, or when max_digits
/// do not reach the bound (a cancellation of more digits, or a 0 that the
/// bound cannot prove). Expressions the bound does not cover (complex
/// intermediate values, functions other than sin cos tan exp log abs atan sinh
/// cosh tanh) fall back to precisions raised until two agree to 2^-60.
double accurate_double(const GiNaC::ex& e, int max_digits = 2560);

/// e with inputs = point put in exactly (the doubles as the binary rationals
/// they denote); where that is 0/0 (a removable singularity), the value of the
/// continuous extension: the limit along a line through the point, as below.
/// A pole gives domain_error.
GiNaC::ex value_at(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs, const std::vector<double>& point);

/// outputs evaluated at inputs = point (point.size() == inputs.size()) with
/// `digits` significant decimal digits, rounded to long double at the end.
/// Where an output is 0/0 at the point (a removable singularity: |w| = 0 in a
/// rotating-frame solution, an exact resonance), its limit along a line
/// through the point (the value of its continuous extension) is returned;
/// a pole gives domain_error.
/// Throws type_error when a symbol has no value, domain_error for a complex or
/// non-numeric result. digits: 20 .. 10000.
std::vector<long double> reference_eval(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                                        const std::vector<double>& point, int digits = 60);

}  // namespace symrep::num
