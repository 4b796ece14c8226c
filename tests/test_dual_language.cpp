// Dual numbers in the language (issue 31 item 1): the constant eps, the reduction
// modulo eps^2 in every operation, dual/primal/dual_part, printing p + eps*d, the
// zero-divisor error with its place, and the transference principle checked on
// the identities the engine already proves (rules/vector.rules, tests/test_vector.cpp).
#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <string>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/lang/print_value.h"
#include "symrep/output/formats.h"
#include "symrep/output/printer.h"
#include "symrep/rules/rules.h"
#include "symrep/vector/vector.h"
#include "test_support.h"

using namespace symrep;
using GiNaC::ex;
using symrep::test::test_session;

namespace {

/// The printed value of one expression of the language.
std::string text(test_session& t, const std::string& e) { return lang::print_value(t.val(e), false); }
bool yes(test_session& t, const std::string& e) {
    const lang::value v = t.val(e);
    EXPECT_TRUE(v.is_bool()) << e;
    return v.is_bool() && v.as_bool();
}

}  // namespace

TEST(DualLanguage, EpsIsTheDualUnit) {
    test_session t;
    EXPECT_TRUE(dual::has_dual_unit(t.ex("eps")));
    EXPECT_TRUE(t.ex("eps*eps").is_zero());
    EXPECT_TRUE(t.ex("eps^2").is_zero());
    EXPECT_TRUE(t.ex("(x + eps*y)^3 - x^3 - 3*eps*x^2*y").is_zero() ||
                yes(t, "(x + eps*y)^3 == x^3 + 3*eps*x^2*y"));
    EXPECT_EQ(text(t, "(1 + eps)^2"), "1 + 2*eps");
    EXPECT_EQ(text(t, "(1 + eps)*(1 - eps)"), "1");
    EXPECT_EQ(text(t, "x + eps*y"), "x + eps*y");
    EXPECT_EQ(text(t, "x - eps*y"), "x - eps*y");
    EXPECT_EQ(text(t, "eps*y + eps*z + x"), "x + eps*(y + z)");
    EXPECT_EQ(text(t, "eps*(2*y)"), "2*eps*y");
    EXPECT_EQ(text(t, "-eps"), "-eps");
    EXPECT_EQ(text(t, "eps/2 + 1"), "1 + eps/2");
    // sums of three terms and products fold the same way (the chain of + and * is reduced too)
    EXPECT_TRUE(t.ex("eps*x*eps*y + 1 + eps*eps").is_equal(1));
    EXPECT_TRUE(yes(t, "eps != 0"));
    EXPECT_TRUE(yes(t, "eps^2 == 0"));
}

TEST(DualLanguage, FunctionsExtendByTheirDerivative) {
    test_session t;
    EXPECT_TRUE(yes(t, "sin(a + eps*b) == sin(a) + eps*b*cos(a)"));
    EXPECT_TRUE(yes(t, "exp(a + eps*b) == exp(a)*(1 + eps*b)"));
    EXPECT_TRUE(yes(t, "log(a + eps*b) == log(a) + eps*b/a"));
    EXPECT_TRUE(yes(t, "sqrt(a + eps*b) == sqrt(a) + eps*b/(2*sqrt(a))"));
    EXPECT_TRUE(yes(t, "atan(a + eps*b) == atan(a) + eps*b/(1 + a^2)"));
    EXPECT_TRUE(yes(t, "(a + eps*b)/(c + eps*d) == a/c + eps*(b*c - a*d)/c^2"));
    EXPECT_FALSE(yes(t, "sin(a + eps*b) == sin(a) - eps*b*cos(a)"));
    EXPECT_TRUE(t.ex("dual_part(cos(a + eps*b)) + b*sin(a)").is_zero());
    EXPECT_TRUE(t.ex("primal(cos(a + eps*b)) - cos(a)").is_zero());
    // a dual angle: cos and sin of the screw's a + eps*d, the dual extension in the language
    EXPECT_TRUE(yes(t, "cos(u + eps*d)^2 + sin(u + eps*d)^2 == 1"));
    // subs, expand, simplify, diff keep the value reduced
    EXPECT_TRUE(yes(t, "subs(x + eps*y^2, y = 1 + eps) == x + eps"));
    EXPECT_EQ(text(t, "expand((x + eps*y)^2)"), "x^2 + 2*eps*x*y");
    EXPECT_TRUE(yes(t, "diff(sin(x + eps*x^2), x) == cos(x) + eps*(2*x*cos(x) - x^2*sin(x))"));
}

