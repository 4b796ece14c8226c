// tests/test_interpreter.cpp -- evaluation, values, element arithmetic, errors.
#include <gtest/gtest.h>

#include <fstream>

#include "output/printer.h"
#include "test_support.h"
#include "lang/print_value.h"

using namespace symrep;
using namespace symrep::lang;
using namespace symrep::output;
using symrep::test::same;
using symrep::test::test_session;
using GiNaC::ex;

TEST(Interpreter, ArithmeticAndPrecedence) {
    test_session t;
    EXPECT_TRUE(same(t.ex("1 + 2*3"), 7));
    EXPECT_TRUE(same(t.ex("2^3^2"), 512));
    EXPECT_TRUE(same(t.ex("-2^2"), -4));
    EXPECT_TRUE(same(t.ex("2^-1"), ex(1) / 2));
    EXPECT_TRUE(same(t.ex("(1 + 2)/6"), ex(1) / 2));
    EXPECT_TRUE(same(t.ex("10 - 2 - 3"), 5));
    GiNaC::ex x = t.s.symbol("x");
    EXPECT_TRUE(same(t.ex("(x + 1)^2 - x^2"), 2 * x + 1));
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(t.ex("0.25")));
    EXPECT_FALSE(GiNaC::ex_to<GiNaC::numeric>(t.ex("0.25")).is_rational());
    EXPECT_TRUE(GiNaC::ex_to<GiNaC::numeric>(t.ex("1/4")).is_rational());
}

TEST(Interpreter, SymbolsAreUniquePerName) {
    test_session t;
    ex a = t.ex("x"), b = t.ex("x");
    EXPECT_TRUE(a.is_equal(b));
    EXPECT_TRUE(same(t.ex("subs(x^2, x = 3)"), 9));  // builtins see the same symbol
    EXPECT_TRUE(same(t.ex("sum(seq(k, k, 1, 4))"), 10));
    EXPECT_TRUE(same(t.ex("x - x"), 0));
    EXPECT_TRUE(same(t.ex("pi"), GiNaC::Pi));
    EXPECT_TRUE(same(t.ex("I^2"), -1));
}

TEST(Interpreter, AssignmentListsIndexing) {
    test_session t;
    EXPECT_EQ(t.run("a := 3\nl := [a, a^2, [5, 6]]"), 0);
    EXPECT_TRUE(same(t.ex("l[1]"), 9));
    EXPECT_TRUE(same(t.ex("l[2][0]"), 5));
    EXPECT_TRUE(same(t.ex("length(l)"), 3));
    lang::value v = t.val("[1, 2] + [3, 4]");
    ASSERT_TRUE(v.is_list());
    EXPECT_TRUE(same(v.as_list()[1].as_ex(), 6));
    v = t.val("2*[1, x]");
    EXPECT_TRUE(same(v.as_list()[1].as_ex(), 2 * t.s.symbol("x")));
    EXPECT_EQ(t.out.str(), "");  // assignments are silent
    EXPECT_THROW(t.val("[1, 2] + 1"), script_error);
    EXPECT_THROW(t.val("[1, 2][2]"), script_error);
}

TEST(Interpreter, ComparisonsAreMathematical) {
    test_session t;
    EXPECT_TRUE(t.val("(x + 1)^2 == x^2 + 2*x + 1").as_bool());
    EXPECT_TRUE(t.val("(x^2 - 1)/(x - 1) == x + 1").as_bool());
    EXPECT_TRUE(t.val("x != y").as_bool());
    EXPECT_FALSE(t.val("[1, 2] == [1, 3]").as_bool());
    EXPECT_TRUE(t.val("2 < 3").as_bool());
    EXPECT_TRUE(t.val("pi > 3").as_bool());
    lang::value r = t.val("x = 1");
    ASSERT_TRUE(r.is_ex());
    EXPECT_TRUE(GiNaC::is_a<GiNaC::relational>(r.as_ex()));
}

