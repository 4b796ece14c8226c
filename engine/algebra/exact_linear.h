// symrep/algebra/exact_linear.h -- exact linear algebra on GiNaC coordinate
// vectors, used by the general methods of II.1-II.2 and III.4.
//
// Entries are GiNaC expressions (rationals, algebraic numbers, symbols,
// transcendental atoms). A pivot is accepted when it does not normalize to 0;
// with symbolic entries this is GiNaC's generic reading (a pivot a - 1 is taken
// as non-zero), and results hold for the generic values of the symbols.
//
//  - krylov_basis: incremental Gaussian elimination. Vectors are added one by
//    one; each is reduced against the stored echelon rows, and a vector that
//    reduces to 0 yields the linear relation expressing it through the earlier
//    ones. This is how the minimal polynomial (Cor. II.1.1) is found without
//    recomputing ranks of growing matrices.
//  - solve_linear: A x = b for a (possibly overdetermined) system, with the
//    right-hand side allowed to hold arbitrary expressions (functions of t);
//    returns nullopt when the system is inconsistent or A is rank deficient.
//  - solve_any: M x = y where M may be rank deficient (a zero divisor's
//    multiplication matrix): any solution, the free unknowns 0, by GiNaC's
//    Gaussian elimination. Not solve_linear with a flag: its pivots are GiNaC's
//    (a pivot is any entry that normalizes to non-zero, not one proved non-zero),
//    and the forms of the responses of signals/response.cpp are those pivots'.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <ginac/ginac.h>

#include "symrep/algebra/algebra.h"

namespace symrep {

/// Incremental echelon form of the vectors v_0, v_1, ... added so far.
class krylov_basis {
public:
    explicit krylov_basis(std::size_t length) : length_(length) {}
    /// Adds v as v_m (m = size()). If v is independent of v_0..v_{m-1}, stores it
    /// and returns nullopt; otherwise returns c_0..c_{m-1} with v = sum_i c_i v_i
    /// (v is then not stored).
    std::optional<std::vector<GiNaC::ex>> add(const coeffs& v);
    /// Number of independent vectors stored.
    std::size_t size() const { return rows_.size(); }

private:
    struct row {
        coeffs v;                      // reduced vector
        std::size_t pivot;             // first non-zero position of v
        std::vector<GiNaC::ex> comb;   // v = sum_i comb[i] v_i (original vectors)
    };
    std::size_t length_;
    std::vector<row> rows_;
};

/// Solves A x = b (A: rows x cols, rows >= cols) exactly. Returns nullopt when A
/// has rank < cols or the system is inconsistent.
std::optional<std::vector<GiNaC::ex>> solve_linear(std::vector<std::vector<GiNaC::ex>> A,
                                                   std::vector<GiNaC::ex> b);

/// A solution of M x = y (M rows x cols, rows >= cols, possibly rank deficient), the free
/// unknowns set to 0, each entry tidied; false when the system is inconsistent.
bool solve_any(const GiNaC::matrix& M, const std::vector<GiNaC::ex>& y, coeffs& x);

/// A basis of the null space {x : A x = 0} of A (rows x cols), exact
/// (reduced row echelon form; free variables set to 1 in turn).
std::vector<coeffs> null_space(std::vector<std::vector<GiNaC::ex>> A);

}  // namespace symrep
