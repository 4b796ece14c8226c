// symrep/algebra/multicomplex.cpp -- the exact multicomplex algebra (III.1).
#include "symrep/algebra/multicomplex.h"

#include <algorithm>
#include <sstream>

#include "symrep/algebra/double_path.h"
#include "symrep/algebra/multicomplex_double.h"
#include "symrep/algebra/multicomplex_indexing.h"
#include "symrep/algebra/multicomplex_transform.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/core/expression_size.h"

namespace symrep {

using GiNaC::ex;
namespace dp = double_path;

namespace {

// Product of the factors, multiplied pairwise (a balanced product tree) and
// expanded at each level. The guard bounds the result by its monomials when the
// factors are polynomials (2^n quadratics in X: 2^(n+1) + 1 terms), and each
// pairwise product again before it is made.
ex expanded_product(std::vector<ex> f) {
    if (f.empty()) return 1;
    guard_terms(product_terms(f), "the product of the factors");
    while (f.size() > 1) {
        std::vector<ex> g;
        for (std::size_t k = 0; k + 1 < f.size(); k += 2) {
            guard_terms(product_terms({f[k], f[k + 1]}), "the product of the factors");
            g.push_back(GiNaC::expand(f[k] * f[k + 1]));
        }
        if (f.size() % 2) g.push_back(f.back());
        f = std::move(g);
    }
    return GiNaC::expand(f[0]);
}

}  // namespace

std::shared_ptr<const multicomplex> multicomplex::make(unsigned n) {
    if (n > multicomplex_d::max_order())
        throw size_error("multicomplex(" + std::to_string(n) +
                         "): the exact multicomplex algebra is limited to n <= " +
                         std::to_string(max_order) + " (dimension 2^" + std::to_string(max_order + 1) +
                         ") and the double-precision path to n <= " +
                         std::to_string(multicomplex_d::max_order()) + " on this machine");
    return std::shared_ptr<const multicomplex>(new multicomplex(n));
}




std::string multicomplex::name() const { return "multicomplex(" + std::to_string(n_) + ")"; }

// (III.1.4) e_p = i0^{p_0} ... in^{p_n}, digit p_k at bit n-k.
std::string multicomplex::basis_name(std::size_t p) const {
    if (p >= dim()) return algebra::basis_name(p);
    if (p == 0) return "1";
    std::string s;
    for (unsigned k = 0; k <= n_; ++k)
        if (p & multicomplex_imag_unit_index(n_, k)) s += (s.empty() ? "i" : "*i") + std::to_string(k);
    return s;
}

coeffs multicomplex::tidy_all(coeffs c) const {
    for (auto& x : c) x = tidy(x);
    return c;
}

std::vector<cplx<ex>> multicomplex::component_pairs(const coeffs& w) const {
    check_size(w, "idempotent components");
    auto c = multicomplex_components<ex>(w, n_);  // (III.1.40-41) by one FWHT
    for (auto& z : c) z = {tidy(z.re), tidy(z.im)};
    return c;
}

coeffs multicomplex::from_component_pairs(const std::vector<cplx<ex>>& c) const {
    if (c.size() != half_dim())
        throw algebra_error("idempotent components: " + name() + " has " + std::to_string(half_dim()) +
                            " idempotent components, but " + std::to_string(c.size()) + " were given");
    return tidy_all(multicomplex_from_components<ex>(c, n_));  // (III.1.42-43, corrected)
}

// (III.1.39, III.1.16) the product is componentwise in the idempotent basis.
coeffs multicomplex::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "product");
    check_size(b, "product");
    if (takes_double_path({&a, &b}, "product"))
        return dp::from_doubles(multicomplex_d(n_).multiply(dp::to_doubles(a), dp::to_doubles(b)));
    auto ca = multicomplex_components<ex>(a, n_);
    const auto cb = multicomplex_components<ex>(b, n_);
    for (std::size_t p = 0; p < ca.size(); ++p) ca[p] = ca[p] * cb[p];
    return tidy_all(multicomplex_from_components<ex>(std::move(ca), n_));
}

// (III.1.7)
coeffs multicomplex::basis_product(std::size_t i, std::size_t j) const {
    coeffs c = zero();
    if (i >= dim() || j >= dim()) return algebra::basis_product(i, j);  // throws with the range
    c[i ^ j] = multicomplex_product_sign(i, j);
    return c;
}

