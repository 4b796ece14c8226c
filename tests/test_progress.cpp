// tests/test_progress.cpp -- progress reports (core/progress.h): the hooked operations
// report a monotone done that reaches total, nothing without a sink, the rate limit, a
// throwing sink and an interruption; the program's progress line only on a terminal.
#include <gtest/gtest.h>

#include "test_util.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/interrupt.h"
#include "core/progress.h"
#include "identification/identify.h"
#include "identification/operational_matrix.h"
#include "numeric/integrate.h"
#include "numeric/rotation_tensor.h"
#include "numeric/verify.h"

using namespace symrep;

namespace {

struct recorder {
    std::vector<progress_report> seen;
    std::vector<std::string> names;  // the reports' task views live only during the call
    progress_sink sink() {
        return [this](const progress_report& r) {
            seen.push_back(r);
            names.emplace_back(r.task);
        };
    }
};

/// Every report names `task`, done increases, and exactly the last one is final
/// with done == total.
::testing::AssertionResult complete_and_monotone(const recorder& rec, const std::string& task) {
    if (rec.seen.empty()) return ::testing::AssertionFailure() << "no report";
    for (std::size_t k = 0; k < rec.seen.size(); ++k) {
        const progress_report& r = rec.seen[k];
        if (rec.names[k] != task) return ::testing::AssertionFailure() << "report " << k << " of '" << rec.names[k] << "'";
        if (!(r.done >= 0 && r.done <= r.total)) return ::testing::AssertionFailure() << "done " << r.done << " of " << r.total;
        // strictly increasing, but the final report may repeat the last done (an inner task
        // that completed its parent's last part)
        if (k > 0 && !(r.done > rec.seen[k - 1].done || (r.final && r.done == rec.seen[k - 1].done)))
            return ::testing::AssertionFailure() << "done " << r.done << " after " << rec.seen[k - 1].done;
        if (r.final != (k + 1 == rec.seen.size())) return ::testing::AssertionFailure() << "final at report " << k;
    }
    const progress_report& last = rec.seen.back();
    if (last.done != last.total) return ::testing::AssertionFailure() << "ends at " << last.done << " of " << last.total;
    return ::testing::AssertionSuccess() << rec.seen.size() << " reports";
}

// y' = -y, y(0) = 1: the closed form exp(-t)
num::verify_result small_verify() {
    GiNaC::symbol t("t"), y("y");
    return num::verify({GiNaC::exp(-t)}, t, {-y}, {y}, {}, {}, 0.0, 5.0, 50);
}

}  // namespace

TEST(Progress, VerifyReportsOneMonotoneTask) {
    recorder rec;
    {
        progress_scope scope(rec.sink(), std::chrono::steady_clock::duration::zero());
        const num::verify_result v = small_verify();
        EXPECT_LT(v.max_relative_difference, 1e-8);
    }
    // the closed form's rows and the integration inside move verify's one bar
    EXPECT_TRUE(complete_and_monotone(rec, "verify"));
    EXPECT_GT(rec.seen.size(), 10u);
}

TEST(Progress, IntegrateAndMagnusAndIdentification) {
    const auto zero = std::chrono::steady_clock::duration::zero();
    {
        recorder rec;
        progress_scope scope(rec.sink(), zero);
        const num::rhs_function f = [](double, const double* y, double* dy) { dy[0] = y[1], dy[1] = -y[0]; };
        num::integrate(f, 0.0, {1.0, 0.0}, {1.0, 2.0, 10.0});
        EXPECT_TRUE(complete_and_monotone(rec, "integrate"));
        EXPECT_EQ(rec.seen.back().total, 10.0);  // in time units of the span
    }
    {
        recorder rec;
        progress_scope scope(rec.sink(), zero);
        const num::angular_velocity w = [](double t) { return Eigen::Vector3d(std::cos(t), std::sin(t), 1.0); };
        num::rotation_tensor(w, {1.0, 20.0});
        EXPECT_TRUE(complete_and_monotone(rec, "rotation tensor"));
    }
    {
        recorder rec;
        progress_scope scope(rec.sink(), zero);
        identification::simulate_system([](double x) { return 4 * x; }, [](double t) { return std::sin(t); }, {1.0}, 4,
                                        2.0);
        EXPECT_TRUE(complete_and_monotone(rec, "simulate_system"));
    }
    {
        recorder rec;
        progress_scope scope(rec.sink(), zero);
        identification::operational_matrix_power_exact(3, 2);
        EXPECT_TRUE(complete_and_monotone(rec, "operational matrix"));
        EXPECT_EQ(rec.seen.size(), 8u);  // one per row of the 2^3 x 2^3 matrix
    }
}

