// Tests of the Walsh algebra W and its complex extension W* (III.3, III.4.2c):
// exact with symbolic and rational coefficients, fast paths against the general
// (product-derived) methods of the base class, and the double path.
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>
#include <complex>
#include <random>

#include "algebra/walsh.h"
#include "algebra/walsh_complex.h"
#include "algebra/walsh_double.h"
#include "scalar/scalar.h"
#include "algebra/walsh_hadamard.h"
#include "core/error.h"

using namespace symrep;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

std::shared_ptr<const walsh> W(unsigned n) {
    return std::static_pointer_cast<const walsh>(walsh::make(n));
}
std::shared_ptr<const walsh_complex> WC(unsigned n) {
    return std::static_pointer_cast<const walsh_complex>(walsh_complex::make(n));
}

int sgn(std::size_t p, std::size_t q) { return __builtin_popcountll(p & q) % 2 ? -1 : 1; }

coeffs symbolic(std::size_t N, std::vector<GiNaC::realsymbol>& keep, const std::string& p = "f") {
    coeffs c(N);
    for (std::size_t k = 0; k < N; ++k) {
        keep.emplace_back(p + std::to_string(k));
        c[k] = keep.back();
    }
    return c;
}

coeffs rational(std::size_t N, unsigned seed) {
    std::mt19937 gen(seed);
    std::uniform_int_distribution<int> U(-9, 9);
    coeffs c(N);
    for (auto& x : c) x = numeric(U(gen), 1 + (U(gen) + 9) % 4);
    return c;
}

using symrep::test::same;

bool close(const coeffs& a, const coeffs& b, double tol = 1e-12) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const ex d = GiNaC::evalf(a[k] - b[k]);
        if (!GiNaC::is_a<numeric>(d) || GiNaC::abs(GiNaC::ex_to<numeric>(d)).to_double() > tol)
            return false;
    }
    return true;
}

/// Product of coordinate vectors straight from (III.3.6): O(4^n) dyadic convolution.
coeffs xor_product(const coeffs& a, const coeffs& b) {
    coeffs c(a.size(), ex(0));
    for (std::size_t p = 0; p < a.size(); ++p)
        for (std::size_t q = 0; q < b.size(); ++q) c[p ^ q] += a[p] * b[q];
    for (auto& x : c) x = GiNaC::normal(GiNaC::expand(x));
    return c;
}

}  // namespace

// (III.3.3, III.3.6) basis w_p = prod u_k^{p_k}, w_p w_q = w_{p xor q}; p_0 is the MSB.
TEST(Walsh, DyadicGroupTable) {
    auto A = W(3);
    for (std::size_t p = 0; p < 8; ++p)
        for (std::size_t q = 0; q < 8; ++q)
            EXPECT_TRUE(algebra::equal(A->multiply(A->basis_vector(p), A->basis_vector(q)),
                                       A->basis_vector(p ^ q)));
    EXPECT_EQ(A->name(), "walsh(3)");
    EXPECT_EQ(A->basis_name(0), "1");
    EXPECT_EQ(A->basis_name(4), "u0");
    EXPECT_EQ(A->basis_name(1), "u2");
    EXPECT_EQ(A->basis_name(6), "u0*u1");
    // (III.3.1) u_k^2 = 1, and w_p is the product of its u_k
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_TRUE(algebra::equal(A->multiply(A->generator(k), A->generator(k)), A->unit()));
    EXPECT_TRUE(algebra::equal(A->multiply(A->generator(0), A->generator(2)), A->basis_vector(5)));
    std::vector<GiNaC::realsymbol> s, t;
    const coeffs f = symbolic(8, s, "f"), g = symbolic(8, t, "g");
    EXPECT_TRUE(algebra::equal(A->multiply(f, g), xor_product(f, g)));
}

