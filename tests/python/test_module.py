"""tests/python/test_module.py -- the Python module `symrep` (docs/python.md): sessions,
values, errors with line and column, conversions, the compiled fast path.
Run by ctest (python.pytest) with PYTHONPATH=build/python."""
import math
import os
from fractions import Fraction

import numpy as np
import pytest
import sympy

import symrep


@pytest.fixture
def s():
    return symrep.Session()


def test_eval_returns_python_values(s):
    assert s.eval("1/3 + 1/6").to_python() == Fraction(1, 2)
    assert s.eval("2^100").to_python() == 2**100
    assert s.eval("[1, 2/3, [true, \"a\"]]").to_python() == [1, Fraction(2, 3), [True, "a"]]
    assert s.eval("(1 + 2*I)/(3 - I)").to_python() == complex(Fraction(1, 10), Fraction(7, 10))
    assert s.eval("vector w").to_python() is None
    assert abs(s.eval("evalf(pi)").to_python() - math.pi) < 1e-15
    with pytest.raises(TypeError, match="no exact Python number"):
        s.eval("x^2 + 1").to_python()


def test_text_latex_kind(s):
    v = s.eval("(x + 1)^2")
    assert v.kind == "expression"
    assert v.text == "(1 + x)^2" or v.text == "(x + 1)^2"
    assert "^{2}" in v.latex
    assert v._repr_latex_().startswith("$") and v._repr_latex_().endswith("$")
    assert s.eval('"a string"').text == "a string"
    assert s.eval("multicomplex(1)").kind == "algebra"


def test_errors_carry_line_and_column(s):
    with pytest.raises(symrep.Error) as e:
        s.eval("a := 1\nb := inverse(element(multicomplex(1), [1, 0, 1, 0])) + undefined_thing(")
    err = e.value
    assert err.line == 2
    assert err.column >= 1
    assert "b := inverse" in err.source_line
    assert str(err).startswith("<python>:2:")
    assert err.caret().splitlines()[-1].strip() == "^"
    with pytest.raises(symrep.Error, match="zero divisor"):
        s.eval("inverse(element(multicomplex(1), [1, 0, 0, 1]))")
    # errors of operations and calls carry no place (the statement is the module's, not the user's)
    with pytest.raises(symrep.Error) as e:
        s.eval("x") + [1, [2]]
    assert e.value.line is None and str(e.value) == "cannot add an expression and a list (operator '+')"
    # the session goes on after an error
    assert s.eval("a + 1").to_python() == 2


def test_values_have_operations_and_builtins_as_methods(s):
    w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    one = w * w.inverse()
    assert one == s.eval("element(multicomplex(1), [1, 0, 0, 0])")
    assert (w + 1) - w == s.eval("element(multicomplex(1), [1, 0, 0, 0])")
    assert (2 * w) / 2 == w
    assert w.kind == "element"
    assert "charpoly" in s.builtin_names()
    p = w.charpoly(s.eval("X"))
    assert p.kind == "expression"
    with pytest.raises(AttributeError):
        w.no_such_builtin
    # Python numbers go in exactly
    assert (s.eval("x") * Fraction(1, 3)).text in ("1/3*x", "x/3")
    # operations leave no temporaries behind; None and foreign objects are not equal
    assert [v for v in s.variables() if v.startswith("__")] == []
    assert not (w == None) and w != object()  # noqa: E711
    s.set("k", Fraction(2, 7))
    assert s.get("k").to_python() == Fraction(2, 7)
    assert s.get("nothing_here") is None


def test_truth_values_numbers_and_lists(s):
    assert bool(s.eval("1 < 2")) is True
    assert not s.eval("x^2 - 1 == (x - 1)*(x + 1) + 1")
    with pytest.raises(TypeError, match="truth value"):
        bool(s.eval("x + 1"))  # never a guess
    assert float(s.eval("sqrt(2)")) == pytest.approx(2**0.5, rel=1e-15)
    assert float(s.eval("3/4")) == 0.75
    with pytest.raises(TypeError):
        float(s.eval("x"))
    l = s.eval("[1, x, [2]]")
    assert len(l) == 3 and l[1].text == "x" and [v.text for v in l] == ["1", "x", "[2]"]
    assert (2 ** s.eval("x")).text == "2^x"


