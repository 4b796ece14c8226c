// Tests of signals/multicomplex_signals.h (thesis IV.1.1): signals over the multicomplex
// algebra. Identities in t are checked at 7 values of t with 30 digits against a
// tolerance of 1e-25 (the forms compared are sums of products of cosines whose exact
// equality needs trigonometric identities the zero test does not apply); everything else
// is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "algebra/multicomplex.h"
#include "algebra/sobrero.h"
#include "core/error.h"
#include "lang/interpreter.h"
#include "scalar/equality.h"
#include "scalar/scalar.h"
#include "signals/multicomplex_signals.h"
#include "signals/representation.h"
#include "signals/response.h"

using namespace symrep;
using namespace symrep::signals;
using GiNaC::ex;

namespace {

const GiNaC::symbol t("t"), X("X");

bool same_function(const ex& a, const ex& b) {
    for (int x10 : {0, 3, 17, 29, 50, 113, 200}) {  // t = x10 / 10, exact
        const GiNaC::numeric x(x10, 10);
        GiNaC::numeric v;
        if (!evaluate_numeric((a - b).subs(t == x), 30, v)) return false;
        if (GiNaC::abs(v) > GiNaC::numeric("1e-25")) {
            return false;
        }
    }
    return true;
}

std::size_t unit_index(const multicomplex& A, unsigned k) {
    const coeffs u = A.imag_unit(k);
    for (std::size_t i = 0; i < u.size(); ++i)
        if (!u[i].is_zero()) return i;
    return 0;
}

coeffs carrier_element(const multicomplex& A, const std::vector<ex>& omega) {
    coeffs d(A.dim(), ex(0));
    for (unsigned k = 0; k < omega.size(); ++k) d[unit_index(A, k)] = omega[k];
    return d;
}

}  // namespace

// (IV.1.15-16, 24-25) Psi^-1(w) = scal(w exp(d t)): v_p represents v_p^2 prod_k cos(omega_k t - p_k pi/2)
// (the printed Psi(phi_p) = v_p up to the sign of v_p^2), Psi^-1(d w) = Psi^-1(w)', Psi(Psi^-1(w)) = w.
TEST(MulticomplexSignals, RepresentationAndProductsOfCosines) {
    for (unsigned n : {1u, 2u}) {
        const auto A = multicomplex::make(n);
        const std::vector<ex> omega = n == 1 ? std::vector<ex>{3, 1} : std::vector<ex>{7, 2, ex(1) / 2};
        const coeffs d = carrier_element(*A, omega);
        const auto R = represent_on(A, d);
        for (std::size_t p = 0; p < A->dim(); ++p) {
            const coeffs v = A->gray_basis(p);
            std::size_t m = 0;
            while (v[m].is_zero()) ++m;
            ex phi = 1;
            for (unsigned k = 0; k <= n; ++k)
                phi *= ((m & unit_index(*A, k)) ? GiNaC::sin(omega[k] * t) : GiNaC::cos(omega[k] * t));
            const ex square = A->multiply(v, v)[0] * v[m] * v[m];  // v_p^2 = +-1
            EXPECT_TRUE(is_zero_scalar(tidy((signal_of(R, v, t) - square * phi).expand()))) << "n = " << n << ", p = " << p;
        }
        coeffs w(A->dim());
        for (std::size_t i = 0; i < w.size(); ++i) w[i] = ex(int(i * 3 % 5) - 2) / 3;
        const ex f = signal_of(R, w, t);
        EXPECT_TRUE(same_function(signal_of(R, A->multiply(d, w), t), f.diff(t)));
        const coeffs back = element_of(R, f, t);
        for (std::size_t i = 0; i < w.size(); ++i) EXPECT_TRUE(is_zero_scalar(tidy(back[i] - w[i]))) << i;
    }
}