// (III.3.7) e_p = 2^{-n} prod_k (1 + (-1)^{p_k} u_k) equals (III.3.22); corrected (III.3.8)
// prefactor 1/4^n, and (III.3.9-10).
TEST(Walsh, HadamardIdempotents) {
    for (unsigned n : {1u, 2u, 3u}) {
        auto A = W(n);
        const std::size_t N = A->dim();
        coeffs sum = A->zero();
        for (std::size_t p = 0; p < N; ++p) {
            coeffs prod = A->unit();
            for (unsigned k = 0; k < n; ++k) {
                const int s = (p >> (n - 1 - k)) & 1 ? -1 : 1;  // (-1)^{p_k}
                prod = A->multiply(prod, algebra::add(A->unit(), algebra::scale(s, A->generator(k))));
            }
            EXPECT_TRUE(algebra::equal(algebra::scale(inv_pow2<ex>(n), prod), A->idempotent(p)));
            sum = algebra::add(sum, A->idempotent(p));
            for (std::size_t q = 0; q < N; ++q) {
                const coeffs epq = A->multiply(A->idempotent(p), A->idempotent(q));
                EXPECT_TRUE(algebra::equal(epq, p == q ? A->idempotent(p) : A->zero()));  // (9)
                // (8) corrected: e_p e_q = 4^{-n} prod_k {(-1)^{p_k+q_k} + 1 + [(-1)^{p_k} + (-1)^{q_k}] u_k}
                coeffs r = A->unit();
                for (unsigned k = 0; k < n; ++k) {
                    const int sp = (p >> (n - 1 - k)) & 1 ? -1 : 1, sq = (q >> (n - 1 - k)) & 1 ? -1 : 1;
                    r = A->multiply(r, algebra::add(algebra::scale(sp * sq + 1, A->unit()),
                                                    algebra::scale(sp + sq, A->generator(k))));
                }
                EXPECT_TRUE(algebra::equal(algebra::scale(inv_pow2<ex>(2 * n), r), epq));
                if (n >= 2 && p == q) {  // the printed 1/2^{n+1} is wrong for n >= 2
                    EXPECT_FALSE(algebra::equal(algebra::scale(inv_pow2<ex>(n + 1), r), epq));
                }
            }
        }
        EXPECT_TRUE(algebra::equal(sum, A->unit()));  // (10)
        EXPECT_EQ(A->idempotent_count(), N);
    }
}

// (III.3.11, 13-16) u_k e_p = (-1)^{p_k} e_p, u_k = sum (-1)^{p_k} e_p, u_k^m, w_q = sum (-1)^{<p,q>} e_p.
TEST(Walsh, GeneratorsInIdempotentBasis) {
    const unsigned n = 3;
    auto A = W(n);
    for (unsigned k = 0; k < n; ++k) {
        coeffs uk = A->zero(), uk3 = A->zero();
        for (std::size_t p = 0; p < 8; ++p) {
            const int s = (p >> (n - 1 - k)) & 1 ? -1 : 1;
            EXPECT_TRUE(algebra::equal(A->multiply(A->generator(k), A->idempotent(p)),
                                       algebra::scale(s, A->idempotent(p))));  // (11)
            uk = algebra::add(uk, algebra::scale(s, A->idempotent(p)));
            uk3 = algebra::add(uk3, algebra::scale(s * s * s, A->idempotent(p)));
        }
        EXPECT_TRUE(algebra::equal(uk, A->generator(k)));                // (13)
        EXPECT_TRUE(algebra::equal(uk3, A->power(A->generator(k), 3)));  // (14), m = 3
    }
    for (std::size_t q = 0; q < 8; ++q) {  // (15-16)
        coeffs wq = A->zero();
        for (std::size_t p = 0; p < 8; ++p) wq = algebra::add(wq, algebra::scale(sgn(p, q), A->idempotent(p)));
        EXPECT_TRUE(algebra::equal(wq, A->basis_vector(q)));
    }
}

