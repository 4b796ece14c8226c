// symrep/identification/sindy.h -- the strong baseline of identification: a standard SINDy
// pipeline (Brunton, Proctor & Kutz 2016) with its two tuning parameters chosen by
// cross-validation, for q^(m) + a_1 q^(m-1) + ... + a_m q + f(q) = u (thesis IV.2.37).
//
//  1. Derivatives by Savitzky-Golay: at every sample the polynomial of order m + 2 fitted by
//     least squares to the 2w + 1 samples around it (the first and last w samples take the
//     fit of the first / last full window, SciPy's mode "interp"), differentiated.
//  2. The regression of u - q^(m) - sum_(known) a_k q^(m-k) on the library 1, q, ..., q^d
//     (q smoothed by the same filter) and the columns q^(m-k) of the unknown a_k, by
//     sequentially thresholded least squares (STLSQ): a term whose share |c_j| |A_j| / |b|
//     of the target is below the threshold lambda is dropped and the rest refitted.
//  3. (w, lambda) from a grid (half widths w growing by 1.5 from 3 to N/8, at most 256;
//     lambda in {0, 1e-4, 1e-3, 1e-2, 3e-2, 1e-1}) by 5-fold cross-validation on contiguous
//     time blocks: fitted on four blocks, scored on the fifth by the weak form of the equation,
//     int phi (u - f(q) - sum_k a_k q^(m-k)) - (-1)^m int phi^(m) q, for the test functions
//     phi = (s (1 - s))^(m+6) on pieces of the held-out block -- a score without derivatives of
//     the data, so that windows are compared on the same footing (a score on each window's own
//     smoothed derivatives would favour the widest). The chosen pair is refitted on all data.
//
// Deterministic: no random folds, ties go to the smaller window and threshold.
#pragma once
#include <vector>

#include "symrep/identification/identify.h"

namespace symrep::identification {

/// The Savitzky-Golay estimates of y and its derivatives 0 .. r at every one of the equally
/// spaced samples (step h): the local least-squares polynomial of the given order on 2w + 1
/// samples (order < 2w + 1 <= y.size(); symrep::domain_error otherwise).
std::vector<std::vector<double>> savitzky_golay(const std::vector<double>& y, double h, unsigned half_width,
                                                unsigned order, unsigned derivatives);

/// The cross-validated SINDy pipeline above on samples of q and u at equal steps T/N
/// (samples.period = T; N >= 64). The report's window and threshold are the chosen ones.
identification_report identify_sindy_cv(const measured_system& samples, const linear_part& a, unsigned degree);

}  // namespace symrep::identification