def test_compile_a_list_of_closed_forms(s):
    f = s.compile("[sin(w*t), [t^2, exp(-t)]]", ["t"], {"w": 2})
    t = np.array([0.0, 0.5, 1.0])
    np.testing.assert_allclose(f(t=t), np.stack([np.sin(2 * t), t**2, np.exp(-t)], axis=1), rtol=1e-15)
    with pytest.raises(symrep.Error, match="expression or a list"):
        s.compile("multicomplex(1)", ["t"])


def test_vector_solutions_are_values(s):
    s.eval("vector w, r0, v0; positive w0")
    P = s.eval("P := ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0)")
    assert P.kind == "problem"
    r = s.eval("solve(P)")
    assert s.call("check", P, r).to_python() is True
    wr = s.eval("w").cross(s.eval("r0"))
    assert wr.text == "-(r0 x w)"  # the canonical order: by name
    assert s.eval("w").dot(s.eval("w")).text == "|w|^2"
    with pytest.raises(TypeError, match="vector"):
        r.to_sympy()


def test_to_sympy_is_exact_or_refuses(s):
    e = s.eval("sqrt(2)*sin(w0*t)/w0 + x^3/7 + exp(-k*t)*abs(y)")
    z = e.to_sympy()
    t, w0, x, k, y = sympy.symbols("t w0 x k y", real=True)
    assert sympy.simplify(z - (sympy.sqrt(2) * sympy.sin(w0 * t) / w0 + x**3 / 7 + sympy.exp(-k * t) * sympy.Abs(y))) == 0
    assert s.eval("[1/2, x]").to_sympy() == [sympy.Rational(1, 2), x]
    with pytest.raises(TypeError):
        s.eval("multicomplex(1)").to_sympy()


def test_completion_and_help(s):
    s.eval("my_variable := 3")
    assert "inverse" in s.completions("inver")
    assert "my_variable" in s.completions("my_")
    assert "quit" in s.completions("qu", True) and "quit" not in s.completions("qu", False)
    h = s.help("inverse")
    assert h.startswith("inverse(")
    assert s.help("no_such_function") is None
    assert "did you mean" in s.unknown_builtin_message("invers")


def test_run_gives_the_events_of_a_cell_in_order(s, tmp_path):
    png = str(tmp_path / "p.png")
    ev = s.run('print("hello")\n1 + 1\nplot(sin(t), [], t = [0, 1], "%s")\nx^2\n1/0\n"never"' % png)
    kinds = [k for k, _ in ev]
    assert kinds == ["text", "result", "file", "result", "error"], ev
    assert ev[0][1] == "hello\n"
    assert ev[1][1].to_python() == 2
    assert ev[2][1] == png and os.path.getsize(png) > 0
    e = ev[4][1]  # the exception Session.eval raises for the same statement
    assert isinstance(e, symrep.DivisionByZeroError) and isinstance(e, ZeroDivisionError)
    assert (e.file, e.line, e.column) == ("<cell>", 5, 2) and e.source_line == "1/0"
    assert "division by zero" in e.message
    # the next cell runs again (stop at the first error is per cell)
    assert [k for k, _ in s.run("2 + 2")] == ["result"]


def foucault(s):
    s.eval("vector w, r0, v0; positive w0")
    return s.eval("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))")


PARIS = {"w": [7.2921e-5 * math.cos(math.radians(48.85)), 0, 7.2921e-5 * math.sin(math.radians(48.85))],
         "w0": math.sqrt(9.81 / 67), "r0": [3, 0, 0], "v0": [0, 0, 0]}


def hand_written(t, w, w0, r0, v0):
    # (VI.1.79) r = psi - sin(W t)/W w x psi + (1 - cos(W t))/W^2 w x (w x psi), NumPy
    w = np.asarray(w, float)
    W = np.linalg.norm(w)
    t = np.asarray(t, float)[:, None]
    psi = np.asarray(r0, float) * np.cos(w0 * t) + (np.asarray(v0, float) + np.cross(w, r0)) / w0 * np.sin(w0 * t)
    wpsi = np.cross(w, psi)
    return psi - np.sin(W * t) / W * wpsi + (1 - np.cos(W * t)) / W**2 * np.cross(w, wpsi)


