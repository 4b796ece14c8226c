// tests/test_scene_differential.cpp -- differential test (a) of issue 13: random
// exact rational scenes of the five constant-rotation problems (fixed seeds).
//
// For each scene: solve(P, values) must be exactly equal (vector::equal, the exact
// zero test by components, no tolerance) to solve(P) with the values put in, the
// exact check of P with the values must pass, and eval of both at a time must
// agree to 1e-13 relative (both are evaluated by the precision-controlled path to
// double precision; 1e-13 leaves room for the rounding of the final doubles only).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "lang/values.h"
#include "mechanics/cauchy_problem.h"
#include "mechanics/scene.h"
#include "numeric/reference.h"
#include "scalar/scalar.h"
#include "test_support.h"
#include "vector/vector.h"

using namespace symrep;
using namespace symrep::lang;
using symrep::test::test_session;
using GiNaC::ex;

namespace {

struct problem_case {
    std::string name, declarations, problem;
    std::vector<std::string> vectors;  // vector parameters (and initial values)
    std::vector<std::string> scalars;  // scalar parameters: positive ones first
    std::size_t positive;              // how many of scalars are positive
};

const std::vector<problem_case> problems = {
    {"centrifugal", "vector w, g, r0, v0", "ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0)",
     {"w", "g", "r0", "v0"}, {}, 0},
    {"coriolis", "vector w, g, r0, v0", "ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)",
     {"w", "g", "r0", "v0"}, {}, 0},
    {"charge velocity", "vector E, B, v0; positive m", "ode(m*v' = q*(v x B + E), v(0) = v0)",
     {"B", "E", "v0"}, {"m", "q"}, 1},
    {"charge position", "vector E, B, r0, v0; positive m", "ode(r'' = q/m*(r' x B + E), r(0) = r0, r'(0) = v0)",
     {"B", "E", "r0", "v0"}, {"m", "q"}, 1},
    {"foucault", "vector w, r0, v0; positive w0",
     "ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)", {"w", "r0", "v0"}, {"w0"}, 1},
};

// A small rational, sometimes 0 (so that zero, parallel and perpendicular data occur).
std::string rational(std::mt19937& gen, bool nonzero_positive) {
    std::uniform_int_distribution<int> num(nonzero_positive ? 1 : -3, 3), den(1, 3);
    const int n = num(gen), d = den(gen);
    return d == 1 ? std::to_string(n) : "(" + std::to_string(n) + ")/" + std::to_string(d);
}

std::string vector_value(std::mt19937& gen) {
    std::uniform_int_distribution<int> kind(0, 9);
    switch (kind(gen)) {
        case 0: return "[0, 0, 0]";
        case 1: return "[0, 0, " + rational(gen, true) + "]";
        default: return "[" + rational(gen, false) + ", " + rational(gen, false) + ", " + rational(gen, false) + "]";
    }
}

double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double scale = 0, diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        scale = std::max({scale, std::abs(a[i]), std::abs(b[i])});
        diff = std::max(diff, std::abs(a[i] - b[i]));
    }
    return scale == 0 ? diff : diff / scale;
}

std::vector<double> numbers(const ex& e, const data_values& d, const ex& t) {
    std::vector<double> out;
    for (const ex& c : components(put_values_limit(e, d, t))) out.push_back(num::accurate_double(c));
    return out;
}

/// What run_problem compared: the test bodies assert that the comparisons ran.
struct tally {
    int solved = 0;          ///< scenes solved by solve(P, values)
    int equal_general = 0;   ///< scenes equal to solve(P) with the values put in
    int general_singular = 0;
    int checked = 0;         ///< scenes whose exact check passed
    int evaluated = 0;       ///< eval comparisons within 1e-13
};

