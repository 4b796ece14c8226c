#!/usr/bin/env bash
# Work-precision chart of the dual Poisson-Darboux problem Q^' = -Omega^ Q^ on SE(3)
# (docs/performance.md, "Rigid motions on SE(3)"): runs the Se3* benchmarks of
# bench/bench_se3.cpp and draws error against CPU time with gnuplot.
#
# usage: bash bench/plot_se3.sh [build-dir]          (default build dir: build)
#        PLOT_ONLY=1 bash bench/plot_se3.sh          (redraw from docs/figures/se3_wp.csv)
# Output: docs/figures/se3_wp.{csv,png}; about a minute after the build.
source "$(dirname "${BASH_SOURCE[0]}")/plot_common.sh"  # strict mode, repository root, $build, $out
if [ -z "${PLOT_ONLY:-}" ]; then
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSYMREP_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target symrep_bench
csv=$(mktemp)
"$build"/symrep_bench --benchmark_filter='^Se3' --benchmark_min_time=0.2 --benchmark_format=csv > "$csv" 2>/dev/null
# method, tolerance, cpu microseconds, error, orthogonality, twist evaluations
{
    echo "method,tolerance,cpu_us,error,orthogonality,twist_evals"
    grep -E '^"Se3' "$csv" | tr -d '"' |
        awk -F, '{split($1, a, "/"); tol = (a[1] ~ /ClosedForm/ ? "exact" : "1e-" a[2]);
                  printf "%s,%s,%s,%s,%s,%s\n", a[1], tol, $4, $11, $12, $13}'
} > "$out/se3_wp.csv"
rm -f "$csv"
fi
command -v gnuplot >/dev/null || { echo "gnuplot is not installed; the data are in $out/se3_wp.csv" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo size 1100,480 font ",10"
set output "$out/se3_wp.png"
set datafile separator ","
set multiplot layout 1,2
set logscale xy
set grid
set format y "10^{%L}"
set xlabel "CPU time per trajectory (µs)"
set ylabel "max(|R - R_{ref}|, |d - d_{ref}| / |d_{ref}|) at t = 200"
set key bottom left
set title "Q' = -Omega Q on SE(3), a moving twist (no closed form)"
plot "< grep Se3Moving_Magnus6 $out/se3_wp.csv" using 3:4 with linespoints pt 7 title "Magnus 6 on SE(3)", \
     "< grep Se3Moving_Odeint12_rkf78 $out/se3_wp.csv" using 3:4 with linespoints pt 5 title "rkf78, 12 components", \
     "< grep Se3Moving_Odeint12_dopri5 $out/se3_wp.csv" using 3:4 with linespoints pt 9 title "dopri5, 12 components"
set title "regular screw precession: Q = exp(-t b) exp(-t a)"
set key center left
plot "< grep Se3Precession_Magnus6 $out/se3_wp.csv" using 3:4 with linespoints pt 7 title "Magnus 6 on SE(3)", \
     "< grep Se3Precession_Odeint12_rkf78 $out/se3_wp.csv" using 3:4 with linespoints pt 5 title "rkf78, 12 components", \
     "< grep Se3Precession_Odeint12_dopri5 $out/se3_wp.csv" using 3:4 with linespoints pt 9 title "dopri5, 12 components", \
     "< grep Se3Precession_ClosedForm $out/se3_wp.csv" using 3:(\$4 > 0 ? \$4 : 1e-17) with points pt 13 ps 2 title "closed form (evaluation)"
unset multiplot
GP
echo "wrote $out/se3_wp.png"