TEST(DualLanguage, BuiltinsAndShadowing) {
    test_session t;
    EXPECT_TRUE(yes(t, "dual(x, y) == x + eps*y"));
    EXPECT_TRUE(t.ex("primal(dual(x, y)) - x").is_zero());
    EXPECT_TRUE(t.ex("dual_part(dual(x, y)) - y").is_zero());
    EXPECT_TRUE(t.ex("dual_part(x^2)").is_zero());
    EXPECT_THROW(t.val("dual(eps, 1)"), std::exception);
    // eps is a constant like pi: an assignment shadows it, and the Sobrero element eps keeps working
    EXPECT_EQ(t.run("eps := 1/10\nexpect(eps^2 == 1/100)\nS := sobrero(2)\neps := sobrero_eps(S)\n"
                    "expect(eps^3 == 0*one(S))\nexpect(eps^2 != 0*one(S))"),
              0)
        << t.err.str();
    test_session u;
    EXPECT_EQ(u.run("positive eps"), 1);
    EXPECT_NE(u.err.str().find("dual unit"), std::string::npos) << u.err.str();
}

TEST(DualLanguage, ZeroDivisorIsAnErrorWithItsPlace) {
    test_session t;
    EXPECT_EQ(t.run("x := 1/eps"), 1);
    EXPECT_NE(t.err.str().find("t.sr:1:7:"), std::string::npos) << t.err.str();
    EXPECT_NE(t.err.str().find("zero divisor"), std::string::npos) << t.err.str();
    test_session u;
    EXPECT_EQ(u.run("y := 2\nz := (1 + eps)/(eps*y)"), 1);
    EXPECT_NE(u.err.str().find("t.sr:2:15:"), std::string::npos) << u.err.str();
    test_session w;
    EXPECT_EQ(w.run("log(eps*x)"), 1);
    EXPECT_NE(w.err.str().find("zero divisor"), std::string::npos) << w.err.str();
    test_session o;
    EXPECT_EQ(o.run("1 + eps < 2"), 1);
    EXPECT_NE(o.err.str().find("not ordered"), std::string::npos) << o.err.str();
    // an invertible primal part divides
    EXPECT_TRUE(yes(t, "1/(2 + eps) == 1/2 - eps/4"));
}

TEST(DualLanguage, PrintedValueReadsBackAndLatex) {
    test_session t;
    t.run("vector a, b, c, d");
    for (const std::string e : {"x + eps*y", "sin(x + eps*y)", "(x + eps*y)/(1 + x + eps)", "a + eps*b",
                                "(a + eps*b) x (c + eps*d)", "(a + eps*b) . (c + eps*d)", "|a + eps*b|",
                                "[1, eps, 0] + eps*a", "-eps*a"}) {
        const lang::value v = t.val(e);
        const std::string s = lang::print_value(v, false);
        const lang::value back = t.val(s);
        EXPECT_EQ(lang::print_value(back, false), s) << e;
        EXPECT_TRUE(lang::values_equal(back, v)) << e << " printed " << s;
    }
    EXPECT_EQ(text(t, "a + eps*b"), "a + eps*b");
    EXPECT_EQ(text(t, "(a + eps*b) x c"), "a x c + eps*(b x c)");
    EXPECT_EQ(output::latex_ex(t.ex("x + eps*(y + z)")), "x + \\varepsilon \\left(y + z\\right)");
    EXPECT_EQ(output::latex_ex(t.ex("x - eps*y")), "x - \\varepsilon y");
}

TEST(DualLanguage, DualVectorProducts) {
    test_session t;
    t.run("vector a, b, c, d");
    EXPECT_TRUE(yes(t, "(a + eps*b) x (c + eps*d) == a x c + eps*(a x d + b x c)"));
    EXPECT_TRUE(yes(t, "(a + eps*b) . (c + eps*d) == a . c + eps*(a . d + b . c)"));
    EXPECT_TRUE(yes(t, "|a + eps*b| == |a| + eps*(a . b)/|a|"));
    EXPECT_TRUE(yes(t, "dual(a, b) x dual(a, b) == 0"));
    EXPECT_FALSE(yes(t, "(a + eps*b) x (c + eps*d) == a x c + eps*(a x d - b x c)"));
    // the line through p with direction x is x + eps*(p x x): its moment does not depend on the point chosen
    EXPECT_TRUE(yes(t, "dual(c, (a + 3*c) x c) == dual(c, a x c)"));
    // literals by components, also written as lists with dual entries
    EXPECT_TRUE(t.ex("[eps, 1, 0] . [eps, 0, 0]").is_zero());
    EXPECT_TRUE(yes(t, "[1, eps, 0] x [0, 1, 0] == [0, 0, 1]"));
    EXPECT_TRUE(yes(t, "[1, 0, 0] + eps*[0, 1, 0] == dual([1, 0, 0], [0, 1, 0])"));
    EXPECT_TRUE(yes(t, "([1, 0, 0] + eps*[0, 1, 0]) x ([0, 1, 0] + eps*[0, 0, 1]) == [0, 0, 1] + eps*[0, -1, 0]"));
    EXPECT_EQ(text(t, "dual([1, 0, 0], [0, 1, 0])"), "[1, eps, 0]");
}

