// symrep/algebra/walsh_double.h -- the fast double-precision path of the Walsh
// algebra W, of its complex extension W*, and of the generalized Sobrero algebra S.
//
// Same coordinate orders as the exact classes (walsh.h, walsh_complex.h, sobrero.h):
//   walsh_d          f = [f_0..f_{2^n-1}]                       (III.3.23)
//   walsh_complex_d  w = [a_0..a_{2^n-1}, b_0..b_{2^n-1}]       (III.3.53)
//   sobrero_d        w = [a_0..a_n, b_0..b_n]                   (III.2.6)
// The math is the same template code as the exact path (walsh_kernel.h,
// sobrero_kernel.h) instantiated with T = double; W and W* work through the
// idempotent components computed by fwht in O(n 2^n).
//
// Zero-divisor tests in double precision use a relative tolerance: a component
// counts as zero when |a_p| <= tol * sum_q |f_q| (the bound on |a_p| itself), default
// tol = 1e-12, a few hundred ulps of the rounding error of the transform.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace symrep {

/// Double-precision Walsh algebra W of order 2^n.
// The double-precision classes share their declarations, not their operations (the
// fast transforms differ: fwht, complex fwht, truncated convolution).
class walsh_d {
public:
    static constexpr unsigned max_n = 26;
    /// Throws size_error for n > max_n.
    explicit walsh_d(unsigned n);
    unsigned n() const { return n_; }
    std::size_t dim() const { return std::size_t(1) << n_; }

    std::vector<double> unit() const;
    /// u_k = w_{2^{n-1-k}} (p_0 is the most significant bit).
    std::vector<double> generator(std::size_t k) const;
    /// (III.3.25) a = H f.
    std::vector<double> components(const std::vector<double>& f) const;
    /// (III.3.21) f = 2^{-n} H a.
    std::vector<double> from_components(const std::vector<double>& a) const;
    std::vector<double> multiply(const std::vector<double>& f, const std::vector<double>& g) const;
    /// (III.3.31) ranks p with |a_p| <= tol * sum |f_q|.
    std::vector<std::size_t> zero_divisor_ranks(const std::vector<double>& f, double tol = 1e-12) const;
    /// Throws zero_divisor_error naming the ranks.
    std::vector<double> inverse(const std::vector<double>& f, double tol = 1e-12) const;
    /// (III.3.44)
    std::vector<double> exp(const std::vector<double>& f, double t = 1.0) const;
    /// (III.3.40); throws zero_divisor_error, or domain_error for a negative root (use W*).
    std::vector<double> log(const std::vector<double>& f, double tol = 1e-12) const;
    /// (III.3.28)
    double determinant(const std::vector<double>& f) const;

private:
    void check(const std::vector<double>& f, const char* what) const;
    unsigned n_;
};

/// Double-precision complex extension W* (real form, order 2^{n+1}).
class walsh_complex_d {
public:
    static constexpr unsigned max_n = 25;
    explicit walsh_complex_d(unsigned n);
    unsigned n() const { return n_; }
    std::size_t size() const { return std::size_t(1) << n_; }
    std::size_t dim() const { return std::size_t(2) << n_; }

    std::vector<double> unit() const;
    std::vector<double> generator(std::size_t k) const;
    std::vector<double> i0() const;
    /// (III.3.62-63) y_p = c_p + i d_p.
    std::vector<std::complex<double>> components(const std::vector<double>& w) const;
    std::vector<double> from_components(const std::vector<std::complex<double>>& y) const;
    std::vector<double> multiply(const std::vector<double>& a, const std::vector<double>& b) const;
    std::vector<std::size_t> zero_divisor_ranks(const std::vector<double>& w, double tol = 1e-12) const;
    std::vector<double> inverse(const std::vector<double>& w, double tol = 1e-12) const;
    std::vector<double> exp(const std::vector<double>& w, double t = 1.0) const;
    /// (III.3.64-67), principal argument theta_p in (-pi, pi].
    std::vector<double> log(const std::vector<double>& w, double tol = 1e-12) const;

private:
    void check(const std::vector<double>& w, const char* what) const;
    unsigned n_;
};

/// Double-precision generalized Sobrero algebra S (order 2(n+1)).
class sobrero_d {
public:
    static constexpr unsigned max_n = 4096;
    explicit sobrero_d(unsigned n);
    unsigned n() const { return n_; }
    std::size_t dim() const { return 2 * (std::size_t(n_) + 1); }

    std::vector<double> unit() const;
    /// (III.2.4) truncated complex convolution.
    std::vector<double> multiply(const std::vector<double>& a, const std::vector<double>& b) const;
    /// Zero divisor iff |xi_0| <= tol * max_k |xi_k| (III.2.13).
    bool is_zero_divisor(const std::vector<double>& w, double tol = 1e-12) const;
    std::vector<double> inverse(const std::vector<double>& w, double tol = 1e-12) const;
    std::vector<double> exp(const std::vector<double>& w, double t = 1.0) const;
    std::vector<double> log(const std::vector<double>& w, double tol = 1e-12) const;

private:
    void check(const std::vector<double>& w, const char* what) const;
    unsigned n_;
};

}  // namespace symrep
