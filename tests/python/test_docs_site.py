"""tests/python/test_docs_site.py -- the docs site's parts that are Python: the Pygments lexer
(repl/python/symrep/lexer.py) and the ```python examples of docs/*.md, run against the built
module. The site itself is built by ctest's docs.site (docs/build_site.py, warnings are errors);
the symrep examples of the pages run in tests/test_docs_examples.cpp."""
import glob
import importlib.util
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

pygments = pytest.importorskip("pygments")
from pygments.token import Comment, Error, Keyword, Name, Number, Operator, Punctuation, String  # noqa: E402

LEXER_FILE = os.path.join(SOURCE_DIR, "repl", "python", "symrep", "lexer.py")


def _load_lexer():
    # by its path, as docs/conf.py loads it (no compiled module needed)
    spec = importlib.util.spec_from_file_location("symrep_lexer_under_test", LEXER_FILE)
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


lexer_module = _load_lexer()


def tokens(text):
    """The tokens of text without the whitespace ones."""
    return [(t, v) for t, v in lexer_module.SymrepLexer().get_tokens(text) if v.strip()]


def test_lexer_reads_declarations_assignments_and_operators():
    assert tokens("vector w, r0, v0; positive w0") == [
        (Keyword.Declaration, "vector"), (Name.Variable, "w"), (Punctuation, ","), (Name.Variable, "r0"),
        (Punctuation, ","), (Name.Variable, "v0"), (Punctuation, ";"),
        (Keyword.Declaration, "positive"), (Name.Variable, "w0")]
    assert tokens("P := ode(r'' + 2*w x r' = 0, r(0) = r0)  # the ODE") == [
        (Name.Variable, "P"), (Operator, ":="), (Name.Builtin, "ode"), (Punctuation, "("),
        (Name, "r"), (Operator, "''"), (Operator, "+"), (Number.Integer, "2"), (Operator, "*"),
        (Name, "w"), (Operator.Word, "x"), (Name, "r"), (Operator, "'"), (Operator, "="),
        (Number.Integer, "0"), (Punctuation, ","), (Name, "r"), (Punctuation, "("), (Number.Integer, "0"),
        (Punctuation, ")"), (Operator, "="), (Name, "r0"), (Punctuation, ")"), (Comment.Single, "# the ODE")]
    # x is the cross product after an operand only: a symbol elsewhere
    assert tokens("(a x b) . c == x^2")[:8] == [
        (Punctuation, "("), (Name, "a"), (Operator.Word, "x"), (Name, "b"), (Punctuation, ")"),
        (Operator, "."), (Name, "c"), (Operator, "==")]
    assert tokens("x^2")[0] == (Name, "x")
    assert tokens("vector q(t)") == [(Keyword.Declaration, "vector"), (Name.Variable, "q"), (Punctuation, "("),
                                     (Name, "t"), (Punctuation, ")")]


def test_lexer_reads_numbers_strings_constants_and_results():
    assert tokens('print("a \\"b\\"", 3/4, 0.5, 1e-3, .5, 3., pi, I, true, %, %%, %3)') == [
        (Name.Builtin, "print"), (Punctuation, "("), (String.Double, '"'), (String.Double, "a "),
        (String.Escape, '\\"'), (String.Double, "b"), (String.Escape, '\\"'), (String.Double, '"'),
        (Punctuation, ","), (Number.Integer, "3"), (Operator, "/"), (Number.Integer, "4"), (Punctuation, ","),
        (Number.Float, "0.5"), (Punctuation, ","), (Number.Float, "1e-3"), (Punctuation, ","),
        (Number.Float, ".5"), (Punctuation, ","), (Number.Float, "3."), (Punctuation, ","),
        (Keyword.Constant, "pi"), (Punctuation, ","), (Keyword.Constant, "I"), (Punctuation, ","),
        (Keyword.Constant, "true"), (Punctuation, ","), (Name.Variable.Magic, "%"), (Punctuation, ","),
        (Name.Variable.Magic, "%%"), (Punctuation, ","), (Name.Variable.Magic, "%3"), (Punctuation, ")")]
    # the Unicode products, a name that merely starts like a builtin, a builtin's name assigned
    assert tokens("a \u00d7 b \u00b7 c") == [(Name, "a"), (Operator, "\u00d7"), (Name, "b"), (Operator, "\u00b7"),
                                            (Name, "c")]
    assert tokens("sinx + det := 2")[0] == (Name, "sinx")
    assert tokens("det := 2")[0] == (Name.Variable, "det")


