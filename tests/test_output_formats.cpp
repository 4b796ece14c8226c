// tests/test_output_formats.cpp -- output formats and script-mode options as
// transcripts (script in, text out): latex(), --format latex, ccode() compiled
// with the system C++ compiler, pycode() run by python3, --format json, digits /
// Digits, --echo, --stop-on-error, the caret under errors, load().
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.h"

namespace {

using symrep::test::cli_result;
using symrep::test::run_symrep;
using symrep::test::slurp;

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + "/symrep_of_" + std::to_string(getpid()) + "_" + name;
}

/// Runs `script` (written to a file) with the options `opts`.
cli_result run_script(const std::string& script, const std::string& opts = "", const std::string& name = "s.sr") {
    const std::string path = temp_path(name);
    std::ofstream(path, std::ios::binary) << script;
    return run_symrep(opts + " '" + path + "'");
}

/// The standard output of -e 'code' (which must succeed).
std::string out_of(const std::string& code, const std::string& opts = "") {
    const std::string path = temp_path("e.sr");
    std::ofstream(path, std::ios::binary) << code;
    cli_result r = run_symrep(opts + " '" + path + "'");
    EXPECT_EQ(r.status, 0) << code << "\n" << r.err;
    return r.out;
}

}  // namespace

// --- LaTeX -------------------------------------------------------------------

TEST(OutputLatex, ScalarExpressions) {
    EXPECT_EQ(out_of("print(latex(x^2/2 + sqrt(y) - 3*a*b/c))"), "\\frac{x^{2}}{2} - \\frac{3 a b}{c} + \\sqrt{y}\n");
    EXPECT_EQ(out_of("print(latex(sin(alpha)^2 + x1))"), "x_1 + \\sin\\left(\\alpha\\right)^{2}\n");
    EXPECT_EQ(out_of("print(latex(-1/3))"), "-\\frac{1}{3}\n");
    // a sum alone above or below the bar needs no parentheses; next to another factor it does
    EXPECT_EQ(out_of("print(latex((a + b)/(c - d)))"), "\\frac{a + b}{c - d}\n");
    EXPECT_EQ(out_of("print(latex(1/(x + 1)))"), "\\frac{1}{x + 1}\n");
    EXPECT_EQ(out_of("print(latex((a + b)/(2*(c - d))))"), "\\frac{a + b}{2 \\left(c - d\\right)}\n");
    EXPECT_EQ(out_of("print(latex(3*(a + b)/(c - d)))"), "\\frac{3 \\left(a + b\\right)}{c - d}\n");
    EXPECT_EQ(out_of("print(latex((a + b)^2/(c - d)^3))"),
              "\\frac{\\left(a + b\\right)^{2}}{\\left(c - d\\right)^{3}}\n");
    EXPECT_EQ(out_of("print(latex(matrix([[1, x], [0, y^3]])))"),
              "\\begin{pmatrix} 1 & x \\\\ 0 & y^{3} \\end{pmatrix}\n");
}

TEST(OutputLatex, VectorsInThesisNotation) {
    EXPECT_EQ(out_of("vector w, r0; print(latex(w x r0))"), "-\\boldsymbol{r}_0 \\times \\boldsymbol{w}\n");
    EXPECT_EQ(out_of("vector w, r0; print(latex(norm(w)*(w . r0) + 2))"),
              "\\left(\\boldsymbol{r}_0 \\cdot \\boldsymbol{w}\\right) \\|\\boldsymbol{w}\\| + 2\n");
    EXPECT_EQ(out_of("vector w; print(latex(w . w))"), "\\|\\boldsymbol{w}\\|^{2}\n");
}

TEST(OutputLatex, ElementsAreSumsOfCoefficientTimesBasis) {
    EXPECT_EQ(out_of("S := sobrero(1); print(latex(element(S, [1, 2, -x, 4])))"),
              "1 + 2 \\varepsilon - x j + 4 j \\varepsilon\n");
    EXPECT_EQ(out_of("A := multicomplex(2); print(latex(element(A, [0, 0, 0, 0, 0, 0, 0, -x - y])))"),
              "-\\left(x + y\\right) i_0 i_1 i_2\n");
}

TEST(OutputLatex, SumsFollowTheCanonicalOrderWhateverTheSymbolOrder) {
    // GiNaC orders terms by creation order of the symbols; the output must not.
    const std::string a = out_of("u := b + a + c; print(latex(c*a + b^2 + a^2 - 1))");
    const std::string b = out_of("u := c + a + b; print(latex(b^2 - 1 + a^2 + c*a))");
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, "a^{2} + a c + b^{2} - 1\n");
    EXPECT_EQ(out_of("c*a + b^2 + a^2 - 1"), "a^2 + a*c + b^2 - 1\n");  // the same order as the text printer
}

