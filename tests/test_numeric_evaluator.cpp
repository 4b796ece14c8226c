// Tests of the flat double evaluator (numeric/evaluator.h): agreement with
// GiNaC's evalf, common-subexpression sharing, determinism, error messages.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "numeric/evaluator.h"
#include "numeric/stable_evaluator.h"

using namespace symrep;
using namespace symrep::num;
using GiNaC::ex;
using GiNaC::symbol;

namespace {

/// GiNaC's value of e at the point, at 30 digits, rounded to double.
double reference(const ex& e, const std::vector<symbol>& vars, const std::vector<double>& at) {
    GiNaC::exmap m;
    for (std::size_t i = 0; i < vars.size(); ++i) m[vars[i]] = GiNaC::numeric(at[i]);
    const long saved = GiNaC::Digits;
    GiNaC::Digits = 30;
    const ex v = e.subs(m).evalf();
    GiNaC::Digits = saved;
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(v)) << v;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

/// Random expression trees. With `positive`, every subexpression is positive
/// at positive inputs (no subtraction, only increasing or positive functions),
/// so every operation is well conditioned: each rounds with at most ~1 ulp of
/// relative error and errors add along the tree.
struct expression_generator {
    std::mt19937 rng;
    std::vector<symbol> vars;
    bool positive;

    ex leaf() {
        std::uniform_int_distribution<int> pick(0, static_cast<int>(vars.size()));
        const int k = pick(rng);
        if (k < static_cast<int>(vars.size())) return vars[k];
        std::uniform_int_distribution<int> num(1, 9), den(1, 7);
        return GiNaC::numeric(num(rng), den(rng));
    }

    ex tree(int depth) {
        if (depth == 0) return leaf();
        std::uniform_int_distribution<int> pick(0, positive ? 8 : 12);
        const ex a = tree(depth - 1);
        switch (pick(rng)) {
            case 0: return a + tree(depth - 1);
            case 1: return a * tree(depth - 1);
            case 2: return a / (1 + GiNaC::pow(tree(depth - 1), 2));
            case 3: return GiNaC::sqrt(1 + GiNaC::pow(a, 2));
            case 4: return GiNaC::exp(a / (1 + GiNaC::pow(a, 2)));
            case 5: return GiNaC::pow(a, 3);
            case 6: return GiNaC::log(2 + GiNaC::pow(a, 2));
            case 7: return 2 + GiNaC::cos(a);
            case 8: return GiNaC::Pi * a + GiNaC::sqrt(ex(2));
            case 9: return a - tree(depth - 1);
            case 10: return GiNaC::sin(a);
            case 11: return GiNaC::atan(a) * GiNaC::pow(a, -2);
            default: return GiNaC::atan2(a, tree(depth - 1)) + GiNaC::tanh(a);
        }
    }
};

}  // namespace

// Well-conditioned expressions (positive terms only): relative error of at most
// a few ulps per operation; trees of depth 4 have at most a few dozen
// operations, so 1e-13 relative (about 450 ulps) is a safe bound that still
// catches any wrong operation.
TEST(NumericEvaluator, AgreesWithEvalfOnWellConditionedRandomExpressions) {
    symbol x("x"), y("y"), z("z");
    expression_generator gen{std::mt19937(12345), {x, y, z}, true};
    std::mt19937 pts(777);
    std::uniform_real_distribution<double> u(0.1, 2.0);
    for (int n = 0; n < 60; ++n) {
        const ex e = gen.tree(4);
        const compiled_function f = compile(std::vector<ex>{e}, {x, y, z});
        for (int p = 0; p < 5; ++p) {
            std::vector<double> at = {u(pts), u(pts), u(pts)};
            const double ref = reference(e, {x, y, z}, at);
            double got;
            f.eval(at.data(), &got);
            EXPECT_LE(std::fabs(got - ref), 1e-13 * std::fabs(ref)) << e << " at " << at[0] << "," << at[1] << "," << at[2];
        }
    }
}

