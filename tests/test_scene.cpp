// tests/test_scene.cpp -- scenes (a problem plus values) and their smallest exact
// models (mechanics/scene.h, solve(P, values), model(P, values), check(P, s, values)).
//
// Every scene is solved twice: in its minimal model, and by the general solver
// with the values put in afterwards (the exact limit where the general form is
// singular at the values). The two must be exactly equal (vector::equal: exact
// zero test by components, no tolerance), and the minimal solution must pass the
// exact check of the problem with the values put in.
#include <gtest/gtest.h>

#include <cmath>

#include <random>
#include <sstream>

#include "scalar/scalar.h"
#include "lang/values.h"
#include "mechanics/scene.h"
#include "test_support.h"
#include "vector/vector.h"

using namespace symrep;
using namespace symrep::lang;
using symrep::mechanics::data_relation;
using symrep::test::test_session;
using GiNaC::ex;

namespace {

constexpr data_relation Z = data_relation::zero, A = data_relation::along_axis,
                        Pp = data_relation::perpendicular, G = data_relation::general,
                        N = data_relation::no_operator;

struct scene_case {
    std::string name;
    std::string declarations;
    std::string problem;
    std::string values;
    std::vector<data_relation> relations;  // per data vector: initial values, then forcing vectors
};

// A scene in a session: P, its general solution Gs, the values vals, the minimal
// solution s; the values read as the builtins read them, and the scene's model.
struct solved_scene {
    test_session t;
    data_values d;
    mechanics::parameter_values v;
    const mechanics::cauchy_problem* P = nullptr;
    mechanics::scene_model M;
    solved_scene(const std::string& declarations, const std::string& problem, const std::string& values) {
        const int failed = t.run(declarations + "\nP := " + problem + "\nGs := solve(P)\nvals := " + values +
                                 "\ns := solve(P, vals)");
        EXPECT_EQ(failed, 0) << t.err.str();
        if (failed) return;
        builtin b;
        b.name = "test";
        d = read_values(t.val("vals"), b, 0);
        v = {d.vectors, d.scalars};
        P = &t.val("P").as_problem();
        M = mechanics::classify(*P, v);
    }
};

// The general solution with the values put in; where it is singular there, its
// exact limit: each zero scalar value approached by lambda -> 0 (the lambda^0 term
// of the series, after the 1/lambda terms are seen to cancel; cos(-u) read as
// cos(u) so that they do), or eval's limit for a zero vector (lang/values.h).
ex general_with_values(const ex& g, const data_values& d, const mechanics::parameter_values& v) {
    try {
        return mechanics::put_values(g, v);
    } catch (const symrep::error&) {
    }
    const GiNaC::possymbol lambda("lambda");
    mechanics::parameter_values vl = v;
    bool any = false;
    for (auto& [k, x] : vl.scalars)
        if (x.is_zero()) {
            x = lambda;
            any = true;
        }
    if (!any) return put_values_limit(g, d);
    const ex c = mechanics::put_values(g, vl);
    auto lim = [&](const ex& x) {
        const ex p = GiNaC::expand(normalize_trig_signs(GiNaC::series_to_poly(x.series(lambda == 0, 1))));
        EXPECT_TRUE(is_zero_scalar(p.coeff(lambda, -1))) << p;
        return p.coeff(lambda, 0);
    };
    if (!GiNaC::is_a<GiNaC::matrix>(c)) return lim(c);
    return vector_literal(lim(c.op(0)), lim(c.op(1)), lim(c.op(2)));
}

// Solves the scene both ways and checks everything the minimal model promises.
void check_minimal_equals_general(const scene_case& c) {
    SCOPED_TRACE(c.name);
    solved_scene sc(c.declarations, c.problem, c.values);
    ASSERT_NE(sc.P, nullptr);
    test_session& t = sc.t;
    const mechanics::cauchy_problem& P = *sc.P;
    const mechanics::scene_model& M = sc.M;
    const mechanics::parameter_values& v = sc.v;
    ASSERT_EQ(M.data.size(), c.relations.size()) << M.report();
    for (std::size_t i = 0; i < c.relations.size(); ++i)
        EXPECT_EQ(int(M.data[i].relation), int(c.relations[i])) << M.data[i].name << "\n" << M.report();
    // equal results, exactly
    const ex s = t.ex("s");
    const ex g = general_with_values(t.ex("Gs"), sc.d, v);
    EXPECT_TRUE(equal(s, g)) << "minimal: " << to_string(s) << "\ngeneral: " << to_string(g);
    // the minimal solution solves the problem with the values, exactly
    const mechanics::solution_check k = mechanics::check(mechanics::with_values(P, v), s);
    EXPECT_TRUE(k.residual_zero) << to_string(k.residual);
    EXPECT_TRUE(k.initial_ok);
    // and the operator-level solution is exact modulo each m_P
    const mechanics::rotation_operator_algebra R(M.form.Omega);
    const mechanics::operator_solution S = mechanics::solve(M.form.ode, R, P.t, M.factors());
    const mechanics::verification ver = mechanics::verify(M.form.ode, R, S, M.factors());
    EXPECT_TRUE(ver) << ver.detail;
    // the printed report names the model (solve's side output)
    EXPECT_NE(t.out.str().find("solve: model: R[X]/("), std::string::npos) << t.out.str();
}

/// check_minimal_equals_general's verdict for one scene: true when it recorded
/// no failure (so each test names the scenes that failed).
bool minimal_equals_general(const scene_case& c) {
    const testing::TestResult* r = testing::UnitTest::GetInstance()->current_test_info()->result();
    const int before = r->total_part_count();
    check_minimal_equals_general(c);
    return r->total_part_count() == before;
}

const std::string rotating = "vector w, g, r0, v0; positive W";
const std::string centrifugal = "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)";
const std::string coriolis = "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)";
const std::string charge_decl = "vector E, B, v0, r0; positive m";
const std::string charge_v = "ode(m*v' = q*(v x B + E), v(0) = v0)";
const std::string charge_r = "ode(m*r'' = q*(r' x B + E), r(0) = r0, r'(0) = v0)";
const std::string foucault_decl = "vector w, r0, v0; positive w0, W";
const std::string foucault = "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)";

}  // namespace