TEST(Interpreter, CoreBuiltins) {
    test_session t;
    GiNaC::ex x = t.s.symbol("x");
    EXPECT_TRUE(same(t.ex("subs(x^2 + y, [x = 2, y = 1])"), 5));
    EXPECT_TRUE(same(t.ex("subs(x^2, x = 3)"), 9));
    EXPECT_TRUE(same(t.ex("diff(x^3, x)"), 3 * x * x));
    EXPECT_TRUE(same(t.ex("diff(x^3, x, 2)"), 6 * x));
    EXPECT_TRUE(same(t.ex("coeff((x + 2)^3, x, 1)"), 12));
    EXPECT_TRUE(same(t.ex("degree(x^3 + x, x)"), 3));
    EXPECT_TRUE(same(t.ex("det(matrix([[1, 2], [3, 4]]))"), -2));
    EXPECT_TRUE(same(t.ex("rank(matrix([[1, 2], [2, 4]]))"), 1));
    EXPECT_TRUE(same(t.ex("sum(seq(k, k, 1, 10))"), 55));
    EXPECT_TRUE(same(t.ex("sum(1/k, k, 1, 3)"), ex(11) / 6));
    EXPECT_TRUE(same(t.ex("numer((x + 1)/(x - 1))"), x + 1));
    EXPECT_TRUE(same(t.ex("exp(log(x))"), x));
    lang::value s = t.val("solve([x + y = 3, x - y = 1], [x, y])");
    ASSERT_TRUE(s.is_list());
    EXPECT_TRUE(same(s.as_list()[0].as_ex().op(1), 2));
    GiNaC::ex f = t.ex("evalf(pi, 30)");
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(f));
    EXPECT_EQ(print_ex(f), "3.14159265358979323846264338328");  // 30 significant digits, rounded (issue 13)
    EXPECT_EQ(t.val("type([1])").as_string(), "list");
    EXPECT_EQ(t.val("type(cplx())").as_string(), "algebra");
}

TEST(Interpreter, ElementArithmetic) {
    test_session t;
    t.run("C := cplx()\nu := element(C, [1, 2])\nv := element(C, [3, 4])");
    EXPECT_TRUE(t.val("u * v == element(C, [-5, 10])").as_bool());
    EXPECT_TRUE(t.val("u + v == element(C, [4, 6])").as_bool());
    EXPECT_TRUE(t.val("u - v == element(C, [-2, -2])").as_bool());
    EXPECT_TRUE(t.val("2*u == u*2").as_bool());
    EXPECT_TRUE(t.val("u/2 == element(C, [1/2, 1])").as_bool());
    EXPECT_TRUE(t.val("u + 1 == element(C, [2, 2])").as_bool());
    EXPECT_TRUE(t.val("u * inverse(u) == one(C)").as_bool());
    EXPECT_TRUE(t.val("u^-1 == inverse(u)").as_bool());
    EXPECT_TRUE(t.val("(u/v)*v == u").as_bool());
    EXPECT_TRUE(t.val("1/u == inverse(u)").as_bool());
    EXPECT_TRUE(t.val("basis(C, 1)^2 == -1").as_bool());
    EXPECT_TRUE(same(t.ex("u[1]"), 2));
    EXPECT_TRUE(same(t.ex("coords(u*v)[0]"), -5));
    EXPECT_TRUE(same(t.ex("dim(C)"), 2));
    EXPECT_TRUE(same(t.ex("det(u)"), 5));
    GiNaC::ex X = t.s.symbol("X");
    EXPECT_TRUE(same(t.ex("charpoly(u, X)"), X * X - 2 * X + 5));
    EXPECT_TRUE(same(t.ex("minpoly(u, X)"), X * X - 2 * X + 5));
    EXPECT_TRUE(t.val("evaluate(X^2 - 2*X + 5, X, u) == 0").as_bool());
    EXPECT_FALSE(t.val("is_zero_divisor(u)").as_bool());
    EXPECT_TRUE(t.val("subs(element(C, [a, b]), [a = 1, b = 2]) == u").as_bool());
    EXPECT_TRUE(same(t.ex("structure_constants(C)[1][1][0]"), -1));
    EXPECT_EQ(print_value(t.val("u * v")), "-5 + 10*j");
}

TEST(Interpreter, ElementErrors) {
    test_session t;
    t.run("C := cplx()\nD := dual_test()\nu := element(C, [1, 2])\nd := basis(D, 1)");
    try {
        t.val("u + d");
        FAIL();
    } catch (const script_error& e) {
        EXPECT_NE(std::string(e.what()).find("different algebras"), std::string::npos) << e.what();
        EXPECT_THROW(std::rethrow_exception(e.original), algebra_error);
    }
    try {
        t.val("inverse(d)");
        FAIL();
    } catch (const script_error& e) {
        EXPECT_THROW(std::rethrow_exception(e.original), zero_divisor_error);
    }
    try {
        t.val("[1] + u");
        FAIL();
    } catch (const script_error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot add a list and an element (operator '+')");
        EXPECT_EQ(e.where.column, 5);
    }
    EXPECT_THROW(t.val("u^x"), script_error);
    EXPECT_THROW(t.val("element(C, [1, 2, 3])"), script_error);
    EXPECT_THROW(t.val("idempotents(C)"), script_error);  // no idempotent basis in a general algebra
}

