"""symrep._sympy -- SymPy interop by walking the expression trees (docs/python.md):
Value.to_sympy() and Value._sympy_() (sympy.sympify(v)) walk the engine's tree
(Value._tree(), module.cpp), symrep.from_sympy(expr, session) walks SymPy's. No text is
printed and read again. What has no counterpart on the other side raises TypeError
naming it (a vector expression, an element, a function one side lacks)."""

import functools
import operator
from fractions import Fraction

# the functions of the engine (GiNaC's names in the tree) and SymPy's of the same meaning;
# step is 1/2 at 0 in both (sympy.Heaviside's default H0 = 1/2)
_TO_SYMPY = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos", "atan": "atan",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "asinh": "asinh", "acosh": "acosh", "atanh": "atanh",
    "exp": "exp", "log": "log", "abs": "Abs", "step": "Heaviside", "factorial": "factorial",
    "binomial": "binomial", "atan2": "atan2", "tgamma": "gamma", "lgamma": "loggamma", "zeta": "zeta",
}
# SymPy's function -> the language's builtin (the builtins the registry has)
_FROM_SYMPY = {
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos", "atan": "atan",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "exp": "exp", "log": "log", "Abs": "abs",
    "Heaviside": "step", "factorial": "factorial", "binomial": "binomial", "atan2": "atan2",
    "re": "real_part", "im": "imag_part", "conjugate": "conjugate",
}
_CONSTANTS = {"Pi": "pi", "Euler": "EulerGamma", "Catalan": "Catalan"}
_RELATIONS = {"=": "Eq", "!=": "Ne", "<": "Lt", "<=": "Le", ">": "Gt", ">=": "Ge"}


def _no_counterpart(what, text):
    return TypeError("%s has no SymPy counterpart: %s" % (what, text))


def _to(node, sympy):
    tag = node[0]
    if tag == "integer":
        return sympy.Integer(node[1])
    if tag == "rational":
        return sympy.Rational(node[1], node[2])
    if tag == "float":
        text = node[1].replace("E", "e")
        digits = sum(ch.isdigit() for ch in text.split("e")[0])
        return sympy.Float(text, max(15, digits))
    if tag == "complex":
        return _to(node[1], sympy) + sympy.I * _to(node[2], sympy)
    if tag == "symbol":
        if node[2] == "positive":
            return sympy.Symbol(node[1], positive=True)
        if node[2] == "real":
            return sympy.Symbol(node[1], real=True)
        return sympy.Symbol(node[1])
    if tag == "constant":
        if node[1] not in _CONSTANTS:
            raise _no_counterpart("the constant " + node[1], node[1])
        return getattr(sympy, _CONSTANTS[node[1]])
    if tag == "add":
        return sympy.Add(*[_to(k, sympy) for k in node[1]])
    if tag == "mul":
        return sympy.Mul(*[_to(k, sympy) for k in node[1]])
    if tag == "power":
        return sympy.Pow(_to(node[1], sympy), _to(node[2], sympy))
    if tag == "function":
        name = node[1]
        if name not in _TO_SYMPY:
            raise TypeError("the function %s has no SymPy counterpart here" % name)
        return getattr(sympy, _TO_SYMPY[name])(*[_to(k, sympy) for k in node[2]])
    if tag == "relation":
        return getattr(sympy, _RELATIONS[node[1]])(_to(node[2], sympy), _to(node[3], sympy))
    if tag == "matrix":
        return sympy.Matrix(node[1], node[2], [_to(k, sympy) for k in node[3]])
    if tag == "list":
        return [_to(k, sympy) for k in node[1]]
    if tag == "boolean":
        return sympy.true if node[1] else sympy.false
    if tag == "string":
        raise _no_counterpart("a symrep string", repr(node[1]))
    if tag == "vector":
        raise _no_counterpart(node[1], node[2])
    if tag == "dual":
        raise TypeError("a dual number has no SymPy counterpart (symrep's eps squares to 0, a SymPy symbol "
                        "does not): %s; convert primal(v) and dual_part(v) separately" % node[1])
    raise _no_counterpart("a symrep " + node[1], node[2])


