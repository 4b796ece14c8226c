#!/usr/bin/env python3
"""bench/python_eval.py -- the Python fast path against the C++ compiled evaluator and NumPy
(issue 18.2; docs/performance.md, docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_eval.py [build]

The Foucault solution at Paris (derived by symrep, the values put in, one input t), per
point: (1) symrep.Compiled over a NumPy array of times (one call, the GIL released, the
C++ eval_many inside); (2) the C++ eval_many itself (build/symrep_bench
--benchmark_filter=Foucault_CompiledMany); (3) the same closed form (VI.1.79) written in
NumPy; (4) a Python loop calling the compiled form point by point. Medians of 7 runs.
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

import symrep

PARIS = {"w": [7.2921e-5 * math.cos(math.radians(48.85)), 0, 7.2921e-5 * math.sin(math.radians(48.85))],
         "w0": math.sqrt(9.81 / 67), "r0": [3, 0, 0], "v0": [0, 0, 0]}


def hand_written(t, w, w0, r0, v0):
    w = np.asarray(w, float)
    W = np.linalg.norm(w)
    t = t[:, None]
    psi = np.asarray(r0, float) * np.cos(w0 * t) + (np.asarray(v0, float) + np.cross(w, r0)) / w0 * np.sin(w0 * t)
    wpsi = np.cross(w, psi)
    return psi - np.sin(W * t) / W * wpsi + (1 - np.cos(W * t)) / W**2 * np.cross(w, wpsi)


def median_time(fn, repeat=7):
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return sorted(ts)[len(ts) // 2]


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    s = symrep.Session()
    s.eval("vector w, r0, v0; positive w0")
    r = s.eval("solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))")
    f = s.compile(r, ["t"], PARIS)
    rows = []
    for n in (1024, 10**6):
        t = np.arange(n) * (86400.0 / n)
        py = median_time(lambda: f(t=t)) / n
        npy = median_time(lambda: hand_written(t, **PARIS)) / n
        rows.append((n, py, npy))
    t = np.arange(2000) * 43.2
    loop = median_time(lambda: [f(t=np.array([x])) for x in t], 3) / len(t)
    cpp = None
    exe = os.path.join(build, "symrep_bench")
    if os.path.exists(exe):
        out = subprocess.run([exe, "--benchmark_filter=Foucault_CompiledMany$", "--benchmark_format=json",
                              "--benchmark_repetitions=7", "--benchmark_report_aggregates_only=true"],
                             capture_output=True, text=True, check=True).stdout
        for b in json.loads(out)["benchmarks"]:
            if b["name"].endswith("_median"):
                cpp = 1.0 / b["items_per_second"]
    print("| evaluation of the Foucault solution, per point | 1024 points | 10^6 points |")
    print("|---|---:|---:|")
    print("| symrep.Compiled over a NumPy array | %.1f ns | %.1f ns |" % (rows[0][1] * 1e9, rows[1][1] * 1e9))
    if cpp:
        print("| C++ compiled_function::eval_many (1024 points) | %.1f ns | |" % (cpp * 1e9))
    print("| the closed form (VI.1.79) written in NumPy | %.1f ns | %.1f ns |" % (rows[0][2] * 1e9, rows[1][2] * 1e9))
    print("| a Python loop over symrep.Compiled, one point per call | %.0f ns | |" % (loop * 1e9))
    if cpp:
        print("\nPython over C++: %.2fx (1024 points), %.2fx (10^6 points)" % (rows[0][1] / cpp, rows[1][1] / cpp))
    print("NumPy over symrep.Compiled: %.2fx (1024 points), %.2fx (10^6 points)"
          % (rows[0][2] / rows[0][1], rows[1][2] / rows[1][1]))


if __name__ == "__main__":
    main()
