// Tests of the solver for linear ODEs with coefficients polynomial in K = w x
// (engine/mechanics/operator_ode.h): thesis VI.1.26-38, 56-57 (corrected), 68-81.
#include <array>
#include <cmath>
#include <map>
#include <random>

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>
#include <gtest/gtest.h>

#include "scalar/scalar.h"
#include "core/error.h"
#include "mechanics/operator_ode.h"

using namespace symrep;
using namespace symrep::mechanics;
using GiNaC::ex;

namespace {

const GiNaC::realsymbol t("t");
const GiNaC::possymbol W("W");    // |w|
const GiNaC::possymbol w0("w0");  // oscillator frequency

bool same_function(const ex& a, const ex& b) { return quasi_polynomial::from_ex(tidy(a - b), t).is_zero(); }

// expected coefficients as an algebra element against the solver's c_0, c_1, c_2
void expect_coefficients(const operator_solution& s, const std::string& P, const element& want) {
    for (unsigned k = 0; k < 3; ++k)
        EXPECT_TRUE(same_function(s.coefficient(P, k), want[k]))
            << P << " k=" << k << ": " << s.coefficient(P, k) << " vs " << tidy(want[k]);
}

quasi_polynomial qp(const ex& e) { return quasi_polynomial::from_ex(e, t); }

}  // namespace

TEST(OperatorOde, FirstOrderVI_1_26_28) {
    // r' + w x r = q(t) F, r(0) = r0:  r = f0 + w x f1 + w x (w x f2), f_k = phi_k r0 + phi_k * f
    const rotation_operator_algebra R(W);
    const ex q = t + GiNaC::cos(2 * t) + GiNaC::exp(-t) * GiNaC::sin(W * t);
    operator_ode ode;
    ode.A = {{0, 1}, {1}};
    ode.initial = {"r0"};
    ode.forcing = {{qp(q), 0, "F"}};
    const operator_solution s = solve(ode, R, t);
    const element E = R.exp_minus_Kt(t);
    expect_coefficients(s, "r0", E);
    for (unsigned k = 0; k < 3; ++k)
        EXPECT_TRUE(same_function(s.coefficient("F", k), convolution(qp(E[k]), qp(q)).to_ex())) << k;
    const verification v = verify(ode, R, s);
    EXPECT_TRUE(v) << v.detail;
}

