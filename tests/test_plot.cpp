// tests/test_plot.cpp -- plot, trajectory and hodograph (lang/builtins_plot.cpp,
// output/plot.cpp): the pictures gnuplot writes, and the messages for bad input
// and for a missing gnuplot.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_support.h"
#include "test_util.h"

using symrep::test::slurp;
using symrep::test::test_session;
using symrep::test::what_of;
namespace fs = std::filesystem;

namespace {

/// A fresh directory for this test's pictures (tests run in parallel processes).
std::string fresh_dir(const std::string& name) {
    const fs::path d = fs::path(::testing::TempDir()) / ("symrep_plot_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d.string();
}

bool is_png(const std::string& bytes) { return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0 && bytes.size() > 1000; }
bool is_svg(const std::string& bytes) { return bytes.find("<svg") != std::string::npos && bytes.find("</svg>") != std::string::npos; }

/// Sets an environment variable for the lifetime of the object.
struct scoped_env {
    std::string name;
    explicit scoped_env(const char* n, const std::string& v) : name(n) { setenv(n, v.c_str(), 1); }
    ~scoped_env() { unsetenv(name.c_str()); }
};

}  // namespace

TEST(Plot, ScalarFunctionToPng) {
    const std::string f = fresh_dir("png") + "/sine.png";
    test_session t;
    t.val("plot(sin(w*t), [w = 3], t = [0, 2*pi], \"" + f + "\")");
    const std::string bytes = slurp(f);
    EXPECT_TRUE(is_png(bytes)) << bytes.size() << " bytes";
}

TEST(Plot, ListOfScalarsToSvgWithLegendAndLabels) {
    const std::string f = fresh_dir("svg") + "/two.svg";
    test_session t;
    t.val("plot([x = cos(t), sin(t)^2], [], t = [0, 1], \"" + f + "\", 50, \"my title\")");
    const std::string svg = slurp(f);
    ASSERT_TRUE(is_svg(svg));
    EXPECT_NE(svg.find("my title"), std::string::npos);
    EXPECT_NE(svg.find(">x<"), std::string::npos);           // the named curve's legend
    EXPECT_NE(svg.find("sin(t)^2"), std::string::npos);     // the other legend: the expression
}

// A list of [x, y] pairs among the curves is drawn as points with its legend (identify_points
// against the true f); a point that is not a pair of numbers is refused by name.
TEST(Plot, PointsBesideCurves) {
    const std::string f = fresh_dir("svg") + "/points.svg";
    test_session t;
    t.val("plot([[[0, 0], [1/2, 1/4], [1, 1]], exact = x^2], [], x = [0, 1], \"" + f + "\")");
    const std::string svg = slurp(f);
    ASSERT_TRUE(is_svg(svg));
    EXPECT_NE(svg.find(">points<"), std::string::npos);
    EXPECT_NE(svg.find(">exact<"), std::string::npos);
    EXPECT_THROW(t.val("plot([[[0, 0], [a, 1]]], [], x = [0, 1], \"" + f + "\")"), symrep::error);
    EXPECT_THROW(t.val("plot([[[0, 0, 1]]], [], x = [0, 1], \"" + f + "\")"), symrep::error);
}

TEST(Plot, TrajectoryAndHodographOfVectorFunctions) {
    const std::string d = fresh_dir("vec");
    test_session t;
    ASSERT_EQ(t.run("vector r0, u, e1, e2, e3"), 0);
    const std::string axes = "e1 = [1, 0, 0], e2 = [0, 1, 0], e3 = [0, 0, 1]";
    // a helix: not flat, drawn in 3-D with labelled axes
    t.val("trajectory(r0 + cos(t)*e1 + sin(t)*e2 + t/5*e3, [r0 = [1, 0, 0], " + axes + "], t = [0, 4*pi], \"" + d + "/helix.svg\")");
    const std::string helix = slurp(d + "/helix.svg");
    ASSERT_TRUE(is_svg(helix));
    EXPECT_NE(helix.find(">z<"), std::string::npos);
    // its hodograph [-sin t, cos t, 1/5]: r0 is constant, the curve lies in the plane dz/dt = 0.2
    t.val("hodograph(r0 + cos(t)*e1 + sin(t)*e2 + t/5*e3 + t*u, [r0 = [1, 0, 0], u = [0, 0, 0], " + axes + "], t = [0, 2*pi], \"" + d +
          "/hodo.svg\", 100)");
    const std::string hodo = slurp(d + "/hodo.svg");
    ASSERT_TRUE(is_svg(hodo));
    EXPECT_NE(hodo.find("dx/dt"), std::string::npos);
    EXPECT_NE(hodo.find("dz/dt = 0.2"), std::string::npos);
}

TEST(Plot, NonFiniteSamplesAreLeftOut) {
    const std::string d = fresh_dir("nan");
    test_session t;
    t.val("plot(log(t), [], t = [-1, 1], \"" + d + "/half.svg\", 101)");  // NaN for t <= 0: half a curve
    EXPECT_TRUE(is_svg(slurp(d + "/half.svg")));
    EXPECT_NE(what_of([&] { t.val("plot(log(t), [], t = [-2, -1], \"" + d + "/none.svg\")"); })
                  .find("no sample is a finite number"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(d + "/none.svg"));
    EXPECT_NE(what_of([&] { t.val("plot(t, [], t = [0, 1], \"" + d + "/n.svg\", 1)"); }).find("plot"),
              std::string::npos);  // at least 2 samples
    EXPECT_FALSE(fs::exists(d + "/n.svg"));
}

TEST(Plot, SamePictureTwiceLeavesTheFileAlone) {
    const std::string f = fresh_dir("twice") + "/p.png";
    test_session t;
    const std::string call = "plot(t^2, [], t = [-1, 1], \"" + f + "\", 200)";
    t.val(call);
    const std::string first = slurp(f);
    ASSERT_TRUE(is_png(first));
    const auto old = fs::last_write_time(f) - std::chrono::hours(1);
    fs::last_write_time(f, old);
    t.val(call);
    EXPECT_EQ(slurp(f), first);
    EXPECT_EQ(fs::last_write_time(f), old);  // not rewritten
}

TEST(Plot, FileNamesReachNoShell) {
    const std::string d = fresh_dir("quote");
    test_session t;
    const std::string name = d + "/it's $(touch pwned) `touch pwned2`  ' ; x.svg";
    t.val("plot(t, [], t = [0, 1], \"" + name + "\", 10)");
    EXPECT_TRUE(is_svg(slurp(name)));
    for (const fs::path& dir : {fs::path(d), fs::current_path()}) {
        EXPECT_FALSE(fs::exists(dir / "pwned"));
        EXPECT_FALSE(fs::exists(dir / "pwned2"));
    }
}

TEST(Plot, BadInputsGiveClearMessages) {
    const std::string d = fresh_dir("bad");
    test_session t;
    ASSERT_EQ(t.run("vector r0"), 0);
    // a symbol without a value
    EXPECT_NE(what_of([&] { t.val("plot(sin(a*t), [], t = [0, 1], \"" + d + "/a.png\")"); })
                  .find("symbol 'a' has no value"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("trajectory(r0*t, [], t = [0, 1], \"" + d + "/a.png\")"); }).find("trajectory: no value given for the vector r0"),
              std::string::npos);
    // a value that is not a number
    EXPECT_NE(what_of([&] { t.val("plot(sin(a*t), [a = b], t = [0, 1], \"" + d + "/a.png\")"); }).find("b"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(a*t), [a = [1, 2, 3]], t = [0, 1], \"" + d + "/a.png\")"); })
                  .find("a is a scalar"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [0, c], \"" + d + "/a.png\")"); })
                  .find("does not evaluate to a real number"),
              std::string::npos);
    // a bad extension, a reversed or empty range, a missing file name
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [0, 1], \"" + d + "/a.jpg\")"); }).find("must end in .png or .svg"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(d + "/a.jpg"));
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [1, 0], \"" + d + "/a.png\")"); }).find("reversed"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [1, 1], \"" + d + "/a.png\")"); }).find("reversed"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = 1, \"" + d + "/a.png\")"); }).find("[t0, t1]"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [0, 1], 3)"); }).find("file name"), std::string::npos);
    // a scalar where a vector is needed, and a directory that does not exist
    EXPECT_NE(what_of([&] { t.val("trajectory(sin(t), [], t = [0, 1], \"" + d + "/a.png\")"); }).find("use plot"),
              std::string::npos);
    EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [0, 1], \"" + d + "/no/such/dir/a.png\")"); })
                  .find("cannot write"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(d + "/a.png"));
}

