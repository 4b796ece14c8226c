#!/usr/bin/env python3
"""Builds the documentation site (Sphinx + MyST + nbsphinx) into BUILD_DIR/docs/html.

    /usr/bin/python3 docs/build_site.py BUILD_DIR [--no-execute]      (bash build.sh docs runs it)

BUILD_DIR holds the built program (symrep) and the Python module (python/symrep). The Sphinx
sources are staged in BUILD_DIR/docs/src, so that nothing is written into the source tree:
- every page of docs/ (linked), with docs/conf.py as the configuration (sphinx-build -c docs);
- language.md made as docs/regen_language_md.sh makes it, from language.prose.md and the
  `symrep --doc` of the built program: the function reference is the registry's, never a copy;
- the notebooks of examples/notebooks, executed here with the symrep kernel (a kernel spec in a
  temporary JUPYTER_PATH on the built module), so that the site shows their outputs; nbsphinx
  itself never executes (nbsphinx_execute = "never"). An error cell fails the build.
  --no-execute stages them as stored (without outputs) instead.
- MathJax: Debian's libjs-mathjax, linked as html/_static/mathjax, so that the formulas are
  typeset without a network (to publish the site elsewhere, copy it with cp -rL).
sphinx-build runs with -W (a warning is an error) and -E (a fresh environment: the reference
and the notebooks are regenerated each time). ctest's docs.site runs this script.
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(SOURCE, "docs")
MATHJAX = "/usr/share/javascript/mathjax/MathJax.js"  # Debian's libjs-mathjax (MathJax 2)


def stage_pages(src, program):
    for name in sorted(os.listdir(DOCS)):
        if name in ("language.md", "language.prose.md", "conf.py", "build_site.py") or name.startswith("."):
            continue
        os.symlink(os.path.join(DOCS, name), os.path.join(src, name))
    reference = subprocess.run([program, "--doc"], check=True, capture_output=True, text=True).stdout
    # The registry's texts are plain text (help() shows them in a terminal): formulas such as
    # L[f^2](0) are not Markdown links, so their ']( ' is escaped for the site.
    def unlink(line):
        if line.startswith("    "):  # an example (a code block)
            return line
        parts = line.split("`")      # outside code spans only
        return "`".join(p if k % 2 else p.replace("](", "]\\(") for k, p in enumerate(parts))
    reference = "\n".join(unlink(l) for l in reference.split("\n"))
    with open(os.path.join(DOCS, "language.prose.md"), encoding="utf-8") as f:
        prose = f.read()
    with open(os.path.join(src, "language.md"), "w", encoding="utf-8") as f:
        f.write(prose + reference)


def stage_notebooks(src, python_dir, execute):
    books = os.path.join(SOURCE, "examples", "notebooks")
    out = os.path.join(src, "notebooks")
    os.makedirs(out)
    names = sorted(n for n in os.listdir(books) if n.endswith(".ipynb"))
    if not execute:
        for n in names:
            shutil.copy(os.path.join(books, n), os.path.join(out, n))
        return
    import nbformat
    from nbconvert.preprocessors import ExecutePreprocessor
    with tempfile.TemporaryDirectory(prefix="symrep-docs-") as root:
        spec = os.path.join(root, "kernels", "symrep")
        os.makedirs(spec)
        with open(os.path.join(spec, "kernel.json"), "w") as f:
            json.dump({"argv": [sys.executable, "-Xfrozen_modules=off", "-m", "symrep.kernel", "-f",
                                "{connection_file}"],
                       "display_name": "symrep", "language": "symrep", "interrupt_mode": "signal",
                       "env": {"PYTHONPATH": python_dir}}, f)
        for k, d in (("JUPYTER_PATH", ""), ("JUPYTER_RUNTIME_DIR", "runtime"), ("JUPYTER_DATA_DIR", "data"),
                     ("IPYTHONDIR", "ipython")):
            os.environ[k] = os.path.join(root, d)
        for n in names:
            t = time.monotonic()
            nb = nbformat.read(os.path.join(books, n), as_version=4)
            ExecutePreprocessor(timeout=300, kernel_name="symrep").preprocess(nb, {"metadata": {"path": out}})
            errors = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
            if errors:
                sys.exit("docs: %s: a cell failed: %s" % (n, errors[0].get("evalue", "")))
            # the cells are symrep whatever lexer the kernel names (the contract: "symrep")
            nb.metadata.setdefault("language_info", {})["pygments_lexer"] = "symrep"
            nbformat.write(nb, os.path.join(out, n))
            print("docs: executed %s (%.1f s)" % (n, time.monotonic() - t), flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build_dir")
    ap.add_argument("--no-execute", action="store_true", help="stage the notebooks without running them")
    a = ap.parse_args()
    build = os.path.abspath(a.build_dir)
    program = os.path.join(build, "symrep")
    python_dir = os.path.join(build, "python")
    out = os.path.join(build, "docs")
    src = os.path.join(out, "src")
    shutil.rmtree(src, ignore_errors=True)
    os.makedirs(src)
    stage_pages(src, program)
    stage_notebooks(src, python_dir, not a.no_execute)
    env = dict(os.environ, SYMREP_BUILD_DIR=build, PYTHONDONTWRITEBYTECODE="1")
    t = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
                        "-c", DOCS, "-d", os.path.join(out, "doctrees"), src, os.path.join(out, "html")], env=env)
    if r.returncode != 0:
        sys.exit("docs: sphinx-build failed (warnings are errors)")
    if os.path.exists(MATHJAX):  # the formulas typeset offline (docs/conf.py: mathjax_path)
        link = os.path.join(out, "html", "_static", "mathjax")
        if not os.path.islink(link):
            os.symlink(os.path.dirname(MATHJAX), link)
    print("docs: built in %.1f s: %s" % (time.monotonic() - t, os.path.join(out, "html", "index.html")))


if __name__ == "__main__":
    main()
