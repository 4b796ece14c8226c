"""symrep: exact solutions of dynamical systems by the algebraic methods (docs/python.md).

    >>> import symrep
    >>> s = symrep.Session()
    >>> w = s.eval("element(multicomplex(1), [1, 2, 3, 4])")
    >>> print(w.inverse())
    ...
    >>> s.eval("vector w, r0, v0; positive w0")
    >>> r = s.eval("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))")
    >>> f = s.compile(r, "t", w=[0, 0, 7.29e-5], w0=0.38, r0=[3, 0, 0], v0=[0, 0, 0])
    >>> f(numpy.linspace(0, 86400, 10**6))          # 10^6 x 3, no Python loop

Session runs statements of the symrep language (docs/language.md); Value is one of its
values, with .text, .latex, .kind, Python operators and every builtin as a method
(v.inverse(), v.charpoly("X")); to_python(), to_sympy() and from_sympy() convert where
exact. The classes and their methods are defined by the compiled module (module.cpp);
this file defines the exceptions (Error and its subclasses, one per typed exception of
the engine, core/error.h) and the session that values without one belong to.
"""

from . import _rules  # noqa: F401  (an installed package: its rule files, SYMREP_RULES_DIR)
import threading
from fractions import Fraction
from typing import List, Optional, Union

from ._symrep import Compiled, Session, Value, caret_text, needs_more_input, version  # noqa: F401

__version__ = version

#: What the API accepts where a value of the language goes (an argument of a method, a
#: variable, a value of compile): NumPy arrays are lists.
ValueLike = Union[Value, bool, int, float, Fraction, str, list, tuple]


class Error(Exception):
    """An error of the engine: the message (the same text the symrep program prints after
    "FILE:LINE:COL: error: "), and where it was (file, line, column, the source line) when it
    comes from a statement; line is None for errors outside a statement. The subclasses
    mirror the engine's typed exceptions (core/error.h)."""

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

    def __reduce__(self):
        return (type(self), (self.message, self.file, self.line, self.column, self.source_line))

    def caret(self):
        """The message, the source line and a caret under the column (as symrep --caret)."""
        text = str(self)
        if self.line is not None and self.source_line:
            text += "\n" + caret_text(self.source_line, self.column).rstrip("\n")
        return text


class ParseError(Error):
    """Malformed statement text (syntax_error): always with its line and column."""


class LanguageTypeError(Error, TypeError):
    """A value of the wrong kind for an operation or a builtin, a wrong number of
    arguments, an unknown name (the language's type_error); also a TypeError."""


class AlgebraError(Error):
    """An algebra that is not what was claimed, elements of different algebras combined
    (algebra_error)."""


class ZeroDivisorError(AlgebraError, ZeroDivisionError):
    """The inverse or logarithm of a zero divisor (zero_divisor_error); .ranks lists the
    vanishing idempotent components (III.1.55, III.3.31). Also a ZeroDivisionError."""

    ranks: List[int] = []


class DomainError(Error, ValueError):
    """A value outside the domain of an operation (domain_error, GiNaC's poles); also a
    ValueError."""


class DivisionByZeroError(DomainError, ZeroDivisionError):
    """A division by zero (1/0); also a ZeroDivisionError."""


class UndecidedError(DomainError):
    """The engine cannot decide a zero test, a sign, an equality or a convergence: it says
    so ("cannot decide ...") instead of guessing."""


class SizeError(Error):
    """A request larger than this machine can hold, or out of memory (size_error)."""


class ClosedFormError(Error):
    """No closed form can be derived by the methods implemented (closed_form_error)."""


class InternalError(Error):
    """A defect of the engine: a result its own check shows wrong, withheld (internal_error)."""


class TimeLimitError(Error):
    """The statement ran longer than the session's time limit."""


class Interrupted(Error, KeyboardInterrupt):
    """Ctrl-C (SIGINT, the notebook's stop button) stopped the engine; also a
    KeyboardInterrupt, so `except Exception` does not swallow it."""


_default = threading.local()
_default_lock = threading.Lock()
_shared = []  # the process's default session, made on first use


def default_session() -> Session:
    """The session that values made without one belong to: unpickled values and
    from_sympy(expr) without a session. One per process (made on first use) unless
    set_default_session() chose another for this thread."""
    s = getattr(_default, "session", None)
    if s is not None:
        return s
    with _default_lock:
        if not _shared:
            _shared.append(Session())
        return _shared[0]


def set_default_session(session: Optional[Session]) -> Optional[Session]:
    """Makes `session` the default session of this thread (None: back to the process's);
    returns the previous choice of this thread. Unpickling a value declares the vector and
    positive symbols it needs in that session."""
    if session is not None and not isinstance(session, Session):
        raise TypeError("set_default_session: a symrep.Session or None, not %s" % type(session).__name__)
    previous = getattr(_default, "session", None)
    _default.session = session
    return previous


def __getattr__(name):
    """symrep.eps: the dual unit (eps^2 = 0) as a Value of the default session, the same
    as default_session().eval("eps") where that session has not assigned eps."""
    if name == "eps":
        return default_session().call("dual", 0, 1)
    raise AttributeError("module %r has no attribute %r" % (__name__, name))


def __dir__():
    """The module's names with eps (made by __getattr__ for the default session of the thread)."""
    return sorted(set(globals()) | {"eps"})


from ._sympy import from_sympy  # noqa: E402

__all__ = ["Session", "Value", "Compiled", "ValueLike", "Error", "ParseError", "LanguageTypeError",
           "AlgebraError", "ZeroDivisorError", "DomainError", "DivisionByZeroError", "UndecidedError",
           "SizeError", "ClosedFormError", "InternalError", "TimeLimitError", "Interrupted",
           "default_session", "set_default_session", "from_sympy", "caret_text", "needs_more_input",
           "version", "__version__"]
