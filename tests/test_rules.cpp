// tests/test_rules.cpp -- rewrite rules (engine/rules, rules/vector.rules):
// every shipped rule applies and keeps the value, nested rewriting to a fixed
// point, the step bound, typed variables, argument orders chosen by GiNaC,
// malformed rule files, and the builtins load_rules / rewrite / rules.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "core/error.h"
#include "rules/rules.h"
#include "test_support.h"
#include "vector/vector.h"

using GiNaC::ex;
using namespace symrep;
using symrep::test::test_session;

namespace {

struct Rules : ::testing::Test {
    ex a = vector_symbol("a"), b = vector_symbol("b"), c = vector_symbol("c"), d = vector_symbol("d");
    ex p = vector_symbol("p"), q = vector_symbol("q"), r = vector_symbol("r"), u = vector_symbol("u");
    GiNaC::realsymbol s{"s"}, t{"t"};
    const rules::rule_set& shipped = rules::default_rules();

    const rules::rule& named(const std::string& name) const {
        for (const auto& x : shipped.rules())
            if (x.name == name) return x;
        ADD_FAILURE() << "no shipped rule named " << name;
        return shipped.rules().front();
    }
};

bool has_fn(const ex& e, const char* name) {
    if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == name) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
        if (has_fn(e.op(i), name)) return true;
    return false;
}

// The message of the syntax_error parse_rules throws, "" if none.
std::string load_error(const std::string& text, const std::string& file = "t.rules") {
    try {
        (void)rules::parse_rules(text, file);
    } catch (const syntax_error& e) {
        return e.where.file + ":" + std::to_string(e.where.line) + ":" + std::to_string(e.where.column) + ": " +
               e.what();
    }
    return "";
}

// A folder of this test process, removed at exit.
struct temp_dir {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("symrep_rules_test_" + std::to_string(::getpid()));
    ~temp_dir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

std::string temp_file(const std::string& name, const std::string& text) {
    static temp_dir td;
    const auto& dir = td.path;
    std::filesystem::create_directories(dir);
    const auto path = dir / name;
    std::ofstream(path) << text;
    return path.string();
}

}  // namespace

// Each shipped rule, at the top of an expression it is written for, fires and
// keeps the value; afterwards the identity's left-side shape is gone.
TEST_F(Rules, EveryShippedRuleAppliesAndKeepsTheValue) {
    const ex dd = vector_symbol("e"), ff = vector_symbol("f");
    struct example {
        const char* rule;
        ex e;
    };
    const ex abc = triple(a, b, c);
    const std::vector<example> examples = {
        {"(a x b) x (c x d)", cross(cross(a, b), cross(c, d))},
        {"Binet-Cauchy", dot(cross(a, b), cross(c, d))},
        {"BAC-CAB", cross(a, cross(b, c))},
        {"triple with a cross product (cyclicity)", triple(a, b, cross(c, d))},
        {"scalar triple product", dot(a, cross(cross(b, c), d))},
        {"Gram determinant", abc * triple(d, dd, ff)},
        {"Gram determinant, squared triple", GiNaC::pow(abc, 2)},
    };
    ASSERT_GE(shipped.rules().size(), 9u);
    for (const auto& x : examples) {
        const rules::rule& rl = named(x.rule);
        auto m = rules::match_partial(rl.lhs, x.e);
        ASSERT_TRUE(m) << x.rule << " does not match " << to_string(x.e);
        const auto res = shipped.rewrite(x.e, 1);
        EXPECT_EQ(res.steps, 1u) << x.rule;
        EXPECT_FALSE(res.result.is_equal(x.e)) << x.rule;
        EXPECT_TRUE(symrep::equal(res.result, x.e)) << x.rule << ": " << to_string(res.result);
    }
    // the two repeat rules, on expressions GiNaC has not evaluated (held)
    const ex pp = vcross(p, p).hold();
    ASSERT_TRUE(rules::match(named("a x a = 0").lhs, pp));
    EXPECT_FALSE(rules::match(named("a x a = 0").lhs, vcross(p, q).hold()));
    EXPECT_TRUE(shipped.rewrite(pp).result.is_zero());
    auto m = rules::match(named("a . (a x b) = 0").lhs, dot(cross(a, b), cross(cross(a, b), c)));
    EXPECT_FALSE(m) << "GiNaC already evaluates this to 0; the test expression is not a dot";
    const auto z = rules::match(named("a . (a x b) = 0").lhs, vdot(p, cross(p, q)).hold());
    ASSERT_TRUE(z);
    EXPECT_TRUE(z->first.at("a").is_equal(p));
    EXPECT_TRUE(z->first.at("b").is_equal(q));
}

