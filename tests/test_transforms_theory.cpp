// Tests of Ch. V as theory (issue 29 item 5): impulses (transforms/distribution.h), signals
// that are not quasi-polynomials (transforms/signal_transform.h), the inner product and the
// hypercomplex Parseval relation (transforms/parseval.h), the algebra-valued inversion
// (transforms/algebra_inversion.h) and monogenicity (transforms/monogenic.h). Exact unless a
// tolerance is stated; the numeric references are mpmath's (30 digits, quad / diff), computed
// apart from the engine.
#include <gtest/gtest.h>

#include "test_util.h"

#include <cmath>

#include "algebra/multicomplex.h"
#include "algebra/sobrero.h"
#include "core/error.h"
#include "scalar/equality.h"
#include "scalar/scalar.h"
#include "transforms/algebra_inversion.h"
#include "transforms/distribution.h"
#include "transforms/inversion.h"
#include "transforms/laplace.h"
#include "transforms/monogenic.h"
#include "transforms/parseval.h"
#include "transforms/signal_transform.h"

using namespace symrep;
using namespace symrep::transforms;
using GiNaC::ex;
using symrep::test::same;
using symrep::test::what_of;

namespace {

const GiNaC::realsymbol t("t"), s("s"), u("u"), v("v"), w("w"), x("x"), y("y"), e("e");

coeffs mc_d(const std::shared_ptr<const multicomplex>& M, const std::vector<ex>& omega) {
    coeffs d = M->zero();
    for (unsigned k = 0; k < omega.size(); ++k) d = algebra::add(d, algebra::scale(omega[k], M->imag_unit(k)));
    return d;
}

coeffs sob(const algebra_ptr& S, const std::vector<ex>& c) {  // sum_k c_k basis_k
    coeffs d = S->zero();
    for (std::size_t k = 0; k < c.size(); ++k) d[k] = c[k];
    return d;
}

double value_of(const ex& x) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(x)).to_double(); }
double re_of(const ex& x) { return value_of(GiNaC::real_part(GiNaC::evalf(x))); }
double im_of(const ex& x) { return value_of(GiNaC::imag_part(GiNaC::evalf(x))); }

bool has_float(const coeffs& c) {
    for (const ex& x : c)
        for (GiNaC::const_preorder_iterator i = x.preorder_begin(); i != x.preorder_end(); ++i)
            if (GiNaC::is_a<GiNaC::numeric>(*i) && !GiNaC::ex_to<GiNaC::numeric>(*i).is_cinteger() &&
                !GiNaC::ex_to<GiNaC::numeric>(*i).is_crational())
                return true;
    return false;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// (V.2.32-35, V.3.33-36) T delta^(k) = d^k over both algebras, exactly, for symbolic d too;
// a shifted impulse gives d^k e^(-a d); c(t) delta'(t - 1) = c(1) delta'(t - 1) - c'(1) delta(t - 1);
// an impulse before 0 is outside a causal signal; products and non-linear arguments are refused.
TEST(TransformsTheory, ImpulsesGiveThePowersOfTheOperator) {
    const auto M = multicomplex::make(1);
    const algebra_ptr S = sobrero::make(2);
    const std::vector<std::pair<algebra_ptr, coeffs>> cases{
        {M, mc_d(M, {3, 1})}, {M, mc_d(M, {u, v})}, {S, sob(S, {2, 1})}, {S, sob(S, {x, 1, 0, y})}};
    for (const auto& [A, d] : cases)
        for (unsigned k = 0; k <= 3; ++k) {
            const algebra_transform T = transform_signal(A, d, dirac(t, k), t);
            EXPECT_TRUE(same(T.value, A->power(d, k))) << A->name() << " k = " << k;
            EXPECT_EQ(T.converges, truth::yes);
        }
    const coeffs d = mc_d(M, {3, 1});
    const coeffs shift = M->exp(algebra::scale(-1, d), 1);
    EXPECT_TRUE(same(transform_signal(M, d, dirac(t - 1, 0), t).value, shift));
    // t delta'(t - 1) = delta'(t - 1) - delta(t - 1): (d - 1) e^(-d)
    EXPECT_TRUE(same(transform_signal(M, d, t * dirac(t - 1, 1), t).value,
                     M->multiply(algebra::sub(d, M->unit()), shift)));
    // delta(2 t - 2) = delta(t - 1)/2
    EXPECT_TRUE(same(transform_signal(M, d, dirac(2 * t - 2, 0), t).value, algebra::scale(ex(1) / 2, shift)));
    EXPECT_TRUE(same(transform_signal(M, d, dirac(t + 1, 0) + GiNaC::exp(-t), t).value,
                     transform(M, d, GiNaC::exp(-t), t).value));
    // the derivative of the language's dirac is the next order
    EXPECT_TRUE(same(dirac(t, 0).diff(t), dirac(t, 1)));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, GiNaC::pow(dirac(t, 0), 2), t); }), "impulse"));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, dirac(t * t - 1, 0), t); }), "not linear in t"));
}

