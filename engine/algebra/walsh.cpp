// symrep/algebra/walsh.cpp -- the Walsh algebra W (III.3.1-III.3.3).
#include "symrep/algebra/walsh.h"

#include <sstream>

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

algebra_ptr walsh::make(long n) {
    if (n < 0) throw domain_error("walsh(n): n must be >= 0, got " + std::to_string(n));
    if (n > long(walsh_d::max_n))
        throw size_error("walsh(n): n = " + std::to_string(n) + " is too large; the exact Walsh "
                         "algebra is limited to n <= " + std::to_string(max_n) + " (order 2^n) and the "
                         "double-precision path to n <= " + std::to_string(walsh_d::max_n));
    return std::make_shared<walsh>(unsigned(n));
}

walsh::walsh(unsigned n) : n_(n) {
    if (n > walsh_d::max_n)
        throw size_error("walsh(n): n = " + std::to_string(n) + " exceeds the limit n <= " +
                         std::to_string(walsh_d::max_n) + " of the double-precision path");
}




std::string walsh::name() const { return "walsh(" + std::to_string(n_) + ")"; }

std::size_t walsh::generator_index(std::size_t k) const {
    if (k >= n_)
        throw domain_error("walsh_generator: " + name() +
                           (n_ == 0 ? std::string(" has no generators u_k")
                                    : " has generators u_0..u_" + std::to_string(n_ - 1)) +
                           "; there is no u_" + std::to_string(k));
    return std::size_t(1) << (n_ - 1 - k);
}

coeffs walsh::generator(std::size_t k) const { return basis_vector(generator_index(k)); }

// (III.3.3) w_p = u_0^{p_0} ... u_{n-1}^{p_{n-1}}, p_0 the most significant bit.
std::string walsh::basis_name(std::size_t p) const {
    if (p >= dim()) return algebra::basis_name(p);
    if (p == 0) return "1";
    std::string s;
    for (unsigned k = 0; k < n_; ++k)
        if (p & (std::size_t(1) << (n_ - 1 - k))) s += (s.empty() ? "u" : "*u") + std::to_string(k);
    return s;
}

// (III.3.6) w_p w_q = w_{p xor q}.
coeffs walsh::basis_product(std::size_t i, std::size_t j) const {
    if (i >= dim() || j >= dim()) return algebra::basis_product(i, j);
    return basis_vector(i ^ j);
}

// Product through the idempotent components (III.3.26): (fg)_p = a_p b_p.
coeffs walsh::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "walsh product");
    check_size(b, "walsh product");
    if (takes_double_path({&a, &b}, "product"))
        return dp::from_doubles(walsh_d(n_).multiply(dp::to_doubles(a), dp::to_doubles(b)));
    std::vector<ex> x = wm::components(a), y = wm::components(b);
    for (std::size_t p = 0; p < x.size(); ++p) x[p] = x[p] * y[p];
    return wm::from_components(std::move(x));
}

// (III.3.22) e_p = 2^{-n} sum_q (-1)^{<p,q>} w_q.
coeffs walsh::idempotent(std::size_t p) const {
    if (p >= dim())
        throw domain_error("idempotent: " + name() + " has idempotents e_0..e_" +
                           std::to_string(dim() - 1) + "; there is no e_" + std::to_string(p));
    coeffs e(dim());
    const ex s = inv_pow2<ex>(n_);
    for (std::size_t q = 0; q < dim(); ++q) e[q] = wm::dyadic_sign(p, q) * s;
    return e;
}

// (III.3.25) a_p = sum_q (-1)^{<p,q>} f_q.
std::vector<ex> walsh::idempotent_components(const coeffs& w) const {
    check_size(w, "idempotent components");
    return wm::components(w);
}

// (III.3.21) f = 2^{-n} H a.
coeffs walsh::from_idempotent_components(const std::vector<ex>& a) const {
    if (a.size() != dim())
        throw algebra_error("from_idempotent_components: " + name() + " has " +
                            std::to_string(dim()) + " idempotents, but " +
                            std::to_string(a.size()) + " components were given");
    return wm::from_components(a);
}

namespace {
// The ranks p with a_p = 0 (III.3.31), decided exactly (is_nonzero_generic: refused where
// undecidable, never guessed).
std::vector<std::size_t> vanishing_components(const std::vector<ex>& a, const std::string& algebra_name) {
    std::vector<std::size_t> r;
    for (std::size_t p = 0; p < a.size(); ++p)
        if (!is_nonzero_generic(a[p], algebra_name + ": an idempotent component")) r.push_back(p);
    return r;
}
}  // namespace

// (III.3.31-32) the ranks p with a_p = 0.
std::vector<std::size_t> walsh::zero_divisor_ranks(const coeffs& w) const {
    check_size(w, "zero divisor ranks");
    // (III.3.31) in doubles: |a_p| <= 1e-12 max |a_q|
    if (takes_double_path({&w}, "zero divisor ranks")) return walsh_d(n_).zero_divisor_ranks(dp::to_doubles(w));
    const std::vector<ex> a = idempotent_components(w);
    return vanishing_components(a, name());
}

// (III.3.30)
bool walsh::is_zero_divisor(const coeffs& w) const { return !zero_divisor_ranks(w).empty(); }

// (III.3.28) det [f] = a_0 a_1 ... a_{2^n-1}.
ex walsh::determinant(const coeffs& w) const {
    require_exact("determinant");
    const std::vector<ex> a = idempotent_components(w);
    ex d = 1;
    for (const auto& x : a) d = d * x;
    return tidy(d);
}

