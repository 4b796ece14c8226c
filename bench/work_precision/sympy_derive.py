#!/usr/bin/env python3
"""Time SymPy's dsolve on the Cauchy problems whose closed forms symrep derives
(bench/work_precision/work_precision.cpp, the "derivation" table), each with a
general axis: w, B, E, g, r0, v0 have symbolic components, w0, m, q are symbols.

usage: python3 bench/work_precision/sympy_derive.py [--timeout S] [--out FILE]
Each problem runs in its own process, killed after S seconds (default 60);
the CSV has problem,tool,seconds,cpu_seconds,status (wall and CPU time of
dsolve; status: ok, timeout, failed: ...).
Never part of the test suite; SymPy is optional (not installed by build.sh).
"""
import subprocess
import sys
import time

PROBLEMS = ["VI.1.41_velocity", "VI.1.50_coriolis", "VI.1.56_centrifugal", "VI.1.58_charge_velocity",
            "VI.1.58_charge_position", "VI.1.68_foucault", "VI.2.93_reduced_foucault"]


def solve_one(name):
    import sympy as sp
    t = sp.symbols("t", real=True)
    vec = lambda n: sp.Matrix(sp.symbols(f"{n}1 {n}2 {n}3", real=True))
    w, g, E, B, r0, v0 = vec("w"), vec("g"), vec("E"), vec("B"), vec("r0"), vec("v0")
    w0, m = sp.symbols("w0 m", positive=True)
    q = sp.symbols("q", real=True)
    f = [sp.Function(n) for n in "xyz"]
    r = sp.Matrix([fi(t) for fi in f])
    d1, d2 = r.diff(t), r.diff(t, 2)
    if name == "VI.1.41_velocity":
        eq, order = d1 + 2 * w.cross(r) - g, 1
    elif name == "VI.1.50_coriolis":
        eq, order = d2 + 2 * w.cross(d1) - g, 2
    elif name == "VI.1.56_centrifugal":
        eq, order = d2 + 2 * w.cross(d1) + w.cross(w.cross(r)) - g, 2
    elif name == "VI.1.58_charge_velocity":
        eq, order = m * d1 - q * (r.cross(B) + E), 1
    elif name == "VI.1.58_charge_position":
        eq, order = m * d2 - q * (d1.cross(B) + E), 2
    elif name == "VI.1.68_foucault":
        eq, order = d2 + 2 * w.cross(d1) + w.cross(w.cross(r)) + w0**2 * r, 2
    elif name == "VI.2.93_reduced_foucault":
        eq, order = d2 + 2 * w.cross(d1) + w0**2 * r, 2
    else:
        raise SystemExit(f"unknown problem {name}")
    ics = {fi(0): r0[i] for i, fi in enumerate(f)} if order == 2 else {fi(0): v0[i] for i, fi in enumerate(f)}
    if order == 2:
        ics.update({fi(t).diff(t).subs(t, 0): v0[i] for i, fi in enumerate(f)})
    start, cpu = time.perf_counter(), time.process_time()
    sp.dsolve([sp.Eq(e, 0) for e in eq], [fi(t) for fi in f], ics=ics)
    return time.perf_counter() - start, time.process_time() - cpu


def main():
    args = sys.argv[1:]
    if args[:1] == ["--one"]:
        print("%.6g,%.6g" % solve_one(args[1]))
        return
    timeout, out = 60.0, None
    while args:
        a = args.pop(0)
        if a == "--timeout":
            timeout = float(args.pop(0))
        elif a == "--out":
            out = args.pop(0)
        else:
            raise SystemExit(__doc__)
    import sympy
    rows = ["problem,tool,seconds,cpu_seconds,status"]
    for name in PROBLEMS:
        try:
            p = subprocess.run([sys.executable, __file__, "--one", name], capture_output=True, text=True,
                               timeout=timeout)
            if p.returncode == 0:
                rows.append(f"{name},sympy {sympy.__version__},{p.stdout.strip()},ok")
            else:
                last = (p.stderr.strip().splitlines() or ["?"])[-1].replace(",", ";")[:100]
                rows.append(f"{name},sympy {sympy.__version__},,,failed: {last}")
        except subprocess.TimeoutExpired:
            rows.append(f"{name},sympy {sympy.__version__},{timeout:g},,timeout")
        print(rows[-1], file=sys.stderr)
    text = "\n".join(rows) + "\n"
    if out:
        with open(out, "w") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
