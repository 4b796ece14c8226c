// symrep/identification/operational_matrix.h -- the operational matrices of integration
// (thesis IV.2.2): P in the Walsh basis (IV.2.19), Q in the block-pulse basis (IV.2.21),
// their powers and inverses.
//
// int_0^t w = P w (IV.2.18) and int_0^t e = Q e (IV.2.20) for the truncated series on [0, 1).
// Q = (1/2N) I + Delta (IV.2.48-49) is upper triangular Toeplitz, so every integer power of
// it is too: Q^m is the Toeplitz matrix of the power series (1/2N)^m ((1 + x)/(1 - x))^m,
// whose coefficients g_k satisfy (1 - x^2) g' = 2 m g, i.e.
//     g_0 = 1, g_1 = 2 m, g_(k+1) = (2 m g_k + (k - 1) g_(k-1)) / (k + 1),
// for positive and negative m alike (IV.2.51 for m > 0; Q^-1 the same way): O(N) for the
// row, O(N^2) (or O(N log N) by FFT) to apply it, never a dense O(N^3) inverse. P's powers
// follow from P^m = W Q^m W^T / N (IV.2.24, Paley's W: walsh_series.h).
//
// On [0, T) every integral carries T: Q_T = T Q, P_T = T P.
#pragma once
#include <vector>

#include <Eigen/Core>
#include <ginac/ginac.h>

namespace symrep::identification {

/// P_(2^n) by the recursion (IV.2.19), exact rationals (n <= 12: 4096 x 4096 is the limit of a
/// dense exact matrix here; symrep::size_error above).
GiNaC::matrix operational_matrix_exact(unsigned n);
/// P_(2^n) in double (dense; n <= 13).
Eigen::MatrixXd operational_matrix(unsigned n);
/// Q_(2^n) (IV.2.21), exact and double (dense; the same limits).
GiNaC::matrix block_pulse_matrix_exact(unsigned n);
Eigen::MatrixXd block_pulse_matrix(unsigned n);

/// P^m for any integer m (m < 0: powers of P^-1), exact: W Q^m W^T / 2^n (IV.2.24), Q^m from its
/// Toeplitz row; n <= 8.
GiNaC::matrix operational_matrix_power_exact(unsigned n, long m);

/// The first row of Q^m (any integer m; upper triangular Toeplitz), exact and double, times T^m.
std::vector<GiNaC::numeric> block_pulse_power_row_exact(unsigned n, long m);
std::vector<double> block_pulse_power_row(unsigned n, long m, double T = 1);

/// The block-pulse coordinates of the m-fold integral int_0^t ... of the function with
/// coordinates g (m < 0: the m-fold derivative in the same sense): (Q^m)^T g, a causal
/// convolution with the row of Q^m. O(N^2) up to N = 256, by FFT (Eigen) above.
std::vector<double> integrate_blocks(const std::vector<double>& g, long m, double T = 1);

}  // namespace symrep::identification
