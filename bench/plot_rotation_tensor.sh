#!/usr/bin/env bash
# Work-precision chart of the rotation tensor (docs/performance.md, "Rotation tensor"):
# runs the RotationTensor/RotatingKepler benchmarks of bench/bench_rotation_tensor.cpp
# (unless a CSV of theirs is given) and draws error against CPU time with gnuplot.
#
# usage: bash bench/plot_rotation_tensor.sh [build-dir]          (default build dir: build)
#        PLOT_ONLY=1 bash bench/plot_rotation_tensor.sh   (redraw from the CSV files in docs/figures)
# Output: docs/figures/rotation_tensor_wp.{csv,png}, rotating_kepler_drift.{csv,png},
# relative_motion_cw.{csv,png} and relative_motion_elliptic.{csv,png}.
source "$(dirname "${BASH_SOURCE[0]}")/plot_common.sh"  # strict mode, repository root, $build, $out
if [ -z "${PLOT_ONLY:-}" ]; then
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"${JOBS:-2}" --target symrep_bench
csv=$(mktemp)
rel=$(mktemp)
# two runs: the CSV reporter wants the same counters in every row of one run
"$build"/symrep_bench --benchmark_filter='RotationTensor|RotatingKepler_(Reduction|Odeint)' --benchmark_min_time=0.2 \
    --benchmark_format=csv > "$csv" 2>/dev/null
"$build"/symrep_bench --benchmark_filter='RelativeMotion_ExactAgainstCW' --benchmark_format=csv > "$rel" 2>/dev/null
ecc=$(mktemp)
"$build"/symrep_bench --benchmark_filter='RelativeMotion_Eccentric' --benchmark_format=csv > "$ecc" 2>/dev/null
# separation (m), orbits, CPU ms of the linear model, relative errors of Clohessy-Wiltshire and Tschauner-Hempel
{
    echo "separation_m,orbits,th_cpu_ms,cw_relative_error,th_relative_error"
    grep -E '^"RelativeMotion_Eccentric' "$ecc" | tr -d '"' |
        awk -F, '{split($1, a, "/"); printf "%s,%s,%s,%s,%s\n", $12, a[3], $4, $11, $13}'
} > "$out/relative_motion_elliptic.csv"
drift=$(mktemp)
"$build"/symrep_bench --benchmark_filter='EnergyDrift' --benchmark_format=csv > "$drift" 2>/dev/null
# method, time, cpu milliseconds, relative drift of the energy integral
{
    echo "method,time,cpu_ms,energy_drift"
    grep -E '^"RotatingKepler_EnergyDrift' "$drift" | tr -d '"' |
        awk -F, '{split($1, a, "/"); sub("RotatingKepler_EnergyDrift_", "", a[1]); printf "%s,%s,%s,%s\n", a[1], $12, $4, $11}'
} > "$out/rotating_kepler_drift.csv"
# method, tolerance exponent, cpu microseconds, error, orthogonality, w evaluations
{
    echo "method,tolerance,cpu_us,error,orthogonality,w_evals"
    grep -E '^"(RotationTensor|RotatingKepler)' "$csv" | tr -d '"' |
        awk -F, '{split($1, a, "/"); tol = (a[1] ~ /rk4/ ? "step 2^-" : "1e-") a[2];
                  printf "%s,%s,%s,%s,%s,%s\n", a[1], tol, $4, $11, $12, $13}'
} > "$out/rotation_tensor_wp.csv"
# separation (m), orbits, CPU microseconds of the exact form, relative error of Clohessy-Wiltshire
{
    echo "separation_m,orbits,exact_cpu_us,cw_relative_error"
    grep -E '^"RelativeMotion' "$rel" | tr -d '"' |
        awk -F, '{split($1, a, "/"); printf "%s,%s,%s,%s\n", $12, a[3], $4, $11}'
} > "$out/relative_motion_cw.csv"
fi
command -v gnuplot >/dev/null || { echo "gnuplot is not installed; the data are in $out/rotation_tensor_wp.csv" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo size 1100,480 font ",10"
set output "$out/rotation_tensor_wp.png"
set datafile separator ","
set multiplot layout 1,2
set logscale xy
set grid
set format y "10^{%L}"
set xlabel "CPU time per trajectory (µs)"
set ylabel "error at t = 200"
set key bottom left
set title "Q' = -W Q, w = (0.7 sin 1.3t, 0.4 cos 2.1t, 0.5), t = 200"
plot "< grep Magnus6 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 7 title "Magnus 6 on SO(3)", \
     "< grep Odeint9_rkf78 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 5 title "rkf78, 9 components", \
     "< grep Odeint9_dopri5 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 9 title "dopri5, 9 components"
set title "Kepler in that frame (VI.3.153): r at t = 200"
set ylabel "relative error of r"
plot "< grep RotatingKepler_Reduction $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 7 title "reduction r = Q psi (Magnus + universal variables)", \
     "< grep RotatingKepler_Odeint_rkf78 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 5 title "rkf78 on the rotating-frame ODE", \
     "< grep RotatingKepler_Odeint_dopri5 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 9 title "dopri5", \
     "< grep RotatingKepler_Odeint_bulirsch_stoer $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 11 title "Bulirsch-Stoer", \
     "< grep RotatingKepler_Odeint_rk4 $out/rotation_tensor_wp.csv" using 3:4 with linespoints pt 13 title "rk4 (fixed steps)"
unset multiplot
set terminal pngcairo size 640,480 font ",10"
set output "$out/rotating_kepler_drift.png"
set title "Kepler in the turning frame: drift of the energy integral (VI.3.140)"
set xlabel "time"
set ylabel "|E(t) - E(0)| / |E(0)|"
set key top left
plot "< grep Reduction $out/rotating_kepler_drift.csv" using 2:(\$4 > 0 ? \$4 : 1e-17) with linespoints pt 7 title "reduction (0 plotted as 1e-17)", \
     "< grep rkf78 $out/rotating_kepler_drift.csv" using 2:4 with linespoints pt 5 title "rkf78 at 1e-12"
set terminal pngcairo size 640,480 font ",10"
set output "$out/relative_motion_cw.png"
unset multiplot
set title "Clohessy-Wiltshire against the exact relative motion (circular LEO, 7000 km)"
set xlabel "initial separation (m)"
set ylabel "relative error of the CW position"
set key top left
plot "< awk -F, '\$2 == 1' $out/relative_motion_cw.csv" using 1:4 with linespoints pt 7 title "after 1 orbit", \
     "< awk -F, '\$2 == 10' $out/relative_motion_cw.csv" using 1:4 with linespoints pt 5 title "after 10 orbits"
set output "$out/relative_motion_elliptic.png"
set title "Linear models against the exact relative motion, target with e = 0.3"
set ylabel "relative error of the linear model's position"
plot "< awk -F, '\$2 == 1' $out/relative_motion_elliptic.csv" using 1:5 with linespoints pt 7 title "Tschauner-Hempel, 1 orbit", \
     "< awk -F, '\$2 == 10' $out/relative_motion_elliptic.csv" using 1:5 with linespoints pt 5 title "Tschauner-Hempel, 10 orbits", \
     "< awk -F, '\$2 == 1' $out/relative_motion_elliptic.csv" using 1:4 with linespoints pt 9 title "Clohessy-Wiltshire (mean motion), 1 orbit"
GP
echo "wrote $out/rotation_tensor_wp.png"
