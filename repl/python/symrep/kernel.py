"""The symrep Jupyter kernel (docs/python.md): a wrapper kernel on the Python module.

    python3 -m symrep.kernel install [--user | --sys-prefix | --prefix DIR]   # the kernel spec
    python3 -m symrep.kernel -f CONNECTION_FILE                              # run by Jupyter
    python3 -m symrep.kernel kernel-js > symrep/kernelspec/kernel.js         # regenerate the mode

A cell is run statement by statement as the interactive prompt runs it (a statement ends
at the end of a line where no bracket is open and no backslash continues it: syntax/lexer.h),
up to its first error, and each statement's output is sent as soon as it ran. A result is an
execute_result (Out[n]) as LaTeX (MathJax) with the canonical text as fallback; a picture
written by plot, trajectory or hodograph is shown inline (display_data, PNG or SVG); an
error is an `error` reply named by its Python class, with its line, column, the source line
and a caret. Tab completes builtins, variables and keywords; ?name (or help name) and
Shift-Tab show a builtin's help; the stop button interrupts the running statement
(interrupt_mode signal: SIGINT sets the engine's interruption flag, module.cpp).

The kernel spec is the folder kernelspec/ beside this file (kernel.json, the logos, and
kernel.js: the CodeMirror mode of the classic notebook, its builtin list generated from
Session.builtin_names by `kernel-js`).
"""

import base64
import json
import os
import re
import shutil
import sys
import tempfile
import threading

import symrep
import symrep.progress

try:
    from ipykernel.kernelbase import Kernel
except ImportError:  # only `install` and `kernel-js` work without ipykernel
    Kernel = object

SPEC_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "kernelspec")
CELL = "<cell>"  # the FILE of a cell's errors

_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*$")
_HELP = re.compile(r"^\s*(?:\?\s*|help\s+)([A-Za-z_][A-Za-z0-9_]*)\s*\??\s*$")
# the keywords of the language (syntax/parser.cpp) and its constants (lang/help.cpp's completions)
KEYWORDS = ["vector", "positive"]
ATOMS = ["true", "false", "pi", "I"]


def statements(code):
    """The statements of a cell with the number of their first line, as the engine reads a
    stream (lang::session::run_stream): a statement ends at the end of a line where no
    bracket is open and no backslash continues it. Blank runs are skipped."""
    pending, first = [], 1
    for n, line in enumerate(code.split("\n"), 1):
        if not pending:
            first = n
        pending.append(line)
        text = "\n".join(pending)
        if not symrep.needs_more_input(text):
            if text.strip():
                yield first, text
            pending = []
    if pending and "\n".join(pending).strip():
        yield first, "\n".join(pending)  # an unclosed bracket: the engine reports it


def error_of(event, first_line=1):
    """The exception of a Session.run error event (its place moved to the cell's line numbers
    when the statement began at first_line); an exception event is taken as it is."""
    if isinstance(event, BaseException):
        e = event
        if getattr(e, "file", None) == CELL and getattr(e, "line", None):
            e.line += first_line - 1
        return e
    message, file, line, column, source = event[:5]
    if not line:
        return symrep.Error(message)
    if file == CELL:
        line += first_line - 1
    return symrep.Error(message, file, line, column, source)


def error_content(e):
    """The content of an `error` message: ename the exception's class (symrep.Error or its
    subclass), evalue the message, the traceback the report with its source line and caret."""
    message = getattr(e, "message", None) or str(e)
    lines = e.caret().split("\n") if hasattr(e, "caret") else [str(e)]
    return {"ename": type(e).__name__, "evalue": message, "traceback": lines}