// GiNaC puts cross(b, a) as -cross(a, b) and dot(b x c, a) as dot(a, b x c):
// the matcher tries the swapped argument order, with the sign for x.
TEST_F(Rules, SwappedArgumentsMatchWithTheirSign) {
    const rules::rule& bac = named("BAC-CAB");
    // (p x q) x r is held as -(r x (p x q)) or cross(p x q, r): either way it rewrites
    const ex e = cross(cross(p, q), r);
    const auto res = shipped.rewrite(e);
    EXPECT_TRUE(symrep::equal(res.result, e));
    EXPECT_FALSE(has_fn(res.result, "cross")) << to_string(res.result);
    // direct: pattern a x (b x c) against cross(b x c, a): sign -1
    const ex held = vcross(cross(p, q), r).hold();
    auto m = rules::match(bac.lhs, held);
    ASSERT_TRUE(m);
    EXPECT_TRUE(m->second.is_equal(-1));
    EXPECT_TRUE(m->first.at("a").is_equal(r));
    // triple(a, b, c x d) found in every argument position
    for (const ex& x : {triple(cross(p, q), r, u), triple(r, cross(p, q), u), triple(r, u, cross(p, q))}) {
        const auto t1 = shipped.rewrite(x);
        EXPECT_FALSE(has_fn(t1.result, "triple")) << to_string(x) << " -> " << to_string(t1.result);
        EXPECT_TRUE(symrep::equal(t1.result, x)) << to_string(x);
    }
}

// a x (b x (c x (d x e))) and deeper mixtures are reduced to dots times vectors.
TEST_F(Rules, NestedCrossesReachTheFixedPoint) {
    const ex e5 = vector_symbol("e");
    const ex e = cross(a, cross(b, cross(c, cross(d, e5))));
    const auto res = shipped.rewrite(e);
    EXPECT_FALSE(res.bound_hit);
    EXPECT_EQ(res.steps, 3u);  // c x (d x e); then linearity leaves two a x (b x .)
    EXPECT_FALSE(has_fn(res.result, "cross")) << to_string(res.result);
    EXPECT_TRUE(symrep::equal(res.result, e));
    // a fixed point: rewriting again does nothing
    EXPECT_EQ(shipped.rewrite(res.result).steps, 0u);
    // scalar: |(a x b) x (c x d)|^2 and (a x (b x c)) . (d x (a x b))
    const ex f = dot(cross(a, cross(b, c)), cross(d, cross(a, b))) + s * dot(cross(cross(a, b), cross(c, d)), a);
    const auto rf = shipped.rewrite(f);
    EXPECT_FALSE(has_fn(rf.result, "cross")) << to_string(rf.result);
    EXPECT_TRUE(symrep::equal(rf.result, f));
}

// A rule and its inverse loop; the bound stops them and says so.
TEST_F(Rules, StepBoundStopsALoop) {
    rules::rule_set set;
    set.add(rules::parse_rules("vector a, b, c\n"
                               "a . (b x c) -> triple(a, b, c)   # to triple\n"
                               "triple(a, b, c) -> a . (b x c)   # back\n",
                               "loop.rules"));
    const auto res = set.rewrite(triple(p, q, r), 50);
    EXPECT_TRUE(res.bound_hit);
    EXPECT_EQ(res.steps, 50u);
    ASSERT_NE(res.last, nullptr);
    EXPECT_TRUE(symrep::equal(res.result, triple(p, q, r)));
    // through the language: an error with the bound and the rule
    test_session ts;
    const std::string file = temp_file("loop.rules", "vector a, b, c\na . (b x c) -> triple(a, b, c)  # to triple\n"
                                                    "triple(a, b, c) -> a . (b x c)  # back\n");
    EXPECT_EQ(ts.s.run_string("load_rules(\"" + file + "\")\nvector p, q, r\nrewrite(triple(p, q, r), 20)", "<t>"), 1);
    EXPECT_NE(ts.err.str().find("no fixed point after 20 rewrites"), std::string::npos) << ts.err.str();
    EXPECT_NE(ts.err.str().find("<t>:3:1: error: rewrite"), std::string::npos) << ts.err.str();
}

