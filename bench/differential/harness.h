// bench/differential/harness.h -- the differential test across the solvers (issue 27.6).
//
// Random problems are drawn from the families the engine solves; each is given to
// symrep as a user writes it (a session, the language), and what symrep prints
// (solve's closed form evaluated by `eval`, `solve(P, values)`, the stable
// compiled evaluator, `response`, `laplace`, `inverse_laplace`, `exp` in an algebra)
// is compared with an independent numeric computation written here from the
// drawn numbers alone: Boost.Odeint (runge_kutta_fehlberg78 at 1e-13) on the
// original equation, Boost.Math quadrature for transforms, Eigen's matrix
// exponential of the regular representation for algebras. Nothing of the
// engine's numeric side (numeric/integrate.h, numeric/quadrature.h) is used for
// the reference.
//
// Magnitudes: the data of the linear problems (g, r0, v0, the forcing) are
// scaled by one factor 10^e, e uniform in [-250, 250] (the reference integrates
// the unscaled problem and scales its result: the problems are linear in their
// data); |w| is 10^e with e uniform in [-300, 0.5] (|w| t from 1e-300 to ~20), or
// exactly 0; numbers reach symrep as decimal floats (%.17g) or as exact rationals.
//
// A disagreement is a difference beyond the tolerance of its family, stated with
// each family: the norm of the difference over the norm of the reference (or of
// the scale of the problem's terms where the answer itself cancels). A symrep
// error counts as a disagreement too, unless the family says the refusal is
// allowed (none does today). The test (tests/test_differential.cpp) runs a few
// hundred cases in CI; bench/differential/ runs any number (docs/testing.md). More families:
// frames.h (turning w, charges in B(t), Kepler, relative motion), compiled.h (the compiled
// paths); families.h runs them all.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/numeric/odeint.hpp>
#include <ginac/ginac.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "lang/interpreter.h"

namespace symrep::differential {

/// One compared case.
struct outcome {
    std::string family;
    std::string statements;  ///< what symrep was given (to reproduce it)
    double difference = 0;   ///< relative difference found (or -1: symrep failed)
    double tolerance = 0;
    std::string error;       ///< symrep's message when it failed
    bool agreed() const { return error.empty() && difference <= tolerance; }
};

using vec3 = std::array<double, 3>;

inline vec3 cross(const vec3& a, const vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// A double as the language reads it back exactly (17 significant digits).
inline std::string decimal(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    std::string s = buf;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return "(" + s + ")";
}

/// A double written as the exact rational it is (as a program that prints exact doubles would).
inline std::string exact(double x) {
    if (x == 0) return "0";
    int e = 0;
    const double m = std::frexp(x, &e);  // x = m 2^e, 0.5 <= |m| < 1
    long long M = (long long)std::ldexp(m, 53);
    e -= 53;
    while (M % 2 == 0) M /= 2, ++e;  // lowest terms
    std::string s = "(" + std::to_string(M);
    if (e > 0) s += "*2^" + std::to_string(e);
    if (e < 0) s += "/2^" + std::to_string(-e);
    return s + ")";
}

inline std::string vector_text(const vec3& v, bool exact_numbers) {
    auto f = exact_numbers ? exact : decimal;
    return "[" + f(v[0]) + ", " + f(v[1]) + ", " + f(v[2]) + "]";
}

/// Relative norm difference of a against the reference b, with `scale` as the floor of the norm.
inline double relative(const std::vector<double>& a, const std::vector<double>& b, double scale = 0) {
    if (a.size() != b.size()) return INFINITY;
    double d = 0, n = scale;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(a[i])) return INFINITY;
        d = std::max(d, std::abs(a[i] - b[i]));
        n = std::max(n, std::abs(b[i]));
    }
    return n == 0 ? d : d / n;
}