// The transference principle: every identity of real vectors built from +, x, .,
// the triple product, scalar factors and the norm holds for dual vectors (each
// variable v replaced by v + eps v', scalars s by s + eps s'). Checked on every rule
// of rules/vector.rules (each side built with dual values) and on the identities of
// tests/test_vector.cpp; a perturbed identity must still fail (the check can fail).
TEST(DualLanguage, TransferencePrincipleOnTheEnginesIdentities) {
    const auto start = std::chrono::steady_clock::now();
    const rules::rule_set& R = rules::default_rules();
    ASSERT_GE(R.rules().size(), 8u);
    std::map<std::string, ex> duals;  // one dual value per variable name
    auto dual_of = [&](const std::string& name, bool vec) {
        const std::string key = name + (vec ? "#v" : "#s");
        if (auto it = duals.find(key); it != duals.end()) return it->second;
        GiNaC::realsymbol p(name + "_p"), d(name + "_d");
        if (vec) {
            register_vector(p);
            register_vector(d);
        }
        return duals[key] = dual::make_dual(p, d);
    };
    std::function<void(const rules::pattern&, rules::bindings&)> bind = [&](const rules::pattern& p,
                                                                             rules::bindings& b) {
        if (p.kind == rules::pattern::var) b[p.name] = dual_of(p.name, p.type == rules::var_type::vector);
        for (const auto& k : p.kids) bind(k, b);
    };
    int checked = 0;
    for (const rules::rule& r : R.rules()) {
        rules::bindings b;
        bind(r.lhs, b);
        bind(r.rhs, b);
        const ex l = dual::reduce(rules::instantiate(r.lhs, b)), h = dual::reduce(rules::instantiate(r.rhs, b));
        EXPECT_TRUE(dual::has_dual_unit(l) || l.is_zero()) << r.name;
        EXPECT_TRUE(dual::dual_equal(l, h)) << r.name << ": " << r.text;
        ++checked;
    }
    const ex a = dual_of("a", true), b = dual_of("b", true), c = dual_of("c", true), d = dual_of("d", true);
    const ex w = dual_of("w", true), r0 = dual_of("r0", true), s = dual_of("s", false);
    using dual::dual_cross;
    using dual::dual_dot;
    auto X = [](const ex& u, const ex& v) { return cross(u, v); };  // on dual vectors, reduced below
    auto D = [](const ex& u, const ex& v) { return dot(u, v); };
    const std::vector<std::pair<std::string, ex>> ids = {
        {"Jacobi", X(a, X(b, c)) + X(b, X(c, a)) + X(c, X(a, b))},
        {"BAC-CAB", X(a, X(b, c)) - (D(a, c) * b - D(a, b) * c)},
        {"BAC-CAB left", X(X(a, b), c) - (D(a, c) * b - D(b, c) * a)},
        {"Lagrange", D(X(a, b), X(c, d)) - (D(a, c) * D(b, d) - D(a, d) * D(b, c))},
        {"|a x b|^2", D(X(a, b), X(a, b)) - (D(a, a) * D(b, b) - GiNaC::pow(D(a, b), 2))},
        {"cyclic", D(a, X(b, c)) - D(b, X(c, a))},
        {"cyclic2", D(X(a, b), c) - triple(c, a, b)},
        {"antisym", triple(a, b, c) + D(b, X(a, c))},
        {"cross of crosses", X(X(a, b), X(c, d)) - (triple(a, b, d) * c - triple(a, b, c) * d)},
        {"w x (w x w x r)", X(w, X(w, X(w, r0))) + D(w, w) * X(w, r0)},
        {"four vectors", triple(a, b, c) * d - (D(a, d) * X(b, c) + D(b, d) * X(c, a) + D(c, d) * X(a, b))},
        {"linearity", X(a, 2 * b + s * c) - (2 * X(a, b) + s * X(a, c))},
        {"norm", norm(a) * norm(a) - D(a, a)},
    };
    for (const auto& [name, e] : ids) {
        const ex z = dual::reduce(e);
        EXPECT_TRUE(dual::dual_equal(z, 0)) << name;
        // the products of dual/dual.h give the same reduced values
        ++checked;
    }
    EXPECT_TRUE(dual::dual_equal(dual::reduce(X(a, X(b, c))), dual::reduce(dual_cross(a, dual_cross(b, c)))));
    EXPECT_TRUE(dual::dual_equal(dual::reduce(D(a, X(b, c))), dual_dot(a, dual_cross(b, c))));
    // perturbed: the dual parts must catch an error the primal parts do not have
    const ex wrong_dual = X(a, X(b, c)) - (D(a, c) * b - D(a, b) * c) + dual::dual_unit() * X(b, c);
    EXPECT_FALSE(dual::dual_equal(dual::reduce(wrong_dual), 0));
    EXPECT_FALSE(dual::dual_equal(dual::reduce(X(a, X(b, c)) - (D(a, b) * c - D(a, c) * b)), 0));
    EXPECT_GE(checked, 20);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);  // a budget, not a benchmark: CI runs every test on 2 cores
}
