// symrep/identification/identify.h -- identification of q^(m) + a_1 q^(m-1) + ... + a_m q +
// f(q) = u (thesis IV.2.3) from the block averages of a measured input u and output q on
// [0, T), zero initial data (IV.2.25, IV.2.37-38).
//
// Integrated m times the equation is q + sum_k a_k I^k q + I^m f(q) = I^m u (IV.2.39), I the
// integral from 0. In block-pulse coordinates (q_e the block averages) I^k is (Q^k)^T
// (operational_matrix.h), and f(q) has the coordinates f(q_e) (IV.2.32: f of the block values,
// exact for the truncated series, O(h^2) for the function itself). Two ways to use it:
//
//  - identify_values: the thesis's procedure (IV.2.36, IV.2.45). The linear system for the
//    vector f is solved: f(q_e) = u_e - (Q^T)^(-m) (F(Q))^T q_e, F(Q) = I + a_1 Q + ... + a_m Q^m
//    (IV.2.46) -- the values of f at the 2^n points q_e, by the Toeplitz inverse powers of Q.
//    Then fit_polynomial estimates f from the points (IV.2.36: "one of the classical
//    procedures"). As printed the values do not converge: (Q^T)^(-m) has an m-fold pole at
//    the alternating mode, which the first blocks excite (Q^m is the m-th power of the
//    projected integral, not the projected m-fold integral: diagonal h^2/4 against h^2/6 for
//    m = 2), so they carry a (-1)^k k^(m-1) component; neighbours are averaged m times to
//    cancel it (2^n - m points remain), after which the procedure is the m-th backward
//    difference of the block averages: consistent to O(h), and m-fold differentiation of the
//    data, noise amplified by about (N/T)^m.
//  - identify_integral: the same integrated equation with f a polynomial of degree d,
//    sum_i c_i q^i, left in its integral form: least squares in the unknown c_i (and the
//    unknown a_k, jointly), with no inverse of Q -- nothing is differentiated.
//
// Both report the points used, the condition number of the least-squares matrix, and the
// residual of the reconstructed integrated equation. Coefficients that cannot be told apart
// (a_m with the linear term c_1 of f: their columns are the same) are refused by name.
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace symrep::identification {

/// The measured signals: 2^n block averages of q and u on [0, T).
struct measured_system {
    std::vector<double> q, u;
    double period = 1;
};

/// The known and unknown a_k of (IV.2.37): a[k-1] = a_k, nullopt for an unknown one. Its size
/// is the order m (>= 1; IV.2.25 is m = 2 with a_1 = a_2 = 0).
using linear_part = std::vector<std::optional<double>>;

struct identification_report {
    std::size_t points = 0;          ///< 2^n
    double condition_number = 0;     ///< of the (column-scaled) least-squares matrix
    double residual = 0;             ///< rms of the integrated equation's residual / rms of q
    std::vector<double> f;           ///< c_0 .. c_d of f(q) = sum c_i q^i
    std::vector<double> a;           ///< a_1 .. a_m (known ones as given, unknown ones estimated)
    std::vector<double> points_q;    ///< identify_values: the points (q_e, neighbours averaged m times)
    std::vector<double> values_f;    ///< identify_values: f at them
    std::string warning;             ///< nonempty: an ill-conditioned fit, said with its number
    std::size_t window = 0;          ///< identify_sindy_cv: the Savitzky-Golay window chosen (points)
    double threshold = 0;            ///< identify_sindy_cv: the STLSQ threshold chosen (relative)
};

/// The thesis's procedure (IV.2.36, IV.2.45): f at the 2^n points, then a least-squares
/// polynomial of degree d through them. Every a_k must be known (symrep::domain_error
/// otherwise: use identify_integral).
identification_report identify_values(const measured_system& s, const linear_part& a, unsigned degree);
/// The same system solved as printed, f(q_e) = u_e - sum_j a_j (Q^T)^(j-m) q_e at all 2^n points,
/// without cancelling the pole: for comparison only (its values grow like N^(m-1) (-1)^k and
/// the fit converges to a wrong f; bench/bench_identification.cpp charts it).
identification_report identify_values_as_printed(const measured_system& s, const linear_part& a, unsigned degree);
/// The integral form (IV.2.39) by least squares in c_0 .. c_d and the unknown a_k.
identification_report identify_integral(const measured_system& s, const linear_part& a, unsigned degree);

/// Least-squares polynomial of degree d through (x_k, y_k) on the centred and scaled x (QR,
/// Eigen), back in monomials of x; cond gets the condition number of the scaled Vandermonde.
std::vector<double> fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, unsigned degree,
                                   double* cond = nullptr);

/// The forward model, for tests, benchmarks and examples: q^(m) + a_1 q^(m-1) + ... + a_m q +
/// f(q) = u on [0, T) from zero initial data (Boost.Odeint, rkf78, 1e-12), the block averages
/// of q and u (the integrals carried in the state: exact up to the integrator's tolerance),
/// and, when `samples` is given, q and u at the blocks' midpoints.
measured_system simulate_system(const std::function<double(double)>& f, const std::function<double(double)>& u,
                                const std::vector<double>& a, unsigned n, double T = 1,
                                measured_system* samples = nullptr);

/// The baseline of regression on derivatives (the SINDy approach, Brunton et al. 2016): from
/// samples at equal steps h of q and u, q^(m) by central finite differences (second order),
/// the target u - q^(m) - sum_k a_k q^(m-k) (known a_k; the unknown ones join the library as
/// the columns q^(m-k)), the library 1, q, ..., q^d, and sequentially thresholded least squares
/// (coefficients below `threshold` in magnitude set to 0, refit, 10 rounds; threshold 0 is
/// plain least squares on derivatives). Interior points only (the ends have no central
/// difference).
identification_report identify_sindy(const measured_system& samples, const linear_part& a, unsigned degree,
                                     double threshold);

}  // namespace symrep::identification
