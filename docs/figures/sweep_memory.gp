# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 900,600 enhanced font 'Sans,10'
set datafile separator ','
set output "sweep_memory.png"
set title 'nanopush sweep --task friction: peak resident memory against points' noenhanced
set xlabel 'points of the grid' noenhanced
set ylabel 'peak RSS (MB)' noenhanced
set logscale x
set grid
set key outside bottom center horizontal
set yrange [0:*]
plot "sweep_memory.csv" skip 1 using 1:7 with linespoints lw 2 pt 7 title 'peak RSS', \
     200 with lines dt 2 lc rgb 'black' title 'target (200 MB)'

unset output
