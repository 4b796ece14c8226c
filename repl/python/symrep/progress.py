"""Progress of the engine's long operations (docs/progress.md): verify, the ODE
integrations, the Magnus integrator of the rotation tensor, the operational matrices
of identification with many blocks report how far they are (C++: core/progress.h).

    import symrep, symrep.progress

    s = symrep.Session()
    with symrep.progress.callback(lambda r: print(r.task, r.done, r.total)):
        s.eval("...")                      # callback(report) at most ~10 times a second

    with symrep.progress.bar():            # a tqdm bar (tqdm.auto: a widget in a notebook)
        s.eval("...")                      # when tqdm is installed and stderr is a terminal

A report has .task ('verify', 'integrate', ...), .done and .total (in the task's units),
.elapsed (seconds since the task started) and .final (its last report). Nested work
reports as a part of the outer task: one task, one monotone done. Nothing is printed
unless asked for, and bar() prints nothing when stderr is not a terminal (and not a
notebook), so scripts and their output files stay byte-identical.
"""

import contextlib
import os
import sys

from ._symrep import ProgressReport, ProgressScope  # noqa: F401

__all__ = ["callback", "bar", "kernel_line", "ProgressReport"]


def callback(fn, interval=0.1):
    """A context manager: while it is open, the engine's long operations on this thread call
    fn(report) (a ProgressReport), at most once per `interval` seconds except for the last
    report of a task. An exception raised by fn stops the statement: symrep.Error
    'progress callback: ...'."""
    return ProgressScope(fn, interval)


def _in_notebook():
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and type(shell).__name__ == "ZMQInteractiveShell"


def _tqdm(file):
    """The tqdm class to use, or None (tqdm not installed, or neither a terminal nor a notebook)."""
    try:
        if _in_notebook():
            from tqdm.auto import tqdm
            return tqdm
        if not (hasattr(file, "isatty") and file.isatty()):
            return None
        from tqdm import tqdm
        return tqdm
    except ImportError:
        return None


class _Bars:
    """The sink of bar(): one tqdm bar per task, shown once the task has run `delay` seconds."""

    def __init__(self, tqdm, file, delay):
        self.tqdm, self.file, self.delay = tqdm, file, delay
        self.current = None

    def __call__(self, r):
        if r.final:
            self.close(r)
            return
        if self.current is None:
            if r.elapsed < self.delay:
                return
            self.current = self.tqdm(total=100, desc=r.task, file=self.file, leave=False,
                                     bar_format="{desc} {percentage:3.0f}%|{bar}| {elapsed}")
        self.current.n = 100.0 * r.done / r.total if r.total > 0 else 0.0
        self.current.refresh()

    def close(self, r=None):
        if self.current is not None:
            if r is not None and r.total > 0:
                self.current.n = 100.0 * r.done / r.total
            self.current.close()
            self.current = None


@contextlib.contextmanager
def bar(delay=1.0, file=None):
    """A context manager: a tqdm progress bar (cleared at the end) for each long operation that
    runs longer than `delay` seconds in the block. Silent (but the block runs the same) when
    tqdm is not installed, or when `file` (default sys.stderr) is not a terminal and this is
    not a notebook."""
    file = sys.stderr if file is None else file
    tqdm = _tqdm(file)
    if tqdm is None:
        yield
        return
    bars = _Bars(tqdm, file, delay)
    try:
        with ProgressScope(bars, 0.1):
            yield
    finally:
        bars.close()


class _KernelLine:
    """The sink of kernel_line(): a display_data with a display_id, updated in place
    (update_display_data), emptied at the task's end."""

    def __init__(self, kernel, delay):
        self.kernel, self.delay = kernel, delay
        self.display_id = None
        self.count = 0

    def _send(self, kind, text):
        self.kernel.send_response(self.kernel.iopub_socket, kind, {
            "data": {"text/plain": text}, "metadata": {}, "transient": {"display_id": self.display_id}})

    def __call__(self, r):
        if r.final:
            self.end()
            return
        if r.elapsed < self.delay:
            return
        text = r.text()
        if self.display_id is None:
            self.count += 1
            self.display_id = "symrep-progress-%d-%d" % (id(self), self.count)
            self._send("display_data", text)
        else:
            self._send("update_display_data", text)

    def end(self):
        if self.display_id is not None:
            self._send("update_display_data", "")
            self.display_id = None


def _default_delay():
    """SYMREP_PROGRESS_DELAY (seconds, as for the symrep program), else 1 second."""
    try:
        d = float(os.environ.get("SYMREP_PROGRESS_DELAY", "1"))
    except ValueError:
        return 1.0
    return d if d >= 0 else 1.0


@contextlib.contextmanager
def kernel_line(kernel, delay=None):
    """For the Jupyter kernel (symrep.kernel): while a cell runs, a long operation (longer than
    `delay` seconds; default SYMREP_PROGRESS_DELAY or 1) shows one output line
    'verify  42% (3.1 s)' that updates in place and is emptied when the operation ends."""
    line = _KernelLine(kernel, _default_delay() if delay is None else delay)
    try:
        with ProgressScope(line, 0.1):
            yield
    finally:
        line.end()
