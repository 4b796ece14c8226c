"""tests/python/test_api_stubs.py -- the type stubs (symrep/__init__.pyi, _symrep.pyi, py.typed;
issue 30, item 1; docs/python.md): up to date with the registry's builtins, every public name of
the runtime module in the stub and back, and mypy on a typed script catches a missing method."""
import importlib.util
import os
import shutil
import subprocess
import sys
import time

import pytest

import symrep
import symrep._symrep as compiled

PACKAGE = os.path.dirname(os.path.abspath(symrep.__file__))
SOURCE = os.environ.get("SYMREP_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))


def load_make_stubs():
    spec = importlib.util.spec_from_file_location("make_stubs", os.path.join(SOURCE, "repl", "python", "make_stubs.py"))
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


def test_stub_files_are_in_the_package():
    for name in ("__init__.pyi", "_symrep.pyi", "py.typed"):
        assert os.path.exists(os.path.join(PACKAGE, name)), name


def test_the_generated_stub_is_up_to_date():
    m = load_make_stubs()
    with open(os.path.join(SOURCE, "repl", "python", "symrep", "_symrep.pyi")) as f:
        committed = f.read()
    assert committed == m.render(), (
        "repl/python/symrep/_symrep.pyi is out of date (a builtin or a class changed): "
        "PYTHONPATH=build/python /usr/bin/python3 repl/python/make_stubs.py")


def stub_names(path):
    import ast
    with open(path) as f:
        tree = ast.parse(f.read())
    top, classes = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            classes[node.name] = {n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.AnnAssign))
                                  and not isinstance(n, ast.AnnAssign)} | {
                n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            top.add(node.target.id)
        elif isinstance(node, ast.Assign):
            top.update(t.id for t in node.targets)
        elif isinstance(node, ast.ImportFrom):
            top.update(a.asname or a.name for a in node.names if a.asname)
    return top, classes


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_every_public_name_of_the_runtime_is_in_the_stubs_and_back():
    top, classes = stub_names(os.path.join(PACKAGE, "_symrep.pyi"))
    runtime = public(dir(compiled))
    assert runtime - top == set(), "in _symrep but not in its stub"
    assert public(top) - {"ValueLike", "ArrayLike"} - runtime == set(), "in the stub but not in _symrep"
    for cls in ("Session", "Value", "Compiled"):
        have = public(vars(getattr(compiled, cls)))
        assert have - classes[cls] == set(), cls
        # the builtins are Value's methods at run time (through __getattr__)
        extra = public(classes[cls]) - have
        if cls == "Value":
            extra -= set(symrep.Session().builtin_names())
        assert extra == set(), cls
    top, classes = stub_names(os.path.join(PACKAGE, "__init__.pyi"))
    assert set(symrep.__all__) - {"__version__"} <= top | {"version"}
    assert public(top) <= set(dir(symrep))
    for name in symrep.__all__:
        obj = getattr(symrep, name)
        if isinstance(obj, type) and issubclass(obj, BaseException):
            assert name in classes


TYPED = '''
import numpy as np
import symrep

s = symrep.Session()
v = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
assert v is not None
w: symrep.Value = v.inverse()
p: symrep.Value = v.charpoly(s.symbol("X"))
t: str = (w * 2 + 1).text
d: symrep.Value = symrep.eps * 2 + 1
f = s.compile("a*t", "t", a=2)
y = f(np.zeros(3))
z: float = float(y[0])
try:
    s.eval("1/0")
except symrep.ZeroDivisorError as e:
    n: int = len(e.ranks)
except symrep.Error as e:
    line = e.line
'''


def test_mypy_checks_a_typed_script_and_catches_a_missing_method(tmp_path):
    mypy = shutil.which("mypy")
    if mypy is None:
        pytest.skip("mypy is not installed")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(PACKAGE), MYPYPATH=os.path.dirname(PACKAGE))
    good = tmp_path / "good.py"
    good.write_text(TYPED)
    bad = tmp_path / "bad.py"
    bad.write_text(TYPED + "v.no_such_builtin()\nw.inverse(1, 2, 3)\n")
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--no-incremental", "--cache-dir", os.devnull,
                        str(good), str(bad)],
                       capture_output=True, text=True, env=env, timeout=120)
    out = r.stdout + r.stderr
    assert "good.py" not in out, out
    n = TYPED.count("\n") + 1
    assert 'bad.py:%d: error: "Value" has no attribute "no_such_builtin"' % n in out, out
    assert "bad.py:%d: error: Too many arguments" % (n + 1) in out, out
    assert time.perf_counter() - t0 < 60
