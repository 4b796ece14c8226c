// tests/test_two_body.cpp -- the two-body problem in a rotating frame beyond the decoupling
// (thesis VI.3.4.2.4-5, mechanics/two_body.h), the vector first integrals and generalized
// potentials (VI.2.99-115, VI.3.141, 221-230; mechanics/first_integrals.h), the decisions of
// Consequence VI.3.3.2 and VI.3.282-284 (mechanics/orbit_decisions.h) and the properties of the
// rotation operator at a variable rate (Thm VI.2.1.1, VI.3.1.1).
//
// Exact side: every statement is proved inside the engine; the tests re-prove the constants
// independently (derivative along the equation by the test's own acceleration). Numeric side:
// the coupled two-body system integrated by Boost.Odeint (rkf78 at 1e-13 over 10 time units;
// measured drift of the integrals ~1e-12), the quantities evaluated at the numeric states with
// the engine's exact expressions; tolerance 1e-9 relative (three orders above the drift; a wrong
// sign or a missing term gives O(1e-2) or more).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "mechanics/scene.h"
#include "numeric/integrate.h"
#include "numeric/reference.h"
#include "test_support.h"
#include "vector/vector.h"

using symrep::test::test_session;

namespace {

double number_of(const GiNaC::ex& e) {
    const GiNaC::ex v = GiNaC::evalf(e);
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
        ADD_FAILURE() << "not a real number: " << e;
        return NAN;
    }
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

GiNaC::ex literal(const Eigen::Vector3d& x) {
    using GiNaC::numeric;
    return symrep::vector_literal(symrep::num::exact_floats_of(numeric(x.x())), symrep::num::exact_floats_of(numeric(x.y())),
                                  symrep::num::exact_floats_of(numeric(x.z())));
}

double size_of(const GiNaC::ex& e) {
    if (!symrep::is_vector_literal(e)) return std::abs(number_of(e));
    double s = 0;
    for (unsigned i = 0; i < 3; ++i) s += std::pow(number_of(e.op(i)), 2);
    return std::sqrt(s);
}

}  // namespace