// The windowed ramp 3 (1 - t/2) step(2 - t): exact (pieces of quasi-polynomials, V.1.5 on
// [0, 2]), against mpmath's quadrature: over multicomplex(1) with d = 3 i0 + i1 the components
// F(4 i), F(2 i); over sobrero(2) at d = 2 + eps the coefficients Lf^(k)(2)/k!. Tolerance 1e-25
// at 40 digits (the closed form is exact; it covers the references' 30 printed digits).
TEST(TransformsTheory, WindowedRampIsExact) {
    const ex f = 3 * (1 - t / 2) * GiNaC::step(2 - t);
    const auto M = multicomplex::make(1);
    const algebra_transform T = transform_signal(M, mc_d(M, {3, 1}), f, t);
    EXPECT_FALSE(has_float(T.value));
    EXPECT_EQ(T.converges, truth::yes);
    const auto c = M->idempotent_components(T.value);
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 40;
    EXPECT_NEAR(re_of(c[0]), 0.107390628169557518050203879547, 1e-15);
    EXPECT_NEAR(im_of(c[0]), -0.657247664379057958330488412665, 1e-15);
    EXPECT_NEAR(re_of(c[1]), 0.620116357823854467989688068662, 1e-15);
    EXPECT_NEAR(im_of(c[1]), -1.78380093574047309426473966044, 1e-15);
    const algebra_ptr S = sobrero::make(2);
    const algebra_transform U = transform_signal(S, sob(S, {2, 1}), f, t);
    EXPECT_FALSE(has_float(U.value));
    EXPECT_NEAR(value_of(U.value[0]), 1.13186836458327531761014425797755, 1e-15);
    EXPECT_NEAR(value_of(U.value[1]), -0.395605093749825952830432773932409, 1e-15);
    EXPECT_NEAR(value_of(U.value[2]), 0.126374731770557758648185225392951, 1e-15);
    GiNaC::Digits = saved;
    // the same signal written as a difference of two causal pieces: step(t) - step(t - 2) on a ramp
    const ex g = 3 * (1 - t / 2) * (1 - GiNaC::step(t - 2));
    EXPECT_TRUE(same(transform_signal(M, mc_d(M, {3, 1}), g, t).value, T.value));
    // symbolic d: the closed form is a function of d (checked at the numeric point above)
    const coeffs ds = mc_d(M, {u, v});
    const coeffs Ts = transform_signal(M, ds, f, t).value;
    coeffs at(Ts.size());
    for (std::size_t k = 0; k < Ts.size(); ++k) at[k] = Ts[k].subs(GiNaC::lst{u == 3, v == 1});
    EXPECT_TRUE(same(at, T.value));
}