class SymrepKernel(Kernel):
    implementation = "symrep"
    implementation_version = symrep.version
    language_info = {
        "name": "symrep",
        "version": symrep.version,
        "mimetype": "text/x-symrep",
        "file_extension": ".symrep",
        "codemirror_mode": "symrep",  # kernelspec/kernel.js defines it
        "pygments_lexer": "symrep",  # symrep.lexer.SymrepLexer (the pygments.lexers entry point)
    }
    banner = ("symrep %s: exact solutions of dynamical systems by the algebraic methods "
              "(?name for help on a function)" % symrep.version)

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.engine = symrep.Session()  # (self.session is the kernel's messaging session)

    # --- output -------------------------------------------------------------------------

    def _stream(self, name, text):
        if text:
            self.send_response(self.iopub_socket, "stream", {"name": name, "text": text})

    def _display(self, data):
        self.send_response(self.iopub_socket, "display_data", {"data": data, "metadata": {}})

    def _result(self, value):
        data = {"text/plain": value.text}
        latex = value.latex
        if latex:
            data["text/latex"] = "$" + latex + "$"
        self.send_response(self.iopub_socket, "execute_result",
                           {"execution_count": self.execution_count, "data": data, "metadata": {}})

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

    def _flush(self):
        # The messages are sent by ipykernel's IOPub thread; the engine holds the GIL while a
        # statement runs (module.cpp), so without this wait the output of one statement would
        # reach the front end only when the next one ends.
        thread = getattr(self.iopub_socket, "io_thread", None)
        if thread is None or not thread.thread.is_alive() or thread.thread is threading.current_thread():
            return
        done = threading.Event()
        thread.schedule(done.set)
        done.wait(5)

    # --- running a cell ---------------------------------------------------------------

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
        first = 1
        try:
            for first, text in statements(code):
                with symrep.progress.kernel_line(self):  # a long operation shows a progress line (progress.py)
                    failed = self._run(text, first, silent)
                if failed:
                    return failed
                if not silent:
                    self._flush()
        except KeyboardInterrupt:
            # SIGINT between two statements (in the engine it sets the interruption flag)
            e = symrep.Error("interrupted before the statement of line %d; the statements before it ran" % first)
            return self._error(e, silent)
        return self._ok()

    def _run(self, text, first, silent):
        """Runs one statement; the reply content of its error, or None."""
        for kind, x in self.engine.run(text, CELL):
            if kind == "error":
                return self._error(error_of(x, first), silent)
            if silent:
                continue
            if kind == "text":
                self._stream("stdout", x)
            elif kind == "result":
                self._result(x)
            elif kind == "file":
                self._picture(x)
        return None

    def _error(self, e, silent):
        content = error_content(e)
        if not silent:
            self.send_response(self.iopub_socket, "error", content)
        return dict(content, status="error", execution_count=self.execution_count)

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
        builtins = set(self.engine.builtin_names())
        variables = set(self.engine.variables())

        def kind(name):
            if name in variables:
                return "instance"
            if name in builtins:
                return "function"
            return "keyword"

        types = [{"start": start, "end": cursor_pos, "text": n, "type": kind(n)} for n in matches]
        return {"status": "ok", "matches": matches, "cursor_start": start, "cursor_end": cursor_pos,
                "metadata": {"_jupyter_types_experimental": types}}

    def do_inspect(self, code, cursor_pos, detail_level=0, omit_sections=()):
        text = None
        for name in _names_at(code, cursor_pos):
            text = self.engine.help(name)
            if text is not None:
                break
        if text is None:
            return {"status": "ok", "found": False, "data": {}, "metadata": {}}
        return {"status": "ok", "found": True, "data": {"text/plain": text}, "metadata": {}}

    def do_is_complete(self, code):
        # a statement goes on while a bracket or a string is open (syntax/lexer.h)
        if symrep.needs_more_input(code):
            return {"status": "incomplete", "indent": ""}
        return {"status": "complete"}


def _names_at(code, cursor_pos):
    """The names Shift-Tab may mean, nearest first: the word under the cursor, then the
    functions whose call's brackets enclose the cursor (inverse(w|) means inverse)."""
    before, after = code[:cursor_pos], code[cursor_pos:]
    m = _WORD.search(before)
    tail = re.match(r"[A-Za-z0-9_]*", after)
    word = (m.group(0) if m else "") + (tail.group(0) if tail else "")
    if word:
        yield word
    depth = 0
    for i in range(len(before) - 1, -1, -1):
        c = before[i]
        if c in ")]":
            depth += 1
        elif c in "([":
            if depth:
                depth -= 1
            elif c == "(":
                m = _WORD.search(before[:i].rstrip())
                if m:
                    yield m.group(0)
        elif c == "\n" and depth == 0 and not symrep.needs_more_input(before[:i]):
            return  # the statement began at this line


# --- the kernel spec ------------------------------------------------------------------


