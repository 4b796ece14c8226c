// tests/test_signals_theory.cpp -- issue 29, items 6-8: digital systems (IV.3 with the shift,
// remarks 3-4: sequence_response on cos(a k), cos(k pi/n) and rational-base exponentials, the Z
// transform), `response` for any p (a factor without roots in radicals: the particular response
// still derived, also in resonance), and the modulation-preserving filter with a real phase shift
// (IV.3.2 c, V.2.54-67 with the sign of FORMULAS.md).
//
// References are independent of symrep's derivations: the recurrence x(j+1) = x(j)/2 + f(j) run
// from x(0) = 0 with GiNaC's 40-digit evaluation of f(j); partial sums of the Z series; the closed
// form of V.2.67 (corrected) at a point. Tolerances: 1e-25 for 40-digit evaluations of exact
// closed forms (rounding ~1e-38 times the few terms' sizes); 1e-30 for Z series truncated after
// 300 terms at z = 3 (tail below 300 3^-300).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "lang/interpreter.h"
#include "scalar/equality.h"
#include "scalar/scalar.h"

using namespace symrep;

namespace {

GiNaC::numeric at40(const GiNaC::ex& x) {
    GiNaC::numeric v;
    EXPECT_TRUE(evaluate_numeric(x, 40, v)) << x;
    return v;
}

}  // namespace

// Item 6: x(k+1) - x(k)/2 = f(k), x(0) = 0 (IV.3.7, 19), for inputs the audit found undecided or
// failing and held-out ones of the same classes (cos(a k) for several a, rational bases written
// any way).
TEST(SignalsTheory, DigitalResponsesAgainstTheRecurrence) {
    std::ostringstream out, err;
    lang::session S(out, err);
    const GiNaC::symbol& k = GiNaC::ex_to<GiNaC::symbol>(S.evaluate("k").as_ex());
    for (const std::string f : {"cos(k)", "cos(k*pi/3)", "k*3^(-k)", "cos(2*k)", "sin(3*k/2)", "cos(k*pi/5)",
                                "k*(2/3)^k", "9^(-k/2)*k"}) {
        const lang::list R = S.evaluate("sequence_response([1, -1/2], [1], " + f + ", k)").as_list();
        ASSERT_EQ(R.size(), 3u) << f;
        const GiNaC::ex fk = S.evaluate(f).as_ex(), particular = R[0].as_ex(), zero_state = R[1].as_ex();
        GiNaC::numeric x = 0;  // the recurrence
        for (int j = 0; j <= 8; ++j) {
            EXPECT_LT(GiNaC::abs(at40(zero_state.subs(k == j)) - x), GiNaC::numeric("1e-25")) << f << " at k = " << j;
            // the particular response solves the difference equation
            EXPECT_LT(GiNaC::abs(at40(particular.subs(k == j + 1) - particular.subs(k == j) / 2 - fk.subs(k == j))),
                      GiNaC::numeric("1e-25"))
                << f;
            x = x / 2 + at40(fk.subs(k == j));
        }
    }
}