def test_lexer_marks_what_the_language_refuses():
    for bad in ('a $ b', 'f{x}', 'print("open\nx', 'caf\u00e9'):
        assert any(t in Error for t, v in lexer_module.SymrepLexer().get_tokens(bad)), bad


def test_every_example_script_lexes_without_error_tokens():
    scripts = sorted(glob.glob(os.path.join(SOURCE_DIR, "examples", "*.symrep")))
    assert len(scripts) >= 10
    for path in scripts:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        bad = [(t, v) for t, v in lexer_module.SymrepLexer().get_tokens(text) if t in Error]
        assert not bad, (path, bad[:5])


def test_lexer_builtins_are_the_registry():
    symrep = pytest.importorskip("symrep")
    current = set(symrep.Session().builtin_names())
    listed = set(lexer_module.BUILTINS)
    assert listed == current, (
        "symrep/lexer.py's BUILTINS differ from the registry: missing %s, extra %s; regenerate: "
        "PYTHONPATH=build/python python3 -m symrep.lexer" % (sorted(current - listed), sorted(listed - current)))


def test_lexer_works_without_the_compiled_module_and_through_pygments():
    # a fresh interpreter that cannot import symrep at all: the lexer file alone
    code = ("import importlib.util, sys\n"
            "spec = importlib.util.spec_from_file_location('lx', sys.argv[1])\n"
            "m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n"
            "print(m.SymrepLexer.name, len(list(m.SymrepLexer().get_tokens('w := 1'))))\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    r = subprocess.run([sys.executable, "-c", code, LEXER_FILE], capture_output=True, text=True, env=env,
                       cwd="/")
    assert r.returncode == 0 and r.stdout.startswith("symrep "), r.stderr
    # as a package module (the pygments entry point names symrep.lexer:SymrepLexer)
    lexer = pytest.importorskip("symrep.lexer")
    from pygments import highlight
    from pygments.formatters import HtmlFormatter
    html = highlight("w := element(multicomplex(0), [1, 2])  # w\n", lexer.SymrepLexer(), HtmlFormatter())
    assert 'class="nb">element<' in html and 'class="c1"># w<' in html


# --- the ```python examples of the docs -------------------------------------------------------

_FENCE = re.compile(r"^[ \t]*```(.*)$")


def python_blocks(path):
    """[(line, flags, code)] of the ```python blocks of one page."""
    out, lines, info, start = [], None, None, 0
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = _FENCE.match(line)
            if m and lines is None:
                info, start, lines = m.group(1).split(), n, []
            elif m:
                if info and info[0] == "python":
                    out.append((start, info[1:], "".join(lines)))
                lines = None
            elif lines is not None:
                lines.append(line)
    return out


def test_every_python_example_of_the_docs_runs(tmp_path, monkeypatch):
    """The ```python blocks of a page run in order in one namespace (a page reads as one
    session), against the built module, in a scratch directory. A block that cannot run here
    says why at its fence: ```python norun (and the text around it gives the reason)."""
    pytest.importorskip("symrep")
    monkeypatch.chdir(tmp_path)
    ran = 0
    for page in sorted(glob.glob(os.path.join(SOURCE_DIR, "docs", "*.md"))):
        namespace = {"__name__": "__docs__"}
        for line, flags, code in python_blocks(page):
            assert set(flags) <= {"norun"}, (page, line, flags)
            if "norun" in flags:
                continue
            try:
                exec(compile(code, "%s:%d" % (os.path.basename(page), line), "exec"), namespace)
            except Exception as e:  # pragma: no cover - the message names the block
                pytest.fail("%s:%d: the example raised %s: %s" % (page, line, type(e).__name__, e))
            ran += 1
    assert ran >= 3
