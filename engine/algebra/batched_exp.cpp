// symrep/algebra/batched_exp.cpp -- see batched_exp.h.
#include "symrep/algebra/batched_exp.h"

#include <cmath>

#if defined(SYMREP_HAVE_LIBMVEC) && defined(__x86_64__) && defined(__GNUC__)
#define SYMREP_LIBMVEC_X86 1
#include <immintrin.h>
#endif

namespace symrep {

namespace {

// Values per block: the three arrays stay in L1 (3 * 256 * 8 bytes).
constexpr std::size_t block = 256;

using kernel = void (*)(const double* a, const double* b, double* e, double* c, double* s, std::size_t m);

void scalar_kernel(const double* a, const double* b, double* e, double* c, double* s, std::size_t m) {
    for (std::size_t k = 0; k < m; ++k) {
        e[k] = std::exp(a[k]);
        c[k] = std::cos(b[k]);
        s[k] = std::sin(b[k]);
    }
}

#ifdef SYMREP_LIBMVEC_X86
}  // namespace
// glibc's vector ABI (x86_64 libmvec): b = SSE (2 doubles), d = AVX2 (4), e = AVX-512 (8).
extern "C" {
__m128d _ZGVbN2v_exp(__m128d);
__m128d _ZGVbN2v_cos(__m128d);
__m128d _ZGVbN2v_sin(__m128d);
__attribute__((target("avx2"))) __m256d _ZGVdN4v_exp(__m256d);
__attribute__((target("avx2"))) __m256d _ZGVdN4v_cos(__m256d);
__attribute__((target("avx2"))) __m256d _ZGVdN4v_sin(__m256d);
__attribute__((target("avx512f"))) __m512d _ZGVeN8v_exp(__m512d);
__attribute__((target("avx512f"))) __m512d _ZGVeN8v_cos(__m512d);
__attribute__((target("avx512f"))) __m512d _ZGVeN8v_sin(__m512d);
}
namespace {

// One kernel per vector width: alike in shape, but the intrinsics, the glibc vector entry
// points and the target attributes differ (a template cannot choose them).
// m is a multiple of the width except in the last block: the tail goes through libm.
void sse_kernel(const double* a, const double* b, double* e, double* c, double* s, std::size_t m) {
    std::size_t k = 0;
    for (; k + 2 <= m; k += 2) {
        _mm_storeu_pd(e + k, _ZGVbN2v_exp(_mm_loadu_pd(a + k)));
        const __m128d x = _mm_loadu_pd(b + k);
        _mm_storeu_pd(c + k, _ZGVbN2v_cos(x));
        _mm_storeu_pd(s + k, _ZGVbN2v_sin(x));
    }
    scalar_kernel(a + k, b + k, e + k, c + k, s + k, m - k);
}

__attribute__((target("avx2"))) void avx2_kernel(const double* a, const double* b, double* e, double* c,
                                                 double* s, std::size_t m) {
    std::size_t k = 0;
    for (; k + 4 <= m; k += 4) {
        _mm256_storeu_pd(e + k, _ZGVdN4v_exp(_mm256_loadu_pd(a + k)));
        const __m256d x = _mm256_loadu_pd(b + k);
        _mm256_storeu_pd(c + k, _ZGVdN4v_cos(x));
        _mm256_storeu_pd(s + k, _ZGVdN4v_sin(x));
    }
    scalar_kernel(a + k, b + k, e + k, c + k, s + k, m - k);
}

__attribute__((target("avx512f"))) void avx512_kernel(const double* a, const double* b, double* e, double* c,
                                                      double* s, std::size_t m) {
    std::size_t k = 0;
    for (; k + 8 <= m; k += 8) {
        _mm512_storeu_pd(e + k, _ZGVeN8v_exp(_mm512_loadu_pd(a + k)));
        const __m512d x = _mm512_loadu_pd(b + k);
        _mm512_storeu_pd(c + k, _ZGVeN8v_cos(x));
        _mm512_storeu_pd(s + k, _ZGVeN8v_sin(x));
    }
    scalar_kernel(a + k, b + k, e + k, c + k, s + k, m - k);
}
#endif

struct chosen {
    kernel run;
    const char* name;
};

chosen choose() {
#ifdef SYMREP_LIBMVEC_X86
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) return {avx512_kernel, "avx512"};
    if (__builtin_cpu_supports("avx2")) return {avx2_kernel, "avx2"};
    return {sse_kernel, "sse"};
#else
    return {scalar_kernel, "scalar"};
#endif
}

const chosen& the_kernel() {
    static const chosen k = choose();
    return k;
}

}  // namespace

const char* exp_components_kernel() { return the_kernel().name; }

// (III.1.45-52) componentwise, one block at a time.
void exp_components(std::complex<double>* z, std::size_t count, double t) {
    const kernel run = the_kernel().run;
    alignas(64) double a[block], b[block], e[block], c[block], s[block];
    for (std::size_t p0 = 0; p0 < count; p0 += block) {
        const std::size_t m = count - p0 < block ? count - p0 : block;
        std::complex<double>* w = z + p0;
        for (std::size_t k = 0; k < m; ++k) {
            a[k] = w[k].real() * t;
            b[k] = w[k].imag() * t;
        }
        run(a, b, e, c, s, m);
        for (std::size_t k = 0; k < m; ++k) w[k] = {e[k] * c[k], e[k] * s[k]};
    }
}

}  // namespace symrep
