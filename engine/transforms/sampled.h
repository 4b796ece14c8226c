// symrep/transforms/sampled.h -- the Fourier transform of a sampled causal signal by the
// FFT (Eigen's FFT module, kissfft), to compare with the exact transforms of laplace.h.
//
// From N samples f_k = f(k h), k < N, of a signal that is 0 before t = 0 and negligible
// after N h, the trapezoid rule at the N frequencies omega_m = 2 pi m / (N h) is
//     F(i omega_m) ~ h (sum_k f_k e^(-2 pi i m k / N) - f_0 / 2),
// one FFT (the half weight at t = 0 is the jump's: the transform of a causal signal sees
// f(0+)/2 there). Error: O(h^2) for a smooth f on (0, N h) (the trapezoid rule; h^2/12
// times the transform of f'' plus the jump of f' at 0), plus the tail |f| beyond N h.
// For m > N/2 the frequencies are the negative ones, omega_m - 2 pi / h.
#pragma once

#include <complex>
#include <vector>

namespace symrep::transforms {

/// F(i omega_m), m = 0 .. N-1, omega_m = 2 pi m / (N h) (see above). Throws domain_error for
/// fewer than 2 samples or h <= 0.
std::vector<std::complex<double>> sampled_fourier(const std::vector<double>& samples, double h);

}  // namespace symrep::transforms
