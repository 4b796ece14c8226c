// symrep/algebra/algebra.h -- a finite-dimensional commutative, associative,
// unital real algebra A_n (thesis II.1), with exact coefficients.
//
// algebra/ holds the algebras of Ch. II-III: the general algebra from structure
// constants, the multicomplex, Sobrero, Walsh and complex Walsh algebras and
// the polynomial algebras, exact and double, with their elements and the
// functions on them (exp, log, inverse, minimal polynomial, ...). It includes
// core/ and scalar/ (docs/architecture.md).
//
// An algebra is known by its product on coefficient vectors in a fixed basis
// {eps_1..eps_n} (II.1.1-2). Everything else has a general default derived from
// the product through the canonical matrix [w] (II.1.3-4):
//   a_jk = sum_i w_i gamma_ijk, i.e. row j of [w] holds the coordinates of w eps_j.
// Families with a fast structure (multicomplex, Sobrero, Walsh, polynomial)
// override the virtuals with their own theorems; tests check that the fast paths
// agree with these general defaults on the structure-constant algebra built
// from the same table (structure_algebra::from).
//
// Algebras are immutable and shared (algebra_ptr); elements (element.h) are values.
#pragma once

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace symrep {

/// Coordinates of an element in the algebra's basis (exact).
using coeffs = std::vector<GiNaC::ex>;

class algebra;
using algebra_ptr = std::shared_ptr<const algebra>;

/// A scalar function to be applied to an algebra element through its minimal
/// polynomial (Hermite interpolation at the roots). `value(re, im, j)` returns
/// the real and imaginary parts of f^{(j)}(re + i im). Used by exp(w t) and log.
struct scalar_function {
    std::string name;
    /// Writes Re and Im of the j-th derivative of f at the point re + i*im.
    /// Throws domain_error where f (or the derivative) is not defined.
    std::function<void(const GiNaC::ex& re, const GiNaC::ex& im, unsigned j,
                       GiNaC::ex& out_re, GiNaC::ex& out_im)> value;
};

class algebra : public std::enable_shared_from_this<algebra> {
public:
    virtual ~algebra() = default;

    // --- identity ---------------------------------------------------------
    /// Canonical name, also used as identity: two algebras with the same name are
    /// the same algebra (e.g. "multicomplex(2)", "sobrero(3)", "walsh(4)").
    virtual std::string name() const = 0;
    /// Order n = dim over R.
    virtual std::size_t dim() const = 0;
    /// Printable name of basis element k (e.g. "e3", "i0*i2"); default "e<k>".
    virtual std::string basis_name(std::size_t k) const;

    // --- the product: the only thing a subclass must provide -----------------
    /// Product of two coordinate vectors (II.1.2).
    virtual coeffs multiply(const coeffs& a, const coeffs& b) const = 0;
    /// Coordinates of the identity (default: the first basis element).
    virtual coeffs unit() const;
    /// Structure constants gamma_ij. (k = 0..n-1): coordinates of eps_i eps_j
    /// (default: multiply of unit vectors).
    virtual coeffs basis_product(std::size_t i, std::size_t j) const;

    // --- general methods (II.1-II.2, III.4), overridable by fast paths --------
    /// (II.1.3-4) canonical matrix [w], a_jk = sum_i w_i gamma_ijk.
    virtual GiNaC::matrix canonical_matrix(const coeffs& w) const;
    /// det [w] (II.1.21).
    virtual GiNaC::ex determinant(const coeffs& w) const;
    /// Monic characteristic polynomial det(X I - [w]) in X (II.1.20 up to the sign (-1)^n).
    virtual GiNaC::ex charpoly(const coeffs& w, const GiNaC::symbol& X) const;
    /// Monic minimal polynomial of w (Cor. II.1.1): the first power of w that is a
    /// linear combination of the lower ones.
    virtual GiNaC::ex minpoly(const coeffs& w, const GiNaC::symbol& X) const;
    /// w is a zero divisor iff det [w] = 0 (II.1.22).
    virtual bool is_zero_divisor(const coeffs& w) const;
    /// Inverse; throws zero_divisor_error for a zero divisor.
    virtual coeffs inverse(const coeffs& w) const;
    /// exp(w t) as a closed form in t (Thm II.2.3; II.2 e^{dt} = sum d^k t^k/k!).
    virtual coeffs exp(const coeffs& w, const GiNaC::ex& t) const;
    /// A logarithm u with exp(u) = w, where one exists in the algebra; throws
    /// zero_divisor_error or domain_error otherwise.
    virtual coeffs log(const coeffs& w) const;
    /// f(w) for a scalar function, by Hermite interpolation on the roots of the
    /// minimal polynomial (the general method behind exp and log).
    coeffs apply_function(const coeffs& w, const scalar_function& f) const;

    // --- idempotent structure and special forms (Ch. III families) -------------
    // Defaults throw algebra_error naming the algebra: a general structure-constant
    // algebra has no idempotent basis computed for it. Families override.
    /// Number of orthogonal idempotents e_p of the family's idempotent basis (0: none).
    virtual std::size_t idempotent_count() const { return 0; }
    /// Coordinates of the orthogonal idempotent e_p (III.1.15, III.3.7).
    virtual coeffs idempotent(std::size_t p) const;
    /// Components c_p of w = sum_p c_p e_p: complex GiNaC expressions a_p + I b_p in the
    /// multicomplex algebra (III.1.39) and W* (III.3.61), real in W (III.3.24).
    virtual std::vector<GiNaC::ex> idempotent_components(const coeffs& w) const;
    /// Inverse of idempotent_components.
    virtual coeffs from_idempotent_components(const std::vector<GiNaC::ex>& c) const;
    /// The ranks p with c_p = 0 (III.1.55, III.3.31): empty iff w is not a zero divisor.
    virtual std::vector<std::size_t> zero_divisor_ranks(const coeffs& w) const;
    /// Semiexponential form w = rho exp(theta) (III.1.72-76, III.2.16): returns {rho, theta}.
    virtual std::pair<coeffs, coeffs> semiexponential(const coeffs& w) const;
    /// Special-type test (III.1.77-78, III.2.19-20 corrected). `strict` = false admits
    /// real coefficients of either sign where the family distinguishes (Sobrero).
    virtual bool is_special_type(const coeffs& w, bool strict = true) const;
    /// Decomposition of w into special-type elements (Thm III.1.3.1, Thm III.2.2.1).
    virtual std::vector<coeffs> special_type_decomposition(const coeffs& w) const;
    /// A generating element of the algebra (III.4.2 a-c) with the given parameters
    /// (omega_k, alpha/beta, alpha_k); empty params: the family's default choice.
    virtual coeffs generating_element(const std::vector<GiNaC::ex>& params) const;

    // --- helpers shared by all algebras -----------------------------------------
    /// Coordinates of basis element k.
    coeffs basis_vector(std::size_t k) const;
    /// The zero vector.
    coeffs zero() const { return coeffs(dim(), GiNaC::ex(0)); }
    /// Sum, difference and scalar multiple of coordinate vectors.
    static coeffs add(const coeffs& a, const coeffs& b);
    static coeffs sub(const coeffs& a, const coeffs& b);
    static coeffs scale(const GiNaC::ex& s, const coeffs& a);
    /// w^k, k >= 0, by repeated squaring.
    coeffs power(const coeffs& w, unsigned long k) const;
    /// p(w) for a polynomial p in X (Horner).
    coeffs evaluate_polynomial(const GiNaC::ex& p, const GiNaC::symbol& X, const coeffs& w) const;
    /// True when the basis is 1, w, w^2, ..., w^(dim-1) (the polynomial algebras' generator v):
    /// then a polynomial of degree < dim evaluated at w has its coefficients as coordinates,
    /// and evaluate_polynomial reads them off instead of running Horner's scheme.
    virtual bool is_power_basis_generator(const coeffs& w) const;
    /// Exact equality of coordinate vectors (each difference normalizes to 0).
    static bool equal(const coeffs& a, const coeffs& b);
    /// Checks that a vector has dim() entries; throws algebra_error otherwise.
    void check_size(const coeffs& a, const char* what) const;
    /// Largest n for which dense n x n exact matrices are built (canonical matrix,
    /// general determinant/charpoly/minpoly/inverse, power basis, ...).
    static constexpr std::size_t max_dense_dim = 1024;
    /// Throws size_error naming `what` and the limit when dim() > max_dense_dim.
    void check_dense(const char* what) const;

    /// Whether exact coordinates are allowed: false above a family's exact limit,
    /// where it computes in double precision only (algebra/double_path.h).
    virtual bool exact() const { return true; }

protected:
    algebra() = default;
    /// The largest order with exact coordinates (for the double path's messages).
    virtual unsigned exact_limit() const { return 0; }
    /// Whether operands with these coordinates take the family's double path
    /// (double_path::takes); throws size_error for symbolic coordinates when !exact().
    bool takes_double_path(std::initializer_list<const coeffs*> operands, const char* what) const;
    /// Throws size_error naming the exact limit when !exact().
    void require_exact(const char* what) const;
    /// exp(w t) on the double path, computed by `double_exp` from the doubles of w and t, when
    /// t is a real number and w and t take that path; nullopt for the exact path. A symbolic t
    /// in a float-only algebra (!exact()) is refused by name (size_error).
    std::optional<coeffs> exp_on_double_path(
        const coeffs& w, const GiNaC::ex& t,
        const std::function<std::vector<double>(const std::vector<double>&, double)>& double_exp) const;
};

/// The ranks of a zero divisor's vanishing idempotent components as text, "0, 3, 5" (the
/// messages of zero_divisor_error).
std::string rank_list(const std::vector<std::size_t>& ranks);

}  // namespace symrep
