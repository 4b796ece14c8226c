"""tests/python/test_api_sympy.py -- SymPy interop by walking the expression trees (issue 30,
item 2; docs/python.md): Value._sympy_ / to_sympy and symrep.from_sympy, round trips, and
the TypeError that names what has no counterpart."""
from fractions import Fraction

import pytest

sympy = pytest.importorskip("sympy")

import symrep  # noqa: E402


@pytest.fixture
def s():
    return symrep.Session()


ROUND_TRIPS = [
    "1/3", "-7", "2^100", "(1 + 2*I)/(3 - I)", "x", "x^3/7 - 2*x*y + 1",
    "sin(x) + cos(2*x) - tan(x/3)", "exp(-k*t)*log(x)", "sqrt(2)*x^(3/2) + x^(-2)",
    "abs(y)*step(t - 1)", "atan(x) + asin(1/3) + acos(x/2) + sinh(x) + cosh(x)*tanh(x)",
    "factorial(5) + binomial(n, 2)", "pi*x + exp(1)", "x = y + 1", "[1/2, x, [sin(t)]]",
    "matrix([[1, x], [y^2, 0]])", "[1, 2, x]", "true",
]


@pytest.mark.parametrize("text", ROUND_TRIPS)
def test_round_trip_through_sympy_is_exact(s, text):
    v = s.eval(text)
    z = sympy.sympify(v) if v.kind != "list" else v.to_sympy()
    back = symrep.from_sympy(z, s)
    assert back.session is s
    assert back == v, (text, z, back.text)
    assert back.text == v.text


def test_the_tree_is_walked_not_printed(s):
    z = sympy.sympify(s.eval("sqrt(2)*sin(w0*t)/w0 + x^3/7 + exp(-k*t)*abs(y)"))
    t, w0, x, k, y = sympy.symbols("t w0 x k y", real=True)
    assert z == sympy.sqrt(2) * sympy.sin(w0 * t) / w0 + x**3 / 7 + sympy.exp(-k * t) * sympy.Abs(y)
    s.eval("positive w0")
    assert sympy.sympify(s.eval("w0")).is_positive
    assert sympy.sympify(s.eval("step(t)")) == sympy.Heaviside(t)
    # floats keep their digits
    f = sympy.sympify(s.eval("evalf(1/3, 30)"))
    assert isinstance(f, sympy.Float) and abs(f - sympy.Rational(1, 3)) < sympy.Float("1e-29")
    # mixed arithmetic: a Value meets a SymPy object through _sympy_
    assert s.eval("x") + sympy.Symbol("y", real=True) == x + y


def test_from_sympy_builds_engine_values(s):
    x, y = sympy.symbols("x y")
    v = symrep.from_sympy(sympy.Rational(2, 3) * sympy.sin(x) ** 2 + sympy.sqrt(y), s)
    assert v == s.eval("2/3*sin(x)^2 + sqrt(y)")
    assert symrep.from_sympy(sympy.Eq(x, 2), s).text == "x = 2"
    assert symrep.from_sympy([1, sympy.Integer(2), Fraction(1, 3)], s).to_python() == [1, 2, Fraction(1, 3)]
    assert symrep.from_sympy(sympy.Float(0.25), s).to_python() == 0.25
    hi = symrep.from_sympy(sympy.Float("0.1", 40), s)
    assert abs(sympy.Float(hi.text, 40) - sympy.Rational(1, 10)) < sympy.Float("1e-35")
    # the symbol, not a variable of the same name
    s.eval("x := 5")
    assert symrep.from_sympy(x + 1, s).text in ("1 + x", "x + 1")
    # no session: the default one
    assert symrep.from_sympy(y).session is symrep.default_session()


@pytest.mark.parametrize("make, named", [
    (lambda: sympy.oo, "Infinity"),
    (lambda: sympy.Function("f")(sympy.Symbol("t")), "f"),
    (lambda: sympy.Derivative(sympy.Function("f")(sympy.Symbol("t")), sympy.Symbol("t")), "Derivative"),
    (lambda: sympy.Symbol("x_{1}"), "x_{1}"),
    (lambda: sympy.Lt(sympy.Symbol("x"), 1), "StrictLessThan"),
    (lambda: sympy.gamma(sympy.Symbol("x")), "gamma"),
    (lambda: object(), "object"),
])
def test_from_sympy_names_what_has_no_counterpart(s, make, named):
    with pytest.raises(TypeError, match=named.replace("{", r"\{").replace("}", r"\}")):
        symrep.from_sympy(make(), s)


def test_to_sympy_names_what_has_no_counterpart(s):
    s.eval("vector w, r")
    with pytest.raises(TypeError, match=r"vector expression has no SymPy counterpart: .*w x r|r x w"):
        s.eval("w x r").to_sympy()
    with pytest.raises(TypeError, match="element has no SymPy counterpart"):
        sympy.sympify(s.eval("element(multicomplex(1), [1, 2, 3, 4])"))
    with pytest.raises(TypeError, match="algebra has no SymPy counterpart"):
        s.eval("multicomplex(1)").to_sympy()
    with pytest.raises(TypeError, match="string has no SymPy counterpart"):
        s.eval('"a"').to_sympy()
