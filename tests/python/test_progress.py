"""tests/python/test_progress.py -- progress of long operations in Python (symrep/progress.py,
repl/python/progress.cpp, core/progress.h): the callback receives the engine's reports, a
callback that raises stops the statement, the tqdm bar prints nothing when stderr is not a
terminal, and the kernel's progress line updates one display in place."""
import io

import pytest

import symrep
import symrep.progress

# verify in a few hundred ms: a closed form against the ODE integrated on [0, 60]
VERIFY = ("vector r0\n"
          "verify(ode(r'' + 4*r = 0, r(0) = r0, r'(0) = 0), cos(2*t)*r0, [r0 = [1, 2, 3]], 60)")


def test_callback_receives_monotone_reports():
    s = symrep.Session()
    seen = []
    with symrep.progress.callback(lambda r: seen.append((r.task, r.done, r.total, r.final)), interval=0):
        value = s.eval(VERIFY)
    assert value.text  # the statement ran as usual
    assert seen, "no report"
    assert {t for t, _, _, _ in seen} == {"verify"}
    done = [d for _, d, _, _ in seen]
    assert all(b >= a for a, b in zip(done, done[1:]))
    assert [f for _, _, _, f in seen].count(True) == 1 and seen[-1][3]
    assert seen[-1][1] == seen[-1][2]  # done == total at the end
    # outside the block: no callback
    seen.clear()
    s.eval(VERIFY)
    assert seen == []


def test_same_value_with_and_without_progress():
    plain = symrep.Session().eval(VERIFY).text
    with symrep.progress.callback(lambda r: None, interval=0):
        assert symrep.Session().eval(VERIFY).text == plain


def test_callback_that_raises_stops_the_statement():
    def boom(report):
        raise ValueError("boom")

    s = symrep.Session()
    with symrep.progress.callback(boom, interval=0):
        with pytest.raises(symrep.Error, match="progress callback: ValueError: boom"):
            s.eval(VERIFY)
    assert s.eval("1 + 1").text == "2"  # the session goes on


def test_callback_must_be_callable():
    with pytest.raises(TypeError):
        symrep.progress.callback(42)


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_bar_silent_when_not_a_terminal():
    out = io.StringIO()
    with symrep.progress.bar(delay=0, file=out):
        symrep.Session().eval(VERIFY)
    assert out.getvalue() == ""


def test_bar_on_a_terminal():
    pytest.importorskip("tqdm")
    out = _Terminal()
    with symrep.progress.bar(delay=0, file=out):
        symrep.Session().eval(VERIFY)
    text = out.getvalue()
    assert "verify" in text and "%" in text, text


class _FakeKernel:
    iopub_socket = "iopub"

    def __init__(self):
        self.sent = []

    def send_response(self, socket, kind, content):
        self.sent.append((kind, content))


def test_kernel_line_updates_one_display():
    k = _FakeKernel()
    with symrep.progress.kernel_line(k, delay=0):
        symrep.Session().eval(VERIFY)
    kinds = [kind for kind, _ in k.sent]
    assert kinds[0] == "display_data" and kinds[1:] and set(kinds[1:]) == {"update_display_data"}, kinds
    ids = {c["transient"]["display_id"] for _, c in k.sent}
    assert len(ids) == 1
    assert k.sent[0][1]["data"]["text/plain"].startswith("verify ")
    assert k.sent[-1][1]["data"]["text/plain"] == ""  # emptied at the end
    # a short statement (below the delay) shows nothing
    k.sent.clear()
    with symrep.progress.kernel_line(k, delay=60):
        symrep.Session().eval(VERIFY)
    assert k.sent == []


def test_kernel_shows_a_progress_line(tmp_path, monkeypatch):
    """A real symrep kernel through jupyter_client (SYMREP_PROGRESS_DELAY=0: the line at once)."""
    pytest.importorskip("ipykernel")
    pytest.importorskip("jupyter_client")
    import json

    import symrep.kernel
    from jupyter_client.manager import start_new_kernel

    spec = tmp_path / "kernels" / "symrep"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps(symrep.kernel.kernel_spec()))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("JUPYTER_DATA_DIR", str(tmp_path / "data"))
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    monkeypatch.setenv("SYMREP_PROGRESS_DELAY", "0")
    km, kc = start_new_kernel(kernel_name="symrep", startup_timeout=120)
    try:
        msg_id = kc.execute(VERIFY)
        msgs = []
        while True:
            msg = kc.get_iopub_msg(timeout=120)
            if msg["parent_header"].get("msg_id") != msg_id:
                continue
            if msg["msg_type"] == "status" and msg["content"]["execution_state"] == "idle":
                break
            msgs.append(msg)
    finally:
        kc.stop_channels()
        km.shutdown_kernel(now=True)
    lines = [m for m in msgs if "display_id" in m["content"].get("transient", {})]
    assert lines and lines[0]["msg_type"] == "display_data", [m["msg_type"] for m in msgs]
    assert lines[0]["content"]["data"]["text/plain"].startswith("verify ")
    assert {m["content"]["transient"]["display_id"] for m in lines} == {lines[0]["content"]["transient"]["display_id"]}
    assert [m["msg_type"] for m in lines[1:]] == ["update_display_data"] * (len(lines) - 1) and len(lines) >= 2
    assert lines[-1]["content"]["data"]["text/plain"] == ""
    # the result comes after the progress line, as without it
    results = [m for m in msgs if m["msg_type"] in ("display_data", "execute_result") and m not in lines]
    assert results and msgs.index(results[-1]) > msgs.index(lines[-1])