// floats in scientific form typeset as m \cdot 10^{e}, every digit kept (issue 32 item 3);
// ordinary magnitudes and integers unchanged, inside products, lists, matrices, powers too
TEST(OutputLatex, FloatsInScientificFormAsPowersOfTen) {
    EXPECT_EQ(out_of("print(latex(1.7670602574040041e-5)); print(latex(-2.5e-12)); print(latex(6.02e23)); "
                     "print(latex(0.5)); print(latex(123456.0)); print(latex(42)); print(latex(3.0e-5*x)); "
                     "print(latex(-3.0e-5*x + y)); print(latex([1.5e-7, 2])); print(latex(matrix([[1e-9, 0], [0, 1]]))); "
                     "print(latex(x^(2.5e-6))); print(latex((2.5e-6)^x)); print(latex(1e-5 + 2e-5*I))"),
              "1.7670602574040041 \\cdot 10^{-5}\n"
              "-2.5 \\cdot 10^{-12}\n"
              "6.02 \\cdot 10^{23}\n"
              "0.5\n"
              "123456.0\n"
              "42\n"
              "3.0 \\cdot 10^{-5} x\n"
              "-3.0 \\cdot 10^{-5} x + y\n"
              "\\left[1.5 \\cdot 10^{-7}, 2\\right]\n"
              "\\begin{pmatrix} 1.0 \\cdot 10^{-9} & 0 \\\\ 0 & 1 \\end{pmatrix}\n"
              "x^{2.5 \\cdot 10^{-6}}\n"
              "\\left(2.5 \\cdot 10^{-6}\\right)^{x}\n"
              "1.0 \\cdot 10^{-5} + 2.0 \\cdot 10^{-5} i\n");
    // the text printer keeps its E form
    EXPECT_EQ(out_of("2.5e-12"), "2.5E-12\n");
}

TEST(OutputLatex, FormatLatexPrintsEveryResultInLatex) {
    cli_result r = run_symrep("--format latex -e 'x^2/2; [1/2, y]; \"a_b\"'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "\\frac{x^{2}}{2}\n\\left[\\frac{1}{2}, y\\right]\n\\text{a\\_b}\n");
}

// --- C code -----------------------------------------------------------------

namespace {

bool have_compiler() { return std::system("c++ --version >/dev/null 2>&1") == 0; }

/// Compiles `double f(double x, double y) { return CODE; }` with a main that
/// prints f(x, y), runs it and returns the number printed.
double run_c(const std::string& code, double x, double y) {
    const std::string src = temp_path("f.cpp"), exe = temp_path("f.out"), out = temp_path("f.txt");
    std::ofstream(src) << "#include <math.h>\n#include <stdio.h>\n"
                       << "static double f(double x, double y) { (void)x; (void)y; return " << code << "; }\n"
                       << "int main() { printf(\"%.17g\\n\", f(" << x << ", " << y << ")); return 0; }\n";
    const std::string cmd = "c++ -o '" + exe + "' '" + src + "' -lm && '" + exe + "' > '" + out + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << code;
    return std::stod(slurp(out));
}

}  // namespace

TEST(OutputCode, CcodeCompilesAndEvaluatesLikeEvalf) {
    if (!have_compiler()) GTEST_SKIP() << "no c++ compiler";
    const std::string e = "sin(x)^2 + x/3 + pi*sqrt(y) - exp(-x*y)/(1 + y^3) + abs(x - 2)^(3/2)";
    std::string code = out_of("print(ccode(" + e + "))");
    ASSERT_FALSE(code.empty());
    code.pop_back();  // newline
    const double got = run_c(code, 0.7, 1.3);
    const std::string want = out_of("evalf(subs(" + e + ", [x = 7/10, y = 13/10]))");
    EXPECT_NEAR(got, std::stod(want), 1e-12) << code;
}

TEST(OutputCode, CcodeOfAVectorNeedsComponents) {
    cli_result r = run_symrep("-e 'vector w, r0; ccode(w x r0)'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("ccode: the expression has abstract vectors (r0, w); give their components first"),
              std::string::npos)
        << r.err;
    // after subs of components: one C expression per component
    EXPECT_EQ(out_of("vector w; print(ccode(subs(w x [1, 0, 0], [w = [a, b, c]])))"), "{0.0, c, -b}\n");
}

TEST(OutputCode, CodeIsDeterministicAndUsesDoubleLiterals) {
    const std::string a = out_of("u := y + x; print(ccode(sin(x)^2 + 1/(3*y) - x*y)); print(pycode(x - y^2))");
    const std::string b = out_of("u := x + y; print(ccode(-y*x + 1/(3*y) + sin(x)^2)); print(pycode(-y^2 + x))");
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, "-x*y + pow(sin(x), 2.0) + 1.0/3.0/y\n-y**2 + x\n");
}

