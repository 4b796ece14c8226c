#!/usr/bin/env bash
# Work-precision charts of docs/performance.md ("Speed against accuracy"): builds
# and runs bench/work_precision/ (symrep_work_precision), times SymPy on the same
# problems when it is installed, and draws the charts with gnuplot.
#
# usage: bash bench/work_precision.sh [--quick] [build-dir]     (default build dir: build)
#        PLOT_ONLY=1 bash bench/work_precision.sh [--quick]     (only redraw from the CSV files)
# Full run: CSV and PNG in docs/figures/ (wp_*), 4-8 minutes on 2 shared cores
# (the bench about 4, SymPy 30 s per problem at most). --quick: fewer tolerances
# and points, smaller budgets, SymPy limited to 10 s per problem, everything in
# /tmp/symrep-work-precision (docs/ untouched), 1-2 minutes.
# Environment: JOBS (build parallelism, default 2), SYMPY_TIMEOUT (seconds per problem).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

quick=""
build=build
for a in "$@"; do
    case $a in
        --quick) quick=--quick ;;
        -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
        *) build=$a ;;
    esac
done
out=docs/figures
sympy_timeout=${SYMPY_TIMEOUT:-30}
if [ -n "$quick" ]; then
    out=/tmp/symrep-work-precision
    sympy_timeout=${SYMPY_TIMEOUT:-10}
fi
mkdir -p "$out"