// (III.3.18-22) H = [[1,1],[1,-1]]^{(x)n}, H^{-1} = 2^{-n} H; fwht applies H.
TEST(Walsh, HadamardMatrix) {
    const unsigned n = 4;
    const std::size_t N = 16;
    GiNaC::matrix H(1, 1, GiNaC::lst{1});
    for (unsigned k = 0; k < n; ++k) {  // Kronecker power (19)
        GiNaC::matrix K(H.rows() * 2, H.cols() * 2);
        for (unsigned i = 0; i < H.rows(); ++i)
            for (unsigned j = 0; j < H.cols(); ++j)
                for (unsigned a = 0; a < 2; ++a)
                    for (unsigned b = 0; b < 2; ++b)
                        K(2 * i + a, 2 * j + b) = H(i, j) * (a && b ? -1 : 1);
        H = K;
    }
    for (std::size_t p = 0; p < N; ++p)
        for (std::size_t q = 0; q < N; ++q) EXPECT_EQ(H(p, q), ex(sgn(p, q)));  // (17)
    GiNaC::matrix HH = H.mul(H);
    for (std::size_t p = 0; p < N; ++p)
        for (std::size_t q = 0; q < N; ++q) EXPECT_EQ(HH(p, q), ex(p == q ? 16 : 0));  // (20)
    auto A = W(n);
    std::vector<GiNaC::realsymbol> s;
    const coeffs f = symbolic(N, s);
    const auto a = A->idempotent_components(f);
    for (std::size_t p = 0; p < N; ++p) {
        ex direct = 0;
        for (std::size_t q = 0; q < N; ++q) direct += sgn(p, q) * f[q];  // (25)
        EXPECT_TRUE(same(a[p], direct));
    }
    EXPECT_TRUE(algebra::equal(A->from_idempotent_components(a), f));  // (21)
    coeffs sum = A->zero();  // (24)
    for (std::size_t p = 0; p < N; ++p) sum = algebra::add(sum, algebra::scale(a[p], A->idempotent(p)));
    EXPECT_TRUE(algebra::equal(sum, f));
}

// (III.3.26-29, 33-34) e_k f = a_k e_k, det, charpoly, p(f) = 0; against the general methods.
TEST(Walsh, DeterminantCharpolyMinpoly) {
    GiNaC::symbol X("X");
    {
        auto A = W(2);
        std::vector<GiNaC::realsymbol> s;
        const coeffs f = symbolic(4, s);
        const auto a = A->idempotent_components(f);
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_TRUE(algebra::equal(A->multiply(A->idempotent(k), f), algebra::scale(a[k], A->idempotent(k))));
        EXPECT_TRUE(same(A->determinant(f), A->algebra::determinant(f)));
        EXPECT_TRUE(same(A->charpoly(f, X), A->algebra::charpoly(f, X)));
        EXPECT_TRUE(algebra::equal(A->evaluate_polynomial(A->charpoly(f, X), X, f), A->zero()));
        EXPECT_TRUE(same(A->minpoly(f, X), A->charpoly(f, X)));  // generic: distinct roots
    }
    auto A = W(3);
    const coeffs f = rational(8, 7);
    {  // (27) in the idempotent basis [f] is diag(a_0..a_7): E [f] E^{-1} = diag(a)
        GiNaC::matrix E(8, 8);
        for (std::size_t p = 0; p < 8; ++p) {
            const coeffs e = A->idempotent(p);
            for (std::size_t q = 0; q < 8; ++q) E(p, q) = e[q];
        }
        const GiNaC::matrix D = E.mul(A->canonical_matrix(f)).mul(E.inverse());
        const auto a = A->idempotent_components(f);
        for (std::size_t p = 0; p < 8; ++p)
            for (std::size_t q = 0; q < 8; ++q) EXPECT_TRUE(same(D(p, q), p == q ? a[p] : ex(0)));
    }
    EXPECT_TRUE(same(A->determinant(f), A->algebra::determinant(f)));
    EXPECT_TRUE(same(A->charpoly(f, X), A->algebra::charpoly(f, X)));
    // repeated roots: components (1, 1, 2, 2, 2, -1, 0, 0)
    const coeffs g = A->from_idempotent_components({1, 1, 2, 2, 2, -1, 0, 0});
    EXPECT_TRUE(same(A->minpoly(g, X), (X - 1) * (X - 2) * (X + 1) * X));
    EXPECT_TRUE(same(A->minpoly(g, X), A->algebra::minpoly(g, X)));
    EXPECT_TRUE(same(A->minpoly(f, X), A->algebra::minpoly(f, X)));
}

