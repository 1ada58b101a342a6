# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 800,700 enhanced font 'Sans,10'
set datafile separator ','
set output "fit_coverage.png"
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "fit coverage: (estimate - truth) / stderr against normal quantiles" noenhanced
set xlabel "standard normal quantile" noenhanced
set ylabel "z" noenhanced
set key inside top left

plot "fit_coverage.csv" skip 1 using 7:(strcol(1) eq 'smooth push.force' ? $6 : 1/0) with points pt 7 ps 0.6 title "smooth push.force" noenhanced, \
     "fit_coverage.csv" skip 1 using 7:(strcol(1) eq 'rough thesis surface.mu' ? $6 : 1/0) with points pt 7 ps 0.6 title "rough thesis surface.mu" noenhanced, \
     "fit_coverage.csv" skip 1 using 7:(strcol(1) eq 'rough coulomb surface.mu' ? $6 : 1/0) with points pt 7 ps 0.6 title "rough coulomb surface.mu" noenhanced, \
     "fit_coverage.csv" skip 1 using 7:7 with lines lw 1 lc rgb 'black' title "y = x" noenhanced

unset output