// (IV.1.18, every digit pattern; = IV.1.51 with alpha_k = omega_k t - p_k pi/2)
// 2^n prod_k cos(omega_k t - p_k pi/2) = sum over sign vectors s of (prod_k s_k^p_k)
// cos(Omega_s t - (pi/2) sum p_i), Omega_s = omega_0 + sum s_k omega_k; and the idempotent form of
// the signal (IV.1.17, through exp by idempotent components) equals the product form (IV.1.15).
TEST(MulticomplexSignals, ProductOfCosinesIdentities) {
    for (unsigned n : {1u, 2u}) {
        const auto A = multicomplex::make(n);
        const std::vector<ex> omega = n == 1 ? std::vector<ex>{3, 1} : std::vector<ex>{7, 2, ex(1) / 2};
        const coeffs d = carrier_element(*A, omega);
        const auto R = represent_on(A, d);
        const std::size_t P = std::size_t{1} << n;
        for (std::size_t m = 0; m < A->dim(); ++m) {
            std::vector<int> digit(n + 1);
            int total = 0;
            for (unsigned k = 0; k <= n; ++k) total += digit[k] = (m & unit_index(*A, k)) ? 1 : 0;
            ex lhs = ex(int(P));
            for (unsigned k = 0; k <= n; ++k) lhs *= GiNaC::cos(omega[k] * t - digit[k] * GiNaC::Pi / 2);
            ex rhs = 0;
            for (std::size_t q = 0; q < P; ++q) {
                ex Omega = omega[0];
                int sign = 1;
                for (unsigned k = 1; k <= n; ++k) {
                    const int s = (q >> (k - 1)) & 1 ? -1 : 1;
                    Omega += s * omega[k];
                    if (digit[k] && s < 0) sign = -sign;
                }
                rhs += sign * GiNaC::cos(Omega * t - total * GiNaC::Pi / 2);
            }
            EXPECT_TRUE(same_function(lhs, rhs)) << "n = " << n << ", m = " << m;
            // the engine's two routes to the same signal: product form and idempotent form
            const coeffs e = A->basis_vector(m);
            const ex idempotent_form = tidy(A->multiply(e, A->exp(d, t))[0]);
            EXPECT_TRUE(same_function(signal_of(R, e, t), idempotent_form)) << m;
            EXPECT_TRUE(same_function(signal_of(R, e, t) * int(P), (A->multiply(e, e)[0]) * lhs)) << m;
        }
    }
}

// (IV.1.43-49) zero divisors represent degenerate signals: an idempotent e_p represents
// cos(Omega_p t)/2^n (IV.1.32) and i0 e_p -sin(Omega_p t)/2^n (IV.1.34 up to the sign), with
// least equation X^2 + Omega_p^2; a divisor of r ranks satisfies an equation of order 2^(n+1) - 2r.
TEST(MulticomplexSignals, ZeroDivisorsAreDegenerateSignals) {
    const auto A = multicomplex::make(2);
    const std::vector<ex> omega{7, 2, ex(1) / 2};
    const coeffs d = carrier_element(*A, omega);
    const auto R = represent_on(A, d);
    const std::vector<ex> Omega = A->generating_frequencies(omega);
    for (std::size_t p = 0; p < 4; ++p) {
        const coeffs e = A->idempotent(p);
        EXPECT_TRUE(same_function(signal_of(R, e, t), GiNaC::cos(Omega[p] * t) / 4)) << p;
        EXPECT_TRUE(same_function(signal_of(R, A->multiply(A->imag_unit(0), e), t), -GiNaC::sin(Omega[p] * t) / 4));
        EXPECT_TRUE(is_zero_scalar((annihilator(signal_of(R, e, t), t, X) - (X * X + Omega[p] * Omega[p])).expand()));
    }
    // ranks 1 and 3 vanish: order 8 - 4
    coeffs w = A->add(A->idempotent(0), A->scale(3, A->idempotent(2)));
    EXPECT_EQ(A->zero_divisor_ranks(w), (std::vector<std::size_t>{1, 3}));
    EXPECT_EQ(annihilator(signal_of(R, w, t), t, X).degree(X), 4);
    EXPECT_EQ(annihilator(signal_of(R, A->unit(), t), t, X).degree(X), 8);
}

