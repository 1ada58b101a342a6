# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>
if (strstrt(ARG0, "/") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne "/") { _d = _d[1:strlen(_d)-1] }; cd _d }
set terminal pngcairo size 900,600 enhanced font 'Sans,10'
set datafile separator ','
set output "sweep_bench.png"
set title 'nanopush sweep: 1000 rough-surface points (fig3_18, coulomb law), task run; median of 5 runs' noenhanced
set xlabel 'workers (threads in one process, or MPI ranks of one thread)'
set ylabel 'points/s'
set grid
set key left top
set xrange [0.8:2.2]
set xtics 1
set yrange [0:*]
P1 = 184.19656975624088
plot "sweep_bench.csv" skip 1 using (strcol(1) eq 'threads' ? $4 : 1/0):($5/$7):($5/$9):($5/$8) with yerrorlines lw 2 pt 7 title 'threads (one process)', \
     "sweep_bench.csv" skip 1 using (strcol(1) eq 'mpi' ? $4 : 1/0):($5/$7):($5/$9):($5/$8) with yerrorlines lw 2 pt 5 title 'MPI ranks (mpirun -np R, one thread each)', \
     P1*x with lines dt 2 lw 1.5 lc rgb 'black' title 'ideal: workers x 1-thread rate'

unset output
