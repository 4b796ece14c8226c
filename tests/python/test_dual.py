"""tests/python/test_dual.py -- dual numbers through the module (issue 31 item 1;
docs/rigid_body.md section 6): symrep.eps and s.eval("eps"), the reduction modulo
eps^2 under Python's operators, primal/dual_part as bound builtins, the zero-divisor
error with its place, pickling, and SymPy interop that refuses eps clearly."""
import pickle

import pytest

import symrep


@pytest.fixture
def s():
    return symrep.Session()


def test_eps_is_the_dual_unit_in_statements_and_operators(s):
    eps = s.eval("eps")
    assert eps.text == "eps"
    assert (eps * eps).text == "0"
    x, y = s.eval("x"), s.eval("y")
    v = x + eps * y
    assert v.text == "x + eps*y"
    assert (v * v).text == "x^2 + 2*eps*x*y"
    assert (v * v) == s.eval("(x + eps*y)^2")
    assert s.eval("sin(x + eps*y)") == s.eval("sin(x) + eps*y*cos(x)")
    assert symrep.eps == s.eval("eps")
    assert (1 + symrep.eps) ** 2 == 1 + 2 * symrep.eps


def test_primal_and_dual_part_are_bound_builtins(s):
    v = s.eval("cos(a + eps*b)")
    assert v.primal() == s.eval("cos(a)")
    assert v.dual_part() == s.eval("-b*sin(a)")
    assert s.call("dual", s.eval("a"), s.eval("b")) == s.eval("a + eps*b")
    # a builtin called from Python reduces like one called in a statement
    assert s.call("sin", s.eval("a + eps*b")) == s.eval("sin(a) + eps*b*cos(a)")
    assert s.eval("a + eps*b").sin().text == s.eval("sin(a + eps*b)").text
    s.eval("vector p, q")
    w = s.eval("(p + eps*q) x (p + eps*q)")
    assert w.text == "0"
    assert s.eval("(p + eps*q) . (p + eps*q)").dual_part() == s.eval("2*(p . q)")


def test_zero_divisor_has_its_place_and_the_typed_class(s):
    with pytest.raises(symrep.ZeroDivisorError) as e:
        s.eval("z := 2\nw := (1 + eps)/(eps*z)")
    assert (e.value.line, e.value.column) == (2, 15)
    assert "zero divisor" in e.value.message
    with pytest.raises(ZeroDivisionError):
        1 / s.eval("eps")
    with pytest.raises(symrep.DomainError, match="not ordered"):
        s.eval("1 + eps < 2")


def test_assignment_shadows_eps_and_pickling_keeps_the_dual_unit(s):
    v = s.eval("x + eps*y")
    previous = symrep.set_default_session(s)
    try:
        u = pickle.loads(pickle.dumps(v))
        assert u.session is s and u == v and u.text == "x + eps*y"
    finally:
        symrep.set_default_session(previous)
    s.eval("eps := 1/10")
    assert s.eval("eps^2").text == "1/100"
    with pytest.raises(ValueError):
        s.symbol("eps")


def test_sympy_refuses_dual_numbers_clearly(s):
    sympy = pytest.importorskip("sympy")
    with pytest.raises(TypeError, match="dual number has no SymPy counterpart"):
        s.eval("x + eps*y").to_sympy()
    with pytest.raises(TypeError, match="dual unit"):
        symrep.from_sympy(sympy.Symbol("eps") + 1, s)
    # the parts convert
    v = s.eval("sin(x + eps*y)")
    x, y = sympy.symbols("x y", real=True)
    assert v.primal().to_sympy() == sympy.sin(x)
    assert v.dual_part().to_sympy() == y * sympy.cos(x)