// General expressions (subtraction, sin, atan2, negative powers): cancellation
// can amplify rounding errors by the ratio of intermediate to final
// magnitudes, which this generator keeps moderate (bounded functions,
// denominators >= 1, inputs in [-2, 2]); the tolerance is absolute-relative,
// 1e-11 (1 + |ref|).
TEST(NumericEvaluator, AgreesWithEvalfOnGeneralRandomExpressions) {
    symbol x("x"), y("y");
    expression_generator gen{std::mt19937(2024), {x, y}, false};
    std::mt19937 pts(99);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int compared = 0;
    for (int n = 0; n < 80; ++n) {
        ex e;
        try {
            e = gen.tree(4);
        } catch (const std::domain_error&) {
            continue;  // GiNaC refused to build it (e.g. (a - a)^(-2))
        }
        compiled_function f;
        try {
            f = compile(std::vector<ex>{e}, {x, y});
        } catch (const symrep::error& err) {
            FAIL() << err.what() << " for " << e;
        }
        for (int p = 0; p < 4; ++p) {
            std::vector<double> at = {u(pts), u(pts)};
            double got;
            f.eval(at.data(), &got);
            if (!std::isfinite(got)) continue;  // e.g. atan(0)/0^2 at an unlucky point
            const double ref = reference(e, {x, y}, at);
            EXPECT_LE(std::fabs(got - ref), 1e-11 * (1 + std::fabs(ref))) << e;
            ++compared;
        }
    }
    EXPECT_GT(compared, 250);
}

TEST(NumericEvaluator, EveryOperation) {
    symbol x("x"), y("y");
    const std::vector<ex> outs = {
        x + y, x - y, x * y, x / y, -x, GiNaC::pow(x, 7), GiNaC::pow(x, -3), GiNaC::pow(x, y),
        GiNaC::pow(x, GiNaC::numeric(1, 3)), GiNaC::sqrt(x), GiNaC::pow(x, GiNaC::numeric(-1, 2)),
        GiNaC::pow(x, GiNaC::numeric(5, 2)), GiNaC::exp(x), GiNaC::log(x), GiNaC::abs(x - y), GiNaC::sin(x),
        GiNaC::cos(x), GiNaC::tan(x), GiNaC::asin(x / 2), GiNaC::acos(x / 2), GiNaC::atan(x), GiNaC::atan2(x, -y),
        GiNaC::sinh(x), GiNaC::cosh(x), GiNaC::tanh(x), GiNaC::asinh(x), GiNaC::acosh(1 + x), GiNaC::atanh(x / 2),
        GiNaC::Pi * x, GiNaC::numeric(3, 7), GiNaC::Euler + GiNaC::Catalan};
    const double X = 0.7, Y = 1.9;
    const std::vector<double> expect = {
        X + Y, X - Y, X * Y, X / Y, -X, std::pow(X, 7), std::pow(X, -3), std::pow(X, Y), std::cbrt(X), std::sqrt(X),
        1 / std::sqrt(X), std::pow(X, 2.5), std::exp(X), std::log(X), std::fabs(X - Y), std::sin(X), std::cos(X),
        std::tan(X), std::asin(X / 2), std::acos(X / 2), std::atan(X), std::atan2(X, -Y), std::sinh(X), std::cosh(X),
        std::tanh(X), std::asinh(X), std::acosh(1 + X), std::atanh(X / 2), M_PI * X, 3.0 / 7.0,
        0.57721566490153286 + 0.91596559417721902};
    const compiled_function f = compile(outs, {x, y});
    ASSERT_EQ(f.n_outputs(), outs.size());
    const std::vector<double> got = f({X, Y});
    for (std::size_t i = 0; i < outs.size(); ++i)
        EXPECT_NEAR(got[i], expect[i], 4e-16 * (1 + std::fabs(expect[i])) * 4) << i << ": " << outs[i];
}

