"""tests/python/test_notebooks.py -- examples/notebooks/signals.ipynb and identification.ipynb executed
together with nbclient and the symrep kernel (the build tree's spec in a temporary JUPYTER_PATH): no error
cell, and a few results checked by another route (SymPy, or the numbers the thesis gives)."""
import os
import re
import shutil
from fractions import Fraction

import nbformat
import pytest
import symrep.kernel
import sympy
from conftest import SOURCE_DIR


NOTEBOOKS = ("signals.ipynb", "identification.ipynb")


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    """Both notebooks executed at once (each with its own kernel): name -> (results, images, folder)."""
    import asyncio

    from nbclient import NotebookClient

    root = tmp_path_factory.mktemp("notebooks")
    symrep.kernel.install(prefix=str(root), build_tree=True)
    saved = {k: os.environ.get(k) for k in ("JUPYTER_PATH", "JUPYTER_RUNTIME_DIR", "JUPYTER_DATA_DIR")}
    os.environ["JUPYTER_PATH"] = str(root / "share" / "jupyter")
    os.environ["JUPYTER_RUNTIME_DIR"] = str(root / "runtime")
    os.environ["JUPYTER_DATA_DIR"] = str(root / "data")
    books = {}
    for name in NOTEBOOKS:
        folder = root / name.split(".")[0]
        folder.mkdir()
        shutil.copy(os.path.join(SOURCE_DIR, "examples", "notebooks", name), folder / name)
        books[name] = (nbformat.read(str(folder / name), as_version=4), folder)

    async def run_all():
        await asyncio.gather(*(NotebookClient(nb, timeout=300, kernel_name="symrep",
                                              resources={"metadata": {"path": str(folder)}}).async_execute()
                               for nb, folder in books.values()))

    try:
        asyncio.run(run_all())
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    out = {}
    for name, (nb, folder) in books.items():
        code = [c for c in nb.cells if c.cell_type == "code"]
        assert all(c.execution_count for c in code), name
        outputs = [o for c in code for o in c.outputs]
        errors = [o for o in outputs if o.output_type == "error"]
        assert not errors, errors[0].traceback
        results = [o.data["text/plain"] for o in outputs if o.output_type == "execute_result"]
        images = [o for o in outputs if o.output_type == "display_data" and "image/png" in o.data]
        out[name] = (results, images, folder)
    return out


def expr(text, **names):
    return sympy.sympify(text.replace("^", "**"), locals={k: sympy.Symbol(k, real=True) for k in names} | {
        "I": sympy.I, "pi": sympy.pi})


def test_the_signals_notebook(executed):
    results, images, folder = executed["signals.ipynb"]
    t, s, z, X = sympy.symbols("t s z X", real=True)
    # the least equation of f = e^-t (3 cos 2t + sin 2t): p(D) f = 0 (SymPy), p of degree 2
    f = sympy.exp(-t) * (3 * sympy.cos(2 * t) + sympy.sin(2 * t))
    p = expr(results[0], X=1)
    assert sympy.degree(p, X) == 2
    assert sympy.simplify(sum(p.coeff(X, k) * sympy.diff(f, t, k) for k in range(3))) == 0
    # every check the notebook shows is true; the signal of (v^2 + 2 v + 5) w vanishes
    assert results.count("true") == 3 and results[4] == "0"
    # the resonant response x = t sin(2t)/4: x'' + 4 x = cos 2t, x(0) = x'(0) = 0
    x = expr(next(r for r in results if "sin(2*t)*t" in r or "t*sin(2*t)" in r), t=1)
    assert sympy.simplify(sympy.diff(x, t, 2) + 4 * x - sympy.cos(2 * t)) == 0
    assert x.subs(t, 0) == 0 and sympy.diff(x, t).subs(t, 0) == 0
    # Laplace: L{e^-t cos 2t} = (s + 1)/((s + 1)^2 + 4), and back
    i = results.index("cos(2*t)*exp(-t)")
    assert sympy.simplify(expr(results[i - 1], s=1) - (s + 1) / ((s + 1) ** 2 + 4)) == 0
    # the Fourier type transform over multicomplex(1), d = 3 i0 + i1: F(i Omega), Omega = 4, 2
    comps = [expr(c) for c in results[i + 1].strip("[]").split(",")]
    assert [sympy.simplify(c - 1 / (1 + sympy.I * w)) for c, w in zip(comps, (4, 2))] == [0, 0]
    # the Z transform of cos(k pi/3): z (z - 1/2)/(z^2 - z + 1)
    assert sympy.simplify(expr(results[-1], z=1) - z * (z - sympy.Rational(1, 2)) / (z ** 2 - z + 1)) == 0
    # the notch filter's gain, drawn inline
    assert len(images) == 1 and (folder / "notch_gain.png").exists()


def test_the_identification_notebook(executed):
    results, images, folder = executed["identification.ipynb"]
    # Walsh coefficients of t^2 on [0, 1) in Paley's order: averages on the quarters (exact),
    # combined with the signs of w_1 = r_1, w_2 = r_2, w_3 = r_1 r_2
    blocks = [Fraction((k + 1) ** 3 - k ** 3, 48) for k in range(4)]
    signs = [[1, 1, 1, 1], [1, 1, -1, -1], [1, -1, 1, -1], [1, -1, -1, 1]]
    coefficients = [sum(s * b for s, b in zip(row, blocks)) / 4 for row in signs]
    assert results[0] == "[%s]" % ", ".join(str(c) for c in coefficients)
    assert results[1] == "[%s]" % ", ".join(str(b) for b in blocks)
    assert results.count("true") == 3  # the two characteristic polynomials, the pendulum's fit
    # Duffing, 2^10 blocks: f = 4 q + 50 q^3 identified to 0.01 (the example's tolerance)
    a3, a1 = (float(v) for v in results[results.index("true", 4) + 2].strip("[]").split(","))
    assert abs(a3 - 50) < 0.01 and abs(a1 - 4) < 0.01
    # order 3: a_1 = 2 and a_2 = 5 estimated with f (tolerances of examples/identification.symrep)
    est = [float(v) for v in re.search(r"\[([^\[\]]*)\]\]$", results[-1]).group(1).split(",")]
    assert abs(est[0] - 2) < 0.01 and abs(est[1] - 5) < 0.02
    assert len(images) == 2
    assert all(len(o.data["image/png"]) > 1000 for o in images)
