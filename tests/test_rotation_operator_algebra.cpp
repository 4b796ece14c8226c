// Tests of the algebra of K = w x (thesis VI.1.12-15) as P(X^3 + Omega^2 X).
#include <gtest/gtest.h>

#include "scalar/scalar.h"
#include "core/error.h"
#include "mechanics/rotation_operator_algebra.h"

using namespace symrep;
using namespace symrep::mechanics;
using GiNaC::ex;

TEST(RotationOperatorAlgebra, CayleyHamiltonAndIdempotents) {
    const GiNaC::possymbol W("W");
    const rotation_operator_algebra R(W);
    const element K = R.K(), one = R.one();
    EXPECT_EQ(R.algebra()->dim(), 3u);
    EXPECT_TRUE(K.pow(3) == -W * W * K);  // VI.1.15
    const GiNaC::symbol X("X");
    EXPECT_TRUE(GiNaC::normal(K.minpoly(X) - (GiNaC::pow(X, 3) + W * W * X)).is_zero());
    const element P0 = R.P0(), P1 = R.P1(), J = R.J();
    EXPECT_TRUE(P0 * P0 == P0);
    EXPECT_TRUE(P1 * P1 == P1);
    EXPECT_TRUE(P0 * P1 == R.make(0, 0, 0));
    EXPECT_TRUE(P0 + P1 == one);
    EXPECT_TRUE(K * P0 == R.make(0, 0, 0));  // K kills the axial part
    EXPECT_TRUE(J * J == -P1);               // J^2 = -1 on the plane
    EXPECT_TRUE(K * P1 == W * J);            // K = Omega J on P1
    // components and back
    const GiNaC::realsymbol a("a"), b("b"), c("c");
    const coeffs v{a, b, c};
    const auto comp = R.decompose(v);
    EXPECT_TRUE(algebra::equal(R.recombine(comp.axial, comp.planar), v));
    // K^2 P0 = 0 and at_i_omega is the planar component of a polynomial
    const cex z = R.at_i_omega({a, b, c, ex(1)});
    const auto cz = R.decompose(R.polynomial({a, b, c, ex(1)}).coefficients());
    EXPECT_TRUE(is_zero_cex(z - cz.planar));
}

TEST(RotationOperatorAlgebra, ExpMinusKtIsVI_1_14) {
    const GiNaC::possymbol W("W");
    const GiNaC::realsymbol t("t");
    const rotation_operator_algebra R(W);
    const element E = R.exp_minus_Kt(t);
    const ex phi0 = 1, phi1 = -GiNaC::sin(W * t) / W, phi2 = (1 - GiNaC::cos(W * t)) / (W * W);
    EXPECT_TRUE(is_zero_scalar(tidy(E[0] - phi0))) << E[0];
    EXPECT_TRUE(is_zero_scalar(tidy(E[1] - phi1))) << E[1];
    EXPECT_TRUE(is_zero_scalar(tidy(E[2] - phi2))) << E[2];
    // the operator 2 w x of VI.1.42: Omega -> 2 Omega
    const element E2 = (-2 * R.K()).exp(t);
    // coefficient of K is 2 phi1(2 Omega), of K^2 is 4 phi2(2 Omega)
    EXPECT_TRUE(is_zero_scalar(tidy(E2[1] + 2 * GiNaC::sin(2 * W * t) / (2 * W)))) << E2[1];
    EXPECT_TRUE(is_zero_scalar(tidy(E2[2] - 4 * (1 - GiNaC::cos(2 * W * t)) / (4 * W * W)))) << E2[2];
}

TEST(RotationOperatorAlgebra, DegenerateAndBadOmega) {
    const rotation_operator_algebra R0(0);
    EXPECT_TRUE(R0.degenerate());
    EXPECT_TRUE(R0.K().pow(3) == R0.make(0, 0, 0));
    EXPECT_THROW(R0.P0(), domain_error);
    const GiNaC::realsymbol t("t");
    const element E = R0.exp_minus_Kt(t);  // exact limit: 1 - K t + K^2 t^2/2
    EXPECT_TRUE(E == R0.make(1, -t, t * t / 2));
    EXPECT_THROW(rotation_operator_algebra(-2), domain_error);
    EXPECT_THROW(rotation_operator_algebra(GiNaC::realsymbol("r")), domain_error);
    EXPECT_NO_THROW(rotation_operator_algebra(GiNaC::sqrt(ex(2))));
}

