// symrep/algebra/polynomial_algebra.cpp -- P_n = R[X]/(p) with the cyclic basis.
#include "symrep/algebra/polynomial_algebra.h"

#include <sstream>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep {

using GiNaC::ex;

namespace {
// through the canonical printer (message_text): GiNaC's own output orders terms by its
// history-dependent term order, (k+m*w^2) in one session and (m*w^2+k) in another

/// Largest integer exponent in e (0 when none): checked before degree(), which
/// reads exponents as machine integers.
GiNaC::numeric max_exponent(const ex& e, const GiNaC::symbol& X) {
    GiNaC::numeric m = 0;
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) && e.op(0).has(X))
        m = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(1)));
    for (std::size_t i = 0; i < e.nops(); ++i) m = std::max(m, max_exponent(e.op(i), X));
    return m;
}
}  // namespace

polynomial_algebra::polynomial_algebra(const ex& p, const GiNaC::symbol& X) : X_(X) {
    const auto check_degree = [&](const ex& e) {
        const GiNaC::numeric d = max_exponent(e, X);
        if (d > GiNaC::numeric(long(max_degree)))
            throw size_error("polynomial algebra: the polynomial has degree " + message_text(d, text_limit::name) +
                             " in " + message_text(X, text_limit::name) + ", more than the limit " +
                             std::to_string(max_degree));
    };
    check_degree(p);
    const ex q = GiNaC::expand(p);
    if (!q.is_polynomial(X))
        throw algebra_error("polynomial algebra: " + message_text(p, text_limit::name) + " is not a polynomial in " +
                            message_text(X, text_limit::name));
    check_degree(q);
    const int n = q.degree(X);
    if (n < 1)
        throw algebra_error("polynomial algebra: " + message_text(p, text_limit::name) + " has degree 0 in " +
                            message_text(X, text_limit::name) + "; P_n needs degree n >= 1");
    if (!is_zero_scalar(q.coeff(X, n) - 1))
        throw algebra_error("polynomial algebra: " + message_text(p, text_limit::name) +
                            " is not monic (leading coefficient " + message_text(q.coeff(X, n), text_limit::name) +
                            "); divide it by its leading coefficient");
    n_ = std::size_t(n);
    p_ = q;
    low_.resize(n_);
    for (std::size_t k = 0; k < n_; ++k) low_[k] = tidy(q.coeff(X, int(k)));
    // name: descending powers, each coefficient printed by GiNaC
    std::ostringstream os;
    os << "polynomial(" << X;
    if (n > 1) os << "^" << n;
    for (int k = n - 1; k >= 0; --k) {
        const ex c = low_[k];
        if (c.is_zero()) continue;
        std::string cs = message_text(c, text_limit::name);
        // negative number, or a product with a negative numeric factor (-2*a)
        const ex num = GiNaC::is_a<GiNaC::mul>(c) ? c.op(c.nops() - 1) : c;
        const bool neg = GiNaC::is_a<GiNaC::numeric>(num) && GiNaC::ex_to<GiNaC::numeric>(num).is_negative();
        if (neg) cs = message_text(-c, text_limit::name);
        os << (neg ? " - " : " + ");
        const bool atomic = !GiNaC::is_a<GiNaC::add>(c);
        if (k == 0) {
            os << (atomic ? cs : "(" + cs + ")");
        } else {
            if (cs != "1") os << (atomic ? cs : "(" + cs + ")") << "*";
            os << X;
            if (k > 1) os << "^" << k;
        }
    }
    os << ")";
    name_ = os.str();
}

std::shared_ptr<const polynomial_algebra> polynomial_algebra::make(const ex& p, const GiNaC::symbol& X) {
    return std::make_shared<const polynomial_algebra>(p, X);
}

std::string polynomial_algebra::basis_name(std::size_t k) const {
    if (k == 0) return "1";
    if (k == 1) return "v";
    return "v^" + std::to_string(k);
}

// Product of sum a_i v^i and sum b_j v^j, reduced with v^n = -sum_k low_k v^k.
coeffs polynomial_algebra::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "product");
    check_size(b, "product");
    const std::size_t n = n_;
    std::vector<ex> r(2 * n - 1, ex(0));
    for (std::size_t i = 0; i < n; ++i) {
        if (a[i].is_zero()) continue;
        for (std::size_t j = 0; j < n; ++j)
            if (!b[j].is_zero()) r[i + j] += a[i] * b[j];
    }
    for (std::size_t d = 2 * n - 2; d >= n; --d) {  // reduce v^d = v^{d-n} v^n
        const ex c = tidy(r[d]);
        if (!c.is_zero())
            for (std::size_t k = 0; k < n; ++k) r[d - n + k] -= c * low_[k];
        r[d] = 0;
    }
    coeffs out(n);
    for (std::size_t k = 0; k < n; ++k) out[k] = tidy(r[k]);
    return out;
}

coeffs polynomial_algebra::generator() const {
    if (n_ == 1) return coeffs{tidy(-low_[0])};
    return basis_vector(1);
}

// (II.1 completion) superdiagonal ones, last row -a_n .. -a_1.
GiNaC::matrix polynomial_algebra::frobenius_matrix() const {
    check_dense("Frobenius matrix");
    GiNaC::matrix F(n_, n_);
    for (std::size_t j = 0; j + 1 < n_; ++j) F(j, j + 1) = 1;
    for (std::size_t k = 0; k < n_; ++k) F(n_ - 1, k) = tidy(-low_[k]);
    return F;
}

ex polynomial_algebra::charpoly(const coeffs& w, const GiNaC::symbol& X) const {
    if (equal(w, generator())) return p_.subs(X_ == X);
    return algebra::charpoly(w, X);
}

ex polynomial_algebra::minpoly(const coeffs& w, const GiNaC::symbol& X) const {
    if (equal(w, generator())) return p_.subs(X_ == X);
    return algebra::minpoly(w, X);
}

bool polynomial_algebra::is_power_basis_generator(const coeffs& w) const {
    if (w.size() != dim() || dim() < 2) return false;
    for (std::size_t i = 0; i < w.size(); ++i)
        if (!(i == 1 ? w[i].is_equal(1) : w[i].is_zero())) return false;
    return true;
}

}  // namespace symrep
