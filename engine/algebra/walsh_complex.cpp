// symrep/algebra/walsh_complex.cpp -- the complex extension W* (III.3.45-67).
#include "symrep/algebra/walsh_complex.h"

#include <sstream>

#include "symrep/scalar/cplx.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/algebra/double_path.h"
#include "symrep/algebra/walsh_double.h"
#include "symrep/algebra/walsh_kernel.h"
#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

using GiNaC::ex;
namespace wm = walsh_math;
namespace dp = double_path;
using cx = cplx<ex>;

algebra_ptr walsh_complex::make(long n) {
    if (n < 0) throw domain_error("walsh_complex(n): n must be >= 0, got " + std::to_string(n));
    if (n > long(walsh_complex_d::max_n))
        throw size_error("walsh_complex(n): n = " + std::to_string(n) + " is too large; the exact "
                         "algebra is limited to n <= " + std::to_string(max_n) +
                         " (real order 2^(n+1)) and the double-precision path to n <= " +
                         std::to_string(walsh_complex_d::max_n));
    return std::make_shared<walsh_complex>(unsigned(n));
}

walsh_complex::walsh_complex(unsigned n) : n_(n) {
    if (n > walsh_complex_d::max_n)
        throw size_error("walsh_complex(n): n = " + std::to_string(n) + " exceeds the limit n <= " +
                         std::to_string(walsh_complex_d::max_n) + " of the double-precision path");
}




std::string walsh_complex::name() const { return "walsh_complex(" + std::to_string(n_) + ")"; }

std::string walsh_complex::basis_name(std::size_t k) const {
    if (k >= dim()) return algebra::basis_name(k);
    const std::size_t p = k % size();
    std::string s;
    for (unsigned b = 0; b < n_; ++b)
        if (p & (std::size_t(1) << (n_ - 1 - b))) s += (s.empty() ? "u" : "*u") + std::to_string(b);
    if (k < size()) return s.empty() ? "1" : s;
    return s.empty() ? "i0" : "i0*" + s;
}

coeffs walsh_complex::generator(std::size_t k) const {
    if (k >= n_)
        throw domain_error("walsh_generator: " + name() +
                           (n_ == 0 ? std::string(" has no generators u_k")
                                    : " has generators u_0..u_" + std::to_string(n_ - 1)) +
                           "; there is no u_" + std::to_string(k));
    return basis_vector(std::size_t(1) << (n_ - 1 - k));
}

coeffs walsh_complex::i0() const { return basis_vector(size()); }

// Product through the components (III.3.49): y_p z_p.
coeffs walsh_complex::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "walsh_complex product");
    check_size(b, "walsh_complex product");
    if (takes_double_path({&a, &b}, "product"))
        return dp::from_doubles(walsh_complex_d(n_).multiply(dp::to_doubles(a), dp::to_doubles(b)));
    std::vector<cx> y = wm::complex_components(a), z = wm::complex_components(b);
    for (std::size_t p = 0; p < y.size(); ++p) y[p] = y[p] * z[p];
    return wm::from_complex_components(std::move(y));
}

// (III.3.47) e_p = 2^{-n} sum_k (-1)^{<p,k>} w_k, in the real part.
coeffs walsh_complex::idempotent(std::size_t p) const {
    if (p >= size())
        throw domain_error("idempotent: " + name() + " has idempotents e_0..e_" +
                           std::to_string(size() - 1) + "; there is no e_" + std::to_string(p));
    coeffs e = zero();
    const ex s = inv_pow2<ex>(n_);
    for (std::size_t q = 0; q < size(); ++q) e[q] = wm::dyadic_sign(p, q) * s;
    return e;
}

// (III.3.62-63) y_p = c_p + I d_p.
std::vector<ex> walsh_complex::idempotent_components(const coeffs& w) const {
    check_size(w, "idempotent components");
    const std::vector<cx> y = wm::complex_components(w);
    std::vector<ex> out(y.size());
    for (std::size_t p = 0; p < y.size(); ++p) out[p] = y[p].re + GiNaC::I * y[p].im;
    return out;
}

coeffs walsh_complex::from_idempotent_components(const std::vector<ex>& c) const {
    if (c.size() != size())
        throw algebra_error("from_idempotent_components: " + name() + " has " +
                            std::to_string(size()) + " idempotents, but " +
                            std::to_string(c.size()) + " components were given");
    std::vector<cx> y(c.size());
    for (std::size_t p = 0; p < c.size(); ++p)
        y[p] = cx(tidy(c[p].real_part()), tidy(c[p].imag_part()));
    return wm::from_complex_components(std::move(y));
}

namespace {
bool zero_c(const cx& z) {
    return !is_nonzero_generic(z.re, "an idempotent component") && !is_nonzero_generic(z.im, "an idempotent component");
}

std::vector<std::size_t> ranks_of(const std::vector<cx>& y) {
    std::vector<std::size_t> r;
    for (std::size_t p = 0; p < y.size(); ++p)
        if (zero_c(y[p])) r.push_back(p);
    return r;
}

[[noreturn]] void throw_zero_divisor(const std::string& algebra_name, const char* what,
                                     const std::vector<std::size_t>& r) {
    throw zero_divisor_error(std::string(what) + " of a zero divisor in " + algebra_name +
                                 ": the idempotent components c_p + i0 d_p of rank " + rank_list(r) +
                                 " vanish (rho_p = 0 in III.3.64), so w e_p = 0 for these p",
                             r);
}
}  // namespace

