// symrep/identification/identify_detail.h -- the pieces the identification methods share
// (identify.cpp: the integral form, the thesis's values, regression on derivatives;
// sindy.cpp: the cross-validated SINDy pipeline). Not part of the library's interface.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "symrep/identification/identify.h"

namespace symrep::identification::detail {

double rms(const std::vector<double>& v);
/// n with 2^n = the number of block values; every precondition of identification checked by name.
unsigned check_system(const measured_system& s, const linear_part& a);
/// sum_i c_i x^i
double horner(const std::vector<double>& c, double x);
/// An unknown a_m with a linear term in f: both multiply q (symrep::domain_error).
void refuse_collinear(const linear_part& a, unsigned degree);
/// The residual of the integrated equation (IV.2.39) with f and a: rms over rms(q).
double integrated_residual(const measured_system& s, const std::vector<double>& a, const std::vector<double>& f);

struct lsq {
    Eigen::VectorXd x;
    double cond;
};
/// min |A x - b| with the columns scaled to unit norm (SVD); the condition number of the scaled A.
lsq least_squares(Eigen::MatrixXd A, const Eigen::VectorXd& b);
/// The warnings of a report (few blocks, data not from rest, a condition number above 1e8), "; "-joined.
std::string warnings(const measured_system& s, double cond);
/// The report of a solved system: x holds the unknown a_j (in `unknown`'s order), then the
/// degree + 1 coefficients of f; the known a_k from `a`; residual and warnings of s.
identification_report report_of(const measured_system& s, const linear_part& a, const std::vector<std::size_t>& unknown,
                                unsigned degree, const Eigen::VectorXd& x, std::size_t points, double cond);

}  // namespace symrep::identification::detail
