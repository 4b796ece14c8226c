"""Same input, same bytes, from Python too (issue 27.4): the module runs in an ordinary process,
with address randomization on, where GiNaC's term order (hash values seeded by the addresses of
its type names) changes from one process to the next. The engine prints canonically: results,
error messages, and the forms its solvers choose. Several fresh processes must print the same
bytes for every statement below, which covers solutions with square roots in denominators,
responses whose pivots follow the term order, and errors quoting expressions."""
import os
import subprocess
import sys

STATEMENTS = [
    "solve(ode(y'' + c*y' + w0^2*y = 0, y(0) = 1, y'(0) = 0))",
    "solve(ode(y'' + c*y' + k*y = sin(b*t), y(0) = y0, y'(0) = v))",
    "vector w, r0, v0; positive w0; solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))",
    "vector E, B, v0; positive m; solve(ode(m*v' = q*(v x B + E), v(0) = v0))",
    "response([1, 3, 1], [2, 2], exp(-t) + t*exp(-2*t)/3, t)[1]",
    "response([1, 1], [1], exp(-t), t); response([1, 3, 1], [2, 2], exp(-t) + t*exp(-2*t)/3, t)[1]",
    "inverse_laplace(1/(s^2 + a*s + b), s, t)",
    "A := multicomplex(1); w := element(A, [a, b, c, d]); inverse(w)",
    "exp(element(sobrero(1), [a, b, c, d]), t)",
]

SCRIPT = r'''
import sys, symrep
for st in sys.argv[1:]:
    s = symrep.Session()
    try:
        print(s.eval(st).text)
    except symrep.Error as e:
        print("error:", e)
'''


def run_once():
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)  # the module the tests import
    out = subprocess.run([sys.executable, "-c", SCRIPT] + STATEMENTS, capture_output=True, text=True, env=env,
                         timeout=600)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_fresh_processes_print_the_same_bytes():
    with open("/proc/sys/kernel/randomize_va_space") as f:
        assert f.read().strip() != "0", "address randomization is off: this test would prove nothing"
    first = run_once()
    assert first.count("\n") == len(STATEMENTS)
    for _ in range(3):
        again = run_once()
        assert again == first, "\n".join(
            f"{a}\n  !=\n{b}" for a, b in zip(first.splitlines(), again.splitlines()) if a != b)
