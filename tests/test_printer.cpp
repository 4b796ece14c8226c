// tests/test_printer.cpp -- the canonical printer: exact texts and determinism.
#include <gtest/gtest.h>

#include "output/printer.h"
#include "test_support.h"
#include "lang/print_value.h"

using namespace symrep;
using namespace symrep::lang;
using symrep::test::test_session;

namespace {
std::string show(test_session& t, const std::string& text) { return print_value(t.val(text)); }
}  // namespace

TEST(Printer, Numbers) {
    test_session t;
    EXPECT_EQ(show(t, "3/4"), "3/4");
    EXPECT_EQ(show(t, "-6/4"), "-3/2");
    EXPECT_EQ(show(t, "2 + 3*I"), "2 + 3*I");
    EXPECT_EQ(show(t, "2 - I"), "2 - I");
    EXPECT_EQ(show(t, "-I/2"), "-I/2");
    EXPECT_EQ(show(t, "1 + 3*I/2"), "1 + 3*I/2");
    EXPECT_EQ(show(t, "2*I*x - I*y/3"), "2*I*x - I*y/3");
    EXPECT_EQ(show(t, "0.5"), "0.5");
    EXPECT_EQ(show(t, "pi"), "pi");
}

TEST(Printer, SumsAreOrderedByDegreeThenLexicographically) {
    test_session t;
    EXPECT_EQ(show(t, "expand((x + 1)^2)"), "x^2 + 2*x + 1");
    EXPECT_EQ(show(t, "expand((y + x)^3)"), "x^3 + 3*x^2*y + 3*x*y^2 + y^3");
    EXPECT_EQ(show(t, "expand((x - 1)^3)"), "x^3 - 3*x^2 + 3*x - 1");
    EXPECT_EQ(show(t, "1 - x"), "-x + 1");
    EXPECT_EQ(show(t, "sin(x) + x^2 + 1"), "x^2 + sin(x) + 1");
    EXPECT_EQ(show(t, "series(exp(x), x = 0, 3)"), "x^2/2 + x + 1 + Order(x^3)");
}

TEST(Printer, ProductsPowersQuotients) {
    test_session t;
    EXPECT_EQ(show(t, "y*x*3"), "3*x*y");
    EXPECT_EQ(show(t, "-x/2"), "-x/2");
    EXPECT_EQ(show(t, "3*x/(2*y)"), "3*x/(2*y)");
    EXPECT_EQ(show(t, "1/y^2"), "1/y^2");
    EXPECT_EQ(show(t, "(x + 1)^2"), "(x + 1)^2");
    EXPECT_EQ(show(t, "(-2)^x"), "(-2)^x");
    EXPECT_EQ(show(t, "x^(2/3)"), "x^(2/3)");
    EXPECT_EQ(show(t, "sqrt(2)/2"), "sqrt(2)/2");
    EXPECT_EQ(show(t, "(x - 1)*(x + 1)"), "(x + 1)*(x - 1)");  // factors sorted by text
    EXPECT_EQ(show(t, "(1 + 2*I)*x"), "(1 + 2*I)*x");
}

TEST(Printer, RelationsMatricesListsStringsBooleans) {
    test_session t;
    EXPECT_EQ(show(t, "x = y + 1"), "x = y + 1");
    EXPECT_EQ(show(t, "matrix([[1, 2], [3, x]])"), "matrix([[1, 2], [3, x]])");
    EXPECT_EQ(show(t, "[1, \"a\\\"b\", [true, false]]"), "[1, \"a\\\"b\", [true, false]]");
    EXPECT_EQ(print_value(t.val("\"raw\""), false), "raw");
    EXPECT_EQ(show(t, "cplx()"), "cplx_test");
    EXPECT_EQ(print_value(value()), "");
}

TEST(Printer, Elements) {
    test_session t;
    EXPECT_EQ(show(t, "element(cplx(), [2, 3])"), "2 + 3*j");
    EXPECT_EQ(show(t, "element(cplx(), [0, -1])"), "-j");
    EXPECT_EQ(show(t, "element(cplx(), [a + b, -2*c])"), "a + b - 2*c*j");
    EXPECT_EQ(show(t, "element(cplx(), [-1, x - y])"), "-1 + (x - y)*j");
    EXPECT_EQ(show(t, "element(cplx(), [0, 0])"), "0");
    EXPECT_EQ(show(t, "element(cplx(), [1, -a - 2*b])"), "1 - (a + 2*b)*j");
}

// The same expressions built with the symbols created in opposite orders, in two
// sessions: GiNaC's internal term order differs, the printed text must not.
TEST(Printer, DeterministicAcrossSymbolCreationOrder) {
    const char* exprs[] = {"expand((a + b + c)^3 - 2*a*c)", "expand((c - a)^2*(b + 1))", "c/a + b/c + a/b",
                           "[c*b*a, (c + a)^2, sin(c + b) - cos(a)]"};
    for (const char* e : exprs) {
        test_session t1, t2;
        t1.val("a; b; c");
        t2.val("c; b; a");
        // extra symbols and allocations to shift hashes further
        t2.val("zz := expand((q + r + s)^5)");
        EXPECT_EQ(show(t1, e), show(t2, e)) << e;
    }
    test_session t3;
    EXPECT_EQ(show(t3, "expand((a + b + c)^2)"), "a^2 + 2*a*b + 2*a*c + b^2 + 2*b*c + c^2");
}

// GiNaC keeps (x2 - x1)*t or -(x1 - x2)*t depending on the order it built the
// terms in; both must print alike, with every sum factor's leading term positive.
TEST(Printer, SignOfSumFactorsIsCanonical) {
    using GiNaC::ex;
    const GiNaC::realsymbol x1("x1"), x2("x2"), t("t"), y("y");
    const ex a = x2 - x1, b = x1 - x2;
    const ex held1 = GiNaC::dynallocate<GiNaC::mul>(a, t).setflag(GiNaC::status_flags::evaluated);
    const ex held2 = -(b * t);  // mul(x1 - x2, t) with coefficient -1
    EXPECT_EQ(symrep::output::print_ex(held1), symrep::output::print_ex(held2));
    EXPECT_EQ(symrep::output::print_ex(held1), "-(x1 - x2)*t");
    const ex p1 = GiNaC::dynallocate<GiNaC::power>(a, 3).setflag(GiNaC::status_flags::evaluated);
    EXPECT_EQ(symrep::output::print_ex(p1), "-(x1 - x2)^3");
    const ex p2 = GiNaC::dynallocate<GiNaC::power>(a, 2).setflag(GiNaC::status_flags::evaluated);
    EXPECT_EQ(symrep::output::print_ex(p2), "(x1 - x2)^2");
    EXPECT_EQ(symrep::output::print_ex(ex(1) / a * y), "-y/(x1 - x2)");
}