// exp(-t^2) cos 3t: on the whole line the Gaussian integral, exact, over both algebras (components
// sqrt(pi)/2 (e^(-(W - 3)^2/4) + e^(-(W + 3)^2/4)); over sobrero(2) the Taylor coefficients of
// sqrt(pi) e^((s^2 - 9)/4) cos(3 s/2) at s = 1/2, mpmath's values); for t >= 0 only (an erfc, not
// elementary) by quadrature with its estimate, against mpmath to 1e-12 (the estimate is ~1e-14).
TEST(TransformsTheory, GaussianExactOnTheLineAndByQuadratureOnTheHalfLine) {
    const ex f = GiNaC::exp(-t * t) * GiNaC::cos(3 * t);
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {3, 1});
    const algebra_transform T = transform_signal(M, d, f, t, &f);
    EXPECT_FALSE(has_float(T.value));
    const auto c = M->idempotent_components(T.value);
    const auto F = [](int W) {
        return GiNaC::sqrt(GiNaC::Pi) / 2 * (GiNaC::exp(-ex((W - 3) * (W - 3)) / 4) + GiNaC::exp(-ex((W + 3) * (W + 3)) / 4));
    };
    EXPECT_TRUE(same(c[0], F(4)));
    EXPECT_TRUE(same(c[1], F(2)));
    const algebra_ptr S = sobrero::make(2);
    const algebra_transform U = transform_signal(S, sob(S, {ex(1) / 2, 1}), f, t, &f);
    EXPECT_NEAR(value_of(U.value[0]), 0.145506436683514875479739, 1e-15);
    EXPECT_NEAR(value_of(U.value[1]), -0.1669533127992794533289684, 1e-15);
    EXPECT_NEAR(value_of(U.value[2]), -0.1736035364442552192357556, 1e-15);
    // the half line: quadrature
    const algebra_transform H = transform_signal(M, d, f, t);
    EXPECT_TRUE(contains(H.report, "quadrature"));
    const auto h = M->idempotent_components(H.value);
    EXPECT_NEAR(re_of(h[0]), 0.345099232110722922198940971647, 1e-12);
    EXPECT_NEAR(im_of(h[0]), -0.287028988291389390343542065394, 1e-12);
    EXPECT_NEAR(re_of(h[1]), 0.34595252197772406491419384981, 1e-12);
    EXPECT_NEAR(im_of(h[1]), 0.100676330667293407403562517119, 1e-12);
    const algebra_transform HS = transform_signal(S, sob(S, {1, 1}), f, t);
    EXPECT_NEAR(value_of(HS.value[0]), 0.1742641462884590328616535, 1e-12);
    EXPECT_NEAR(value_of(HS.value[1]), 0.03607733223146326861601548, 1e-12);
    EXPECT_NEAR(value_of(HS.value[2]), -0.0312254801727273985536458, 1e-12);
}

// A divergent integral is refused by name, an undecidable one says "cannot decide", a symbolic d
// without a closed form asks for numbers; a singular integrand misses the quadrature's tolerance.
TEST(TransformsTheory, RefusalsNameTheReason) {
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {3, 1});
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, 1 / (1 + t * t), t); }), "cannot decide"));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, GiNaC::exp(t * t), t); }), "diverges"));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, GiNaC::exp(t) * GiNaC::step(t - 1), t); }), "diverges"));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, mc_d(M, {u, v}), GiNaC::exp(-t * t), t); }),
                         "numeric coordinates"));
    EXPECT_FALSE(contains(what_of([&] { transform_signal(M, d, 1 / (t - 1) * GiNaC::step(2 - t), t); }),
                          "<no exception>"));
    EXPECT_TRUE(contains(what_of([&] { transform_signal(M, d, GiNaC::step(t * t - 1), t); }), "not linear"));
    // a finite window is exact at a d where p(d) is singular (removable): by quadrature then
    const coeffs d0 = mc_d(M, {1, 1});  // Omega_1 = 0: p(d) = d singular for the ramp
    const algebra_transform R = transform_signal(M, d0, 3 * (1 - t / 2) * GiNaC::step(2 - t), t);
    EXPECT_NEAR(value_of(M->idempotent_components(R.value)[1]), 3.0, 1e-12);  // int_0^2 3 (1 - t/2) dt
}