// (III.3.30-32), Thm III.3.2.3 and its remark: zero divisors of rank p.
TEST(Walsh, ZeroDivisorRanks) {
    auto A = W(3);
    const coeffs f = A->from_idempotent_components({3, 0, 1, -2, 5, 0, 7, 1});
    EXPECT_EQ(A->zero_divisor_ranks(f), (std::vector<std::size_t>{1, 5}));
    EXPECT_TRUE(A->is_zero_divisor(f));
    EXPECT_TRUE(A->algebra::is_zero_divisor(f));
    for (std::size_t p : {1u, 5u}) {
        EXPECT_TRUE(algebra::equal(A->multiply(f, A->idempotent(p)), A->zero()));
        ex s32 = 0;  // (32)
        for (std::size_t q = 0; q < 8; ++q) s32 += sgn(p, q) * f[q];
        EXPECT_TRUE(same(s32, 0));
    }
    EXPECT_FALSE(algebra::equal(A->multiply(f, A->idempotent(2)), A->zero()));
    const auto r = A->zero_divisor_ranks(A->idempotent(3));  // e_3: every rank but 3
    EXPECT_EQ(r, (std::vector<std::size_t>{0, 1, 2, 4, 5, 6, 7}));
    try {
        A->inverse(f);
        FAIL();
    } catch (const zero_divisor_error& e) {
        EXPECT_EQ(e.ranks, (std::vector<std::size_t>{1, 5}));
        EXPECT_NE(std::string(e.what()).find("rank 1, 5"), std::string::npos) << e.what();
    }
    EXPECT_THROW(A->log(f), zero_divisor_error);
}

TEST(Walsh, Inverse) {
    {
        auto A = W(2);
        std::vector<GiNaC::realsymbol> s;
        const coeffs f = symbolic(4, s);
        EXPECT_TRUE(algebra::equal(A->multiply(f, A->inverse(f)), A->unit()));
    }
    auto A = W(3);
    const coeffs f = rational(8, 11);
    ASSERT_FALSE(A->is_zero_divisor(f));
    EXPECT_TRUE(algebra::equal(A->inverse(f), A->algebra::inverse(f)));
}

// (III.3.41-44) exp through the idempotents; d/dt exp(f t) = f exp(f t).
TEST(Walsh, Exp) {
    GiNaC::realsymbol t("t");
    auto A = W(2);
    std::vector<GiNaC::realsymbol> s;
    const coeffs f = symbolic(4, s);
    const coeffs E = A->exp(f, t);
    coeffs dE(4), E0(4);
    for (std::size_t k = 0; k < 4; ++k) {
        dE[k] = E[k].diff(t);
        E0[k] = E[k].subs(t == 0);
    }
    EXPECT_TRUE(algebra::equal(dE, A->multiply(f, E)));
    EXPECT_TRUE(algebra::equal(E0, A->unit()));
    // (44) written out: 2^{-n} sum_p [sum_k (-1)^{<p,k>} exp(sum_q (-1)^{<k,q>} f_q)] w_p
    const coeffs E1 = A->exp(f, 1);
    for (std::size_t p = 0; p < 4; ++p) {
        ex v = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            ex ak = 0;
            for (std::size_t q = 0; q < 4; ++q) ak += sgn(k, q) * f[q];
            v += sgn(p, k) * GiNaC::exp(ak);
        }
        EXPECT_TRUE(same(E1[p], v / 4));
    }
    // exp(u_k t) = cosh t + u_k sinh t
    const coeffs Eu = A->exp(A->generator(1), t);
    EXPECT_TRUE(same(Eu[0], (GiNaC::exp(t) + GiNaC::exp(-t)) / 2));
    EXPECT_TRUE(same(Eu[1], (GiNaC::exp(t) - GiNaC::exp(-t)) / 2));
}

