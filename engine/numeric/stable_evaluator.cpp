// symrep/numeric/stable_evaluator.cpp -- see stable_evaluator.h.
#include "symrep/numeric/stable_evaluator.h"

#include <cln/float.h>
#include <cln/real.h>
#include <quadmath.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include "symrep/core/error.h"
#include "symrep/numeric/certified.h"
#include "symrep/numeric/reference.h"

namespace symrep::num {

const char* tier_name(precision_tier t) {
    switch (t) {
        case precision_tier::binary64: return "binary64";
        case precision_tier::binary128: return "binary128";
        case precision_tier::multiprecision: return "multiprecision";
    }
    return "?";
}

namespace {

// The arithmetic of one tier: unit roundoff u (half an ulp of 1), the bound
// on a library function's error relative to its result (f_err), and the
// functions themselves. The specializations look alike on purpose: one table per
// type, each naming its own library (libm, libquadmath).
template <class T>
struct arith;

template <>
struct arith<double> {
    static constexpr double u = 0x1p-53;
    static constexpr double f_err = 0x1p-52;  // glibc: < 1 ulp for these functions
    static constexpr double min_normal = 0x1p-1022, eta = 0x1p-1074;  // below min_normal: eta absolute
    static double abs(double x) { return std::fabs(x); }
    static double sqrt(double x) { return std::sqrt(x); }
    static double exp(double x) { return std::exp(x); }
    static double expm1(double x) { return std::expm1(x); }
    static double log(double x) { return std::log(x); }
    static double log1p(double x) { return std::log1p(x); }
    static double pow(double x, double y) { return std::pow(x, y); }
    static double sin(double x) { return std::sin(x); }
    static double cos(double x) { return std::cos(x); }
    static double tan(double x) { return std::tan(x); }
    static double asin(double x) { return std::asin(x); }
    static double acos(double x) { return std::acos(x); }
    static double atan(double x) { return std::atan(x); }
    static double atan2(double y, double x) { return std::atan2(y, x); }
    static double sinh(double x) { return std::sinh(x); }
    static double cosh(double x) { return std::cosh(x); }
    static double tanh(double x) { return std::tanh(x); }
    static double asinh(double x) { return std::asinh(x); }
    static double acosh(double x) { return std::acosh(x); }
    static double atanh(double x) { return std::atanh(x); }
    static bool finite(double x) { return std::isfinite(x); }
};

template <>
struct arith<__float128> {
    using q = __float128;
    static constexpr q u = 0x1p-113;
    static constexpr q f_err = 0x1p-110;  // libquadmath: a few ulp
    static inline const q min_normal = ldexpq(1, -16382), eta = ldexpq(1, -16494);
    static q abs(q x) { return fabsq(x); }
    static q sqrt(q x) { return sqrtq(x); }
    static q exp(q x) { return expq(x); }
    static q expm1(q x) { return expm1q(x); }
    static q log(q x) { return logq(x); }
    static q log1p(q x) { return log1pq(x); }
    static q pow(q x, q y) { return powq(x, y); }
    static q sin(q x) { return sinq(x); }
    static q cos(q x) { return cosq(x); }
    static q tan(q x) { return tanq(x); }
    static q asin(q x) { return asinq(x); }
    static q acos(q x) { return acosq(x); }
    static q atan(q x) { return atanq(x); }
    static q atan2(q y, q x) { return atan2q(y, x); }
    static q sinh(q x) { return sinhq(x); }
    static q cosh(q x) { return coshq(x); }
    static q tanh(q x) { return tanhq(x); }
    static q asinh(q x) { return asinhq(x); }
    static q acosh(q x) { return acoshq(x); }
    static q atanh(q x) { return atanhq(x); }
    static bool finite(q x) { return finiteq(x); }
};

template <class T>
T infinity() {
    return T(std::numeric_limits<double>::infinity());
}

template <class T>
T max0(T x) {
    return x > T(0) ? x : T(0);
}

template <class T>
T min(T a, T b) {
    return a < b ? a : b;
}

/// The bound of a sum's error: operand bounds plus the rounding of the result.
template <class T>
T sum_bound(T ea, T eb, T v) {
    return ea + eb + arith<T>::u * arith<T>::abs(v);
}

/// Propagated error of f(a) for |a' - a| <= ea, given a bound L of |f'| on
/// [a - ea, a + ea], plus f's own error relative to its value.
template <class T>
T function_bound(T L, T ea, T v) {
    return L * ea + arith<T>::f_err * arith<T>::abs(v);
}

/// Splits the exact value of a constant into binary64 and binary128
/// roundings with their exact errors.
struct constant_split {
    double bound64;
    __float128 value128;
    __float128 bound128;
    double lo64;      // exact - double, rounded to double
    double bound_dd;  // |exact - (double + lo64)|
};

constant_split split_constant(double c, const GiNaC::ex& source, bool known) {
    const double unknown64 = std::fabs(c) * 0x1p-52;
    if (!known) return {unknown64, __float128(c), __float128(unknown64), 0.0, unknown64};
    try {
        // exact - c to 2^-70 relative with a proved bound (numeric/certified.h): a
        // constant that cancels (1 - cos(1e-30)) is not 0 at 60 digits, as GiNaC's evalf has it
        const certified_result rest = certified_double(source - exact_rational(c), 0x1p-70, 2560);
        if (!rest.proved) {
            const double inf = std::numeric_limits<double>::infinity();
            return {inf, __float128(c), __float128(inf), 0.0, inf};
        }
        const double hi = c, lo = rest.value;
        const __float128 q = __float128(hi) + __float128(lo);
        // |exact - c - lo| <= rest's bound + the rounding of lo to double
        const double e128 = (rest.bound + std::fabs(lo) * 0x1p-52) * (1 + 1e-12) + std::fabs(c) * 1e-55;
        const double e64 = std::fabs(lo) * (1 + 1e-12) + e128;
        return {e64, q, __float128(e128) + arith<__float128>::u * fabsq(q), lo, e128};
    } catch (const std::exception&) {
        return {unknown64, __float128(c), __float128(unknown64), 0.0, unknown64};
    }
}

}  // namespace

stable_function::stable_function(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                                 const stable_options& options)
    : program_(compile(outputs, inputs)), options_(options), outputs_(outputs), inputs_(inputs) {
    if (!(options.rel_tol > 0) && !(options.abs_tol > 0))
        throw domain_error("stable_function: rel_tol or abs_tol must be positive");
    const std::size_t n = program_.constants_.size();
    constant_bound64_.resize(n);
    constant128_.resize(n);
    constant_bound128_.resize(n);
    constant_lo64_.resize(n);
    constant_bound_dd_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const constant_split s =
            split_constant(program_.constants_[k], program_.constant_sources_[k], program_.constant_known_[k] != 0);
        constant_bound64_[k] = s.bound64;
        constant128_[k] = s.value128;
        constant_bound128_[k] = s.bound128;
        constant_lo64_[k] = s.lo64;
        constant_bound_dd_[k] = s.bound_dd;
    }
    // sin/cos/sincos whose argument is (constant * input): error-free phases in binary64
    const std::size_t n_in = program_.n_inputs_;
    const auto& code = program_.program_;
    std::vector<std::size_t> defined_by(program_.n_registers_, code.size());
    for (std::size_t i = 0; i < code.size(); ++i) defined_by[code[i].dst] = i;
    phases_.resize(code.size());
    for (std::size_t i = 0; i < code.size(); ++i) {
        const instruction& ins = code[i];
        if (ins.op != opcode::sin && ins.op != opcode::cos && ins.op != opcode::sincos) continue;
        const std::size_t d = defined_by[ins.a];
        if (d == code.size() || code[d].op != opcode::mul) continue;
        std::uint32_t x = code[d].a, c = code[d].b;
        if (x >= n_in) std::swap(x, c);
        if (x < n_in && c >= n_in && c < n_in + n) phases_[i] = {c, x, true};
    }
}