TEST(NumericEvaluator, CommonSubexpressionsAreShared) {
    symbol x("x"), y("y");
    const ex e = x * y + GiNaC::sin(x * y);
    const compiled_function shared = compile(std::vector<ex>{e}, {x, y});
    const compiled_function unshared = compile(std::vector<ex>{e}, {x, y}, compile_options{false});
    EXPECT_EQ(shared.n_instructions(), 3u) << shared.listing();    // mul, sin, add
    EXPECT_EQ(unshared.n_instructions(), 4u) << unshared.listing();  // mul, mul, sin, add
    EXPECT_LT(shared.n_instructions(), unshared.n_instructions());
    EXPECT_EQ(shared({0.3, 0.4}), unshared({0.3, 0.4}));

    // Across outputs, and powers share their partial products: x^2, x^4 (= (x^2)^2), x^5.
    const compiled_function p = compile(std::vector<ex>{GiNaC::pow(x, 2), GiNaC::pow(x, 4), GiNaC::pow(x, 5)}, {x});
    EXPECT_EQ(p.n_instructions(), 3u) << p.listing();
    const std::vector<double> v = p({1.5});
    EXPECT_EQ(v[0], 1.5 * 1.5);
    EXPECT_EQ(v[1], (1.5 * 1.5) * (1.5 * 1.5));
    EXPECT_EQ(v[2], v[1] * 1.5);

    // Symbol-free subtrees become one constant: sqrt(2)*Pi*x is one multiplication.
    const compiled_function c = compile(GiNaC::sqrt(ex(2)) * GiNaC::Pi * x, {x});
    EXPECT_EQ(c.n_instructions(), 1u) << c.listing();
    EXPECT_NEAR(c({1.0})[0], std::sqrt(2.0) * M_PI, 1e-15);
}

TEST(NumericEvaluator, DeterministicAndVectorOutputs) {
    symbol t("t");
    const ex e = GiNaC::lst{GiNaC::cos(t), GiNaC::sin(t), t * t / 3};
    const compiled_function f1 = compile(e, {t}), f2 = compile(e, {t});
    EXPECT_EQ(f1.listing(), f2.listing());
    for (double tv : {0.0, 0.5, 10.0, -3.25}) {
        const Eigen::Vector3d a = f1.eval3({tv}), b = f2.eval3(&tv), c = f1.eval3(&tv);
        EXPECT_EQ(a, b);
        EXPECT_EQ(a, c);
        EXPECT_EQ(a[0], std::cos(tv));
        EXPECT_EQ(a[1], std::sin(tv));
    }
    // A 3x1 matrix gives three outputs, row by row.
    const compiled_function m = compile(GiNaC::matrix{{t}, {2 * t}, {3 * t}}, {t});
    EXPECT_EQ(m.eval3({2.0}), Eigen::Vector3d(2, 4, 6));
    // eval_many
    const double in[3] = {0.0, 1.0, 2.0};
    double out[9];
    m.eval_many(in, out, 3);
    EXPECT_EQ(out[7], 4.0);
    // No inputs at all
    const compiled_function k = compile(std::vector<ex>{GiNaC::Pi}, {});
    EXPECT_EQ(k({})[0], M_PI);
}

