// Where methods fail (issue 5, part 2): resonance, stiffness and w = 0 exactly,
// for the exact solution (stable evaluation) and for each integrator, through
// the language's own solve and verify. Tolerances are stated per test.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <sstream>

#include "lang/interpreter.h"
#include "lang/values.h"
#include "numeric/reference.h"
#include "numeric/stable_evaluator.h"
#include "test_util.h"

using namespace symrep;

namespace {

struct verify_run {
    double difference = -1;
    long rhs_evaluations = -1;
};

/// verify(...) in a session where `setup` has run; the returned difference and
/// the number of right-hand sides from verify's report.
verify_run run_verify(lang::session& S, std::ostringstream& out, const std::string& call) {
    out.str("");
    verify_run r;
    r.difference = GiNaC::ex_to<GiNaC::numeric>(S.evaluate(call).as_ex()).to_double();
    std::smatch m;
    const std::string text = out.str();
    if (std::regex_search(text, m, std::regex("\\((\\d+) right-hand sides\\)"))) r.rhs_evaluations = std::stol(m[1]);
    return r;
}

const char* const steppers[] = {"rkf78", "bulirsch_stoer", "dopri5"};

}  // namespace

TEST(MethodLimits, ResonanceSecularGrowthForEveryIntegrator) {
    // r'' + w0^2 r = F cos(w0 t): the exact solution grows like t sin(w0 t) F/(2 w0)
    // (secular term). Over 50 periods the amplitude grows 80-fold; each
    // integrator at tolerance 1e-12 follows it to 1e-7 of the largest value
    // (global error of 1e-12 per step over ~1e4 steps, with the growth).
    std::ostringstream out, err;
    lang::session S(out, err);
    S.evaluate(
        "vector r0, v0, F\npositive w0\n"
        "P := ode(r'' + w0^2*r = F*cos(w0*t), r(0) = r0, r'(0) = v0)\n"
        "s := solve(P)\n"
        "vals := [w0 = 2, F = [1, 0, 0], r0 = [0, 1, 0], v0 = [0, 0, 1]]");
    // the secular term is there: x = t sin(2 t)/4 (indices from 0)
    const double T = 50 * M_PI;  // 50 periods of w0 = 2
    const double x = GiNaC::ex_to<GiNaC::numeric>(S.evaluate("eval(s, vals, t = 50*pi + pi/4)[0]").as_ex())
                         .to_double();
    EXPECT_NEAR(x, (50 * M_PI + M_PI / 4) / 4, 1e-9);  // t sin(2 t)/4 at sin = 1
    for (const char* st : steppers) {
        const verify_run r = run_verify(S, out, "verify(P, s, vals, " + std::to_string(T) + ", 200, \"" + st + "\")");
        EXPECT_LT(r.difference, 1e-7) << st;
        EXPECT_GT(r.rhs_evaluations, 0) << st;
    }
}

TEST(MethodLimits, StiffnessCostsTheIntegratorsNotTheClosedForm) {
    // The Foucault problem with w0 much larger than |w|: integrators must
    // resolve every one of the fast oscillations, so their work grows with
    // w0 (here 10x w0 -> at least 5x right-hand sides for every stepper),
    // while the closed form is evaluated at the same cost and to 1e-14.
    std::ostringstream out, err;
    lang::session S(out, err);
    S.evaluate(
        "vector w, r0, v0\npositive w0\n"
        "P := ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)\n"
        "s := solve(P)");
    for (const char* st : steppers) {
        long previous = 0;
        for (int w0 : {10, 100}) {
            const std::string vals = "[w = [0, 3/5000, 4/5000], w0 = " + std::to_string(w0) +
                                     ", r0 = [1, 0, 0], v0 = [0, 1/2, 0]]";
            const verify_run r = run_verify(S, out, "verify(P, s, " + vals + ", 20, 100, \"" + st + "\")");
            // tolerance 1e-12 per step, ~w0 * 20 / (2 pi) periods: 1e-7 of the amplitude
            EXPECT_LT(r.difference, 1e-6) << st << " w0 = " << w0;
            EXPECT_GT(r.rhs_evaluations, 0) << st;
            std::printf("stiffness: %s w0 = %d: difference %.2e, %ld right-hand sides\n", st, w0, r.difference,
                        r.rhs_evaluations);
            if (previous > 0) {
                EXPECT_GT(r.rhs_evaluations, 5 * previous) << st;
            }
            previous = r.rhs_evaluations;
        }
    }
    // the closed form at w0 = 1e4, |w| = 1e-3: one stable evaluation, exact to 1e-14
    const GiNaC::ex s = S.evaluate("subs(s, [w = [0, 3/5000, 4/5000], w0 = 10000, r0 = [1, 0, 0], v0 = [0, 1/2, 0]])")
                            .as_ex();
    const auto comps = lang::components(s);
    const GiNaC::ex t = test::symbol_named(s, "t");
    const num::stable_function f(comps, {t});
    for (double T : {0.5, 20.0, 1e4}) {
        std::vector<double> v(3);
        f.eval(&T, v.data());
        const auto ref = num::reference_eval(comps, {t}, {T}, 100);
        double scale = 0;
        for (auto x : ref) scale = std::max(scale, static_cast<double>(std::fabs(x)));
        for (int i = 0; i < 3; ++i)
            EXPECT_LE(std::fabs(v[i] - ref[i]), 1e-14 * std::fabs(ref[i]) + 1e-300) << "t = " << T << " i = " << i;
    }
}