coeffs multicomplex::imag_unit(unsigned k) const {
    if (k > n_)
        throw algebra_error(name() + " has the imaginary units i0..i" + std::to_string(n_) +
                            "; there is no i" + std::to_string(k));
    return basis_vector(multicomplex_imag_unit_index(n_, k));
}

// (III.1.13)
coeffs multicomplex::gray_basis(std::size_t k) const {
    if (k >= dim())
        throw algebra_error(name() + " has the Gray basis elements v_0..v_" + std::to_string(dim() - 1) +
                            "; there is no v_" + std::to_string(k));
    return basis_vector(multicomplex_gray(n_, k));
}

coeffs multicomplex::to_gray_coordinates(const coeffs& w) const {
    check_size(w, "Gray coordinates");
    coeffs v(dim());
    for (std::size_t k = 0; k < dim(); ++k) v[k] = w[multicomplex_gray(n_, k)];
    return v;
}

coeffs multicomplex::from_gray_coordinates(const coeffs& v) const {
    check_size(v, "Gray coordinates");
    coeffs w(dim());
    for (std::size_t k = 0; k < dim(); ++k) w[multicomplex_gray(n_, k)] = v[k];
    return w;
}

// (III.1.15) e_p has the single component 1 at p.
coeffs multicomplex::idempotent(std::size_t p) const {
    if (p >= half_dim())
        throw algebra_error(name() + " has the idempotents e_0..e_" + std::to_string(half_dim() - 1) +
                            "; there is no e_" + std::to_string(p));
    std::vector<cplx<ex>> c(half_dim(), cplx<ex>(0, 0));
    c[p] = cplx<ex>(1, 0);
    return from_component_pairs(c);
}

std::vector<ex> multicomplex::idempotent_components(const coeffs& w) const {
    std::vector<ex> out;
    for (const auto& z : component_pairs(w)) out.push_back(z.re + GiNaC::I * z.im);
    return out;
}

coeffs multicomplex::from_idempotent_components(const std::vector<ex>& c) const {
    std::vector<cplx<ex>> z;
    z.reserve(c.size());
    for (const auto& x : c) {
        const ex e = GiNaC::expand(x);
        z.emplace_back(tidy(GiNaC::real_part(e)), tidy(GiNaC::imag_part(e)));
    }
    return from_component_pairs(z);
}

// (III.1.54) det [w] = prod_p r_p^2.
ex multicomplex::determinant(const coeffs& w) const {
    require_exact("determinant");
    std::vector<ex> f;
    for (const auto& z : component_pairs(w)) f.push_back(tidy(z.norm2()));
    return tidy(expanded_product(std::move(f)));
}

// (III.1.59) the characteristic polynomial.
ex multicomplex::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    require_exact("characteristic polynomial");
    std::vector<ex> f;
    for (const auto& z : component_pairs(w))
        f.push_back(GiNaC::pow(X, 2) - 2 * z.re * X + tidy(z.norm2()));
    return expanded_product(std::move(f));
}

// (III.1.59-60, corrected): lcm of the real minimal polynomials of the components.
ex multicomplex::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    require_exact("minimal polynomial");
    struct factor { ex a, b2; bool linear; };
    std::vector<factor> distinct;
    for (const auto& z : component_pairs(w)) {
        const bool linear = !is_nonzero_generic(z.im, "minimal polynomial in " + name());
        const ex b2 = linear ? ex(0) : tidy(z.im * z.im);
        const bool seen = std::any_of(distinct.begin(), distinct.end(), [&](const factor& f) {
            return f.linear == linear && !is_nonzero_generic(f.a - z.re, "minimal polynomial in " + name()) &&
                   !is_nonzero_generic(f.b2 - b2, "minimal polynomial in " + name());
        });
        if (!seen) distinct.push_back({z.re, b2, linear});
    }
    std::vector<ex> f;
    for (const auto& d : distinct)
        f.push_back(d.linear ? X - d.a : GiNaC::pow(X, 2) - 2 * d.a * X + tidy(d.a * d.a + d.b2));
    return expanded_product(std::move(f));
}

