// symrep/algebra/structure_algebra.cpp -- algebras from structure constants (II.1.2).
#include "symrep/algebra/structure_algebra.h"

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "symrep/algebra/exact_linear.h"
#include "symrep/scalar/scalar.h"
#include "symrep/core/error.h"

namespace symrep {

using GiNaC::ex;

namespace {

std::string show(const coeffs& c) {
    std::ostringstream os;
    os << "[";
    for (std::size_t k = 0; k < c.size(); ++k) os << (k ? ", " : "") << c[k];
    os << "]";
    return os.str();
}

// FNV-1a over the printed table: deterministic for a given table.
std::string table_hash(const std::vector<std::vector<coeffs>>& g) {
    std::ostringstream os;
    for (const auto& row : g)
        for (const auto& c : row) {
            for (const auto& x : c) os << x << ',';
            os << ';';
        }
    std::uint64_t h = 1469598103934665603ULL;
    for (unsigned char ch : os.str()) {
        h ^= ch;
        h *= 1099511628211ULL;
    }
    char buf[17];
    std::snprintf(buf, sizeof buf, "%08llx", static_cast<unsigned long long>(h & 0xffffffffULL));
    return buf;
}

// eps_i * v in the table g (v a coordinate vector).
coeffs times_basis(const std::vector<std::vector<coeffs>>& g, std::size_t i, const coeffs& v) {
    const std::size_t n = g.size();
    coeffs r(n, ex(0));
    for (std::size_t l = 0; l < n; ++l) {
        if (v[l].is_zero()) continue;
        for (std::size_t k = 0; k < n; ++k) r[k] += v[l] * g[i][l][k];
    }
    for (auto& x : r) x = tidy(x);
    return r;
}

}  // namespace

structure_algebra::structure_algebra(std::vector<std::vector<coeffs>> gamma,
                                     std::vector<std::string> names, std::string nm)
    : n_(gamma.size()), gamma_(std::move(gamma)), names_(std::move(names)), name_(std::move(nm)) {
    const std::size_t n = n_;
    if (n == 0) throw algebra_error("a structure-constant table needs at least one basis element");
    for (std::size_t i = 0; i < n; ++i) {
        if (gamma_[i].size() != n)
            throw algebra_error("structure constants: row " + std::to_string(i) + " has " +
                                std::to_string(gamma_[i].size()) + " products, expected " +
                                std::to_string(n) + " (one per basis element)");
        for (std::size_t j = 0; j < n; ++j) {
            if (gamma_[i][j].size() != n)
                throw algebra_error("structure constants: the product e" + std::to_string(i) +
                                    "*e" + std::to_string(j) + " has " +
                                    std::to_string(gamma_[i][j].size()) +
                                    " coordinates, expected " + std::to_string(n));
            for (auto& x : gamma_[i][j]) x = tidy(x);
        }
    }
    if (!names_.empty() && names_.size() != n)
        throw algebra_error("structure constants: " + std::to_string(names_.size()) +
                            " basis names given for " + std::to_string(n) + " basis elements");
    // commutativity: gamma_ij = gamma_ji
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (!equal(gamma_[i][j], gamma_[j][i]))
                throw algebra_error("the table is not commutative: for the basis pair (" +
                                    std::to_string(i) + "," + std::to_string(j) + ") e" +
                                    std::to_string(i) + "*e" + std::to_string(j) + " = " +
                                    show(gamma_[i][j]) + " but e" + std::to_string(j) + "*e" +
                                    std::to_string(i) + " = " + show(gamma_[j][i]));
    // associativity: (e_i e_j) e_k = e_i (e_j e_k); with commutativity both
    // sides are products of basis elements with the table rows.
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t k = 0; k < n; ++k) {
                const coeffs lhs = times_basis(gamma_, k, gamma_[i][j]);
                const coeffs rhs = times_basis(gamma_, i, gamma_[j][k]);
                if (!equal(lhs, rhs))
                    throw algebra_error("the table is not associative: for the basis triple (" +
                                        std::to_string(i) + "," + std::to_string(j) + "," +
                                        std::to_string(k) + ") (e" + std::to_string(i) + "*e" +
                                        std::to_string(j) + ")*e" + std::to_string(k) + " = " +
                                        show(lhs) + " but e" + std::to_string(i) + "*(e" +
                                        std::to_string(j) + "*e" + std::to_string(k) + ") = " +
                                        show(rhs));
            }
    // unit: sum_i u_i gamma_ijk = delta_jk for all j, k (n^2 equations, n unknowns)
    std::vector<std::vector<ex>> A;
    std::vector<ex> b;
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t k = 0; k < n; ++k) {
            std::vector<ex> rowv(n);
            for (std::size_t i = 0; i < n; ++i) rowv[i] = gamma_[i][j][k];
            A.push_back(std::move(rowv));
            b.push_back(ex(j == k ? 1 : 0));
        }
    auto u = solve_linear(std::move(A), std::move(b));
    if (!u)
        throw algebra_error("the table has no unit element: no u with u*e_j = e_j for every "
                            "basis element e_j (the linear system is inconsistent)");
    unit_ = std::move(*u);
    if (name_.empty()) name_ = "algebra(" + std::to_string(n) + ", #" + table_hash(gamma_) + ")";
}

std::shared_ptr<const structure_algebra> structure_algebra::make(
    std::vector<std::vector<coeffs>> gamma, std::vector<std::string> names, std::string name) {
    return std::make_shared<const structure_algebra>(std::move(gamma), std::move(names),
                                                     std::move(name));
}

std::shared_ptr<const structure_algebra> structure_algebra::from(const algebra& A,
                                                                 std::string name) {
    const std::size_t n = A.dim();
    std::vector<std::vector<coeffs>> g(n, std::vector<coeffs>(n));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) g[i][j] = A.basis_product(i, j);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < n; ++k) names.push_back(A.basis_name(k));
    return make(std::move(g), std::move(names), std::move(name));
}

std::string structure_algebra::basis_name(std::size_t k) const {
    return names_.empty() ? algebra::basis_name(k) : names_.at(k);
}

// (II.1.2) c_k = sum_ij a_i b_j gamma_ijk.
coeffs structure_algebra::multiply(const coeffs& a, const coeffs& b) const {
    check_size(a, "product");
    check_size(b, "product");
    coeffs c(n_, ex(0));
    for (std::size_t i = 0; i < n_; ++i) {
        if (a[i].is_zero()) continue;
        for (std::size_t j = 0; j < n_; ++j) {
            if (b[j].is_zero()) continue;
            const ex ab = a[i] * b[j];
            const coeffs& g = gamma_[i][j];
            for (std::size_t k = 0; k < n_; ++k)
                if (!g[k].is_zero()) c[k] += ab * g[k];
        }
    }
    for (auto& x : c) x = tidy(x);
    return c;
}

coeffs structure_algebra::basis_product(std::size_t i, std::size_t j) const {
    if (i >= n_ || j >= n_)
        throw algebra_error(name_ + " has basis elements 0.." + std::to_string(n_ - 1) +
                            "; there is no product e" + std::to_string(i) + "*e" + std::to_string(j));
    return gamma_[i][j];
}

}  // namespace symrep