// (IV.1.26-30) a cos(omega_0 t) + b sin(omega_0 t) = A cos(omega_0 t - theta) = the signal.
TEST(MulticomplexSignals, AmplitudeAndPhaseModulation) {
    const auto A = multicomplex::make(2);
    const std::vector<ex> omega{7, 2, ex(1) / 2};
    const coeffs d = carrier_element(*A, omega);
    const auto R = represent_on(A, d);
    coeffs w(A->dim());
    for (std::size_t i = 0; i < w.size(); ++i) w[i] = ex(int(i * 5 % 7) - 3) / 2;
    const ex f = signal_of(R, w, t);
    const auto c = carriers_of(*A, d);
    ASSERT_TRUE(c.has_value());
    const modulation m = modulation_of(R, *c, w, t);
    EXPECT_TRUE(same_function(m.a * GiNaC::cos(7 * t) + m.b * GiNaC::sin(7 * t), f));
    EXPECT_TRUE(same_function(m.amplitude * GiNaC::cos(7 * t - m.phase), f));
    // a and b do not contain the carrier omega_0
    EXPECT_FALSE(m.a.has(GiNaC::cos(7 * t)) || m.b.has(GiNaC::sin(7 * t)));
    // d with a product component is not of the form IV.1.9
    coeffs bad = d;
    bad[unit_index(*A, 1) | unit_index(*A, 2)] = 1;
    EXPECT_FALSE(carriers_of(*A, bad).has_value());
}

// (IV.1.50-57, 64-68) amplitude modulation decided without branches of arg.
TEST(MulticomplexSignals, AmplitudeModulatedElements) {
    const auto A = multicomplex::make(2);
    const std::vector<ex> phi{ex(1) / 3, 2, ex(-3) / 4};
    coeffs theta(A->dim(), ex(0));
    for (unsigned k = 0; k <= 2; ++k) theta[unit_index(*A, k)] = -phi[k];
    const coeffs w = A->scale(5, A->exp(theta, 1));
    const amplitude_modulation r = amplitude_modulated(*A, w);
    ASSERT_EQ(r.holds, truth::yes) << r.report;
    EXPECT_TRUE(is_zero_scalar(r.amplitude - 5));
    // it represents 5 prod_k cos(omega_k t - phi_k) for every carrier choice (here 7, 2, 1/2)
    const std::vector<ex> omega{7, 2, ex(1) / 2};
    const auto R = represent_on(A, carrier_element(*A, omega));
    ex s = r.amplitude;
    for (unsigned k = 0; k <= 2; ++k) s *= GiNaC::cos(omega[k] * t - r.phases[k]);
    EXPECT_TRUE(same_function(signal_of(R, w, t), s));
    // equal moduli, phases not of the form phi_0 + sum +-phi_k: no
    const coeffs twisted = A->from_idempotent_components({ex(1), ex(1), ex(1), GiNaC::I});
    const amplitude_modulation no = amplitude_modulated(*A, twisted);
    EXPECT_EQ(no.holds, truth::no);
    EXPECT_NE(no.report.find("IV.1.68"), std::string::npos) << no.report;
    // different moduli (a hyperbolic part), and a zero divisor: no
    EXPECT_EQ(amplitude_modulated(*A, A->add(A->unit(), A->basis_vector(unit_index(*A, 1) | unit_index(*A, 2)))).holds,
              truth::no);
    EXPECT_EQ(amplitude_modulated(*A, A->idempotent(1)).holds, truth::no);
    // multicomplex(1): every element with equal moduli is amplitude-modulated; (3 + 4 i0 i1)/5 is not
    const auto B = multicomplex::make(1);
    EXPECT_EQ(amplitude_modulated(*B, B->add(B->unit(), B->imag_unit(1))).holds, truth::yes);
    coeffs h = B->unit();
    h[0] = ex(3) / 5;
    h[unit_index(*B, 0) | unit_index(*B, 1)] = ex(4) / 5;
    EXPECT_EQ(amplitude_modulated(*B, h).holds, truth::no);
}

