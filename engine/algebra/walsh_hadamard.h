// symrep/algebra/walsh_hadamard.h -- the fast Walsh-Hadamard transform.
//
// fwht(a) replaces a (length 2^n) by H a, where H = [[1,1],[1,-1]]^{(x)n} is the
// Hadamard matrix (III.3.19): (H a)_p = sum_q (-1)^{<p,q>} a_q with <p,q> the
// number of common one bits (III.3.16). H^{-1} = 2^{-n} H (III.3.20). The cost
// is n 2^{n-1} additions and as many subtractions: O(n 2^n) instead of O(4^n).
// Works for any T with + and - (double, GiNaC::ex, cplx<T>).
//
// This is the transform behind every idempotent basis in symrep: the Walsh
// algebra (III.3.25), its complex extension (III.3.62-63) and the multicomplex
// algebra (III.1.40-43, after the Gray/sign reindexing described there).
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace symrep {

/// True when k is a power of two (k >= 1).
constexpr bool is_pow2(std::size_t k) { return k != 0 && (k & (k - 1)) == 0; }

/// In-place unnormalized transform a <- H a. Precondition: a.size() is a power of two.
template <class T>
void fwht(std::vector<T>& a) {
    const std::size_t N = a.size();
    for (std::size_t h = 1; h < N; h <<= 1) {
        for (std::size_t i = 0; i < N; i += 2 * h) {
            for (std::size_t j = i; j < i + h; ++j) {
                T x = a[j];
                T y = a[j + h];
                a[j] = x + y;
                a[j + h] = x - y;
            }
        }
    }
}

/// The same transform for complex doubles, on the underlying array of doubles
/// (std::complex<double> is laid out as two doubles, [complex.numbers]): the
/// butterflies act on real and imaginary parts alike, and the inner loop over
/// contiguous doubles vectorizes. Two stages are fused per pass (radix 4), which
/// halves the passes over memory.
inline void fwht(std::vector<std::complex<double>>& a) {
    const std::size_t N = a.size();
    double* d = reinterpret_cast<double*>(a.data());
    std::size_t h = 1;
    for (; 2 * h < N; h <<= 2) {  // stages h and 2h at once
        const std::size_t s = 2 * h;  // stride of stage h in doubles
        for (std::size_t i = 0; i < N; i += 4 * h) {
            double* p = d + 2 * i;
            for (std::size_t j = 0; j < s; ++j) {
                const double x0 = p[j], x1 = p[j + s], x2 = p[j + 2 * s], x3 = p[j + 3 * s];
                const double y0 = x0 + x1, y1 = x0 - x1, y2 = x2 + x3, y3 = x2 - x3;
                p[j] = y0 + y2;
                p[j + s] = y1 + y3;
                p[j + 2 * s] = y0 - y2;
                p[j + 3 * s] = y1 - y3;
            }
        }
    }
    if (h < N) {  // one radix-2 stage left when log2 N is odd
        const std::size_t s = 2 * h;
        for (std::size_t i = 0; i < N; i += 2 * h) {
            double* p = d + 2 * i;
            for (std::size_t j = 0; j < s; ++j) {
                const double x = p[j], y = p[j + s];
                p[j] = x + y;
                p[j + s] = x - y;
            }
        }
    }
}

}  // namespace symrep
