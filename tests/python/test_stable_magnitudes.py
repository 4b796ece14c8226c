"""tests/python/test_stable_magnitudes.py -- issue 27: `eval`, the stable evaluator and the
checked compiled path at every magnitude a double holds (1e-300 .. 1e300), against mpmath at
1500 digits (an independent evaluation of r = exp(-t W) rho, rho'' = exp(t W) g, not of symrep's
closed form). Tolerances: 1e-14 relative per component for eval and f.stable (their documented
accuracy, 8e-15 plus the rounding to double), 1e-6 for the checked plain path f(...)."""
import math

import mpmath as mp
import numpy as np
import pytest

import symrep

mp.mp.dps = 1500

GRAVITY = """vector w, g, r0, v0
s := solve(ode(r'' + 2*w x r' + w x (w x r) = g, r(0) = r0, r'(0) = v0))"""


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def gravity_reference(w, g, r0, v0, t):
    """r'' + 2 w x r' + w x (w x r) = g: rho = exp(t W) r satisfies rho'' = exp(t W) g,
    rho(0) = r0, rho'(0) = v0 + w x r0 (W = w x); the inputs are the doubles given, exactly."""
    w, g, r0, v0 = ([mp.mpf(x) for x in v] for v in (w, g, r0, v0))
    t = mp.mpf(t)
    k = mp.sqrt(sum(x * x for x in w))
    Wg = cross(w, g)
    WWg = cross(w, Wg)
    A = t**2 / 2
    B = (k * t - mp.sin(k * t)) / k**3 if k else 0
    C = t**2 / (2 * k**2) - (1 - mp.cos(k * t)) / k**4 if k else 0
    wr0 = cross(w, r0)
    rho = [r0[i] + (v0[i] + wr0[i]) * t + A * g[i] + B * Wg[i] + C * WWg[i] for i in range(3)]
    if not k:
        return rho
    s1, c1 = mp.sin(k * t) / k, (1 - mp.cos(k * t)) / k**2
    Wr = cross(w, rho)
    WWr = cross(w, Wr)
    return [rho[i] - s1 * Wr[i] + c1 * WWr[i] for i in range(3)]


def close(x, ref, rel):
    ref = [float(r) for r in ref]
    return all(abs(a - b) <= rel * abs(b) for a, b in zip(x, ref)), (list(x), ref)


@pytest.fixture
def s():
    return symrep.Session()


MAGNITUDES = [1e-300, 1e-200, 1e-100, 1e-70, 1e-49, 1e-40, 1e-30, 1e-20, 1e-12, 1e-8, 1e-3]


@pytest.mark.parametrize("w", [1e-300, 1e-150, 1e-100, 1e-70, 1e-40, 1e-20, 1e-8])
def test_eval_of_cancelling_terms(s, w):
    wm = mp.mpf(w)
    a = s.eval("eval((1 - cos(w*t))/w^2, [w = %r], t = 1)" % w).to_python()
    b = s.eval("eval((w*t - sin(w*t))/w^3, [w = %r], t = 1)" % w).to_python()
    c = s.eval("eval((w*t - sin(w*t))/w^3 + 1, [w = %r], t = 1)" % w).to_python()
    assert abs(a - float((1 - mp.cos(wm)) / wm**2)) <= 1e-15
    assert abs(b - float((wm - mp.sin(wm)) / wm**3)) <= 1e-15
    assert abs(c - float((wm - mp.sin(wm)) / wm**3 + 1)) <= 2e-15


def test_eval_of_an_exact_tiny_value(s):
    assert s.eval("eval((1 - cos(w*t))/w^2, [w = 1/10^100], t = 1)").to_python() == 0.5


@pytest.mark.parametrize("k", [-300, -200, -100, -70, -49, -40, -30, -20, -12, -8, -3, 0, 3, 100, 300])
def test_eval_of_the_gravity_solution(s, k):
    # w exactly 10^k (at |w| t = 1e301 the phase depends on every digit of w: no decimal float)
    s.eval(GRAVITY)
    x = s.eval("eval(s, [w = [0, 10^(%d), 10^(%d)], g = [0, 0, -981/100], r0 = [0, 0, 0], v0 = [1, 0, 0]], "
               "t = 10)" % (k, k)).to_python()
    e = mp.mpf(10) ** k
    ok, why = close(x, gravity_reference([0, e, e], [0, 0, mp.mpf(-981) / 100], [0, 0, 0], [1, 0, 0], 10), 1e-14)
    assert ok, why


@pytest.mark.parametrize("e", MAGNITUDES + [1.0, 1e3])
def test_compiled_gravity_solution(s, e):
    s.eval(GRAVITY)
    values = {"w": [0, e, e], "g": [0, 0, -9.81], "r0": [0, 0, 0], "v0": [1, 0, 0]}
    f = s.compile(s.get("s"), ["t"], values, stable=True)
    ref = gravity_reference([0, e, e], [0, 0, -9.81], [0, 0, 0], [1, 0, 0], 10)
    ok, why = close(f.stable(t=[10.0])[0], ref, 1e-14)
    assert ok, why
    # the plain path: checked by the running error bound, 1e-6 relative per output at least
    ok, why = close(f(t=[10.0])[0], ref, 1e-6)
    assert ok, why


def test_the_unchecked_path_is_what_the_checked_one_repairs(s):
    s.eval(GRAVITY)
    values = {"w": [0, 1e-8, 1e-8], "g": [0, 0, -9.81], "r0": [0, 0, 0], "v0": [1, 0, 0]}
    f = s.compile(s.get("s"), ["t"], values)
    ref = gravity_reference([0, 1e-8, 1e-8], [0, 0, -9.81], [0, 0, 0], [1, 0, 0], 10)
    y = f(t=np.array([10.0, 10.0]))[:, 1]
    assert np.all(np.abs(y - float(ref[1])) <= 1e-6 * abs(float(ref[1])))


def test_compile_refuses_a_value_for_a_name_the_form_does_not_have(s):
    s.eval(GRAVITY)
    with pytest.raises(symrep.Error, match="'ww'.*does not have"):  # a scalar typo
        s.compile(s.get("s"), ["t"], {"ww": 1.0, "w": [0, 1, 1], "g": [0, 0, -9.81],
                                      "r0": [0, 0, 0], "v0": [1, 0, 0]})


def test_compile_at_a_removable_singularity(s):
    s.eval(GRAVITY)
    values = {"w": [0, 0, 0], "g": [0, 0, -9.81], "r0": [1, 2, 3], "v0": [1, 0, 0]}
    try:
        f = s.compile(s.get("s"), ["t"], values)
    except symrep.Error as err:
        assert "power::eval" not in str(err) and "solve(P, values)" in str(err)
        return
    x = f(t=[2.0])[0]  # the limit: r0 + v0 t + g t^2/2
    assert np.allclose(x, [3.0, 2.0, 3.0 - 9.81 * 2.0], rtol=1e-14, atol=0)
