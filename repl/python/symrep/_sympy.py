"""symrep._sympy -- Value.to_sympy() (module.cpp calls to_sympy here): a value as a SymPy
object, read from its printed form and checked exact by the engine's == (docs/python.md)."""

import re

_SYMPY_FUNCTIONS = {"abs": "Abs", "step": "Heaviside"}


def to_sympy(value):
    """The value as a SymPy object, read from its printed form and checked exact: the
    engine compares the SymPy result printed back with the value (==) and refuses when
    they differ or cannot be compared. Lists give lists; vector expressions (x, ., |v|)
    and elements have no SymPy form here (TypeError)."""
    import sympy
    from sympy.parsing.sympy_parser import parse_expr

    from . import Error

    if value.kind == "list":
        return [to_sympy(x) for x in value]
    if value.kind == "boolean":
        return sympy.true if value else sympy.false
    if value.kind != "expression":
        raise TypeError("a %s has no SymPy form (to_sympy converts scalar expressions and lists)" % value.kind)
    text = value.text
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
    s = value.session
    try:
        same = value == s.eval(back)
    except Error as x:
        raise TypeError("the SymPy form of %s could not be checked exact (%s)" % (text, x.message)) from None
    if not same:
        raise TypeError("the SymPy form of %s is not exact (%s)" % (text, back))
    return e
