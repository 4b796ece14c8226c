// symrep/algebra/walsh_double.cpp -- double-precision W, W* and S (see walsh_double.h).
#include "symrep/algebra/walsh_double.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "symrep/scalar/cplx.h"
#include "symrep/algebra/batched_exp.h"
#include "symrep/algebra/sobrero_kernel.h"
#include "symrep/algebra/walsh_kernel.h"
#include "symrep/core/error.h"

namespace symrep {

namespace wm = walsh_math;
namespace sm = sobrero_math;
using cd = cplx<double>;

namespace {
std::string ranks_text(const std::vector<std::size_t>& r) {
    std::string s;
    for (std::size_t i = 0; i < r.size(); ++i) s += (i ? ", " : "") + std::to_string(r[i]);
    return s;
}
double l1(const std::vector<double>& f) {
    double s = 0;
    for (double x : f) s += std::abs(x);
    return s;
}
void size_check(unsigned n, unsigned max_n, const char* what) {
    if (n > max_n)
        throw size_error(std::string(what) + ": n = " + std::to_string(n) +
                         " is too large; the double path is limited to n <= " +
                         std::to_string(max_n));
}
void dim_check(std::size_t got, std::size_t want, const std::string& alg, const char* what) {
    if (got != want)
        throw algebra_error(std::string(what) + ": " + alg + " has dimension " +
                            std::to_string(want) + ", but " + std::to_string(got) +
                            " coordinates were given");
}
// The coordinates of basis element k of an algebra of dimension dim.
std::vector<double> basis_element(std::size_t dim, std::size_t k) {
    std::vector<double> u(dim, 0.0);
    u[k] = 1;
    return u;
}
}  // namespace

// ---------------------------------------------------------------- walsh_d
walsh_d::walsh_d(unsigned n) : n_(n) { size_check(n, max_n, "walsh_d"); }

void walsh_d::check(const std::vector<double>& f, const char* what) const {
    dim_check(f.size(), dim(), "walsh_d(" + std::to_string(n_) + ")", what);
}

std::vector<double> walsh_d::unit() const {
    return basis_element(dim(), 0);
}

std::vector<double> walsh_d::generator(std::size_t k) const {
    if (k >= n_) throw domain_error("walsh_d: there is no generator u_" + std::to_string(k));
    return basis_element(dim(), std::size_t(1) << (n_ - 1 - k));
}

std::vector<double> walsh_d::components(const std::vector<double>& f) const {
    check(f, "components");
    return wm::components(f);
}

std::vector<double> walsh_d::from_components(const std::vector<double>& a) const {
    check(a, "from_components");
    return wm::from_components(a);
}

// (III.3.26) componentwise product.
std::vector<double> walsh_d::multiply(const std::vector<double>& f, const std::vector<double>& g) const {
    std::vector<double> a = components(f), b = components(g);
    for (std::size_t p = 0; p < a.size(); ++p) a[p] *= b[p];
    return wm::from_components(std::move(a));
}

std::vector<std::size_t> walsh_d::zero_divisor_ranks(const std::vector<double>& f, double tol) const {
    const std::vector<double> a = components(f);
    const double bound = tol * l1(f);
    std::vector<std::size_t> r;
    for (std::size_t p = 0; p < a.size(); ++p)
        if (std::abs(a[p]) <= bound) r.push_back(p);
    return r;
}

std::vector<double> walsh_d::inverse(const std::vector<double>& f, double tol) const {
    const auto r = zero_divisor_ranks(f, tol);
    if (!r.empty())
        throw zero_divisor_error("inverse of a zero divisor in walsh_d(" + std::to_string(n_) +
                                     "): components of rank " + ranks_text(r) + " vanish (III.3.31)",
                                 r);
    std::vector<double> a = components(f);
    for (auto& x : a) x = 1.0 / x;
    return wm::from_components(std::move(a));
}

// (III.3.44)
std::vector<double> walsh_d::exp(const std::vector<double>& f, double t) const {
    std::vector<double> a = components(f);
    for (auto& x : a) x = std::exp(x * t);
    return wm::from_components(std::move(a));
}

// (III.3.40)
std::vector<double> walsh_d::log(const std::vector<double>& f, double tol) const {
    const auto r = zero_divisor_ranks(f, tol);
    if (!r.empty())
        throw zero_divisor_error("log of a zero divisor in walsh_d(" + std::to_string(n_) +
                                     "): components of rank " + ranks_text(r) + " vanish (III.3.31)",
                                 r);
    std::vector<double> a = components(f);
    for (std::size_t p = 0; p < a.size(); ++p) {
        if (a[p] < 0) {
            std::ostringstream os;
            os << "log in walsh_d(" << n_ << "): the root a_" << p << " = " << a[p]
               << " is negative; Thm III.3.3.1 needs every a_p > 0. Use walsh_complex_d (III.3.64-67)";
            throw domain_error(os.str());
        }
        a[p] = std::log(a[p]);
    }
    return wm::from_components(std::move(a));
}

double walsh_d::determinant(const std::vector<double>& f) const {
    double d = 1;
    for (double x : components(f)) d *= x;
    return d;
}

// -------------------------------------------------------- walsh_complex_d
walsh_complex_d::walsh_complex_d(unsigned n) : n_(n) { size_check(n, max_n, "walsh_complex_d"); }

void walsh_complex_d::check(const std::vector<double>& w, const char* what) const {
    dim_check(w.size(), dim(), "walsh_complex_d(" + std::to_string(n_) + ")", what);
}

std::vector<double> walsh_complex_d::unit() const {
    return basis_element(dim(), 0);
}

std::vector<double> walsh_complex_d::generator(std::size_t k) const {
    if (k >= n_) throw domain_error("walsh_complex_d: there is no generator u_" + std::to_string(k));
    return basis_element(dim(), std::size_t(1) << (n_ - 1 - k));
}

std::vector<double> walsh_complex_d::i0() const {
    return basis_element(dim(), size());
}

std::vector<std::complex<double>> walsh_complex_d::components(const std::vector<double>& w) const {
    check(w, "components");
    const std::vector<cd> y = wm::complex_components(w);
    std::vector<std::complex<double>> out(y.size());
    for (std::size_t p = 0; p < y.size(); ++p) out[p] = {y[p].re, y[p].im};
    return out;
}

std::vector<double> walsh_complex_d::from_components(const std::vector<std::complex<double>>& y) const {
    if (y.size() != size())
        throw algebra_error("walsh_complex_d::from_components: " + std::to_string(size()) +
                            " components expected, got " + std::to_string(y.size()));
    std::vector<cd> c(y.size());
    for (std::size_t p = 0; p < y.size(); ++p) c[p] = cd(y[p].real(), y[p].imag());
    return wm::from_complex_components(std::move(c));
}

std::vector<double> walsh_complex_d::multiply(const std::vector<double>& a, const std::vector<double>& b) const {
    auto y = components(a);
    const auto z = components(b);
    for (std::size_t p = 0; p < y.size(); ++p) y[p] *= z[p];
    return from_components(y);
}

std::vector<std::size_t> walsh_complex_d::zero_divisor_ranks(const std::vector<double>& w, double tol) const {
    const auto y = components(w);
    const double bound = tol * l1(w);
    std::vector<std::size_t> r;
    for (std::size_t p = 0; p < y.size(); ++p)
        if (std::abs(y[p]) <= bound) r.push_back(p);
    return r;
}

std::vector<double> walsh_complex_d::inverse(const std::vector<double>& w, double tol) const {
    const auto r = zero_divisor_ranks(w, tol);
    if (!r.empty())
        throw zero_divisor_error("inverse of a zero divisor in walsh_complex_d(" + std::to_string(n_) +
                                     "): components of rank " + ranks_text(r) + " vanish",
                                 r);
    auto y = components(w);
    for (auto& z : y) z = 1.0 / z;
    return from_components(y);
}

std::vector<double> walsh_complex_d::exp(const std::vector<double>& w, double t) const {
    auto y = components(w);
    exp_components(y.data(), y.size(), t);  // e^(a t) (cos b t + i sin b t), batched
    return from_components(y);
}

// (III.3.64-67)
std::vector<double> walsh_complex_d::log(const std::vector<double>& w, double tol) const {
    const auto r = zero_divisor_ranks(w, tol);
    if (!r.empty())
        throw zero_divisor_error("log of a zero divisor in walsh_complex_d(" + std::to_string(n_) +
                                     "): components of rank " + ranks_text(r) + " vanish",
                                 r);
    auto y = components(w);
    for (auto& z : y) z = std::complex<double>(std::log(std::abs(z)), std::arg(z));
    return from_components(y);
}

// ---------------------------------------------------------------- sobrero_d
sobrero_d::sobrero_d(unsigned n) : n_(n) { size_check(n, max_n, "sobrero_d"); }

void sobrero_d::check(const std::vector<double>& w, const char* what) const {
    dim_check(w.size(), dim(), "sobrero_d(" + std::to_string(n_) + ")", what);
}

std::vector<double> sobrero_d::unit() const {
    return basis_element(dim(), 0);
}

std::vector<double> sobrero_d::multiply(const std::vector<double>& a, const std::vector<double>& b) const {
    check(a, "multiply");
    check(b, "multiply");
    return sm::to_coords(sm::multiply(sm::from_coords(a), sm::from_coords(b)));
}

bool sobrero_d::is_zero_divisor(const std::vector<double>& w, double tol) const {
    check(w, "zero-divisor test");
    const std::size_t m = n_ + 1;
    double mx = 0;
    for (std::size_t k = 0; k < m; ++k) mx = std::max(mx, std::hypot(w[k], w[m + k]));
    return std::hypot(w[0], w[m]) <= tol * mx;
}

std::vector<double> sobrero_d::inverse(const std::vector<double>& w, double tol) const {
    if (is_zero_divisor(w, tol))
        throw zero_divisor_error("inverse of a zero divisor in sobrero_d(" + std::to_string(n_) +
                                     "): a_0 = b_0 = 0 (III.2.13)",
                                 {0});
    return sm::to_coords(sm::inverse(sm::from_coords(w)));
}

std::vector<double> sobrero_d::exp(const std::vector<double>& w, double t) const {
    check(w, "exp");
    return sm::to_coords(sm::exp(sm::from_coords(w), t));
}

std::vector<double> sobrero_d::log(const std::vector<double>& w, double tol) const {
    if (is_zero_divisor(w, tol))
        throw zero_divisor_error("log of a zero divisor in sobrero_d(" + std::to_string(n_) +
                                     "): a_0 = b_0 = 0 (III.2.13)",
                                 {0});
    return sm::to_coords(sm::log(sm::from_coords(w)));
}

}  // namespace symrep
