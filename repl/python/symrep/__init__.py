"""symrep: exact solutions of dynamical systems by the algebraic methods (docs/python.md).

    >>> import symrep
    >>> s = symrep.Session()
    >>> w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    >>> print(w.inverse())
    ...
    >>> s.eval("vector w, r0, v0; positive w0")
    >>> r = s.eval("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))")
    >>> f = s.compile(r, ["t"], {"w": [0, 0, 7.29e-5], "w0": 0.38, "r0": [3, 0, 0], "v0": [0, 0, 0]})
    >>> f(t=numpy.linspace(0, 86400, 10**6))          # 10^6 x 3, no Python loop

Session runs statements of the symrep language (docs/language.md); Value is one of its
values, with .text, .latex, .kind, Python operators and every builtin as a method
(v.inverse(), v.charpoly("X")); to_python() and to_sympy() convert where exact.
"""

import re
from fractions import Fraction as _Fraction

from ._symrep import Compiled, Session, Value, caret_text, needs_more_input, version  # noqa: F401

__all__ = ["Session", "Value", "Compiled", "Error", "version"]
__version__ = version


class Error(Exception):
    """An error of the engine: the message, and where it was (file, line, column, the source
    line) when it comes from a statement; line is None for errors outside a statement."""

    def __init__(self, message, file=None, line=None, column=None, source_line=None):
        super().__init__(message)
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        self.source_line = source_line

    def __str__(self):
        if self.line is None:
            return self.message
        return "%s:%d:%d: error: %s" % (self.file, self.line, self.column, self.message)

    def caret(self):
        """The message, the source line and a caret under the column (as symrep --caret)."""
        text = str(self)
        if self.line is not None and self.source_line:
            text += "\n" + caret_text(self.source_line, self.column).rstrip("\n")
        return text


def _to_python(self):
    """The value as a Python object where that is exact: bool, int, fractions.Fraction,
    float (a floating-point value), complex, str, None, lists of these. A symbolic
    expression, an element or a problem raises TypeError (use .text, .latex, to_sympy())."""
    b = self._bool()
    if b is not None:
        return b
    if self._is_none():
        return None
    st = self._string()
    if st is not None:
        return st
    items = self._items()
    if items is not None:
        return [x.to_python() for x in items]
    n = self._number()
    if n is not None:
        if n[0] == "rational":
            q = _Fraction(int(n[1]), int(n[2]))
            return q.numerator if q.denominator == 1 else q
        if n[0] == "real":
            return n[1]
        if n[0] == "gaussian":
            return complex(_Fraction(int(n[1]), int(n[2])), _Fraction(int(n[3]), int(n[4])))
        return complex(n[1], n[2])
    raise TypeError("%s has no exact Python number form: %s (use .text, .latex or to_sympy())"
                    % (self.kind, self.text))


_SYMPY_FUNCTIONS = {"abs": "Abs", "step": "Heaviside"}


def _to_sympy(self):
    """The value as a SymPy object, read from its printed form and checked exact: the
    engine compares the SymPy result printed back with the value (==) and refuses when
    they differ or cannot be compared. Lists give lists; vector expressions (x, ., |v|)
    and elements have no SymPy form here (TypeError)."""
    import sympy
    from sympy.parsing.sympy_parser import parse_expr

    items = self._items()
    if items is not None:
        return [x.to_sympy() for x in items]
    if self.kind == "boolean":
        return sympy.true if self._bool() else sympy.false
    if self.kind != "expression":
        raise TypeError("a %s has no SymPy form (to_sympy converts scalar expressions and lists)" % self.kind)
    text = self.text
    if " x " in text or " . " in text or "|" in text or "[" in text:
        raise TypeError("a vector expression has no SymPy form: " + text)
    names = {}
    for name in set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", text)):
        if name in _SYMPY_FUNCTIONS:
            names[name] = getattr(sympy, _SYMPY_FUNCTIONS[name])
        elif name in ("I", "pi"):
            names[name] = getattr(sympy, name)
        elif hasattr(sympy.functions, name) and re.search(r"\b%s\(" % re.escape(name), text):
            names[name] = getattr(sympy, name)
        else:
            names[name] = sympy.Symbol(name, real=True)
    try:
        e = parse_expr(text.replace("^", "**"), local_dict=names, evaluate=True)
    except Exception as x:  # a printed form SymPy does not read
        raise TypeError("no SymPy form for %s (%s)" % (text, x)) from None
    back = sympy.sstr(e, full_prec=True).replace("**", "^").replace("Abs(", "abs(").replace("Heaviside(", "step(")
    s = self.session
    try:
        same = self == s.eval(back)
    except Error as x:
        raise TypeError("the SymPy form of %s could not be checked exact (%s)" % (text, x.message)) from None
    if not same:
        raise TypeError("the SymPy form of %s is not exact (%s)" % (text, back))
    return e


def _getattr(self, name):
    if name.startswith("_"):
        raise AttributeError(name)
    if name not in self.session.builtin_names():
        raise AttributeError("'%s' is neither an attribute of a symrep value nor a builtin" % name)

    def method(*args):
        return self.call(name, *args)

    method.__name__ = name
    method.__doc__ = self.session.help(name)
    return method


def _compile(self, expression, inputs, values=None, stable=False):
    """Compiles a closed form (a Value, or statements whose last value is one) in the named
    inputs; see Compiled.__call__."""
    if isinstance(expression, str):
        expression = self.eval(expression)
    if isinstance(inputs, str):
        inputs = [inputs]
    return self._compile(expression, list(inputs), values, stable)


def _bool(self):
    # only a boolean has a truth value: `if s.eval("check(P, r)"):` must not be true for false
    b = self._bool()
    if b is None:
        raise TypeError("the truth value of a symrep %s is not defined (only booleans have one): %s"
                        % (self.kind, self.text))
    return b


def _float(self):
    """float(v) for a real number, exact or not (evalf at the session's Digits)."""
    x = self if self._number() is not None else self.call("evalf")
    n = x._number()
    if n is None or n[0] in ("gaussian", "complex"):
        raise TypeError("not a real number: %s" % self.text)
    return float(_Fraction(int(n[1]), int(n[2]))) if n[0] == "rational" else n[1]


def _items_or_raise(self):
    items = self._items()
    if items is None:
        raise TypeError("a symrep %s is not a list" % self.kind)
    return items


Value.to_python = _to_python
Value.__bool__ = _bool
Value.__float__ = _float
Value.__len__ = lambda self: len(_items_or_raise(self))
Value.__getitem__ = lambda self, k: _items_or_raise(self)[k]
Value.__iter__ = lambda self: iter(_items_or_raise(self))
Value.to_sympy = _to_sympy
Value.__getattr__ = _getattr
Session._compile = Session.compile
Session.compile = _compile