TEST(Interpreter, ErrorsCarryLocationAndRunContinues) {
    test_session t;
    const int failed = t.run("1 + 1\n2 + foo(3)\n3 + 3\n");
    EXPECT_EQ(failed, 1);
    EXPECT_EQ(t.out.str(), "2\n6\n");
    EXPECT_EQ(t.err.str().rfind("t.sr:2:5: error: unknown function 'foo'", 0), 0u) << t.err.str();
}

TEST(Interpreter, GinacExceptionsAreCaught) {
    test_session t;
    EXPECT_EQ(t.run("a := 1\nb := a/0\nc := 2\nc"), 1);
    EXPECT_EQ(t.out.str(), "2\n");
    EXPECT_EQ(t.err.str().rfind("t.sr:2:7: error: division by zero", 0), 0u) << t.err.str();
    test_session u;
    EXPECT_EQ(u.run("log(0)\ntan(pi/2)\nx := 1"), 2);  // GiNaC pole errors
    EXPECT_NE(u.err.str().find("t.sr:1:1: error:"), std::string::npos) << u.err.str();
    EXPECT_NE(u.err.str().find("t.sr:2:1: error:"), std::string::npos) << u.err.str();
    EXPECT_TRUE(u.s.get("x") != nullptr);
}

TEST(Interpreter, SyntaxErrorsResynchronize) {
    test_session t;
    EXPECT_EQ(t.run("1 +\n2 $ 3\n[1,\n 2)\n4; 5 )\n7"), 4);
    EXPECT_EQ(t.out.str(), "4\n7\n");
    const std::string e = t.err.str();
    EXPECT_NE(e.find("t.sr:1:4: error: syntax error:"), std::string::npos) << e;
    EXPECT_NE(e.find("t.sr:2:3: error: syntax error: unexpected character '$'"), std::string::npos) << e;
    EXPECT_NE(e.find("t.sr:4:3: error: syntax error:"), std::string::npos) << e;
    EXPECT_NE(e.find("t.sr:5:6: error: syntax error:"), std::string::npos) << e;
}

TEST(Interpreter, WrongArgumentCountShowsUsage) {
    test_session t;
    try {
        t.val("diff(x)");
        FAIL();
    } catch (const script_error& e) {
        EXPECT_EQ(std::string(e.what()), "diff: expects 2 to 3 arguments, got 1 (usage: diff(e, x [, n]))");
        EXPECT_THROW(std::rethrow_exception(e.original), type_error);
    }
    try {
        t.val("expnd(x)");
        FAIL();
    } catch (const script_error& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean expand"), std::string::npos) << e.what();
    }
}

TEST(Interpreter, PrintAndEcho) {
    test_session t;
    EXPECT_EQ(t.run("print(\"a\", 1/2, [\"b\"])\n\"q\"\nx := 2\nx^2\ntrue"), 0);
    EXPECT_EQ(t.out.str(), "a 1/2 [\"b\"]\n\"q\"\n4\ntrue\n");
}

TEST(Interpreter, LoadRunsInTheSameSession) {
    const std::string dir = ::testing::TempDir();
    {
        std::ofstream f(dir + "/symrep_load_inner.sr");
        f << "inner := 41\nbad(1 2)\n";
    }
    {
        std::ofstream f(dir + "/symrep_load_outer.sr");
        f << "load(\"symrep_load_inner.sr\")\ninner + 1\n";
    }
    test_session t;
    EXPECT_EQ(t.s.run_file(dir + "/symrep_load_outer.sr"), 1);  // the syntax error inside
    EXPECT_EQ(t.out.str(), "42\n");
    EXPECT_NE(t.err.str().find("symrep_load_inner.sr:2:7: error: syntax error"), std::string::npos) << t.err.str();
    EXPECT_GE(t.run("load(\"/nonexistent/file.sr\")"), 1);
}