tally run_problem(const problem_case& pc, unsigned seed, int scenes) {
    SCOPED_TRACE(pc.name);
    tally r;
    std::mt19937 gen(seed);
    test_session t;
    if (t.run(pc.declarations + "\nP := " + pc.problem + "\nGs := solve(P)") != 0) {
        ADD_FAILURE() << t.err.str();
        return r;
    }
    const mechanics::cauchy_problem& P = t.val("P").as_problem();
    const ex Gs = t.ex("Gs");
    builtin b;
    b.name = "test";
    for (int n = 0; n < scenes; ++n) {
        std::string vals = "[";
        for (std::size_t i = 0; i < pc.vectors.size(); ++i)
            vals += (i ? ", " : "") + pc.vectors[i] + " = " + vector_value(gen);
        for (std::size_t i = 0; i < pc.scalars.size(); ++i)
            vals += ", " + pc.scalars[i] + " = " + rational(gen, i < pc.positive);
        vals += "]";
        SCOPED_TRACE(vals);
        t.out.str("");
        t.err.str("");
        if (t.run("vals := " + vals + "\ns := solve(P, vals)") != 0) {
            ADD_FAILURE() << "solve(P, vals) failed: " << t.err.str();
            continue;
        }
        ++r.solved;
        const ex s = t.ex("s");
        const data_values d = read_values(t.val("vals"), b, 0);
        const mechanics::parameter_values v{d.vectors, d.scalars};
        // exactly the general solution with the values put in (where that is defined)
        bool defined = true;
        ex g;
        try {
            g = mechanics::put_values(Gs, v);
        } catch (const symrep::error&) {
            defined = false;
            ++r.general_singular;
        }
        if (defined) {
            const bool same = equal(s, g);
            EXPECT_TRUE(same) << "scene: " << to_string(s) << "\ngeneral: " << to_string(g);
            r.equal_general += same;
        }
        // the exact check of P with the values
        const mechanics::solution_check k = mechanics::check(mechanics::with_values(P, v), s);
        EXPECT_TRUE(k.residual_zero) << to_string(k.residual);
        EXPECT_TRUE(k.initial_ok);
        r.checked += bool(k);
        // eval agrees with the general path (its exact limit where it is singular)
        for (const ex& T : {ex(GiNaC::numeric(7, 3)), ex(GiNaC::numeric(-1, 2))}) {
            data_values dt = d;
            dt.scalars[P.t] = T;
            const std::vector<double> a = numbers(s, dt, P.t), c = numbers(Gs, dt, P.t);
            const double rel = relative_difference(a, c);
            EXPECT_LE(rel, 1e-13) << "t = " << T;
            r.evaluated += rel <= 1e-13;
        }
    }
    std::cout << pc.name << ": " << scenes << " scenes, general form singular at " << r.general_singular
              << " of them (compared through eval's limit)\n";
    return r;
}

/// Every scene solved, checked and evaluated; most compared exactly with the general solution.
/// Every scene solved, checked and evaluated at two times, and compared with the
/// general solution (exactly, or where that is singular at the values, by its limit).
::testing::AssertionResult all_compared(const tally& r, int scenes) {
    if (r.solved != scenes || r.checked != scenes || r.evaluated != 2 * scenes ||
        r.equal_general + r.general_singular != scenes)
        return ::testing::AssertionFailure() << "solved " << r.solved << ", checked " << r.checked << ", evaluated "
                                             << r.evaluated << ", equal to the general solution " << r.equal_general
                                             << " + singular there " << r.general_singular << " of " << scenes;
    if (r.equal_general < scenes / 2)
        return ::testing::AssertionFailure() << "too few scenes compared exactly with the general solution: "
                                             << r.equal_general << " of " << scenes;
    return ::testing::AssertionSuccess();
}

}  // namespace

TEST(SceneDifferential, CentrifugalAndCoriolis) {
    EXPECT_TRUE(all_compared(run_problem(problems[0], 13001, 50), 50));
    EXPECT_TRUE(all_compared(run_problem(problems[1], 13002, 50), 50));
}

TEST(SceneDifferential, Charge) {
    EXPECT_TRUE(all_compared(run_problem(problems[2], 13003, 50), 50));
    EXPECT_TRUE(all_compared(run_problem(problems[3], 13004, 50), 50));
}

TEST(SceneDifferential, Foucault) { EXPECT_TRUE(all_compared(run_problem(problems[4], 13005, 50), 50)); }