stable_function::stable_function(const GiNaC::ex& output, const std::vector<GiNaC::ex>& inputs,
                                 const stable_options& options)
    : stable_function(flatten_outputs(output), inputs, options) {}

// The program with a running error bound (Wilkinson's running error analysis):
// bound[r] bounds |value[r] - exact value of register r at the same inputs|.
template <class T>
void stable_function::run(const T* constants, const T* constant_bounds, const double* in, T* value,
                          T* bound) const {
    using A = arith<T>;
    const std::size_t n_in = program_.n_inputs_, n_const = program_.constants_.size();
    for (std::size_t i = 0; i < n_in; ++i) {
        value[i] = T(in[i]);
        bound[i] = T(0);
    }
    for (std::size_t k = 0; k < n_const; ++k) {
        value[n_in + k] = constants[k];
        bound[n_in + k] = constant_bounds[k];
    }
    const T inf = infinity<T>();
    const auto& code = program_.program_;
    for (std::size_t pc = 0; pc < code.size(); ++pc) {
        const instruction& ins = code[pc];
        if constexpr (std::is_same_v<T, double>) {
            if (phases_[pc].active) {
                run_phase(ins, phases_[pc], in, value, bound);
                continue;
            }
        }
        const T a = value[ins.a], ea = bound[ins.a];
        const T b = value[ins.b], eb = bound[ins.b];
        T v = 0, e = 0;
        switch (ins.op) {
            case opcode::add:
                v = a + b;
                e = sum_bound(ea, eb, v);
                break;
            case opcode::sub:
                v = a - b;
                e = sum_bound(ea, eb, v);
                break;
            case opcode::mul:
                v = a * b;
                e = A::abs(a) * eb + A::abs(b) * ea + ea * eb + A::u * A::abs(v);
                break;
            case opcode::div:
                v = a / b;
                // |a/b - a'/b'| <= (|a/b| eb + ea) / (|b| - eb)
                e = eb < A::abs(b) ? (A::abs(v) * eb + ea) / (A::abs(b) - eb) * (1 + 4 * A::u) + A::u * A::abs(v)
                                   : inf;
                break;
            case opcode::neg:
                v = -a;
                e = ea;
                break;
            case opcode::pow: {
                v = A::pow(a, b);
                // a^b = exp(b log a): relative perturbation of the exponent
                if (a - ea > 0) {
                    const T d = A::abs(b) * -A::log1p(-ea / a) + A::abs(A::log(a)) * eb +
                                -A::log1p(-ea / a) * eb;
                    e = A::abs(v) * A::expm1(d) + A::f_err * A::abs(v);
                } else {
                    e = (ea == 0 && eb == 0) ? A::f_err * A::abs(v) : inf;
                }
                break;
            }
            case opcode::sqrt:
                v = A::sqrt(a);
                // |sqrt(a') - sqrt(a)| = |a' - a| / (sqrt(a') + sqrt(a))
                e = (ea == 0 ? T(0) : ea / (v + A::sqrt(max0(a - ea)))) + A::u * A::abs(v);
                if (!(a >= 0)) e = inf;
                break;
            case opcode::exp:
                v = A::exp(a);
                e = A::abs(v) * A::expm1(ea) + A::f_err * A::abs(v);
                break;
            case opcode::log:
                v = A::log(a);
                e = a - ea > 0 ? -A::log1p(-ea / a) + A::f_err * A::abs(v) : (ea == 0 ? T(0) : inf);
                break;
            case opcode::abs:
                v = A::abs(a);
                e = ea;
                break;
            case opcode::sin:
                v = A::sin(a);
                e = function_bound(min(T(1), A::abs(A::cos(a)) + ea), ea, v);
                break;
            case opcode::cos:
                v = A::cos(a);
                e = function_bound(min(T(1), A::abs(A::sin(a)) + ea), ea, v);
                break;
            case opcode::sincos: {
                v = A::sin(a);
                const T c = A::cos(a);
                e = function_bound(min(T(1), A::abs(c) + ea), ea, v);
                value[ins.b] = c;
                bound[ins.b] = function_bound(min(T(1), A::abs(v) + ea), ea, c);
                break;
            }
            case opcode::tan: {
                v = A::tan(a);
                // tan' = 1 + tan^2; no pole within the error interval while (1 + v^2) ea < 1/4
                const T d = (1 + v * v) * ea;
                if (d < T(0.25)) {
                    const T vmax = A::abs(v) + 2 * d;
                    e = function_bound(1 + vmax * vmax, ea, v);
                } else {
                    e = inf;
                }
                break;
            }
            case opcode::asin:
            case opcode::acos: {
                v = ins.op == opcode::asin ? A::asin(a) : A::acos(a);
                const T m = A::abs(a) + ea;
                e = ea == 0 ? A::f_err * A::abs(v) : (m < 1 ? function_bound(1 / A::sqrt(1 - m * m), ea, v) : inf);
                break;
            }
            case opcode::atan: {
                v = A::atan(a);
                const T m = max0(A::abs(a) - ea);
                e = function_bound(1 / (1 + m * m), ea, v);
                break;
            }
            case opcode::atan2: {
                v = A::atan2(a, b);
                const T ya = max0(A::abs(a) - ea), xb = max0(A::abs(b) - eb);
                const T den = ya * ya + xb * xb;
                const T num = A::abs(b) * ea + A::abs(a) * eb + ea * eb;
                e = (num == 0 ? T(0) : (den > 0 ? min(T(6.3), num / den) : T(6.3))) + A::f_err * A::abs(v);
                break;
            }
            case opcode::sinh:
                v = A::sinh(a);
                e = function_bound(A::cosh(A::abs(a) + ea), ea, v);
                break;
            case opcode::cosh:
                v = A::cosh(a);
                e = function_bound(A::cosh(A::abs(a) + ea), ea, v);
                break;
            case opcode::tanh: {
                v = A::tanh(a);
                const T m = A::tanh(max0(A::abs(a) - ea));
                e = function_bound(1 - m * m, ea, v);
                break;
            }
            case opcode::asinh: {
                v = A::asinh(a);
                const T m = max0(A::abs(a) - ea);
                e = function_bound(1 / A::sqrt(1 + m * m), ea, v);
                break;
            }
            case opcode::acosh: {
                v = A::acosh(a);
                const T m = a - ea;
                e = ea == 0 ? A::f_err * A::abs(v) : (m > 1 ? function_bound(1 / A::sqrt(m * m - 1), ea, v) : inf);
                break;
            }
            case opcode::atanh: {
                v = A::atanh(a);
                const T m = A::abs(a) + ea;
                e = ea == 0 ? A::f_err * A::abs(v) : (m < 1 ? function_bound(1 / (1 - m * m), ea, v) : inf);
                break;
            }
        }
        // Underflow: below the smallest normal number a rounding is eta (half a subnormal ulp,
        // rounded up), not u |v|: w^2 = 0 at w = 1e-170 is no exact 0. Sums are exact there,
        // and an exact 0 operand gives an exact 0 (sin 0, 0 * x).
        if (A::abs(v) < A::min_normal && ins.op != opcode::add && ins.op != opcode::sub &&
            ins.op != opcode::neg && ins.op != opcode::abs && a != 0 && (ins.op != opcode::mul || b != 0))
            e += A::eta;
        value[ins.dst] = v;
        bound[ins.dst] = A::finite(e) ? e : inf;
    }
}