namespace {
// The ranks p whose idempotent component a_p + i b_p is 0 (III.1.55), decided exactly
// (is_nonzero_generic: refused where undecidable, never guessed).
std::vector<std::size_t> vanishing_components(const std::vector<cplx<ex>>& c, const std::string& algebra_name) {
    std::vector<std::size_t> ranks;
    for (std::size_t p = 0; p < c.size(); ++p)
        if (!is_nonzero_generic(c[p].re, algebra_name + ": an idempotent component") &&
            !is_nonzero_generic(c[p].im, algebra_name + ": an idempotent component"))
            ranks.push_back(p);
    return ranks;
}
}  // namespace

// (III.1.55)
std::vector<std::size_t> multicomplex::zero_divisor_ranks(const coeffs& w) const {
    check_size(w, "zero divisor ranks");
    // (III.1.55) in doubles: |c_p| <= 1e-12 max |c_q| (multicomplex_d::default_rel_tol)
    if (takes_double_path({&w}, "zero divisor ranks")) return multicomplex_d(n_).zero_divisor_ranks(dp::to_doubles(w));
    return vanishing_components(component_pairs(w), name());
}

bool multicomplex::is_zero_divisor(const coeffs& w) const { return !zero_divisor_ranks(w).empty(); }

namespace {
[[noreturn]] void throw_zero_divisor(const multicomplex& A, const char* what,
                                     std::vector<std::size_t> ranks) {
    const std::string msg = std::string(what) + " of a zero divisor in " + A.name() +
                            ": the idempotent component(s) of rank " + rank_list(ranks) +
                            " vanish (a_k = b_k = 0, III.1.55), so w e_k = 0 (III.1.56)";
    throw zero_divisor_error(msg, std::move(ranks));
}
}  // namespace

// (III.1.57)
coeffs multicomplex::inverse(const coeffs& w) const {
    check_size(w, "inverse");
    if (takes_double_path({&w}, "inverse")) return dp::from_doubles(multicomplex_d(n_).inverse(dp::to_doubles(w)));
    auto c = component_pairs(w);
    std::vector<std::size_t> ranks = vanishing_components(c, name());
    if (!ranks.empty()) throw_zero_divisor(*this, "inverse", std::move(ranks));
    for (auto& z : c) z = multicomplex_component_inverse<ex>(z.re, z.im);
    return from_component_pairs(c);
}

// (III.1.45-52)
coeffs multicomplex::exp(const coeffs& w, const ex& t) const {
    check_size(w, "exp");
    const auto on_doubles = [&](const std::vector<double>& x, double s) { return multicomplex_d(n_).exp(x, s); };
    if (auto d = exp_on_double_path(w, t, on_doubles)) return *std::move(d);
    auto c = component_pairs(w);
    for (auto& z : c) z = multicomplex_component_exp<ex>(z.re, z.im, t);
    return from_component_pairs(c);
}

// (III.1.53). Steps as in inverse() (the double path, the zero-divisor ranks, a map of the
// components); only the map differs.
coeffs multicomplex::log(const coeffs& w) const {
    check_size(w, "log");
    if (takes_double_path({&w}, "log")) return dp::from_doubles(multicomplex_d(n_).log(dp::to_doubles(w)));
    auto c = component_pairs(w);
    std::vector<std::size_t> ranks = vanishing_components(c, name());
    if (!ranks.empty()) throw_zero_divisor(*this, "logarithm", std::move(ranks));
    for (auto& z : c) z = multicomplex_component_log<ex>(z.re, z.im);
    return from_component_pairs(c);
}

// (III.1.72-76): rho = sum r_p e_p = sum rho_k u_k, theta = sum i0 phi_p e_p = sum theta_k j_k.
std::pair<coeffs, coeffs> multicomplex::semiexponential(const coeffs& w) const {
    require_exact("semiexponential form");
    const auto c = component_pairs(w);
    std::vector<cplx<ex>> r, phi;
    for (const auto& z : c) {
        r.emplace_back(multicomplex_modulus(z.re, z.im), 0);
        phi.emplace_back(0, multicomplex_argument(z.re, z.im));
    }
    return {from_component_pairs(r), from_component_pairs(phi)};
}