TEST(Progress, NoSinkNoCalls) {
    recorder rec;
    { progress_scope scope(rec.sink()); }  // installed and gone again
    EXPECT_FALSE(progress_wanted());
    small_verify();
    progress_task task("inert", 10);
    task.report(5);
    task.finish();
    report_progress("free", 1, 1);
    EXPECT_TRUE(rec.seen.empty());
    // a scope with an empty sink installs nothing
    progress_scope empty{progress_sink{}};
    EXPECT_FALSE(progress_wanted());
}

TEST(Progress, RateLimited) {
    recorder rec;
    progress_scope scope(rec.sink(), std::chrono::milliseconds(40));
    const auto start = std::chrono::steady_clock::now();
    {
        progress_task task("loop", 1e6);
        double k = 0;
        while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(200)) task.report(++k);
        task.finish();
    }
    // 200 ms at one call per 40 ms: about 5, plus the final one (always delivered)
    EXPECT_GE(rec.seen.size(), 2u);
    EXPECT_LE(rec.seen.size(), 8u);
    EXPECT_TRUE(rec.seen.back().final);
    EXPECT_EQ(rec.seen.back().done, 1e6);
    // many short tasks back to back: still at most one call per interval (+ their finals)
    rec.seen.clear();
    for (int i = 0; i < 1000; ++i) {
        progress_task task("short", 2);
        task.report(1);
        task.finish();
    }
    EXPECT_LE(rec.seen.size(), 4u);
}

TEST(Progress, NestedTasksReportThroughTheOuterOne) {
    recorder rec;
    progress_scope scope(rec.sink(), std::chrono::steady_clock::duration::zero());
    {
        progress_task outer("outer", 4);
        for (int k = 0; k < 4; ++k) {
            progress_task inner("inner", 10);  // the outer's unit [k, k + 1]
            for (int j = 1; j <= 10; ++j) inner.report(j);
            outer.report(k + 1);
        }
    }
    EXPECT_TRUE(complete_and_monotone(rec, "outer"));
    EXPECT_EQ(rec.seen.size(), 41u);  // 40 from the inner tasks, the outer's final
    EXPECT_DOUBLE_EQ(rec.seen[4].done, 0.5);
}

TEST(Progress, ThrowingSinkStopsTheWorkOnce) {
    int calls = 0;
    {
        progress_scope scope([&](const progress_report&) {
            ++calls;
            throw std::runtime_error("sink failed");
        }, std::chrono::steady_clock::duration::zero());
        EXPECT_EQ(test::what_of([] { small_verify(); }), "sink failed");
        EXPECT_EQ(calls, 1);  // not called again for that task (nor by its unwinding)
        // the next task reports again
        EXPECT_EQ(test::what_of([] { progress_task t("next", 1); t.finish(); }), "sink failed");
        EXPECT_EQ(calls, 2);
    }
    EXPECT_FALSE(progress_wanted());
}

