"""tests/python/test_kernel.py -- the symrep Jupyter kernel (symrep/kernel.py): the main job as a
notebook executed by nbconvert, and the protocol (results as LaTeX, errors with a caret,
completion, help, interruption) through jupyter_client. The kernel spec is written into a
temporary JUPYTER_PATH, as `python3 -m symrep.kernel install` writes it."""
import json
import os
import shutil
import time

import nbformat
import pytest
from conftest import SOURCE_DIR


@pytest.fixture(scope="module")
def jupyter_env(tmp_path_factory):
    import symrep.kernel

    root = tmp_path_factory.mktemp("jupyter")
    spec = root / "kernels" / "symrep"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps(symrep.kernel.kernel_spec()))
    saved = {k: os.environ.get(k) for k in ("JUPYTER_PATH", "JUPYTER_RUNTIME_DIR", "JUPYTER_DATA_DIR", "IPYTHONDIR")}
    os.environ["JUPYTER_PATH"] = str(root)
    os.environ["JUPYTER_RUNTIME_DIR"] = str(root / "runtime")
    os.environ["JUPYTER_DATA_DIR"] = str(root / "data")
    os.environ["IPYTHONDIR"] = str(root / "ipython")
    yield root
    for k, v in saved.items():
        if v is None:
            os.environ.pop(k, None)
        else:
            os.environ[k] = v


def test_the_foucault_notebook_runs(jupyter_env, tmp_path):
    from nbconvert.preprocessors import ExecutePreprocessor

    src = os.path.join(SOURCE_DIR, "examples", "notebooks", "foucault.ipynb")
    shutil.copy(src, tmp_path / "foucault.ipynb")
    nb = nbformat.read(str(tmp_path / "foucault.ipynb"), as_version=4)
    ExecutePreprocessor(timeout=600, kernel_name="symrep").preprocess(nb, {"metadata": {"path": str(tmp_path)}})
    code = [c for c in nb.cells if c.cell_type == "code"]
    outputs = [o for c in code for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    # every cell that shows something shows it; the solution as LaTeX with its text fallback
    latex = [o.data["text/latex"] for o in outputs if o.output_type == "display_data" and "text/latex" in o.data]
    texts = [o.data["text/plain"] for o in outputs if o.output_type == "display_data"]
    assert any("\\times" in x and "\\cos" in x for x in latex), latex
    assert texts.count("true") >= 3, texts  # check(P, s), s == thesis79, e < 1e-5
    images = [o for o in outputs if o.output_type == "display_data" and "image/png" in o.data]
    assert len(images) == 1 and len(images[0].data["image/png"]) > 1000
    assert (tmp_path / "foucault_trace.png").exists()


@pytest.fixture
def kernel(jupyter_env):
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


def run(kc, code, timeout=120):
    msg_id = kc.execute(code)
    outputs = []
    while True:
        msg = kc.get_iopub_msg(timeout=timeout)
        if msg["parent_header"].get("msg_id") != msg_id:
            continue
        if msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle":
            break
        outputs.append(msg)
    return reply_to(kc, msg_id, timeout)["content"], outputs


def test_kernel_protocol(kernel):
    km, kc = kernel
    reply, out = run(kc, "A := multicomplex(1)\ninverse(element(A, [1, 2, 3, 4]))")
    assert reply["status"] == "ok"
    shown = [m["content"]["data"] for m in out if m["msg_type"] == "display_data"]
    assert len(shown) == 1 and "text/latex" in shown[0] and "text/plain" in shown[0]
    # an error: line, column, the source line and a caret
    reply, out = run(kc, "x := 1\ny := x +* 2")
    assert reply["status"] == "error" and reply["ename"] == "symrep.Error"
    tb = reply["traceback"]
    assert tb[0].startswith("<cell>:2:") and tb[1].strip() == "y := x +* 2" and tb[2].strip() == "^"
    assert tb[2].index("^") == 4 + tb[1].strip().index("*")
    # the session goes on; variables of earlier cells are kept
    reply, out = run(kc, "x + 1")
    assert [m["content"]["data"]["text/plain"] for m in out if m["msg_type"] == "display_data"] == ["2"]
    # Tab completion and help from the engine
    c = reply_to(kc, kc.complete("y := inver", 10))["content"]
    assert "inverse" in c["matches"] and c["cursor_start"] == 5
    i = reply_to(kc, kc.inspect("inverse(w)", 3))["content"]
    assert i["found"] and i["data"]["text/plain"].startswith("inverse(")
    assert reply_to(kc, kc.is_complete("f(1,\n"))["content"]["status"] == "incomplete"
    assert reply_to(kc, kc.is_complete("f(1, 2)"))["content"]["status"] == "complete"
    reply, out = run(kc, "?inverse")
    assert any(m["msg_type"] == "stream" and "inverse(" in m["content"]["text"] for m in out)
    reply, out = run(kc, "?inversee")
    assert any(m["msg_type"] == "stream" and "did you mean" in m["content"]["text"] for m in out)


def test_kernel_interrupt(kernel):
    km, kc = kernel
    # (stop_on_error=False: the next request is not aborted by the error this one ends with)
    msg_id = kc.execute("sum(k^2, k, 1, 5*10^6)", stop_on_error=False)
    time.sleep(2)
    km.interrupt_kernel()
    reply = reply_to(kc, msg_id)["content"]
    assert reply["status"] == "error" and "interrupted" in reply["evalue"]
    reply, out = run(kc, "1 + 1")
    assert reply["status"] == "ok"