// A scalar variable does not match a vector, a vector variable not a scalar;
// the types pick the right factors in a product.
TEST_F(Rules, VariablesAreTyped) {
    const auto sv = rules::parse_rules("scalar s; vector a\ns*a -> a*s  # scaled", "typed.rules");
    const auto ss = rules::parse_rules("scalar s, t\ns*t -> t*s  # two scalars", "typed.rules");
    ASSERT_EQ(sv.size(), 1u);
    ASSERT_EQ(ss.size(), 1u);
    const ex pq = dot(p, q);
    auto m = rules::match(sv[0].lhs, pq * r);
    ASSERT_TRUE(m);
    EXPECT_TRUE(m->first.at("s").is_equal(pq));
    EXPECT_TRUE(m->first.at("a").is_equal(r));
    EXPECT_FALSE(rules::match(ss[0].lhs, pq * r)) << "a scalar variable matched the vector r";
    EXPECT_TRUE(rules::match(ss[0].lhs, pq * s));
    const auto vv = rules::parse_rules("vector a, b\na x b -> -(b x a)", "typed.rules");
    EXPECT_FALSE(rules::match(vv[0].lhs, vcross(p, ex(0)).hold())) << "a vector variable matched 0";
    EXPECT_FALSE(rules::match(vv[0].lhs, pq));
    // an ill-typed side is a load error
    EXPECT_NE(load_error("scalar s; vector b\ns x b -> 0").find("t.rules:2:1: rule at t.rules:2 is ill-typed"),
              std::string::npos)
        << load_error("scalar s; vector b\ns x b -> 0");
}

TEST_F(Rules, MalformedFilesNameFileAndLine) {
    // syntax error in a side: the column is the file's column
    EXPECT_EQ(load_error("vector a, b\n\na x (b x) -> 0"), "t.rules:3:8: expected ')' to close '(', found name 'x'");
    // no arrow
    EXPECT_EQ(load_error("vector a\n  a x a"),
              "t.rules:2:3: expected a rule 'left -> right' or a declaration 'vector a, b' / 'scalar s', found 'a x a'");
    // undeclared variable, unbound right-side variable
    EXPECT_EQ(load_error("vector a\na x q -> 0").rfind("t.rules:2:5: 'q' is not a pattern variable", 0), 0u)
        << load_error("vector a\na x q -> 0");
    EXPECT_EQ(load_error("vector a, b, c\na x b -> c x b"),
              "t.rules:2:10: the right side uses 'c', which the left side does not bind");
    // a false rule
    const std::string f = load_error("vector a, b, c\n# comment\na x (b x c) -> c*(a . b) - b*(a . c)  # wrong sign");
    EXPECT_EQ(f.rfind("t.rules:3:1: rule at t.rules:3 does not hold: ", 0), 0u) << f;
    // bad declaration, unknown function, lone variable
    EXPECT_EQ(load_error("vector a, 2b").rfind("t.rules:1:11: expected a variable name", 0), 0u)
        << load_error("vector a, 2b");
    EXPECT_EQ(load_error("vector a\nsin(a . a) -> 0").rfind("t.rules:2:1: unknown function 'sin'", 0), 0u);
    EXPECT_EQ(load_error("vector a\na -> a").rfind("t.rules:2:1: the left side of a rule must not be", 0), 0u);
    // a rule after ';' on the same line
    EXPECT_EQ(load_error("vector a, b; a x b -> b x a").rfind("t.rules:1:14: rule at t.rules:1 does not hold", 0),
              0u)
        << load_error("vector a, b; a x b -> b x a");
    // through the language: reported at the call with the file's place; nothing added
    test_session ts;
    const std::string bad = temp_file("bad.rules", "vector a, b\na x b -> b x a   # wrong\n");
    const long before = long(ts.s.rewrite_rules().rules().size());
    EXPECT_EQ(ts.s.run_string("load_rules(\"" + bad + "\")", "<t>"), 1);
    EXPECT_NE(ts.err.str().find(bad + ":2:1: rule at " + bad + ":2 does not hold"), std::string::npos)
        << ts.err.str();
    EXPECT_EQ(long(ts.s.rewrite_rules().rules().size()), before);
    EXPECT_EQ(ts.s.run_string("load_rules(\"/nonexistent/none.rules\")", "<t>"), 1);
    EXPECT_NE(ts.err.str().find("cannot open rule file"), std::string::npos);
}

