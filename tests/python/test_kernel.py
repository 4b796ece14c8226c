"""tests/python/test_kernel.py -- the symrep Jupyter kernel (symrep/kernel.py) and its spec folder
(symrep/kernelspec/): the main job as a notebook executed by nbconvert, and the protocol through
jupyter_client (results as execute_result with Out[n], output streamed statement by statement,
errors with their class and a caret, completion, help, interruption). The kernel spec is
installed into a temporary JUPYTER_PATH by `symrep.kernel.install`, as
`python3 -m symrep.kernel install --prefix DIR` installs it."""
import json
import os
import shutil
import sys
import time

import nbformat
import pytest
import symrep
import symrep.kernel
from conftest import SOURCE_DIR


def install_spec(root):
    """The build tree's kernel spec under root (JUPYTER_PATH=root/share/jupyter); the folder."""
    return symrep.kernel.install(prefix=str(root), build_tree=True)


@pytest.fixture(scope="module")
def jupyter_env(tmp_path_factory):
    root = tmp_path_factory.mktemp("jupyter")
    install_spec(root)
    saved = {k: os.environ.get(k) for k in ("JUPYTER_PATH", "JUPYTER_RUNTIME_DIR", "JUPYTER_DATA_DIR", "IPYTHONDIR")}
    os.environ["JUPYTER_PATH"] = str(root / "share" / "jupyter")
    os.environ["JUPYTER_RUNTIME_DIR"] = str(root / "runtime")
    os.environ["JUPYTER_DATA_DIR"] = str(root / "data")
    os.environ["IPYTHONDIR"] = str(root / "ipython")
    yield root
    for k, v in saved.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


# --- the kernel spec folder ---------------------------------------------------------------


def test_the_kernel_spec_folder(tmp_path):
    spec_dir = symrep.kernel.SPEC_DIR
    assert sorted(os.listdir(spec_dir)) == ["kernel.js", "kernel.json", "logo-32x32.png", "logo-64x64.png"]
    with open(os.path.join(spec_dir, "kernel.json")) as f:
        spec = json.load(f)
    # the installed spec: no path of this machine in it ("python3": jupyter_client puts the
    # server's interpreter there)
    assert spec == {"argv": ["python3", "-m", "symrep.kernel", "-f", "{connection_file}"],
                    "display_name": "symrep", "language": "symrep", "interrupt_mode": "signal"}
    for size in (32, 64):
        with open(os.path.join(spec_dir, "logo-%dx%d.png" % (size, size)), "rb") as f:
            head = f.read(24)
        assert head[:8] == b"\x89PNG\r\n\x1a\n"
        assert int.from_bytes(head[16:20], "big") == size and int.from_bytes(head[20:24], "big") == size
    # the CodeMirror mode's builtin list is the registry's (regenerate: python3 -m symrep.kernel kernel-js)
    with open(os.path.join(spec_dir, "kernel.js")) as f:
        assert f.read() == symrep.kernel.kernel_js(), "kernel.js is stale: python3 -m symrep.kernel kernel-js"
    # installed from the build tree: the same folder, with this package's folder on PYTHONPATH
    where = install_spec(tmp_path)
    assert sorted(os.listdir(where)) == sorted(os.listdir(spec_dir))
    with open(os.path.join(where, "kernel.json")) as f:
        installed = json.load(f)
    parent = os.path.dirname(os.path.dirname(os.path.abspath(symrep.kernel.__file__)))
    assert installed == dict(spec, argv=[sys.executable] + spec["argv"][1:], env={"PYTHONPATH": parent})
    # from site-packages: the folder as it is
    assert symrep.kernel.kernel_spec(build_tree=False) == spec


def test_statements_of_a_cell():
    # as the engine reads a stream: a statement ends where no bracket is open
    cell = "a := 1\nf(1,\n  2)\n\n# note\nb := [1, \\\n 2]; c := 3\nd := (1"
    assert list(symrep.kernel.statements(cell)) == [
        (1, "a := 1"), (2, "f(1,\n  2)"), (5, "# note"), (6, "b := [1, \\\n 2]; c := 3"), (8, "d := (1")]


# --- the main job as a notebook -------------------------------------------------------------