/// The numbers of a value printed by eval: a number or a list of numbers.
inline std::vector<double> numbers_of(const lang::value& v) {
    std::vector<double> out;
    auto one = [&](const GiNaC::ex& e) {
        const GiNaC::ex x = GiNaC::evalf(e);
        if (!GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real())
            throw std::runtime_error("not a real number: " + [&] {
                std::ostringstream o;
                o << e;
                return o.str();
            }());
        out.push_back(GiNaC::ex_to<GiNaC::numeric>(x).to_double());
    };
    if (v.is_ex()) {
        const GiNaC::ex& e = v.as_ex();
        if (GiNaC::is_a<GiNaC::matrix>(e))
            for (std::size_t i = 0; i < e.nops(); ++i) one(e.op(i));
        else if (GiNaC::is_a<GiNaC::lst>(e))
            for (std::size_t i = 0; i < e.nops(); ++i) one(e.op(i));
        else
            one(e);
    } else if (v.is_list()) {
        for (const lang::value& x : v.as_list()) {
            const auto k = numbers_of(x);
            out.insert(out.end(), k.begin(), k.end());
        }
    } else {
        throw std::runtime_error("eval gave " + v.a_kind());
    }
    return out;
}

/// With SYMREP_DIFFERENTIAL_TRACE set, each case's statements on standard error before it runs.
inline void trace(const std::string& statements) {
    static const bool on = std::getenv("SYMREP_DIFFERENTIAL_TRACE") != nullptr;
    if (on) std::cerr << "--- case\n" << statements << std::endl;
}

/// A session that collects its error messages.
struct runner {
    std::ostringstream out, err;
    lang::session s{out, err};
    /// Runs a script; throws with symrep's message when a statement fails.
    void run(const std::string& text) {
        err.str("");
        if (s.run_string(text, "case") != 0) throw std::runtime_error(err.str());
    }
    lang::value value(const std::string& text) {
        err.str("");
        try {
            return s.evaluate(text);
        } catch (const std::exception& e) {
            throw std::runtime_error(std::string(e.what()) + " " + err.str());
        }
    }
};

/// Runs the reference `f`; when the reference itself fails (odeint finds no step), the case is
/// recorded as a disagreement naming that instead of ending the run, and not compared.
inline bool reference(outcome& o, const std::function<void()>& f) {
    try {
        f();
        return true;
    } catch (const std::exception& e) {
        o.difference = -1;
        o.error = std::string("the reference failed (not symrep): ") + e.what();
        return false;
    }
}

// ---- the reference integrator -------------------------------------------------------------

using state = std::vector<double>;

/// y(T) of y' = f(t, y), y(0) = y0, by odeint's Bulirsch-Stoer extrapolation with abs and rel
/// tolerance 1e-13 (the data are of size 1, see the scaling above): its global error over
/// |w| t <= 20 and t <= 10 stays below ~1e-11 relative (checked against closed forms in
/// test_differential.cpp). Not Fehlberg 7(8): its error estimate vanishes where the forcing
/// alone drives a component (y' = g(t): stages 12 and 13 repeat 1 and 11), and its step then
/// grows without control (r'' = cos 3t came out 3.04 for 0.103 at t = 8.9).
inline state integrate(const std::function<void(const state&, state&, double)>& f, state y0, double T) {
    using namespace boost::numeric::odeint;
    bulirsch_stoer<state> stepper(1e-13, 1e-13);
    integrate_adaptive(stepper, f, y0, 0.0, T, T / 200);
    return y0;
}

// ---- family: constant w, r'' + 2 w x r' + w x (w x r) + k r = f(t) g (VI.1.62-86) -----------

struct forcing {
    std::string text;  ///< in t, with the vector g
    std::function<double(double)> f;
};

inline forcing draw_forcing(std::mt19937& gen) {
    std::uniform_int_distribution<int> kind(0, 6), small(1, 9);
    const int a = small(gen), b = small(gen), c = small(gen);
    const double A = a / 4.0, B = b / 3.0;
    const std::string As = std::to_string(a) + "/4", Bs = std::to_string(b) + "/3";
    switch (kind(gen)) {
        case 0: return {"g", [](double) { return 1.0; }};
        case 1: return {"t*g", [](double t) { return t; }};
        case 2: return {"t^2*g", [](double t) { return t * t; }};
        case 3: return {"cos(" + Bs + "*t)*g", [B](double t) { return std::cos(B * t); }};
        case 4: return {"exp(-" + As + "*t)*g", [A](double t) { return std::exp(-A * t); }};
        case 5:
            return {"t*exp(-" + As + "*t)*sin(" + Bs + "*t)*g",
                    [A, B](double t) { return t * std::exp(-A * t) * std::sin(B * t); }};
        default:
            return {"(" + std::to_string(c) + " + sin(" + Bs + "*t))*g",
                    [B, c](double t) { return c + std::sin(B * t); }};
    }
}

