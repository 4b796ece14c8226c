# The symrep kernel logo (repl/python/symrep/kernelspec/logo-*.png): the trace of a Foucault pendulum,
# seen from above (thesis VI.1.79). Regenerate: cd repl/python/symrep/kernelspec &&
#   gnuplot -c ../../kernel_logo.gp 32 logo-32x32.png && gnuplot -c ../../kernel_logo.gp 64 logo-64x64.png
size = int(ARG1)
set terminal pngcairo size size,size transparent enhanced
set output ARG2
unset border; unset tics; unset key
set margins 0,0,0,0
set size square
set xrange [-1.08:1.08]; set yrange [-1.08:1.08]
set parametric
set samples 4000
set trange [0:2*pi]
W = 1.0; w0 = 9.0
# r = exp(-i W t) (cos(w0 t) + i W/w0 sin(w0 t)) (thesis VI.1.79 seen from above)
x(t) = cos(W*t)*cos(w0*t) + sin(W*t)*(W/w0)*sin(w0*t)
y(t) = -sin(W*t)*cos(w0*t) + cos(W*t)*(W/w0)*sin(w0*t)
set object 1 circle at 0,0 size 1.05 fc rgb "#1f3a5f" fs solid 1.0 noborder behind
lw = size/32.0
plot x(t), y(t) lw lw lc rgb "#f2b134"