def test_the_foucault_notebook_runs(jupyter_env, tmp_path):
    from nbconvert.preprocessors import ExecutePreprocessor

    src = os.path.join(SOURCE_DIR, "examples", "notebooks", "foucault.ipynb")
    shutil.copy(src, tmp_path / "foucault.ipynb")
    nb = nbformat.read(str(tmp_path / "foucault.ipynb"), as_version=4)
    ExecutePreprocessor(timeout=600, kernel_name="symrep").preprocess(nb, {"metadata": {"path": str(tmp_path)}})
    code = [c for c in nb.cells if c.cell_type == "code"]
    outputs = [o for c in code for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    # results are Out[n] of their cell: the solution as LaTeX with its text fallback
    for c in code:
        for o in c.outputs:
            if o.output_type == "execute_result":
                assert o.execution_count == c.execution_count
    results = [o for o in outputs if o.output_type == "execute_result"]
    latex = [o.data["text/latex"] for o in results if "text/latex" in o.data]
    texts = [o.data["text/plain"] for o in results]
    assert any("\\times" in x and "\\cos" in x for x in latex), latex
    assert texts.count("true") >= 3, texts  # check(P, s), s == thesis79, e < 1e-5
    # the picture is display data, not a result
    images = [o for o in outputs if o.output_type == "display_data" and "image/png" in o.data]
    assert len(images) == 1 and len(images[0].data["image/png"]) > 1000
    assert not [o for o in outputs if o.output_type == "display_data" and "image/png" not in o.data]
    assert (tmp_path / "foucault_trace.png").exists()


# --- the protocol --------------------------------------------------------------------------


@pytest.fixture(scope="module")
def kernel(jupyter_env):
    # one kernel for the protocol tests (each uses its own names)
    from jupyter_client.manager import start_new_kernel

    km, kc = start_new_kernel(kernel_name="symrep", startup_timeout=120)
    yield km, kc
    kc.stop_channels()
    km.shutdown_kernel(now=True)


def reply_to(kc, msg_id, timeout=120):
    # the shell reply to this request (a late reply to start_new_kernel's kernel_info may come first)
    while True:
        msg = kc.get_shell_msg(timeout=timeout)
        if msg["parent_header"].get("msg_id") == msg_id:
            return msg


def run(kc, code, timeout=120, **kw):
    """The reply content and the IOPub messages of a cell, each with the time it arrived."""
    msg_id = kc.execute(code, **kw)
    outputs = []
    while True:
        msg = kc.get_iopub_msg(timeout=timeout)
        if msg["parent_header"].get("msg_id") != msg_id:
            continue
        msg["arrived"] = time.monotonic()
        if msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle":
            break
        outputs.append(msg)
    return reply_to(kc, msg_id, timeout)["content"], outputs


def shown(out):
    return [(m["msg_type"], m["content"].get("text") or m["content"].get("data", {}).get("text/plain"))
            for m in out if m["msg_type"] in ("stream", "execute_result", "display_data")]


def test_kernel_results_and_errors(kernel):
    km, kc = kernel
    reply, out = run(kc, "A := multicomplex(1)\ninverse(element(A, [1, 2, 3, 4]))")
    assert reply["status"] == "ok"
    results = [m["content"] for m in out if m["msg_type"] == "execute_result"]
    assert len(results) == 1 and not [m for m in out if m["msg_type"] == "display_data"]
    # Out[n]: the execution count of the cell
    assert results[0]["execution_count"] == reply["execution_count"]
    assert results[0]["data"]["text/plain"] == symrep.Session().eval(
        "inverse(element(multicomplex(1), [1, 2, 3, 4]))").text
    assert results[0]["data"]["text/latex"].startswith("$") and "\\frac" in results[0]["data"]["text/latex"]
    # printed text, results and their order, statement by statement
    reply, out = run(kc, 'print("one")\n1 + 1\nprint("two")\n[1,\n 2]')
    assert shown(out) == [("stream", "one\n"), ("execute_result", "2"), ("stream", "two\n"),
                          ("execute_result", "[1, 2]")]
    count = reply["execution_count"]
    # an error: its Python class (as Session.eval raises it), line, column, the source line, a caret;
    # the line is the cell's (here after a statement of two lines)
    code = "x := 1\ny := [x,\n  2]\nz := x +* 2\nw := 5"
    with pytest.raises(symrep.Error) as raised:
        symrep.Session().eval(code)
    reply, out = run(kc, code, stop_on_error=False)
    assert reply["status"] == "error" and reply["execution_count"] == count + 1
    assert reply["ename"] == type(raised.value).__name__
    assert reply["evalue"] == raised.value.message and "syntax error" in reply["evalue"]
    tb = reply["traceback"]
    assert tb[0] == "<cell>:4:9: error: " + reply["evalue"]
    assert tb[1].strip() == "z := x +* 2" and tb[2].strip() == "^"
    assert tb[2].index("^") == tb[1].index("*")
    errors = [m["content"] for m in out if m["msg_type"] == "error"]
    assert errors == [{"ename": reply["ename"], "evalue": reply["evalue"], "traceback": tb}]
    # the statements before the error ran, the one after did not; the session goes on
    reply, out = run(kc, "[x, y, w]")
    assert shown(out) == [("execute_result", "[1, [1, 2], w]")]
    # an error of the engine (not of the syntax)
    reply, out = run(kc, "inverse(element(A, [1, 0, 0, 1]))", stop_on_error=False)
    assert reply["status"] == "error" and reply["traceback"][0].startswith("<cell>:1:")
    assert reply["traceback"][1] == "    inverse(element(A, [1, 0, 0, 1]))"


def test_kernel_streams_while_a_cell_runs(kernel):
    km, kc = kernel
    # the first line's output arrives while the slow statement (about 1 s) still runs
    reply, out = run(kc, 'print("before")\nsum(k^2, k, 1, 2*10^5)\nprint("after")')
    assert reply["status"] == "ok"
    busy = out[0]["arrived"]
    out = [m for m in out if m["msg_type"] != "status"]
    kinds = [(m["msg_type"], m["content"].get("text")) for m in out]
    assert kinds == [("execute_input", None), ("stream", "before\n"), ("execute_result", None),
                     ("stream", "after\n")]
    before, result = out[1]["arrived"], out[2]["arrived"]
    # held until the end, "before" would arrive with the result; streamed, it arrives at the start
    assert result - before > 0.05 and result - before > 0.5 * (result - busy), \
        "the output of the first statement was held until the second ended"


def test_kernel_completion_and_help(kernel):
    km, kc = kernel
    run(kc, "inverse_of_w := 1")
    c = reply_to(kc, kc.complete("y := inver", 10))["content"]
    assert "inverse" in c["matches"] and "inverse_of_w" in c["matches"]
    assert c["cursor_start"] == 5 and c["cursor_end"] == 10
    types = {t["text"]: t["type"] for t in c["metadata"]["_jupyter_types_experimental"]}
    assert types["inverse"] == "function" and types["inverse_of_w"] == "instance"
    c = reply_to(kc, kc.complete("vec", 3))["content"]
    assert "vector" in c["matches"]
    # Shift-Tab: the name under the cursor, else the function whose brackets enclose it
    help_text = symrep.Session().help("inverse")
    for code, pos in (("inverse(w)", 3), ("inverse(w)", 8), ("y := inverse(element(A, [1, 2]), ", 33)):
        i = reply_to(kc, kc.inspect(code, pos))["content"]
        assert i["found"] and i["data"]["text/plain"] == help_text, (code, pos)
    i = reply_to(kc, kc.inspect("y := element(A, [1, 2", 21))["content"]
    assert i["found"] and i["data"]["text/plain"].startswith("element(")
    assert not reply_to(kc, kc.inspect("zzz + 1", 2))["content"]["found"]
    assert reply_to(kc, kc.is_complete("f(1,\n"))["content"]["status"] == "incomplete"
    assert reply_to(kc, kc.is_complete("f(1, 2)"))["content"]["status"] == "complete"
    reply, out = run(kc, "?inverse")
    assert any(m["msg_type"] == "stream" and "inverse(" in m["content"]["text"] for m in out)
    reply, out = run(kc, "?inversee")
    assert any(m["msg_type"] == "stream" and "did you mean" in m["content"]["text"] for m in out)
    info = reply_to(kc, kc.kernel_info())["content"]["language_info"]
    assert info["pygments_lexer"] == "symrep" and info["codemirror_mode"] == "symrep"


def test_kernel_interrupt(kernel):
    km, kc = kernel
    # (stop_on_error=False: the next request is not aborted by the error this one ends with)
    msg_id = kc.execute('a := 1\nsum(k^2, k, 1, 5*10^6)\nb := 2', stop_on_error=False)
    time.sleep(1.5)
    km.interrupt_kernel()
    reply = reply_to(kc, msg_id)["content"]
    assert reply["status"] == "error" and "interrupted" in reply["evalue"]
    assert reply["traceback"][0].startswith("<cell>:2:")
    assert km.is_alive()
    reply, out = run(kc, "[a, b]")
    assert reply["status"] == "ok" and shown(out) == [("execute_result", "[1, b]")]