inline vec3 draw_direction(std::mt19937& gen) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> kind(0, 5);
    vec3 v{u(gen), u(gen), u(gen)};
    switch (kind(gen)) {  // special directions: along an axis, in a plane
        case 0: v = {0, 0, 1}; break;
        case 1: v[0] = 0; break;
        default: break;
    }
    return v;
}

/// One case of the constant-w family; `general` is solve(P) of the same problem text, kept per
/// forcing by the caller (name "s" in the runner).
struct constant_w_case {
    std::string problem;  ///< the ode(...) text
    bool foucault;        ///< k = w0^2 (positive w0) or k = 0
    forcing F;
};

inline constant_w_case draw_constant_w(std::mt19937& gen) {
    constant_w_case c;
    c.foucault = std::uniform_int_distribution<int>(0, 1)(gen) == 1;
    c.F = draw_forcing(gen);
    c.problem = std::string("ode(r'' + 2*w x r' + w x (w x r)") + (c.foucault ? " + w0^2*r" : "") + " = " +
                c.F.text + ", r(0) = r0, r'(0) = v0)";
    return c;
}

/// The reference r(T) for the drawn numbers.
inline std::vector<double> constant_w_reference(const constant_w_case& c, const vec3& w, double w0, const vec3& g,
                                                const vec3& r0, const vec3& v0, double T) {
    const double k = c.foucault ? w0 * w0 : 0;
    auto f = [&](const state& y, state& dy, double t) {
        const vec3 r{y[0], y[1], y[2]}, v{y[3], y[4], y[5]};
        const vec3 wv = cross(w, v), wr = cross(w, r), wwr = cross(w, wr);
        const double ft = c.F.f(t);
        for (int i = 0; i < 3; ++i) {
            dy[i] = v[i];
            dy[3 + i] = ft * g[i] - 2 * wv[i] - wwr[i] - k * r[i];
        }
    };
    const state y = integrate(f, {r0[0], r0[1], r0[2], v0[0], v0[1], v0[2]}, T);
    return {y[0], y[1], y[2]};
}

/// The data of one constant-w case, drawn alike by the constant-w and the compiled families:
/// g, r0, v0 of scale S = 10^e (e in [-250, 250]; the unit-scale g0, r00, v00 for the
/// reference), |w| = 10^e (e in [-300, 0.5]) or exactly 0 (one case in ten), w0 in [0.3, 3],
/// T in [0.5, 10], and one case in four written with the exact rationals of the doubles.
struct constant_w_data {
    double S = 1, w0 = 1, T = 1;
    vec3 w{}, g0{}, r00{}, v00{}, g{}, r0{}, v0{};
    bool exact_numbers = false;
    /// [w = ..., g = ..., r0 = ..., v0 = ...(, w0 = ...)] as symrep reads them
    std::string values(bool with_w0) const {
        return "[w = " + vector_text(w, exact_numbers) + ", g = " + vector_text(g, exact_numbers) +
               ", r0 = " + vector_text(r0, exact_numbers) + ", v0 = " + vector_text(v0, exact_numbers) +
               (with_w0 ? ", w0 = " + (exact_numbers ? exact(w0) : decimal(w0)) : std::string()) + "]";
    }
};

