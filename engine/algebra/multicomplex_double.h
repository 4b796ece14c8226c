// symrep/algebra/multicomplex_double.h -- the multicomplex algebra (x)C^{n+1}
// in double precision: the fast numeric path (thesis III.1).
//
// Same basis and conventions as multicomplex.h (natural binary basis, p_0 the
// most significant bit, i_k = e_{2^{n-k}}); an element is a std::vector<double>
// of 2^{n+1} coordinates, its idempotent components (III.1.39) a
// std::vector<std::complex<double>> of 2^n entries. The change of basis is the
// same template code as the exact path (multicomplex_transform.h): one fast
// Walsh-Hadamard transform, O(n 2^n). multiply_structure is the general
// structure-constant product (III.1.7) from a precomputed sparse table, O(4^n),
// kept for comparison and benchmarks.
//
// Size: n is limited by this machine's physical memory (max_order()): an
// operation holds two operands, the result and two component arrays, about
// 5 * 2^{n+4} bytes, and that must fit in half of the physical memory.
// multiply_structure's table has 4^{n+1} entries of 4 bytes and is limited to
// n <= structure_max_order = 12 (256 MiB).
#pragma once

#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace symrep {

class multicomplex_d {
public:
    using vector = std::vector<double>;
    using components = std::vector<std::complex<double>>;

    /// Largest n for multiply_structure (its table has 4^{n+1} entries).
    static constexpr unsigned structure_max_order = 12;
    /// Default relative tolerance of the zero-divisor test: a component c_p counts
    /// as zero when |c_p| <= rel_tol * max_q |c_q|.
    static constexpr double default_rel_tol = 1e-12;

    /// Largest n whose working set (5 * 2^{n+4} bytes) fits in half of the
    /// physical memory of this machine (sysconf), capped at 40.
    static unsigned max_order();

    /// (x)C^{n+1}; throws size_error (naming max_order()) when n is too large.
    explicit multicomplex_d(unsigned n);

    unsigned order() const { return n_; }
    /// 2^{n+1}.
    std::size_t dim() const { return std::size_t{2} << n_; }
    /// 2^n.
    std::size_t half_dim() const { return std::size_t{1} << n_; }

    /// The identity e_0.
    vector unit() const;
    /// i_k = e_{2^{n-k}} (III.1.4, corrected).
    vector imag_unit(unsigned k) const;

    /// (III.1.39-41) c_p = a_p + i b_p, by one FWHT.
    components idempotent_components(const vector& w) const;
    /// (III.1.42-43, corrected) inverse of idempotent_components.
    vector from_idempotent_components(const components& c) const;

    /// Product through the idempotent components (III.1.39, III.1.16), O(n 2^n).
    vector multiply(const vector& a, const vector& b) const;
    /// (III.1.7) structure-constant product from the precomputed table, O(4^n).
    vector multiply_structure(const vector& a, const vector& b) const;
    /// (III.1.57); zero_divisor_error naming the ranks for a zero divisor.
    vector inverse(const vector& w, double rel_tol = default_rel_tol) const;
    /// (III.1.45-52) exp(w t).
    vector exp(const vector& w, double t = 1.0) const;
    /// (III.1.53) principal logarithm (atan2 in (-pi, pi]); zero_divisor_error
    /// naming the ranks for a zero divisor.
    vector log(const vector& w, double rel_tol = default_rel_tol) const;
    /// (III.1.55) the ranks p with |c_p| <= rel_tol * max_q |c_q| (all ranks for w = 0).
    std::vector<std::size_t> zero_divisor_ranks(const vector& w, double rel_tol = default_rel_tol) const;

private:
    void check_size(const vector& a, const char* what) const;
    const std::vector<std::uint32_t>& structure_table() const;
    struct table_cache;
    unsigned n_;
    std::shared_ptr<table_cache> cache_;
};

}  // namespace symrep
