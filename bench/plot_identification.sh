#!/usr/bin/env bash
# Charts of the identification layer (docs/identification.md, docs/performance.md,
# "Identification"): runs BM_Identify and BM_IdentifyNoise of bench/bench_identification.cpp
# and draws, with gnuplot, the error against the number of blocks, the error against the
# noise in the measured q, and the cost against the number of blocks, for the integral form,
# the thesis's values, the regression on unsmoothed derivatives and the strong baseline (the
# cross-validated SINDy pipeline, identification/sindy.h); and BM_IdentifySystems, five systems
# at four noise levels, as a CSV (the table of docs/identification.md).
#
# usage: bash bench/plot_identification.sh [build-dir]        (default build dir: build)
#        PLOT_ONLY=1 bash bench/plot_identification.sh  (redraw from the CSV files in docs/figures)
# Output: docs/figures/identification_convergence.{csv,png}, identification_noise.{csv,png},
# identification_cost.png, identification_systems.csv.
source "$(dirname "${BASH_SOURCE[0]}")/plot_common.sh"  # strict mode, repository root, $build, $out
if [ -z "${PLOT_ONLY:-}" ]; then
    if [ -z "${NO_BUILD:-}" ]; then  # NO_BUILD=1: symrep_bench is built already
        cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
        cmake --build "$build" -j"${JOBS:-2}" --target symrep_bench
    fi
    conv=$(mktemp)
    noise=$(mktemp)
    systems=$(mktemp)
    # the cross-validated SINDy (method 5) needs 2^6 samples or more
    "$build"/symrep_bench --benchmark_filter='BM_Identify/([0-3]/[0-9]+|5/([68]|1[0246]))$' --benchmark_format=csv > "$conv" 2>/dev/null
    "$build"/symrep_bench --benchmark_filter='BM_IdentifyNoise/' --benchmark_format=csv > "$noise" 2>/dev/null
    "$build"/symrep_bench --benchmark_filter='BM_IdentifySystems/' --benchmark_format=csv > "$systems" 2>/dev/null
    # name,iterations,real_time,cpu_time,time_unit,bytes_per_second,items_per_second,label,error_occurred,error_message,<counters>
    {
        echo "method,blocks,cpu_ms,error"
        grep -E '^"BM_Identify/' "$conv" | tr -d '"' |
            awk -F, '{printf "%s,%d,%s,%s\n", $8, $11, $4, $12}'
    } > "$out/identification_convergence.csv"
    {
        echo "method,noise,cpu_ms,error"
        grep -E '^"BM_IdentifyNoise/' "$noise" | tr -d '"' |
            awk -F, '{printf "%s,%s,%s,%s\n", $8, $12, $4, $11}'
    } > "$out/identification_noise.csv"
    # counters in alphabetical order: error, noise, system, window
    {
        echo "method,system,noise,error,window,cpu_ms"
        grep -E '^"BM_IdentifySystems/' "$systems" | tr -d '"' |
            awk -F, '{printf "%s,%d,%s,%s,%d,%s\n", $8, $13, $12, $11, $14, $4}'
    } > "$out/identification_systems.csv"
    rm -f "$conv" "$noise" "$systems"
fi
gp=${SYMREP_GNUPLOT:-gnuplot}
for m in integral values derivatives values_as_printed sindy_stlsq sindy_cv; do
    grep "^$m," "$out/identification_convergence.csv" > "/tmp/idconv_$m.dat" || true
    grep "^$m," "$out/identification_noise.csv" | awk -F, '$2 > 0' > "/tmp/idnoise_$m.dat" || true
done
"$gp" <<GP
set datafile separator ","
set terminal pngcairo noenhanced size 900,600 font ",11"
set logscale xy
set format y "%.0e"
set format x "%g"
set grid
set key top right
set output "$out/identification_convergence.png"
set title "Duffing q'' + 4 q + 50 q^3 = u: coefficient error against the number of blocks (no noise)"
set xlabel "blocks 2^n"
set ylabel "|c - c_true| / |c_true|"
plot "/tmp/idconv_integral.dat" using 2:4 with linespoints title "integral form (least squares, IV.2.39)", \
     "/tmp/idconv_values.dat" using 2:4 with linespoints title "thesis's values (IV.2.36), pole cancelled", \
     "/tmp/idconv_derivatives.dat" using 2:4 with linespoints title "regression on finite differences", \
     "/tmp/idconv_sindy_cv.dat" using 2:4 with linespoints title "SINDy: Savitzky-Golay + STLSQ, cross-validated", \
     "/tmp/idconv_values_as_printed.dat" using 2:4 with linespoints title "thesis's values as printed (IV.2.36)"
set output "$out/identification_noise.png"
set title "coefficient error against relative noise in the measured q (2^10 blocks, fixed seed)"
set xlabel "noise (relative to rms q)"
set format x "%.0e"
set key top left
plot "/tmp/idnoise_integral.dat" using 2:4 with linespoints title "integral form", \
     "/tmp/idnoise_values.dat" using 2:4 with linespoints title "thesis's values", \
     "/tmp/idnoise_derivatives.dat" using 2:4 with linespoints title "regression on finite differences", \
     "/tmp/idnoise_sindy_stlsq.dat" using 2:4 with linespoints title "finite differences + STLSQ (threshold 0.5)", \
     "/tmp/idnoise_sindy_cv.dat" using 2:4 with linespoints title "SINDy: Savitzky-Golay + STLSQ, cross-validated"
set output "$out/identification_cost.png"
set title "CPU time of one identification against the number of blocks"
set xlabel "blocks 2^n"
set ylabel "CPU ms"
set format y "%g"
plot "/tmp/idconv_integral.dat" using 2:3 with linespoints title "integral form", \
     "/tmp/idconv_values.dat" using 2:3 with linespoints title "thesis's values", \
     "/tmp/idconv_derivatives.dat" using 2:3 with linespoints title "regression on finite differences", \
     "/tmp/idconv_sindy_cv.dat" using 2:3 with linespoints title "SINDy, cross-validated (60 fits)"
GP
echo "wrote $out/identification_convergence.{csv,png} $out/identification_noise.{csv,png} $out/identification_cost.png $out/identification_systems.csv"