// Thm III.3.3.1 (III.3.39-40): log when every root a_p > 0; errors otherwise.
TEST(Walsh, Log) {
    auto A = W(3);
    const coeffs f = A->from_idempotent_components({1, 2, 3, numeric(1, 2), 5, 6, 7, 8});
    const coeffs g = A->log(f);
    EXPECT_TRUE(algebra::equal(A->exp(g, 1), f));  // (39)
    for (std::size_t p = 0; p < 8; ++p) {
        ex v = 0;  // (40)
        const std::vector<ex> a = {1, 2, 3, numeric(1, 2), 5, 6, 7, 8};
        for (std::size_t k = 0; k < 8; ++k) v += sgn(p, k) * GiNaC::log(a[k]);
        EXPECT_TRUE(same(g[p], v / 8));
    }
    {
        auto B = W(2);
        std::vector<GiNaC::realsymbol> s;
        const coeffs h = symbolic(4, s);
        EXPECT_TRUE(algebra::equal(B->log(B->exp(h, 1)), h));
    }
    const coeffs neg = A->from_idempotent_components({1, 2, -3, 4, 5, 6, 7, 8});
    try {
        A->log(neg);
        FAIL();
    } catch (const domain_error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("a_2 = -3"), std::string::npos) << m;
        EXPECT_NE(m.find("walsh_complex(3)"), std::string::npos) << m;
    }
    // ... but W* has it (III.3.64-67)
    auto C = WC(3);
    coeffs negc = neg;
    negc.resize(16, ex(0));
    EXPECT_TRUE(algebra::equal(C->exp(C->log(negc), 1), negc));
}

// (III.4.15-18) d = sum alpha_k u_k with alpha_k = 2^k: distinct nonzero Omega_p, minimal charpoly.
TEST(Walsh, GeneratingElement) {
    GiNaC::symbol X("X");
    for (unsigned n = 1; n <= 4; ++n) {
        auto A = W(n);
        const coeffs d = A->generating_element({});
        const auto Om = A->idempotent_components(d);
        for (std::size_t p = 0; p < Om.size(); ++p) {
            ex o = 0;  // (17)
            for (unsigned k = 0; k < n; ++k) o += ((p >> (n - 1 - k)) & 1 ? -1 : 1) * GiNaC::pow(2, k);
            EXPECT_TRUE(same(Om[p], o));
            EXPECT_FALSE(Om[p].is_zero());
            for (std::size_t q = 0; q < p; ++q) EXPECT_FALSE(same(Om[p], Om[q]));
        }
        const ex p = A->charpoly(d, X);
        EXPECT_TRUE(same(A->minpoly(d, X), p));
        EXPECT_TRUE(same(A->algebra::minpoly(d, X), p)) << n;
        EXPECT_EQ(p.degree(X), int(A->dim()));
    }
    auto A = W(2);
    EXPECT_TRUE(same(A->minpoly(A->generating_element({1, 1}), X), X * (X - 2) * (X + 2)));  // Omega = 2,0,0,-2
    EXPECT_THROW(A->generating_element({1}), type_error);
}