// sin/cos of c * x with c = hi + lo (a double-double of c's exact value) and
// x an exact input: p + d = hi x exactly (fma), d += lo x; then
// sin(p + d) = sin p + d cos p - (d^2/2) sin p ..., cos likewise. The phase
// error is |x| bound_dd(c) plus the rounding of d; the first-order correction
// leaves d^2/2.
void stable_function::run_phase(const instruction& ins, const phase_operands& ph, const double* in, double* value,
                                double* bound) const {
    using A = arith<double>;
    const std::size_t k = ph.constant - program_.n_inputs_;
    const double x = in[ph.input], hi = program_.constants_[k], lo = constant_lo64_[k];
    const double p = hi * x;
    const double d = std::fma(hi, x, -p) + lo * x;
    const double phase_bound = std::fabs(x) * constant_bound_dd_[k] + A::u * std::fabs(d) * 2;
    const double s = std::sin(p), c = std::cos(p);
    const double sv = s + d * c, cv = c - d * s;
    // The first-order correction leaves |sin(p + d) - (s + d c)| <= d^2/2 + |d|^3/6: an error
    // of the value, whatever the derivative at the point (added as such, not as a phase error
    // scaled by |cos|, which vanishes where sin peaks).
    const double second_order = (0.5 * d * d + std::fabs(d * d * d) / 6) * (1 + 4 * A::u);
    auto b = [&](double v, double deriv) {
        return min(1.0, deriv + phase_bound) * phase_bound + second_order +
               A::f_err * (std::fabs(s) + std::fabs(c)) * (1 + std::fabs(d)) + 2 * A::u * std::fabs(v);
    };
    switch (ins.op) {
        case opcode::sin:
            value[ins.dst] = sv;
            bound[ins.dst] = b(sv, std::fabs(cv));
            break;
        case opcode::cos:
            value[ins.dst] = cv;
            bound[ins.dst] = b(cv, std::fabs(sv));
            break;
        default:  // sincos
            value[ins.dst] = sv;
            bound[ins.dst] = b(sv, std::fabs(cv));
            value[ins.b] = cv;
            bound[ins.b] = b(cv, std::fabs(sv));
            break;
    }
}

