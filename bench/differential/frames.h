// bench/differential/frames.h -- the differential families of turning frames (issue 27.6):
// an arbitrary w(t) (VI.3, Thm VI.3.2.1), charges in B(t) of a fixed direction (VI.2.42-63),
// Kepler in a turning frame (VI.3.153-157) and relative orbital motion
// (mechanics/relative_motion.h). As in harness.h, symrep gets each problem as a user writes
// it; the reference is Boost.Odeint's Bulirsch-Stoer at 1e-13 on the equation as stated,
// written here from the drawn numbers alone (w'(t) and the LVLH frame by hand).
#pragma once

#include <map>

#include "harness.h"

namespace symrep::differential {

inline vec3 operator+(const vec3& a, const vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline vec3 operator-(const vec3& a, const vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline vec3 operator*(double s, const vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const vec3& a, const vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double norm(const vec3& a) { return std::sqrt(dot(a, a)); }

inline std::string number_text(double x, bool exact_numbers) { return exact_numbers ? exact(x) : decimal(x); }

/// The largest of the relative differences of position and velocity, each against its own
/// norm with its floor (they differ in size by a rate).
inline double relative_pv(const std::vector<double>& got, const std::vector<double>& ref, double floor_r,
                          double floor_v) {
    if (got.size() != 6 || ref.size() != 6) return INFINITY;
    return std::max(relative({got[0], got[1], got[2]}, {ref[0], ref[1], ref[2]}, floor_r),
                    relative({got[3], got[4], got[5]}, {ref[3], ref[4], ref[5]}, floor_v));
}

/// An angular velocity w(t) with its derivative, for the reference.
struct turning_w {
    std::function<vec3(double)> w, dw;
};

/// The rotating-frame equation r'' + 2 w x r' + w' x r + w x (w x r) + f(|r|) r/|r| = 0 as a
/// first-order system (r, r').
inline std::function<void(const state&, state&, double)> rotating_frame_rhs(const turning_w& W,
                                                                             std::function<double(double)> f_over_r) {
    return [W, f_over_r](const state& y, state& dy, double t) {
        const vec3 r{y[0], y[1], y[2]}, v{y[3], y[4], y[5]}, w = W.w(t), dw = W.dw(t);
        const vec3 a = -2.0 * cross(w, v) - cross(dw, r) - cross(w, cross(w, r)) - f_over_r(norm(r)) * r;
        for (int j = 0; j < 3; ++j) dy[j] = v[j], dy[3 + j] = a[j];
    };
}

/// The kinds of w(t) the VI.3 path reads, as problem text and values: a generic turning w
/// [a1 sin(c1 t), a2 cos(c2 t), a3] (Magnus), a regular precession [pa sin(nu t),
/// pa cos(nu t), pb] (Q closed, two Rodrigues rotations), a declared `vector w(t)` given its
/// value at evaluation, and (Kepler only) a fixed axis at a sign-changing rate.
struct drawn_w {
    int kind = 0;
    std::string name;        ///< the name of w in the problem (one per kind: a declared function stays one)
    std::string definition;  ///< statements defining w before the problem ("" for none)
    std::string values;      ///< "name = value" pairs for eval, with a leading ", " ("" for none)
    turning_w W;
};

/// |w| spread by 10^e, e in [e_low, 0.5] (or O(1) when e_low >= 0); frequencies in [0.2, 2.5].
inline drawn_w draw_w(std::mt19937& gen, int kinds, double e_low, bool exact_numbers) {
    drawn_w d;
    d.kind = std::uniform_int_distribution<int>(0, kinds - 1)(gen);
    const std::string name = std::array<const char*, 4>{"w", "wp", "wf", "wa"}[std::size_t(d.kind)];
    d.name = name;
    std::uniform_real_distribution<double> amp(-1.5, 1.5), freq(0.2, 2.5), e(e_low, 0.5);
    const double M = e_low < 0 ? std::pow(10.0, e(gen)) : 1.0;
    const double A1 = M * amp(gen), A2 = M * amp(gen), A3 = M * amp(gen), c1 = freq(gen), c2 = freq(gen);
    auto N = [&](double x) { return number_text(x, exact_numbers); };
    switch (d.kind) {
        case 0:  // generic turning w, its numbers as values
            d.definition = name + " := [a1*sin(c1*t), a2*cos(c2*t), a3]";
            d.values = ", a1 = " + N(A1) + ", c1 = " + N(c1) + ", a2 = " + N(A2) + ", c2 = " + N(c2) + ", a3 = " + N(A3);
            d.W.w = [=](double t) { return vec3{A1 * std::sin(c1 * t), A2 * std::cos(c2 * t), A3}; };
            d.W.dw = [=](double t) { return vec3{A1 * c1 * std::cos(c1 * t), -A2 * c2 * std::sin(c2 * t), 0}; };
            break;
        case 1:  // regular precession
            d.definition = name + " := [pa*sin(nu*t), pa*cos(nu*t), pb]";
            d.values = ", pa = " + N(A1) + ", nu = " + N(c1) + ", pb = " + N(A3);
            d.W.w = [=](double t) { return vec3{A1 * std::sin(c1 * t), A1 * std::cos(c1 * t), A3}; };
            d.W.dw = [=](double t) { return vec3{A1 * c1 * std::cos(c1 * t), -A1 * c1 * std::sin(c1 * t), 0}; };
            break;
        case 2:  // a declared vector function, its value a list in t
            d.definition = "vector " + name + "(t)";
            d.values = ", " + name + " = [" + N(A1) + "*sin(" + N(c1) + "*t), " + N(A2) + "*cos(" + N(c2) + "*t), " +
                       N(A3) + "]";
            d.W.w = [=](double t) { return vec3{A1 * std::sin(c1 * t), A2 * std::cos(c2 * t), A3}; };
            d.W.dw = [=](double t) { return vec3{A1 * c1 * std::cos(c1 * t), -A2 * c2 * std::sin(c2 * t), 0}; };
            break;
        default:  // a fixed axis, a rate that changes sign: (a3 + a1 sin(c1 t)) [0, 0, 1]
            d.definition = name + " := (a3 + a1*sin(c1*t))*[0, 0, 1]";
            d.values = ", a1 = " + N(A1) + ", c1 = " + N(c1) + ", a3 = " + N(A3);
            d.W.w = [=](double t) { return vec3{0, 0, A3 + A1 * std::sin(c1 * t)}; };
            d.W.dw = [=](double t) { return vec3{0, 0, A1 * c1 * std::cos(c1 * t)}; };
            break;
    }
    return d;
}

/// The rotating-frame terms of the problem in w's name: r'' + 2 w x r' + w' x r + w x (w x r).
inline std::string frame_terms(const std::string& w) {
    return "r'' + 2*" + w + " x r' + " + w + "' x r + " + w + " x (" + w + " x r)";
}

/// Runs a case: `setup` once per problem text in the runner (names cached), then `query`
/// (an expression) evaluated; the numbers it gives.
struct cached_runner {
    runner R;
    std::map<std::string, std::string> solved;  ///< setup text -> the name of its solution
    std::string name_for(const std::string& setup) {
        auto it = solved.find(setup);
        if (it != solved.end()) return it->second;
        const std::string name = "sol" + std::to_string(solved.size());
        std::string text = setup;
        // the last statement's "s :=" names the solution
        const auto at = text.rfind("s := ");
        text.replace(at, 5, name + " := ");
        R.run(text);
        solved[setup] = name;
        return name;
    }
};

// ---- family: turning w, the free particle and the oscillator (VI.3.150-151) -----------------

/// r'' + 2 w x r' + w' x r + w x (w x r) (+ w0^2 r) = 0 for each kind of w above with |w|
/// spread over 10^[-300, 0.5] (a tenth of the cases), the data r0, v0 scaled by 10^e,
/// e in [-250, 250] (the problem is linear in them); eval(s, ...) and eval(s', ...) at T in
/// [0.5, 6]. Tolerance 1e-9 relative to the norms of r and r' (floors 1e-3 of the data's
/// scale): Magnus is at 1e-13 per unit time, the oscillator closed, the reference ~1e-11.
inline std::vector<outcome> turning_w_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    cached_runner C;
    C.R.run("vector r0, v0");
    std::uniform_real_distribution<double> e_data(-250, 250), times(0.5, 6), unit(0.3, 2);
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "turning w";
        o.tolerance = 1e-9;
        const bool exact_numbers = std::uniform_int_distribution<int>(0, 3)(gen) == 0;
        const bool tiny = std::uniform_int_distribution<int>(0, 9)(gen) == 0;
        const drawn_w d = draw_w(gen, 3, tiny ? -300 : 0, exact_numbers);
        const bool oscillator = std::uniform_int_distribution<int>(0, 1)(gen) == 1;
        const double w0 = unit(gen), S = std::pow(10.0, std::floor(e_data(gen))), T = times(gen);
        const vec3 r00 = draw_direction(gen), v00 = draw_direction(gen);
        const std::string setup = d.definition + "\nP := ode(" + frame_terms(d.name) +
                                  (oscillator ? " + w0^2*r" : "") + " = 0, r(0) = r0, r'(0) = v0)\ns := solve(P)";
        const std::string values = "[r0 = " + vector_text(S * r00, exact_numbers) + ", v0 = " +
                                   vector_text(S * v00, exact_numbers) +
                                   (oscillator ? ", w0 = " + number_text(w0, exact_numbers) : "") + d.values + "]";
        const std::string at = ", t = " + number_text(T, exact_numbers) + ")";
        o.statements = "vector r0, v0\n" + setup + "\neval(s, " + values + at + "\neval(s', " + values + at;
        trace(o.statements);
        const double k = oscillator ? w0 * w0 : 0;
        state y;
        if (!reference(o, [&] {
                y = integrate(rotating_frame_rhs(d.W, [k](double) { return k; }),
                              {r00[0], r00[1], r00[2], v00[0], v00[1], v00[2]}, T);
            })) {
            out.push_back(std::move(o));
            continue;
        }
        for (double& x : y) x *= S;
        try {
            const std::string s = C.name_for(setup);
            std::vector<double> got = numbers_of(C.R.value("eval(" + s + ", " + values + at));
            const std::vector<double> v = numbers_of(C.R.value("eval(" + s + "', " + values + at));
            got.insert(got.end(), v.begin(), v.end());
            o.difference = relative_pv(got, y, 1e-3 * S, 1e-3 * S);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- family: a charge in E and B(t) = b(t) n, n fixed (VI.2.42-63) ---------------------------

/// m r'' = q (r' x B + E) (position) or m v' = q (v x B + E) (velocity), B := b(t) N with b
/// in a + b t, a + b t^2, a + b sin(c t) (changes sign when b > a), a e^(-b t), N of size
/// 10^eB (eB in [-30, 30]; a vector symbol n with its value, or a literal); q of size 10^eq (eq in [-25, 5]) and m such that q |N|/m is
/// in [0.3, 2] (a rate of order one: the reference integrates the orbit); E along N, across it
/// or neither, |E| ~ |N| (q |E|/m of order one too); E, r0, v0 scaled by 10^e, e in [-200, 200]; T in [0.3, 6]. symrep:
/// solve(P) and eval (the Duhamel integrals and, for the position with E across B, the nested
/// integrals VI.2.62-63 by quadrature). Tolerance 1e-8 relative, as the fixed-axis family.
inline std::vector<outcome> charge_family(unsigned seed, int n, bool float_literals = true) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    cached_runner C;
    C.R.run("vector E, r0, v0, n");
    std::uniform_int_distribution<int> small(1, 5), kind(0, 3), ekind(0, 2);
    std::uniform_real_distribution<double> e_data(-200, 200), e_B(-30, 30), e_q(-25, 5), rate(0.3, 2),
        times(0.3, 6);
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "charge in B(t)";
        o.tolerance = 1e-8;
        const bool exact_numbers = std::uniform_int_distribution<int>(0, 3)(gen) == 0;
        const bool position = std::uniform_int_distribution<int>(0, 2)(gen) != 0;
        const int a = small(gen), b = small(gen), c = small(gen);
        std::string b_text;
        std::function<double(double)> bt;
        switch (kind(gen)) {
            case 0:
                b_text = std::to_string(a) + "/2 + " + std::to_string(b) + "/3*t";
                bt = [=](double t) { return a / 2.0 + b / 3.0 * t; };
                break;
            case 1:
                b_text = std::to_string(a) + "/2 + " + std::to_string(b) + "/10*t^2";
                bt = [=](double t) { return a / 2.0 + b / 10.0 * t * t; };
                break;
            case 2:
                b_text = std::to_string(a) + "/4 + " + std::to_string(b) + "/3*sin(" + std::to_string(c) + "*t)";
                bt = [=](double t) { return a / 4.0 + b / 3.0 * std::sin(c * t); };
                break;
            default:
                b_text = std::to_string(a) + "/2*exp(-" + std::to_string(b) + "/4*t)";
                bt = [=](double t) { return a / 2.0 * std::exp(-b / 4.0 * t); };
                break;
        }
        vec3 n0 = draw_direction(gen);
        n0 = (1 / norm(n0)) * n0;
        const double NB = std::pow(10.0, std::floor(e_B(gen)));
        const vec3 N = NB * n0;
        const double q = (std::uniform_int_distribution<int>(0, 1)(gen) ? 1 : -1) * rate(gen) *
                         std::pow(10.0, e_q(gen));
        const double m = std::abs(q) * NB / rate(gen);
        vec3 E0 = draw_direction(gen);
        switch (ekind(gen)) {
            case 0: E0 = dot(E0, n0) * n0; if (norm(E0) == 0) E0 = n0; break;  // along B
            case 1: E0 = cross(n0, E0); break;                                   // across B
            default: break;
        }
        E0 = NB * E0;  // E of the size of v x B: q E/m of order one, as q |B|/m
        const double S = std::pow(10.0, std::floor(e_data(gen))), T = times(gen);
        const vec3 r00 = draw_direction(gen), v00 = draw_direction(gen);
        // E, r0, v0 scaled by S: the reference integrates the data of size 1 (linear in them)
        // N: a vector symbol given its value (most cases), or a literal of exact rationals; a
        // literal of decimals only with float_literals (docs/testing.md, still open: the rate
        // multiplied into the decimals is no longer read as b(t) times one direction)
        const int nkind = std::uniform_int_distribution<int>(0, float_literals ? 3 : 2)(gen);
        const std::string N_text = nkind <= 1 ? "n" : vector_text(N, nkind == 2);
        const std::string setup =
            "B := (" + b_text + ")*" + N_text + "\n" +
            (position ? "P := ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)"
                      : "P := ode(m*v' = q*(v x B + E), v(0) = v0)") +
            "\ns := solve(P)";
        const std::string values = "[q = " + number_text(q, exact_numbers) + ", m = " + number_text(m, exact_numbers) +
                                   (nkind <= 1 ? ", n = " + vector_text(N, exact_numbers) : std::string()) +
                                   ", E = " + vector_text(S * E0, exact_numbers) +
                                   (position ? ", r0 = " + vector_text(S * r00, exact_numbers) : "") +
                                   ", v0 = " + vector_text(S * v00, exact_numbers) + "]";
        const std::string at = ", t = " + number_text(T, exact_numbers) + ")";
        o.statements = "vector E, r0, v0, n\n" + setup + "\neval(s, " + values + at;
        trace(o.statements);
        const double qm = q / m;
        auto rhs = [&](const state& y, state& dy, double t) {
            const vec3 v{y[3], y[4], y[5]};
            const vec3 acc = qm * (cross(v, bt(t) * N) + E0);
            for (int j = 0; j < 3; ++j) dy[j] = v[j], dy[3 + j] = acc[j];
        };
        state y;
        if (!reference(o, [&] { y = integrate(rhs, {r00[0], r00[1], r00[2], v00[0], v00[1], v00[2]}, T); })) {
            out.push_back(std::move(o));
            continue;
        }
        std::vector<double> ref;
        for (int j = position ? 0 : 3; j < (position ? 3 : 6); ++j) ref.push_back(S * y[j]);
        try {
            const std::string s = C.name_for(setup);
            o.difference = relative(numbers_of(C.R.value("eval(" + s + ", " + values + at)), ref, 1e-3 * S);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- family: Kepler in a turning frame (VI.3.153-157) ----------------------------------------

/// r'' + 2 w x r' + w' x r + w x (w x r) + k r/|r|^3 = 0 with w none (the inertial orbit),
/// generic turning, a regular precession, declared, or a fixed axis at a sign-changing rate
/// (|w| of order 1), k = L^3 k0 and r0 = L r00, v0 = L v00 with the length L = 10^e, e in
/// [-90, 90] (time unscaled: r/L solves the problem with k0); the inertial orbit psi(0) = r00,
/// psi'(0) = v00 + w(0) x r00 keeps its pericentre above 0.25 (ellipses and hyperbolas);
/// eval(s) and eval(s') at T in [0.5, 5]. Tolerance 1e-8 relative (docs/mechanics.md: the
/// reduction ~1e-13; the reference near the pericentre ~1e-10).
inline std::vector<outcome> kepler_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    cached_runner C;
    C.R.run("vector r0, v0");
    std::uniform_real_distribution<double> e_L(-90, 90), times(0.5, 5), kk(0.5, 2), unit(-1, 1);
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "kepler";
        o.tolerance = 1e-8;
        const bool exact_numbers = std::uniform_int_distribution<int>(0, 3)(gen) == 0;
        const bool inertial = std::uniform_int_distribution<int>(0, 4)(gen) == 0;
        const drawn_w d = draw_w(gen, 4, 0, exact_numbers);
        const double k0 = kk(gen), L = std::pow(10.0, std::floor(e_L(gen))), T = times(gen);
        vec3 r00, v00;
        for (int tries = 0;; ++tries) {
            r00 = {unit(gen), unit(gen), unit(gen)};
            r00 = ((0.6 + 0.8 * (unit(gen) + 1) / 2) / norm(r00)) * r00;  // |r0| in [0.6, 1.4]
            v00 = {unit(gen), unit(gen), unit(gen)};
            const vec3 p = inertial ? v00 : v00 + cross(d.W.w(0), r00);
            const double h = norm(cross(r00, p)), E = dot(p, p) / 2 - k0 / norm(r00);
            const double e = std::sqrt(std::max(0.0, 1 + 2 * E * h * h / (k0 * k0)));
            if (h * h / (k0 * (1 + e)) > 0.25) break;
        }
        const std::string setup =
            (inertial ? std::string("P := ode(r'' + k*r/|r|^3 = 0, r(0) = r0, r'(0) = v0)")
                      : d.definition + "\nP := ode(" + frame_terms(d.name) + " + k*r/|r|^3 = 0, r(0) = r0, r'(0) = v0)") +
            "\ns := solve(P)";
        const std::string values = "[k = " + number_text(k0 * L * L * L, exact_numbers) + ", r0 = " +
                                   vector_text(L * r00, exact_numbers) + ", v0 = " +
                                   vector_text(L * v00, exact_numbers) + (inertial ? "" : d.values) + "]";
        const std::string at = ", t = " + number_text(T, exact_numbers) + ")";
        o.statements = "vector r0, v0\n" + setup + "\neval(s, " + values + at + "\neval(s', " + values + at;
        trace(o.statements);
        turning_w W = d.W;
        if (inertial) W.w = W.dw = [](double) { return vec3{0, 0, 0}; };
        state y;
        if (!reference(o, [&] {
                y = integrate(rotating_frame_rhs(W, [k0](double r) { return k0 / (r * r * r); }),
                              {r00[0], r00[1], r00[2], v00[0], v00[1], v00[2]}, T);
            })) {
            out.push_back(std::move(o));
            continue;
        }
        for (double& x : y) x *= L;
        try {
            const std::string s = C.name_for(setup);
            std::vector<double> got = numbers_of(C.R.value("eval(" + s + ", " + values + at));
            const std::vector<double> v = numbers_of(C.R.value("eval(" + s + "', " + values + at));
            got.insert(got.end(), v.begin(), v.end());
            o.difference = relative_pv(got, y, 1e-3 * L, 1e-3 * L);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

// ---- family: relative orbital motion (mechanics/relative_motion.h) ---------------------------

/// The LVLH axes of an orbital state as the columns of C (x radial, z along R x V, y = z x x).
inline std::array<vec3, 3> lvlh_axes(const vec3& R, const vec3& V) {
    const vec3 x = (1 / norm(R)) * R, h = cross(R, V), z = (1 / norm(h)) * h, y = cross(z, x);
    return {x, y, z};
}

/// (R + d)/|R + d|^3 - R/|R|^3 without the cancellation of the difference (d << R).
inline vec3 field_difference(const vec3& R, const vec3& d) {
    const vec3 Rd = R + d;
    const double a = norm(R), b = norm(Rd);
    const double a_minus_b = -(2 * dot(R, d) + dot(d, d)) / (a + b);                // |R| - |R + d|
    const double inv3 = a_minus_b * (a * a + a * b + b * b) / (a * a * a * b * b * b);  // 1/b^3 - 1/a^3
    return (1 / (b * b * b)) * d + inv3 * R;
}

/// relative_motion (exact), clohessy_wiltshire, tschauner_hempel and yamanaka_ankersen at
/// T in [0.1, 2] orbits of a target with eccentricity up to ~0.6 (R0 of any direction), the
/// length L = 10^e (e in [-30, 30]) and the mean motion 10^e' (e' in [-5, 1]), so mu =
/// L^3 n^2 spreads over 10^[-100, 92]; the separation 10^[-7, -1] of L (exact), 10^[-150, 0]
/// for the linear models (beyond |R| their integration, target and rho in one state with one
/// absolute tolerance from |rho|, no longer controls the target: not a meaningful input). References (units L and 1/n, mu = 1): the exact motion from the target and
/// the separation d = r_c - r_t integrated inertially (d scaled by its size, the field
/// difference without cancellation) and turned into LVLH components, rho' = C^T (d' - w x d),
/// w = (R x V)/|R|^2; the linear models from their LVLH equations with the target's orbit
/// (Clohessy-Wiltshire: the target circular at the rate n). Tolerance 1e-8 relative to the
/// norms of rho and rho', for the exact model plus 1e-14 |R|/|rho| (it differences two Kepler
/// orbits, each to a few ulps of |R| times their growth over two orbits).
inline std::vector<outcome> relative_motion_family(unsigned seed, int n) {
    std::mt19937 gen(seed);
    std::vector<outcome> out;
    runner R;
    std::uniform_real_distribution<double> e_L(-30, 30), e_n(-5, 1), e_sep(-7, -1), e_lin(-150, 0), unit(-1, 1),
        orbits(0.1, 2), speed(0.85, 1.2);
    const char* models[] = {"relative_motion", "clohessy_wiltshire", "tschauner_hempel", "yamanaka_ankersen"};
    for (int i = 0; i < n; ++i) {
        outcome o;
        o.family = "relative motion";
        o.tolerance = 1e-8;
        const int model = std::uniform_int_distribution<int>(0, 3)(gen);
        const double L = std::pow(10.0, std::floor(e_L(gen))), nm = std::pow(10.0, e_n(gen));
        // the target in units L, 1/n (mu = 1): |R0| = 1, V0 across R0 times [0.85, 1.2] plus a radial part
        vec3 R0 = {unit(gen), unit(gen), unit(gen)};
        R0 = (1 / norm(R0)) * R0;
        vec3 a = cross(R0, {unit(gen), unit(gen), unit(gen)});
        a = (1 / norm(a)) * a;
        const vec3 V0 = speed(gen) * a + (0.2 * unit(gen)) * R0;
        const double sep = model == 0 ? std::pow(10.0, e_sep(gen)) : std::pow(10.0, e_lin(gen));
        const vec3 rho0 = sep * vec3{unit(gen), unit(gen), unit(gen)}, drho0 = sep * vec3{unit(gen), unit(gen), unit(gen)};
        const double En = dot(V0, V0) / 2 - 1, sma = -1 / (2 * En);
        const double period = 2 * M_PI * std::pow(sma, 1.5);
        const double tau = orbits(gen) * (model == 1 ? 2 * M_PI : period);  // in units 1/n
        const bool exact_numbers = std::uniform_int_distribution<int>(0, 3)(gen) == 0;
        auto N = [&](double x) { return number_text(x, exact_numbers); };
        auto Vt = [&](const vec3& v) { return vector_text(v, exact_numbers); };
        const double mu = L * L * L * nm * nm;
        const std::string tail = Vt(L * rho0) + ", " + Vt(L * nm * drho0) + ", t = " + N(tau / nm) + ")";
        if (model == 1)
            o.statements = std::string(models[model]) + "(" + N(nm) + ", " + tail;
        else
            o.statements = std::string(models[model]) + "(" + N(mu) + ", " + Vt(L * R0) + ", " + Vt(L * nm * V0) +
                           ", " + tail;
        o.family = std::string("relative motion: ") + models[model];
        // the exact model differences two Kepler orbits, each to a few ulps of |R| times their
        // growth over two orbits: 1e-14 |R|/|rho| more (1e-7 at the closest separation)
        if (model == 0) o.tolerance = 1e-8 + 1e-14 / sep;
        trace(o.statements);
        std::vector<double> ref(6);
        if (!reference(o, [&] {
        if (model == 1) {  // x'' - 2 y' - 3 x = 0, y'' + 2 x' = 0, z'' + z = 0 (n = 1)
            auto f = [](const state& y, state& dy, double) {
                dy = {y[3], y[4], y[5], 2 * y[4] + 3 * y[0], -2 * y[3], -y[2]};
            };
            const state y = integrate(
                f, {rho0[0] / sep, rho0[1] / sep, rho0[2] / sep, drho0[0] / sep, drho0[1] / sep, drho0[2] / sep}, tau);
            for (int j = 0; j < 6; ++j) ref[j] = sep * y[j];
        } else {
            const auto C0 = lvlh_axes(R0, V0);
            const vec3 w0 = (1 / dot(R0, R0)) * cross(R0, V0);
            if (model == 0) {
                // inertial: d = C rho, d' = C rho' + w x d; the state R, V, d/sep, d'/sep
                vec3 d0{0, 0, 0}, dd0{0, 0, 0};
                for (int j = 0; j < 3; ++j) d0 = d0 + rho0[j] * C0[j], dd0 = dd0 + drho0[j] * C0[j];
                dd0 = dd0 + cross(w0, d0);
                d0 = (1 / sep) * d0, dd0 = (1 / sep) * dd0;
                auto f = [sep](const state& y, state& dy, double) {
                    const vec3 Rt{y[0], y[1], y[2]}, d{y[6], y[7], y[8]};
                    const double r = norm(Rt);
                    const vec3 gt = (-1 / (r * r * r)) * Rt, gd = (-1 / sep) * field_difference(Rt, sep * d);
                    dy = {y[3], y[4], y[5], gt[0], gt[1], gt[2], y[9], y[10], y[11], gd[0], gd[1], gd[2]};
                };
                const state y = integrate(
                    f, {R0[0], R0[1], R0[2], V0[0], V0[1], V0[2], d0[0], d0[1], d0[2], dd0[0], dd0[1], dd0[2]}, tau);
                const vec3 RT{y[0], y[1], y[2]}, VT{y[3], y[4], y[5]}, dT{y[6], y[7], y[8]}, ddT{y[9], y[10], y[11]};
                const auto CT = lvlh_axes(RT, VT);
                const vec3 wT = (1 / dot(RT, RT)) * cross(RT, VT), rel = ddT - cross(wT, dT);
                for (int j = 0; j < 3; ++j) ref[j] = sep * dot(CT[j], dT), ref[3 + j] = sep * dot(CT[j], rel);
            } else {
                // the linearized LVLH equation: w = (0, 0, h/|R|^2), w' = (0, 0, -2 h (R.V)/|R|^4)
                const double h = norm(cross(R0, V0));
                auto f = [h, sep](const state& y, state& dy, double) {
                    const vec3 Rt{y[0], y[1], y[2]}, Vv{y[3], y[4], y[5]}, p{y[6], y[7], y[8]}, dp{y[9], y[10], y[11]};
                    const double r = norm(Rt), rr = r * r;
                    const vec3 w{0, 0, h / rr}, dw{0, 0, -2 * h * dot(Rt, Vv) / (rr * rr)};
                    const vec3 tidal = (1 / (rr * r)) * (p - vec3{3 * p[0], 0, 0});
                    const vec3 acc = -2.0 * cross(w, dp) - cross(dw, p) - cross(w, cross(w, p)) - tidal;
                    const vec3 gt = (-1 / (rr * r)) * Rt;
                    dy = {y[3], y[4], y[5], gt[0], gt[1], gt[2], dp[0], dp[1], dp[2], acc[0], acc[1], acc[2]};
                    (void)sep;
                };
                const state y = integrate(f,
                                          {R0[0], R0[1], R0[2], V0[0], V0[1], V0[2], rho0[0] / sep, rho0[1] / sep,
                                           rho0[2] / sep, drho0[0] / sep, drho0[1] / sep, drho0[2] / sep},
                                          tau);
                for (int j = 0; j < 6; ++j) ref[j] = sep * y[6 + j];
            }
        }
            })) {
            out.push_back(std::move(o));
            continue;
        }
        for (int j = 0; j < 6; ++j) ref[j] *= L * (j < 3 ? 1 : nm);
        try {
            const std::vector<double> got = numbers_of(R.value(o.statements));
            o.difference = relative_pv(got, ref, 1e-3 * L * sep, 1e-3 * L * nm * sep);
        } catch (const std::exception& e) {
            o.difference = -1;
            o.error = e.what();
        }
        out.push_back(std::move(o));
    }
    return out;
}

}  // namespace symrep::differential