// Gravity in a rotating frame (VI.1.50, 56): w parallel, perpendicular, general to g.
TEST(Scene, GravityInARotatingFrame) {
    const std::vector<scene_case> cases = {
        {"w parallel to g", rotating, centrifugal,
         "[w = [0, 0, W], g = [0, 0, -981/100], r0 = [1, 2, 0], v0 = [0, 0, 3]]", {Pp, A, A}},
        {"w perpendicular to g", rotating, centrifugal,
         "[w = [0, 0, W], g = [-981/100, 0, 0], r0 = [1, 2, 3], v0 = [0, 0, 0]]", {G, Z, Pp}},
        {"general w and g", rotating, centrifugal,
         "[w = [1, 2, 2], g = [0, 0, -10], r0 = [1, 0, 0], v0 = [0, 1, 0]]", {G, G, G}},
        {"Coriolis only, w parallel to g", rotating, coriolis,
         "[w = [0, 0, W], g = [0, 0, -981/100], r0 = [1, 0, 0], v0 = [0, 0, 0]]", {Pp, Z, A}},
        {"Coriolis only, w perpendicular to g", rotating, coriolis,
         "[w = [0, W, 0], g = [0, 0, -981/100], r0 = [0, 5, 0], v0 = [0, 0, 1]]", {A, Pp, Pp}},
        {"symbolic g in the plane of rotation", rotating, centrifugal, "[w = [0, 0, W], g = [a, b, 0]]",
         {G, G, Pp}},
        {"w = 0", rotating, centrifugal, "[w = [0, 0, 0], g = [0, 0, -10], r0 = [1, 2, 3], v0 = [4, 5, 6]]",
         {A, A, A}},
    };
    for (const scene_case& c : cases) EXPECT_TRUE(minimal_equals_general(c)) << c.name;
}

