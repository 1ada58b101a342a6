# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 1000,700 enhanced font 'Sans,10'
set datafile separator ','
set output "plan_benchmark.png"
set multiplot layout 1,2 title "bench-plan: pushes per task" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "pushes (0: not found)" noenhanced
set xlabel "task" noenhanced
set ylabel "pushes" noenhanced
set key top left
plot "plan_benchmark.csv" skip 1 using 1:(strcol(2) eq 'plan' ? $8 * $7 : NaN) with points pt 7 ps 0.6 title "plan" noenhanced, \
     "plan_benchmark.csv" skip 1 using 1:(strcol(2) eq 'baseline' ? $8 * $7 : NaN) with points pt 6 ps 0.8 title "baseline" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "planning time" noenhanced
set xlabel "task" noenhanced
set ylabel "s" noenhanced
set logscale y
set format y '10^{%L}'
set key top left
plot "plan_benchmark.csv" skip 1 using 1:(strcol(2) eq 'plan' ? $11 : NaN) with points pt 7 ps 0.6 title "plan" noenhanced, \
     "plan_benchmark.csv" skip 1 using 1:(strcol(2) eq 'baseline' ? $11 : NaN) with points pt 6 ps 0.8 title "baseline" noenhanced
unset multiplot

unset output