// W*: (III.3.47-51, 56-58, 62-63) idempotents, i0, components.
TEST(WalshComplex, BasisAndComponents) {
    const unsigned n = 2;
    auto C = WC(n);
    EXPECT_EQ(C->name(), "walsh_complex(2)");
    EXPECT_EQ(C->dim(), 8u);
    EXPECT_EQ(C->basis_name(4), "i0");
    EXPECT_EQ(C->basis_name(6), "i0*u0");
    EXPECT_TRUE(algebra::equal(C->multiply(C->i0(), C->i0()), algebra::scale(-1, C->unit())));  // (51)
    for (std::size_t p = 0; p < 4; ++p) {
        for (std::size_t q = 0; q < 4; ++q) {
            EXPECT_TRUE(algebra::equal(C->multiply(C->basis_vector(p), C->basis_vector(q)),
                                       C->basis_vector(p ^ q)));  // (45)
            EXPECT_TRUE(algebra::equal(C->multiply(C->idempotent(p), C->idempotent(q)),
                                       p == q ? C->idempotent(p) : C->zero()));
        }
        coeffs wk = C->zero(), iwk = C->zero();  // (48) and (56): w* = S e*
        for (std::size_t r = 0; r < 4; ++r) {
            wk = algebra::add(wk, algebra::scale(sgn(r, p), C->idempotent(r)));
            iwk = algebra::add(iwk, algebra::scale(sgn(r, p), C->multiply(C->i0(), C->idempotent(r))));
        }
        EXPECT_TRUE(algebra::equal(wk, C->basis_vector(p)));
        EXPECT_TRUE(algebra::equal(iwk, C->basis_vector(4 + p)));
    }
    std::vector<GiNaC::realsymbol> s;
    const coeffs w = symbolic(8, s);
    const auto y = C->idempotent_components(w);
    for (std::size_t p = 0; p < 4; ++p) {
        ex c = 0, d = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            c += sgn(p, k) * w[k];      // (62)
            d += sgn(p, k) * w[4 + k];  // (63)
        }
        EXPECT_TRUE(same(y[p], c + GiNaC::I * d));
    }
    EXPECT_TRUE(algebra::equal(C->from_idempotent_components(y), w));  // (58)
    coeffs sum = C->zero();  // (61)
    for (std::size_t p = 0; p < 4; ++p)
        sum = algebra::add(sum, algebra::add(algebra::scale(y[p].real_part(), C->idempotent(p)),
                                             algebra::scale(y[p].imag_part(), C->multiply(C->i0(), C->idempotent(p)))));
    EXPECT_TRUE(algebra::equal(sum, w));
    // W is the subalgebra of the first 2^n basis elements
    auto A = W(n);
    const coeffs f = rational(4, 3), g = rational(4, 5);
    coeffs fc = f, gc = g;
    fc.resize(8, ex(0));
    gc.resize(8, ex(0));
    coeffs fg = A->multiply(f, g);
    fg.resize(8, ex(0));
    EXPECT_TRUE(algebra::equal(C->multiply(fc, gc), fg));
}

TEST(WalshComplex, AgainstGeneralMethods) {
    GiNaC::symbol X("X");
    auto C = WC(2);
    const coeffs w = rational(8, 21);
    EXPECT_TRUE(same(C->determinant(w), C->algebra::determinant(w)));
    EXPECT_TRUE(same(C->charpoly(w, X), C->algebra::charpoly(w, X)));
    EXPECT_TRUE(same(C->minpoly(w, X), C->algebra::minpoly(w, X)));
    EXPECT_TRUE(algebra::equal(C->inverse(w), C->algebra::inverse(w)));
    // repeated and conjugate components: y = (1+2i, 1-2i, 3, 1+2i): minpoly (X^2-2X+5)(X-3)
    const coeffs v = C->from_idempotent_components({1 + 2 * GiNaC::I, 1 - 2 * GiNaC::I, 3, 1 + 2 * GiNaC::I});
    EXPECT_TRUE(same(C->minpoly(v, X), (X * X - 2 * X + 5) * (X - 3)));
    EXPECT_TRUE(same(C->minpoly(v, X), C->algebra::minpoly(v, X)));
    EXPECT_TRUE(same(C->charpoly(v, X), C->algebra::charpoly(v, X)));
    {
        auto C1 = WC(1);
        std::vector<GiNaC::realsymbol> s;
        const coeffs u = symbolic(4, s);
        EXPECT_TRUE(same(C1->charpoly(u, X), C1->algebra::charpoly(u, X)));
        EXPECT_TRUE(algebra::equal(C1->multiply(u, C1->inverse(u)), C1->unit()));
    }
    // zero divisors
    const coeffs z = C->from_idempotent_components({1, 0, GiNaC::I, 2});
    EXPECT_EQ(C->zero_divisor_ranks(z), (std::vector<std::size_t>{1}));
    EXPECT_TRUE(C->algebra::is_zero_divisor(z));
    try {
        C->log(z);
        FAIL();
    } catch (const zero_divisor_error& e) {
        EXPECT_EQ(e.ranks, (std::vector<std::size_t>{1}));
    }
    EXPECT_THROW(C->inverse(z), zero_divisor_error);
}