// (Thm V.2.4, V.2.43-49) inner product and Parseval: the time side L[f g](0), the frequency side
// by residues (a double pole included, a symbolic rate a > 0), equal exactly; over multicomplex(1)
// and (2) the algebra-valued relation (conjugate, components) proved; the frequency integral by
// quadrature within 1e-10 (its estimate is ~1e-15). The printed (41) (only i0 negated in B) does
// not give the components F conj G; a signal not in L2 is refused by name.
TEST(TransformsTheory, ParsevalRelationOverTheMulticomplexAlgebra) {
    EXPECT_TRUE(same(inner_product(GiNaC::exp(-t), GiNaC::exp(-2 * t) * GiNaC::cos(t), t), ex(3) / 10));
    EXPECT_TRUE(same(parseval_frequency_side(t * GiNaC::exp(-t), GiNaC::exp(-t) * GiNaC::sin(2 * t), t), ex(1) / 8));
    const GiNaC::possymbol a("a");
    EXPECT_TRUE(same(parseval_frequency_side(GiNaC::exp(-a * t), GiNaC::exp(-a * t), t), 1 / (2 * a)));
    EXPECT_TRUE(same(energy(GiNaC::exp(-a * t), t), 1 / (2 * a)));
    for (const ex& f : std::vector<ex>{t * GiNaC::exp(-t), GiNaC::exp(-t)}) {
        const auto M = multicomplex::make(1);
        const ex g = GiNaC::exp(-t) * GiNaC::sin(2 * t);
        const parseval_result r = parseval(M, f, g, t);
        EXPECT_EQ(r.proved, truth::yes) << r.report;
        EXPECT_TRUE(same(r.element, algebra::scale(r.time_side, M->unit())));
        ASSERT_TRUE(r.has_quadrature);
        EXPECT_NEAR(r.quadrature, value_of(r.time_side), 1e-10);
        EXPECT_LT(r.quadrature_error, 1e-10);
    }
    // the printed conjugate (41) in B: i0-coordinates negated
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {u, v});
    const coeffs Tf = transform(M, d, GiNaC::exp(-t), t).value;
    coeffs printed = Tf;
    printed[1] = -printed[1];  // i0
    printed[3] = -printed[3];  // i0 i1
    const auto P = M->idempotent_components(M->multiply(Tf, printed));
    const auto D = M->idempotent_components(d);
    const ex F = 1 / (s + 1);
    EXPECT_EQ(decide_zero(GiNaC::normal(P[0] - F.subs(s == D[0]) * F.subs(s == -D[0]))).is_zero, truth::no);
    EXPECT_TRUE(same(hypercomplex_conjugate(M, M->imag_unit(1)), algebra::scale(-1, M->imag_unit(1))));
    EXPECT_TRUE(contains(what_of([&] { parseval(M, GiNaC::exp(t), GiNaC::exp(-t), t); }), "not in L2"));
    EXPECT_TRUE(contains(what_of([&] { hypercomplex_conjugate(sobrero::make(1), sobrero::make(1)->unit()); }),
                         "multicomplex"));
}

// (Thm V.2.3, V.2.37-39; Thm V.3.3, V.3.38-41) the algebra-valued inversion: derived transforms
// over multicomplex(0), (1) and sobrero(2) inverted back to their signals; a two-sided signal
// gives both halves; impulses come back; every component's numeric inversion integral
// (fourier_inversion) gives f(0.7) to 1e-12; non-transforms and poles on the axis are refused.
TEST(TransformsTheory, AlgebraValuedInversion) {
    const ex f1 = GiNaC::exp(-t) * GiNaC::cos(2 * t), f2 = t * GiNaC::exp(-2 * t);
    for (unsigned n : {0u, 1u}) {
        const auto M = multicomplex::make(n);
        const coeffs d = n == 0 ? mc_d(M, {u}) : mc_d(M, {u, v});
        for (const ex& f : {f1, f2}) {
            const algebra_inverse r = inverse_transform(M, transform(M, d, f, t).value, d, t);
            EXPECT_TRUE(same(r.f, f));
            EXPECT_TRUE(same(r.g, 0));
        }
    }
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {u, v});
    const algebra_inverse two = inverse_transform(M, transform_two_sided(M, d, GiNaC::exp(-t), GiNaC::exp(t), t).value, d, t);
    EXPECT_TRUE(same(two.f, GiNaC::exp(-t)));
    EXPECT_TRUE(same(two.g, GiNaC::exp(t)));
    const ex imp = dirac(t, 1) + 2 * dirac(t, 0) + GiNaC::exp(-2 * t);
    EXPECT_TRUE(same(inverse_transform(M, transform_signal(M, d, imp, t).value, d, t).f, imp));
    // the inversion integral of each component at t0 = 0.7 (V.2.37)
    const coeffs Td = transform(M, d, f1, t).value;
    const auto Tc = M->idempotent_components(Td);
    const auto Dc = M->idempotent_components(d);
    for (std::size_t p = 0; p < Tc.size(); ++p) {
        const ex xs = (s - Dc[p].expand().coeff(u, 0)) / Dc[p].expand().coeff(u, 1);
        const ex Fp = GiNaC::normal(Tc[p].subs(u == xs)).subs(v == 0);
        EXPECT_NEAR(fourier_inversion(Fp, s, 0.7).value, std::exp(-0.7) * std::cos(1.4), 1e-12);
    }
}