// A charge in uniform fields (VI.1.58): E parallel, perpendicular, general to B.
TEST(Scene, ChargeInElectricAndMagneticFields) {
    const std::vector<scene_case> cases = {
        {"E parallel to B (velocity)", charge_decl, charge_v, "[B = [0, 0, 2], E = [0, 0, 3], v0 = [1, 0, 1]]",
         {G, A}},
        {"E perpendicular to B (velocity)", charge_decl, charge_v,
         "[B = [0, 0, 2], E = [0, 3, 0], v0 = [1, 0, 0]]", {Pp, Pp}},
        {"general E and B (velocity)", charge_decl, charge_v, "[B = [0, 0, 2], E = [1, 0, 1], v0 = [1, 1, 1]]",
         {G, G}},
        {"E perpendicular to B (position), symbolic q", charge_decl, charge_r,
         "[B = [0, 0, 1], E = [0, 1/2, 0], r0 = [0, 0, 0], v0 = [0, 1, 3/10]]", {Z, G, Pp}},
        {"E parallel to B (position), along data", charge_decl, charge_r,
         "[B = [1, 1, 0], E = [2, 2, 0], r0 = [3, 3, 0], v0 = [-1, -1, 0], q = 2, m = 3]", {A, A, A}},
        {"no charge", charge_decl, charge_v, "[B = [0, 0, 2], E = [1, 0, 1], v0 = [1, 1, 1], q = 0]", {N, Z}},
    };
    for (const scene_case& c : cases) EXPECT_TRUE(minimal_equals_general(c)) << c.name;
}

// Foucault (VI.1.68) with w0 = 0 (the general form is singular there: the limit is
// compared), data in the plane of rotation, the reduced problem (VI.2.93) with
// data along w.
TEST(Scene, FoucaultPendulum) {
    const std::vector<scene_case> cases = {
        {"w0 = 0", foucault_decl, foucault, "[w0 = 0, w = [0, 0, 3], r0 = [1, 0, 0], v0 = [0, 1, 0]]", {Pp, Pp}},
        {"swing in the plane of rotation", foucault_decl, foucault,
         "[w = [0, 0, W], r0 = [3, 0, 0], v0 = [0, 0, 0], w0 = 1/2]", {Pp, Z}},
        {"released on the axis", foucault_decl, foucault, "[w = [0, 0, W], r0 = [0, 0, 3], v0 = [0, 0, 1]]",
         {A, A}},
        {"reduced problem, data along w", foucault_decl,
         "ode(r'' + 2*w x r' + w0^2*r = 0, r(0) = r0, r'(0) = v0 + w x r0)",
         "[w = [1, 1, 1], r0 = [2, 2, 2], v0 = [-1, -1, -1]]", {A, A}},
    };
    for (const scene_case& c : cases) EXPECT_TRUE(minimal_equals_general(c)) << c.name;
}

// Scenes not taken from the examples: random integer directions that happen to be
// perpendicular or parallel (g = a x b is perpendicular to w = a, r0 = k a along it),
// a first-order problem with quasi-polynomial forcing, symbolic directions.
TEST(Scene, HeldOutScenes) {
    std::mt19937 gen(20240607);
    std::uniform_int_distribution<int> d(-5, 5), k(1, 7);
    auto vec = [](int x, int y, int z) {
        return "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + "]";
    };
    for (int n = 0; n < 4; ++n) {
        int a[3], b[3];
        do {
            for (int i = 0; i < 3; ++i) { a[i] = d(gen); b[i] = d(gen); }
        } while ((a[0] == 0 && a[1] == 0 && a[2] == 0) ||
                 (a[1] * b[2] - a[2] * b[1] == 0 && a[2] * b[0] - a[0] * b[2] == 0 && a[0] * b[1] - a[1] * b[0] == 0));
        const int c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        const int s = k(gen);
        const std::string values = "[w = " + vec(a[0], a[1], a[2]) + "/" + std::to_string(s) + ", g = " +
                                   vec(c[0], c[1], c[2]) + ", r0 = " + vec(s * a[0], s * a[1], s * a[2]) +
                                   "/7, v0 = " + vec(b[0] + c[0], b[1] + c[1], b[2] + c[2]) + "]";
        // v0 = b + a x b is perpendicular to w exactly when a . b = 0
        const bool v0_perp = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] == 0;
        EXPECT_TRUE(minimal_equals_general({"random directions " + values, rotating, centrifugal, values, {A, v0_perp ? Pp : G, Pp}}));
    }
    EXPECT_TRUE(minimal_equals_general({"first order, forcing along and across w", "vector w, a, b, r0",
                                   "ode(r' + w x r = cos(2*t)*a + t*exp(-t)*b, r(0) = r0)",
                                   "[w = [2, -1, 2], a = [1, 2, 0], b = [4, -2, 4], r0 = [0, 2, 1]]", {Pp, Pp, A}}));
    EXPECT_TRUE(minimal_equals_general({"symbolic axis, forcing along it", "vector w, g, r0, v0",
                                   "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)",
                                   "[w = [p, q, u], g = [5*p, 5*q, 5*u], v0 = [q, -p, 0]]", {G, Pp, A}}));
    EXPECT_TRUE(minimal_equals_general({"(w . r) w term", "vector w, r0, v0; positive k",
                                   "ode(r'' + k*(w . r)*w = 0, r(0) = r0, r'(0) = v0)",
                                   "[w = [0, 0, 2], r0 = [1, 1, 0], v0 = [0, 0, 1]]", {Pp, A}}));
}