TEST(OutputCode, CcodeOfVectorComponentsEvaluates) {
    if (!have_compiler()) GTEST_SKIP() << "no c++ compiler";
    std::string code = out_of("vector w, v; print(ccode(subs(w x v, [w = [x, y, 2], v = [1, x*y, 3]])))");
    code.pop_back();
    // {3*y - 2*x*y, 2 - 3*x, x^2*y - y}
    const std::string src = temp_path("v.cpp"), exe = temp_path("v.out"), out = temp_path("v.txt");
    std::ofstream(src) << "#include <math.h>\n#include <stdio.h>\nint main() { double x = 0.5, y = 3.0;\n"
                       << "double c[3] = " << code << ";\nprintf(\"%g %g %g\\n\", c[0], c[1], c[2]); }\n";
    ASSERT_EQ(std::system(("c++ -o '" + exe + "' '" + src + "' -lm && '" + exe + "' > '" + out + "'").c_str()), 0)
        << code;
    EXPECT_EQ(slurp(out), "6 0.5 -2.25\n") << code;
}

// --- Python code ------------------------------------------------------------

TEST(OutputCode, PycodeEvaluatesLikeEvalf) {
    if (std::system("python3 -c 'pass' >/dev/null 2>&1") != 0) GTEST_SKIP() << "no python3";
    std::string pythonpath;
    if (std::system("python3 -c 'import numpy' >/dev/null 2>&1") != 0) {
        // no NumPy: a stand-in module with the functions pycode uses, from math
        const std::string dir = temp_path("pystub");
        std::system(("mkdir -p '" + dir + "'").c_str());
        std::ofstream(dir + "/numpy.py") << "from math import sin, cos, tan, sinh, cosh, tanh, exp, log, sqrt, pi\n"
                                         << "from math import asin as arcsin, acos as arccos, atan as arctan\n"
                                         << "abs = abs\ndef array(l): return list(l)\n";
        pythonpath = "PYTHONPATH='" + dir + "' ";
    }
    const std::string e = "sin(x)^2 + x/3 - pi*y^(-2) + sqrt(y) - (x - y)^3 + atan(x)";
    std::string code = out_of("print(pycode(" + e + "))");
    code.pop_back();
    const std::string py = temp_path("f.py"), out = temp_path("py.txt");
    std::ofstream(py) << "import numpy\nx = 0.7\ny = 1.3\nprint(repr(float(" << code << ")))\n";
    ASSERT_EQ(std::system((pythonpath + "python3 '" + py + "' > '" + out + "'").c_str()), 0) << code;
    const std::string want = out_of("evalf(subs(" + e + ", [x = 7/10, y = 13/10]))");
    EXPECT_NEAR(std::stod(slurp(out)), std::stod(want), 1e-12) << code;
    EXPECT_EQ(out_of("print(pycode([x, y^2]))"), "numpy.array([x, y**2])\n");
}

// --- JSON -------------------------------------------------------------------

TEST(OutputJson, OneObjectPerResultAndPerError) {
    cli_result r = run_script("1 + 1\n\"a\\\"b\\nc\"\n[1, x]\nnosuch(2)\ntrue\n", "--format json", "j.sr");
    const std::string file = temp_path("j.sr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "{\"file\": \"" + file + "\", \"line\": 1, \"kind\": \"expression\", \"value\": \"2\"}\n"
                     "{\"file\": \"" + file + "\", \"line\": 2, \"kind\": \"string\", \"value\": \"a\\\"b\\nc\"}\n"
                     "{\"file\": \"" + file + "\", \"line\": 3, \"kind\": \"list\", \"value\": \"[1, x]\"}\n"
                     "{\"file\": \"" + file + "\", \"line\": 5, \"kind\": \"boolean\", \"value\": \"true\"}\n");
    EXPECT_EQ(r.err, "{\"error\": \"unknown function 'nosuch' (help() lists all functions)\", \"file\": \"" + file +
                         "\", \"line\": 4, \"column\": 1}\n");
}

TEST(OutputJson, ControlCharactersAreEscaped) {
    cli_result r = run_symrep("--format json -e 'print(1); \"tab\\there\"'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\"value\": \"tab\\there\"}"), std::string::npos) << r.out;
}