if [ -z "${PLOT_ONLY:-}" ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$build" -j"${JOBS:-2}" --target symrep_work_precision
    "$build"/symrep_work_precision $quick --out "$out"
    # Derivation by other systems, same problems, general axis (never required).
    {
        echo "problem,tool,seconds,cpu_seconds,status"
        if python3 -c "import sympy" 2>/dev/null; then
            python3 bench/work_precision/sympy_derive.py --timeout "$sympy_timeout" | tail -n +2
        else
            echo "all,sympy,,,not installed"
        fi
        if command -v maxima >/dev/null; then
            python3 bench/work_precision/maxima_derive.py --timeout "$sympy_timeout" | tail -n +2
        else
            echo "all,maxima,,,not installed"
        fi
    } > "$out/wp_derivation_others.csv"
fi

command -v gnuplot >/dev/null || { echo "gnuplot is not installed; CSV files are in $out" >&2; exit 1; }

scenes=(foucault_1d foucault_30d reduced_foucault_1d charge_1000 coriolis_60s centrifugal_60s)
titles=("Foucault pendulum, Paris, 1 day"
        "Foucault pendulum, Paris, 30 days"
        "reduced Foucault r'' + 2w×r' + w_0^2 r = 0, 1 day"
        "proton in E, B at 60°, 1000 gyrations"
        "gravity, rotating frame (Coriolis only), 60 s"
        "gravity, rotating frame (Coriolis + centrifugal), 60 s")

# Styles shared by all charts: one colour and point type per method.
common='
set datafile separator ","
set datafile missing ""
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid xtics ytics mxtics mytics lc rgb "#dddddd", lc rgb "#f0f0f0"
set style line 1 lc rgb "#000000" pt 13 ps 2.2 lw 2
set style line 2 lc rgb "#c00000" pt 7 ps 1.6 lw 2
set style line 3 lc rgb "#e69f00" pt 4 ps 1.1 lw 1.5
set style line 4 lc rgb "#0072b2" pt 6 ps 1.1 lw 1.5
set style line 5 lc rgb "#009e73" pt 8 ps 1.1 lw 1.5
set style line 6 lc rgb "#cc79a7" pt 12 ps 1.1 lw 1.5
set style line 7 lc rgb "#56b4e9" pt 9 ps 1.9 lw 2
clip(y) = y < 1e-17 ? 1e-17 : y
is(col, s) = strcol(col) eq s
'

# The legend of a figure, once, in the strip at the bottom of the canvas
# (multiplot cannot share a key): $1 the closed forms' style (p or l), $2 rk4's label, $3 the tolerances.
legend() {
    cat <<GP
set origin 0, 0
set size 1, 0.055
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid; unset logscale; unset arrow; unset label
set xrange [0:1]; set yrange [0:1]
set key center center horizontal maxcols 3 samplen 3 font ",12"
plot NaN w $1 ls 1 t "symrep closed form, compiled double program", NaN w $1 ls 7 t "symrep closed form, spectral evaluator", \\
     NaN w $1 ls 2 t "symrep closed form, stable evaluator", NaN w lp ls 3 t "rk4, $2", NaN w lp ls 4 t "dopri5, $3", \\
     NaN w lp ls 5 t "rkf78, $3", NaN w lp ls 6 t "bulirsch\\\\_stoer, $3"
GP
}

# One 3 x 2 figure of work-precision panels; $1: x column (5 wall seconds, 8 rhs
# evaluations), $2: file, $3: x label.
work_precision_figure() {
    local xcol=$1 png=$2 xlabel=$3 f="$out/wp_scenes.csv"
    {
        echo "$common"
        echo 'set terminal pngcairo size 1400,1500 font "DejaVu Sans,11"'
        echo "set output \"$out/$png\""
        echo 'set multiplot title "Error against cost: symrep closed forms and Boost.Odeint (max relative error over 200 output times, positions)" font ",13"'
        echo 'set ylabel "max relative error"'
        echo "set xlabel \"$xlabel\""
        echo 'set yrange [1e-17:10]'
        if [ "$xcol" = 8 ]; then echo 'set xrange [10:3e8]'; else echo 'set xrange [1e-6:30]'; fi
        echo 'set lmargin 10; set rmargin 3; set tmargin 2; set bmargin 4'
        echo 'unset key'
        echo "f = \"$f\""
        for i in "${!scenes[@]}"; do
            s=${scenes[$i]}
            echo "set origin $((i % 2)) * 0.5, 0.055 + (2 - $((i / 2))) * 0.305"
            echo 'set size 0.5, 0.305'
            echo "set title \"${titles[$i]}\""
            if [ "$xcol" = 8 ]; then
                # no right-hand sides: the closed forms are dashed horizontal lines at their error
                echo "stats f using (is(1, \"$s\") && is(2, \"symrep compiled\") ? clip(\$4) : NaN) nooutput"
                echo "cf = STATS_min; st = NaN; sp = NaN"
                if grep -q "^$s,symrep spectral," "$f"; then
                    echo "stats f using (is(1, \"$s\") && is(2, \"symrep spectral\") ? clip(\$4) : NaN) nooutput"
                    echo "sp = STATS_min"
                fi
                if grep -q "^$s,symrep stable," "$f"; then
                    echo "stats f using (is(1, \"$s\") && is(2, \"symrep stable\") ? clip(\$4) : NaN) nooutput"
                    echo "st = STATS_min"
                fi
                echo "plot cf w l ls 1 dt 2, st w l ls 2 dt 2, sp w l ls 7 dt 3, \\"
            else
                echo "plot f using (is(1, \"$s\") && is(2, \"symrep compiled\") ? \$$xcol : NaN):(clip(\$4)) w p ls 1, \\"
                echo "     f using (is(1, \"$s\") && is(2, \"symrep stable\") ? \$$xcol : NaN):(clip(\$4)) w p ls 2, \\"
                echo "     f using (is(1, \"$s\") && is(2, \"symrep spectral\") ? \$$xcol : NaN):(clip(\$4)) w p ls 7, \\"
            fi
            for m in rk4 dopri5 rkf78 bulirsch_stoer; do
                case $m in rk4) ls=3 ;; dopri5) ls=4 ;; rkf78) ls=5 ;; *) ls=6 ;; esac
                sep=", \\"; [ $m = bulirsch_stoer ] && sep=""
                echo "     f using (is(1, \"$s\") && is(2, \"$m\") ? \$$xcol : NaN):(clip(\$4)) w lp ls $ls$sep"
            done
        done
        if [ "$xcol" = 8 ]; then legend l "fixed steps" "tol 1e-3 .. 1e-14"; else legend p "fixed steps" "tol 1e-3 .. 1e-14"; fi
        echo 'unset multiplot'
    } > "$out/wp_plot.gp"
    gnuplot "$out/wp_plot.gp"
}

work_precision_figure 5 wp_cost_seconds.png "wall time per trajectory [s] (median of repeats)"
work_precision_figure 8 wp_cost_rhs.png "right-hand-side evaluations per trajectory (closed forms: none; dashed at their error)"

