// Output is deterministic: the same input prints the same bytes. Every example
// script and a set of scenes (exact and decimal values) run twice, each in a
// process of its own (GiNaC's order of terms follows hash values that can
// change between processes), and the outputs must agree byte for byte. The
// only output that may differ is a time measurement ("closed form 1.12 ms" in
// verify's report, "(0.3 s)"), which is masked first.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "test_util.h"

namespace {

using symrep::test::run_symrep;

std::string without_timings(const std::string& s) {
    static const std::regex time(R"([0-9.]+(e[-+]?[0-9]+)? (us|ms|s)\b)");
    return std::regex_replace(s, time, "<time>");
}

/// Runs twice and expects the same bytes; returns the first run's output.
std::string expect_twice_the_same(const std::string& args, const std::string* input, const std::string& what) {
    const auto a = run_symrep(args, input, "", true);
    const auto b = run_symrep(args, input, "", true);
    EXPECT_EQ(a.status, b.status) << what;
    EXPECT_EQ(without_timings(a.out), without_timings(b.out)) << what << ": two runs printed different output";
    return a.out;
}

TEST(Determinism, EveryExampleScriptPrintsTheSameBytesTwice) {
    std::size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(std::string(SYMREP_SOURCE_DIR) + "/examples")) {
        if (e.path().extension() != ".symrep") continue;
        ++n;
        expect_twice_the_same("'" + e.path().string() + "'", nullptr, e.path().filename().string());
    }
    EXPECT_GE(n, 10u);
}

TEST(Determinism, ScenesWithExactAndDecimalValuesPrintTheSameBytesTwice) {
    const std::string scenes = R"(vector w, g, r0, v0, E, B
positive w0
P := ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)
solve(P, [w = [0.3e-4, 0, 0.7e-4], w0 = 0.38, r0 = [3.0, 0, 0], v0 = [0, 0.1, 0]])
solve(P, [w = [1/10, 0, 1/5], w0 = 1/2, r0 = [3, 0, 0], v0 = [0, 0, 0]])
G := ode(r'' + 2*w x r' = g, r(0) = r0, r'(0) = v0)
solve(G, [w = [1, 1, 1], g = [0, 0, -1], r0 = [0, 0, 0], v0 = [1, 0, 0]])
solve(G, [w = [0, 7.2921e-5, 0.0001], g = [0, 0, -9.81], r0 = [0, 0, 10.0], v0 = [1.5, 0, 0]])
C := ode(r'' = q/m*(r' x B + E), r(0) = r0, r'(0) = v0)
solve(C, [q = -3, m = 2, B = [1, 1, 1], E = [0, 1, 0], r0 = [0, 0, 0], v0 = [1, 0, 0]])
)";
    const std::string out = expect_twice_the_same("", &scenes, "scenes");
    // the scenes really ran: one model report per solve, no error
    std::size_t models = 0;
    for (std::size_t p = 0; (p = out.find("solve: model:", p)) != std::string::npos; ++p) ++models;
    EXPECT_EQ(models, 5u) << out;
    EXPECT_EQ(out.find("error"), std::string::npos) << out;
}

}  // namespace