def test_compiled_closed_form_over_numpy_arrays(s):
    r = foucault(s)
    f = s.compile(r, ["t"], PARIS)
    assert f.inputs == ["t"] and f.n_outputs == 3
    t = np.linspace(0, 86400, 10001)
    x = f(t=t)
    assert x.shape == (10001, 3)
    ref = hand_written(t, **PARIS)
    # the compiled form cancels by about 1e8 at the Earth's rate (docs/performance.md): 1e-6 m of
    # a 3 m swing is far above its 5e-11 relative error and far below any wrong formula
    assert np.max(np.abs(x - ref)) < 1e-6
    # the stable evaluator on demand: close to the exact value
    g = s.compile(r, ["t"], PARIS, stable=True)
    y = g.stable(t=t[:50])
    assert np.max(np.abs(y - ref[:50])) < 1e-12
    # a parameter sweep: w0 as an array next to t, a vector input as n x 3
    h = s.compile(r, ["t", "w0", "r0"], {"w": PARIS["w"], "v0": [0, 0, 0]})
    assert h.columns == ["t", "w0", "r0_x", "r0_y", "r0_z"]
    n = 1000
    w0s = np.linspace(0.3, 0.5, n)
    r0s = np.tile([3.0, 0.0, 0.0], (n, 1))
    z = h(t=3600.0, w0=w0s, r0=r0s)
    assert z.shape == (n, 3)
    for i in (0, 500, 999):
        zi = hand_written([3600.0], PARIS["w"], w0s[i], r0s[i], [0, 0, 0])[0]
        assert np.max(np.abs(z[i] - zi)) < 1e-6
    with pytest.raises(symrep.Error, match="missing input 't'"):
        h(w0=0.3, r0=[1, 2, 3])
    with pytest.raises(symrep.Error, match="different lengths"):
        h(t=np.zeros(3), w0=np.zeros(4), r0=[1, 2, 3])
    with pytest.raises(symrep.Error, match="compile"):
        s.compile(r, ["t"], {"w0": 1})  # w, r0, v0 have no values


def test_classes_and_methods_are_the_modules_for_introspection():
    # every method is the compiled module's (none patched on from Python), and every
    # signature names the module's types, not the C++ types behind them
    import pydoc
    import types
    for cls in (symrep.Session, symrep.Value, symrep.Compiled):
        text = pydoc.render_doc(cls, renderer=pydoc.plaintext)
        assert "anonymous" not in text and "py_value" not in text and "session_state" not in text, cls
    for name in ("to_python", "to_sympy", "__bool__", "__float__", "__len__", "__getitem__", "__iter__",
                 "__getattr__", "__dir__", "cross", "dot", "call"):
        assert name in symrep.Value.__dict__, name
        assert not isinstance(symrep.Value.__dict__[name], types.FunctionType), name
        assert symrep.Value.__dict__[name].__doc__, name
    assert not isinstance(symrep.Session.__dict__["compile"], types.FunctionType)
    assert symrep.Session.eval.__doc__.startswith(
        "eval(self: symrep._symrep.Session, code: str) -> symrep._symrep.Value")
    assert "-> symrep._symrep.Compiled" in symrep.Session.compile.__doc__


def test_calls_run_the_builtins_on_values(s):
    k = s.eval("k")
    # seq and sum substitute the values of k (the builtin's body, not k's name re-read)
    assert s.call("sum", k**2, k, 1, 3).to_python() == 14
    assert s.call("seq", k**2, k, 0, 3).to_python() == [0, 1, 4, 9]
    assert s.call("seq", k**2, k, [Fraction(1, 2), 3]).to_python() == [Fraction(1, 4), 9]
    assert (k**2).sum(k, 1, 3).to_python() == 14
    # the language's checks of the name and the number of arguments, with its messages
    with pytest.raises(symrep.Error, match=r"no function named 'inversee'; did you mean inverse") as e:
        s.call("inversee", k)
    assert e.value.line is None
    with pytest.raises(symrep.Error, match=r"inverse: expects 1 argument, got 2 \(usage: inverse"):
        s.call("inverse", k, k)
    # ode reads its equation as written: made in a statement
    with pytest.raises(symrep.Error, match=r"ode: .*read as written.*s\.eval"):
        s.call("ode", s.eval("x = 1"), s.eval("y = 1"))
    w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    assert "inverse" in dir(w) and "text" in dir(w)
    assert w.inverse.__doc__ == s.help("inverse") and w.inverse.__name__ == "inverse"
    assert [v for v in s.variables() if v.startswith("__")] == []
