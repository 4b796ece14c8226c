#!/usr/bin/env python3
"""Time Maxima's desolve (Laplace transform method) on the Cauchy problems whose closed forms
symrep derives: the seven problems of the derivation table (bench/work_precision/work_precision.cpp,
as in sympy_derive.py: w, B, E, g, r0, v0 with symbolic components, w0, m, q symbols) and the forced
problems of issue 15.1 (r'' + 2 w x r' = f(t) g and the Foucault operator r'' + 2 w x r' + w x (w x r)
+ w0^2 r = f(t) g, f from bench_mechanics.cpp's list), all in components.

usage: python3 bench/work_precision/maxima_derive.py [--timeout S] [--out FILE] [--forced-only]
Each problem runs in its own Maxima process (maxima -b), killed after S seconds (default 60). Maxima asks
about the signs of symbolic expressions while it inverts Laplace transforms; every question gets the
answer "positive" (the generic case; symrep's solution holds for all signs). A result that still
holds an inverse Laplace transform Maxima could not do (ilt(...)) is marked "no closed form". The CSV has
problem,tool,seconds,cpu_seconds,status with Maxima's elapsed_real_time and elapsed_run_time around
desolve (not the process start). Never part of the test suite; Maxima is optional (not installed by
build.sh; Debian package maxima).
"""
import os
import re
import subprocess
import sys
import tempfile

HEADER = """display2d: false$
cross(a, b) := [a[2]*b[3] - a[3]*b[2], a[3]*b[1] - a[1]*b[3], a[1]*b[2] - a[2]*b[1]]$
w: [w1, w2, w3]$ g: [g1, g2, g3]$ E: [E1, E2, E3]$ B: [B1, B2, B3]$
r0: [r01, r02, r03]$ v0: [v01, v02, v03]$
r: [x(t), y(t), z(t)]$ d1: diff(r, t)$ d2: diff(r, t, 2)$
"""

DERIVATION = {
    "VI.1.41_velocity": ("d1 + 2*cross(w, r) - g", 1),
    "VI.1.50_coriolis": ("d2 + 2*cross(w, d1) - g", 2),
    "VI.1.56_centrifugal": ("d2 + 2*cross(w, d1) + cross(w, cross(w, r)) - g", 2),
    "VI.1.58_charge_velocity": ("m*d1 - q*(cross(r, B) + E)", 1),
    "VI.1.58_charge_position": ("m*d2 - q*(cross(d1, B) + E)", 2),
    "VI.1.68_foucault": ("d2 + 2*cross(w, d1) + cross(w, cross(w, r)) + w0^2*r", 2),
    "VI.2.93_reduced_foucault": ("d2 + 2*cross(w, d1) + w0^2*r", 2),
}

FORCINGS = ["1", "t^3", "t^6", "(1 + t + t^2 + t^3 + t^4 + t^5 + t^6)", "exp(-k*t)", "t*exp(-k*t)",
            "t^2*exp(-k*t)", "t^3*exp(-k*t)", "t*exp(-t)*cos(2*t)"]


def problems(forced_only):
    out = [] if forced_only else [(name, eq, order) for name, (eq, order) in DERIVATION.items()]
    for f in FORCINGS:
        out.append((f"coriolis_forced {f}", f"d2 + 2*cross(w, d1) - ({f})*g", 2))
        out.append((f"foucault_forced {f}", f"d2 + 2*cross(w, d1) + cross(w, cross(w, r)) + w0^2*r - ({f})*g", 2))
    return out


def script(eq, order):
    s = HEADER + f"eqs: {eq}$\n"
    init = "v0" if order == 1 else "r0"
    for i, u in enumerate("xyz"):
        s += f"atvalue({u}(t), t = 0, {init}[{i + 1}])$\n"
        if order == 2:
            s += f"atvalue(diff({u}(t), t), t = 0, v0[{i + 1}])$\n"
    s += """t0: elapsed_real_time()$ c0: elapsed_run_time()$
sol: desolve([eqs[1] = 0, eqs[2] = 0, eqs[3] = 0], [x(t), y(t), z(t)])$
print("RESULT", elapsed_real_time() - t0, elapsed_run_time() - c0, if freeof('ilt, sol) then 1 else 0)$
"""
    return s


def run(eq, order, timeout):
    with tempfile.NamedTemporaryFile("w", suffix=".mac", delete=False) as fh:
        fh.write(script(eq, order))
        path = fh.name
    try:
        p = subprocess.run(["maxima", "--very-quiet", "-b", path], input="positive;\n" * 2000,
                           capture_output=True, text=True, timeout=timeout)
        m = re.search(r"RESULT\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+([01])", p.stdout)
        if not m:
            last = (p.stdout.strip().splitlines() or ["?"])[-1].replace(",", ";")[:80]
            return ",,failed: " + last
        status = "ok" if m.group(3) == "1" else "no closed form (ilt left unevaluated)"
        return f"{float(m.group(1)):.6g},{float(m.group(2)):.6g},{status}"
    except subprocess.TimeoutExpired:
        return f"{timeout:g},,timeout"
    finally:
        os.unlink(path)


def main():
    args = sys.argv[1:]
    timeout, out, forced_only = 60.0, None, False
    while args:
        a = args.pop(0)
        if a == "--timeout":
            timeout = float(args.pop(0))
        elif a == "--out":
            out = args.pop(0)
        elif a == "--forced-only":
            forced_only = True
        else:
            raise SystemExit(__doc__)
    version = subprocess.run(["maxima", "--version"], capture_output=True, text=True).stdout.split()[-1]
    rows = ["problem,tool,seconds,cpu_seconds,status"]
    for name, eq, order in problems(forced_only):
        rows.append(f"{name},maxima {version},{run(eq, order, timeout)}")
        print(rows[-1], file=sys.stderr)
    text = "\n".join(rows) + "\n"
    if out:
        with open(out, "w") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