// (Thm V.3.3, V.3.38-41) the Sobrero inversion of derived transforms; a coefficient that breaks
// V.3.40 is refused.
TEST(TransformsTheory, AlgebraValuedInversionOverTheSobreroAlgebra) {
    const ex f2 = t * GiNaC::exp(-2 * t);
    // sobrero(2): d = x + eps, and d = x + eps + j y
    const algebra_ptr S = sobrero::make(2), S1 = sobrero::make(1);
    const ex f = t * GiNaC::exp(-t) * GiNaC::sin(t);
    EXPECT_TRUE(same(inverse_transform(S, transform(S, sob(S, {x, 1}), f, t).value, sob(S, {x, 1}), t).f, f));
    const coeffs dj = sob(S1, {x, 1, y});
    EXPECT_TRUE(same(inverse_transform(S1, transform(S1, dj, f2, t).value, dj, t).f, f2));
    coeffs bad = transform(S, sob(S, {x, 1}), f2, t).value;
    bad[1] = bad[1] + 1 / (x + 5);
    EXPECT_TRUE(contains(what_of([&] { inverse_transform(S, bad, sob(S, {x, 1}), t); }), "V.3.40"));
}

// Not transforms over multicomplex(1): components from two different signals; a pole on the
// imaginary axis.
TEST(TransformsTheory, AlgebraValuedInversionRefusesNonTransforms) {
    const ex f1 = GiNaC::exp(-t) * GiNaC::cos(2 * t), f2 = t * GiNaC::exp(-2 * t);
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {u, v});
    const auto mixed = M->from_idempotent_components(
        {M->idempotent_components(transform(M, d, f1, t).value)[0], M->idempotent_components(transform(M, d, f2, t).value)[1]});
    EXPECT_TRUE(contains(what_of([&] { inverse_transform(M, mixed, d, t); }), "different signals"));
    EXPECT_TRUE(contains(what_of([&] { inverse_transform(M, transform(M, d, GiNaC::cos(t), t).value, d, t); }),
                         "imaginary axis"));
}

// (Thm V.2.1 with V.2.21; Thm V.3.1 with V.3.19) the derived transforms are monogenic: every
// generalized Cauchy-Riemann condition proved; the printed conjugate (41) of a transform, a
// function of (-omega0, omega1), and the coordinatewise j-conjugate over sobrero are not (a
// witness point).
TEST(TransformsTheory, TransformsAreMonogenic) {
    for (const ex& f : std::vector<ex>{GiNaC::exp(-t) * GiNaC::cos(2 * t)}) {
        const auto M = multicomplex::make(1);
        const coeffs d = mc_d(M, {u, v});
        const coeffs T = transform(M, d, f, t).value;
        const monogenicity m = monogenic(M, T, d);
        EXPECT_EQ(m.holds, truth::yes) << m.report;
        EXPECT_TRUE(contains(m.report, "i0 dF/dv = i1 dF/du: proved"));
    }
    const auto M = multicomplex::make(1);
    const coeffs d = mc_d(M, {u, v});
    coeffs printed = transform(M, d, GiNaC::exp(-t), t).value;
    printed[1] = -printed[1];
    printed[3] = -printed[3];
    EXPECT_EQ(monogenic(M, printed, d).holds, truth::no);
}

// (Thm V.3.1, V.3.19) over sobrero(1) with d = x + e eps + j y: j dF/dx = dF/dy and
// eps dF/dx = dF/de proved; the coordinatewise j-conjugate is not monogenic.
TEST(TransformsTheory, SobreroTransformsAreMonogenic) {
    const algebra_ptr S = sobrero::make(1);
    const coeffs ds = sob(S, {x, e, y});  // x + e eps + j y
    const coeffs U = transform(S, ds, GiNaC::exp(-2 * t), t).value;
    const monogenicity m = monogenic(S, U, ds);
    EXPECT_EQ(m.holds, truth::yes) << m.report;
    coeffs conj = U;
    for (std::size_t k = 2; k < 4; ++k) conj[k] = -conj[k];
    EXPECT_EQ(monogenic(S, conj, ds).holds, truth::no);
}
