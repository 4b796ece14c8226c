#!/usr/bin/env bash
# Whole-process times of the SymPy comparison in docs/performance.md ("Against SymPy"): each
# problem as one process of python3 (interpreter start, `import sympy`, the call) and one of
# symrep (start, the statement), CPU time (user + system, getrusage), median of 3.
# usage: bash bench/signals/processes.sh [build-dir]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
build=${1:-build}
cpu() {  # the median CPU seconds (user + system, getrusage of the child) of 3 runs of "$@"
    python3 - "$@" <<'PY'
import resource, subprocess, sys
times = []
for _ in range(3):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    times.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
print(f"{sorted(times)[1]:.4f}")
PY
}
py() { cpu python3 -c "import sympy as sp; t, s, k = sp.symbols('t s k', positive=True); x = sp.Function('x'); $1"; }
sr() { cpu "$build"/symrep -e "$1"; }
echo "problem,sympy_process_s,symrep_process_s"
echo "python3 start + import sympy,$(cpu python3 -c 'import sympy'),$(sr '1')"
echo "laplace,$(py 'sp.laplace_transform(t*sp.exp(-t/3)*sp.cos(3*t) + sp.sin(2*t), t, s, noconds=True)'),$(sr 'laplace(t*exp(-t/3)*cos(3*t) + sin(2*t), t, s)')"
echo "inverse_laplace,$(py 'sp.inverse_laplace_transform(((s + sp.Rational(1, 3))**2 - 9)/((s + sp.Rational(1, 3))**2 + 9)**2 + 2/(s**2 + 4), s, t)'),$(sr 'inverse_laplace(((s + 1/3)^2 - 9)/((s + 1/3)^2 + 9)^2 + 2/(s^2 + 4), s, t)')"
echo "rsolve_fibonacci,$(py 'sp.rsolve(x(k + 2) - x(k + 1) - x(k), x(k), {x(0): 0, x(1): 1})'),$(sr 'A := polynomial_algebra(X^2 - X - 1, X); sequence_formula(find_generator(A), k)')"
echo "rsolve_geometric,$(py 'sp.rsolve(x(k + 1) - x(k)/2 - 1, x(k), {x(0): 0})'),$(sr 'sequence_response([1, -1/2], [1], 1, k)')"