// The language: modulation and amplitude_modulated, their errors.
TEST(MulticomplexSignals, Builtins) {
    std::ostringstream out, err;
    lang::session S(out, err);
    S.evaluate("A := multicomplex(1); i0 := imag_unit(A, 0); i1 := imag_unit(A, 1); d := 3*i0 + i1");
    EXPECT_EQ(S.evaluate("signal(one(A), t, d)").as_ex().is_zero(), false);
    const lang::value am = S.evaluate("amplitude_modulated(2*exp(-(i0/3 + 2*i1)))");
    ASSERT_EQ(am.as_list().size(), 4u);
    EXPECT_TRUE(std::get<bool>(am.as_list()[0].v));
    const auto message = [&](const std::string& stmt) -> std::string {
        try {
            S.evaluate(stmt);
        } catch (const symrep::error& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(message("modulation(one(A), t, d + i0*i1)").find("(IV.1.9)"), std::string::npos);
    EXPECT_NE(message("amplitude_modulated(element(walsh(1), [1, 0]))").find("not a multicomplex algebra"),
              std::string::npos);
}

// (IV.1.2.8-18, corrected) the Sobrero algebra with d = delta + eps + j omega:
// Psi^-1(w) = Re [w exp(d t)]_n (the coordinate of eps^n) is derivative-compatible and
// represents eps^k by t^(n-k)/(n-k)! e^(delta t) cos(omega t) and j eps^k by
// -t^(n-k)/(n-k)! e^(delta t) sin(omega t) (the printed IV.1.2.17-18 with k -> n - k and
// the sign of j: the printed map turns d into its conjugate).
TEST(SobreroSignals, RepresentationModulationAndSpecialType) {
    const unsigned n = 2;
    const auto S = sobrero::make(n);
    const ex delta = ex(-1) / 2, omega = 2;
    coeffs d(S->dim(), ex(0));
    d[0] = delta;
    d[1] = 1;
    d[n + 1] = omega;
    const auto R = represent_on(S, d);
    const auto fact = [](unsigned m) { return GiNaC::factorial(m); };
    for (unsigned k = 0; k <= n; ++k) {
        const ex envelope = GiNaC::pow(t, n - k) / fact(n - k) * GiNaC::exp(delta * t);
        EXPECT_TRUE(same_function(signal_of(R, S->basis_vector(k), t), envelope * GiNaC::cos(omega * t))) << k;
        EXPECT_TRUE(same_function(signal_of(R, S->basis_vector(n + 1 + k), t), -envelope * GiNaC::sin(omega * t)));
    }
    const coeffs w{1, 3, 0, 2, -1, 0};  // 1 + 3 eps + j (2 - eps)
    const ex f = signal_of(R, w, t);
    EXPECT_TRUE(same_function(signal_of(R, S->multiply(d, w), t), f.diff(t)));
    const coeffs back = element_of(R, f, t);
    for (std::size_t i = 0; i < w.size(); ++i) EXPECT_TRUE(is_zero_scalar(tidy(back[i] - w[i]))) << i;
    // (IV.1.2.20-25) a cos(omega t) + b sin(omega t) = A cos(omega t - theta) = the signal
    const modulation m = sobrero_modulation(R, w, t);
    EXPECT_TRUE(same_function(m.a * GiNaC::cos(omega * t) + m.b * GiNaC::sin(omega * t), f));
    EXPECT_TRUE(same_function(m.amplitude * GiNaC::cos(omega * t - m.phase), f));
    // (IV.1.2.42-45) special-type elements (coefficients on one line through 0) have a constant
    // phase: b a' - a b' = 0; the element above does not
    const auto phase_rate = [](const modulation& x) { return tidy((x.b * x.a.diff(t) - x.a * x.b.diff(t)).expand()); };
    const coeffs special{3, 6, -3, 1, 2, -1};  // (3 + j)(1 + 2 eps - eps^2)
    ASSERT_TRUE(S->is_special_type(special, false));
    EXPECT_TRUE(is_zero_scalar(phase_rate(sobrero_modulation(R, special, t))));
    EXPECT_FALSE(S->is_special_type(w, false));
    EXPECT_FALSE(is_zero_scalar(phase_rate(m)));
    // (IV.1.2.38-41) zero divisors (a_0 = b_0 = 0) represent degenerate signals: order <= 2n
    const coeffs zd{0, 1, 2, 0, 3, 0};
    EXPECT_TRUE(S->is_zero_divisor(zd));
    EXPECT_LE(annihilator(signal_of(R, zd, t), t, X).degree(X), int(2 * n));
    EXPECT_EQ(annihilator(f, t, X).degree(X), int(2 * (n + 1)));
}

// (IV.3.2 cases c, d, a, b, e over multicomplex(1), d = 3 i0 + i1, Omega = 4, 2): responses
// derived on the algebra, each substituted into the system by respond_over itself.
TEST(MulticomplexSignals, FilterCasesCAndD) {
    const auto A = multicomplex::make(1);
    const coeffs d = carrier_element(*A, {3, 1});
    // c: x'' + 10 x = cos 3t cos t: |H(4i)| = |H(2i)| = 1/6, the response stays amplitude-modulated
    const auto c = signals::respond_over(A, d, {1, 0, 10}, {1}, GiNaC::cos(3 * t) * GiNaC::cos(t), t);
    EXPECT_EQ(c.kind, response_kind::not_distorted) << c.report;
    EXPECT_TRUE(same_function(c.particular, GiNaC::sin(3 * t) * GiNaC::sin(t) / 6));
    // d: x'' + 12 x = cos 4t + 2 cos 2t (not amplitude-modulated): H = -1/4, 1/8 evens the moduli out
    const auto e = signals::respond_over(A, d, {1, 0, 12}, {1}, GiNaC::cos(4 * t) + 2 * GiNaC::cos(2 * t), t);
    EXPECT_EQ(e.kind, response_kind::corrected) << e.report;
    EXPECT_EQ(amplitude_modulated(*A, e.element).holds, truth::yes);
    // distorted: x' + x = cos 3t cos t (|H| differs at 4 and 2)
    EXPECT_EQ(signals::respond_over(A, d, {1, 1}, {1}, GiNaC::cos(3 * t) * GiNaC::cos(t), t).kind,
              response_kind::distorted);
    // a notch at 4 (q = D^2 + 16): cos 4t filtered out; cos 4t + cos 2t loses one mode (b)
    EXPECT_EQ(signals::respond_over(A, d, {1, 0, 0, 1}, {1, 0, 16}, GiNaC::cos(4 * t), t).kind,
              response_kind::filtered_out);
    const auto b = signals::respond_over(A, d, {1, 0, 0, 1}, {1, 0, 16}, GiNaC::cos(4 * t) + GiNaC::cos(2 * t), t);
    EXPECT_NE(b.report.find("case b"), std::string::npos) << b.report;
    // e: p(d) a zero divisor
    EXPECT_THROW(signals::respond_over(A, d, {1, 0, 16}, {1}, GiNaC::cos(4 * t), t), symrep::zero_divisor_error);
    EXPECT_THROW(signals::respond_over(A, d, {1, 0}, {1, 0}, GiNaC::cos(4 * t), t), symrep::domain_error);
}