// (III.3.33-34) p(X) = prod_p (X - a_p), returned expanded.
ex walsh::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    require_exact("characteristic polynomial");
    const std::vector<ex> a = idempotent_components(w);
    ex p = 1;
    for (const auto& x : a) p = guarded_expand(p * (X - x), "characteristic polynomial");
    return p;
}

// W is semisimple (Thm III.3.2.2): minimal polynomial = prod over the DISTINCT a_p of (X - a_p).
ex walsh::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    require_exact("minimal polynomial");
    const std::vector<ex> a = idempotent_components(w);
    std::vector<ex> roots;
    for (const auto& x : a) {
        bool seen = false;
        for (const auto& r : roots)
            if (!is_nonzero_generic(x - r, "minimal polynomial in " + name())) { seen = true; break; }
        if (!seen) roots.push_back(x);
    }
    ex p = 1;
    for (const auto& r : roots) p = guarded_expand(p * (X - r), "minimal polynomial");
    return p;
}

namespace {
[[noreturn]] void throw_zero_divisor(const std::string& algebra_name, const char* what,
                                     const std::vector<std::size_t>& r) {
    throw zero_divisor_error(std::string(what) + " of a zero divisor in " + algebra_name +
                                 ": the idempotent components of rank " + rank_list(r) +
                                 " vanish (III.3.31), so w e_p = 0 for these p (Thm III.3.2.3)",
                             r);
}
}  // namespace

// Inverse through the components: a_p -> 1/a_p (III.3.26).
coeffs walsh::inverse(const coeffs& w) const {
    check_size(w, "inverse");
    if (takes_double_path({&w}, "inverse")) return dp::from_doubles(walsh_d(n_).inverse(dp::to_doubles(w)));
    std::vector<ex> a = idempotent_components(w);
    const std::vector<std::size_t> r = vanishing_components(a, name());
    if (!r.empty()) throw_zero_divisor(name(), "inverse", r);
    for (auto& x : a) x = tidy(1 / x);
    return wm::from_components(std::move(a));
}

// (III.3.44) exp(f t) = 2^{-n} sum_p [sum_k (-1)^{<p,k>} e^{a_k t}] w_p.
coeffs walsh::exp(const coeffs& w, const ex& t) const {
    check_size(w, "exp");
    const auto on_doubles = [&](const std::vector<double>& x, double s) { return walsh_d(n_).exp(x, s); };
    if (auto d = exp_on_double_path(w, t, on_doubles)) return *std::move(d);
    std::vector<ex> a = idempotent_components(w);
    for (auto& x : a) x = exp_scalar(tidy(x * t));
    return wm::from_components(std::move(a));
}

namespace {
/// Decides a_p > 0 for a root of the characteristic polynomial; 1 yes, -1 no, 0 unknown.
int positive_root(const ex& a) {
    if (GiNaC::is_a<GiNaC::numeric>(a)) {
        const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(a);
        return v.is_real() && v > 0 ? 1 : -1;
    }
    if (a.info(GiNaC::info_flags::positive)) return 1;
    if (GiNaC::is_the_function<GiNaC::exp_SERIAL>(a) && a.op(0).info(GiNaC::info_flags::real)) return 1;
    if ((-a).info(GiNaC::info_flags::nonnegative)) return -1;
    const ex f = GiNaC::evalf(a);
    if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f).is_real())
        return GiNaC::ex_to<GiNaC::numeric>(f) > 0 ? 1 : -1;
    return 0;
}
}  // namespace

// Thm III.3.3.1 (III.3.39-40): g_p = 2^{-n} sum_k (-1)^{<p,k>} ln a_k, every a_k > 0.
// Steps as in inverse() (the double path, the zero-divisor ranks), then the signs of the a_k.
coeffs walsh::log(const coeffs& w) const {
    check_size(w, "log");
    if (takes_double_path({&w}, "log")) return dp::from_doubles(walsh_d(n_).log(dp::to_doubles(w)));
    std::vector<ex> a = idempotent_components(w);
    const std::vector<std::size_t> r = vanishing_components(a, name());
    if (!r.empty()) throw_zero_divisor(name(), "log", r);
    for (std::size_t p = 0; p < a.size(); ++p) {
        const int s = positive_root(a[p]);
        if (s <= 0) {
            std::ostringstream os;
            os << "log in " << name() << ": the root a_" << p << " = " << a[p]
               << " of the characteristic polynomial "
               << (s < 0 ? "is not positive" : "is not known to be positive")
               << "; Thm III.3.3.1 needs every a_p > 0 (III.3.40). Every non-zero-divisor has a "
                  "logarithm in the complex extension walsh_complex("
               << n_ << ") (III.3.64-67)";
            throw domain_error(os.str());
        }
        a[p] = GiNaC::log(a[p]);
    }
    return wm::from_components(std::move(a));
}

// (III.4.15) d = sum_k alpha_k u_k.
coeffs walsh::generating_element(const std::vector<ex>& params) const {
    if (!params.empty() && params.size() != n_)
        throw type_error("generating_element: " + name() + " takes no parameters or {alpha_0, ..., "
                         "alpha_" + std::to_string(long(n_) - 1) + "} (d = sum alpha_k u_k, "
                         "III.4.15), got " + std::to_string(params.size()));
    coeffs d = zero();
    for (unsigned k = 0; k < n_; ++k)
        d[generator_index(k)] = params.empty() ? ex(GiNaC::pow(2, k)) : params[k];
    return d;
}

}  // namespace symrep