// The global characteristics along the coupled motion (fixed direction w = (1/2 + sin t) e3, so that
// H(t) and L0(t) are closed): T + V, E_cin + V(t, x1, x2), E_cin^c + V(t, r) constant; H, L0, L_c
// equal to their closed F_(-w)(X0) at every time; H^c = 0.
TEST(TwoBody, CharacteristicsAlongTheCoupledMotion) {
    test_session t;
    ASSERT_EQ(t.run("vector R0, V0, r0, u0\nw := (1/2 + sin(t))*[0, 0, 1]\n"
                    "CM := ode(R'' + 2*w x R' + w' x R + w x (w x R) = 0, R(0) = R0, R'(0) = V0)\n"
                    "REL := ode(r'' + 2*w x r' + w' x r + w x (w x r) + G*(m1 + m2)*r/|r|^3 = 0, r(0) = r0, r'(0) = u0)\n"
                    "C := two_body(CM, REL, m1, m2)"),
              0)
        << t.err.str();
    const auto& C = t.val("C").as_list();
    ASSERT_EQ(C.size(), 19u);  // 13 in the frame (V(t, x1, x2) for the fixed direction), 6 in the centre-of-mass frame
    auto item = [&](const std::string& start) {
        for (const auto& q : C)
            if (q.as_list()[0].as_string().rfind(start, 0) == 0) return q.as_list()[1].as_ex();
        ADD_FAILURE() << "no item " << start;
        return GiNaC::ex(0);
    };
    const double m1 = 1, m2 = 0.5, M = m1 + m2, G = 1;
    const Eigen::Vector3d x10(1, 0, 0.1), x20(-0.5, 0.2, 0), v10(0, 0.2, 0.05), v20(0.1, -0.2, 0);
    auto w = [](double s) { return Eigen::Vector3d(0, 0, 0.5 + std::sin(s)); };
    auto wd = [](double s) { return Eigen::Vector3d(0, 0, std::cos(s)); };
    const symrep::num::rhs_function rhs = [&](double s, const double* y, double* dy) {
        const Eigen::Vector3d x1(y[0], y[1], y[2]), x2(y[3], y[4], y[5]), v1(y[6], y[7], y[8]), v2(y[9], y[10], y[11]);
        const Eigen::Vector3d W = w(s), Wd = wd(s), x = x1 - x2;
        const Eigen::Vector3d F = G * m1 * m2 * x / std::pow(x.norm(), 3);
        auto frame = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& v) {
            return Eigen::Vector3d(-2 * W.cross(v) - Wd.cross(p) - W.cross(W.cross(p)));
        };
        const Eigen::Vector3d a1 = frame(x1, v1) - F / m1, a2 = frame(x2, v2) + F / m2;
        for (int i = 0; i < 3; ++i) dy[i] = v1[i], dy[3 + i] = v2[i], dy[6 + i] = a1[i], dy[9 + i] = a2[i];
    };
    std::vector<double> y0;
    for (const Eigen::Vector3d* v : {&x10, &x20, &v10, &v20}) y0.insert(y0.end(), v->data(), v->data() + 3);
    const std::vector<double> times{0, 2.5, 5, 10};
    symrep::num::integration_options o;
    o.abs_tol = o.rel_tol = 1e-13;
    const auto ref = symrep::num::integrate(rhs, 0.0, y0, times, o);
    symrep::mechanics::parameter_values d;
    d.scalars[t.ex("m1")] = 1, d.scalars[t.ex("m2")] = GiNaC::numeric(1, 2), d.scalars[t.ex("G")] = 1;
    d.vectors[t.ex("R0")] = literal((m1 * x10 + m2 * x20) / M), d.vectors[t.ex("V0")] = literal((m1 * v10 + m2 * v20) / M);
    d.vectors[t.ex("r0")] = literal(x20 - x10), d.vectors[t.ex("u0")] = literal(v20 - v10);
    std::map<std::string, double> first;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const Eigen::VectorXd y = ref.states.row(Eigen::Index(k));
        symrep::mechanics::parameter_values e = d;
        e.vectors[t.ex("x1")] = literal(y.segment<3>(0)), e.vectors[t.ex("x2")] = literal(y.segment<3>(3));
        e.vectors[t.ex("v1")] = literal(y.segment<3>(6)), e.vectors[t.ex("v2")] = literal(y.segment<3>(9));
        auto at = [&](const GiNaC::ex& x) {
            const GiNaC::ex v = symrep::mechanics::put_values(x, e).subs(t.ex("t") == times[k]);
            return GiNaC::evalf(symrep::subs_components(v, {}));
        };
        // T + V (VI.3.252), E_cin + V(t, x1, x2) (265), T^c + V (285), E_cin^c + V(t, r) (289-290)
        const GiNaC::ex Ecc = t.ex("((v2 - v1) . (v2 - v1))/6");  // m |r'|^2/2, m = 1/3
        const std::vector<std::pair<std::string, GiNaC::ex>> constants{
            {"T + V", item("E_cin + V_c + V")},
            {"E_cin + V(t, x1, x2)", item("E_cin =") + item("V(t, x1, x2)")},
            {"T^c + V", item("T^c") + item("V = m U")},
            {"E_cin^c + V(t, r)", Ecc + item("V(t, r) =")},
            {"E_cin^c + V(t, r, r')", Ecc + item("V(t, r, r')")}};
        for (const auto& [c, q] : constants) {
            const double v = number_of(at(q));
            if (k == 0) first[c] = v;
            EXPECT_NEAR(v, first[c], 1e-9 * std::abs(first[c])) << c << " at t = " << times[k];
        }
        for (const auto& [now, closed] : {std::pair<const char*, const char*>{"H =", "H(t)"}, {"L0 =", "L0(t)"},
                                          {"L_c =", "L_c(t)"}}) {
            const GiNaC::ex a = at(item(now)), b = at(item(closed));
            double gap = 0;
            for (unsigned i = 0; i < 3; ++i) gap += std::pow(number_of(a.op(i)) - number_of(b.op(i)), 2);
            EXPECT_LT(std::sqrt(gap), 1e-9 * size_of(b)) << now << " at t = " << times[k];
        }
        EXPECT_LT(size_of(at(item("H^c"))), 1e-12) << times[k];
    }
}

