// symrep/core/progress.cpp -- see progress.h.
#include "symrep/core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>

namespace symrep {

progress_scope::progress_scope(progress_sink sink, std::chrono::steady_clock::duration interval)
    : sink_(std::move(sink)), interval_(interval), previous_(detail::current_progress_scope()) {
    if (sink_) detail::current_progress_scope() = this;
}

progress_scope::~progress_scope() {
    if (detail::current_progress_scope() == this) detail::current_progress_scope() = previous_;
}

bool progress_scope::deliver(const progress_report& r, bool force) {
    if (in_sink_) return false;  // a report made by the sink's own work
    const auto now = std::chrono::steady_clock::now();
    if (!force && has_last_ && now - last_ < interval_) return false;
    last_ = now;
    has_last_ = true;
    in_sink_ = true;
    try {
        sink_(r);
    } catch (...) {
        in_sink_ = false;
        throw;
    }
    in_sink_ = false;
    return true;
}

progress_task::progress_task(std::string_view name, double total) {
    progress_scope* scope = detail::current_progress_scope();
    if (!scope) return;
    scope_ = scope;
    name_ = name;
    total_ = total > 0 ? total : 1;
    parent_ = detail::current_progress_task();
    detail::current_progress_task() = this;
    if (!parent_) start_ = std::chrono::steady_clock::now();
}

progress_task::~progress_task() {
    if (!scope_) return;
    detail::current_progress_task() = parent_;
    // A root cut short (an exception, or no finish()) closes what the sink drew.
    if (!parent_ && delivered_ >= 0 && !closed_ && detail::current_progress_scope() == scope_) {
        try {
            closed_ = true;
            scope_->deliver({name_, delivered_, total_,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(), true},
                            true);
        } catch (...) {
            // a sink that throws while the task unwinds: nothing more to tell it
        }
    }
}

void progress_task::nest(double from, double to) {
    if (!scope_) return;
    nest_from_ = std::clamp(from, 0.0, total_);
    nest_to_ = std::clamp(to, nest_from_, total_);
}

double progress_task::position_of_child(double fraction) const {
    double from = nest_from_, to = nest_to_;
    if (from < 0) {
        from = done_;
        to = std::min(done_ + 1, total_);
    }
    return from + std::clamp(fraction, 0.0, 1.0) * (to - from);
}

void progress_task::report_slow(double done) {
    done = std::clamp(done, 0.0, total_);
    if (done < done_) return;
    done_ = done;
    if (nest_from_ >= 0 && done_ >= nest_to_) nest_from_ = nest_to_ = -1;  // the nested part is past
    // up to the root: each parent places this fraction in its nested part
    double value = done_;
    double total = total_;
    progress_task* root = this;
    for (progress_task* p = parent_; p; p = p->parent_) {
        value = p->position_of_child(value / total);
        total = p->total_;
        root = p;
    }
    root->deliver_root(value, parent_ == nullptr && done_ >= total_);
}

void progress_task::deliver_root(double value, bool final) {
    if (closed_ || value < delivered_ || (value == delivered_ && !final)) return;
    const bool force = final && delivered_ >= 0;  // close the bar the sink drew
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    bool delivered = false;
    try {
        delivered = scope_->deliver({name_, value, total_, elapsed, final}, force);
    } catch (...) {
        closed_ = true;  // a sink that threw is not called again for this task
        throw;
    }
    if (delivered) {
        delivered_ = value;
        closed_ = final;
    }
}

void report_progress(std::string_view task, double done, double total) {
    progress_scope* scope = detail::current_progress_scope();
    if (!scope || !(total > 0)) return;
    done = std::clamp(done, 0.0, total);
    if (detail::current_progress_task()) {
        progress_task part(task, total);
        part.report(done);
        return;
    }
    scope->deliver({task, done, total, 0.0, done >= total}, false);
}

std::string progress_text(const progress_report& r) {
    const double fraction = r.total > 0 ? std::clamp(r.done / r.total, 0.0, 1.0) : 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, " %3d%% (%.1f s)", static_cast<int>(std::floor(100 * fraction + 1e-9)),
                  r.elapsed);
    return std::string(r.task) + buffer;
}

progress_sink terminal_progress_sink(int fd, double delay) {
    auto shown = std::make_shared<bool>(false);
    return [fd, delay, shown](const progress_report& r) {
        std::string line;
        if (r.final) {
            if (!*shown) return;
            *shown = false;
            line = "\r\033[K";
        } else {
            if (r.elapsed < delay) return;
            *shown = true;
            line = "\r" + progress_text(r) + "\033[K";
        }
        // one write(): the line is never split by other output of this process
        for (std::size_t at = 0; at < line.size();) {
            const ssize_t w = ::write(fd, line.data() + at, line.size() - at);
            if (w <= 0) return;  // a terminal that went away: progress is not worth an error
            at += static_cast<std::size_t>(w);
        }
    };
}

std::unique_ptr<progress_scope> progress_on_terminal(int fd, double delay) {
    if (!::isatty(fd)) return nullptr;
    return std::make_unique<progress_scope>(terminal_progress_sink(fd, delay));
}

}  // namespace symrep