TEST(Plot, MissingGnuplotIsReported) {
    const std::string d = fresh_dir("missing");
    test_session t;
    {
        scoped_env env("SYMREP_GNUPLOT", d + "/no-such-gnuplot");
        const std::string msg = what_of([&] { t.val("plot(sin(t), [], t = [0, 1], \"" + d + "/a.png\")"); });
        EXPECT_NE(msg.find("gnuplot is needed"), std::string::npos) << msg;
        EXPECT_NE(msg.find("gnuplot-nox"), std::string::npos) << msg;
        EXPECT_NE(msg.find("SYMREP_GNUPLOT"), std::string::npos) << msg;
    }
    {
        scoped_env env("SYMREP_GNUPLOT", "false");  // runs, but draws nothing
        EXPECT_NE(what_of([&] { t.val("plot(sin(t), [], t = [0, 1], \"" + d + "/a.png\")"); }).find("failed"),
                  std::string::npos);
    }
    EXPECT_FALSE(fs::exists(d + "/a.png"));
}

TEST(Plot, MissingGnuplotOnThePathFromTheProgram) {
    const std::string d = fresh_dir("path");
    fs::create_directories(d + "/empty");
    std::ofstream(d + "/s.symrep") << "plot(sin(t), [], t = [0, 1], \"out.png\")\n";
    const auto r = symrep::test::run_symrep("'" + d + "/s.symrep'", nullptr);
    EXPECT_EQ(r.status, 0) << r.err;  // with gnuplot: the picture, next to the script
    EXPECT_TRUE(is_png(slurp(d + "/out.png")));
    fs::remove(d + "/out.png");
    // PATH of an empty directory: no gnuplot
    const std::string cmd_prefix = "PATH='" + d + "/empty' ";
    FILE* p = popen((cmd_prefix + "'" + SYMREP_BINARY + "' '" + d + "/s.symrep' 2>&1 </dev/null").c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    const int st = pclose(p);
    EXPECT_NE(st, 0);
    EXPECT_NE(out.find("gnuplot-nox"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(d + "/out.png"));
}