// The vector first integral and the generalized potentials proved again here, by the test's own
// acceleration, for a fixed direction at the rate 1 + cos t (closed F_(-w)) and for a turning w.
TEST(FirstIntegrals, VectorIntegralAndPotentialsHaveZeroDerivativeAlongTheEquation) {
    using namespace symrep;
    for (const char* w : {"(1 + cos(t))*u", "[a1*sin(c1*t), a2*cos(c2*t), a3]"}) {
        test_session t;
        ASSERT_EQ(t.run(std::string("vector u, r0, v0\nw := ") + w +
                        "\nP := ode(m*(r'' + 2*w x r' + w' x r + w x (w x r)) + m*k*r/|r|^3 = 0, r(0) = r0, r'(0) = v0)\n"
                        "I := vector_first_integrals(P)\nV := generalized_potentials(P)"),
                  0)
            << t.err.str();
        const auto& P = t.val("P").as_problem();
        const GiNaC::ex W = P.turning->terms.w, k = t.ex("k"), m = t.ex("m");
        const GiNaC::ex &r = P.unknowns[0], &r1 = P.unknowns[1], &r2 = P.unknowns[2];
        const GiNaC::ex acc =
            -(2 * cross(W, r1) + cross(diff_t(W, P.t), r) + cross(W, cross(W, r)) + k * r / pow(norm(r), 3));
        const auto& I = t.val("I").as_list();
        ASSERT_EQ(I.size(), 1u) << w;
        const GiNaC::ex X = I[0].as_list()[1].as_ex();
        EXPECT_TRUE(equal(subs_vectors(diff_t(X, P.t), {{r2, acc}}) + cross(W, X), 0)) << w;
        const bool fixed = std::string(w).find('u') != std::string::npos;
        EXPECT_EQ(I[0].as_list()[2].is_ex(), fixed) << w;  // closed F_(-w)(Omega0) only for the fixed direction
        const auto& V = t.val("V").as_list();
        ASSERT_EQ(V.size(), fixed ? 2u : 1u) << w;
        const GiNaC::ex E = m * dot(r1, r1) / 2 + V[0].as_list()[1].as_ex();
        EXPECT_TRUE(equal(subs_vectors(diff_t(E, P.t), {{r2, acc}}), 0)) << w;
    }
    // a constant w: the centrifugal potential (VI.2.115) is there, and a free term is refused by name
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nw := [0, 0, W]\nP := ode(r'' + 2*w x r' + w x (w x r) + k*r = 0, r(0) = r0, r'(0) = v0)\n"
                    "V := generalized_potentials(P)\nG := ode(r'' + 2*w x r' + w x (w x r) = [0, 0, -1], r(0) = r0, r'(0) = v0)"),
              0)
        << t.err.str();
    EXPECT_EQ(t.val("V").as_list().size(), 3u);
    EXPECT_NE(t.run("generalized_potentials(G)"), 0);
    EXPECT_NE(t.err.str().find("does work"), std::string::npos) << t.err.str();
}

// Consequence VI.3.3.2 and the planarity criterion decided, and "cannot decide" where the sign or
// the zero is not established (never a guess).
TEST(OrbitDecisions, BoundedAndPlanarDecideOrSaySo) {
    test_session t;
    ASSERT_EQ(t.run("vector r0, v0\nw := (1 + cos(t))*[0, 0, 1]\n"
                    "K := ode(r'' + 2*w x r' + w' x r + w x (w x r) + k*r/|r|^3 = 0, r(0) = r0, r'(0) = v0)\n"
                    "b1 := bounded(K, [k = 1, r0 = [1, 0, 0], v0 = [0, 0.5, 0]])\n"
                    "b2 := bounded(K, [k = 1, r0 = [1, 0, 0], v0 = [0, -1, 1]])\n"
                    "p1 := planar(K, [r0 = [a, b, 0], v0 = [c, d, 0]])\n"
                    "p2 := planar(K, [r0 = [1, 0, 0], v0 = [0, 1, 1/20]])"),
              0)
        << t.err.str();
    // E = |v0 + w0 x r0|^2/2 - 1 = (2.5)^2/2 - 1 > 0 for v0 = [0, 0.5, 0] (w(0) = 2 e3): unbounded
    EXPECT_FALSE(t.val("b1").as_bool());
    // v0 = [0, -1, 1]: p0 = [0, 1, 1], E = 1 - 1 = 0: a parabola, unbounded
    EXPECT_FALSE(t.val("b2").as_bool());
    ASSERT_EQ(t.run("b3 := bounded(K, [k = 1, r0 = [1, 0, 0], v0 = [0, -1.5, 0]])"), 0) << t.err.str();
    EXPECT_TRUE(t.val("b3").as_bool());  // p0 = [0, 0.5, 0], E = 1/8 - 1 < 0
    EXPECT_TRUE(t.val("p1").as_bool());
    EXPECT_FALSE(t.val("p2").as_bool());
    for (const char* undecided : {"bounded(K, [r0 = [1, 0, 0], v0 = [0, -1.5, 0]])", "bounded(K, [k = 1])",
                                  "planar(K, [r0 = [1, 0, 0], v0 = [0, 1, z]])"}) {
        t.err.str("");
        EXPECT_NE(t.run(undecided), 0) << undecided;
        EXPECT_NE(t.err.str().find("cannot decide"), std::string::npos) << undecided << ": " << t.err.str();
    }
    t.err.str("");
    ASSERT_EQ(t.run("Wt := [sin(t), cos(2*t), 1]\nT := ode(r'' + 2*Wt x r' + Wt' x r + Wt x (Wt x r) + k*r/|r|^3 = 0, "
                    "r(0) = r0, r'(0) = v0)"),
              0);
    EXPECT_NE(t.run("planar(T, [r0 = [1, 0, 0], v0 = [0, 1, 0]])"), 0);
    EXPECT_NE(t.err.str().find("fixed direction"), std::string::npos) << t.err.str();
}

