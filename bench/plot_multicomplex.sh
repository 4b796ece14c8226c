#!/usr/bin/env bash
# Runs the multicomplex benchmarks and draws docs/multicomplex_bench.png.
# usage: bash bench/plot_multicomplex.sh [build-dir]       (default: build)
#        CSV=existing.csv bash bench/plot_multicomplex.sh   (only redraw)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
csv=${CSV:-docs/multicomplex_bench.csv}
if [ -z "${CSV:-}" ]; then
    "$build"/symrep_bench --benchmark_filter='Multicomplex' --benchmark_min_time=0.2 \
        --benchmark_format=csv 2>/dev/null > /tmp/symrep_mc_raw.csv
    # name,iterations,real_time,cpu_time,time_unit,...  ->  series,n,cpu_us
    awk -F, 'NR > 1 && $1 ~ /BM_/ {
        gsub(/"/, "", $1); split($1, p, "/"); s = p[1]; sub(/^BM_Multicomplex/, "", s);
        t = $4; u = $5; if (u == "ns") t /= 1000; else if (u == "ms") t *= 1000;
        print s "," p[2] "," t }' /tmp/symrep_mc_raw.csv > "$csv"
fi
for s in Double_Product Double_Inverse Double_Exp Double_ProductStructure Exact_Product; do
    grep "^$s," "$csv" | cut -d, -f2,3 | tr , ' ' > "/tmp/symrep_mc_$s.dat"
done
gnuplot <<GP
set terminal pngcairo size 900,600 font "DejaVu Sans,11"
set output "docs/multicomplex_bench.png"
set title "Multicomplex algebra (x)C^{n+1}: CPU time per operation"
set xlabel "n (order 2^{n+1})"
set ylabel "time per operation [µs]"
set logscale y
set format y "10^{%L}"
set grid
set key bottom right box opaque
set xrange [0.5:20.5]
plot "/tmp/symrep_mc_Double_Product.dat" w lp pt 7 t "product, idempotent components (double)", \
     "/tmp/symrep_mc_Double_Inverse.dat" w lp pt 5 t "inverse (double)", \
     "/tmp/symrep_mc_Double_Exp.dat" w lp pt 9 t "exp(w t) (double)", \
     "/tmp/symrep_mc_Double_ProductStructure.dat" w lp pt 11 t "structure-constant product (double)", \
     "/tmp/symrep_mc_Exact_Product.dat" w lp pt 13 t "exact product (GiNaC)"
GP
echo "wrote docs/multicomplex_bench.png from $csv"
