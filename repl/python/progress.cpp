// symrep/repl/python/progress.cpp -- the progress reports of the engine (core/progress.h)
// in Python: _symrep.ProgressScope(callback, interval) is a context manager that installs
// the callback as this thread's sink while the block runs; callback(report) gets a
// _symrep.ProgressReport (task, done, total, elapsed, final). symrep/progress.py builds the
// user-facing helpers (a callback, a tqdm bar, the kernel's progress line) on it.
//
// The engine calls the sink from the thread that runs it. Session.eval and Session.run keep
// the GIL while the engine runs (module.cpp: GiNaC is not thread safe); the sink takes the
// GIL anyway (gil_scoped_acquire), so that a caller that released it is safe too. A
// callback that raises stops the statement as an error: "progress callback: <its message>".
#include <pybind11/pybind11.h>

#include <chrono>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/progress.h"

namespace py = pybind11;

namespace {

struct py_progress_scope {
    py::object callback;
    double interval;
    std::unique_ptr<symrep::progress_scope> scope;
};

}  // namespace

void bind_progress(py::module_& m) {
    py::class_<symrep::progress_report>(m, "ProgressReport",
                                        "One progress report of a long operation of the engine (core/progress.h).")
        .def_property_readonly("task", [](const symrep::progress_report& r) { return std::string(r.task); },
                               "the operation: 'verify', 'integrate', 'rotation tensor', ...")
        .def_readonly("done", &symrep::progress_report::done, "how much is done, in the task's units")
        .def_readonly("total", &symrep::progress_report::total, "the task's total")
        .def_readonly("elapsed", &symrep::progress_report::elapsed, "seconds since the task started")
        .def_readonly("final", &symrep::progress_report::final, "the task's last report (it ended)")
        .def("text", [](const symrep::progress_report& r) { return symrep::progress_text(r); },
             "the one-line text: 'verify  42% (3.1 s)'")
        .def("__repr__", [](const symrep::progress_report& r) {
            return "ProgressReport(" + symrep::progress_text(r) + (r.final ? ", final)" : ")");
        });

    py::class_<py_progress_scope>(m, "ProgressScope",
                                  "with ProgressScope(callback, interval=0.1): the engine's long operations "
                                  "run in the block call callback(ProgressReport), at most once per interval "
                                  "seconds (the last report of a task always). Per thread.")
        .def(py::init([](py::object callback, double interval) {
                 if (!PyCallable_Check(callback.ptr())) throw py::type_error("ProgressScope: callback must be callable");
                 if (!(interval >= 0)) throw py::value_error("ProgressScope: interval must be >= 0 seconds");
                 return py_progress_scope{std::move(callback), interval, nullptr};
             }),
             py::arg("callback"), py::arg("interval") = 0.1)
        .def("__enter__",
             [](py_progress_scope& self) -> py_progress_scope& {
                 if (self.scope) throw py::value_error("ProgressScope: already entered");
                 py::object callback = self.callback;
                 auto sink = [callback](const symrep::progress_report& r) {
                     py::gil_scoped_acquire gil;
                     try {
                         callback(r);
                     } catch (py::error_already_set& e) {
                         // "ValueError: boom", without the traceback what() may append
                         const std::string type = py::str(e.type().attr("__name__"));
                         const std::string text = py::str(e.value());
                         throw symrep::error("progress callback: " + type + (text.empty() ? "" : ": " + text));
                     }
                 };
                 const auto interval = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                     std::chrono::duration<double>(self.interval));
                 self.scope = std::make_unique<symrep::progress_scope>(sink, interval);
                 return self;
             })
        .def("__exit__", [](py_progress_scope& self, py::args) {
            self.scope.reset();
            return false;
        });
}
