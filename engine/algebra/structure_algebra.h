// symrep/algebra/structure_algebra.h -- an algebra A_n given by its structure
// constants gamma_ijk (thesis II.1.2): eps_i eps_j = sum_k gamma_ijk eps_k.
//
// The table is validated at construction with exact GiNaC arithmetic: it must be
// square (n x n entries of n coordinates each), commutative (gamma_ij = gamma_ji,
// the failing basis pair is named), associative ((eps_i eps_j) eps_k =
// eps_i (eps_j eps_k), the failing triple is named) and unital: the identity e
// is found by solving e eps_j = eps_j for all j (it need not be eps_0). With
// symbolic constants the checks hold identically in the symbols.
//
// Every general method (canonical matrix, charpoly, minpoly, inverse, exp, log)
// comes from algebra_general.cpp / functions.cpp; structure_algebra::from(A)
// rebuilds any algebra from its basis_product so that family fast paths can be
// compared with the general method.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "symrep/algebra/algebra.h"

namespace symrep {

class structure_algebra : public algebra {
public:
    /// gamma[i][j] = coordinates of eps_i eps_j (II.1.2). `names`: empty or one
    /// printable name per basis element; `name`: empty for the default
    /// "algebra(<n>, #<hash>)". Throws algebra_error on an invalid table.
    static std::shared_ptr<const structure_algebra> make(std::vector<std::vector<coeffs>> gamma,
                                                         std::vector<std::string> names = {},
                                                         std::string name = {});
    /// The structure-constant algebra with the same table (and basis names) as A.
    static std::shared_ptr<const structure_algebra> from(const algebra& A, std::string name = {});

    std::string name() const override { return name_; }
    std::size_t dim() const override { return n_; }
    std::string basis_name(std::size_t k) const override;
    /// (II.1.2) c_k = sum_ij a_i b_j gamma_ijk.
    coeffs multiply(const coeffs& a, const coeffs& b) const override;
    coeffs unit() const override { return unit_; }
    coeffs basis_product(std::size_t i, std::size_t j) const override;

    /// The table gamma[i][j][k] = gamma_ijk.
    const std::vector<std::vector<coeffs>>& table() const { return gamma_; }

    structure_algebra(std::vector<std::vector<coeffs>> gamma, std::vector<std::string> names,
                      std::string name);  // use make()

private:
    std::size_t n_;
    std::vector<std::vector<coeffs>> gamma_;
    std::vector<std::string> names_;
    std::string name_;
    coeffs unit_;
};

}  // namespace symrep
