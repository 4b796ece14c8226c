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

#include "algebra/cplx.h"
#include "algebra/scalar.h"
#include "algebra/walsh_hadamard.h"

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

/// (III.1.38-41) idempotent components c_p = a_p + i b_p, p = 0..2^n-1, of the
/// element with natural-basis coordinates w (size 2^{n+1}).
template <class T>
std::vector<typename multicomplex_complex<T>::type> multicomplex_components(const std::vector<T>& w,
                                                                            unsigned n) {
    const std::size_t N = std::size_t{1} << n;
    std::vector<typename multicomplex_complex<T>::type> x;
    x.reserve(N);
    for (std::size_t q = 0; q < N; ++q)
        x.push_back(multicomplex_rotate<T>(w[q], w[N + q], static_cast<unsigned>(std::popcount(q))));
    fwht(x);
    return x;
}

/// (III.1.42-43, corrected) natural-basis coordinates of sum_p (a_p + i0 b_p) e_p.
template <class T>
std::vector<T> multicomplex_from_components(std::vector<typename multicomplex_complex<T>::type> c,
                                            unsigned n) {
    using CT = multicomplex_complex<T>;
    const std::size_t N = std::size_t{1} << n;
    fwht(c);
    const T scale = inv_pow2<T>(n);
    std::vector<T> w(2 * N);
    for (std::size_t q = 0; q < N; ++q) {
        const unsigned m = (4u - (static_cast<unsigned>(std::popcount(q)) & 3u)) & 3u;
        const auto y = multicomplex_rotate<T>(CT::re(c[q]), CT::im(c[q]), m);
        w[q] = scale * CT::re(y);
        w[N + q] = scale * CT::im(y);
    }
    return w;
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
    using std::exp;
    using std::sin;
    const T e = exp(a * t);
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
    using std::log;
    return multicomplex_complex<T>::make(log(multicomplex_modulus(a, b)), multicomplex_argument(a, b));
}

}  // namespace symrep