TEST(OperatorOde, SecondOrderVI_1_27_31_32) {
    // r'' + 2 w x r' + w x (w x r) = q(t) F:  g_k = phi_k [r0 + (v0 + w x r0) t] + (tau phi_k) * f
    const rotation_operator_algebra R(W);
    const ex q = GiNaC::exp(-2 * t) + t * t;
    operator_ode ode;
    ode.A = {{0, 0, 1}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    ode.forcing = {{qp(q), 0, "F"}};
    const operator_solution s = solve(ode, R, t);
    const element E = R.exp_minus_Kt(t);
    expect_coefficients(s, "r0", E * (R.one() + t * R.K()));
    expect_coefficients(s, "v0", t * E);
    for (unsigned k = 0; k < 3; ++k)  // FORMULAS.md: t phi_k * f is (tau phi_k(tau)) * f
        EXPECT_TRUE(same_function(s.coefficient("F", k), convolution(qp(t * E[k]), qp(q)).to_ex())) << k;
    const verification v = verify(ode, R, s);
    EXPECT_TRUE(v) << v.detail;
}

TEST(OperatorOde, CentrifugalGravityVI_1_57Corrected) {
    // r'' + 2 w x r' + w x (w x r) = g (constant): the corrected VI.1.57 of FORMULAS.md,
    // r0* = r0 + g/W^2, written in powers of K (P0 g = g + K^2 g / W^2)
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{0, 0, 1}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    ode.forcing = {{quasi_polynomial::constant(1, t), 0, "g"}};
    const operator_solution s = solve(ode, R, t);
    const ex S = GiNaC::sin(W * t), C = GiNaC::cos(W * t);
    const element rot = R.make(1, -S / W, (1 - C) / (W * W));  // 1 - (sin/W) K + ((1-cos)/W^2) K^2
    const element sec = R.make(0, t * C, -t * S / W);          // t cos K - (t sin / W) K^2
    expect_coefficients(s, "r0", rot + sec);
    expect_coefficients(s, "v0", t * rot);
    const element g = t * t / 2 * R.make(1, 0, 1 / (W * W)) + (1 / (W * W)) * (rot - R.one() + sec);
    expect_coefficients(s, "g", g);
    EXPECT_TRUE(verify(ode, R, s));
}

TEST(OperatorOde, FoucaultVI_1_68_78) {
    // r'' + 2 w x r' + w x (w x r) + w0^2 r = 0
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{w0 * w0, 0, 1}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    const operator_solution s = solve(ode, R, t);
    const verification v = verify(ode, R, s);
    EXPECT_TRUE(v.residual_zero) << v.detail;
    EXPECT_TRUE(v.initial_ok) << v.detail;
    // VI.1.78: r = e^{-Kt} [r0 cos(w0 t) + (v0 + K r0) sin(w0 t) / w0]
    const element E = R.exp_minus_Kt(t);
    const ex c = GiNaC::cos(w0 * t), sn = GiNaC::sin(w0 * t) / w0;
    expect_coefficients(s, "r0", E * R.make(c, sn, 0));
    expect_coefficients(s, "v0", sn * E);
}

TEST(OperatorOde, ResonantForcingGivesSecularTerms) {
    const rotation_operator_algebra R(W);
    for (unsigned order : {1u, 2u}) {
        operator_ode ode;
        if (order == 1) {
            ode.A = {{0, 1}, {1}};
            ode.initial = {"r0"};
        } else {
            ode.A = {{0, 0, 1}, {0, 2}, {1}};
            ode.initial = {"r0", "v0"};
        }
        ode.forcing = {{qp(GiNaC::cos(W * t)), 0, "F"}, {qp(GiNaC::sin(W * t)), 1, "G"}};
        const operator_solution s = solve(ode, R, t);
        const verification v = verify(ode, R, s);
        EXPECT_TRUE(v) << v.detail;
        bool secular = false;  // some t^k cos / sin with k >= 1
        for (const auto& P : s.terms)
            for (const auto& c : P.c)
                for (const auto& u : c.terms()) secular = secular || (u.k >= order && !u.lambda.im.is_zero());
        EXPECT_TRUE(secular) << order;
    }
    // first order, F: the planar part resonates: c1 contains t cos(W t) / (2)
    operator_ode ode;
    ode.A = {{0, 1}, {1}};
    ode.initial = {"r0"};
    ode.forcing = {{qp(GiNaC::cos(W * t)), 0, "F"}};
    const operator_solution s = solve(ode, R, t);
    EXPECT_TRUE(verify(ode, R, s));
}

TEST(OperatorOde, OmegaZeroIsTheExactLimit) {
    const rotation_operator_algebra R0(0);
    operator_ode ode;
    ode.A = {{0, 1}, {1}};
    ode.initial = {"r0"};
    ode.forcing = {{qp(GiNaC::cos(t)), 0, "F"}};
    const operator_solution s = solve(ode, R0, t);
    expect_coefficients(s, "r0", R0.make(1, -t, t * t / 2));  // limits of phi_0, phi_1, phi_2
    EXPECT_TRUE(verify(ode, R0, s));
    // the general coefficients tend to these as W -> 0
    const rotation_operator_algebra R(W);
    const operator_solution sw = solve(ode, R, t);
    for (unsigned k = 0; k < 3; ++k) {
        const ex lim = GiNaC::series_to_poly(GiNaC::series(sw.coefficient("F", k), W == 0, 1));
        EXPECT_TRUE(same_function(lim, s.coefficient("F", k))) << k << ": " << lim;
    }
    // Foucault and the gravity problem at w = 0
    operator_ode f;
    f.A = {{w0 * w0, 0, 1}, {0, 2}, {1}};
    f.initial = {"r0", "v0"};
    f.forcing = {{qp(GiNaC::exp(-t)), 2, "F"}};
    EXPECT_TRUE(verify(f, R0, solve(f, R0, t)));
}

TEST(OperatorOde, HigherOrderAndRepeatedRoots) {
    // x''' + K x'' + w0^2 x' + K w0^2 x = e^{-t} F  (characteristic (s + K)(s^2 + w0^2));
    // and x'' + 2 x' + x = t e^{-t} (double root -1 resonating with the forcing)
    const rotation_operator_algebra R(W);
    operator_ode a;
    a.A = {{0, w0 * w0}, {w0 * w0}, {0, 1}, {1}};
    a.initial = {"x0", "x1", "x2"};
    a.forcing = {{qp(GiNaC::exp(-t)), 1, "F"}};
    const verification va = verify(a, R, solve(a, R, t));
    EXPECT_TRUE(va) << va.detail;
    operator_ode b;
    b.A = {{1}, {2}, {1}};
    b.initial = {"x0", "v0"};
    b.forcing = {{qp(t * GiNaC::exp(-t)), 0, "F"}};
    const operator_solution sb = solve(b, R, t);
    EXPECT_TRUE(verify(b, R, sb));
    EXPECT_TRUE(same_function(sb.coefficient("F", 0), GiNaC::pow(t, 3) * GiNaC::exp(-t) / 6));
}

TEST(OperatorOde, BadInputThrows) {
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{1}};
    EXPECT_THROW(solve(ode, R, t), domain_error);  // order 0
    ode.A = {{0, 1}, {1}};
    EXPECT_THROW(solve(ode, R, t), domain_error);  // missing initial names
    ode.initial = {"r0"};
    EXPECT_THROW(solve(ode, R, t * 2), domain_error);
    ode.A = {{1}, {0, 1}};  // K x' + x: K is a zero divisor
    EXPECT_THROW(solve(ode, R, t), algebra_error);
    ode.A = {{1}, {W * W, 0, 1}};  // (K^2 + W^2) vanishes at K = i W
    EXPECT_THROW(solve(ode, R, t), algebra_error);
    ode.A = {{t}, {1}};
    EXPECT_THROW(solve(ode, R, t), domain_error);
}