// Item 6, remark 4: Z{f} from the representation against the series, and the Z transfer function:
// Z{x} = Z{f}/p(z) for the zero-state x of p(E) x = f; with q = z + 1 (b = [1, 1]) the corrected
// relation p Z{x} = q Z{f} - f(0) z (z_transform.h).
TEST(SignalsTheory, ZTransformAndTransferFunction) {
    std::ostringstream out, err;
    lang::session S(out, err);
    const GiNaC::symbol& k = GiNaC::ex_to<GiNaC::symbol>(S.evaluate("k").as_ex());
    for (const std::string f : {"cos(k*pi/3)", "k*3^(-k)", "k^2*2^k + 1", "cos(k)"}) {
        const GiNaC::ex F = S.evaluate("z_transform(" + f + ", k, z)").as_ex();
        const GiNaC::ex fk = S.evaluate(f).as_ex();
        const GiNaC::ex z = S.evaluate("z").as_ex();
        GiNaC::numeric sum = 0, zk = 1;
        for (int j = 0; j < 300; ++j) {
            sum += at40(fk.subs(k == j)) / zk;
            zk *= 3;
        }
        EXPECT_LT(GiNaC::abs(at40(F.subs(z == 3)) - sum), GiNaC::numeric("1e-30")) << f;
    }
    EXPECT_TRUE(S.evaluate("z_transform(cos(k*pi/3), k, z) == (z^2 - z/2)/(z^2 - z + 1)").as_bool());
    EXPECT_TRUE(S.evaluate("z_transform(sequence_response([1, -1/2], [1], k*3^(-k), k)[1], k, z) == "
                           "z_transform(k*3^(-k), k, z)/(z - 1/2)")
                    .as_bool());
    EXPECT_TRUE(S.evaluate("(z - 1/3)*z_transform(sequence_response([1, -1/3], [1, 1], 2^k + k, k)[1], k, z) == "
                           "(z + 1)*z_transform(2^k + k, k, z) - z")
                    .as_bool());
}

// Item 7: p with a factor of degree 5 (X^5 - X + 1, no roots in radicals): the particular response
// is derived, passed or resonant; the zero-state part is refused by name, never guessed.
TEST(SignalsTheory, ResponseWithAQuinticFactor) {
    std::ostringstream out, err;
    lang::session S(out, err);
    // p = X^5 - X + 1, p(-1) = 1: passed
    lang::list R = S.evaluate("response([1, 0, 0, 0, -1, 1], [1], exp(-t), t)").as_list();
    EXPECT_TRUE(S.evaluate("response([1, 0, 0, 0, -1, 1], [1], exp(-t), t)[0] == exp(-t)").as_bool());
    EXPECT_EQ(R[1].as_string(), "not derived");
    EXPECT_NE(R[2].as_string().find("X^5 - X + 1"), std::string::npos) << R[2].as_string();
    // p = (X + 1)(X^5 - X + 1): resonant with exp(-t); p'(-1) = 1, so x = t e^(-t)
    R = S.evaluate("response([1, 1, 0, 0, -1, 0, 1], [1], exp(-t), t)").as_list();
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(GiNaC::normal(R[0].as_ex() / S.evaluate("t*exp(-t)").as_ex())) &&
                GiNaC::normal(R[0].as_ex() / S.evaluate("t*exp(-t)").as_ex()).is_equal(1))
        << R[0].as_ex();
    EXPECT_NE(R[2].as_string().find("resonant"), std::string::npos);
    EXPECT_EQ(R[1].as_string(), "not derived");
    // digital: (X - 1)(X^5 - X + 1) x = 1 gives x = k (p'(1) = 1)
    R = S.evaluate("sequence_response([1, -1, 0, 0, -1, 2, -1], [1], 1, k)").as_list();
    EXPECT_TRUE(R[0].as_ex().is_equal(S.evaluate("k").as_ex())) << R[0].as_ex();
}

