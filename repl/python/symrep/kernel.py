"""The symrep Jupyter kernel (docs/python.md): a wrapper kernel on the Python module.

    python3 -m symrep.kernel install [--user | --sys-prefix | --prefix DIR]   # the kernel spec
    python3 -m symrep.kernel -f CONNECTION_FILE                              # run by Jupyter

A cell is run statement by statement as the interactive prompt runs it, up to its first
error. Each result is shown as LaTeX (MathJax) with the canonical text as fallback; a
picture written by plot, trajectory or hodograph is shown inline (PNG or SVG); an error
shows its line, column, the source line and a caret. Tab completes builtins, variables and
keywords; ?name (or help name) and Shift-Tab show a builtin's help; the stop button
interrupts the running statement (SIGINT: the engine's interruption flag).
"""

import base64
import json
import os
import re
import shutil
import sys
import tempfile

import symrep
import symrep.progress

try:
    from ipykernel.kernelbase import Kernel
except ImportError:  # only `install` works without ipykernel
    Kernel = object

_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*$")
_HELP = re.compile(r"^\s*(?:\?\s*|help\s+)([A-Za-z_][A-Za-z0-9_]*)\s*\??\s*$")


class SymrepKernel(Kernel):
    implementation = "symrep"
    implementation_version = symrep.version
    language_info = {
        "name": "symrep",
        "version": symrep.version,
        "mimetype": "text/x-symrep",
        "file_extension": ".symrep",
        "codemirror_mode": "text/x-symrep",
        "pygments_lexer": "text",
    }
    banner = ("symrep %s: exact solutions of dynamical systems by the algebraic methods "
              "(?name for help on a function)" % symrep.version)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.engine = symrep.Session()  # (self.session is the kernel's messaging session)

    # --- running a cell ---------------------------------------------------------------

    def _stream(self, name, text):
        if text:
            self.send_response(self.iopub_socket, "stream", {"name": name, "text": text})

    def _display(self, data):
        self.send_response(self.iopub_socket, "display_data", {"data": data, "metadata": {}})

    def _picture(self, path):
        ext = os.path.splitext(path)[1].lower()
        try:
            with open(path, "rb") as f:
                raw = f.read()
        except OSError as e:
            self._stream("stderr", "cannot show %s: %s\n" % (path, e))
            return
        if ext == ".svg":
            self._display({"image/svg+xml": raw.decode("utf-8"), "text/plain": path})
        elif ext == ".png":
            self._display({"image/png": base64.b64encode(raw).decode("ascii"), "text/plain": path})

    def do_execute(self, code, silent, store_history=True, user_expressions=None, allow_stdin=False):
        m = _HELP.match(code)
        if m:
            name = m.group(1)
            text = self.engine.help(name)
            if not silent:
                if text is None:
                    self._stream("stderr", self.engine.unknown_builtin_message(name) + "\n")
                else:
                    self._stream("stdout", text)
            return self._ok()
        with symrep.progress.kernel_line(self):  # a long operation shows a progress line (progress.py)
            events = self.engine.run(code, "<cell>")
        for kind, x in events:
            if silent and kind != "error":
                continue
            if kind == "text":
                self._stream("stdout", x)
            elif kind == "result":
                data = {"text/plain": x.text}
                latex = x.latex
                if latex:
                    data["text/latex"] = "$" + latex + "$"
                self._display(data)
            elif kind == "file":
                self._picture(x)
            elif kind == "error":
                message, file, line, column, source = x
                err = symrep.Error(message, file, line, column, source)
                lines = err.caret().split("\n")
                content = {"ename": "symrep.Error", "evalue": message, "traceback": lines}
                self.send_response(self.iopub_socket, "error", content)
                return dict(content, status="error", execution_count=self.execution_count)
        return self._ok()

    def _ok(self):
        return {"status": "ok", "execution_count": self.execution_count, "payload": [], "user_expressions": {}}

    # --- completion and help -------------------------------------------------------------

    def do_complete(self, code, cursor_pos):
        before = code[:cursor_pos]
        m = _WORD.search(before)
        prefix = m.group(0) if m else ""
        start = cursor_pos - len(prefix)
        at_line_start = before[:start].rsplit("\n", 1)[-1].strip() == ""
        matches = self.engine.completions(prefix, at_line_start) if prefix or at_line_start else []
        return {"status": "ok", "matches": matches, "cursor_start": start, "cursor_end": cursor_pos, "metadata": {}}

    def do_inspect(self, code, cursor_pos, detail_level=0, omit_sections=()):
        m = _WORD.search(code[:cursor_pos])
        tail = re.match(r"[A-Za-z0-9_]*", code[cursor_pos:])
        name = (m.group(0) if m else "") + (tail.group(0) if tail else "")
        text = self.engine.help(name) if name else None
        if text is None:
            return {"status": "ok", "found": False, "data": {}, "metadata": {}}
        return {"status": "ok", "found": True, "data": {"text/plain": text}, "metadata": {}}

    def do_is_complete(self, code):
        # a statement goes on while a bracket or a string is open (syntax/lexer.h)
        if symrep.needs_more_input(code):
            return {"status": "incomplete", "indent": ""}
        return {"status": "complete"}


def kernel_spec(python=None):
    """The kernel.json of this installation: this interpreter, this package on its path."""
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return {
        "argv": [python or sys.executable, "-Xfrozen_modules=off", "-m", "symrep.kernel", "-f", "{connection_file}"],
        "display_name": "symrep",
        "language": "symrep",
        "interrupt_mode": "signal",
        "env": {"PYTHONPATH": package_parent},
    }


def install(user=False, prefix=None, name="symrep"):
    """Installs the kernel spec (jupyter_client's KernelSpecManager); returns its folder."""
    from jupyter_client.kernelspec import KernelSpecManager

    folder = tempfile.mkdtemp()
    try:
        with open(os.path.join(folder, "kernel.json"), "w") as f:
            json.dump(kernel_spec(), f, indent=1)
        return KernelSpecManager().install_kernel_spec(folder, name, user=user, prefix=prefix)
    finally:
        shutil.rmtree(folder)


def main(argv):
    if argv[:1] == ["install"]:
        import argparse

        p = argparse.ArgumentParser(prog="python3 -m symrep.kernel install",
                                    description="Install the symrep Jupyter kernel spec.")
        g = p.add_mutually_exclusive_group()
        g.add_argument("--user", action="store_true", help="in the user's Jupyter folder")
        g.add_argument("--sys-prefix", action="store_true", help="in sys.prefix (a virtual environment)")
        g.add_argument("--prefix", help="under PREFIX/share/jupyter/kernels")
        a = p.parse_args(argv[1:])
        prefix = sys.prefix if a.sys_prefix else a.prefix
        print("installed the symrep kernel in", install(user=a.user, prefix=prefix))
        return 0
    from ipykernel.kernelapp import IPKernelApp

    IPKernelApp.launch_instance(kernel_class=SymrepKernel)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