void stable_function::eval_binary64(const double* in, double* value, double* bound) const {
    // register files reused per thread (no allocation per evaluation)
    thread_local std::vector<double> r, e;
    r.resize(program_.n_registers_);
    e.resize(program_.n_registers_);
    run<double>(program_.constants_.data(), constant_bound64_.data(), in, r.data(), e.data());
    for (std::size_t i = 0; i < program_.outputs_.size(); ++i) {
        value[i] = r[program_.outputs_[i]];
        bound[i] = e[program_.outputs_[i]];
    }
}

void stable_function::eval_binary128(const double* in, double* value, double* bound) const {
    thread_local std::vector<__float128> r, e;
    r.resize(program_.n_registers_);
    e.resize(program_.n_registers_);
    run<__float128>(constant128_.data(), constant_bound128_.data(), in, r.data(), e.data());
    for (std::size_t i = 0; i < program_.outputs_.size(); ++i) {
        const __float128 v = r[program_.outputs_[i]];
        value[i] = static_cast<double>(v);
        // plus the rounding to double (eta where it underflows), rounded up
        const __float128 eq = e[program_.outputs_[i]];
        bound[i] = static_cast<double>(eq) * (1 + 0x1p-52) + std::fabs(value[i]) * 0x1p-53 +
                   (std::fabs(value[i]) < 0x1p-1022 && (v != 0 || eq != 0) ? 0x1p-1074 : 0.0);
    }
}

