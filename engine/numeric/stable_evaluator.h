// symrep/numeric/stable_evaluator.h -- evaluate closed forms to a guaranteed
// relative accuracy, wherever their formulas cancel.
//
// Closed forms of rotating-frame problems contain terms such as
// (1 - cos(w t))/w^2 and (sin(w t) - w t)/w^3 that lose every digit in double
// arithmetic as w t -> 0, and phases w0 t that are rounded when formed at long
// times (a rounded phase of 6e6 rad is already off by 5e-10). A
// stable_function evaluates the same compiled program (numeric/evaluator.h)
// with a running error bound and raises the precision at the points that
// need it (Ziv's strategy):
//
//   1. binary64: the double program, each register carrying a bound on its
//      absolute error against the exact value at the same (binary) inputs
//      (running error analysis: rounding of every operation, propagation by
//      the derivative of every function over the error interval, the exact
//      error of every rounded constant). An output is accepted when its bound
//      is at most rel_tol times its value.
//      Phases c * t (c a constant, t an input) inside sin and cos are formed
//      without rounding error: c as a double-double (its exact value split
//      in two doubles), the product c_hi t split exactly by fma, and the
//      sine corrected to first order, sin(p + d) = sin p + d cos p; so
//      oscillations at long times stay in binary64.
//   2. binary128: the same program in IEEE quadruple precision (113-bit
//      significand, libquadmath) with the same bound, constants rounded from
//      their exact values; phases such as w0 t are then formed with an error
//      of 1e-34 relative, and cancellations of up to about 1e16 are absorbed.
//   3. multiprecision: the outputs that still fail are evaluated by CLN at the
//      exact binary inputs with a proved error bound (numeric/certified.h),
//      the digits doubled until the bound is rel_tol / 4 relative (two
//      precisions that agree prove nothing: both can lose every digit to a
//      cancellation). An output that max_digits do not bound is NaN.
//
//   In tiers 1 and 2 an output is accepted only when it is finite; below the
//   smallest normal number each rounding is bounded by half a subnormal ulp
//   (underflow is no exact 0).
//
// So the result is the exact value of the closed form at the given doubles,
// correctly rounded up to a small multiple of rel_tol, at the cost of the
// cheapest precision that achieves it: double almost everywhere, quadruple
// precision where w t is small or t long, CLN only in extreme corners
// (w t < 1e-6 with third-order cancellation). The tier used is reported.
//
// Removable singularities are evaluated as limits: at |w| = 0 exactly, where
// (1 - cos(|w| t))/|w|^2 is 0/0 in every floating-point format, tier 3
// returns the value of the continuous extension (t^2/2), as the exact
// solution of the problem with w = 0 has it. Otherwise NaN and infinity follow
// IEEE double semantics (log of a negative number is NaN, a pole infinite).
//
// Thread safety: tiers 1 and 2 are reentrant; tier 3 sets GiNaC::Digits for
// its duration, so concurrent evaluations that reach it must be serialized.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/numeric/evaluator.h"

namespace symrep::num {

struct stable_options {
    /// Accept an output when its error bound is at most rel_tol * |value|.
    /// The bound is a worst case over all roundings (actual errors are
    /// typically 10x smaller), so the default guarantees 1e-14 relative with
    /// room for the final rounding to double.
    double rel_tol = 8e-15;
    /// ... or when its error bound is at most abs_tol (0: relative only).
    double abs_tol = 0.0;
    /// Largest CLN precision (decimal digits) tier 3 tries.
    int max_digits = 2560;
};

/// Which arithmetic produced a value.
enum class precision_tier : std::uint8_t { binary64 = 0, binary128 = 1, multiprecision = 2 };
const char* tier_name(precision_tier t);

/// A closed form compiled for evaluation to a stated relative accuracy.
class stable_function {
public:
    stable_function() = default;
    /// As compile(outputs, inputs) of evaluator.h (same errors).
    stable_function(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs,
                    const stable_options& options = {});
    /// One scalar, a list, or a matrix (row by row), as compile().
    stable_function(const GiNaC::ex& output, const std::vector<GiNaC::ex>& inputs,
                    const stable_options& options = {});

    std::size_t n_inputs() const { return program_.n_inputs(); }
    std::size_t n_outputs() const { return program_.n_outputs(); }
    const compiled_function& program() const { return program_; }
    const stable_options& options() const { return options_; }

    /// Evaluate at one point; returns the highest tier any output needed.
    precision_tier eval(const double* in, double* out) const;
    std::vector<double> operator()(const std::vector<double>& in) const;

    /// Many points (n rows of n_inputs() values, row-major, as
    /// compiled_function::eval_many) to a looser, proved accuracy: tier 1 at every
    /// point, and the points where an output's bound exceeds check_tol times its
    /// value (or two subnormal ulps) evaluated again by eval(). The first half,
    /// eval_many_binary64, is reentrant (no GiNaC) and returns those points; eval_many
    /// does both. The Python module's f(...) (docs/python.md) uses check_tol = 1e-6.
    std::vector<std::size_t> eval_many_binary64(const double* in, double* out, std::size_t n,
                                                double check_tol) const;
    void eval_many(const double* in, double* out, std::size_t n, double check_tol) const;

    /// The double program with its running error bound only (tier 1): values
    /// and absolute error bounds of every output. For tests and charts.
    void eval_binary64(const double* in, double* value, double* bound) const;
    /// Tier 2 alone: values (rounded to double) and bounds.
    void eval_binary128(const double* in, double* value, double* bound) const;

private:
    compiled_function program_;
    stable_options options_;
    std::vector<GiNaC::ex> outputs_, inputs_;  // for tier 3
    std::vector<double> constant_bound64_;     // |exact - double| of each constant (inf if unknown)
    std::vector<__float128> constant128_;      // each constant rounded to binary128 (double if unknown)
    std::vector<__float128> constant_bound128_;
    // Error-free phases in binary64: for each instruction, if it is sin, cos or
    // sincos of (constant * input), the registers of both; else {0, 0}.
    struct phase_operands {
        std::uint32_t constant = 0, input = 0;
        bool active = false;
    };
    std::vector<phase_operands> phases_;
    std::vector<double> constant_lo64_;        // exact - double, rounded (the low part of a double-double)
    std::vector<double> constant_bound_dd_;    // |exact - (double + lo)|

    void run_phase(const instruction& ins, const phase_operands& ph, const double* in, double* value,
                   double* bound) const;
    template <class T>
    void run(const T* constants, const T* constant_bounds, const double* in, T* value, T* bound) const;
};

}  // namespace symrep::num