std::vector<std::size_t> walsh_complex::zero_divisor_ranks(const coeffs& w) const {
    check_size(w, "zero-divisor ranks");
    if (takes_double_path({&w}, "zero divisor ranks"))
        return walsh_complex_d(n_).zero_divisor_ranks(dp::to_doubles(w));
    return ranks_of(wm::complex_components(w));
}

bool walsh_complex::is_zero_divisor(const coeffs& w) const { return !zero_divisor_ranks(w).empty(); }

// det [w] = prod_p |y_p|^2 = prod_p (c_p^2 + d_p^2).
ex walsh_complex::determinant(const coeffs& w) const {
    check_size(w, "determinant");
    require_exact("determinant");
    ex d = 1;
    for (const auto& z : wm::complex_components(w)) d = d * z.norm2();
    return tidy(d);
}

// Real form: each component y_p gives the roots y_p and conj y_p.
ex walsh_complex::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "characteristic polynomial");
    require_exact("characteristic polynomial");
    ex p = 1;
    for (const auto& z : wm::complex_components(w))
        p = guarded_expand(p * (X * X - 2 * z.re * X + z.norm2()), "characteristic polynomial");
    return p;
}

// Semisimple: product of the distinct real irreducible factors.
ex walsh_complex::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "minimal polynomial");
    require_exact("minimal polynomial");
    std::vector<ex> factors;
    for (const auto& z : wm::complex_components(w)) {
        const ex f = !is_nonzero_generic(z.im, "minimal polynomial") ? ex(X - z.re) : ex(X * X - 2 * z.re * X + z.norm2());
        bool seen = false;
        for (const auto& g : factors)
            if (!is_nonzero_generic(GiNaC::expand(f - g), "minimal polynomial")) { seen = true; break; }
        if (!seen) factors.push_back(f);
    }
    ex p = 1;
    for (const auto& f : factors) p = guarded_expand(p * f, "minimal polynomial");
    return p;
}

// Components y_p -> 1/y_p = conj(y_p)/|y_p|^2.
coeffs walsh_complex::inverse(const coeffs& w) const {
    check_size(w, "inverse");
    if (takes_double_path({&w}, "inverse")) return dp::from_doubles(walsh_complex_d(n_).inverse(dp::to_doubles(w)));
    std::vector<cx> y = wm::complex_components(w);
    const auto r = ranks_of(y);
    if (!r.empty()) throw_zero_divisor(name(), "inverse", r);
    for (auto& z : y) {
        const ex d = z.norm2();
        z = cx(tidy(z.re / d), tidy(-z.im / d));
    }
    return wm::from_complex_components(std::move(y));
}

// exp(w t): y_p -> e^{c_p t} (cos d_p t + i0 sin d_p t) (III.3.44 on complex components).
coeffs walsh_complex::exp(const coeffs& w, const ex& t) const {
    check_size(w, "exp");
    const auto on_doubles = [&](const std::vector<double>& x, double s) { return walsh_complex_d(n_).exp(x, s); };
    if (auto d = exp_on_double_path(w, t, on_doubles)) return *std::move(d);
    std::vector<cx> y = wm::complex_components(w);
    for (auto& z : y) {
        const ex e = exp_scalar(tidy(z.re * t));
        z = cx(e * GiNaC::cos(tidy(z.im * t)), e * GiNaC::sin(tidy(z.im * t)));
    }
    return wm::from_complex_components(std::move(y));
}

// (III.3.64-67) u = sum_p (ln rho_p e_p + theta_p i0 e_p). Steps as in inverse() (the
// double path, the zero-divisor ranks, a map of the components); only the map differs.
coeffs walsh_complex::log(const coeffs& w) const {
    check_size(w, "log");
    if (takes_double_path({&w}, "log")) return dp::from_doubles(walsh_complex_d(n_).log(dp::to_doubles(w)));
    std::vector<cx> y = wm::complex_components(w);
    const auto r = ranks_of(y);
    if (!r.empty()) throw_zero_divisor(name(), "log", r);
    for (auto& z : y)
        z = cx(tidy(log_modulus(z.re, z.im)), tidy(GiNaC::atan2(z.im, z.re)));
    return wm::from_complex_components(std::move(y));
}

coeffs walsh_complex::generating_element(const std::vector<ex>& params) const {
    if (!params.empty() && params.size() != n_ && params.size() != n_ + 1)
        throw type_error("generating_element: " + name() + " takes no parameters, {alpha_0, ..., "
                         "alpha_" + std::to_string(long(n_) - 1) + "} or {alpha_0, ..., alpha_" +
                         std::to_string(long(n_) - 1) + ", beta} (d = sum alpha_k u_k + beta i0), "
                         "got " + std::to_string(params.size()));
    coeffs d = zero();
    for (unsigned k = 0; k < n_; ++k)
        d[std::size_t(1) << (n_ - 1 - k)] = params.empty() ? ex(GiNaC::pow(2, k)) : params[k];
    d[size()] = params.size() == n_ + 1 ? params[n_] : ex(1);
    return d;
}

}  // namespace symrep