def to_sympy(value):
    """The value as a SymPy object by a walk of its expression tree: numbers (floats with
    their digits), symbols (real, positive=True where declared positive), +, *, ^, the
    elementary functions, relations (Eq), matrices and vector literals (sympy.Matrix),
    booleans; a list gives a Python list. A vector expression (x, ., |v|), an element, an
    algebra, a string or a function SymPy lacks here raises TypeError naming it."""
    import sympy

    return _to(value._tree(), sympy)


def from_sympy(expr, session=None):
    """A SymPy object as a symrep.Value of `session` (default: symrep.default_session()), by
    a walk of SymPy's tree: Integer and Rational (exact), Float (a double where it has at
    most 53 bits, else evalf of its exact binary value at its digits), Symbol (the session's
    symbol of that name), Add, Mul, Pow, the functions the language has, pi, E, I, Eq,
    Matrix (matrix([[...]])), Tuple and Python lists (lists), true/false. Anything else
    raises TypeError naming it (oo, a Derivative, an undefined function, ...)."""
    import sympy

    from . import Value, default_session

    s = session if session is not None else default_session()
    return _from(expr, s, sympy, Value)


def _from(e, s, sympy, Value):
    if isinstance(e, Value):
        if e.session is not s:
            raise TypeError("from_sympy: a symrep.Value of another session")
        return e
    if isinstance(e, (list, tuple, sympy.Tuple)):
        return s.value([_from(x, s, sympy, Value) for x in e])
    if isinstance(e, bool):
        return s.value(e)
    if isinstance(e, (int, Fraction)):
        return s.value(e)
    if isinstance(e, float):
        return s.value(e)
    if isinstance(e, sympy.MatrixBase):
        rows = [[_from(e[i, j], s, sympy, Value) for j in range(e.cols)] for i in range(e.rows)]
        return s.call("matrix", rows)
    if not isinstance(e, sympy.Basic):
        raise TypeError("from_sympy: a Python %s is no SymPy expression" % type(e).__name__)
    if e is sympy.true or e is sympy.false:
        return s.value(bool(e))
    if isinstance(e, sympy.Integer):
        return s.value(int(e))
    if isinstance(e, sympy.Rational):
        return s.value(Fraction(int(e.p), int(e.q)))
    if isinstance(e, sympy.Float):
        if e._prec <= 53:
            return s.value(float(e))
        sign, man, exp, _ = e._mpf_
        exact = Fraction((-1) ** sign * man) * (Fraction(2) ** exp)
        from mpmath.libmp import prec_to_dps

        return s.call("evalf", s.value(exact), max(17, int(prec_to_dps(e._prec))))
    if e is sympy.pi:
        return s.eval("pi")
    if e is sympy.E:
        return s.call("exp", 1)
    if e is sympy.I:
        return s.eval("I")
    if isinstance(e, sympy.Symbol):
        if e.name == "eps":
            raise TypeError("from_sympy: the SymPy symbol eps would be symrep's dual unit eps (eps^2 = 0), which "
                            "it is not; rename it, or build a dual number with symrep's dual(a, b)")
        try:
            return s.symbol(e.name)
        except ValueError:
            raise TypeError("from_sympy: the symbol %r is no name of the symrep language" % e.name) from None
    if isinstance(e, sympy.Add):
        return functools.reduce(operator.add, [_from(a, s, sympy, Value) for a in e.args])
    if isinstance(e, sympy.Mul):
        return functools.reduce(operator.mul, [_from(a, s, sympy, Value) for a in e.args])
    if isinstance(e, sympy.Pow):
        return _from(e.base, s, sympy, Value) ** _from(e.exp, s, sympy, Value)
    if isinstance(e, sympy.Equality):
        return _from(e.lhs, s, sympy, Value)._op("=", _from(e.rhs, s, sympy, Value))
    if isinstance(e, sympy.Heaviside) and len(e.args) == 2 and e.args[1] != sympy.Rational(1, 2):
        raise TypeError("from_sympy: Heaviside with H0 = %s has no counterpart (step(0) is 1/2)" % e.args[1])
    if isinstance(e, sympy.Function) and type(e).__name__ in _FROM_SYMPY and not isinstance(e, sympy.core.function.AppliedUndef):
        args = e.args[:1] if isinstance(e, sympy.Heaviside) else e.args
        return s.call(_FROM_SYMPY[type(e).__name__], *[_from(a, s, sympy, Value) for a in args])
    raise TypeError("from_sympy: %s has no counterpart in the symrep language (%s)" % (type(e).__name__, e))