TEST(NumericEvaluator, ErrorsNameTheCulprit) {
    symbol t("t"), k("k"), x("x");
    try {
        compile(std::vector<ex>{k * t}, {t});
        FAIL() << "no error";
    } catch (const type_error& e) {
        EXPECT_NE(std::string(e.what()).find("'k'"), std::string::npos) << e.what();
    }
    try {
        compile(std::vector<ex>{GiNaC::zeta(t)}, {t});
        FAIL() << "no error";
    } catch (const type_error& e) {
        EXPECT_NE(std::string(e.what()).find("'zeta'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(compile(std::vector<ex>{GiNaC::I * t}, {t}), domain_error);
    EXPECT_THROW(compile(std::vector<ex>{t}, {t, t}), type_error);
    EXPECT_THROW(compile(std::vector<ex>{GiNaC::lst{t}}, {t}), type_error);
    EXPECT_THROW(compile(std::vector<ex>{t == 1}, {t}), type_error);
    const compiled_function two = compile(GiNaC::lst{t, t}, {t});
    EXPECT_THROW(two.eval3({1.0}), type_error);
    EXPECT_THROW(two({1.0, 2.0}), type_error);
    // A symbol-free unsupported function is folded to its value by GiNaC.
    EXPECT_NEAR(compile(std::vector<ex>{GiNaC::zeta(ex(2)) * x}, {x})({1.0})[0], M_PI * M_PI / 6, 1e-15);
}

TEST(NumericEvaluator, EvalManyIsBitwiseEval) {
    symbol x("x"), y("y");
    const std::vector<ex> outs = {GiNaC::sin(x * y) + GiNaC::cos(x * y) * x, GiNaC::exp(-x) / (1 + y * y),
                                  GiNaC::atan2(y, x) + GiNaC::pow(x, 5), GiNaC::Pi};
    const compiled_function f = compile(outs, {x, y});
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3, 3);
    for (std::size_t n : {std::size_t{1}, std::size_t{15}, std::size_t{16}, std::size_t{37}}) {
        std::vector<double> in(2 * n), out(4 * n);
        for (auto& v : in) v = u(rng);
        f.eval_many(in.data(), out.data(), n);
        for (std::size_t p = 0; p < n; ++p) {
            double one[4];
            f.eval(&in[2 * p], one);
            for (int j = 0; j < 4; ++j) EXPECT_EQ(out[4 * p + j], one[j]) << n << " " << p << " " << j;
        }
    }
    f.eval_many(nullptr, nullptr, 0);  // nothing to do, no access
}

// The interpreter's symbols are realsymbols; a realsymbol copied into a plain
// GiNaC::symbol gets another hash and would no longer match the expression.
TEST(NumericEvaluator, RealsymbolInputsAreNotSliced) {
    const GiNaC::realsymbol a("a"), b("b");
    const compiled_function f = compile(ex(a * a + 3 * b), {a, b});
    EXPECT_DOUBLE_EQ(f({2.0, 5.0})[0], 19.0);
    const GiNaC::possymbol p("p");
    EXPECT_DOUBLE_EQ(compile(ex(sqrt(p * p)), {p})({1.5})[0], 1.5);
}

TEST(NumericEvaluator, CheckedBatchFlagsAndRepairsCancellingPoints) {
    // issue 27 1.3: the bare program is wrong in every digit where the closed form cancels
    // ((1 - cos(w t))/w^2 at w t = 1e-9 gives 0 or noise); stable_function::eval_many proves
    // each output to check_tol by the double tier's bound and evaluates the others again.
    // Reference: 1/2 - (w t)^2/24 to 1e-16 relative for w t <= 1e-3.
    const GiNaC::symbol w("w"), t("t");
    const GiNaC::ex e = (1 - GiNaC::cos(w * t)) / GiNaC::pow(w, 2);
    const symrep::num::compiled_function bare = symrep::num::compile(e, {w, t});
    const symrep::num::stable_function checked(e, {w, t});
    std::vector<double> in, plain(6), good(6);
    for (double W : {1e-300, 1e-100, 1e-9, 1e-5, 1e-3, 0.5}) {
        in.push_back(W);
        in.push_back(1.0);
    }
    bare.eval_many(in.data(), plain.data(), 6);
    const auto again = checked.eval_many_binary64(in.data(), good.data(), 6, 1e-6);
    EXPECT_GE(again.size(), 3u);  // at least w = 1e-300, 1e-100, 1e-9 need more than double
    checked.eval_many(in.data(), good.data(), 6, 1e-6);
    for (int i = 0; i < 5; ++i) {
        const double wt = in[2 * i];
        EXPECT_NEAR(good[i], 0.5 - wt * wt / 24, 1e-6 * 0.5) << "w = " << wt;
    }
    EXPECT_NEAR(good[5], (1 - std::cos(0.5)) / 0.25, 1e-6);
    EXPECT_GT(std::fabs(plain[2] - 0.5), 0.1);  // the bare program at w t = 1e-9: wrong
}
