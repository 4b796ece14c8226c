"""tests/python/test_api.py -- the Python API that explains itself (issue 30, item 2;
docs/python.md): the exception hierarchy with the program's messages, Python's TypeError for
wrong Python types, builtins in dir()/Tab completion with their signatures and help,
NumPy arrays as lists, pickling, abs()/int(), compile's positional and keyword arguments."""
import inspect
import os
import pickle
import pydoc
import signal
import subprocess
import warnings
from fractions import Fraction

import numpy as np
import pytest

import symrep


@pytest.fixture
def s():
    return symrep.Session()


# --- errors -----------------------------------------------------------------------------

def program_message(statement, tmp_path):
    """The message the symrep program prints for the statement (after FILE:LINE:COL: error: )."""
    binary = os.path.join(os.environ.get("SYMREP_BINARY_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build")), "symrep")
    if not os.path.exists(binary):
        pytest.skip("no symrep program built")
    script = tmp_path / "s.symrep"
    script.write_text(statement + "\n")
    r = subprocess.run([binary, str(script)], capture_output=True, text=True, timeout=60)
    line = [l for l in r.stderr.splitlines() if ": error: " in l][0]
    return line.split(": error: ", 1)[1]


@pytest.mark.parametrize("statement, cls, python_too", [
    ("a +* 2", symrep.ParseError, None),
    ("inverse(element(multicomplex(1), [1, 0, 0, 1]))", symrep.ZeroDivisorError, ZeroDivisionError),
    ("1/0", symrep.DivisionByZeroError, ZeroDivisionError),
    ("log(0)", symrep.DomainError, ValueError),
    ("energy(exp(-k*t), t)", symrep.UndecidedError, ValueError),
    ("inverse(3, 4)", symrep.LanguageTypeError, TypeError),
    ("[1] + element(multicomplex(1), [1, 0, 0, 0])", symrep.LanguageTypeError, TypeError),
    ("exp(find_generator(polynomial_algebra(X^4 - 2, X)), t)", symrep.ClosedFormError, None),
    ("element(multicomplex(1), [1, 0, 0, 0]) + element(multicomplex(2), [1, 0, 0, 0, 0, 0, 0, 0])",
     symrep.AlgebraError, None),
    ("tan(pi/2)", symrep.DomainError, ValueError),
    ("factorial(10^100)", symrep.SizeError, None),
])
def test_each_typed_error_of_the_engine_has_its_class_and_the_programs_message(s, tmp_path, statement, cls,
                                                                                python_too):
    with pytest.raises(cls) as e:
        s.eval(statement)
    err = e.value
    assert isinstance(err, symrep.Error)
    if python_too is not None:
        assert isinstance(err, python_too)
    # the class is the most specific one: no sibling of the hierarchy also matches
    for other in (symrep.ParseError, symrep.AlgebraError, symrep.DomainError, symrep.ZeroDivisorError, symrep.DivisionByZeroError, symrep.UndecidedError,
                  symrep.LanguageTypeError, symrep.ClosedFormError, symrep.SizeError, symrep.TimeLimitError):
        assert isinstance(err, other) == issubclass(cls, other), (other, type(err))
    assert err.line == 1 and err.column >= 1 and err.source_line == statement
    # the same bytes as the program prints after FILE:LINE:COL: error:
    assert err.message == program_message(statement, tmp_path)
    assert str(err) == "<python>:1:%d: error: %s" % (err.column, err.message)


def test_parse_error_has_line_and_column_and_caret(s):
    with pytest.raises(symrep.ParseError) as e:
        s.eval("a := 1\nb := a +* 2")
    assert (e.value.line, e.value.column) == (2, 9)
    assert e.value.message.startswith("syntax error: ")
    assert e.value.caret().splitlines()[-1] == " " * 8 + "^" or e.value.caret().splitlines()[-1].strip() == "^"