precision_tier stable_function::eval(const double* in, double* out) const {
    const std::size_t m = program_.outputs_.size();
    auto accepted = [&](double v, double b) {
        // an infinite value is no answer of a tier (inf <= rel_tol * inf): 1/|w|^4 overflows
        // at |w| = 1e-300 in a form whose value is finite
        // (or within two subnormal ulps: the double is then right to the last bit doubles have there)
        return std::isfinite(v) &&
               (b <= options_.rel_tol * std::fabs(v) || b <= options_.abs_tol || b <= 0x1p-1073);
    };
    thread_local std::vector<double> b;
    b.resize(m);
    eval_binary64(in, out, b.data());
    bool all = true;
    for (std::size_t i = 0; i < m; ++i) all = all && accepted(out[i], b[i]);
    if (all) return precision_tier::binary64;

    eval_binary128(in, out, b.data());
    std::vector<std::size_t> pending;
    for (std::size_t i = 0; i < m; ++i)
        if (!accepted(out[i], b[i])) pending.push_back(i);  // NaN and inf too: 0/0 may have a limit
    if (pending.empty()) return precision_tier::binary128;

    // Tier 3: CLN at the exact binary inputs with a proved error bound
    // (numeric/certified.h), the precision doubled until the bound is rel_tol / 4
    // relative. (Two precisions that agree prove nothing: both lose every digit of
    // (1 - cos(w t))/w^2 at w = 1e-100 up to 160 digits.) At a removable
    // singularity (0/0 at the point) the limit (numeric/reference.h, value_at).
    // An output that max_digits do not bound is NaN: not known, never a guess.
    // One without a real value (log of a negative number, a pole) keeps binary128's
    // NaN or infinity.
    const std::vector<double> point(in, in + program_.n_inputs_);
    for (std::size_t i : pending) {
        GiNaC::ex at;
        try {
            at = value_at(outputs_[i], inputs_, point);
        } catch (const domain_error&) {
            continue;
        }
        try {
            const certified_result r = certified_double(at, options_.rel_tol * 0.25, options_.max_digits);
            out[i] = r.proved ? r.value : std::numeric_limits<double>::quiet_NaN();
            continue;
        } catch (const domain_error&) {
            continue;
        } catch (const not_certifiable&) {
        }
        // not covered by the bound (a complex intermediate value, another function):
        // precisions raised until two agree, none below 160 digits for a 0
        long double previous = 0;
        for (int digits = 40; digits <= options_.max_digits; digits *= 2) {
            long double now;
            try {
                now = reference_eval({at}, {}, {}, digits)[0];
            } catch (const domain_error&) {
                break;
            }
            out[i] = static_cast<double>(now);
            const bool agree = digits > 40 && (now == 0 ? previous == 0 && digits >= 160
                                                        : std::fabs(now - previous) <=
                                                              options_.rel_tol * 0.25L * std::fabs(now));
            if (agree) break;
            previous = now;
        }
    }
    return precision_tier::multiprecision;
}

