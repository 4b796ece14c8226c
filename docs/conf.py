# The Sphinx configuration of the documentation site (MyST pages, nbsphinx notebooks, autodoc of
# the Python module, the symrep lexer). Built by `bash build.sh docs`, which runs
# docs/build_site.py: it stages the sources in BUILD_DIR/docs/src (the pages of docs/, the
# language page with the `symrep --doc` of the built program, the executed notebooks) and runs
# sphinx-build -W -c docs there; SYMREP_BUILD_DIR names the build tree whose module autodoc reads.
import importlib.util
import os
import sys

_here = os.path.dirname(os.path.abspath(__file__))
_source = os.path.dirname(_here)
_build = os.environ.get("SYMREP_BUILD_DIR", os.path.join(_source, "build"))
sys.path.insert(0, os.path.join(_build, "python"))

# The lexer, loaded from its file: it needs Pygments only, not the compiled module.
_spec = importlib.util.spec_from_file_location("symrep_docs_lexer",
                                               os.path.join(_source, "repl", "python", "symrep", "lexer.py"))
_lexer = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_lexer)

project = "symrep"
author = "the symrep authors"
copyright = "the symrep authors"
try:
    import symrep
    release = version = symrep.__version__
except Exception:  # the pages still build; autodoc then reports the missing module
    release = version = ""

extensions = ["myst_parser", "nbsphinx", "sphinx.ext.autodoc", "sphinx.ext.mathjax"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "**.ipynb_checkpoints", "language.prose.md"]

# Code blocks without a language (and the indented examples of the function reference) are
# symrep; other languages are named at the fence (```sh, ```cpp, ```python, ```text).
highlight_language = "symrep"
pygments_style = "sphinx"

myst_heading_anchors = 3           # [text](page.md#a-heading) links, as on GitHub

# The notebooks are executed by build_site.py (with the symrep kernel on the built module),
# so that the tests' own notebook runs and this build do not depend on each other.
nbsphinx_execute = "never"
nbsphinx_codecell_lexer = "symrep"

autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": True, "show-inheritance": True}

try:
    import sphinx_rtd_theme  # noqa: F401  (Debian: python3-sphinx-rtd-theme)
    html_theme = "sphinx_rtd_theme"
except ImportError:
    html_theme = "alabaster"
html_title = "symrep " + version if version else "symrep"
html_static_path = []
# The formulas (the notebooks' LaTeX results): Debian's MathJax 2 (libjs-mathjax), offline;
# build_site.py links it as _static/mathjax. nbsphinx fills mathjax2_config's delimiters.
if os.path.exists("/usr/share/javascript/mathjax/MathJax.js"):
    mathjax_path = "mathjax/MathJax.js?config=TeX-AMS-MML_HTMLorMML"
    mathjax2_config = {}
html_show_sourcelink = False


def _verbatim_docstring(app, what, name, obj, options, lines):
    # The module's docstrings are plain text written for help() (the function reference's
    # text, formulas with * and _): shown verbatim, never read as reStructuredText.
    if not lines:
        return
    text = list(lines)
    lines[:] = [".. code-block:: text", ""] + ["   " + l if l.strip() else "" for l in text] + [""]


def _list_every_page(app, docname, source):
    # A page of docs/ that index.md does not list (a new one) goes under "More", so that every
    # page is in the site (Sphinx warns about a page outside every toctree; -W fails on it).
    if docname != root_doc:
        return
    listed = set(l.strip() for l in source[0].splitlines())
    extra = sorted(d for d in app.env.found_docs
                   if d != root_doc and d not in listed and not d.startswith("notebooks/"))
    if extra:
        source[0] += "\n```{toctree}\n:maxdepth: 1\n:caption: More\n\n" + "\n".join(extra) + "\n```\n"


def setup(app):
    app.connect("source-read", _list_every_page)
    app.add_lexer("symrep", _lexer.SymrepLexer)
    app.connect("autodoc-process-docstring", _verbatim_docstring)