def test_zero_divisor_names_its_components_and_operations_raise_the_same_classes(s):
    w = s.eval("element(multicomplex(1), [1, 0, 0, 1])")
    with pytest.raises(symrep.ZeroDivisorError) as e:
        w.inverse()  # a method: no place
    assert e.value.line is None and isinstance(e.value.ranks, list) and e.value.ranks
    with pytest.raises(ZeroDivisionError):
        1 / w
    with pytest.raises(symrep.DivisionByZeroError):
        s.eval("x") / 0
    with pytest.raises(symrep.UndecidedError, match="cannot decide"):
        s.call("energy", s.eval("exp(-k*t)"), s.eval("t"))
    # an undecided comparison: == raises, never a guess (in a statement and in Python)
    with pytest.raises(symrep.UndecidedError, match="cannot decide whether the two sides are equal"):
        s.eval("sqrt(x^2 + 2*x + 1) == abs(x + 1)")
    with pytest.raises(symrep.UndecidedError, match="cannot decide whether the two sides are equal"):
        s.eval("sqrt(x^2 + 2*x + 1)") == s.eval("abs(x + 1)")


# a statement that runs for minutes, its steps the language's own (the time limit and Ctrl-C are
# seen at every evaluation step; one long GiNaC call is not cut short in the module)
LOOP = "seq(length(seq(j, j, 1, 10000)), k, 1, 10000)"


def test_time_limit_and_interruption(s):
    s.time_limit = 0.3
    with pytest.raises(symrep.TimeLimitError, match="time limit"):
        s.eval(LOOP)
    s.time_limit = 0
    assert s.time_limit == 0
    with pytest.raises(ValueError):
        s.time_limit = -1
    # SIGINT (Ctrl-C) during a statement: symrep.Interrupted, a KeyboardInterrupt as Python's Ctrl-C
    # (sent by another process: the engine holds the GIL, no Python thread runs meanwhile)
    killer = subprocess.Popen(["sh", "-c", "sleep 0.3; kill -INT %d" % os.getpid()])
    try:
        with pytest.raises(symrep.Interrupted) as e:
            s.eval(LOOP)
    finally:
        killer.wait()
    assert isinstance(e.value, KeyboardInterrupt) and isinstance(e.value, symrep.Error)
    assert e.value.message == "interrupted"
    assert s.eval("1 + 1").to_python() == 2  # the session goes on


def test_deep_lists_are_a_size_error_and_errors_pickle(s):
    deep = 1
    for _ in range(1001):
        deep = [deep]
    with pytest.raises(symrep.SizeError, match="nest more than 1000"):
        s.value(deep)
    e = symrep.ParseError("syntax error: x", "<python>", 2, 3, "a +* 2")
    f = pickle.loads(pickle.dumps(e))
    assert type(f) is symrep.ParseError and str(f) == str(e) and f.source_line == "a +* 2"


def test_wrong_python_types_are_pythons_type_error(s):
    x = s.eval("x")
    with pytest.raises(TypeError) as e:
        s.eval(3)
    assert not isinstance(e.value, symrep.Error)
    for op in (lambda: x + object(), lambda: object() * x, lambda: x ** {1: 2}, lambda: x - None):
        with pytest.raises(TypeError, match="unsupported operand"):
            op()
    with pytest.raises(TypeError, match="cannot pass a Python object"):
        s.set("k", object())
    with pytest.raises(TypeError, match="cannot pass a Python dict"):
        x.subs({1: 2})
    with pytest.raises(TypeError, match="cannot pass a Python object"):
        x.cross(object())
    with pytest.raises(TypeError, match="complex128"):
        s.value(np.array([1j]))
    with pytest.raises(ValueError, match="finite"):
        x + float("nan")
    assert x != object() and not (x == {})


# --- dir(), Tab completion, signatures, help ---------------------------------------------

def test_builtins_are_in_dir_and_in_ipythons_completion(s):
    w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    names = dir(w)
    for n in ("inverse", "charpoly", "exp", "text", "latex", "to_sympy", "cross"):
        assert n in names, n
    assert set(s.builtin_names()) <= set(names)
    import rlcompleter
    c = rlcompleter.Completer({"w": w})
    assert "w.inverse()" in [c.complete("w.inver", i) for i in range(3)]
    completer = pytest.importorskip("IPython.core.completer")
    ip = completer.IPCompleter(namespace={"w": w}, global_namespace={})
    ip.use_jedi = False  # the attribute completer, which reads dir()
    with warnings.catch_warnings():  # complete() is IPython's stable call, "pending deprecation" since 6.0
        warnings.simplefilter("ignore", PendingDeprecationWarning)
        _, matches = ip.complete(line_buffer="w.inver", cursor_pos=7)
    assert "w.inverse" in matches, matches
    # jedi (IPython's default completer, IDEs): the live object and the stubs
    jedi = pytest.importorskip("jedi")
    assert "inverse" in [c.name for c in jedi.Interpreter("w.inver", [{"w": w}]).complete()]


