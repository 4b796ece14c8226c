// symrep/core/progress.h -- feedback on long work: progress reports to a sink.
//
// The long operations of the engine (verify, the Magnus integrator of the
// rotation tensor, the ODE integrations, the Walsh operational matrices of
// identification with many blocks) say how far they are. A front end that
// wants to show it installs a sink for the calling thread:
//
//     symrep::progress_scope scope([](const symrep::progress_report& r) {
//         std::fprintf(stderr, "\r%s %3.0f%%", std::string(r.task).c_str(), 100 * r.done / r.total);
//     });
//     ... run the work ...
//
// and the engine's loops report through a progress_task:
//
//     progress_task task("verify", n);      // inert (a flag test) when no sink is installed
//     for (k = 0; k < n; ++k) { ...; task.report(k + 1); }
//
// Tasks nest: a task started while another runs on the same thread reports as
// a part of its parent (by default the parent's next unit, [done, done + 1]),
// so the sink sees one task with one monotone `done` (an integration inside
// verify moves verify's bar; it does not start a bar of its own). The sink is
// called
//   * at most once per interval (100 ms by default: ~10 calls a second), except
//     for the last report of a task, which is always delivered when an earlier
//     report of the task was (so that a consumer that drew a bar can close it);
//   * with `done` strictly increasing within a task (the final report may repeat
//     the last value), reaching `total` when the task completes (final == true); a task cut short by an exception (an
//     interruption, a time limit, an error) ends with one report final == true
//     and done < total;
//   * never from inside itself (reports made while the sink runs are dropped),
//     and never when no sink is installed: the cost is then one thread-local
//     load per report.
// A sink that throws stops the work with its exception, as an interruption
// does (core/interrupt.h); the sink is not called again for that task. Sinks
// are per thread, as the interruption depth (core/interrupt.h) is.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace symrep {

/// One report: the task's name (a string literal of the engine, e.g.
/// "verify"), how much is done of its total (0 <= done <= total, in the
/// task's own units), the seconds since the task started, and whether it is
/// the task's last report.
struct progress_report {
    std::string_view task;
    double done = 0;
    double total = 0;
    double elapsed = 0;
    bool final = false;
};

using progress_sink = std::function<void(const progress_report&)>;

class progress_task;

/// Installs a sink for this thread while it lives (the previous one, if any,
/// is restored at its end). interval: the least time between two calls of the
/// sink (0: every report; tests use it).
class progress_scope {
public:
    explicit progress_scope(progress_sink sink,
                            std::chrono::steady_clock::duration interval = std::chrono::milliseconds(100));
    ~progress_scope();
    progress_scope(const progress_scope&) = delete;
    progress_scope& operator=(const progress_scope&) = delete;

    /// Used by progress_task: delivers r unless the interval forbids it
    /// (always when force). True when the sink was called.
    bool deliver(const progress_report& r, bool force);

private:
    progress_sink sink_;
    std::chrono::steady_clock::duration interval_;
    std::chrono::steady_clock::time_point last_{};
    bool has_last_ = false;
    bool in_sink_ = false;
    progress_scope* previous_;
};

namespace detail {
/// The sink of this thread (null: none; every report is then a no-op).
inline progress_scope*& current_progress_scope() {
    thread_local progress_scope* scope = nullptr;
    return scope;
}
/// The innermost running (not inert) progress_task of this thread.
inline progress_task*& current_progress_task() {
    thread_local progress_task* task = nullptr;
    return task;
}
}  // namespace detail

/// True while a sink is installed on this thread.
inline bool progress_wanted() { return detail::current_progress_scope() != nullptr; }

/// A long operation of `total` units (total > 0) that reports how far it is.
/// Made when no sink is installed, it stays inert. name must outlive the task
/// (a string literal); the task ends before the progress_scope it was made
/// under (both are scoped objects of one thread).
class progress_task {
public:
    progress_task(std::string_view name, double total);
    ~progress_task();
    progress_task(const progress_task&) = delete;
    progress_task& operator=(const progress_task&) = delete;

    /// done units of total are done (values below an earlier report are ignored).
    void report(double done) {
        if (scope_) report_slow(done);
    }
    /// The task is complete: report(total).
    void finish() { report(total_); }
    /// The part [from, to] of this task's units that the next nested tasks
    /// cover (by default [done, done + 1], clipped to the total).
    void nest(double from, double to);

private:
    void report_slow(double done);
    double position_of_child(double fraction) const;
    void deliver_root(double value, bool final);

    progress_scope* scope_ = nullptr;  // null: inert
    progress_task* parent_ = nullptr;
    std::string_view name_;
    double total_ = 1;
    double done_ = 0;
    double nest_from_ = -1, nest_to_ = -1;  // negative: the default part
    // the root's own state (a nested task reports through its root)
    std::chrono::steady_clock::time_point start_{};
    double delivered_ = -1;  // the last done given to the sink (-1: none yet)
    bool closed_ = false;    // the final report went out
};

/// A one-off report of a task without a frame; inside a running progress_task
/// it reports as that task's current nested part (the closed form's rows inside
/// verify), outside one it goes to the sink under the rate limit, its final
/// report too (a loop of its own is better a progress_task). Cheap when no sink
/// is installed.
void report_progress(std::string_view task, double done, double total);

/// The one-line text of a report: "verify  42% (3.1 s)" (the percentage
/// rounded down, so that 100% means done).
std::string progress_text(const progress_report& r);

/// A sink that keeps one line on the terminal file descriptor fd up to date
/// ("\r" + progress_text + erase to the end of the line), from the first report
/// of a task that has run `delay` seconds, and erases the line at the task's
/// final report. For terminals only: the caller installs it when isatty(fd),
/// so that output to files and pipes stays byte-identical.
progress_sink terminal_progress_sink(int fd, double delay = 1.0);

/// A scope with terminal_progress_sink(fd, delay) when fd is a terminal; null otherwise.
std::unique_ptr<progress_scope> progress_on_terminal(int fd, double delay = 1.0);

}  // namespace symrep
