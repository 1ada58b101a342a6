# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 1200,1000 enhanced font 'Sans,10'
set datafile separator ','
set output "atlas_cost.png"
set multiplot layout 2,2 title "log10 of the RHS evaluations of each point (estimate included)" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "mu_ratio, coulomb law" noenhanced
set xlabel "mu" noenhanced
set ylabel "push F / (mu N)" noenhanced
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set xrange [0.000776186:2.5767]
set yrange [0.0857696:11.6591]
unset key

plot "atlas.csv" skip 1 using (strcol(1) eq 'mu_ratio' && strcol(2) eq 'coulomb' ? $3 : 1/0):4:(log10($10)) with points pt 5 ps 2.2 palette title "" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "mu_ratio, thesis law" noenhanced
set xlabel "mu" noenhanced
set ylabel "push F / (mu N)" noenhanced
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set xrange [0.000776186:2.5767]
set yrange [0.0857696:11.6591]
unset key

plot "atlas.csv" skip 1 using (strcol(1) eq 'mu_ratio' && strcol(2) eq 'thesis' ? $3 : 1/0):4:(log10($10)) with points pt 5 ps 2.2 palette title "" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "length_force, coulomb law" noenhanced
set xlabel "object length L [m]" noenhanced
set ylabel "push force [N]" noenhanced
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set xrange [7.94328e-09:1.25893e-05]
set yrange [5.01187e-13:0.00199526]
unset key

plot "atlas.csv" skip 1 using (strcol(1) eq 'length_force' && strcol(2) eq 'coulomb' ? $3 : 1/0):4:(log10($10)) with points pt 5 ps 2.2 palette title "" noenhanced
reset session
set datafile separator ','
set grid
set key outside right top vertical
set title "length_force, thesis law" noenhanced
set xlabel "object length L [m]" noenhanced
set ylabel "push force [N]" noenhanced
set logscale x
set format x '10^{%L}'
set logscale y
set format y '10^{%L}'
set xrange [7.94328e-09:1.25893e-05]
set yrange [5.01187e-13:0.00199526]
unset key

plot "atlas.csv" skip 1 using (strcol(1) eq 'length_force' && strcol(2) eq 'thesis' ? $3 : 1/0):4:(log10($10)) with points pt 5 ps 2.2 palette title "" noenhanced
unset multiplot

unset output