# Where each method breaks: error at t = 10 s against |w| t.
gnuplot <<GP
$common
set terminal pngcairo size 1400,620 font "DejaVu Sans,11"
set output "$out/wp_omega.png"
set multiplot title "Gravity in a rotating frame at t = 10 s, |w| from 10^{-12} to 10^{3} rad/s: max over components of |error_i| / |r_i(t)|" font ",13"
set xlabel "|w| t  [rad]"
set ylabel "relative error, worst component"
set yrange [1e-17:1e3]
set xrange [5e-12:2e4]
set arrow 1 from 7.2921e-4, graph 0 to 7.2921e-4, graph 1 nohead dt 3 lc rgb "#555555"
set label 1 "Earth, 10 s" at 7.2921e-4, graph 0.95 offset 0.5, 0 font ",10"
unset key
f = "$out/wp_omega.csv"
set lmargin 10; set rmargin 3
set size 0.5, 0.85
do for [sc in "coriolis centrifugal"] {
  set origin (sc eq "coriolis" ? 0 : 0.5), 0.09
  set title (sc eq "coriolis" ? "r'' + 2w×r' = g  (VI.1.50)" : "r'' + 2w×r' + w×(w×r) = g  (VI.1.56)")
  plot f using (is(1, sc) && is(4, "symrep compiled") ? \$3 : NaN):(clip(\$5)) w lp ls 1 ps 1.2, \
       f using (is(1, sc) && is(4, "symrep stable") ? \$3 : NaN):(clip(\$5)) w lp ls 2 ps 1, \
       f using (is(1, sc) && is(4, "symrep spectral") ? \$3 : NaN):(clip(\$5)) w lp ls 7 ps 1, \
       f using (is(1, sc) && is(4, "rk4") ? \$3 : NaN):(clip(\$5)) w lp ls 3, \
       f using (is(1, sc) && is(4, "dopri5") ? \$3 : NaN):(clip(\$5)) w lp ls 4, \
       f using (is(1, sc) && is(4, "rkf78") ? \$3 : NaN):(clip(\$5)) w lp ls 5, \
       f using (is(1, sc) && is(4, "bulirsch_stoer") ? \$3 : NaN):(clip(\$5)) w lp ls 6
}
unset arrow 1; unset label 1
set origin 0, 0
set size 1, 0.1
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid; unset logscale
set xrange [0:1]; set yrange [0:1]
set key center center horizontal maxcols 4 samplen 3 font ",12"
plot NaN w lp ls 1 t "symrep closed form, compiled double program", NaN w lp ls 7 t "symrep closed form, spectral evaluator", \
     NaN w lp ls 2 t "symrep closed form, stable evaluator", \
     NaN w lp ls 3 t "rk4, step 10^{-3} s", NaN w lp ls 4 t "dopri5, tol 10^{-12}", \
     NaN w lp ls 5 t "rkf78, tol 10^{-12}", NaN w lp ls 6 t "bulirsch\\\\_stoer, tol 10^{-12}"
unset multiplot
GP

# Error growth with t: Foucault pendulum over 30 days (3 with --quick).
gnuplot <<GP
$common
set terminal pngcairo size 1100,700 font "DejaVu Sans,11"
set output "$out/wp_long_time.png"
set title "Foucault pendulum at Paris: error against time (max over components of |error_i(t)| / amplitude; about the phase error in rad)" font ",12"
set xlabel "t [s]"
set ylabel "error / amplitude"
set yrange [1e-17:10]
set xrange [1:3e6]
set bmargin 4
set arrow 1 from 86400, graph 0 to 86400, graph 1 nohead dt 3 lc rgb "#555555"
set label 1 "1 day" at 86400, 3e-15 offset 0.5, 0 font ",10"
set key top left box opaque font ",10"
f = "$out/wp_long_time.csv"
plot f using (is(2, "symrep compiled") ? \$4 : NaN):(clip(\$5)) w l ls 1 t "symrep closed form, compiled double program", \
     f using (is(2, "symrep stable") ? \$4 : NaN):(clip(\$5)) w l ls 2 t "symrep closed form, stable evaluator", \
     f using (is(2, "symrep spectral") ? \$4 : NaN):(clip(\$5)) w l ls 7 t "symrep closed form, spectral evaluator", \
     f using (is(2, "rk4") ? \$4 : NaN):(clip(\$5)) w l ls 3 t "rk4, step 0.5 s", \
     f using (is(2, "dopri5") ? \$4 : NaN):(clip(\$5)) w l ls 4 t "dopri5, tol 10^{-7}", \
     f using (is(2, "rkf78") && is(3, "1e-10") ? \$4 : NaN):(clip(\$5)) w l ls 5 t "rkf78, tol 10^{-10}", \
     f using (is(2, "rkf78") && is(3, "1e-13") ? \$4 : NaN):(clip(\$5)) w l ls 5 dt 2 t "rkf78, tol 10^{-13}", \
     f using (is(2, "bulirsch_stoer") && is(3, "1e-10") ? \$4 : NaN):(clip(\$5)) w l ls 6 t "bulirsch\\\\_stoer, tol 10^{-10}", \
     f using (is(2, "bulirsch_stoer") && is(3, "1e-13") ? \$4 : NaN):(clip(\$5)) w l ls 6 dt 2 t "bulirsch\\\\_stoer, tol 10^{-13}"
GP
rm -f "$out/wp_plot.gp"
echo "wrote $out/wp_cost_seconds.png, wp_cost_rhs.png, wp_omega.png, wp_long_time.png (data: $out/wp_*.csv)"
