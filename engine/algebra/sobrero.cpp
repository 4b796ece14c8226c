// symrep/algebra/sobrero.cpp -- the generalized Sobrero algebra (III.2).
#include "symrep/algebra/sobrero.h"

#include <sstream>

#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/algebra/double_path.h"
#include "symrep/algebra/sobrero_kernel.h"
#include "symrep/algebra/walsh_double.h"
#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

using GiNaC::ex;
namespace sm = sobrero_math;
namespace dp = double_path;

namespace {

/// Decides x >= 0 for an exact expression; throws domain_error when it cannot.
bool nonnegative(const ex& x, const std::string& what) {
    const ex y = tidy(x);
    if (GiNaC::is_a<GiNaC::numeric>(y)) {
        const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(y);
        if (v.is_real()) return v >= 0;
    }
    if (y.info(GiNaC::info_flags::nonnegative)) return true;
    if ((-y).info(GiNaC::info_flags::positive)) return false;
    const ex f = GiNaC::evalf(y);
    if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(f) >= 0;
    std::ostringstream os;
    os << "is_special_type: cannot decide the sign of " << what << " = " << y
       << " (corrected III.2.20 needs a_k a_l + b_k b_l >= 0); use is_special_type(w, false) "
          "for the one-line test";
    throw domain_error(os.str());
}

}  // namespace

algebra_ptr sobrero::make(long n) {
    if (n < 0) throw domain_error("sobrero(n): n must be >= 0, got " + std::to_string(n));
    if (n > long(sobrero_d::max_n))
        throw size_error("sobrero(n): n = " + std::to_string(n) + " is too large; the exact algebra "
                         "is limited to n <= " + std::to_string(max_n) + " (order 2(n+1)) and the "
                         "double-precision path to n <= " + std::to_string(sobrero_d::max_n));
    return std::make_shared<sobrero>(unsigned(n));
}




sobrero::sobrero(unsigned n) : n_(n) {
    if (n > sobrero_d::max_n)
        throw size_error("sobrero(n): n = " + std::to_string(n) + " exceeds the limit n <= " +
                         std::to_string(max_n));
}

std::string sobrero::name() const { return "sobrero(" + std::to_string(n_) + ")"; }

std::string sobrero::basis_name(std::size_t k) const {
    if (k >= dim()) return algebra::basis_name(k);
    const std::size_t m = n_ + 1;
    const bool has_j = k >= m;
    const std::size_t p = k % m;
    std::string e = p == 0 ? "" : (p == 1 ? "eps" : "eps^" + std::to_string(p));
    if (!has_j) return p == 0 ? "1" : e;
    return p == 0 ? "j" : "j*" + e;
}

// (III.2.4) with eps^{n+1} = 0: truncated Cauchy product of the complex sequences.
coeffs sobrero::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "sobrero product");
    check_size(b, "sobrero product");
    if (takes_double_path({&a, &b}, "product"))
        return dp::from_doubles(sobrero_d(n_).multiply(dp::to_doubles(a), dp::to_doubles(b)));
    return sm::to_coords(sm::multiply(sm::from_coords(a), sm::from_coords(b)));
}

// det [w] = |xi_0|^{2(n+1)}: the constant term of (III.2.12).
ex sobrero::determinant(const coeffs& w) const {
    check_size(w, "determinant");
    require_exact("determinant");
    const std::size_t m = n_ + 1;
    return tidy(GiNaC::pow(w[0] * w[0] + w[m] * w[m], int(m)));
}

// (III.2.12) p(X) = (X^2 - 2 a_0 X + a_0^2 + b_0^2)^{n+1}, returned expanded.
ex sobrero::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "characteristic polynomial");
    require_exact("characteristic polynomial");
    const std::size_t m = n_ + 1;
    const ex a0 = w[0], b0 = w[m];
    return guarded_expand(GiNaC::pow(X * X - 2 * a0 * X + a0 * a0 + b0 * b0, int(m)), "characteristic polynomial");
}

// Minimal polynomial: w = xi_0 + N with N^{m} = 0 != N^{m-1}, m = 1 + floor(n/k_0);
// p(w) = sum_j p^{(j)}(xi_0) N^j / j! vanishes iff (X - xi_0)^m | p over C, so the real
// minimal polynomial is ((X - xi_0)(X - conj xi_0))^m, or (X - a_0)^m if b_0 = 0.
ex sobrero::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    check_size(w, "minimal polynomial");
    require_exact("minimal polynomial");
    const std::size_t m = n_ + 1;
    std::size_t k0 = 0;
    for (std::size_t k = 1; k < m && k0 == 0; ++k)
        if (is_nonzero_generic(w[k], "minimal polynomial in " + name()) ||
            is_nonzero_generic(w[m + k], "minimal polynomial in " + name()))
            k0 = k;
    const int index = k0 == 0 ? 1 : int(n_ / k0) + 1;
    const ex a0 = w[0], b0 = w[m];
    const ex factor = !is_nonzero_generic(b0, "minimal polynomial in " + name()) ? ex(X - a0) : ex(X * X - 2 * a0 * X + a0 * a0 + b0 * b0);
    return guarded_expand(GiNaC::pow(factor, index), "minimal polynomial");
}

// (III.2.13) w is a zero divisor iff a_0 = b_0 = 0.
bool sobrero::is_zero_divisor(const coeffs& w) const {
    check_size(w, "zero-divisor test");
    // (III.2.13) in doubles: |xi_0| <= 1e-12 max |xi_k|
    if (takes_double_path({&w}, "zero-divisor test")) return sobrero_d(n_).is_zero_divisor(dp::to_doubles(w));
    return !is_nonzero_generic(w[0], "zero divisor test in " + name()) &&
           !is_nonzero_generic(w[n_ + 1], "zero divisor test in " + name());
}

