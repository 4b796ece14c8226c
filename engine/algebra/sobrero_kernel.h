// symrep/algebra/sobrero_kernel.h -- the arithmetic of the generalized Sobrero
// algebra S = C (x) P, P = R[eps]/(eps^{n+1}) (III.2), written once over the
// scalar type T (GiNaC::ex for the exact path, double for the fast path).
//
// An element is handled as its complex coefficient sequence (III.2.7)
//     w = sum_{k=0}^{n} xi_k eps^k,   xi_k = a_k + j b_k,
// stored as std::vector<cplx<T>> of length n+1. Every element splits as
//     w = xi_0 + N,   N = sum_{k>=1} xi_k eps^k nilpotent (N^{n+1} = 0, III.2.15),
// and the functions of w are the finite nilpotent series around xi_0:
//     w^{-1}   = xi_0^{-1} sum_k (-N/xi_0)^k
//     exp(w t) = e^{xi_0 t} sum_k N^k t^k / k!
//     log w    = log xi_0 + sum_{k>=1} (-1)^{k+1} (N/xi_0)^k / k
// each of which stops at k = n because eps^{n+1} = 0 (III.2.3).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "symrep/scalar/cplx.h"
#include "symrep/scalar/scalar.h"

namespace symrep::sobrero_math {

template <class T>
using seq = std::vector<cplx<T>>;

template <class T>
cplx<T> tidy_c(const cplx<T>& z) { return {tidy(z.re), tidy(z.im)}; }

// (III.2.4) with (III.2.3): truncated Cauchy product of the complex sequences,
// (xy)_k = sum_{l=0}^{k} x_l y_{k-l}, k = 0..n (the row structure of (III.2.8-9)).
template <class T>
seq<T> multiply(const seq<T>& x, const seq<T>& y) {
    const std::size_t m = x.size();
    seq<T> z(m, cplx<T>(from_int<T>(0), from_int<T>(0)));
    for (std::size_t i = 0; i < m; ++i) {
        if (is_zero_scalar(x[i].re) && is_zero_scalar(x[i].im)) continue;
        for (std::size_t l = 0; i + l < m; ++l) z[i + l] += x[i] * y[l];
    }
    for (auto& c : z) c = tidy_c(c);
    return z;
}

/// Complex reciprocal (a - j b)/(a^2 + b^2); the caller guarantees a^2 + b^2 != 0.
template <class T>
cplx<T> reciprocal(const cplx<T>& z) {
    const T d = z.norm2();
    return tidy_c(cplx<T>(z.re / d, -z.im / d));
}

/// The nilpotent part N = w - xi_0 (III.2.14 form).
template <class T>
seq<T> nilpotent_part(const seq<T>& x) {
    seq<T> N = x;
    N[0] = cplx<T>(from_int<T>(0), from_int<T>(0));
    return N;
}

/// s * x for a complex scalar s.
template <class T>
seq<T> scale(const cplx<T>& s, const seq<T>& x) {
    seq<T> y(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) y[k] = tidy_c(s * x[k]);
    return y;
}

/// sum_{k=0}^{n} c_k M^k for a nilpotent M (M_0 = 0) and scalar coefficients c_k,
/// by Horner's scheme: n truncated products.
template <class T>
seq<T> nilpotent_series(const seq<T>& M, const std::vector<cplx<T>>& c) {
    const std::size_t m = M.size();
    seq<T> acc(m, cplx<T>(from_int<T>(0), from_int<T>(0)));
    for (std::size_t k = c.size(); k-- > 0;) {
        acc = multiply(acc, M);
        acc[0] = tidy_c(acc[0] + c[k]);
    }
    return acc;
}

// Inverse of a non-zero-divisor (xi_0 != 0, III.2.13): xi_0^{-1} sum_k (-N/xi_0)^k.
template <class T>
seq<T> inverse(const seq<T>& x) {
    const std::size_t m = x.size();
    const cplx<T> r = reciprocal(x[0]);
    const seq<T> M = scale(cplx<T>(-r.re, -r.im), nilpotent_part(x));  // -N/xi_0
    std::vector<cplx<T>> c(m, cplx<T>(from_int<T>(1), from_int<T>(0)));
    return scale(r, nilpotent_series(M, c));
}

// exp(w t) = e^{xi_0 t} sum_{k=0}^{n} N^k t^k / k!  (e^{N t} is a finite sum, III.2.15).
template <class T>
seq<T> exp(const seq<T>& x, const T& t) {
    using std::cos;
    using std::exp;
    using std::sin;
    const std::size_t m = x.size();
    std::vector<cplx<T>> c(m);
    T coef = from_int<T>(1);
    for (std::size_t k = 0; k < m; ++k) {
        if (k > 0) coef = tidy(coef * t / from_int<T>(long(k)));
        c[k] = cplx<T>(coef, from_int<T>(0));
    }
    const seq<T> s = nilpotent_series(nilpotent_part(x), c);
    const T ea = exp_scalar(x[0].re * t);
    const cplx<T> e0(tidy(ea * cos(x[0].im * t)), tidy(ea * sin(x[0].im * t)));
    return scale(e0, s);
}

/// Principal complex logarithm of xi_0 != 0: ln|xi_0| + j atan2(b_0, a_0).
template <class T>
cplx<T> log_scalar(const cplx<T>& z) {
    using std::atan2;
    return cplx<T>(tidy(log_modulus(z.re, z.im)), tidy(atan2(z.im, z.re)));
}

// log w = log xi_0 + sum_{k=1}^{n} (-1)^{k+1} (N/xi_0)^k / k, for xi_0 != 0.
template <class T>
seq<T> log(const seq<T>& x) {
    const std::size_t m = x.size();
    const seq<T> M = scale(reciprocal(x[0]), nilpotent_part(x));  // N/xi_0
    std::vector<cplx<T>> c(m, cplx<T>(from_int<T>(0), from_int<T>(0)));
    for (std::size_t k = 1; k < m; ++k)
        c[k] = cplx<T>(from_int<T>(k % 2 ? 1 : -1) / from_int<T>(long(k)), from_int<T>(0));
    seq<T> L = nilpotent_series(M, c);
    L[0] = tidy_c(L[0] + log_scalar(x[0]));
    return L;
}

/// Coordinates [a_0..a_n, b_0..b_n] -> sequence xi_k = a_k + j b_k.
template <class T>
seq<T> from_coords(const std::vector<T>& c) {
    const std::size_t m = c.size() / 2;
    seq<T> x(m);
    for (std::size_t k = 0; k < m; ++k) x[k] = cplx<T>(c[k], c[m + k]);
    return x;
}

/// Sequence -> coordinates [a_0..a_n, b_0..b_n].
template <class T>
std::vector<T> to_coords(const seq<T>& x) {
    const std::size_t m = x.size();
    std::vector<T> c(2 * m);
    for (std::size_t k = 0; k < m; ++k) {
        c[k] = x[k].re;
        c[m + k] = x[k].im;
    }
    return c;
}

}  // namespace symrep::sobrero_math
