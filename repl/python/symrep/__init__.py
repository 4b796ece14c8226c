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
(v.inverse(), v.charpoly("X")); to_python() and to_sympy() convert where exact. All three
classes, their methods included, are defined by the compiled module (module.cpp).
"""

from . import _rules  # noqa: F401  (an installed package: its rule files, SYMREP_RULES_DIR)
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
