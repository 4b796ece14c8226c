// Tests of signals/response.h (thesis IV.3.1-IV.3.2, Thm IV.3.2.1): the transmittance,
// the cases of IV.3.2 decided exactly, and agreement of the zero-state response with
// the constant-coefficient solver of the mechanics layer on the same scalar problems.
// All comparisons exact (the zero test); no tolerance.
#include <gtest/gtest.h>

#include "test_util.h"

#include <sstream>

#include "algebra/polynomial_algebra.h"
#include "core/error.h"
#include "lang/interpreter.h"
#include "scalar/scalar.h"
#include "signals/representation.h"
#include "signals/response.h"

using namespace symrep;
using namespace symrep::signals;
using GiNaC::ex;

namespace {

const GiNaC::symbol t("t"), X("X");

using symrep::test::same;

// The mechanics solver's answer to `problem` (a scalar Cauchy problem in the language).
ex solver(const std::string& problem) {
    std::ostringstream out, err;
    lang::session s(out, err);
    const lang::value v = s.evaluate("solve(" + problem + ")");
    return v.as_ex().subs(GiNaC::ex_to<GiNaC::symbol>(s.symbol("t")) == t);
}

}  // namespace

TEST(SignalsResponse, PassedAgreesWithTheSolver) {
    const auto x = respond({1, 3, 2}, {1}, GiNaC::cos(t), t);
    EXPECT_EQ(x.kind, response_kind::passed);
    EXPECT_TRUE(same(x.particular, (GiNaC::cos(t) + 3 * GiNaC::sin(t)) / 10));
    EXPECT_TRUE(same(x.zero_state, solver("ode(x'' + 3*x' + 2*x = cos(t), x(0) = 0, x'(0) = 0)")));
}

// A symbolic rate: the answer is the generic one, and the report says where it fails.
TEST(SignalsResponse, GenericParametersNameTheirException) {
    const GiNaC::possymbol a("a");
    const auto x = respond({1, a}, {1}, GiNaC::exp(-2 * t), t);
    EXPECT_EQ(x.kind, response_kind::passed);
    EXPECT_TRUE(same(x.particular, GiNaC::exp(-2 * t) / (a - 2)));
    EXPECT_NE(x.report.find("not 0"), std::string::npos) << x.report;
    EXPECT_NE(x.report.find("a"), std::string::npos) << x.report;
    // at a = 2 itself: resonant, t e^(-2 t)
    const auto y = respond({1, 2}, {1}, GiNaC::exp(-2 * t), t);
    EXPECT_EQ(y.kind, response_kind::resonant);
    EXPECT_TRUE(same(y.zero_state, t * GiNaC::exp(-2 * t)));
}

TEST(SignalsResponse, ResonanceRaisesTheDegree) {
    const auto x = respond({1, 0, 1}, {1}, GiNaC::cos(t), t);
    EXPECT_EQ(x.kind, response_kind::resonant);
    EXPECT_TRUE(same(x.zero_state, t * GiNaC::sin(t) / 2));
    EXPECT_TRUE(same(x.zero_state, solver("ode(x'' + x = cos(t), x(0) = 0, x'(0) = 0)")));
    // a double root of p on the input's mode: t^2 e^-t
    const auto y = respond({1, 2, 1}, {1}, GiNaC::exp(-t), t);
    EXPECT_EQ(y.kind, response_kind::resonant);
    EXPECT_TRUE(same(y.zero_state, t * t * GiNaC::exp(-t) / 2));
}

TEST(SignalsResponse, FilteredAndPartlyFiltered) {
    // x'' + 3x' + 2x = f' + f with f = e^-t: q(-1) = 0, the input is filtered out
    const auto a = respond({1, 3, 2}, {1, 1}, GiNaC::exp(-t), t);
    EXPECT_EQ(a.kind, response_kind::filtered_out);
    EXPECT_TRUE(a.particular.is_zero());
    // q = X^2 + 4 removes cos 2t from cos t + cos 2t: the response has order 2 < 4
    const auto b = respond({1, 3, 3, 1}, {1, 0, 4}, GiNaC::cos(t) + GiNaC::cos(2 * t), t);
    EXPECT_EQ(b.kind, response_kind::partially_filtered);
    EXPECT_TRUE(same(b.particular, 3 * (GiNaC::sin(t) - GiNaC::cos(t)) / 4));
    // q(D) f = 3 cos t
    EXPECT_TRUE(same(b.zero_state, solver("ode(x''' + 3*x'' + 3*x' + x = 3*cos(t), x(0) = 0, x'(0) = 0, "
                                          "x''(0) = 0)")));
}

// p(d) a zero divisor is not by itself resonance (FORMULAS.md, IV.3 case e): with
// q cancelling the shared mode e^-t, the response stays in the input's class.
TEST(SignalsResponse, ZeroDivisorWithoutResonance) {
    const auto x = respond({1, 4, 3}, {1, 1}, GiNaC::exp(-t) + GiNaC::exp(-2 * t), t);
    EXPECT_EQ(x.kind, response_kind::passed);
    EXPECT_NE(x.report.find("zero divisor"), std::string::npos) << x.report;
    EXPECT_TRUE(same(x.zero_state,
                     solver("ode(x'' + 4*x' + 3*x = -exp(-2*t), x(0) = 0, x'(0) = 0)")));
}