TEST(Progress, InterruptionFromTheSinkEndsTheTaskWithAFinalReport) {
    recorder rec;
    {
        progress_scope scope(
            [&](const progress_report& r) {
                rec.seen.push_back(r);
                rec.names.emplace_back(r.task);
                if (r.done > 1) interrupt_flag() = true;  // the user presses Ctrl-C
            },
            std::chrono::steady_clock::duration::zero());
        const num::rhs_function f = [](double, const double* y, double* dy) { dy[0] = -y[0]; };
        EXPECT_EQ(test::what_of([&] { num::integrate(f, 0.0, {1.0}, {1.0, 2.0, 3.0, 4.0, 5.0}); }), "interrupted");
        interrupt_flag() = false;
    }
    ASSERT_GE(rec.seen.size(), 2u);
    EXPECT_TRUE(rec.seen.back().final);  // the consumer can close its line
    EXPECT_LT(rec.seen.back().done, rec.seen.back().total);
    EXPECT_EQ(std::count_if(rec.seen.begin(), rec.seen.end(), [](const progress_report& r) { return r.final; }), 1);
}

TEST(Progress, TextAndTerminalSink) {
    EXPECT_EQ(progress_text({"verify", 42.9, 100, 3.14, false}), "verify  42% (3.1 s)");
    EXPECT_EQ(progress_text({"integrate", 1, 1, 0, true}), "integrate 100% (0.0 s)");
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    {
        const progress_sink quiet = terminal_progress_sink(fds[1], 1.0);
        quiet({"verify", 1, 2, 0.5, false});  // before the delay: nothing
        quiet({"verify", 2, 2, 0.6, true});   // nothing drawn, nothing to erase
        const progress_sink line = terminal_progress_sink(fds[1], 0.0);
        line({"verify", 1, 2, 0.5, false});
        line({"verify", 2, 2, 0.6, true});
    }
    close(fds[1]);
    std::string got;
    char buf[256];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) got.append(buf, std::size_t(n));
    close(fds[0]);
    EXPECT_EQ(got, "\rverify  50% (0.5 s)\033[K\r\033[K");
}

namespace {
// The program on a script whose first statement integrates (simulate_system over 2^12
// blocks, ~50 ms) and whose output is deterministic (verify's is not: it prints timings).
std::string long_script() {
    const std::string path = ::testing::TempDir() + "/symrep_progress_" + std::to_string(getpid()) + ".symrep";
    std::ofstream(path) << "q := simulate_system(4*x + x^3, x, 10*sin(2*pi*t), t, 12)\n"
                           "[length(q[0]), q[0][4095]]\n";
    return path;
}
}  // namespace

// With standard error not a terminal the output is the same bytes whatever the progress
// settings: SYMREP_PROGRESS_DELAY=0 would show the line at once on a terminal.
TEST(CliProgress, QuietWhenNotATerminal) {
    const std::string script = "'" + long_script() + "'";
    unsetenv("SYMREP_PROGRESS_DELAY");
    const test::cli_result plain = test::run_symrep(script);
    setenv("SYMREP_PROGRESS_DELAY", "0", 1);
    const test::cli_result to_file = test::run_symrep(script);
    const test::cli_result to_pipe = test::run_symrep(script, nullptr, "", true);  // 2>&1 into the pipe
    unsetenv("SYMREP_PROGRESS_DELAY");
    EXPECT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(plain.out.rfind("[4096, ", 0), 0u) << plain.out;
    EXPECT_EQ(plain.err, "");
    EXPECT_EQ(to_file.out, plain.out);
    EXPECT_EQ(to_file.err, plain.err);
    EXPECT_EQ(to_pipe.out, plain.out);
}

// On a terminal (script(1) gives the program a pseudo-terminal) the line appears and is erased.
TEST(CliProgress, LineOnATerminal) {
    if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) here";
    const std::string command = "'" + std::string(SYMREP_BINARY) + "' '" + long_script() + "'";
    setenv("SYMREP_PROGRESS_DELAY", "0", 1);
    FILE* p = popen(("script -qec \"" + command + "\" /dev/null </dev/null").c_str(), "r");
    unsetenv("SYMREP_PROGRESS_DELAY");
    ASSERT_NE(p, nullptr);
    std::string got;
    char buf[4096];
    for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) got.append(buf, n);
    EXPECT_EQ(pclose(p), 0) << got;
    EXPECT_NE(got.find("\rsimulate_system "), std::string::npos) << got;
    EXPECT_NE(got.find("%"), std::string::npos) << got;
    EXPECT_NE(got.find("\r\033[K"), std::string::npos) << got;
}
