// symrep/algebra/multicomplex_transform.h -- the change of basis of (x)C^{n+1}
// from the natural basis {e_q} to the idempotent basis {e_p, i0 e_p}
// (III.1.36-43), written once as templates over the real scalar T (GiNaC::ex
// for the exact path, double for the fast path).
//
// Derivation (checked against (III.1.20), (III.1.40-43) by the tests): the map
// w -> c_p, where w e_p = (a_p + i0 b_p) e_p, is the algebra homomorphism onto C
// with i0 -> i and i_k -> (-1)^{p_k} i (III.1.20). Writing q = (q_0, q') with q'
// the n low bits, e_q -> i^{q_0} i^{|q'|} (-1)^{<p,q'>}, so
//     c_p = sum_{q'} (-1)^{<p,q'>} x_{q'},   x_{q'} = i^{|q'|} (w_{q'} + i w_{2^n+q'}),
// i.e. ONE fast Walsh-Hadamard transform of a complex vector of length 2^n:
// O(n 2^n) instead of the O(4^n) matrix products of (III.1.40-41). Back:
// x = 2^{-n} H c (III.1.30), then w_{q'} + i w_{2^n+q'} = i^{-|q'|} x_{q'}.
#pragma once

#include <bit>
#include <complex>
#include <cstddef>
#include <vector>

#include "symrep/scalar/cplx.h"
#include "symrep/scalar/scalar.h"
#include "symrep/algebra/walsh_hadamard.h"

namespace symrep {

/// The complex type used for idempotent components: cplx<T> in general (exact
/// pairs), std::complex<double> on the double path.
template <class T>
struct multicomplex_complex {
    using type = cplx<T>;
    static type make(T r, T i) { return {std::move(r), std::move(i)}; }
    static const T& re(const type& c) { return c.re; }
    static const T& im(const type& c) { return c.im; }
};
template <>
struct multicomplex_complex<double> {
    using type = std::complex<double>;
    static type make(double r, double i) { return {r, i}; }
    static double re(const type& c) { return c.real(); }
    static double im(const type& c) { return c.imag(); }
};

/// (r + i s) * i^m.
template <class T>
typename multicomplex_complex<T>::type multicomplex_rotate(const T& r, const T& s, unsigned m) {
    using CT = multicomplex_complex<T>;
    switch (m & 3u) {
        case 0: return CT::make(r, s);
        case 1: return CT::make(-s, r);
        case 2: return CT::make(-r, -s);
        default: return CT::make(s, -r);
    }
}

/// The double path without branches: m = popcount(q) mod 4 is effectively random
/// in q, so a switch mispredicts about half of the time, which cost more than the
/// transform itself. (r + i s) i^m = (A r + B s) + i (A s - B r).
template <>
inline std::complex<double> multicomplex_rotate<double>(const double& r, const double& s, unsigned m) {
    static constexpr double A[4] = {1.0, 0.0, -1.0, 0.0};
    static constexpr double B[4] = {0.0, -1.0, 0.0, 1.0};
    const double a = A[m & 3u], b = B[m & 3u];
    return {a * r + b * s, a * s - b * r};
}

/// (III.1.38-41) idempotent components c_p = a_p + i b_p, p = 0..2^n-1, of the
/// element with natural-basis coordinates w (size 2^{n+1}), written into x (its
/// capacity is reused: the double path keeps scratch buffers between calls).
template <class T>
void multicomplex_components_into(const std::vector<T>& w, unsigned n,
                                  std::vector<typename multicomplex_complex<T>::type>& x) {
    const std::size_t N = std::size_t{1} << n;
    x.resize(N);
    // m = popcount(q) mod 4, kept incrementally: popcount(q) = popcount(q-1) + 1 - ctz(q).
    // (std::popcount is a library call on baseline x86-64 and dominated the double path.)
    unsigned m = 0;
    for (std::size_t q = 0; q < N; ++q) {
        if (q) m += 1u - static_cast<unsigned>(std::countr_zero(q));
        x[q] = multicomplex_rotate<T>(w[q], w[N + q], m);
    }
    fwht(x);
}

template <class T>
std::vector<typename multicomplex_complex<T>::type> multicomplex_components(const std::vector<T>& w,
                                                                            unsigned n) {
    std::vector<typename multicomplex_complex<T>::type> x;
    multicomplex_components_into(w, n, x);
    return x;
}

/// (III.1.42-43, corrected) natural-basis coordinates of sum_p (a_p + i0 b_p) e_p.
/// Transforms c in place.
template <class T>
std::vector<T> multicomplex_from_components_inplace(std::vector<typename multicomplex_complex<T>::type>& c,
                                                    unsigned n) {
    using CT = multicomplex_complex<T>;
    const std::size_t N = std::size_t{1} << n;
    fwht(c);
    const T scale = inv_pow2<T>(n);
    std::vector<T> w(2 * N);
    unsigned pc = 0;  // popcount(q) mod 4, as in multicomplex_components
    for (std::size_t q = 0; q < N; ++q) {
        if (q) pc += 1u - static_cast<unsigned>(std::countr_zero(q));
        const unsigned m = (4u - (pc & 3u)) & 3u;
        const auto y = multicomplex_rotate<T>(CT::re(c[q]), CT::im(c[q]), m);
        w[q] = scale * CT::re(y);
        w[N + q] = scale * CT::im(y);
    }
    return w;
}

template <class T>
std::vector<T> multicomplex_from_components(std::vector<typename multicomplex_complex<T>::type> c,
                                            unsigned n) {
    return multicomplex_from_components_inplace<T>(c, n);
}

// --- the functions of one component xi = a + i b (III.1.45-58) ------------------

/// (III.1.57) 1/xi = (a - i b)/(a^2 + b^2); the caller excludes xi = 0.
template <class T>
typename multicomplex_complex<T>::type multicomplex_component_inverse(const T& a, const T& b) {
    const T d = a * a + b * b;
    return multicomplex_complex<T>::make(a / d, -b / d);
}

/// (III.1.45-52) exp(xi t) = e^{a t} (cos b t + i sin b t).
template <class T>
typename multicomplex_complex<T>::type multicomplex_component_exp(const T& a, const T& b, const T& t) {
    using std::cos;
    using std::sin;
    const T e = exp_scalar(a * t);
    return multicomplex_complex<T>::make(e * cos(b * t), e * sin(b * t));
}

/// (III.1.49) modulus r = sqrt(a^2 + b^2).
inline GiNaC::ex multicomplex_modulus(const GiNaC::ex& a, const GiNaC::ex& b) {
    return GiNaC::sqrt(tidy(a * a + b * b));
}
inline double multicomplex_modulus(double a, double b) { return std::hypot(a, b); }

/// (III.1.50) principal argument atan2(b, a) in (-pi, pi]; 0 for xi = 0.
inline GiNaC::ex multicomplex_argument(const GiNaC::ex& a, const GiNaC::ex& b) {
    if (is_zero_scalar(a) && is_zero_scalar(b)) return 0;
    return GiNaC::atan2(b, a);
}
inline double multicomplex_argument(double a, double b) { return std::atan2(b, a); }

/// (III.1.53) principal logarithm log r + i atan2(b, a); the caller excludes xi = 0.
template <class T>
typename multicomplex_complex<T>::type multicomplex_component_log(const T& a, const T& b) {
    return multicomplex_complex<T>::make(log_modulus(a, b), multicomplex_argument(a, b));
}

}  // namespace symrep