TEST(SignalsResponse, TransmittanceAndBadInput) {
    const auto P = polynomial_algebra::make(X * X + 1, X);
    const coeffs H = transmittance(*P, P->generator(), {1, 3, 2}, {1});
    // H(i) = 1/(1 + 3 i) = (1 - 3 i)/10
    EXPECT_TRUE(same(H[0], ex(1) / 10));
    EXPECT_TRUE(same(H[1], ex(-3) / 10));
    EXPECT_THROW(transmittance(*P, P->generator(), {1, 0, 1}, {1}), zero_divisor_error);
    EXPECT_THROW(respond({1, 0, 1}, {1, 0, 1}, GiNaC::cos(t), t), domain_error);  // m = p
    EXPECT_THROW(respond({0, 1}, {1}, GiNaC::cos(t), t), domain_error);           // a_0 = 0
    EXPECT_THROW(respond({1, t}, {1}, GiNaC::cos(t), t), domain_error);           // a coefficient in t
}

// The cases' names as the reports print them (the report's first words are the case).
TEST(SignalsResponse, KindNames) {
    EXPECT_EQ(kind_text(response_kind::passed), "passed");
    EXPECT_EQ(kind_text(response_kind::partially_filtered), "partially filtered");
    EXPECT_EQ(kind_text(response_kind::filtered_out), "filtered out");
    EXPECT_EQ(kind_text(response_kind::resonant), "resonant");
    EXPECT_EQ(kind_text(response_kind::not_distorted), "not distorted");
    EXPECT_EQ(kind_text(response_kind::corrected), "corrected");
    EXPECT_EQ(kind_text(response_kind::distorted), "distorted");
    const GiNaC::symbol t("t");
    const auto x = respond({1, 3, 2}, {1, 1}, GiNaC::exp(-t), t);
    EXPECT_EQ(x.report.rfind(kind_text(x.kind) + ":", 0), 0u) << x.report;
}

// Digital systems (the shift): the same algebra, Psi_d^-1(w) = lambda(w v^k), zero state
// x(0) = ... = x(m-1) = 0 (IV.3.19). Each answer checked here by the recurrence itself.
TEST(SignalsResponse, DigitalSystems) {
    const GiNaC::symbol k("k");
    // x(k+1) - x(k)/2 = f(k+1) + f(k), f = 1: 4 - 4 (1/2)^k
    const auto a = respond_discrete({1, ex(-1) / 2}, {1, 1}, 1, k);
    EXPECT_EQ(a.kind, response_kind::passed);
    EXPECT_TRUE(same(a.particular, 4));
    EXPECT_TRUE(same(a.zero_state, 4 - 4 * GiNaC::pow(ex(1) / 2, k)));
    // (-1)^k is removed by q(E) = E + 1
    EXPECT_EQ(respond_discrete({1, ex(-1) / 2}, {1, 1}, GiNaC::pow(-1, k), k).kind, response_kind::filtered_out);
    // x(k+1) + x(k) = (-1)^k k resonates: (-1)^k (k - k^2)/2
    const auto r = respond_discrete({1, 1}, {1}, GiNaC::pow(-1, k) * k, k);
    EXPECT_EQ(r.kind, response_kind::resonant);
    EXPECT_TRUE(same(r.zero_state, GiNaC::pow(-1, k) * (k - k * k) / 2));
    // the zero state by the recurrence, step by step, for x(k+2) - x(k)/4 = k 3^k
    const auto z = respond_discrete({1, 0, ex(-1) / 4}, {1}, k * GiNaC::pow(3, k), k);
    std::vector<ex> x{0, 0};
    for (int j = 0; j < 8; ++j) x.push_back(x[std::size_t(j)] / 4 + ex(j) * GiNaC::pow(3, j));
    for (int j = 0; j < 10; ++j) EXPECT_TRUE(same(z.zero_state.subs(k == j), x[std::size_t(j)])) << j;
    // sequences: the least equation and the round trip
    const GiNaC::symbol X("X");
    EXPECT_TRUE(same(sequence_annihilator(k * GiNaC::pow(2, k) + GiNaC::cos(GiNaC::Pi * k / 2), k, X),
                     GiNaC::pow(X - 2, 2) * (X * X + 1)));
    const auto R = polynomial_representation(sequence_annihilator(GiNaC::pow(2, k) + k, k, X), X);
    EXPECT_TRUE(same(sequence_formula(R, sequence_element(R, GiNaC::pow(2, k) + k, k), k), GiNaC::pow(2, k) + k));
    EXPECT_THROW(sequence_annihilator(GiNaC::log(k), k, X), domain_error);
    EXPECT_THROW(respond_discrete({1, 1}, {1, 0, 1}, 1, k), domain_error);  // m < p
}

// (IV.3.15) H(i w) as gain and phase: the notch (X^2 + 4)/(X + 1)^3 has gain
// |4 - w^2|/(1 + w^2)^(3/2) (0 at w = 2) and gain * (cos phase + i sin phase) = H(i w).
TEST(SignalsResponse, FrequencyResponse) {
    const GiNaC::realsymbol om("om");
    const auto fr = frequency_response_of({1, 3, 3, 1}, {1, 0, 4}, om);
    for (const GiNaC::numeric& x : {GiNaC::numeric(0), GiNaC::numeric(1, 2), GiNaC::numeric(2), GiNaC::numeric(7)}) {
        const ex H = ((4 - x * x) / GiNaC::pow(1 + GiNaC::I * x, 3)).evalf();
        const ex g = fr.gain.subs(om == x).evalf(), ph = fr.phase.subs(om == x).evalf();
        EXPECT_LT(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>((GiNaC::abs(H) - g).evalf())), 1e-15) << x;
        if (x != 2) {
            EXPECT_LT(GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>((g * (GiNaC::cos(ph) + GiNaC::I * GiNaC::sin(ph)) - H).evalf())),
                      1e-15)
                << x;
        }
    }
    EXPECT_TRUE(fr.gain.subs(om == 2).is_zero());
    EXPECT_THROW(frequency_response_of({}, {1}, om), symrep::type_error);
}