// The model is smaller: only the scalar problems it needs are solved, each data
// vector's coefficients live in R[X]/(m_P), and the motion of data along w stays
// on the line of w.
TEST(Scene, TheModelIsTheSmallestExactOne) {
    solved_scene sc(rotating, centrifugal, "[w = [0, 0, W], g = [0, 0, -10], r0 = [0, 0, 1], v0 = [0, 0, 2]]");
    ASSERT_NE(sc.P, nullptr);
    test_session& t = sc.t;
    const mechanics::cauchy_problem& P = *sc.P;
    const mechanics::scene_model& M = sc.M;
    EXPECT_TRUE(M.algebra.axial);
    EXPECT_FALSE(M.algebra.planar);
    EXPECT_TRUE(M.planar_problem.empty());  // the complex problem is not solved
    EXPECT_FALSE(M.axial_problem.empty());
    const mechanics::rotation_operator_algebra R(M.form.Omega);
    const mechanics::operator_solution S = mechanics::solve(M.form.ode, R, P.t, M.factors());
    for (const auto& pc : S.terms) {
        EXPECT_TRUE(pc.c[1].is_zero()) << pc.vector;
        EXPECT_TRUE(pc.c[2].is_zero()) << pc.vector;
    }
    // the minimal coefficients do not solve the problem in the whole algebra of K:
    // they are exact only modulo m_P = X (the full check sees the difference)
    EXPECT_FALSE(mechanics::verify(M.form.ode, R, S));
    EXPECT_TRUE(mechanics::verify(M.form.ode, R, S, M.factors()));
    // one-dimensional: x(t) stays on the line of w
    EXPECT_TRUE(equal(cross(vector_literal(0, 0, 1), t.ex("s")), 0));
    EXPECT_TRUE(equal(t.ex("s"), vector_literal(0, 0, 1 + 2 * t.s.symbol("t") - 5 * GiNaC::pow(t.s.symbol("t"), 2))));
    // perpendicular data: only the planar problem, coefficients c0, c1
    const mechanics::scene_model Q =
        mechanics::classify(P, {{{t.s.symbol("w"), vector_literal(0, 0, t.s.symbol("W"))},
                                 {t.s.symbol("g"), vector_literal(1, 0, 0)},
                                 {t.s.symbol("r0"), vector_literal(0, 1, 0)},
                                 {t.s.symbol("v0"), vector_literal(0, 0, 0)}},
                                {}});
    EXPECT_FALSE(Q.algebra.axial);
    EXPECT_TRUE(Q.algebra.planar);
    EXPECT_TRUE(Q.axial_problem.empty());
    const mechanics::rotation_operator_algebra RQ(Q.form.Omega);
    for (const auto& pc : mechanics::solve(Q.form.ode, RQ, P.t, Q.factors()).terms) {
        EXPECT_FALSE(pc.c[1].is_zero()) << pc.vector;
        EXPECT_TRUE(pc.c[2].is_zero()) << pc.vector;
    }
}