// (III.3.64-67) every non-zero-divisor of W* has a logarithm; exp solves its ODE.
TEST(WalshComplex, ExpLog) {
    auto C = WC(2);
    // components -1, i, -2i, 2: exact angles
    const coeffs w = C->from_idempotent_components({-1, GiNaC::I, -2 * GiNaC::I, 2});
    const coeffs L = C->log(w);
    EXPECT_TRUE(algebra::equal(C->exp(L, 1), w));
    const auto yl = C->idempotent_components(L);
    EXPECT_TRUE(same(yl[0], GiNaC::I * GiNaC::Pi));  // ln 1 + i pi
    EXPECT_TRUE(same(yl[3], GiNaC::log(ex(2))));
    const coeffs v = rational(8, 99);
    EXPECT_TRUE(close(C->exp(C->log(v), 1), v, 1e-10));
    GiNaC::realsymbol t("t");
    auto C1 = WC(1);
    std::vector<GiNaC::realsymbol> s;
    const coeffs u = symbolic(4, s);
    const coeffs E = C1->exp(u, t);
    coeffs dE(4);
    for (std::size_t k = 0; k < 4; ++k) dE[k] = E[k].diff(t);
    EXPECT_TRUE(algebra::equal(dE, C1->multiply(u, E)));
}

TEST(WalshComplex, GeneratingElement) {
    GiNaC::symbol X("X");
    for (unsigned n = 0; n <= 3; ++n) {
        auto C = WC(n);
        const coeffs d = C->generating_element({});
        const ex p = C->charpoly(d, X);
        EXPECT_EQ(p.degree(X), int(C->dim()));
        EXPECT_TRUE(same(C->minpoly(d, X), p));
        EXPECT_TRUE(same(C->algebra::minpoly(d, X), p)) << n;
    }
}

