// symrep/scalar/cplx.h -- a complex number over any real scalar type.
//
// std::complex<T> is unspecified for T other than float/double/long double, and
// GiNaC's own complex numbers (with I) do not keep real and imaginary parts
// apart for symbolic coefficients. The idempotent components a_k + i0 b_k of
// the multicomplex algebra (III.1.38-39) and of W* (III.3.61) are therefore kept
// as explicit pairs (re, im) of exact or double scalars.
#pragma once

#include <utility>

namespace symrep {

template <class T>
struct cplx {
    T re{};
    T im{};

    cplx() = default;
    cplx(T r, T i) : re(std::move(r)), im(std::move(i)) {}

    friend cplx operator+(const cplx& a, const cplx& b) { return {a.re + b.re, a.im + b.im}; }
    friend cplx operator-(const cplx& a, const cplx& b) { return {a.re - b.re, a.im - b.im}; }
    friend cplx operator-(const cplx& a) { return {-a.re, -a.im}; }
    friend cplx operator*(const cplx& a, const cplx& b) {
        return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
    }
    friend cplx operator*(const T& s, const cplx& a) { return {s * a.re, s * a.im}; }
    cplx& operator+=(const cplx& b) { re = re + b.re; im = im + b.im; return *this; }
    cplx& operator-=(const cplx& b) { re = re - b.re; im = im - b.im; return *this; }
    /// Squared modulus a^2 + b^2.
    T norm2() const { return re * re + im * im; }
    cplx conj() const { return {re, -im}; }
};

}  // namespace symrep