// Terms that vanish for the values are dropped and reported; exact values go into
// the derivation, so a coincidence of the values (resonance) is solved exactly,
// where the general symbolic problem has no closed form (discriminant of unknown sign).
TEST(Scene, VanishingTermsAreDroppedAndExactValuesUsed) {
    test_session t;
    ASSERT_EQ(t.run("P := ode(y'' + c*y' + 4*y = cos(2*t), y(0) = 1, y'(0) = 0)\nvals := [c = 0]"), 0) << t.err.str();
    // s^2 + c s + 4: the sign of c^2 - 16 is unknown; the general solution is the
    // oscillating form, valid for either sign (issue 13, 4.1; it used to be refused)
    ASSERT_EQ(t.run("g := solve(P)"), 0) << t.err.str();
    EXPECT_TRUE(t.val("check(P, g)").as_bool());
    ASSERT_EQ(t.run("s := solve(P, vals)"), 0) << t.err.str();
    const ex tt = t.s.symbol("t");
    EXPECT_TRUE(is_zero_scalar(t.ex("s") - (GiNaC::cos(2 * tt) + tt * GiNaC::sin(2 * tt) / 4)));
    EXPECT_TRUE(t.val("check(P, s, vals)").as_bool());
    EXPECT_FALSE(t.val("check(P, s)").as_bool());  // not a solution for every c
    EXPECT_NE(t.out.str().find("solve: dropped: c y' (0 for the values)"), std::string::npos) << t.out.str();

    // Foucault with w0 = 0: the w0^2 r term is dropped, the roots are double
    test_session f;
    ASSERT_EQ(f.run(foucault_decl + "\nP := " + foucault + "\nm := model(P, [w0 = 0])"), 0) << f.err.str();
    const std::string rep = f.val("m").as_string();
    EXPECT_NE(rep.find("dropped: w0^2 r (0 for the values)"), std::string::npos) << rep;
    EXPECT_NE(rep.find("exact values in the derivation: w0 = 0"), std::string::npos) << rep;
    EXPECT_NE(rep.find("axial problem s^2 = 0"), std::string::npos) << rep;
    // floating-point values stay symbols until the end (an exact derivation cannot use them)
    ASSERT_EQ(f.run("m2 := model(P, [w0 = 0.38])"), 0) << f.err.str();
    EXPECT_NE(f.val("m2").as_string().find("floating-point values put in at the end: w0"), std::string::npos);
}

// A floating-point value that meets the problem exactly (w0 = 2.0 next to cos(2 t):
// resonance) makes the solution with it put in at the end singular; solve() then
// derives again with the float as the exact number it is, says so, and gives the
// resonant solution in floating point (it was "the values make ... singular").
TEST(Scene, FloatValuesThatMeetAreTakenExactly) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, a\nP := ode(r'' + w0^2*r = cos(2*t)*a, r(0) = r0, r'(0) = 0)\n"
                    "v := [w0 = 2.0, r0 = [1, 0, 0], a = [0, 1, 0]]\ns := solve(P, v)"),
              0)
        << t.err.str();
    EXPECT_NE(t.out.str().find("floating-point values taken exactly (put in at the end, they made the solution "
                               "singular): w0"),
              std::string::npos)
        << t.out.str();
    EXPECT_TRUE(t.val("check(P, s, v)").as_bool()) << t.out.str();
    // the secular term t sin(2 t)/4 of the resonance, in floats
    const double y = GiNaC::ex_to<GiNaC::numeric>(t.ex("eval(s, v, t = 3)[1]")).to_double();
    EXPECT_NEAR(y, 3 * std::sin(6.0) / 4, 1e-14);
    // a float that does not meet anything stays deferred
    ASSERT_EQ(t.run("s2 := solve(P, [w0 = 2.5, r0 = [1, 0, 0], a = [0, 1, 0]])"), 0) << t.err.str();
    EXPECT_NE(t.out.str().find("floating-point values put in at the end: w0"), std::string::npos);
}