// Item 8: x'' + 4 x' + 25 x = 3 cos(4 t - a) cos(t - b) on multicomplex(1), d = 4 i0 + i1:
// |H(5 i)| = |H(3 i)| = 1/20 (Omega_0^2 + Omega_1^2 = 34), alpha_0 = -pi/2, alpha_1 = -atan(3/4),
// so H-hat = H e^(i0 Psi_0 + i1 Psi_1) (V.2.65) with 2 Psi_0 = alpha_0 + alpha_1, 2 Psi_1 =
// alpha_0 - alpha_1, and the response is (3/20) cos(4 t - a + Psi_0) cos(t - b + Psi_1) (V.2.67
// with FORMULAS.md's sign).
TEST(SignalsTheory, FilterWithARealPhaseShift) {
    std::ostringstream out, err;
    lang::session S(out, err);
    S.run_string("M := multicomplex(1)\ndM := 4*imag_unit(M, 0) + imag_unit(M, 1)\n"
                 "C := response_over([1, 4, 25], [1], 3*cos(4*t - a)*cos(t - b), t, dM)\nAM := amplitude_modulated(C[1])",
                 "test");
    EXPECT_TRUE(S.evaluate("AM[0]").as_bool()) << err.str();
    EXPECT_TRUE(S.evaluate("AM[1] == 3/20").as_bool());
    EXPECT_TRUE(S.evaluate("AM[2][0] == a + pi/4 + atan(3/4)/2").as_bool());
    EXPECT_TRUE(S.evaluate("AM[2][1] == b + pi/4 - atan(3/4)/2").as_bool());
    EXPECT_NE(S.evaluate("C[2]").as_string().find("not distorted"), std::string::npos);
    // the closed form V.2.67 (corrected sign) at a = 3/10, b = 11/10, t = 7/10
    const GiNaC::ex x = S.evaluate("subs(C[0], [a = 3/10, b = 11/10, t = 7/10])").as_ex();
    const GiNaC::ex psi0 = (-GiNaC::Pi / 2 - GiNaC::atan(GiNaC::numeric(3, 4))) / 2,
                    psi1 = (-GiNaC::Pi / 2 + GiNaC::atan(GiNaC::numeric(3, 4))) / 2;
    const GiNaC::ex t = GiNaC::numeric(7, 10);
    const GiNaC::ex expected = GiNaC::numeric(3, 20) * GiNaC::cos(4 * t - GiNaC::numeric(3, 10) + psi0) *
                               GiNaC::cos(t - GiNaC::numeric(11, 10) + psi1);
    // 1e-15: the reference built here agrees to ~1e-20 only (part of it is evaluated at GiNaC's default
    // precision), far below the O(1) gap of the printed sign below
    EXPECT_LT(GiNaC::abs(at40(x - expected)), GiNaC::numeric("1e-15"));
    // the printed V.2.67 sign (phi_k + Psi_k) is off by O(1) here
    const GiNaC::ex printed = GiNaC::numeric(3, 20) * GiNaC::cos(4 * t - GiNaC::numeric(3, 10) - psi0) *
                              GiNaC::cos(t - GiNaC::numeric(11, 10) - psi1);
    EXPECT_GT(GiNaC::abs(at40(x - printed)), GiNaC::numeric("1e-3"));
    // phases pi/3 and pi/4 (each e^(i c pi) its own algebraic number; one base e^(i pi/12) as nested
    // radicals would hide the relations) and numeric phases: the audit's "internal check failed"
    EXPECT_TRUE(S.evaluate("amplitude_modulated(response_over([1, 4, 25], [1], 3*cos(4*t - pi/3)*cos(t - pi/4), t, dM)[1])[0]")
                    .as_bool());
    EXPECT_TRUE(S.evaluate("amplitude_modulated(response_over([1, 4, 25], [1], cos(4*t - 1)*cos(t + 1/2), t, dM)[1])[0]")
                    .as_bool());
}

// Item 10: IV.1.2.31-35 corrected. On sobrero(2) with d = -1/2 + eps + 2 j, a second-order signal
// A e^(-t/2) cos(2 t - phi) is represented in eps^2 C; the unit (R) represents a signal of order 6,
// checked against the signal's own least equation (annihilator), independent of sobrero_subalgebra.
TEST(SignalsTheory, SobreroSecondOrderSignalsLiveInEpsNC) {
    std::ostringstream out, err;
    lang::session S(out, err);
    S.run_string("S := sobrero(2)\ndS := -1/2 + basis(S, 1) + 2*basis(S, 3)", "test");
    const lang::list second = S.evaluate("sobrero_subalgebra(represent(3*exp(-t/2)*cos(2*t - 1), t, dS))").as_list();
    ASSERT_EQ(second[0].as_list().size(), 1u);
    EXPECT_EQ(second[0].as_list()[0].as_string(), "eps^2 C");
    EXPECT_TRUE(second[1].as_ex().is_equal(2));
    for (const std::string w : {"one(S)", "basis(S, 3)", "basis(S, 1) + basis(S, 4)", "basis(S, 2)", "basis(S, 5)",
                                "3*basis(S, 1)"}) {
        const lang::list place = S.evaluate("sobrero_subalgebra(" + w + ")").as_list();
        const GiNaC::ex order = S.evaluate("degree(annihilator(signal(" + w + ", t, dS), t, X), X)").as_ex();
        EXPECT_TRUE(place[1].as_ex().is_equal(order)) << w << ": " << place[1].as_ex() << " vs " << order;
    }
    EXPECT_EQ(S.evaluate("sobrero_subalgebra(one(S))").as_list()[0].as_list().size(), 3u);  // R, C, P
    EXPECT_TRUE(S.evaluate("sobrero_subalgebra(one(S))[1]").as_ex().is_equal(6));
}