// --- Digits -----------------------------------------------------------------

TEST(OutputDigits, DigitsSetsTheFloatPrecision) {
    const std::string d17 = out_of("evalf(1/3)");
    const std::string d30 = out_of("digits(30); evalf(1/3)");
    EXPECT_EQ(d30.substr(0, 3), "17\n");  // digits returns the previous setting
    EXPECT_GT(d30.size() - 3, d17.size() + 10) << d17 << d30;
    EXPECT_EQ(d30.substr(3, 32), "0.333333333333333333333333333333");
    const std::string d50 = out_of("Digits := 50; evalf(pi); 1/3; digits()");
    // 50 significant digits (the float model: D digits, trailing zeros dropped; docs/language.md)
    EXPECT_EQ(d50.substr(0, 52), "3.1415926535897932384626433832795028841971693993751\n");
    EXPECT_NE(d50.find("\n1/3\n50\n"), std::string::npos) << d50;  // exact stays exact
    cli_result bad = run_symrep("-e 'Digits := -3'");
    EXPECT_EQ(bad.status, 1);
    EXPECT_NE(bad.err.find("Digits must be a positive integer"), std::string::npos) << bad.err;
}

// --- script mode ------------------------------------------------------------

TEST(ScriptMode, EchoPrintsEachStatementAndItsResult) {
    cli_result r = run_script("a := 2; a^10\n# a comment\nexpand((x +\n 1)^2)\nprint(\"hi\")\n", "--echo");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "> a := 2\n> a^10\n1024\n> expand((x +\n 1)^2)\nx^2 + 2*x + 1\n> print(\"hi\")\nhi\n");
}

TEST(ScriptMode, StopOnErrorStopsAtTheFirstFailure) {
    const std::string script = "1 + 1\n2 * nosuch(1)\n3 + 3\n";
    cli_result go_on = run_script(script);
    EXPECT_EQ(go_on.status, 1);
    EXPECT_EQ(go_on.out, "2\n6\n");
    cli_result stop = run_script(script, "--stop-on-error");
    EXPECT_EQ(stop.status, 1);
    EXPECT_EQ(stop.out, "2\n");
    // later -e and files do not run either
    cli_result r = run_symrep("--stop-on-error -e '1/0' -e '5'");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
}

TEST(ScriptMode, ErrorsShowTheLineAndACaret) {
    cli_result r = run_script("1 + 1\n\tb := 2 * nosuch(1)\n", "", "caret.sr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, temp_path("caret.sr") + ":2:11: error: unknown function 'nosuch' (help() lists all functions)\n"
                     "    \tb := 2 * nosuch(1)\n"
                     "    \t         ^\n");
    cli_result e = run_symrep("-e 'x := (1 + ]'");
    EXPECT_NE(e.err.find("\n    x := (1 + ]\n              ^\n"), std::string::npos) << e.err;
    cli_result plain = run_symrep("--no-caret -e 'nosuch(1)'");
    EXPECT_EQ(plain.err, "<command line>:1:1: error: unknown function 'nosuch' (help() lists all functions)\n");
}

// Results written before an error come before its report when both streams go
// to one pipe (symrep s.sr 2>&1 | less; the transcript tests rely on it): std::cerr
// is tied to std::cout, so a report flushes the results first.
TEST(ScriptMode, ErrorReportsKeepTheirPlaceInAMergedStream) {
    cli_result r = run_symrep("--no-caret -e '1 + 1' -e 'nosuch(1)' -e '3 + 3'", nullptr, "", true);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "2\n<command line>:1:1: error: unknown function 'nosuch' (help() lists all functions)\n6\n");
}

TEST(ScriptMode, LoadRunsAnotherScriptInTheSameSession) {
    const std::string inner = temp_path("inner.sr");
    std::ofstream(inner) << "k := 7\nk + 1\nnosuch()\n";
    cli_result r = run_script("load(\"" + inner + "\")\nk * 2\n", "", "outer.sr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "8\n14\n");
    EXPECT_EQ(r.err.rfind(inner + ":3:1: error: unknown function 'nosuch'", 0), 0u) << r.err;
}