def test_builtin_methods_have_signatures_and_the_reference_text(s):
    w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    assert w.inverse.__doc__ == s.help("inverse")
    assert w.inverse.__name__ == "inverse" and w.inverse.__qualname__ == "Value.inverse"
    assert str(inspect.signature(w.inverse)) == "() -> 'symrep.Value'"
    assert str(inspect.signature(w.charpoly)) == "(X: 'symrep.ValueLike', /) -> 'symrep.Value'"
    # exp(x) / exp(w [, t]): t optional; append(l, x, ...): variadic
    assert str(inspect.signature(w.exp)) == "(t: 'symrep.ValueLike' = None, /) -> 'symrep.Value'"
    assert "*args" in str(inspect.signature(s.eval("[1]").append))
    assert w.exp().kind == "element"  # an optional argument left out
    text = pydoc.render_doc(w.inverse, renderer=pydoc.plaintext)
    assert "inverse() -> 'symrep.Value'" in text and s.help("inverse").splitlines()[1].strip() in text
    # help on Session.eval: the pybind11 signature with real types, and where the reference is
    text = pydoc.render_doc(symrep.Session.eval, renderer=pydoc.plaintext)
    assert "eval(self: symrep._symrep.Session, code: str) -> symrep._symrep.Value" in text
    assert "help(v.name)" in text and "s.help" in text
    sig = pydoc.render_doc(symrep.Session.compile, renderer=pydoc.plaintext)
    assert "-> symrep._symrep.Compiled" in sig and "inputs" in sig


# --- NumPy arrays, pickling, abs(), int() --------------------------------------------------

def test_numpy_arrays_are_list_values(s):
    assert s.value(np.array([1, 2, 3])).to_python() == [1, 2, 3]
    assert s.value(np.array([[1.5, 2], [3, 4]])).to_python() == [[1.5, 2.0], [3.0, 4.0]]
    assert s.value(np.int64(7)).to_python() == 7 and s.value(np.bool_(True)).to_python() is True
    s.set("v", np.arange(3))
    assert s.eval("sum(v)").to_python() == 3
    assert s.call("length", np.zeros(5)).to_python() == 5
    assert s.eval("x").subs(s.eval("x = 2")).to_python() == 2
    assert (s.eval("[1, 2]") + np.array([3, 4])).text == s.eval("[1, 2] + [3, 4]").text
    # the values of compile: a vector as a NumPy array
    s.eval("vector g")
    f = s.compile("g . g + t", "t", g=np.array([1.0, 2.0, 2.0]))
    np.testing.assert_array_equal(f(np.array([0.0, 1.0])), [9.0, 10.0])


def test_values_pickle_by_their_text_into_the_default_session(s):
    s.eval("vector w, r0; positive w0")
    values = [s.eval("sqrt(2)*sin(w0*t)/w0 + x^3/7"), s.eval("w x r0 + w0*r0"), s.eval("[1/2, true, \"a b\", [x]]"),
              s.eval('"text"'), s.eval("x = 2"), s.eval("evalf(1/3)")]
    target = symrep.Session()
    previous = symrep.set_default_session(target)
    try:
        for v in values:
            u = pickle.loads(pickle.dumps(v))
            assert u.session is target and u.kind == v.kind and u.text == v.text, (u.text, v.text)
        # the declarations travel: w0 is positive, w and r0 vectors in the target session
        assert target.eval("sqrt(w0^2)").text == "w0"
        assert pickle.loads(pickle.dumps(s.eval("w . w"))).text == "|w|^2"
        # a variable of the target session named like a symbol of the value: refused, never a wrong value
        target.eval("y := 3")
        with pytest.raises(pickle.UnpicklingError, match="y"):
            pickle.loads(pickle.dumps(s.eval("y + 1")))
    finally:
        symrep.set_default_session(previous)
    assert pickle.loads(pickle.dumps(s.eval("x + 1"))).session is symrep.default_session()
    for v in (s.eval("element(multicomplex(1), [1, 2, 3, 4])"), s.eval("multicomplex(1)"), s.eval("[multicomplex(1)]")):
        with pytest.raises(TypeError, match="cannot pickle"):
            pickle.dumps(v)