TEST(Walsh, BadSizes) {
    // above the exact limits the algebras are double-precision only (issue 13, 4.6)
    try {
        walsh::make(27);
        FAIL();
    } catch (const size_error& e) {
        EXPECT_NE(std::string(e.what()).find("n <= 16"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("n <= 26"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(dynamic_cast<const walsh&>(*walsh::make(17)).exact());
    EXPECT_THROW(walsh_complex::make(26), size_error);
    EXPECT_THROW(walsh::make(-2), domain_error);
    EXPECT_THROW(walsh_d(27), size_error);
    EXPECT_THROW(walsh_complex_d(26), size_error);
    auto A = W(2);
    EXPECT_THROW(A->generator(2), domain_error);
    EXPECT_THROW(A->idempotent(4), domain_error);
    EXPECT_THROW(A->multiply(A->unit(), coeffs(3, ex(0))), algebra_error);
    EXPECT_THROW(A->from_idempotent_components({1, 2}), algebra_error);
    walsh_d D(3);
    EXPECT_THROW(D.multiply(D.unit(), {1, 2}), algebra_error);
}

// Double path on random elements up to n = 12 (fixed seeds). Components are sums of 2^n
// terms of size <= 1, so the round-off of fwht is about n 2^n eps |f|_1; the tolerances
// below (1e-9 relative) leave a wide margin at n = 12.
TEST(WalshDouble, RandomIdentities) {
    std::mt19937 gen(1908);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    for (unsigned n : {1u, 3u, 6u, 9u, 12u}) {
        walsh_d A(n);
        const std::size_t N = A.dim();
        std::vector<double> f(N), g(N);
        for (auto& x : f) x = U(gen);
        for (auto& x : g) x = U(gen);
        if (n <= 6) {  // against the O(4^n) dyadic convolution (III.3.6)
            std::vector<double> direct(N, 0.0);
            for (std::size_t p = 0; p < N; ++p)
                for (std::size_t q = 0; q < N; ++q) direct[p ^ q] += f[p] * g[q];
            const auto fg = A.multiply(f, g);
            for (std::size_t p = 0; p < N; ++p) EXPECT_NEAR(fg[p], direct[p], 1e-12 * N);
        }
        // positive components: exp(log) and the inverse
        std::vector<double> a(N);
        for (auto& x : a) x = 0.5 + (U(gen) + 1.0);
        const auto pos = A.from_components(a);
        const auto back = A.exp(A.log(pos));
        const auto one = A.multiply(pos, A.inverse(pos));
        for (std::size_t p = 0; p < N; ++p) {
            EXPECT_NEAR(back[p], pos[p], 1e-9);
            EXPECT_NEAR(one[p], p == 0 ? 1.0 : 0.0, 1e-9);
        }
        walsh_complex_d C(n);
        std::vector<double> w(C.dim());
        for (auto& x : w) x = U(gen);
        w[0] += 4.0;  // keeps the components away from 0
        const auto wb = C.exp(C.log(w));
        const auto w1 = C.multiply(w, C.inverse(w));
        for (std::size_t k = 0; k < C.dim(); ++k) {
            EXPECT_NEAR(wb[k], w[k], 1e-9) << n;
            EXPECT_NEAR(w1[k], k == 0 ? 1.0 : 0.0, 1e-9) << n;
        }
    }
    walsh_d A(2);
    const auto neg = A.from_components({1, -2, 3, 4});
    try {
        A.log(neg);
        FAIL();
    } catch (const domain_error& e) {
        EXPECT_NE(std::string(e.what()).find("walsh_complex_d"), std::string::npos);
    }
    try {
        A.inverse(A.from_components({1, 0, 3, 0}));
        FAIL();
    } catch (const zero_divisor_error& e) {
        EXPECT_EQ(e.ranks, (std::vector<std::size_t>{1, 3}));
    }
}

// Double vs exact on small rational elements (tolerance 1e-12: a few dozen operations on O(1) numbers).
TEST(WalshDouble, MatchesExact) {
    auto A = W(3);
    walsh_d D(3);
    const coeffs f = A->from_idempotent_components({1, 2, 3, numeric(1, 2), 5, 6, 7, 8});
    std::vector<double> fd;
    for (const auto& x : f) fd.push_back(GiNaC::ex_to<numeric>(x).to_double());
    auto check = [](const coeffs& e, const std::vector<double>& d) {
        ASSERT_EQ(e.size(), d.size());
        for (std::size_t k = 0; k < d.size(); ++k)
            EXPECT_NEAR(GiNaC::ex_to<numeric>(GiNaC::evalf(e[k])).to_double(), d[k], 1e-12) << k;
    };
    check(A->inverse(f), D.inverse(fd));
    check(A->exp(f, numeric(1, 3)), D.exp(fd, 1.0 / 3));
    check(A->log(f), D.log(fd));
    EXPECT_NEAR(GiNaC::ex_to<numeric>(A->determinant(f)).to_double(), D.determinant(fd), 1e-9);
    auto C = WC(2);
    walsh_complex_d CD(2);
    const coeffs w = rational(8, 4);
    std::vector<double> wd;
    for (const auto& x : w) wd.push_back(GiNaC::ex_to<numeric>(x).to_double());
    check(C->inverse(w), CD.inverse(wd));
    check(C->exp(w, 1), CD.exp(wd));
    check(C->log(w), CD.log(wd));
    const auto y = C->idempotent_components(w);
    const auto yd = CD.components(wd);
    for (std::size_t p = 0; p < 4; ++p) {
        EXPECT_NEAR(GiNaC::ex_to<numeric>(GiNaC::evalf(y[p].real_part())).to_double(), yd[p].real(), 1e-12);
        EXPECT_NEAR(GiNaC::ex_to<numeric>(GiNaC::evalf(y[p].imag_part())).to_double(), yd[p].imag(), 1e-12);
    }
}
