// Tests of numeric/spectral_evaluator.h: quasi-polynomial closed forms
// evaluated through clusters of their exponents, against the exact value at
// the same binary inputs (numeric/reference.h, CLN with 200 digits).
//
// Tolerance: 4e-15 relative to each component's largest magnitude over the
// sampled times (the work-precision charts' measure, docs/performance.md):
// a handful of double roundings of the result's size; the pointwise relative
// error is not bounded where a component passes through zero.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "lang/interpreter.h"
#include "lang/values.h"
#include "numeric/evaluator.h"
#include "numeric/reference.h"
#include "numeric/spectral_evaluator.h"
#include "test_util.h"

using namespace symrep;
using GiNaC::ex;

namespace {

constexpr int reference_digits = 200;

struct derived {
    std::vector<ex> outputs;
    ex t;
};

derived derive(const std::string& script) {
    std::ostringstream out, err;
    lang::session S(out, err);
    derived d;
    const ex closed_form = S.evaluate(script).as_ex();
    d.outputs = lang::components(closed_form);
    d.t = test::symbol_named(closed_form, "t");
    return d;
}

/// max over components of max_k |f(t_k) - ref(t_k)| / max_k |ref(t_k)|.
template <class F>
double trajectory_error(const F& f, const derived& d, const std::vector<double>& times) {
    const std::size_t n = d.outputs.size();
    std::vector<double> worst(n, 0), scale(n, 0);
    std::vector<double> v(n);
    for (double T : times) {
        f(T, v.data());
        const auto ref = num::reference_eval(d.outputs, {d.t}, {T}, reference_digits);
        for (std::size_t i = 0; i < n; ++i) {
            worst[i] = std::max(worst[i], static_cast<double>(std::fabs(v[i] - ref[i])));
            scale[i] = std::max(scale[i], static_cast<double>(std::fabs(ref[i])));
        }
    }
    double e = 0;
    for (std::size_t i = 0; i < n; ++i) e = std::max(e, scale[i] > 0 ? worst[i] / scale[i] : worst[i]);
    return e;
}

std::vector<double> times_up_to(double span, int n) {
    std::vector<double> t;
    for (int k = 1; k <= n; ++k) t.push_back(span * (k - 0.37 * ((k * 7) % 5) / 5.0) / n);
    return t;
}

const char* gravity_script(const char* rate) {
    static std::string s;
    s = std::string("vector w, g, r0, v0\n"
                    "s := solve(ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0))\n"
                    "subs(s, [w = ") + rate +
        "*[cos(pi/4), 0, sin(pi/4)], g = [0, 0, -9.81], r0 = [0, 0, 100], v0 = [10, 5, 20]])";
    return s.c_str();
}

}  // namespace

TEST(SpectralEvaluator, GravityInARotatingFrame) {
    const derived d = derive(gravity_script("7.2921e-5"));
    const num::spectral_function f(d.outputs, d.t);
    const num::compiled_function naive = num::compile(d.outputs, {d.t});
    const auto times = times_up_to(60, 40);
    const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times);
    const double e_naive = trajectory_error([&](double T, double* v) { naive.eval(&T, v); }, d, times);
    EXPECT_LE(e, 4e-15);
    EXPECT_GT(e_naive, 1e-12);  // the solver's form cancels here: the test is not vacuous
}
TEST(SpectralEvaluator, GravityForEveryRate) {
    // |w| from 1e-12 to 1e3 rad/s (the work-precision sweep): |w| t from 1e-11 to 1e5
    // over 10 s; below |w| t ~ 1e-3 the solver's form has no correct digit in double.
    for (const char* rate : {"1e-12", "3.7e-9", "1.3e-6", "7.2921e-5", "2.9e-3", "0.11", "4.7", "130", "1e3"}) {
        const derived d = derive(gravity_script(rate));
        const num::spectral_function f(d.outputs, d.t);
        const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times_up_to(10, 25));
        EXPECT_LE(e, 4e-15) << "|w| = " << rate;
    }
}

TEST(SpectralEvaluator, CentrifugalTermsAndEveryLevel) {
    // r'' + 2 w x r' + w x (w x r) = g (VI.1.56): exponents 0, +-i|w|; the series about 0
    // below t = 2/|w|, each exponent on its own above; times on both sides of the threshold.
    const derived d = derive(
        "vector w, g, r0, v0\n"
        "s := solve(ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0))\n"
        "subs(s, [w = 0.37*[3/5, 0, 4/5], g = [0, 0, -9.81], r0 = [1, 2, 3], v0 = [0, 1, -1/2]])");
    const num::spectral_function f(d.outputs, d.t);
    ASSERT_GE(f.n_levels(), 2u);
    const double threshold = f.level_start(f.n_levels() - 1);
    std::vector<double> times;
    for (double x : {1e-6, 0.01, 0.3, 0.9, 0.999, 1.001, 1.5, 10.0, 1e3}) times.push_back(x * threshold);
    const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times);
    EXPECT_LE(e, 4e-15);
    // t < 0 evaluates the same analytic function
    std::vector<double> v(3);
    f.eval(-2.5, v.data());
    const auto ref = num::reference_eval(d.outputs, {d.t}, {-2.5}, reference_digits);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(v[i], static_cast<double>(ref[i]), 1e-14 * std::fabs(static_cast<double>(ref[i])) + 1e-14);
}

