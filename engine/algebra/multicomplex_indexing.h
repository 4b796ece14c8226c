// symrep/algebra/multicomplex_indexing.h -- the index maps of the multicomplex
// algebra (x)C^{n+1} (thesis III.1.1-2), shared by the exact and double paths.
//
// Natural binary basis (III.1.4): e_p = i0^{p_0} i1^{p_1} ... in^{p_n}, with
// p = (p_0 p_1 ... p_n)_2 and p_0 the MOST significant bit. Hence digit p_k sits
// at bit position n-k (from the least significant bit), i_0 = e_{2^n} and
// i_k = e_{2^{n-k}} (III.1.4, index as corrected in FORMULAS.md).
//
// The idempotents e_p of (III.1.15) are indexed by p = (p_1 ... p_n)_2 < 2^n;
// their digit p_k (k >= 1) sits at the same bit position n-k as the digit of
// i_k in the natural basis, so "p & q" below always means <p,q> of (III.1.7).
//
// Gray coding with bit reversal (III.1.10-12): g(k) = (kb_0 kb_1 ... kb_n)_2 with
// kb_0 = k_n and kb_p = k_{n-p} xor k_{n-p+1}; equivalently g(k) = gray(rev(k))
// where rev reverses the n+1 bits and gray(x) = x xor (x >> 1).
#pragma once

#include <bit>
#include <cstddef>

namespace symrep {

/// <p,q> = number of common one bits (III.1.7, III.1.64).
constexpr unsigned multicomplex_dot(std::size_t p, std::size_t q) {
    return static_cast<unsigned>(std::popcount(p & q));
}

/// (III.1.7) sign of e_p e_q = (-1)^{<p,q>} e_{p xor q}.
constexpr int multicomplex_product_sign(std::size_t p, std::size_t q) {
    return (multicomplex_dot(p, q) & 1u) ? -1 : 1;
}

/// (III.1.4, corrected) index of the imaginary unit i_k in the natural basis: 2^{n-k}.
constexpr std::size_t multicomplex_imag_unit_index(unsigned n, unsigned k) {
    return std::size_t{1} << (n - k);
}

/// Reversal of the lowest `bits` bits of k.
constexpr std::size_t multicomplex_bit_reverse(std::size_t k, unsigned bits) {
    std::size_t r = 0;
    for (unsigned b = 0; b < bits; ++b) r |= ((k >> b) & 1u) << (bits - 1 - b);
    return r;
}

/// (III.1.11-12) bit-reversed Gray code g(k) of k in {0..2^{n+1}-1}.
constexpr std::size_t multicomplex_gray(unsigned n, std::size_t k) {
    const std::size_t r = multicomplex_bit_reverse(k, n + 1);
    return r ^ (r >> 1);
}

/// (III.1.24) sigma(k) = (-1)^{floor(|g(k)|/2)}, |.| the number of one bits of
/// the Gray digits of k; by (III.1.23) i0^{|g(k)|} = sigma(k) i0^{|g(k)| mod 2}.
constexpr int multicomplex_sigma(unsigned n, std::size_t k) {
    return ((std::popcount(multicomplex_gray(n, k)) / 2) & 1) ? -1 : 1;
}

/// (III.1.29) entry h_{p,k} = (-1)^{<p, g(k)>} of the Walsh matrix H_w of order 2^n
/// (p, k < 2^n, p in natural binary, k in bit-reversed Gray digits). H_w is
/// symmetric (it is the sequency-ordered Walsh matrix), so (III.1.30) holds.
constexpr int multicomplex_walsh(unsigned n, std::size_t p, std::size_t k) {
    return (multicomplex_dot(p, multicomplex_gray(n, k)) & 1u) ? -1 : 1;
}

}  // namespace symrep
