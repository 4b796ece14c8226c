#!/usr/bin/env bash
# Speed against accuracy of the exact full-body relative orbital motion (docs/performance.md,
# "Full-body relative motion"): runs the RelativePose_* benchmarks of bench/bench_relative_pose.cpp
# and draws the pose's error against CPU time with gnuplot.
#
# usage: bash bench/plot_relative_pose.sh [build-dir]     (default build dir: build, configured
#        with -DSYMREP_BUILD_BENCH=ON)
#        PLOT_ONLY=1 bash bench/plot_relative_pose.sh    (redraw from docs/figures/relative_pose_wp.csv)
#        NO_BUILD=1: use the symrep_bench already built
# Output: docs/figures/relative_pose_wp.{csv,png}.
source "$(dirname "${BASH_SOURCE[0]}")/plot_common.sh"  # strict mode, repository root, $build, $out
if [ -z "${PLOT_ONLY:-}" ]; then
[ -n "${NO_BUILD:-}" ] || cmake --build "$build" -j"${JOBS:-2}" --target symrep_bench
csv=$(mktemp)
"$build"/symrep_bench --benchmark_filter='RelativePose_' --benchmark_format=csv > "$csv" 2>/dev/null
# method, tolerance, cpu microseconds, relative position error, attitude error
{
    echo "method,tolerance,cpu_us,pos_error,att_error"
    cols=$(grep -E '^name,' "$csv" | tr -d '"')
    grep -E '^"RelativePose' "$csv" | tr -d '"' |
        awk -F, -v cols="$cols" 'BEGIN { n = split(cols, c, ","); for (i = 1; i <= n; ++i) idx[c[i]] = i }
            { split($1, a, "/"); tol = (a[2] == "" ? "-" : "1e-" a[2]);
              printf "%s,%s,%s,%s,%s\n", a[1], tol, $idx["cpu_time"], $idx["pos_error"], $idx["att_error"] }'
} > "$out/relative_pose_wp.csv"
fi
command -v gnuplot >/dev/null || { echo "gnuplot is not installed; the data are in $out/relative_pose_wp.csv" >&2; exit 1; }
gnuplot <<GP
set terminal pngcairo size 1100,480 font ",10" noenhanced
set output "$out/relative_pose_wp.png"
set datafile separator ","
set multiplot layout 1,2 title "Full-body relative motion after 10 orbits (e ~ 0.2 leader, deputy 1.5 km away, spinning at 0.05 rad/s)"
set logscale xy
set grid
set format y "%.0e"
set xlabel "CPU time per trajectory (µs)"
set key top right
set title "position of the deputy in the leader's body frame"
set ylabel "|rho - rho_ref| / |rho_ref|"
plot "< grep RelativePose_Closed $out/relative_pose_wp.csv" using 3:(\$4 > 1e-17 ? \$4 : 1e-17) with points pt 7 ps 2 title "closed form (5.1) (its difference from rkf78 at 1e-12)", \
     "< grep SixDof_rkf78 $out/relative_pose_wp.csv" using 3:4 with linespoints pt 5 title "6-DOF rkf78", \
     "< grep SixDof_dopri5 $out/relative_pose_wp.csv" using 3:4 with linespoints pt 11 title "6-DOF dopri5"
set title "attitude of the deputy relative to the leader"
set ylabel "|A - A_ref| (Frobenius)"
plot "< grep RelativePose_Closed $out/relative_pose_wp.csv" using 3:(\$5 > 1e-17 ? \$5 : 1e-17) with points pt 7 ps 2 title "closed form (5.1) (its difference from Magnus at 1e-13)", \
     "< grep MagnusDeputy $out/relative_pose_wp.csv" using 3:(\$5 > 1e-17 ? \$5 : 1e-17) with linespoints pt 9 title "(5.1), deputy attitude by Magnus", \
     "< grep SixDof_rkf78 $out/relative_pose_wp.csv" using 3:5 with linespoints pt 5 title "6-DOF rkf78", \
     "< grep SixDof_dopri5 $out/relative_pose_wp.csv" using 3:5 with linespoints pt 11 title "6-DOF dopri5"
unset multiplot
GP
echo "wrote $out/relative_pose_wp.png"