// Classification is exact, never numeric: a floating-point residue of rounding
// counts as non-zero (the general model, still exact); a float product that is
// exactly 0 reduces the model.
TEST(Scene, ClassificationIsExact) {
    test_session t;
    ASSERT_EQ(t.run(rotating + "\nP := " + centrifugal), 0) << t.err.str();
    const mechanics::cauchy_problem& P = t.val("P").as_problem();
    const ex w = t.s.symbol("w"), g = t.s.symbol("g");
    auto exact_a = [](long k) { return GiNaC::ex(GiNaC::numeric(k, 10)); };
    auto float_a = [](long k) { return GiNaC::ex(GiNaC::numeric(k, 10).evalf()); };
    auto relation_of_g = [&](const ex& wv, const ex& gv) {
        const mechanics::scene_model M = mechanics::classify(P, {{{w, wv}, {g, gv}}, {}});
        return M.data.back().relation;
    };
    // exact rationals: g = 3 w
    EXPECT_EQ(relation_of_g(vector_literal(exact_a(1), exact_a(2), exact_a(3)),
                            vector_literal(exact_a(3), exact_a(6), exact_a(9))),
              A);
    // products with exact float zeros are exactly 0
    EXPECT_EQ(relation_of_g(vector_literal(0, 0, GiNaC::numeric(7.2921e-5)), vector_literal(0, 0, GiNaC::numeric(-9.81))),
              A);
    // 0.1, 0.2, 0.3 and 0.3, 0.6, 0.9 are not exact in binary: w x g is 0 only up to
    // rounding, and the model follows the floating-point values as given: along w
    // exactly when every component of the float product w x g is 0, general otherwise
    const ex wf = vector_literal(float_a(1), float_a(2), float_a(3)), gf = vector_literal(float_a(3), float_a(6), float_a(9));
    const ex wxg = subs_components(cross(wf, gf), {});
    const bool float_zero = wxg.op(0).is_zero() && wxg.op(1).is_zero() && wxg.op(2).is_zero();
    EXPECT_FALSE(float_zero);  // 0.2 * 0.9 - 0.3 * 0.6 != 0 in binary
    EXPECT_EQ(relation_of_g(wf, gf), float_zero ? A : G);
    // exact symbolic relation: g = k w with symbolic k and w
    EXPECT_EQ(relation_of_g(vector_literal(t.s.symbol("p"), t.s.symbol("q"), 1),
                            vector_literal(2 * t.s.symbol("p"), 2 * t.s.symbol("q"), 2)),
              A);
    // trigonometric values: w . g = W (cos(phi) sin(phi) - sin(phi) cos(phi)) = 0
    const ex phi = t.s.symbol("phi"), W = t.s.symbol("W");
    EXPECT_EQ(relation_of_g(W * vector_literal(GiNaC::cos(phi), 0, GiNaC::sin(phi)),
                            vector_literal(GiNaC::sin(phi), 0, -GiNaC::cos(phi))),
              Pp);
}

// The report is deterministic (same text in a fresh session) and states model and method.
TEST(Scene, ReportIsDeterministic) {
    const std::string script = rotating + "\nP := " + centrifugal +
                               "\nm := model(P, [w = [0, 0, W], g = [0, 0, -10], r0 = [1, 0, 0], v0 = [0, 0, 0]])";
    std::string first;
    for (int i = 0; i < 2; ++i) {
        test_session t;
        if (i == 1) t.run("vector zz, aa; positive b2");  // other symbols created first
        ASSERT_EQ(t.run(script), 0) << t.err.str();
        const std::string rep = t.val("m").as_string();
        if (i == 0) first = rep;
        else EXPECT_EQ(rep, first);
    }
    EXPECT_EQ(first,
              "model: R[X]/(X^3 + W^2 X), K = w x (the general model)\n"
              "  r(0) = r0: perpendicular to w (w . r0 = 0): R[X]/(X^2 + W^2), two-dimensional: in the plane "
              "perpendicular to w\n"
              "  r'(0) = v0: no term (v0 = 0)\n"
              "  F0 = g: along w (w x g = 0): R[X]/(X), one-dimensional: a multiple of g\n"
              "exact values in the derivation: |w| = W\n"
              "method: closed form; axial problem s^2 = 0; planar problem s^2 + 2*I*W*s - W^2 = 0\n"
              "why: constant coefficients and quasi-polynomial forcing: the closed form is exact (impulse "
              "responses of the scalar problems, convolution with the forcing; VI.1.26-38)\n");
}

// Bad input gets typed errors with clear messages.
TEST(Scene, BadInput) {
    test_session t;
    ASSERT_EQ(t.run(charge_decl + "\nP := " + charge_v + "\nQ := ode(v' = q/m*(v x B + E), v(0) = v0)"), 0)
        << t.err.str();
    auto fails_with = [&](const std::string& stmt, const std::string& msg) {
        t.err.str("");
        EXPECT_EQ(t.run(stmt), 1) << stmt;
        EXPECT_NE(t.err.str().find(msg), std::string::npos) << stmt << ": " << t.err.str();
    };
    fails_with("solve(P, [m = 0])", "the coefficient of v' is 0 for the values");
    fails_with("solve(Q, [m = 0])", "singular for the values");
    fails_with("solve(P, [v = 1])", "v is the unknown of the problem");
    fails_with("solve(P, [t = 1])", "t is the independent variable");
    fails_with("solve(P, 3)", "must list values as name = value");
    fails_with("solve(P, [B = 3])", "must be a vector");
    fails_with("model(3, [])", "must be a problem");
    fails_with("check(P, v0, [q = [1, 2, 3]])", "is a scalar");
    // without values, solve(P) is the general model as before
    EXPECT_EQ(t.run("s := solve(P)"), 0) << t.err.str();
    EXPECT_TRUE(t.val("check(P, s)").as_bool());
}
