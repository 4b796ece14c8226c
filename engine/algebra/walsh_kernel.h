// symrep/algebra/walsh_kernel.h -- the change of basis of the Walsh algebra W
// and of its complex extension W* (III.3.18-25, III.3.47-50, III.3.56-63),
// written once over the scalar type T (GiNaC::ex exact, double fast).
//
// In W every element is diagonal in the Hadamard idempotents e_p (III.3.24):
//     f = sum_q f_q w_q = sum_p a_p e_p,   a = H f   (III.3.25),   f = 2^{-n} H a (III.3.21-22),
// so products, inverses, exp and log act component by component; H is applied by
// the fast Walsh-Hadamard transform fwht() in O(n 2^n).
// In W* the components are complex, y_p = c_p + i0 d_p with c = H a, d = H b
// (III.3.62-63): the same transform on pairs cplx<T>.
#pragma once

#include <cstddef>
#include <vector>

#include "symrep/scalar/cplx.h"
#include "symrep/scalar/scalar.h"
#include "symrep/algebra/walsh_hadamard.h"

namespace symrep::walsh_math {

/// log2 of a power-of-two length.
inline unsigned log2_size(std::size_t N) {
    unsigned n = 0;
    while ((std::size_t(1) << n) < N) ++n;
    return n;
}

// (III.3.25) a_p = sum_q (-1)^{<p,q>} f_q, i.e. a = H f.
template <class T>
std::vector<T> components(std::vector<T> f) {
    fwht(f);
    for (auto& x : f) x = tidy(x);
    return f;
}

// (III.3.21-22) f = 2^{-n} H a.
template <class T>
std::vector<T> from_components(std::vector<T> a) {
    fwht(a);
    const T s = inv_pow2<T>(log2_size(a.size()));
    for (auto& x : a) x = tidy(s * x);
    return a;
}

// (III.3.62-63) y_p = c_p + i0 d_p with c = H a, d = H b; coordinates [a..., b...].
template <class T>
std::vector<cplx<T>> complex_components(const std::vector<T>& coords) {
    const std::size_t N = coords.size() / 2;
    std::vector<cplx<T>> y(N);
    for (std::size_t p = 0; p < N; ++p) y[p] = cplx<T>(coords[p], coords[N + p]);
    fwht(y);
    for (auto& z : y) z = cplx<T>(tidy(z.re), tidy(z.im));
    return y;
}

// (III.3.58) back from the basis B* to B: a = 2^{-n} H c, b = 2^{-n} H d.
template <class T>
std::vector<T> from_complex_components(std::vector<cplx<T>> y) {
    const std::size_t N = y.size();
    fwht(y);
    const T s = inv_pow2<T>(log2_size(N));
    std::vector<T> coords(2 * N);
    for (std::size_t p = 0; p < N; ++p) {
        coords[p] = tidy(s * y[p].re);
        coords[N + p] = tidy(s * y[p].im);
    }
    return coords;
}

/// <p,q> mod 2: parity of the common one bits (III.3.16).
inline int dyadic_sign(std::size_t p, std::size_t q) {
    return __builtin_parityll((unsigned long long)(p & q)) ? -1 : 1;
}

}  // namespace symrep::walsh_math