TEST(SpectralEvaluator, FoucaultAtParisOverThirtyDays) {
    // (VI.1.68): terms of 1/|w|^2 with phases (w0 +- |w|) t: the cluster about w0 below
    // |w| t = 2, the three frequencies apart above, phases of 1e6 rad after 30 days.
    const derived d = derive(
        "vector w, r0, v0\npositive w0\n"
        "s := solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))\n"
        "subs(s, [w = 7.2921e-5*[cos(48.85*pi/180), 0, sin(48.85*pi/180)], w0 = sqrt(9.81/67), "
        "r0 = [3, 0, 0], v0 = [0, 0, 0]])");
    const num::spectral_function f(d.outputs, d.t);
    const num::compiled_function naive = num::compile(d.outputs, {d.t});
    std::vector<double> times = times_up_to(30 * 86400.0, 30);
    for (double T : {1e-3, 1.0, 100.0, 3600.0, 27000.0, 28000.0, 86400.0}) times.push_back(T);
    const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times);
    const double e_naive = trajectory_error([&](double T, double* v) { naive.eval(&T, v); }, d, times);
    EXPECT_LE(e, 4e-15);
    EXPECT_GT(e_naive, 1e-12);
}

TEST(SpectralEvaluator, ReducedFoucaultAndChargedParticle) {
    // r'' + 2 w x r' + w0^2 r = 0 (VI.2.93; frequencies sqrt(w0^2 + |w|^2) +- |w|, w0) and a
    // proton in E and B (VI.1.58; exponents 0, +-i qB/m with qB/m ~ 1e8).
    for (const char* script :
         {"vector w, r0, v0\npositive w0\n"
          "s := solve(ode(r'' + 2*w x r' + w0^2*r = 0, r(0) = r0, r'(0) = v0))\n"
          "subs(s, [w = 7.2921e-5*[cos(48.85*pi/180), 0, sin(48.85*pi/180)], w0 = sqrt(9.81/67), "
          "r0 = [3, 0, 0], v0 = [0, 0, 0]])",
          "vector E, B, v0, r0\npositive m\n"
          "s := solve(ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0))\n"
          "subs(s, [q = 1.602176634e-19, m = 1.67262192e-27, B = [0, 0, 1], E = [1000*sin(pi/3), 0, "
          "1000*cos(pi/3)], v0 = [1e5, 0, 0], r0 = [0, 0, 0]])"}) {
        const derived d = derive(script);
        const num::spectral_function f(d.outputs, d.t);
        const double span = std::string(script).find("q =") != std::string::npos ? 6.6e-5 : 86400.0;
        const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times_up_to(span, 40));
        EXPECT_LE(e, 4e-15) << script;
    }
}

TEST(SpectralEvaluator, NearlyCriticalDamping) {
    // x'' + 2 z x' + x = 0, x(0) = 1, x'(0) = 0 with z = 1 + 1e-9: real exponents
    // -z +- sqrt(z^2 - 1) 9e-5 apart, coefficients of 1e4 that cancel; and z = 1 - 1e-9
    // (a complex pair close to the real axis: the cluster holds both halves).
    const GiNaC::symbol t("t");
    for (int sign : {1, -1}) {
        const GiNaC::numeric z = 1 + sign * GiNaC::numeric(1, 1000000000);
        const ex s = GiNaC::sqrt(z * z - 1);  // real or imaginary
        const ex l1 = -z + s, l2 = -z - s;
        // x = (l1 e^(l2 t) - l2 e^(l1 t)) / (l1 - l2), written with real functions for z < 1
        ex x = (l1 * GiNaC::exp(l2 * t) - l2 * GiNaC::exp(l1 * t)) / (l1 - l2);
        if (sign < 0) {
            const ex b = GiNaC::sqrt(1 - z * z);
            x = GiNaC::exp(-z * t) * (GiNaC::cos(b * t) + z / b * GiNaC::sin(b * t));
        }
        derived d{{x}, t};
        const num::spectral_function f(d.outputs, t);
        const double e = trajectory_error([&](double T, double* v) { f.eval(T, v); }, d, times_up_to(30, 40));
        EXPECT_LE(e, 4e-15) << "z = 1 " << (sign > 0 ? "+" : "-") << " 1e-9";
    }
}

TEST(SpectralEvaluator, RefusesWhatIsNotAQuasiPolynomial) {
    const GiNaC::symbol t("t"), a("a");
    const auto message = [&](const ex& e) -> std::string {
        try {
            num::spectral_function f({e}, t);
        } catch (const symrep::error& x) {
            return x.what();
        }
        return "no error";
    };
    EXPECT_NE(message(GiNaC::sin(t * t)).find("not linear in t"), std::string::npos);
    EXPECT_NE(message(GiNaC::sqrt(t) + 1).find("not a quasi-polynomial in t"), std::string::npos);
    EXPECT_NE(message(1 / (1 + t)).find("not a quasi-polynomial"), std::string::npos);
    EXPECT_NE(message(GiNaC::log(t)).find("log(t)"), std::string::npos);
    EXPECT_NE(message(a * GiNaC::cos(t)).find("not a number"), std::string::npos);
    EXPECT_NE(message(GiNaC::exp(GiNaC::I * t)).find("not real"), std::string::npos);
    EXPECT_THROW(num::spectral_function({t}, t + 1), symrep::type_error);
    // a polynomial and the zero output are fine; exact values at exact inputs
    const num::spectral_function f({t * t * t - 2 * t + 1, ex(0)}, t);
    EXPECT_EQ(f(3.0), (std::vector<double>{22.0, 0.0}));
}
