// symrep/signals/product.h -- products of signals on the tensor product of their
// algebras (thesis II.1-II.2 applied to f g; issue 16.1).
//
// If f = lambda_A(w_A exp(d_A t)) on (A, d_A) and g = lambda_B(w_B exp(d_B t)) on
// (B, d_B), then on A (x) B with d = d_A (x) 1 + 1 (x) d_B (exp(d t) = exp(d_A t) (x)
// exp(d_B t), the two summands commuting) and lambda = lambda_A (x) lambda_B,
//     lambda((w_A (x) w_B) exp(d t)) = f(t) g(t):
// the product of signals is represented by the tensor product of their elements, and
// differentiation is still multiplication by d (Leibniz's rule). d need not generate
// A (x) B (cos t cos t: the exponent 0 twice), so the map is onto the products' span
// without being one-to-one on all of A (x) B; signal() needs only lambda.
#pragma once

#include <memory>

#include "symrep/algebra/structure_algebra.h"
#include "symrep/signals/representation.h"

namespace symrep::signals {

/// A (x) B as a structure-constant algebra (basis e_i (x) f_j at index i dim B + j, names
/// "e_i (x) f_j"), remembering the functional of the product representation.
class tensor_algebra final : public structure_algebra {
public:
    /// The algebra of R_A (x) R_B with lambda = lambda_A (x) lambda_B.
    static std::shared_ptr<const tensor_algebra> make(const representation& RA, const representation& RB);
    const coeffs& functional() const { return lambda_; }
    const coeffs& operator_d() const { return d_; }
    tensor_algebra(std::vector<std::vector<coeffs>> gamma, std::vector<std::string> names, std::string name,
                   coeffs lambda, coeffs d)
        : structure_algebra(std::move(gamma), std::move(names), std::move(name)),
          lambda_(std::move(lambda)),
          d_(std::move(d)) {}  // use make()

private:
    coeffs lambda_, d_;
};

/// x (x) y: coordinates x_i y_j at index i dim B + j.
coeffs tensor(const coeffs& x, const coeffs& y);

/// The representation on A (x) B with d = d_A (x) 1 + 1 (x) d_B and lambda_A (x) lambda_B;
/// p is d's minimal polynomial (its degree may be below dim A dim B).
representation product_representation(const representation& RA, const representation& RB);

}  // namespace symrep::signals
