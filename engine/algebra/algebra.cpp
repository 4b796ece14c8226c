// symrep/algebra/algebra.cpp -- coordinate-vector helpers shared by all algebras.
#include "symrep/algebra/algebra.h"

#include <sstream>

#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"

namespace symrep {

using GiNaC::ex;

std::string algebra::basis_name(std::size_t k) const { return "e" + std::to_string(k); }

coeffs algebra::unit() const { return basis_vector(0); }

coeffs algebra::basis_product(std::size_t i, std::size_t j) const {
    return multiply(basis_vector(i), basis_vector(j));
}

coeffs algebra::basis_vector(std::size_t k) const {
    coeffs c = zero();
    if (k >= c.size())
        throw algebra_error(name() + " has " + std::to_string(c.size()) + " basis elements (0.." +
                            std::to_string(c.size() - 1) + "); there is no basis element " +
                            std::to_string(k));
    c[k] = 1;
    return c;
}

coeffs algebra::add(const coeffs& a, const coeffs& b) {
    coeffs c(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) c[k] = a[k] + b[k];
    return c;
}

coeffs algebra::sub(const coeffs& a, const coeffs& b) {
    coeffs c(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) c[k] = a[k] - b[k];
    return c;
}

coeffs algebra::scale(const ex& s, const coeffs& a) {
    coeffs c(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) c[k] = tidy(s * a[k]);
    return c;
}

coeffs algebra::power(const coeffs& w, unsigned long k) const {
    coeffs result = unit();
    coeffs base = w;
    while (k > 0) {
        check_interrupt();
        if (k & 1) result = multiply(result, base);
        k >>= 1;
        if (k > 0) base = multiply(base, base);
    }
    return result;
}

bool algebra::is_power_basis_generator(const coeffs&) const { return false; }

coeffs algebra::evaluate_polynomial(const ex& p, const GiNaC::symbol& X, const coeffs& w) const {
    check_size(w, "polynomial evaluation");
    ex q = GiNaC::expand(p);
    if (!q.is_polynomial(X))
    {
        std::ostringstream os;
        os << "cannot evaluate " << q << " at an algebra element: it is not a polynomial in " << X;
        throw type_error(os.str());
    }
    const int deg = q.degree(X);
    if (deg < int(dim()) && is_power_basis_generator(w)) {  // the coordinates are the coefficients
        coeffs out(dim(), ex(0));
        for (int k = 0; k <= deg; ++k) out[std::size_t(k)] = tidy(q.coeff(X, k));
        return out;
    }
    if (GiNaC::is_a<GiNaC::add>(q) ? int(q.nops()) * 8 < deg : deg > 8) {
        // sparse (x^100000 + 1): sum c_k w^k with powers by squaring, not deg Horner steps
        coeffs acc = zero();
        for (std::size_t i = 0; i < (GiNaC::is_a<GiNaC::add>(q) ? q.nops() : 1); ++i) {
            const ex term = GiNaC::is_a<GiNaC::add>(q) ? q.op(i) : q;
            const int k = term.degree(X);
            const coeffs wk = power(w, static_cast<unsigned long>(k));
            const ex ck = term.coeff(X, k);
            for (std::size_t j = 0; j < acc.size(); ++j) acc[j] = tidy(acc[j] + ck * wk[j]);
        }
        return acc;
    }
    coeffs acc = zero();
    for (int k = deg; k >= 0; --k) {  // Horner: acc = acc*w + c_k
        check_interrupt();
        acc = multiply(acc, w);
        const ex ck = q.coeff(X, k);
        coeffs u = unit();
        for (std::size_t i = 0; i < u.size(); ++i) acc[i] = tidy(acc[i] + ck * u[i]);
    }
    return acc;
}

namespace {
[[noreturn]] void no_structure(const algebra& A, const std::string& what) {
    throw algebra_error(what + " is not defined for " + A.name() +
                        " in symrep (see docs/algebras.md for what each family provides)");
}
}  // namespace

coeffs algebra::idempotent(std::size_t) const { no_structure(*this, "an idempotent basis"); }
std::vector<ex> algebra::idempotent_components(const coeffs&) const {
    no_structure(*this, "an idempotent basis");
}
coeffs algebra::from_idempotent_components(const std::vector<ex>&) const {
    no_structure(*this, "an idempotent basis");
}
std::vector<std::size_t> algebra::zero_divisor_ranks(const coeffs&) const {
    no_structure(*this, "the rank of a zero divisor");
}
std::pair<coeffs, coeffs> algebra::semiexponential(const coeffs&) const {
    no_structure(*this, "the semiexponential form");
}
bool algebra::is_special_type(const coeffs&, bool) const { no_structure(*this, "the special type"); }
std::vector<coeffs> algebra::special_type_decomposition(const coeffs&) const {
    no_structure(*this, "the special-type decomposition");
}
coeffs algebra::generating_element(const std::vector<ex>&) const {
    throw algebra_error("no generating element is known for " + name() +
                        "; use is_polynomial() to search for one (Thm III.4.1)");
}

bool algebra::equal(const coeffs& a, const coeffs& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!is_zero_scalar(a[k] - b[k])) return false;
    return true;
}

void algebra::check_dense(const char* what) const {
    if (dim() > max_dense_dim)
        throw size_error(std::string(what) + ": " + name() + " has dimension " + std::to_string(dim()) +
                         ", and dense " + std::to_string(dim()) + " x " + std::to_string(dim()) +
                         " exact matrices are limited to " + std::to_string(max_dense_dim) + " x " +
                         std::to_string(max_dense_dim));
}

void algebra::check_size(const coeffs& a, const char* what) const {
    if (a.size() != dim())
        throw algebra_error(std::string(what) + ": " + name() + " has dimension " +
                            std::to_string(dim()) + ", but " + std::to_string(a.size()) +
                            " coordinates were given");
}

std::string rank_list(const std::vector<std::size_t>& ranks) {
    std::string s;
    for (std::size_t i = 0; i < ranks.size(); ++i) s += (i ? ", " : "") + std::to_string(ranks[i]);
    return s;
}

}  // namespace symrep
