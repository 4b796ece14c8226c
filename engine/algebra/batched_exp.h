// symrep/algebra/batched_exp.h -- the componentwise exponential of the double paths, batched.
//
// exp(w t) of an element with idempotent components z_p = a_p + i0 b_p is the
// element with components e^(a_p t) (cos b_p t + i0 sin b_p t) (III.1.45-52).
// After the fast Walsh-Hadamard transform this loop is the rest of the cost, and
// one call of exp, sin and cos per component costs more than the transforms
// (issue 15.5). exp_components() runs it in blocks through glibc's vector math
// library (libmvec: 8, 4 or 2 doubles per call, chosen once for the CPU at hand:
// AVX-512, AVX2, else SSE), and through std::exp and std::sin/cos where libmvec
// is absent (not glibc on x86-64). libmvec's functions are within 4 ulp of the
// exact values (glibc's manual); the transforms around them cost n ulp already.
// Special values follow IEEE as the scalar functions do (inf and nan in, inf and
// nan out); a result is the same bytes on one machine, and may differ in the
// last bits between CPUs of different vector width, as libm's own do.
#pragma once

#include <complex>
#include <cstddef>

namespace symrep {

/// z[p] <- e^(re z[p] t) (cos(im z[p] t) + i sin(im z[p] t)) for p < count.
void exp_components(std::complex<double>* z, std::size_t count, double t);

/// The instruction set exp_components() uses here: "avx512", "avx2", "sse" (libmvec)
/// or "scalar" (libm, one call per value).
const char* exp_components_kernel();

}  // namespace symrep