// The smaller algebras R[X]/(m_P) of a scene (II.1.23-24): m_P(K) kills P for the
// local minimal polynomial of each kind of vector, and recombine(axial, planar, m)
// agrees with the full recombination modulo m, with degree < deg m.
TEST(RotationOperatorAlgebra, RecombineModuloLocalMinimalPolynomial) {
    // the premise, with the skew matrix of w = (1, 2, 2), |w| = 3 (VI.1.9)
    const GiNaC::matrix K(3, 3, GiNaC::lst{0, -2, 2, 2, 0, -1, -2, 1, 0});
    const GiNaC::matrix I3 = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
    const GiNaC::matrix K2 = K.mul(K);
    auto col = [](int x, int y, int z) { return GiNaC::matrix(3, 1, GiNaC::lst{x, y, z}); };
    auto is_zero_col = [](const GiNaC::matrix& m) { return m(0, 0).is_zero() && m(1, 0).is_zero() && m(2, 0).is_zero(); };
    EXPECT_TRUE(is_zero_col(K.mul(col(1, 2, 2))));                            // along w: m = X
    EXPECT_TRUE(is_zero_col(K2.add(I3.mul_scalar(9)).mul(col(2, -1, 0))));    // across w: m = X^2 + 9
    EXPECT_FALSE(is_zero_col(K.mul(col(2, -1, 0))));                          // and no smaller
    EXPECT_FALSE(is_zero_col(K2.add(I3.mul_scalar(9)).mul(col(1, 0, 0))));    // general: neither
    EXPECT_FALSE(is_zero_col(K.mul(col(1, 0, 0))));

    const GiNaC::possymbol W("W");
    const GiNaC::realsymbol t("t"), a("a"), b("b");
    const rotation_operator_algebra R(W);
    const quasi_polynomial u = quasi_polynomial::from_ex(a * GiNaC::cos(t) + t, t);
    const quasi_polynomial z = quasi_polynomial::from_ex(b * GiNaC::exp(-t), t) +
                               cex(ex(0), ex(1)) * quasi_polynomial::from_ex(GiNaC::sin(W * t), t);
    const auto full = R.recombine(u, z);
    auto as_coeffs = [](const std::array<quasi_polynomial, 3>& c) {
        return coeffs{c[0].to_ex(), c[1].to_ex(), c[2].to_ex()};
    };
    auto zero = [](const ex& x) { return is_zero_scalar(x); };
    const cyclic_factors along{true, false}, across{false, true}, both{true, true}, none{false, false};
    const GiNaC::symbol& X = R.variable();
    EXPECT_TRUE(is_zero_scalar(R.minimal_polynomial(along) - X));
    EXPECT_TRUE(is_zero_scalar(R.minimal_polynomial(across) - (X * X + W * W)));
    EXPECT_TRUE(is_zero_scalar(R.minimal_polynomial(both) - (GiNaC::pow(X, 3) + W * W * X)));
    EXPECT_TRUE(R.minimal_polynomial(none).is_equal(1));
    for (const cyclic_factors m : {along, across, both, none}) {
        const auto r = R.recombine(u, z, m);
        coeffs d = as_coeffs(full);
        const coeffs rc = as_coeffs(r);
        for (int k = 0; k < 3; ++k) d[k] = d[k] - rc[k];
        EXPECT_TRUE(R.vanishes_modulo(d, m, zero)) << m.axial << m.planar;
        const int deg = (m.axial ? 1 : 0) + (m.planar ? 2 : 0);
        for (int k = deg; k < 3; ++k) EXPECT_TRUE(r[k].is_zero()) << k;
    }
    // the reduced representatives differ from the full one in the whole algebra
    coeffs d = as_coeffs(full);
    const coeffs rc = as_coeffs(R.recombine(u, z, across));
    for (int k = 0; k < 3; ++k) d[k] = d[k] - rc[k];
    EXPECT_FALSE(R.vanishes_modulo(d, both, zero));
    EXPECT_FALSE(R.vanishes_modulo(d, along, zero));
}