std::vector<std::size_t> stable_function::eval_many_binary64(const double* in, double* out, std::size_t n,
                                                             double check_tol) const {
    const std::size_t k = n_inputs(), m = n_outputs();
    std::vector<double> bound(m);
    std::vector<std::size_t> again;
    for (std::size_t r = 0; r < n; ++r) {
        eval_binary64(in + r * k, out + r * m, bound.data());
        for (std::size_t i = 0; i < m; ++i) {
            const double v = out[r * m + i];
            if (!std::isfinite(v) || !(bound[i] <= check_tol * std::fabs(v) || bound[i] <= 0x1p-1073)) {
                again.push_back(r);
                break;
            }
        }
    }
    return again;
}

void stable_function::eval_many(const double* in, double* out, std::size_t n, double check_tol) const {
    for (std::size_t r : eval_many_binary64(in, out, n, check_tol))
        eval(in + r * n_inputs(), out + r * n_outputs());
}

std::vector<double> stable_function::operator()(const std::vector<double>& in) const {
    if (in.size() != n_inputs())
        throw type_error("stable_function: " + std::to_string(in.size()) + " inputs given, " +
                         std::to_string(n_inputs()) + " expected");
    std::vector<double> out(n_outputs());
    eval(in.data(), out.data());
    return out;
}

}  // namespace symrep::num