TEST(OperatorOde, NumericAgainstOdeint) {
    // r'' + 2 W r' + W^2 r + w0^2 r = F cos(2 t) + G e^{-t/2} (W the skew matrix of w), compared
    // with runge_kutta_dopri5 (abs/rel 1e-12 per step); agreement required to 1e-8;
    // three random draws of w, r0, v0, F, G in [-1, 1]^3
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{w0 * w0, 0, 1}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    ode.forcing = {{qp(GiNaC::cos(2 * t)), 0, "F"}, {qp(GiNaC::exp(-t / 2)), 0, "G"}};
    const operator_solution s = solve(ode, R, t);
    for (unsigned seed : {12345u, 7u, 2026u}) {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> U(-1.0, 1.0);
        using vec = Eigen::Vector3d;
        const vec w(U(gen), U(gen), U(gen)), r0(U(gen), U(gen), U(gen)), v0(U(gen), U(gen), U(gen)),
            F(U(gen), U(gen), U(gen)), G(U(gen), U(gen), U(gen));
        const double w0v = 1.3;
        Eigen::Matrix3d Wm;
        Wm << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;
        const std::map<std::string, vec> vecs{{"r0", r0}, {"v0", v0}, {"F", F}, {"G", G}};
        using state = std::array<double, 6>;
        auto rhs = [&](const state& x, state& dx, double tt) {
            const vec r(x[0], x[1], x[2]), v(x[3], x[4], x[5]);
            const vec a = -2 * Wm * v - Wm * Wm * r - w0v * w0v * r + F * std::cos(2 * tt) + G * std::exp(-tt / 2);
            for (int i = 0; i < 3; ++i) { dx[i] = v(i); dx[3 + i] = a(i); }
        };
        GiNaC::exmap num{{W, w.norm()}, {w0, w0v}};
        for (double tv : {0.4, 1.7, 4.0}) {
            state x{r0(0), r0(1), r0(2), v0(0), v0(1), v0(2)};
            boost::numeric::odeint::integrate_adaptive(
                boost::numeric::odeint::make_controlled<boost::numeric::odeint::runge_kutta_dopri5<state>>(1e-12, 1e-12),
                rhs, x, 0.0, tv, 0.01);
            num[t] = tv;
            vec r = vec::Zero();
            for (const auto& P : s.terms) {
                vec Wk = vecs.at(P.vector);
                for (unsigned k = 0; k < 3; ++k) {
                    const ex c = GiNaC::evalf(P.c[k].to_ex().subs(num));
                    ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(c)) << c;
                    r += GiNaC::ex_to<GiNaC::numeric>(c).to_double() * Wk;
                    Wk = Wm * Wk;
                }
            }
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(r(i), x[i], 1e-8) << "seed " << seed << " t = " << tv << " component " << i;
        }
    }
}