def in_site_packages():
    """True when this package is installed (pip, cmake --install into the interpreter's
    site-packages), False when it is reached through PYTHONPATH (the build tree)."""
    import site

    here = os.path.realpath(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    dirs = list(site.getsitepackages()) + [site.getusersitepackages()]
    return any(os.path.realpath(d) == here for d in dirs)


def kernel_spec(build_tree=None):
    """The kernel.json of this installation: kernelspec/kernel.json ("python3" is the interpreter
    of the Jupyter server: jupyter_client puts its sys.executable there), and for a package
    reached through PYTHONPATH (the build tree, the tests) this interpreter, the one the
    module was built for, with the folder of this package on the kernel's PYTHONPATH."""
    with open(os.path.join(SPEC_DIR, "kernel.json")) as f:
        spec = json.load(f)
    if build_tree is None:
        build_tree = not in_site_packages()
    if build_tree:
        package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        spec["argv"][0] = sys.executable
        spec["env"] = {"PYTHONPATH": package_parent}
    return spec


def install(user=False, prefix=None, name="symrep", build_tree=None):
    """Installs the kernel spec folder (jupyter_client's KernelSpecManager); returns where."""
    from jupyter_client.kernelspec import KernelSpecManager

    folder = tempfile.mkdtemp()
    try:
        spec = os.path.join(folder, name)
        shutil.copytree(SPEC_DIR, spec, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        with open(os.path.join(spec, "kernel.json"), "w") as f:
            json.dump(kernel_spec(build_tree), f, indent=1)
            f.write("\n")
        return KernelSpecManager().install_kernel_spec(spec, name, user=user, prefix=prefix)
    finally:
        shutil.rmtree(folder)


def kernel_js(builtins=None):
    """kernelspec/kernel.js: the CodeMirror 5 mode "symrep" of the classic notebook (comments,
    strings, numbers, keywords, constants, the builtins, :=, previous results %, %%, %N)."""
    if builtins is None:
        builtins = symrep.Session().builtin_names()
    names = sorted(set(builtins))
    lines = ["    %s," % ", ".join(json.dumps(n) for n in names[i:i + 8]) for i in range(0, len(names), 8)]
    return _KERNEL_JS % {
        "builtins": "\n".join(lines).rstrip(","),
        "keywords": ", ".join(json.dumps(k) for k in KEYWORDS),
        "atoms": ", ".join(json.dumps(k) for k in ATOMS),
    }


_KERNEL_JS = """\
// The symrep kernel's CodeMirror mode for the classic notebook (CodeMirror 5, simple mode).
// Generated by `python3 -m symrep.kernel kernel-js` from the builtin registry; a test
// (tests/python/test_kernel.py) checks that the list below is the module's.
define(["codemirror/lib/codemirror", "codemirror/addon/mode/simple", "base/js/namespace"],
function (CodeMirror, _simple, Jupyter) {
  "use strict";
  var builtins = [
%(builtins)s
  ];
  var keywords = [%(keywords)s];
  var atoms = [%(atoms)s];
  function words(list) {
    return new RegExp("(?:" + list.slice().sort(function (a, b) { return b.length - a.length; }).join("|") +
                      ")(?![A-Za-z0-9_'])");
  }
  CodeMirror.defineSimpleMode("symrep", {
    start: [
      {regex: /#.*/, token: "comment"},
      {regex: /"(?:[^\\\\"]|\\\\.)*"?/, token: "string"},
      {regex: /(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?/, token: "number"},
      {regex: words(keywords), token: "keyword"},
      {regex: words(atoms), token: "atom"},
      {regex: words(builtins), token: "builtin"},
      {regex: /%%%%|%%\\d*/, token: "variable-2"},
      {regex: /:=|==|!=|<=|>=|[-+*\\/^=<>|.\\u00d7\\u00b7\\u22c5]/, token: "operator"},
      {regex: /[A-Za-z_][A-Za-z0-9_]*'*/, token: "variable"}
    ],
    meta: {lineComment: "#"}
  });
  CodeMirror.defineMIME("text/x-symrep", "symrep");
  if (CodeMirror.modeInfo) {
    CodeMirror.modeInfo.push({name: "symrep", mime: "text/x-symrep", mode: "symrep", ext: ["symrep"]});
  }
  return {
    onload: function () {
      // the mode may have been asked for before this file was loaded: set it on every cell
      var nb = Jupyter && Jupyter.notebook;
      if (nb && nb._dispatch_mode) {
        nb._dispatch_mode("symrep", "symrep");
      }
    }
  };
});
"""


def main(argv):
    if argv[:1] == ["kernel-js"]:
        sys.stdout.write(kernel_js())
        return 0
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