namespace {
// Zero test that also knows cos^2 + sin^2 = 1: the squared moduli of components
// of exp(theta) are sums of cos(x)^2 and sin(x)^2, which normal() keeps apart.
bool is_zero_trig(const ex& x) {
    if (is_zero_scalar(x)) return true;
    const GiNaC::wildcard u(0);
    const ex y = GiNaC::expand(x).subs(GiNaC::pow(GiNaC::sin(u), 2) == 1 - GiNaC::pow(GiNaC::cos(u), 2),
                                       GiNaC::subs_options::algebraic);
    return is_zero_scalar(y);
}
}  // namespace

// (III.1.95) r_0 = r_1 = ... = r_{2^n-1} != 0 (compared as r_p^2).
bool multicomplex::is_special_type(const coeffs& w, bool) const {
    require_exact("special-type test");
    const auto c = component_pairs(w);
    const ex r0 = tidy(c[0].norm2());
    if (is_zero_trig(r0)) return false;
    for (const auto& z : c)
        if (!is_zero_trig(z.norm2() - r0)) return false;
    return true;
}

// Thm III.1.3.1, (III.1.90-92): term k = rho_k u_k exp(theta); its components are
// rho_k sigma(k) h_{p,k} e^{i phi_p} (III.1.25), of modulus |rho_k| for every p.
std::vector<coeffs> multicomplex::special_type_decomposition(const coeffs& w) const {
    require_exact("special-type decomposition");
    const auto c = component_pairs(w);
    const std::size_t N = half_dim();
    // rho_k = 2^{-n} sum_p sigma(k) h_{k,p} r_p (III.1.75): the u-coordinates of rho.
    std::vector<ex> r(N);
    std::vector<cplx<ex>> phase(N);  // e^{i phi_p} = c_p / r_p, 1 where r_p = 0
    for (std::size_t p = 0; p < N; ++p) {
        r[p] = multicomplex_modulus(c[p].re, c[p].im);
        if (is_zero_scalar(r[p])) phase[p] = cplx<ex>(1, 0);
        else phase[p] = cplx<ex>(tidy(c[p].re / r[p]), tidy(c[p].im / r[p]));
    }
    std::vector<coeffs> terms;
    const ex scale = inv_pow2<ex>(n_);
    for (std::size_t k = 0; k < N; ++k) {
        ex rho = 0;
        for (std::size_t p = 0; p < N; ++p) rho += multicomplex_walsh(n_, p, k) * r[p];
        rho = tidy(multicomplex_sigma(n_, k) * scale * rho);
        if (is_zero_scalar(rho)) continue;
        std::vector<cplx<ex>> t(N);
        for (std::size_t p = 0; p < N; ++p) {
            const ex u = multicomplex_sigma(n_, k) * multicomplex_walsh(n_, p, k);  // (III.1.25)
            t[p] = cplx<ex>(tidy(rho * u * phase[p].re), tidy(rho * u * phase[p].im));
        }
        terms.push_back(from_component_pairs(t));
    }
    return terms;
}

std::vector<ex> multicomplex::generating_frequencies(const std::vector<ex>& omega) const {
    if (omega.size() != n_ + 1)
        throw algebra_error("generating element of " + name() + ": " + std::to_string(n_ + 1) +
                            " parameters omega_0..omega_" + std::to_string(n_) + " are needed, but " +
                            std::to_string(omega.size()) + " were given");
    std::vector<ex> Omega(half_dim());
    for (std::size_t p = 0; p < half_dim(); ++p) {  // (III.4.8)
        ex s = omega[0];
        for (unsigned k = 1; k <= n_; ++k)
            s += ((p & multicomplex_imag_unit_index(n_, k)) ? -1 : 1) * omega[k];
        Omega[p] = tidy(s);
    }
    return Omega;
}

// (III.4.5)
coeffs multicomplex::generating_element(const std::vector<ex>& params) const {
    std::vector<ex> omega = params;
    if (omega.empty()) {
        omega.push_back(GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(n_)));
        for (unsigned k = 1; k <= n_; ++k) omega.push_back(GiNaC::pow(GiNaC::numeric(2), GiNaC::numeric(k - 1)));
    }
    generating_frequencies(omega);  // checks the count
    coeffs d = zero();
    for (unsigned k = 0; k <= n_; ++k) d[multicomplex_imag_unit_index(n_, k)] = omega[k];
    return d;
}

}  // namespace symrep