// The generic scalar pieces these items needed (scalar.h): the zero test relates the angles of
// one monomial over the lcm of their denominators, the multiples of pi over one algebraic
// e^(i pi/L), and rational powers with symbolic exponents over primes; atan2_exact proves an
// angle or leaves atan2. Nonzero stays not proved.
TEST(SignalsTheory, ZeroTestAnglesPowersAndExactAtan2) {
    using GiNaC::cos;
    using GiNaC::sin;
    using GiNaC::Pi;
    const GiNaC::symbol k("k");
    const GiNaC::ex h = GiNaC::numeric(1, 2);
    EXPECT_TRUE(is_zero_scalar(cos(GiNaC::ex(2)) - 2 * GiNaC::pow(cos(GiNaC::ex(1)), 2) + 1));
    EXPECT_TRUE(is_zero_scalar(cos(GiNaC::ex(1)) - 2 * GiNaC::pow(cos(h), 2) + 1));
    EXPECT_TRUE(is_zero_scalar(cos(k + 1) - cos(GiNaC::ex(1)) * cos(k) + sin(GiNaC::ex(1)) * sin(k)));
    EXPECT_TRUE(is_zero_scalar(cos((k + 2) * Pi / 5) + cos(k * Pi / 5) - (1 + GiNaC::sqrt(GiNaC::ex(5))) / 2 * cos((k + 1) * Pi / 5)));
    EXPECT_TRUE(is_zero_scalar(GiNaC::pow(GiNaC::numeric(1, 3), k) - GiNaC::pow(3, -k)));
    EXPECT_TRUE(is_zero_scalar(GiNaC::pow(9, -k / 2) - GiNaC::pow(3, -k)));
    EXPECT_FALSE(is_zero_scalar(cos(GiNaC::ex(1)) - cos(h)));
    EXPECT_FALSE(is_zero_scalar(GiNaC::pow(GiNaC::numeric(1, 3), k) - GiNaC::pow(2, -k)));
    EXPECT_TRUE(atan2_exact(GiNaC::sqrt(GiNaC::ex(3)) / 2, h).is_equal(Pi / 3));
    EXPECT_TRUE(atan2_exact(-GiNaC::sqrt(GiNaC::ex(3)) / 2, -h).is_equal(-2 * Pi / 3));
    EXPECT_TRUE(atan2_exact(sin(GiNaC::ex(1)), cos(GiNaC::ex(1))).is_equal(1));
    EXPECT_TRUE(atan2_exact(GiNaC::sqrt(1 - GiNaC::pow(cos(GiNaC::ex(2)), 2)), cos(GiNaC::ex(2))).is_equal(2));
    // not an angle it can prove: unchanged
    EXPECT_TRUE(GiNaC::is_a<GiNaC::function>(atan2_exact(GiNaC::sqrt(GiNaC::ex(2)) / 3, GiNaC::numeric(1, 6))));
    // sin(1) with the wrong sign: 1 is not the angle of (-sin 1, cos 1)
    EXPECT_FALSE(atan2_exact(-sin(GiNaC::ex(1)), cos(GiNaC::ex(1))).is_equal(1));
}
