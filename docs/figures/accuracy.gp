# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 1300,600 enhanced font 'Sans,10'
set datafile separator ','
set output "accuracy.png"
set multiplot layout 1,2 title "error estimate against the true error; cost of --accuracy" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "honesty (above the dashed line: true > 10x estimate)" noenhanced
set xlabel "estimate" noenhanced
set ylabel "true error" noenhanced
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
plot "accuracy_honesty.csv" skip 1 using 5:(strcol(1) eq 'coulomb' ? $6 : 1/0) with points pt 7 ps 0.6 title "coulomb" noenhanced, \
     "accuracy_honesty.csv" skip 1 using 5:(strcol(1) eq 'thesis' ? $6 : 1/0) with points pt 6 ps 0.6 title "thesis" noenhanced, \
     "accuracy_honesty.csv" skip 1 using 5:($5*10) with lines dt 2 lc rgb 'black' title "true = 10 x estimate" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "--accuracy E: RHS evaluations over a plain run at rtol = E" noenhanced
set xlabel "accuracy asked E" noenhanced
set ylabel "cost ratio" noenhanced
set logscale x
set format x '10^{%L}'
plot "accuracy_cost.csv" skip 1 using 1:9 with points pt 7 ps 0.6 title "scenes" noenhanced
unset multiplot

unset output