// load_rules from a script (path relative to the script), rewrite, rules().
TEST_F(Rules, LoadRulesFromAScript) {
    const std::string rules_file =
        temp_file("mine.rules", "vector a, b\n(a x b) . (a x b) -> (a . a)*(b . b) - (a . b)^2   # Lagrange\n");
    const std::string script = temp_file(
        "script.symrep",
        "vector p, q\nn := load_rules(\"mine.rules\")\nm := load_rules(\"mine.rules\")\n"
        "x := rewrite((p x q) . (p x q))\nk := rules()\n");
    test_session ts;
    EXPECT_EQ(ts.s.run_file(script), 0) << ts.err.str();
    EXPECT_EQ(ts.s.get("n")->as_ex(), ex(1));
    EXPECT_EQ(ts.s.get("m")->as_ex(), ex(0)) << "a file already loaded is loaded again";
    const ex x = ts.s.get("x")->as_ex();
    const ex pp = ts.s.symbol("p"), qq = ts.s.symbol("q");
    EXPECT_TRUE((x - (dot(pp, pp) * dot(qq, qq) - GiNaC::pow(dot(pp, qq), 2))).expand().is_zero())
        << to_string(x);
    const long k = long(GiNaC::ex_to<GiNaC::numeric>(ts.s.get("k")->as_ex()).to_int());
    EXPECT_EQ(std::size_t(k), rules::default_rules().rules().size() + 1);
    EXPECT_NE(ts.out.str().find("BAC-CAB: a x (b x c) -> b*(a . c) - c*(a . b)  (vector.rules:"), std::string::npos)
        << ts.out.str();
    EXPECT_NE(ts.out.str().find("Lagrange: (a x b) . (a x b)"), std::string::npos);
    // the shipped rules in a session of their own: the thesis's w x (w x r)
    test_session t2;
    ASSERT_EQ(t2.s.run_string("vector w, r", "<t>"), 0);
    const ex y = t2.ex("rewrite(w x (w x r) + w x (w x (w x r)))");
    EXPECT_TRUE(symrep::equal(y, t2.ex("(w . r)*w - (w . w)*r - (w . w)*(w x r)")));
    EXPECT_EQ(t2.ex("rewrite(w x (w x r))") - t2.ex("(w . r)*w - (w . w)*r"), ex(0));
}

// SYMREP_RULES_DIR replaces the shipped folder.
TEST_F(Rules, RulesDirFromTheEnvironment) {
    const std::string f = temp_file("vector.rules", "vector a, b\na . (a x b) -> 0   # only rule\n");
    const std::string dir = std::filesystem::path(f).parent_path().string();
    ::setenv("SYMREP_RULES_DIR", dir.c_str(), 1);
    EXPECT_EQ(rules::default_rules_dir(), dir);
    const auto& set = rules::default_rules();
    ::unsetenv("SYMREP_RULES_DIR");
    ASSERT_EQ(set.rules().size(), 1u);
    EXPECT_EQ(set.rules()[0].name, "only rule");
    EXPECT_NE(rules::default_rules_dir(), dir);
}
