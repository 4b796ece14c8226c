// symrep/numeric/spectral_evaluator.h -- closed forms of linear constant-
// coefficient problems evaluated through their spectrum, to full double
// accuracy at compiled speed.
//
// With numbers in, every closed form the constant-rotation solver derives is a
// quasi-polynomial in t,
//
//     x_i(t) = Re sum_k p_ik(t) e^(lambda_k t),
//
// one polynomial p_ik per exponent lambda_k (cos and sin are folded into the
// exponents of the upper half plane). Its formulas lose digits in one place
// only: terms whose exponents are closer together than 1/t, with large
// coefficients that cancel, e.g. (1 - cos(2|w|t))/(4|w|^4) - t^2/(2|w|^2) at
// small |w| t, or the Foucault terms (w0 - |w|) sin((w0 + |w|)t)/(2 w0 |w|)
// - (w0 + |w|) sin((w0 - |w|)t)/(2 w0 |w|). The sum of such a group is a
// smooth function of the spread of its exponents (a divided difference of
// e^(lambda t)); evaluated as its own Taylor series about the group's centre,
//
//     sum_{k in C} p_ik(t) e^(lambda_k t) = e^(c t) sum_n mu_in t^n,
//     mu_in = sum_{k in C} sum_m p_ikm (lambda_k - c)^(n-m) / (n-m)!,
//
// it has no cancellation: the moments mu_in are computed once, at compile
// time, in CLN with as many digits as the cancellation needs, and rounded to
// double. Which exponents form a group depends on t: two exponents are told
// apart when |lambda_k - lambda_j| t >= R (the resolution, default 2). So the
// groups are the clusters of single-linkage clustering at distance R/t, and
// the compiled form holds one level per range of t between the thresholds
// R/|lambda_k - lambda_j| of the exponents' minimum spanning tree: all
// exponents in one series near t = 0, each on its own (direct evaluation,
// where at |lambda_k - lambda_j| t >= R little cancellation is left) for large
// t. The phases are formed without rounding error: each centre c is a
// double-double, c_hi t is split exactly by fma and the exponential corrected
// to first order (as in the stable evaluator's tier 1), so long times (30
// days of a pendulum, 1.6e5 periods) keep their digits.
//
// This is the thesis's own picture read numerically: the solution is
// e^(D t) applied to the data, a function of an operator whose eigenvalues
// (0, +-i|w| for the rotation operator, VI.1.25) nearly coincide when |w| t is
// small; the series about a cluster's centre is the stable way to evaluate a
// function of a matrix with close eigenvalues (divided differences, Opitz),
// and it reduces to r = F_{-w}(psi) with half-angle forms when the problem has
// that structure, without asking the solver for a special form.
//
// Cost: one sincos per cluster of the level in use and one complex Horner
// step per moment and output (docs/performance.md). Accuracy: not bounded
// per point like stable_function (numeric/stable_evaluator.h), which stays
// the evaluator with a guarantee; the work-precision scenes and the tests
// measure 1e-16 .. 1e-15 against the CLN reference.
//
// Scope: outputs whose only input is t, with every parameter a number;
// anything that is not a quasi-polynomial in t (t under a square root, 1/t,
// sin(t^2), a symbol other than t, a complex output) throws
// symrep::type_error / domain_error naming it; use num::compile for those.
//
// Thread safety: immutable after construction; eval is const and reentrant.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

#include <ginac/ginac.h>

namespace symrep::num {

struct spectral_options {
    /// Two exponents are evaluated in one series while |lambda_k - lambda_j| t < resolution.
    double resolution = 2.0;
};

namespace detail {
/// One group of exponents at one level of the compiled form.
struct spectral_cluster {
    double re_hi = 0, re_lo = 0, im_hi = 0, im_lo = 0;  ///< centre c = (re_hi + re_lo) + i (im_hi + im_lo)
    bool series = false;        ///< moments (true) or the polynomial of a single exponent (false)
    std::size_t length = 0;     ///< coefficients per output
    std::vector<std::complex<double>> coeff;  ///< [output][n]: mu_n or the polynomial's coefficients
    /// series: terms needed for |t| <= bound (bounds decreasing, terms decreasing)
    std::vector<double> bound;
    std::vector<std::size_t> terms;
};
/// The clusters used from |t| = start on (up to the next level's start).
struct spectral_level {
    double start = 0;
    std::vector<spectral_cluster> clusters;
};
}  // namespace detail

/// A real quasi-polynomial in one input t, compiled for evaluation by clusters
/// of its exponents.
class spectral_function {
public:
    spectral_function() = default;
    /// outputs: real expressions in t and numbers only. Throws type_error or
    /// domain_error (naming the term) when an output is not a quasi-polynomial in t.
    spectral_function(const std::vector<GiNaC::ex>& outputs, const GiNaC::ex& t, const spectral_options& options = {});

    std::size_t n_outputs() const { return n_outputs_; }
    /// Distinct exponents (upper half plane and real axis).
    std::size_t n_exponents() const { return n_exponents_; }
    /// Levels (ranges of t with one clustering each).
    std::size_t n_levels() const { return levels_.size(); }
    /// The value of t from which level k is used (level 0 from t = 0).
    double level_start(std::size_t k) const { return levels_[k].start; }

    void eval(double t, double* out) const;
    void eval_many(const double* t, double* out, std::size_t n) const;  ///< row k of out at t[k]
    std::vector<double> operator()(double t) const;

private:
    using cluster = detail::spectral_cluster;
    using level = detail::spectral_level;
    std::size_t n_outputs_ = 0, n_exponents_ = 0;
    std::vector<level> levels_;
};

}  // namespace symrep::num