TEST(MethodLimits, ZeroRotationExactly) {
    // w = 0: the closed form has 1/|w|^2 factors; eval takes the exact limit,
    // verify compares the limit with each integrator (no rotation: a plain
    // oscillator, tolerance 1e-9 over 10 periods), and the stable evaluator
    // returns the limit for |w| = 0 given as a number.
    std::ostringstream out, err;
    lang::session S(out, err);
    S.evaluate(
        "vector w, r0, v0\npositive w0\n"
        "P := ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)\n"
        "s := solve(P)\n"
        "vals := [w = [0, 0, 0], w0 = 3, r0 = [1, 2, 0], v0 = [0, 0, 3]]");
    const double z = GiNaC::ex_to<GiNaC::numeric>(S.evaluate("eval(s, vals, t = 1/2)[2]").as_ex()).to_double();
    EXPECT_NEAR(z, std::sin(1.5), 1e-15);  // v0/w0 sin(w0 t)
    for (const char* st : steppers) {
        const verify_run r = run_verify(S, out, std::string("verify(P, s, vals, 20, 100, \"") + st + "\")");
        EXPECT_LT(r.difference, 1e-9) << st;
    }
    // the stable evaluator, with |w| an input that is exactly 0
    const GiNaC::ex s = S.evaluate("positive W\nsubs(s, [w = W*[0, 0, 1], w0 = 3, r0 = [1, 2, 0], v0 = [0, 0, 3]])")
                            .as_ex();
    const GiNaC::ex t = test::symbol_named(s, "t"), W = test::symbol_named(s, "W");
    const num::stable_function f(lang::components(s), {W, t});
    const double in[2] = {0.0, 0.5};
    std::vector<double> v(3);
    f.eval(in, v.data());
    EXPECT_NEAR(v[0], std::cos(1.5), 1e-15);
    EXPECT_NEAR(v[1], 2 * std::cos(1.5), 1e-15);
    EXPECT_NEAR(v[2], std::sin(1.5), 1e-15);
}

TEST(MethodLimits, EvalIsAccurateWhereFormulasCancel) {
    // The language's eval puts values in exactly and evaluates with controlled
    // precision: a fixed 20-digit evalf gives 0 for (1 - cos(w t))/w^2 at
    // w t = 1e-12 and 8 digits for sin(sqrt(2) t) at t = 1e12.
    std::ostringstream out, err;
    lang::session S(out, err);
    auto num = [&](const std::string& s) { return GiNaC::ex_to<GiNaC::numeric>(S.evaluate(s).as_ex()).to_double(); };
    EXPECT_EQ(num("eval((1 - cos(w*t))/w^2, [w = 1e-12], t = 1)"), 0.5);
    EXPECT_NEAR(num("eval((1 - cos(w*t))/w^2, [w = 1e-5], t = 1)"), 0.5 - 1e-10 / 24, 1e-16);
    const GiNaC::symbol t("t");
    const double want = static_cast<double>(
        num::reference_eval({GiNaC::sin(GiNaC::sqrt(GiNaC::ex(2)) * t)}, {t}, {1e12}, 60)[0]);
    EXPECT_EQ(num("eval(sin(sqrt(2)*t), [], t = 1e12)"), want);
}