def test_abs_and_int_where_exact(s):
    assert abs(s.eval("-3/4")).to_python() == Fraction(3, 4)
    assert abs(s.eval("x")).text == "abs(x)"
    assert int(s.eval("2^70")) == 2**70 and int(s.eval("-5")) == -5
    assert [10, 20, 30][s.eval("1")] == 20  # __index__
    with pytest.raises(ValueError, match="not an integer: 5/2"):
        int(s.eval("5/2"))
    with pytest.raises(ValueError):
        int(s.eval("evalf(2)"))  # a floating-point value is no exact integer
    with pytest.raises(TypeError):
        int(s.eval("x"))


# --- compile: positional and keyword arguments ---------------------------------------------

def test_compile_takes_keywords_and_positional_inputs(s):
    t = np.array([0.0, 0.5, 1.0])
    old = s.compile("a*sin(w*t) + b", ["t"], {"w": 2, "a": 3, "b": Fraction(1, 2)})
    new = s.compile("a*sin(w*t) + b", "t", w=2, a=3, b=Fraction(1, 2))
    mixed = s.compile("a*sin(w*t) + b", ["t"], {"w": 2}, a=3, b=0.5)
    expected = 3 * np.sin(2 * t) + 0.5
    for f in (old, new, mixed):
        np.testing.assert_allclose(f(t=t), expected, rtol=1e-15)
        np.testing.assert_allclose(f(t), expected, rtol=1e-15)  # inputs by position
    two = s.compile("a*sin(w*t) + b", "t", "w", a=3, b=0.5)
    assert two.inputs == ["t", "w"]
    np.testing.assert_allclose(two(t, 2.0), expected, rtol=1e-15)
    np.testing.assert_allclose(two(t, w=2.0), expected, rtol=1e-15)
    np.testing.assert_allclose(s.compile("a*t", inputs=["t"], values={"a": 2}, stable=True)(t), 2 * t)
    # names the expression does not have are refused, naming them
    with pytest.raises(symrep.LanguageTypeError, match=r"'ww', which the closed form does not have \(its symbols: a, b, t, w\)"):
        s.compile("a*sin(w*t) + b", "t", w=2, a=3, b=1, ww=1)
    with pytest.raises(TypeError, match=r"the input 'tt' is not a symbol of the closed form"):
        s.compile("a*sin(w*t) + b", "tt", w=2, a=3, b=1)
    with pytest.raises(TypeError, match="given twice"):
        s.compile("a*t", "t", {"a": 1}, a=2)
    with pytest.raises(TypeError, match="multiple values for input 't'"):
        new(t, t=t)
    with pytest.raises(TypeError, match="takes 1 input but 2 were given"):
        new(t, t)
    with pytest.raises(TypeError, match="'z' is not an input"):
        new(t, z=t)


def test_builtin_options_are_keyword_arguments(tmp_path):
    # the language's trajectory(r, values, t = [0, 6], "f.svg", view = "3d") from Python:
    # options are keyword-only in the signature, reach the builtin, and unknown ones are refused
    s = symrep.Session()
    s.eval("vector w, r0")
    r = s.eval("rotation_operator(w, t, r0)")
    sig = inspect.signature(r.trajectory)
    assert sig.parameters["view"].kind == inspect.Parameter.KEYWORD_ONLY
    values, span = s.eval("[w = [0, 0, 1], r0 = [1, 0, 1]]"), s.eval("t = [0, 6]")
    top, box = str(tmp_path / "top.svg"), str(tmp_path / "box.svg")
    r.trajectory(values, span, top)
    r.trajectory(values, span, box, view="3d")
    s.eval('trajectory(rotation_operator(w, t, r0), [w = [0, 0, 1], r0 = [1, 0, 1]], t = [0, 6], "%s", view = "3d")'
           % str(tmp_path / "lang.svg"))
    with open(box) as f, open(str(tmp_path / "lang.svg")) as g:
        assert f.read() == g.read()  # the same picture as the language's call
    with open(top) as f, open(box) as g:
        assert f.read() != g.read()  # the option changed the view
    with pytest.raises(symrep.LanguageTypeError, match="no option viw .its options: view, azimuth, elevation"):
        r.trajectory(values, span, str(tmp_path / "c.svg"), viw="3d")
    with pytest.raises(symrep.LanguageTypeError, match="inverse: no option view"):
        s.call("inverse", 2, view="3d")