inline constant_w_data draw_constant_w_data(std::mt19937& gen) {
    std::uniform_real_distribution<double> e_data(-250, 250), e_w(-300, 0.5), unit(0.3, 3), times(0.5, 10);
    constant_w_data d;
    d.S = std::pow(10.0, std::floor(e_data(gen)));
    const int wkind = std::uniform_int_distribution<int>(0, 9)(gen);
    const double wn = wkind == 0 ? 0.0 : std::pow(10.0, e_w(gen));
    d.w = draw_direction(gen);
    const double wl = std::sqrt(d.w[0] * d.w[0] + d.w[1] * d.w[1] + d.w[2] * d.w[2]);
    for (double& x : d.w) x *= wn / wl;
    d.g0 = draw_direction(gen);
    d.r00 = draw_direction(gen);
    d.v00 = draw_direction(gen);
    d.w0 = unit(gen);
    d.T = times(gen);
    d.exact_numbers = std::uniform_int_distribution<int>(0, 3)(gen) == 0;
    for (int k = 0; k < 3; ++k) d.g[k] = d.g0[k] * d.S, d.r0[k] = d.r00[k] * d.S, d.v0[k] = d.v00[k] * d.S;
    return d;
}

/// Runs `n` cases of the family with the generator seeded by `seed`: eval of solve(P) at the
/// values, and on every fourth case solve(P, values) as well. Tolerance 1e-9 relative to the
/// norm of r(T) or of the data's scale (the reference is good to ~1e-11; a wrong closed form
/// is off by O(1)).
inline std::vector<outcome> constant_w_family(unsigned seed, int n, bool scenes = true) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    R.run("vector w, g, r0, v0\npositive w0");
    std::string solved_for;  // the problem whose general solution is "s"
    for (int i = 0; i < n; ++i) {
        const constant_w_case c = draw_constant_w(gen);
        outcome o;
        o.family = "constant w";
        o.tolerance = 1e-9;
        const constant_w_data d = draw_constant_w_data(gen);
        const double S = d.S, w0 = d.w0, T = d.T;
        const vec3 &w = d.w, &g0 = d.g0, &r00 = d.r00, &v00 = d.v00;
        const bool exact_numbers = d.exact_numbers;
        const std::string values = d.values(true);
        std::vector<double> ref = constant_w_reference(c, w, w0, g0, r00, v00, T);
        for (double& x : ref) x *= S;
        // the floor of the norm: the size of the data (the reference's error is ~1e-11 of it)
        const double floor = 1e-3 * S;
        const std::string times_text = exact_numbers ? exact(T) : decimal(T);
        o.statements = "P := " + c.problem + "\ns := solve(P)\neval(s, " + values + ", t = " + times_text + ")";
        trace(o.statements);
        try {
            if (solved_for != c.problem) {
                R.run("P := " + c.problem + "\ns := solve(P)");
                solved_for = c.problem;
            }
            const std::vector<double> a = numbers_of(R.value("eval(s, " + values + ", t = " + times_text + ")"));
            o.difference = relative(a, ref, floor);
            if (scenes && i % 4 == 0 && o.difference <= o.tolerance) {
                o.statements = "P := " + c.problem + "\neval(solve(P, " + values + "), " + values +
                               ", t = " + times_text + ")";
                const std::vector<double> b =
                    numbers_of(R.value("eval(solve(P, " + values + "), " + values + ", t = " + times_text + ")"));
                o.difference = relative(b, ref, floor);
            }
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}


// ---- family: a fixed axis at a varying rate, w = s(t) u, forcing along or across u (VI.2) ---

/// Runs `n` cases: w := s(t) u with s(t) a + b t, a + b cos(c t) or a exp(-b t) (a, b, c small
/// rationals, u a literal), k r with k = 0 or a positive rational, the forcing f(t) V with V
/// along u, across it or neither (a literal of size 10^e); solve(P) and eval at r0, v0 of the same
/// scale. Tolerance 1e-8 relative: the solution holds integral objects (Duhamel's integrals
/// over cos a(tau), sin a(tau)) evaluated by quadrature to ~1e-12, the reference ~1e-11.
inline std::vector<outcome> fixed_axis_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    std::uniform_int_distribution<int> small(1, 5), kind(0, 2), vkind(0, 2), forc(0, 3), kk(0, 1);
    std::uniform_real_distribution<double> e_data(-200, 200), times(0.5, 4);
    for (int i = 0; i < n; ++i) {
        runner R;
        outcome o;
        o.family = "fixed axis";
        o.tolerance = 1e-8;
        const int a = small(gen), b = small(gen), c = small(gen);
        std::string s_text;
        std::function<double(double)> s, ds;
        switch (kind(gen)) {
            case 0:
                s_text = std::to_string(a) + "/2 + " + std::to_string(b) + "/3*t";
                s = [=](double t) { return a / 2.0 + b / 3.0 * t; };
                ds = [=](double) { return b / 3.0; };
                break;
            case 1:
                s_text = std::to_string(a) + "/2 + " + std::to_string(b) + "/3*cos(" + std::to_string(c) + "*t)";
                s = [=](double t) { return a / 2.0 + b / 3.0 * std::cos(c * t); };
                ds = [=](double t) { return -b / 3.0 * c * std::sin(c * t); };
                break;
            default:
                s_text = std::to_string(a) + "/2*exp(-" + std::to_string(b) + "/4*t)";
                s = [=](double t) { return a / 2.0 * std::exp(-b / 4.0 * t); };
                ds = [=](double t) { return -b / 4.0 * a / 2.0 * std::exp(-b / 4.0 * t); };
                break;
        }
        const vec3 u = std::uniform_int_distribution<int>(0, 1)(gen) ? vec3{0, 0, 1} : vec3{1, 1, 0};
        const vec3 uv = u;
        vec3 V = draw_direction(gen);
        switch (vkind(gen)) {
            case 0: V = u; break;                                   // along the axis
            case 1: V = cross(u, V); break;                         // across it
            default: break;
        }
        const int k = kk(gen) ? small(gen) : 0;
        const int fc = forc(gen), fa = small(gen);
        std::string f_text;
        std::function<double(double)> f;
        switch (fc) {
            case 0: f_text = "1"; f = [](double) { return 1.0; }; break;
            case 1: f_text = "t"; f = [](double t) { return t; }; break;
            case 2: f_text = "cos(" + std::to_string(fa) + "*t)"; f = [=](double t) { return std::cos(fa * t); }; break;
            default: f_text = "exp(-" + std::to_string(fa) + "/3*t)"; f = [=](double t) { return std::exp(-fa / 3.0 * t); }; break;
        }
        const double S = std::pow(10.0, std::floor(e_data(gen)));
        vec3 Vs, r0 = draw_direction(gen), v0 = draw_direction(gen), r0s, v0s;
        for (int j = 0; j < 3; ++j) Vs[j] = V[j] * S, r0s[j] = r0[j] * S, v0s[j] = v0[j] * S;
        const double T = times(gen);
        const std::string w_text = "w := (" + s_text + ")*" + vector_text(uv, false);
        const std::string P_text = "P := ode(r'' + 2*w x r' + w' x r + w x (w x r)" +
                                   (k ? " + " + std::to_string(k) + "*r" : std::string()) + " = " + f_text + "*" +
                                   vector_text(Vs, false) + ", r(0) = r0, r'(0) = v0)";
        const std::string values = "[r0 = " + vector_text(r0s, false) + ", v0 = " + vector_text(v0s, false) + "]";
        o.statements = "vector r0, v0\n" + w_text + "\n" + P_text + "\ns := solve(P)\neval(s, " + values +
                       ", t = " + decimal(T) + ")";
        auto rhs = [&](const state& y, state& dy, double t) {
            const double st = s(t), dst = ds(t);
            const vec3 w{st * u[0], st * u[1], st * u[2]}, dw{dst * u[0], dst * u[1], dst * u[2]};
            const vec3 r{y[0], y[1], y[2]}, v{y[3], y[4], y[5]};
            const vec3 wv = cross(w, v), dwr = cross(dw, r), wwr = cross(w, cross(w, r));
            const double ft = f(t);
            for (int j = 0; j < 3; ++j) {
                dy[j] = v[j];
                dy[3 + j] = ft * V[j] - 2 * wv[j] - dwr[j] - wwr[j] - k * r[j];
            }
        };
        const state y = integrate(rhs, {r0[0], r0[1], r0[2], v0[0], v0[1], v0[2]}, T);
        const std::vector<double> ref{y[0] * S, y[1] * S, y[2] * S};
        trace(o.statements);
        try {
            R.run("vector r0, v0\n" + w_text + "\n" + P_text + "\ns := solve(P)");
            o.difference = relative(numbers_of(R.value("eval(s, " + values + ", t = " + decimal(T) + ")")), ref,
                                    1e-3 * S);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- quasi-polynomials t^k e^(alpha t) cos(beta t) / sin(beta t) --------------------------------

struct quasi_term {
    int k = 0;
    int alpha_num = 0, alpha_den = 1, beta = 0;
    bool sine = false;
    int coefficient = 1;
    double alpha() const { return double(alpha_num) / alpha_den; }
    std::string text() const {
        std::string s = std::to_string(coefficient);
        if (k) s += "*t^" + std::to_string(k);
        if (alpha_num) s += "*exp((" + std::to_string(alpha_num) + ")/" + std::to_string(alpha_den) + "*t)";
        if (beta) s += std::string(sine ? "*sin(" : "*cos(") + std::to_string(beta) + "*t)";
        return "(" + s + ")";
    }
    /// The j-th derivative at t: Re or Im of c d^j/dt^j (t^k e^(lambda t)), lambda = alpha + i beta.
    double derivative(int j, double t) const {
        const std::complex<double> lambda(alpha(), beta);
        std::complex<double> sum = 0;
        double binom = 1;  // C(j, i)
        for (int i = 0; i <= std::min(j, k); ++i) {
            double falling = 1;  // k!/(k - i)!
            for (int q = 0; q < i; ++q) falling *= (k - q);
            sum += binom * falling * std::pow(t, k - i) * std::pow(lambda, j - i);
            binom = binom * (j - i) / (i + 1);
        }
        sum *= std::exp(lambda * t);
        return coefficient * (sine ? sum.imag() : sum.real());
    }
};

inline quasi_term draw_quasi_term(std::mt19937& gen, bool decaying) {
    quasi_term q;
    q.k = std::uniform_int_distribution<int>(0, 2)(gen);
    q.alpha_num = std::uniform_int_distribution<int>(decaying ? -6 : -4, decaying ? 0 : 4)(gen);
    q.alpha_den = std::uniform_int_distribution<int>(1, 3)(gen);
    q.beta = std::uniform_int_distribution<int>(0, 3)(gen);
    q.sine = std::uniform_int_distribution<int>(0, 1)(gen) == 1;
    q.coefficient = std::uniform_int_distribution<int>(1, 4)(gen) * (std::uniform_int_distribution<int>(0, 1)(gen) ? 1 : -1);
    if (q.beta == 0) q.sine = false;
    return q;
}

// ---- family: response of a0 x^(m) + ... + am x = b0 f^(p) + ... + bp f (IV.3, Thm IV.3.2.1) ----

/// The zero-state response to a quasi-polynomial input against Odeint from rest: m = 2 or 3,
/// integer coefficients (so resonance with the input occurs), t in [0.5, 3]. Tolerance 1e-8
/// relative to the norm of the solution's size along the way (unstable systems grow like
/// e^(6 t); the reference keeps 1e-11 of the largest value).
inline std::vector<outcome> response_family(unsigned seed, int n, int max_order = 3) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    std::uniform_int_distribution<int> coef(-3, 3), order(2, max_order);
    std::uniform_real_distribution<double> times(0.5, 3);
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "response";
        o.tolerance = 1e-8;
        const int m = order(gen), p = std::uniform_int_distribution<int>(0, m - 1)(gen);
        std::vector<int> a(m + 1), b(p + 1);
        for (int& x : a) x = coef(gen);
        a[0] = std::uniform_int_distribution<int>(1, 2)(gen);
        for (int& x : b) x = coef(gen);
        if (b[0] == 0) b[0] = 1;
        const quasi_term f = draw_quasi_term(gen, false);
        const double T = times(gen);
        auto list = [](const std::vector<int>& v) {
            std::string s = "[";
            for (std::size_t j = 0; j < v.size(); ++j) s += (j ? ", " : "") + std::to_string(v[j]);
            return s + "]";
        };
        const std::string call = "response(" + list(a) + ", " + list(b) + ", " + f.text() + ", t)";  // [1]: zero_state
        o.statements = "x := " + call + "[1]\neval(x, [], t = " + decimal(T) + ")";
        auto rhs = [&](const state& y, state& dy, double t) {
            double u = 0;
            for (int j = 0; j <= p; ++j) u += b[j] * f.derivative(p - j, t);
            double acc = u;
            for (int j = 1; j <= m; ++j) acc -= a[j] * y[m - j];
            for (int j = 0; j + 1 < m; ++j) dy[j] = y[j + 1];
            dy[m - 1] = acc / a[0];
        };
        const state y = integrate(rhs, state(m, 0.0), T);
        trace(o.statements);
        try {
            R.run("x := " + call + "[1]");
            o.difference = relative(numbers_of(R.value("eval(x, [], t = " + decimal(T) + ")")), {y[0]}, 1e-6);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- family: Laplace pairs (V.1.3-4) --------------------------------------------------------

/// L[f](s0) of a decaying quasi-polynomial (one or two terms) against exp-sinh quadrature of
/// f(t) e^(-s0 t) over [0, oo) (Boost.Math, tolerance ~1e-13), at s0 = 1/2 and 3: 1e-9 relative.
/// And inverse_laplace of q/p (p a product of (s + a), (s + a)^2 and s^2 + b s + c with b^2 < 4c,
/// q of lower degree): the forward transform of symrep's f by the same quadrature must give
/// q(s0)/p(s0) right of every pole.
inline std::vector<outcome> laplace_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    boost::math::quadrature::exp_sinh<double> quad;
    GiNaC::symbol t_sym("t");
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.tolerance = 1e-9;
        if (i % 2 == 0) {
            o.family = "laplace";
            std::vector<quasi_term> f{draw_quasi_term(gen, true)};
            if (std::uniform_int_distribution<int>(0, 1)(gen)) f.push_back(draw_quasi_term(gen, true));
            std::string text;
            for (const quasi_term& q : f) text += (text.empty() ? "" : " + ") + q.text();
            o.statements = "F := laplace(" + text + ", t, s)";
            trace(o.statements);
            try {
                R.run(o.statements);
                double worst = 0;
                for (double s0 : {0.5, 3.0}) {
                    auto integrand = [&](double t) {
                        double v = 0;
                        for (const quasi_term& q : f) v += q.derivative(0, t);
                        return v * std::exp(-s0 * t);
                    };
                    const double ref = quad.integrate(integrand, 1e-14);
                    const double got = numbers_of(R.value("subs(F, s = " + decimal(s0) + ")"))[0];
                    worst = std::max(worst, relative({got}, {ref}, 1e-6));
                }
                o.difference = worst;
            } catch (const std::exception& e) {
                o.difference = -1;
                o.error = e.what();
            }
        } else {
            o.family = "inverse_laplace";
            std::uniform_int_distribution<int> small(1, 4), nf(1, 3), kind(0, 2), qc(-3, 3);
            std::string p_text;
            int degree = 0;
            std::vector<std::function<std::complex<double>(std::complex<double>)>> factors;
            const int count = nf(gen);
            for (int j = 0; j < count; ++j) {
                const int A = small(gen), B = small(gen);
                switch (kind(gen)) {
                    case 0:
                        p_text += "*(s + " + std::to_string(A) + "/2)";
                        factors.push_back([A](std::complex<double> s) { return s + A / 2.0; });
                        degree += 1;
                        break;
                    case 1:
                        p_text += "*(s + " + std::to_string(A) + "/2)^2";
                        factors.push_back([A](std::complex<double> s) { return (s + A / 2.0) * (s + A / 2.0); });
                        degree += 2;
                        break;
                    default:  // s^2 + b s + c, b = A/2, c = b^2/4 + B (complex roots)
                        p_text += "*(s^2 + " + std::to_string(A) + "/2*s + " + std::to_string(A * A) + "/16 + " +
                                  std::to_string(B) + ")";
                        factors.push_back([A, B](std::complex<double> s) { return s * s + A / 2.0 * s + A * A / 16.0 + double(B); });
                        degree += 2;
                        break;
                }
            }
            std::vector<int> q(degree);
            for (int& c : q) c = qc(gen);
            q[0] = q[0] == 0 ? 1 : q[0];
            std::string q_text = "(";
            for (int j = 0; j < degree; ++j)
                q_text += (j ? " + " : "") + std::string("(") + std::to_string(q[j]) + ")*s^" + std::to_string(j);
            q_text += ")";
            const std::string F_text = q_text + "/(1" + p_text + ")";
            o.statements = "f := inverse_laplace(" + F_text + ", s, t)";
            trace(o.statements);
            try {
                R.run(o.statements);
                const GiNaC::ex f = R.value("f").as_ex();
                GiNaC::ex tt;
                for (auto it = f.preorder_begin(); it != f.preorder_end(); ++it)
                    if (GiNaC::is_a<GiNaC::symbol>(*it) && GiNaC::ex_to<GiNaC::symbol>(*it).get_name() == "t") tt = *it;
                double worst = 0;
                for (double s0 : {0.5, 3.0}) {
                    auto integrand = [&](double t) {
                        // f grows at most like a polynomial (every pole has Re <= 0): beyond
                        // s0 t = 700 the integrand is below 1e-300 (and CLN's exp underflows)
                        if (s0 * t > 700) return 0.0;
                        const GiNaC::ex v = tt.is_zero() ? GiNaC::evalf(f) : GiNaC::evalf(f.subs(tt == t));
                        return GiNaC::ex_to<GiNaC::numeric>(v).to_double() * std::exp(-s0 * t);
                    };
                    const double ref = quad.integrate(integrand, 1e-12);
                    std::complex<double> Q = 0, P = 1;
                    for (int j = 0; j < degree; ++j) Q += double(q[j]) * std::pow(std::complex<double>(s0), j);
                    for (const auto& fac : factors) P *= fac(s0);
                    worst = std::max(worst, relative({ref}, {(Q / P).real()}, 1e-6));
                }
                o.difference = worst;
            } catch (const std::exception& e) {
                o.difference = -1;
                o.error = e.what();
            }
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- family: exp in an algebra (Thm II.2.3, III.1.45-52) ---------------------------------

/// exp(w, t) at t = T for an element of multicomplex(1), walsh(2) or sobrero(1) with small
/// rational coordinates against Eigen's matrix exponential of T L_w (L_w the regular
/// representation, its columns the coordinates of w times the basis elements, computed by
/// symrep's product) applied to the coordinates of 1. Tolerance 1e-10 relative.
inline std::vector<outcome> algebra_exp_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    const std::vector<std::string> algebras{"multicomplex(1)", "walsh(2)", "sobrero(1)", "multicomplex(0)"};
    std::uniform_int_distribution<int> coord(-4, 4), which(0, int(algebras.size()) - 1);
    std::uniform_real_distribution<double> times(0.1, 2);
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "algebra exp";
        o.tolerance = 1e-10;
        const std::string A = algebras[which(gen)];
        const double T = times(gen);
        try {
            R.run("A := " + A);
            const int d = int(numbers_of(R.value("dim(A)"))[0]);
            std::string c = "[";
            for (int j = 0; j < d; ++j) c += (j ? ", " : "") + std::to_string(coord(gen)) + "/2";
            c += "]";
            o.statements = "A := " + A + "\nw := element(A, " + c + ")\ncoords(exp(w, t))";
            R.run("w := element(A, " + c + ")\nE := exp(w, t)");
            Eigen::MatrixXd L(d, d);
            for (int k = 0; k < d; ++k) {
                const auto col = numbers_of(R.value("coords(w*basis(A, " + std::to_string(k) + "))"));
                for (int j = 0; j < d; ++j) L(j, k) = col[j];
            }
            const auto one = numbers_of(R.value("coords(one(A))"));
            Eigen::VectorXd e1(d);
            for (int j = 0; j < d; ++j) e1(j) = one[j];
            const Eigen::MatrixXd M = (L * T).exp();
            const Eigen::VectorXd ref = M * e1;
            const auto got = numbers_of(R.value("evalf(subs(coords(E), t = " + decimal(T) + "))"));
            o.difference = relative(got, std::vector<double>(ref.data(), ref.data() + d), 1e-6);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

}  // namespace symrep::differential
