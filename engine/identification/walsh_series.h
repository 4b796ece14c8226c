// symrep/identification/walsh_series.h -- truncated Walsh series on [0, T) (thesis IV.2.1).
//
// The Walsh functions in the ordering for which the operational matrix of integration is
// the recursion (IV.2.19): w_p = r_1^(p_0) r_2^(p_1) ... r_n^(p_(n-1)) (Paley's ordering),
// r_k(t) = sgn sin(2^k pi t) the Rademacher functions (IV.2.1). The thesis writes
// w_p = u_(n-1)^(p_(n-1)) ... u_0^(p_0) with u_k = sgn sin(2^k pi t): u_0 = 1 on (0, 1), so its
// u_k is read as r_(k+1); and with the natural Hadamard matrix H of (IV.2.14) in w = H e
// (IV.2.10) the recursion (IV.2.19) fails from n = 2 on (checked exactly in the tests). In
// Paley's ordering the matrix of the w_p on the 2^n blocks [k/N, (k+1)/N) is W = H R, R the
// bit reversal of the block index: w_p = W e (IV.2.10 with W for H), e = W^T w / N (IV.2.11),
// and P = W Q W^T / N (IV.2.22-23 with W for H). docs/identification.md has the details.
//
// A truncated series sum_(p < N) c_p w_p is constant on each block; its value there is the
// block average of the function it truncates, so block averages (block-pulse coordinates)
// and Walsh coefficients are one fast transform apart: c = W v / N, v = W^T c, each an
// O(N log N) fast Walsh-Hadamard transform (algebra/walsh_hadamard.h) and a permutation.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>
#include <ginac/ginac.h>

namespace symrep::identification {

/// r_k(t) = sgn sin(2^k pi t) (IV.2.1), k >= 1, 1-periodic; +1 at the left end of each half-wave
/// (the right-continuous version, as the block-pulse functions).
double rademacher(unsigned k, double t);
/// w_p(t) in Paley's ordering (IV.2.2, read as above), 1-periodic, right-continuous.
double walsh_function(std::size_t p, double t);
/// The value of w_p on block k of N = 2^n blocks: (-1)^popcount(p & bitrev_n(k)).
int walsh_sign(std::size_t p, std::size_t k, unsigned n);
/// k with its n low bits reversed.
std::size_t bit_reverse(std::size_t k, unsigned n);

/// W (N x N): row p holds w_p on the blocks, so that w = W e (IV.2.10). Exact (+-1) and double.
GiNaC::matrix walsh_matrix_exact(unsigned n);
Eigen::MatrixXd walsh_matrix(unsigned n);

/// Walsh coefficients from block averages: c = W v / N (IV.2.4 for a function constant on
/// the blocks), by one fast transform. v.size() must be a power of two (symrep::domain_error).
std::vector<double> walsh_from_blocks(std::vector<double> v);
std::vector<GiNaC::ex> walsh_from_blocks(std::vector<GiNaC::ex> v);
/// Block values of a truncated series: v = W^T c.
std::vector<double> blocks_from_walsh(std::vector<double> c);
std::vector<GiNaC::ex> blocks_from_walsh(std::vector<GiNaC::ex> c);

/// The 2^n block averages of f on [0, T) by Gauss-Kronrod quadrature (Boost.Math, 15 points
/// per block, adaptive to 1e-13 relative), each block split at the `jumps` inside it (sorted).
/// f must be finite on [0, T).
std::vector<double> block_averages(const std::function<double(double)>& f, unsigned n, double T = 1,
                                   const std::vector<double>& jumps = {});
/// The points in (0, T) where a step(a t + b) or abs(a t + b) of f changes its piece (a != 0, b
/// real numbers; symrep::domain_error naming any other argument), sorted.
std::vector<double> jump_points(const GiNaC::ex& f, const GiNaC::symbol& t, double T);
/// f between two jump points, mid a point there: every step() and abs() replaced by its branch.
GiNaC::ex piece_of(const GiNaC::ex& f, const GiNaC::symbol& t, double mid);
/// The same, exact, for f a piecewise polynomial in t with exact coefficients: polynomials,
/// step(a t + b) and abs(a t + b) with rational a, b (symrep::domain_error otherwise); each block
/// split at the breakpoints inside it, each piece integrated through its antiderivative.
/// T a positive rational.
std::vector<GiNaC::ex> block_averages_exact(const GiNaC::ex& f, const GiNaC::symbol& t, unsigned n,
                                            const GiNaC::ex& T = 1);

/// True when block_averages_exact accepts f (a piecewise polynomial in t as above).
bool is_piecewise_polynomial(const GiNaC::ex& f, const GiNaC::symbol& t);

/// The truncated series sum_p c_p w_p at t in [0, T) (its block value).
double walsh_series_value(const std::vector<double>& c, double t, double T = 1);
/// The product of two truncated series in the Walsh algebra (IV.2.3, III.3): w_p w_q =
/// w_(p xor q), computed through the idempotents (the block values multiply).
std::vector<double> walsh_product(const std::vector<double>& a, const std::vector<double>& b);

/// n with 2^n = N; symrep::domain_error naming `what` when N is not a power of two (>= 2).
unsigned log2_of_count(std::size_t N, const char* what);

}  // namespace symrep::identification