std::vector<std::size_t> sobrero::zero_divisor_ranks(const coeffs& w) const {
    if (is_zero_divisor(w)) return {0};
    return {};
}

namespace {
[[noreturn]] void throw_nilpotent(const sobrero& S, const char* what) {
    throw zero_divisor_error(std::string(what) + " of a zero divisor in " + S.name() +
                                 ": a_0 = b_0 = 0 (III.2.13), so w is nilpotent, w^" +
                                 std::to_string(S.n() + 1) + " = 0 (III.2.15)",
                             {0});
}
}  // namespace

// w^{-1} = xi_0^{-1} sum_{k=0}^{n} (-N/xi_0)^k.
coeffs sobrero::inverse(const coeffs& w) const {
    check_size(w, "inverse");
    if (takes_double_path({&w}, "inverse")) return dp::from_doubles(sobrero_d(n_).inverse(dp::to_doubles(w)));
    if (is_zero_divisor(w)) throw_nilpotent(*this, "inverse");
    return sm::to_coords(sm::inverse(sm::from_coords(w)));
}

// exp(w t) = e^{xi_0 t} sum_{k=0}^{n} N^k t^k / k!, a closed form in t.
coeffs sobrero::exp(const coeffs& w, const ex& t) const {
    check_size(w, "exp");
    const auto on_doubles = [&](const std::vector<double>& x, double s) { return sobrero_d(n_).exp(x, s); };
    if (auto d = exp_on_double_path(w, t, on_doubles)) return *std::move(d);
    return sm::to_coords(sm::exp(sm::from_coords(w), t));
}

// log w = log xi_0 + sum_{k=1}^{n} (-1)^{k+1} (N/xi_0)^k / k (principal log of xi_0).
coeffs sobrero::log(const coeffs& w) const {
    require_exact("log");  // sobrero_d has no log: exact (or float GiNaC) arithmetic up to max_n
    if (is_zero_divisor(w)) throw_nilpotent(*this, "log");
    return sm::to_coords(sm::log(sm::from_coords(w)));
}

// (III.2.16-18) A_k = sqrt(a_k^2 + b_k^2), phi_k = atan2(b_k, a_k) taken in [0, 2 pi).
std::pair<coeffs, coeffs> sobrero::semiexponential(const coeffs& w) const {
    check_size(w, "semiexponential form");
    require_exact("semiexponential form");
    const std::size_t m = n_ + 1;
    coeffs rho = zero(), theta = zero();
    for (std::size_t k = 0; k < m; ++k) {
        const ex a = w[k], b = w[m + k];
        rho[k] = tidy(GiNaC::sqrt(a * a + b * b));
        if (is_zero_scalar(a) && is_zero_scalar(b)) continue;  // A_k = 0: phi_k = 0
        ex phi = GiNaC::atan2(b, a);
        const ex f = GiNaC::evalf(phi);
        if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f).is_real() &&
            GiNaC::ex_to<GiNaC::numeric>(f) < 0)
            phi = phi + 2 * GiNaC::Pi;
        theta[m + k] = phi;
    }
    return {rho, theta};
}

// Corrected (III.2.20): all xi_k on one ray (strict) or on one line through 0.
bool sobrero::is_special_type(const coeffs& w, bool strict) const {
    check_size(w, "special-type test");
    const std::size_t m = n_ + 1;
    for (std::size_t k = 0; k < m; ++k) {
        for (std::size_t l = k + 1; l < m; ++l) {
            const ex ak = w[k], bk = w[m + k], al = w[l], bl = w[m + l];
            if (!is_zero_scalar(ak * bl - al * bk)) return false;
            if (strict && !nonnegative(ak * al + bk * bl, "a_" + std::to_string(k) + " a_" +
                                                              std::to_string(l) + " + b_" +
                                                              std::to_string(k) + " b_" +
                                                              std::to_string(l)))
                return false;
        }
    }
    return true;
}

// (III.2.24) w = (sum a_k eps^k) e^{j 0} + (sum b_k eps^k) e^{j pi/2}.
std::vector<coeffs> sobrero::special_type_decomposition(const coeffs& w) const {
    check_size(w, "special-type decomposition");
    const std::size_t m = n_ + 1;
    coeffs re = zero(), im = zero();
    for (std::size_t k = 0; k < m; ++k) {
        re[k] = w[k];
        im[m + k] = w[m + k];
    }
    return {re, im};
}

// (III.4.10) d = alpha j + beta eps; (III.4.13) alpha = beta = 1.
coeffs sobrero::generating_element(const std::vector<ex>& params) const {
    if (!params.empty() && params.size() != 2)
        throw type_error("generating_element: " + name() + " takes no parameters or {alpha, beta} "
                         "(d = alpha j + beta eps, III.4.10), got " +
                         std::to_string(params.size()));
    const ex alpha = params.empty() ? ex(1) : params[0];
    const ex beta = params.empty() ? ex(1) : params[1];
    coeffs d = zero();
    d[n_ + 1] = alpha;
    if (n_ >= 1) d[1] = beta;
    return d;
}

coeffs sobrero::j() const { return basis_vector(n_ + 1); }

coeffs sobrero::eps() const {
    coeffs e = zero();
    if (n_ >= 1) e[1] = 1;
    return e;
}

}  // namespace symrep
