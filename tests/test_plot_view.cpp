// tests/test_plot_view.cpp -- the picture says what the caption says (issue 32): the view
// of a space curve chosen from its data (output/plot.h: choose_view), the axis labels
// with their scale and offset, and the number of ticks, read from the gnuplot script
// symrep writes (gnuplot_script: no gnuplot is run, except in the last test).
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "output/plot.h"
#include "test_support.h"
#include "test_util.h"

using symrep::output::plot_spec;
using symrep::test::slurp;
using symrep::test::test_session;
using symrep::test::what_of;
namespace fs = std::filesystem;

namespace {

/// A space curve sampled at n points of [0, T].
template <class F>
plot_spec curve(F r, double T, int n = 400) {
    plot_spec s;
    s.three_d = true;
    s.xlabel = "x", s.ylabel = "y", s.zlabel = "z";
    s.title = "test";
    s.columns.assign(3, {});
    for (int i = 0; i < n; ++i) {
        const double t = T * i / (n - 1);
        const auto p = r(t);
        for (int k = 0; k < 3; ++k) s.columns[k].push_back(p[k]);
    }
    return s;
}

struct script_dir {
    fs::path path;
    script_dir() {
        path = fs::path(::testing::TempDir()) / ("symrep_plot_view_" + std::to_string(getpid()));
        fs::create_directories(path);
    }
    ~script_dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

std::string script_of(const plot_spec& s) {
    script_dir d;
    return symrep::output::gnuplot_script(s, "svg", d.path.string(), "test");
}

/// The value of `set <axis>label '...'`, or "" when absent.
std::string label_of(const std::string& script, const std::string& axis) {
    std::smatch m;
    if (std::regex_search(script, m, std::regex("set " + axis + "label '([^']*)'"))) return m[1];
    return "";
}

/// The number of ticks of `set <axis>tics lo, step, hi` (-1 when absent).
int ticks_of(const std::string& script, const std::string& axis) {
    std::smatch m;
    if (!std::regex_search(script, m, std::regex("set " + axis + "tics ([-0-9.e+]+), ([-0-9.e+]+), ([-0-9.e+]+)")))
        return -1;
    const double lo = std::stod(m[1]), step = std::stod(m[2]), hi = std::stod(m[3]);
    return int(std::lround((hi - lo) / step)) + 1;
}

const double pi = std::acos(-1.0);

}  // namespace

// a Foucault-like pendulum: x +-3, y +-0.6, z within 0.003 of a constant: seen from above
TEST(PlotView, NearlyPlanarInZIsSeenFromAbove) {
    const plot_spec s = curve([](double t) { return std::array<double, 3>{3 * std::cos(t), 0.6 * std::sin(t), -0.003 * std::cos(2 * t)}; }, 2 * pi);
    EXPECT_EQ(symrep::output::choose_view(s, "test").kind, "xy");
    const std::string g = script_of(s);
    EXPECT_EQ(g.find("splot"), std::string::npos);
    EXPECT_NE(g.find("seen from above (x-y)"), std::string::npos) << g;
    EXPECT_NE(g.find("z from -0.003 to 0.003"), std::string::npos) << g;
    // x spans 6, y 1.2: more than 1:4, so independent scales, said on the y label
    EXPECT_EQ(label_of(g, "x"), "x");
    EXPECT_EQ(label_of(g, "y"), "y (not to scale with x)");
    EXPECT_EQ(g.find("set size ratio -1"), std::string::npos);
    EXPECT_LE(ticks_of(g, "x"), 7);
    EXPECT_LE(ticks_of(g, "y"), 7);
    EXPECT_GE(ticks_of(g, "y"), 3);
}

// exactly in z = 0 with comparable extents: x-y at one scale
TEST(PlotView, PlanarInZIsDrawnAtEqualScale) {
    const plot_spec s = curve([](double t) { return std::array<double, 3>{std::cos(t), 0.5 * std::sin(t), 0}; }, 2 * pi);
    const std::string g = script_of(s);
    EXPECT_NE(g.find("seen from above (x-y), in the plane z = 0"), std::string::npos) << g;
    EXPECT_NE(g.find("set size ratio -1"), std::string::npos);
    EXPECT_EQ(label_of(g, "y"), "y");
    // one tick step on both axes (equal scale)
    std::smatch mx, my;
    ASSERT_TRUE(std::regex_search(g, mx, std::regex("set xtics [^,]+, ([^,]+),")));
    ASSERT_TRUE(std::regex_search(g, my, std::regex("set ytics [^,]+, ([^,]+),")));
    EXPECT_EQ(mx[1], my[1]);
}

// a circle in the plane x = z (normal (1, 0, -1)/sqrt 2): projected on the plane of the motion
TEST(PlotView, TiltedPlaneIsProjectedOnIt) {
    const plot_spec s = curve([](double t) {
        return std::array<double, 3>{std::cos(t) / std::sqrt(2.0), std::sin(t), std::cos(t) / std::sqrt(2.0)};
    }, 2 * pi);
    const auto v = symrep::output::choose_view(s, "test");
    EXPECT_EQ(v.kind, "plane");
    EXPECT_NE(v.caption.find("projected on the plane of the motion (normal [0.707, 0, -0.707])"), std::string::npos)
        << v.caption;
    const std::string g = script_of(s);
    EXPECT_NE(label_of(g, "x").find("u (along ["), std::string::npos) << g;
    EXPECT_NE(label_of(g, "y").find("v (along ["), std::string::npos) << g;
    EXPECT_NE(g.find("set size ratio -1"), std::string::npos);  // a circle stays round
}

// a helix is truly 3-D: splot, one scale when the extents are comparable, the view asked for
TEST(PlotView, HelixIsDrawnIn3D) {
    plot_spec s = curve([](double t) { return std::array<double, 3>{std::cos(t), std::sin(t), t / (4 * pi)}; }, 4 * pi);
    EXPECT_EQ(symrep::output::choose_view(s, "test").kind, "3d");
    std::string g = script_of(s);
    EXPECT_NE(g.find("splot"), std::string::npos);
    EXPECT_NE(g.find("set view equal xyz"), std::string::npos);
    EXPECT_NE(g.find("set view 60, 30\n"), std::string::npos);  // elevation 30, azimuth 30
    for (const char* a : {"x", "y", "z"}) {
        EXPECT_EQ(label_of(g, a), a);
        EXPECT_LE(ticks_of(g, a), 6) << a;
    }
    s.view = "top";  // asked for: seen from above however it lies
    s.azimuth = 10;
    EXPECT_EQ(symrep::output::choose_view(s, "test").kind, "xy");
    s.view = "3d", s.elevation = 90;
    g = script_of(s);
    EXPECT_NE(g.find("set view 0, 10\n"), std::string::npos) << g;
    s.view = "side";
    EXPECT_NE(what_of([&] { symrep::output::choose_view(s, "trajectory"); }).find("unknown view 'side'"),
              std::string::npos);
}

// very unequal extents in 3-D: z a thousand times thinner but not flat relative to y
TEST(PlotView, UnequalExtentsGetOwnScalesAndScaleLabels) {
    // x spans 2000, y 20, z 0.004: y and z are not flat relative to each other, but the curve
    // is flat in z relative to x (0.004 < 5% of 2000): seen from above, y on its own scale
    plot_spec s = curve([](double t) { return std::array<double, 3>{1000 * std::cos(t), 10 * std::sin(3 * t), 0.002 * std::sin(t)}; }, 2 * pi);
    std::string g = script_of(s);
    EXPECT_NE(g.find("seen from above (x-y)"), std::string::npos);
    EXPECT_EQ(label_of(g, "y"), "y (not to scale with x)");
    // asked for in 3-D: each axis on its own scale, z scaled by 1e-3 and said so
    s.view = "3d";
    g = script_of(s);
    EXPECT_EQ(g.find("set view equal"), std::string::npos);
    EXPECT_EQ(label_of(g, "z"), "z (x 1e-3)");
    EXPECT_NE(g.find("axes not to scale with each other"), std::string::npos);
    for (const char* a : {"x", "y", "z"}) EXPECT_LE(ticks_of(g, a), 6) << a;
    // values crowded around an offset: z = 2 + 1e-4 sin t
    s = curve([](double t) { return std::array<double, 3>{std::cos(t), std::sin(t), 2 + 1e-4 * std::sin(t)}; }, 2 * pi);
    s.view = "xz";
    g = script_of(s);
    EXPECT_EQ(label_of(g, "y"), "z - 2 (x 1e-6) (not to scale with x)");  // values 2 + 1e-4 sin t
    EXPECT_NE(g.find("seen along y (x-z)"), std::string::npos);
}

// plot() of a tiny function: the value axis scaled, at most six ticks
TEST(PlotView, TinyValuesOfAFunctionAreScaled) {
    plot_spec s;
    s.xlabel = "t", s.ylabel = "value";
    for (int i = 0; i < 100; ++i) s.t.push_back(i * 0.1);
    s.columns.assign(1, {});
    for (double t : s.t) s.columns[0].push_back(1.7e-5 * std::sin(t));
    const std::string g = script_of(s);
    EXPECT_EQ(label_of(g, "y"), "value (x 1e-6)");
    EXPECT_EQ(label_of(g, "x"), "t");
    EXPECT_LE(ticks_of(g, "x"), 6);
    EXPECT_LE(ticks_of(g, "y"), 6);
}

// the language: view, azimuth and elevation as named options, and their messages
TEST(PlotView, OptionsInTheLanguage) {
    script_dir d;
    test_session t;
    ASSERT_EQ(t.run("vector r0"), 0);
    const std::string helix = "trajectory(r0 + [cos(t), sin(t), t/5], [r0 = [0, 0, 0]], t = [0, 6], \"" + d.path.string();
    t.val(helix + "/a.svg\", view = \"top\")");
    EXPECT_NE(slurp(d.path.string() + "/a.svg").find("seen from above (x-y)"), std::string::npos);
    t.val(helix + "/b.svg\", 200, view = \"3d\", azimuth = 40, elevation = 20)");
    EXPECT_NE(slurp(d.path.string() + "/b.svg").find("azimuth 40, elevation 20"), std::string::npos);
    EXPECT_NE(what_of([&] { t.val(helix + "/c.svg\", view = \"diagonal\")"); }).find("unknown view 'diagonal'"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val(helix + "/c.svg\", azimuth = 40)"); }).find("give view = \"3d\""),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val(helix + "/c.svg\", view = \"3d\", view = \"xy\")"); }).find("given twice"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(d.path / "c.svg"));
}
