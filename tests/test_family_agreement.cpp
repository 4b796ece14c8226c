// Fast paths of the algebra families agree with the general method.
//
// For every family (multicomplex, Sobrero, Walsh, W*) and small orders, the
// same algebra is rebuilt from its structure constants (structure_algebra::from),
// where every operation comes from the general theorems of II.1-II.2 (canonical
// matrix, Krylov minimal polynomial, Hermite interpolation on the roots of the
// minimal polynomial). Both must give the same products, inverses, characteristic
// and minimal polynomials (exactly), and the same exp(w t) and log(w) (compared
// as exact coordinates after substituting rational t where the closed forms are
// rational, and numerically to 1e-25 at 40 digits otherwise: the two closed
// forms are written differently, e.g. cos(2t) against 2cos(t)^2-1, so a textual
// comparison would be meaningless).
#include <gtest/gtest.h>

#include <random>

#include "algebra/element.h"
#include "algebra/multicomplex.h"
#include "scalar/scalar.h"
#include "algebra/sobrero.h"
#include "algebra/structure_algebra.h"
#include "algebra/walsh.h"
#include "algebra/walsh_complex.h"

using namespace symrep;
using GiNaC::ex;

namespace {

struct family_case {
    std::string label;
    algebra_ptr fast;
};

std::vector<family_case> families() {
    return {
        {"multicomplex(1)", multicomplex::make(1)},
        {"multicomplex(2)", multicomplex::make(2)},
        {"sobrero(1)", sobrero::make(1)},
        {"sobrero(2)", sobrero::make(2)},
        {"walsh(2)", walsh::make(2)},
        {"walsh(3)", walsh::make(3)},
        {"walsh_complex(1)", walsh_complex::make(1)},
        {"walsh_complex(2)", walsh_complex::make(2)},
    };
}

coeffs random_coeffs(std::size_t n, std::mt19937& rng) {
    std::uniform_int_distribution<int> d(-4, 4);
    coeffs c(n);
    for (auto& x : c) x = d(rng);
    return c;
}

// Max |x - y| over the coordinates after numeric evaluation at 40 digits.
double max_numeric_difference(const coeffs& a, const coeffs& b, const GiNaC::symbol& t, double tval) {
    GiNaC::Digits = 40;
    double worst = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        ex d = GiNaC::evalf((a[k] - b[k]).subs(t == GiNaC::numeric(tval)));
        if (!GiNaC::is_a<GiNaC::numeric>(d)) return 1e300;
        worst = std::max(worst, std::abs(GiNaC::ex_to<GiNaC::numeric>(d).to_double()));
    }
    return worst;
}

}  // namespace

TEST(FamilyAgreement, ProductsInversesAndPolynomials) {
    std::mt19937 rng(20261122);
    GiNaC::symbol X("X");
    for (const auto& fc : families()) {
        SCOPED_TRACE(fc.label);
        const algebra_ptr slow = structure_algebra::from(*fc.fast);
        ASSERT_EQ(slow->dim(), fc.fast->dim());
        for (int trial = 0; trial < 3; ++trial) {
            const coeffs a = random_coeffs(fc.fast->dim(), rng);
            const coeffs b = random_coeffs(fc.fast->dim(), rng);
            EXPECT_TRUE(algebra::equal(fc.fast->multiply(a, b), slow->multiply(a, b)));
            EXPECT_TRUE(is_zero_scalar(fc.fast->charpoly(a, X) - slow->charpoly(a, X)));
            EXPECT_TRUE(is_zero_scalar(fc.fast->minpoly(a, X) - slow->minpoly(a, X)));
            EXPECT_TRUE(is_zero_scalar(fc.fast->determinant(a) - slow->determinant(a)));
            EXPECT_EQ(fc.fast->is_zero_divisor(a), slow->is_zero_divisor(a));
            if (!fc.fast->is_zero_divisor(a)) {
                EXPECT_TRUE(algebra::equal(fc.fast->inverse(a), slow->inverse(a)));
            }
        }
    }
}

TEST(FamilyAgreement, ExponentialClosedForms) {
    std::mt19937 rng(7);
    GiNaC::symbol t("t");
    for (const auto& fc : families()) {
        SCOPED_TRACE(fc.label);
        const algebra_ptr slow = structure_algebra::from(*fc.fast);
        const coeffs w = random_coeffs(fc.fast->dim(), rng);
        const coeffs e1 = fc.fast->exp(w, t);
        const coeffs e2 = slow->exp(w, t);
        for (double tv : {0.0, 0.3, 1.7})
            EXPECT_LT(max_numeric_difference(e1, e2, t, tv), 1e-25) << "t = " << tv;
    }
}

TEST(FamilyAgreement, Logarithms) {
    // Elements with rational coordinates that have a logarithm in every family:
    // idempotent components with positive real part (W: positive components),
    // and in S a leading coefficient xi_0 with a_0 > 0. Their minimal polynomials
    // have rational coefficients, which the general method can factor.
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> pos(1, 5), any(-3, 3);
    GiNaC::symbol t("t");
    for (const auto& fc : families()) {
        SCOPED_TRACE(fc.label);
        const algebra_ptr slow = structure_algebra::from(*fc.fast);
        coeffs w;
        if (fc.fast->idempotent_count() > 0) {
            std::vector<ex> c(fc.fast->idempotent_count());
            const bool real = fc.label.rfind("walsh(", 0) == 0;
            for (auto& x : c) x = real ? ex(pos(rng)) : ex(pos(rng) + GiNaC::I * any(rng));
            w = fc.fast->from_idempotent_components(c);
        } else {  // Sobrero: [a_0..a_n, b_0..b_n]
            w = random_coeffs(fc.fast->dim(), rng);
            w[0] = pos(rng);
        }
        const coeffs l1 = fc.fast->log(w);
        const coeffs l2 = slow->log(w);
        // Both are logarithms: exp(log w) = w, checked numerically at 40 digits
        // (with the fast exp, whose agreement with the general one is tested above:
        // the general exp of an element with transcendental coordinates would have
        // to factor a minimal polynomial with transcendental coefficients).
        EXPECT_LT(max_numeric_difference(fc.fast->exp(l1, 1), w, t, 0), 1e-25);
        EXPECT_LT(max_numeric_difference(fc.fast->exp(l2, 1), w, t, 0), 1e-25);
        // Both take the principal argument in every component, so they coincide.
        EXPECT_LT(max_numeric_difference(l1, l2, t, 0), 1e-25);
    }
}