TEST(Interpreter, LongAndDeepInputsDoNotCrash) {
    test_session t;
    std::string longsum = "1";
    for (int i = 0; i < 20000; ++i) longsum += "+x";
    EXPECT_TRUE(same(t.ex(longsum), 20000 * t.s.symbol("x") + 1));
    std::string deep(5000, '(');
    deep += "1" + std::string(5000, ')');
    EXPECT_EQ(t.run(deep), 1);
    EXPECT_NE(t.err.str().find("nested too deeply"), std::string::npos) << t.err.str();
    EXPECT_EQ(t.run("2^(10^9)"), 1);
    EXPECT_NE(t.err.str().find("more than 10^7 bits"), std::string::npos) << t.err.str();
}

TEST(Interpreter, ChainOperatorLocations) {
    test_session t;
    EXPECT_EQ(t.run("u := element(cplx(), [1, 2])\n1 + 2 + [3] * 4 - u"), 1);
    // [3]*4 is fine (a list times a scalar); 1 + 2 + [12] fails at the second '+'
    EXPECT_EQ(t.err.str().rfind("t.sr:2:7: error: cannot add an expression and a list", 0), 0u) << t.err.str();
}

TEST(Interpreter, SeqAndSumEvaluateTheBodyPerValue) {
    test_session t;
    const ex x = t.s.symbol("x");
    // diff(x^3, x, k) needs k as a number when it is evaluated
    lang::value v = t.val("seq(diff(x^3, x, k), k, 0, 2)");
    ASSERT_TRUE(v.is_list());
    ASSERT_EQ(v.as_list().size(), 3u);
    EXPECT_TRUE(same(v.as_list()[2].as_ex(), 6 * x));
    EXPECT_TRUE(same(t.ex("sum(diff(x^4, x, k), k, 1, 2)"), 4 * pow(x, 3) + 12 * pow(x, 2)));
    EXPECT_TRUE(same(t.ex("sum(k^2, k, [1, 2, 3])"), 14));
    // a variable of the same name is restored, an unassigned one stays a symbol
    t.run("k := 7");
    t.val("seq(k, k, 0, 1)");
    EXPECT_TRUE(same(t.ex("k"), 7));
    t.run("j := 0");
    EXPECT_TRUE(same(t.ex("seq(m, m, 1, 1)[0] + m"), 1 + t.s.symbol("m")));
    EXPECT_THROW(t.val("seq(k, k, 3)"), script_error);  // 3 is not a list
}

TEST(Interpreter, PolynomialAlgebraFromScriptSymbols) {
    // the variable of a script-made P_n is the session's realsymbol X
    test_session t;
    t.run("A := polynomial_algebra(X^3 - 2*X + 1, X)\nv := element(A, [0, 1, 0])");
    const ex Y = t.s.symbol("Y");
    EXPECT_TRUE(same(t.ex("minpoly(v, Y)"), pow(Y, 3) - 2 * Y + 1));
    const ex tt = t.s.symbol("t");
    const ex e0 = t.ex("exp(v, t)[0]");
    EXPECT_FALSE(e0.is_zero());
    // e^(v t) solves y''' - 2 y' + y = 0 coordinatewise, with e^(0) = 1
    EXPECT_TRUE(same(e0.diff(GiNaC::ex_to<GiNaC::symbol>(tt), 3) - 2 * e0.diff(GiNaC::ex_to<GiNaC::symbol>(tt)) + e0, 0));
    EXPECT_TRUE(same(e0.subs(tt == 0), 1));
}

TEST(Interpreter, ExpectNearComparesListsMatricesAndElements) {
    test_session t;
    EXPECT_NO_THROW(t.val("expect_near([1, [2, I]], [1.0000001, [2, I + 1e-9]], 1e-6)"));
    EXPECT_NO_THROW(t.val("expect_near(matrix([[1, 2]]), matrix([[1, 2.0001]]), 1e-3)"));
    t.run("A := multicomplex(1)");
    EXPECT_NO_THROW(t.val("expect_near(element(A, [1, 2, 0, 0]), element(A, [1, 2.0000001, 0, 0]), 1e-3)"));
    EXPECT_THROW(t.val("expect_near([1, 2], [1, 3], 0.5)"), script_error);   // entry 1 differs
    EXPECT_THROW(t.val("expect_near([1], [1, 2], 1)"), script_error);        // shapes differ
    EXPECT_THROW(t.val("expect_near(x, 1, 1)"), script_error);               // not a number
    EXPECT_THROW(t.val("expect_near(I, 0, 0.5)"), script_error);             // |I - 0| = 1
}