// Thm VI.2.1.1 (5: isometry, 7: the inverse, and the cross product) for w = (1 + cos t) u, decided by ==
// (the angle |u| (t + sin t) taken as a variable of the zero test); F*_w = F_w for a fixed direction.
TEST(RotationOperator, PropertiesDecidedAtAVariableRate) {
    test_session t;
    ASSERT_EQ(t.run("vector u, x, y\nw := (1 + cos(t))*u\n"
                    "expect(norm(F(w, x))^2 == norm(x)^2)\nexpect(F(-w, F(w, x)) == x)\n"
                    "expect(F(w, x x y) == F(w, x) x F(w, y))\nexpect(F_adjoint(w, x) == F(w, x))\n"),
              0)
        << t.err.str();
}

// Thm VI.3.1.1 for F*_w = Q^T with a regular precession p(t): Q (Q^T x) = x (6; proved inside and here),
// |Q^T x| = |x| (4), Q^T (x x y) = Q^T x x Q^T y (7), and 2: d/dt F*_w(q) = F*_w(q' + w x q) for a
// vector function q(t).
TEST(RotationOperator, AdjointOfAPrecessionHasThePropertiesOfThmVI311) {
    test_session t;
    ASSERT_EQ(t.run("vector x, y\np := [sin(t), cos(t), 1]\nA := F_adjoint(p, x)\nexpect(A . A == x . x)\n"
                    "expect(F_adjoint(p, x x y) == A x F_adjoint(p, y))\nexpect(F(-p, A) == x)\n"
                    "vector q(t)\nexpect(diff(F_adjoint(p, q), t) == F_adjoint(p, q' + p x q))\n"
                    // 3: the second derivative rule; 5: the initial value
                    "expect(diff(F_adjoint(p, q), t, 2) == F_adjoint(p, q'' + 2*p x q' + p x (p x q) + p' x q))\n"
                    "expect(subs(F_adjoint(p, x), t = 0) == x)"),
              0)
        << t.err.str();
}

// The same properties for a fixed direction at a variable rate with a literal axis,
// w = (1 + cos t) [0, 0, 1]: the angle -(t + sin t) and t + sin t are one variable of the
// zero test (cos(-t - sin t) cos(t + sin t) - sin(-t - sin t) sin(t + sin t) = 1 is proved).
TEST(RotationOperator, AdjointOfAFixedDirectionAtAVariableRate) {
    test_session t;
    ASSERT_EQ(t.run("vector x, y, q(t)\nw := (1 + cos(t))*[0, 0, 1]\nA := F_adjoint(w, x)\n"
                    "expect(A . A == x . x)\nexpect(F(-w, A) == x)\nexpect(subs(A, t = 0) == x)\n"
                    "expect(F_adjoint(w, x x y) == A x F_adjoint(w, y))\n"
                    "expect(diff(F_adjoint(w, q), t) == F_adjoint(w, q' + w x q))\n"
                    "expect(diff(F_adjoint(w, q), t, 2) == F_adjoint(w, q'' + 2*w x q' + w x (w x q) + w' x q))\n"
                    "expect(cos(-t - sin(t))*cos(t + sin(t)) - sin(-t - sin(t))*sin(t + sin(t)) == 1)"),
              0)
        << t.err.str();
}