TEST(OperatorOde, VerifyDetectsWrongSolutions) {
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{0, 0, 1}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    ode.forcing = {{qp(GiNaC::sin(t)), 0, "F"}};
    operator_solution s = solve(ode, R, t);
    ASSERT_TRUE(verify(ode, R, s));
    operator_solution bad = s;
    bad.terms[0].c[1] = bad.terms[0].c[1] + qp(t * t * t);  // wrong residual, right x(0), x'(0)
    const verification v1 = verify(ode, R, bad);
    EXPECT_FALSE(v1.residual_zero);
    EXPECT_TRUE(v1.initial_ok) << v1.detail;
    bad = s;
    bad.terms[1].c[0] = bad.terms[1].c[0] + qp(ex(1));  // wrong v0 part at t = 0
    EXPECT_FALSE(verify(ode, R, bad).initial_ok);
}

TEST(OperatorOde, ProjectorFormAndPolynomialInput) {
    // (26) without forcing in the projector form of Thm VI.1.3.3.1 / VI.1.81:
    // e^{-Kt} = P0 - (sin W t / W) K + cos(W t) P1
    const rotation_operator_algebra R(W);
    const GiNaC::symbol K("K");
    operator_ode ode;
    ode.A = {operator_polynomial_from(K, K), operator_polynomial_from(ex(1), K)};
    ode.initial = {"r0"};
    const operator_solution s = solve(ode, R, t);
    const auto pf = R.projector_form(s.of("r0").c);
    EXPECT_TRUE(same_function(pf[0].to_ex(), 1));
    EXPECT_TRUE(same_function(pf[1].to_ex(), -GiNaC::sin(W * t) / W));
    EXPECT_TRUE(same_function(pf[2].to_ex(), GiNaC::cos(W * t)));
    const operator_polynomial p = operator_polynomial_from(GiNaC::pow(K + 1, 2) + w0 * w0, K);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_TRUE(is_zero_scalar(p[0] - (1 + w0 * w0)));
    EXPECT_TRUE(is_zero_scalar(p[1] - 2));
    EXPECT_THROW(operator_polynomial_from(1 / K, K), domain_error);
}

TEST(OperatorOde, CoriolisGravityVI_1_49) {
    // r'' + 2 w x r' = g: VI.1.49 holds as printed; in powers of K (v0 x w = -K v0,
    // (w.g) w = W^2 g + K^2 g)
    const rotation_operator_algebra R(W);
    operator_ode ode;
    ode.A = {{0}, {0, 2}, {1}};
    ode.initial = {"r0", "v0"};
    ode.forcing = {{quasi_polynomial::constant(1, t), 0, "g"}};
    const operator_solution s = solve(ode, R, t);
    EXPECT_TRUE(verify(ode, R, s));
    const ex S = GiNaC::sin(2 * W * t), C = GiNaC::cos(2 * W * t);
    expect_coefficients(s, "r0", R.one());
    expect_coefficients(s, "v0", R.make(t, -(1 - C) / (2 * W * W), -(S - 2 * W * t) / (2 * GiNaC::pow(W, 3))));
    const ex a = (1 - C) / (4 * W * W), b = (S - 2 * W * t) / (4 * GiNaC::pow(W, 3)),
             c = (2 * W * W * t * t + C - 1) / (4 * GiNaC::pow(W, 4));
    expect_coefficients(s, "g", R.make(a + W * W * c, b, c));
}
