#!/usr/bin/env python3
"""SymPy on the inputs of bench/bench_signals.cpp (issue 16.5): laplace_transform,
inverse_laplace_transform and rsolve, timed (CPU, median of 3, timeout per call) and
checked against the closed forms symrep derives (numerically at 5 points, 1e-10).

usage: python3 bench/signals/sympy_transforms.py [--timeout SECONDS] [--warm]
Prints a CSV: problem,tool,seconds,status. Never run by the tests.

Default ("first call"): each call in a freshly forked process (sympy imported by the parent,
every cache cold): the CPU time of a user's first call, import excluded.
--warm: in one process, after one untimed call of the same problem, with SymPy's cache
cleared before each timed call (so that the result is not looked up): the steady-state
cost, comparable with symrep's Google Benchmark repeats.
Whole processes (interpreter start and import included) are timed by bench/signals/processes.sh."""
import argparse
import multiprocessing as mp
import time

import sympy as sp

t, s, k = sp.symbols("t s k", positive=True)
x = sp.Function("x")

f = t * sp.exp(-t / 3) * sp.cos(3 * t) + sp.sin(2 * t)
# symrep's results (laplace(f, t, s) and the recurrences' closed forms), for the check
F_symrep = ((s + sp.Rational(1, 3)) ** 2 - 9) / ((s + sp.Rational(1, 3)) ** 2 + 9) ** 2 + 2 / (s**2 + 4)
fib = (sp.Rational(1, 2) + sp.sqrt(5) / 2) ** k / sp.sqrt(5) - (sp.Rational(1, 2) - sp.sqrt(5) / 2) ** k / sp.sqrt(5)
geo = 2 - 2 * sp.Rational(1, 2) ** k

PROBLEMS = {
    "laplace": (lambda: sp.laplace_transform(f, t, s, noconds=True), F_symrep, s),
    "inverse_laplace": (lambda: sp.inverse_laplace_transform(F_symrep, s, t), f, t),
    "rsolve_fibonacci": (lambda: sp.rsolve(x(k + 2) - x(k + 1) - x(k), x(k), {x(0): 0, x(1): 1}), fib, k),
    "rsolve_geometric": (lambda: sp.rsolve(x(k + 1) - x(k) / 2 - 1, x(k), {x(0): 0}), geo, k),
}


def run(name, q):
    fn, expected, var = PROBLEMS[name]
    start = time.process_time()
    result = fn()
    seconds = time.process_time() - start
    ok = True
    for v in [sp.Rational(1, 2), 1, 2, 3, 5]:
        a = complex(sp.N(result.subs(var, v).subs(sp.Heaviside(v), 1), 30))
        b = complex(sp.N(expected.subs(var, v), 30))
        ok = ok and abs(a - b) <= 1e-10 * max(1.0, abs(b))
    q.put((seconds, "right" if ok else "wrong"))


def warm(name):
    from sympy.core.cache import clear_cache

    fn = PROBLEMS[name][0]
    fn()
    times = []
    for _ in range(3):
        clear_cache()
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return sorted(times)[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--warm", action="store_true")
    args = ap.parse_args()
    print("problem,tool,seconds,status")
    if args.warm:
        for name in PROBLEMS:
            print(f"{name},sympy {sp.__version__} warm,{warm(name)},ok", flush=True)
        return
    for name in PROBLEMS:
        times, status = [], "ok"
        for _ in range(3):
            q = mp.Queue()
            p = mp.Process(target=run, args=(name, q))
            p.start()
            p.join(args.timeout)
            if p.is_alive():
                p.terminate()
                status = "timeout"
                break
            if q.empty():
                status = "error"
                break
            sec, status = q.get()
            times.append(sec)
        med = sorted(times)[len(times) // 2] if times else ""
        print(f"{name},sympy {sp.__version__},{med},{status}", flush=True)


if __name__ == "__main__":
    main()
