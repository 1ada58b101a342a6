#!/usr/bin/env bash
# A rank that waits does not spin (issue 34, item 3): `mpirun -np 2 nanopush-mpi sweep` of one
# slow point (rank 0 computes it; rank 1, given no work, waits for the exit status); rank 1's
# CPU time over a wall interval, read from /proc, must be well below a core. Not timed: the
# bound (50 % of a core) is generous (a waiting rank measures ~0.2 %, one spinning in a
# blocking MPI call ~100 %); the benchmark reports the figure (docs/sweeps.md, "Benchmark").
# Usage: mpi_idle_check.sh NANOPUSH WORKDIR MPIEXEC
set -euo pipefail
np=$1 dir=$2 mpiexec=$3
np_mpi="$(dirname "$np")/nanopush-mpi"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
# One point of a few seconds (fig3_18, coulomb law, 50 us of pushing).
$mpiexec --oversubscribe -np 2 "$np_mpi" sweep fig3_18 --set surface.law=coulomb --set solver.t_end=5e-5 \
  --set solver.max_steps=100000000 --set solver.samples=3 --vary surface.mu=0.02 --no-error-estimate --jobs 1 \
  --quiet --out idle.csv 2> err.txt &
mp=$!
# The journal appears when rank 0 starts its point: every rank is past MPI_Init.
for _ in $(seq 1 600); do [ -f idle.csv.journal ] && break; sleep 0.05; done
[ -f idle.csv.journal ] || fail "no journal after 30 s: $(cat err.txt)"
rank1=""
for p in $(pgrep -P $mp); do
  tr '\0' '\n' < /proc/$p/environ 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1" && rank1=$p
done
[ -n "$rank1" ] || fail "rank 1 not found under mpirun $mp"
ticks() { awk '{sub(/^.*\) /, ""); print $12 + $13}' /proc/$rank1/stat; }  # utime + stime
hz=$(getconf CLK_TCK)
c0=$(ticks); t0=$(date +%s%N)
sleep 1.5
c1=$(ticks) || fail "rank 1 ended before the interval did (the point was too short to watch)"
t1=$(date +%s%N)
kill -0 $mp 2>/dev/null || fail "the job ended before the interval did (the point was too short to watch)"
# CPU share of a core, in percent: ticks / hz over the wall interval
share=$(awk -v c=$((c1 - c0)) -v hz=$hz -v ns=$((t1 - t0)) 'BEGIN { printf "%.1f", 100 * c / hz / (ns / 1e9) }')
echo "rank 1 waiting: $((c1 - c0)) ticks (1/$hz s) over $(( (t1 - t0) / 1000000 )) ms: $share % of a core"
awk -v s=$share 'BEGIN { exit !(s < 50) }' || fail "a waiting rank uses $share % of a core (bound 50 %): it spins"
set +e; wait $mp; rc=$?; set -e
[ "$rc" = 0 ] || fail "the sweep exited $rc: $(cat err.txt)"
[ "$(wc -l < idle.csv)" = 2 ] || fail "the table has not one row: $(cat idle.csv)"
echo "mpi idle check: ok"
