"""symrep._methods -- the builtins as methods of Value (v.inverse()) and the pickling of
values (module.cpp calls bound_builtin and reduce_value; docs/python.md).

A builtin reached as a method is a Python function named after the builtin, with the
builtin's help as its docstring (help(v.inverse) shows the text of `symrep --doc` and
`help inverse`) and a signature read from the registry's (inspect.signature, IPython's
Shift-Tab): the value itself is the builtin's first argument, the others are positional
and typed symrep.ValueLike, the result a symrep.Value."""

import functools
import inspect
import keyword
import re

_ANNOTATION = "symrep.ValueLike"
_RESULT = "symrep.Value"


def _split_arguments(text):
    """The top-level arguments of a signature's argument text, brackets removed:
    "w [, t]" -> ["w", "t"]."""
    text = text.replace("[,", ",").replace("[ ,", ",")
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth <= 0:
            out.append(cur)
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur)
    return [a.strip().strip("[]").strip() for a in out]


@functools.lru_cache(maxsize=None)
def signature_of(name, signature, min_args, max_args, options=()):
    """The inspect.Signature of builtin `name` as a method: its first argument is the value.
    The parameter names come from the form of the registry's signature with the most
    arguments ("exp(x) / exp(w [, t])" -> t); optional ones default to None (left out).
    The builtin's options (view = "3d" in the language) are keyword-only, default None."""
    best = []
    for form in signature.split(" / "):
        m = re.match(r"^\s*[A-Za-z_]\w*\s*\((.*)\)\s*$", form.strip())
        if m:
            args = _split_arguments(m.group(1))
            if len(args) > len(best):
                best = args
    variadic = max_args < 0
    n = min_args if variadic else max_args
    names, params = [], []
    for i in range(1, n):
        a = best[i] if i < len(best) else ""
        nm = re.sub(r"\W", "", a.split("=")[0].strip()) if re.match(r"^[A-Za-z_]\w*\s*(=.*)?$", a) else ""
        if not nm or keyword.iskeyword(nm) or nm in names or nm == "self":
            nm = "arg%d" % (i + 1)
        names.append(nm)
        params.append(inspect.Parameter(nm, inspect.Parameter.POSITIONAL_ONLY,
                                        default=inspect.Parameter.empty if i < min_args else None,
                                        annotation=_ANNOTATION))
    if variadic:
        params.append(inspect.Parameter("args", inspect.Parameter.VAR_POSITIONAL, annotation=_ANNOTATION))
    for o in options:
        params.append(inspect.Parameter(o, inspect.Parameter.KEYWORD_ONLY, default=None, annotation=_ANNOTATION))
    return inspect.Signature(params, return_annotation=_RESULT)


def bound_builtin(value, name):
    """v.name: the builtin name(v, ...) as a function with the builtin's help and signature."""
    sig, doc, lo, hi, options = value.session._builtin_info(name)

    def method(*args, **kwargs):
        args = list(args)
        while len(args) + 1 > lo and args and args[-1] is None:  # an optional argument left out
            args.pop()
        given = {k: x for k, x in kwargs.items() if x is not None}  # an option left out
        return value.call(name, *args, **given)

    method.__name__ = name
    method.__qualname__ = "Value." + name
    method.__module__ = "symrep"
    method.__doc__ = doc
    method.__signature__ = signature_of(name, sig, lo, hi, tuple(options))
    return method


# --- pickling -------------------------------------------------------------------------

_PICKLED_KINDS = ("expression", "boolean", "string", "list")


def _check_picklable(v):
    if v.kind == "list":
        for x in v:
            _check_picklable(x)
    elif v.kind not in _PICKLED_KINDS:
        raise TypeError("cannot pickle a symrep %s (%s): its text does not read back as the same value; "
                        "expressions, booleans, strings and lists of them pickle" % (v.kind, v.text))


def reduce_value(v):
    """Value.__reduce__: the canonical text, the kind and the declarations (vector and
    positive symbols) the text needs to be read back."""
    _check_picklable(v)
    vectors, positives = v._declarations()
    return (restore_value, (v.text, v.kind, tuple(vectors), tuple(positives)))


def restore_value(text, kind, vectors=(), positives=(), session=None):
    """A pickled value read back into `session` (default: symrep.default_session()), after
    declaring its vector and positive symbols there; refused (pickle.UnpicklingError) when
    the value read back does not print as the pickled text (a variable of the session with
    the name of one of its symbols, a declaration that clashes)."""
    import pickle

    from . import Error, default_session

    s = session if session is not None else default_session()
    try:
        if kind == "string":
            return s.value(text)
        if vectors:
            s.eval("vector " + ", ".join(vectors))
        if positives:
            s.eval("positive " + ", ".join(positives))
        v = s.eval(text)
    except Error as e:
        raise pickle.UnpicklingError("cannot restore the symrep %s %s: %s" % (kind, text, e)) from None
    if v is None or v.kind != kind or v.text != text:
        raise pickle.UnpicklingError("cannot restore the symrep %s %s: in this session it reads as %s (a variable "
                                     "named like one of its symbols?)" % (kind, text, "nothing" if v is None else v.text))
    return v
