#!/usr/bin/env bash
# Checks of nanopush sweep and --set that need several runs compared byte for byte.
# Usage: sweep_checks.sh MODE NANOPUSH WORKDIR [MPIEXEC]
set -euo pipefail
mode=$1 np=$2 dir=$3 mpiexec=${4:-}
np_mpi="$(dirname "$np")/nanopush-mpi"  # the command line with MPI, beside nanopush
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
# A small rough-surface grid under the coulomb law (points differ in cost; one fails).
grid=(fig3_18 --set surface.law=coulomb --vary surface.mu=0.02:0.2:5 --vary push.yn=0:45e-9:4 --quiet)
fail() { echo "FAIL: $*"; exit 1; }
status() { set +e; "$@"; local rc=$?; set -e; echo $rc; }
# run_holds SIDECAR EXPR: the Python expression EXPR holds of r, the sidecar's nanopush.run object
run_holds() { python3 -c 'import json, sys; r = json.load(open(sys.argv[1]))["nanopush"]["run"]; sys.exit(0 if eval(sys.argv[2]) else 1)' "$1" "$2"; }

case $mode in
jobs)  # the table is the same bytes for 1 and 2 threads
  [ "$(status "$np" sweep "${grid[@]}" --jobs 1 --out j1.csv)" = 0 ] || fail "jobs 1"
  [ "$(status "$np" sweep "${grid[@]}" --jobs 2 --out j2.csv)" = 0 ] || fail "jobs 2"
  cmp j1.csv j2.csv || fail "jobs 1 and 2 differ"
  [ "$(wc -l < j1.csv)" = 21 ] || fail "expected 20 rows and a header"
  [ -f j1.schema.json ] || fail "no sidecar"
  [ ! -e j1.csv.journal ] || fail "journal left after a complete sweep"
  head -1 j1.csv | grep -q '^point,surface_mu,push_yn,x_final,' || fail "header: $(head -1 j1.csv)" ;;
shards)  # two shards merged equal one run
  "$np" sweep "${grid[@]}" --out all.csv
  "$np" sweep "${grid[@]}" --shard 0/2 --out s0.csv
  "$np" sweep "${grid[@]}" --shard 1/2 --out s1.csv
  "$np" sweep --merge s1.csv s0.csv --out merged.csv --quiet
  cmp all.csv merged.csv || fail "merged shards differ from one run"
  [ "$(status "$np" sweep --merge s0.csv --out part.csv --quiet 2> err.txt)" = 2 ] || fail "a missing shard must be an error"
  grep -q "shard 1/2: is missing" err.txt || fail "message: $(cat err.txt)"
  run_holds merged.schema.json 'r["shard"] == "merged from 2" and r["rows"] == 20' || fail "merged sidecar: $(cat merged.schema.json)"
  # Missing trailing points leave no gap: the plan's size in the sidecar finds them.
  three=(fig3_18 --vary surface.mu=0.05,0.06,0.07 --quiet)
  for i in 0 1 2; do "$np" sweep "${three[@]}" --shard $i/3 --out t$i.csv; done
  [ "$(status "$np" sweep --merge t0.csv t1.csv --out t01.csv --quiet 2> err.txt)" = 2 ] || fail "a missing last shard must be an error"
  grep -q "the plan has 3" err.txt || fail "message: $(cat err.txt)"
  [ ! -e t01.csv ] || fail "a refused merge left a table" ;;
mpi)  # two MPI ranks of nanopush-mpi write the same table as one process of nanopush
  "$np" sweep "${grid[@]}" --out serial.csv
  # The plain nanopush, which loads no MPI, names its MPI twin when mpirun starts it.
  [ "$(status $mpiexec --oversubscribe -np 2 "$np" sweep "${grid[@]}" --out plain.csv 2> plain_err.txt)" != 0 ] \
    || fail "plain nanopush under mpirun must refuse the sweep"
  grep -q 'start the sweep with `mpirun -np R nanopush-mpi sweep' plain_err.txt || fail "message: $(cat plain_err.txt)"
  [ ! -e plain.csv ] || fail "a refused sweep left a table"
  $mpiexec --oversubscribe -np 2 "$np_mpi" sweep "${grid[@]}" --out mpi.csv
  cmp serial.csv mpi.csv || fail "MPI table differs"
  [ ! -e mpi.csv.journal ] || fail "journal left"
  grep -q '"ranks": 2' mpi.schema.json || fail "sidecar: $(grep '"run"' mpi.schema.json)"
  # Ranks of two threads each (rank 1 then feeds threads instead of working on its main thread).
  $mpiexec --oversubscribe -np 2 "$np_mpi" sweep "${grid[@]}" --jobs 2 --out mpi2.csv
  cmp serial.csv mpi2.csv || fail "MPI table with 2 threads per rank differs" ;;
resume)  # killed with SIGKILL mid-way, then resumed: the same table as an uninterrupted run
  big=(fig3_18 --set surface.law=coulomb --vary surface.mu=0.02:0.2:20 --vary push.yn=0:45e-9:20 --quiet --jobs 1)
  set +e; "$np" sweep "${big[@]}" --out full.csv; set -e
  "$np" sweep "${big[@]}" --out killed.csv &
  pid=$!
  for _ in $(seq 1 400); do
    [ -f killed.csv.journal ] && [ "$(wc -l < killed.csv.journal)" -ge 40 ] && break
    sleep 0.02
  done
  kill -9 $pid; wait $pid || true
  [ ! -e killed.csv ] || fail "a table appeared for an unfinished sweep"
  n=$(wc -l < killed.csv.journal)
  [ "$n" -ge 3 ] && [ "$n" -lt 402 ] || fail "journal has $n lines"
  # A record whose point index is out of any range (an integer past 2^64) is skipped and its
  # point computed again; so is a line of text.
  sed -i '3s/^[0-9]*\t/99999999999999999999999\t/' killed.csv.journal  # line 2 is the plan record
  grep -q $'^99999999999999999999999\t' killed.csv.journal || fail "the journal was not tampered"
  printf 'not a record\n' >> killed.csv.journal
  # A record cut short (as by a kill mid-write) is ignored.
  printf '123\tdeadbeef\t123,0.1,trunc' >> killed.csv.journal
  set +e; "$np" sweep "${big[@]}" --out killed.csv; set -e
  cmp full.csv killed.csv || fail "resumed table differs"
  # A journal of another sweep is refused.
  printf 'nanopush-sweep-journal 1 0000000000000000\n' > other.csv.journal
  [ "$(status "$np" sweep "${grid[@]}" --out other.csv 2> err.txt)" = 2 ] || fail "foreign journal accepted"
  grep -q "belongs to a different sweep" err.txt || fail "message: $(cat err.txt)" ;;
twice)  # a second SIGINT while the point in flight finishes (quad precision: ~0.5 s a point):
  # exit 130 at once, the line said, no temporary left, the journal kept for a resume
  "$np" sweep fig3_18 --set solver.precision=quad --set solver.rtol=1e-20 --set solver.error_estimate=false \
    --vary surface.mu=0.05:0.1:100 --jobs 1 --out twice.csv --quiet 2> err.txt &
  pid=$!
  for _ in $(seq 1 400); do [ -f twice.csv.journal ] && break; sleep 0.02; done
  sleep 0.1
  kill -INT $pid
  sleep 0.1  # delivered (two signals sent together can merge into one)
  kill -INT $pid
  set +e; wait $pid; rc=$?; set -e
  [ "$rc" = 130 ] || fail "exit status $rc, expected 130"
  grep -q "nanopush: interrupted (SIGINT): outputs not yet complete were removed" err.txt || fail "stderr: $(cat err.txt)"
  [ -z "$(ls | grep '^twice.csv.tmp')" ] || fail "a temporary was left: $(ls)"
  [ -f twice.csv.journal ] || fail "the journal is gone" ;;
failing)  # a failing point is a row; the exit status counts the failures (64 + n)
  rc=$(status "$np" sweep fig3_6a --vary solver.max_steps=1,100000 --out f.csv --quiet)
  [ "$rc" = 65 ] || fail "exit status $rc, expected 65 (one failed point)"
  grep -q '^0,1,.*,solver_failure,' f.csv || fail "no failure row: $(cat f.csv)"
  grep -q '^1,100000,.*,ok,$' f.csv || fail "the good point is missing"
  # six failures: 65 + 6, never 70 (the internal error's status)
  rc=$(status "$np" sweep fig3_6a --vary solver.max_steps=1,2,3,4,5,6 --out f6.csv --quiet)
  [ "$rc" = 71 ] || fail "exit status $rc, expected 71 (six failed points)" ;;
set)  # --set changes exactly what an edited scene file changes (bit for bit)
  sed -e 's/^mu = 0.06/mu = 0.1/' -e 's/^yn = 45e-9 /yn = 20e-9 /' "$5" > edited.toml
  grep -q '^mu = 0.1$' edited.toml && grep -q '^yn = 20e-9 ' edited.toml || fail "sed did not edit the scene"
  "$np" run fig3_18 --set surface.mu=0.1 --set push.yn=20e-9 --out set.csv --quiet
  "$np" run edited.toml --out edited.csv --quiet
  cmp set.csv edited.csv || fail "--set differs from the edited file"
  "$np" deck fig3_18 --set surface.mu=0.1 --set push.yn=20e-9 > set.deck
  "$np" deck edited.toml > edited.deck
  # (the first line names the source file)
  cmp <(tail -n +2 set.deck) <(tail -n +2 edited.deck) || fail "deck --set differs" ;;
tasks)  # sweeps of closed-form evaluations
  "$np" sweep --task friction --set a=27.5e-9 --set b=50e-9 --vary R=1e-9:1e-6:3 --vary alpha=0,1.5707963267948966 --out fr.csv --quiet
  [ "$(wc -l < fr.csv)" = 7 ] || fail "friction rows"
  head -1 fr.csv | grep -q '^point,R,alpha,fx,fy,mf,status,message$' || fail "friction header $(head -1 fr.csv)"
  "$np" sweep --task icor --vary yn=0:100e-9:3 --set mu=0.1 --out ic.csv --quiet
  grep -q '^2,1e-07,' ic.csv || fail "icor row"
  "$np" sweep --task estimate-mu --set force=2e-6 --set sigma_force=1e-7 --vary yn=10e-9,50e-9 --out mu.csv --quiet
  grep -q '^0,1e-08,force,' mu.csv || fail "estimate-mu row: $(cat mu.csv)"
  [ "$(status "$np" sweep --task friction --vary Q=1,2 --out bad.csv --quiet 2> err.txt)" = 2 ] || fail "bad key accepted"
  grep -q "Q = (varied): not a parameter of --task friction" err.txt || fail "message: $(cat err.txt)"
  run_holds ic.schema.json 'list(r)[:7] == ["task", "plan", "plan_points", "shard", "rows", "failed", "wall_s"] and r["task"] == "icor" and len(r["plan"]) == 16 and int(r["plan"], 16) >= 0 and (r["plan_points"], r["shard"], r["rows"], r["failed"]) == (3, "0/1", 3, 0)' \
    || fail "sidecar run: $(cat ic.schema.json)"
  "$np" sweep --task icor --vary yn=0:100e-9:3 --set cubic=eigen --out ice.csv --quiet
  head -1 ice.csv | grep -q ',R_constrained_negative,R_constrained_positive,' || fail "icor header $(head -1 ice.csv)"
  [ "$(status "$np" sweep --task icor --vary yn=0,1e-8 --set cubic=lapack --out bad.csv --quiet 2> err.txt)" = 2 ] || fail "bad choice accepted"
  grep -q "cubic = lapack: must be one of: brent, eigen" err.txt || fail "message: $(cat err.txt)"
  [ "$(status "$np" sweep --task friction --vary R=1e-8,abc --out bad.csv --quiet 2> err.txt)" = 2 ] || fail "a word for a number accepted"
  grep -q "R = abc: must be a number" err.txt || fail "message: $(cat err.txt)"
  [ ! -e bad.csv ] || fail "a refused sweep left a table" ;;
inputs)  # every input through the guarded reader: a FIFO never blocks, /dev/zero never grows, integers are range-checked
  # refused CODE REGEX ARGS...: nanopush ARGS exits CODE within 10 s, stderr matches REGEX
  refused() {
    local code=$1 re=$2; shift 2
    set +e; timeout 10 "$np" "$@" > out.txt 2> err.txt; local rc=$?; set -e
    [ "$rc" = "$code" ] || fail "nanopush $* -> exit $rc, expected $code (124: it blocked); stderr: $(head -c 400 err.txt)"
    grep -Eq -- "$re" err.txt || fail "nanopush $* -> stderr lacks /$re/: $(head -c 400 err.txt)"
  }
  fr=(--task friction --set a=27.5e-9 --set b=50e-9 --quiet)
  mkfifo pipe.csv
  printf 'R\n1e-8\n' > points.csv
  refused 2 '^nanopush: error: --points = pipe\.csv: is a FIFO' sweep "${fr[@]}" --points pipe.csv --out p.csv
  refused 2 '^nanopush: error: --points = /dev/zero: is a character device' sweep "${fr[@]}" --points /dev/zero --out p.csv
  refused 2 '^nanopush: error: --points = \.: is a directory' sweep "${fr[@]}" --points . --out p.csv
  [ ! -e p.csv ] && [ ! -e p.csv.journal ] || fail "a refused --points left files"
  "$np" sweep "${fr[@]}" --vary R=1e-8,2e-8,3e-8 --shard 0/2 --out s0.csv
  "$np" sweep "${fr[@]}" --vary R=1e-8,2e-8,3e-8 --shard 1/2 --out s1.csv
  refused 2 '^nanopush: error: --merge = pipe\.csv: is a FIFO' sweep --merge s0.csv pipe.csv --out m.csv --quiet
  refused 2 '^nanopush: error: --merge = /dev/zero: is a character device' sweep --merge s0.csv /dev/zero --out m.csv --quiet
  { head -1 s1.csv; echo '99999999999999999999999,2e-08,0,0,0,ok,'; } > huge.csv
  cp s1.schema.json huge.schema.json
  refused 2 '^nanopush: error: --merge = huge\.csv:2: point index = 99999999999999999999999: must be a whole number in \[0, 99999999\]' \
    sweep --merge s0.csv huge.csv --out m.csv --quiet
  cp s0.csv t0.csv
  sed 's/"plan_points": 3/"plan_points": 18446744073709551616/' s0.schema.json > t0.schema.json
  grep -q 18446744073709551616 t0.schema.json || fail "the sidecar was not tampered"
  refused 2 '^nanopush: error: --merge = t0\.schema\.json \(nanopush\.run\): plan_points = 1\.8446744073709552e\+19: must be a whole number in \[0, 100000000\]' \
    sweep --merge t0.csv s1.csv --out m.csv --quiet
  [ ! -e m.csv ] || fail "a refused merge wrote a table"
  "$np" sweep --merge s0.csv s1.csv --out m.csv --quiet
  [ "$(wc -l < m.csv)" = 4 ] || fail "the merge of good shards: $(cat m.csv)"
  # The journal: a FIFO or a device there is refused before any point (never opened).
  mkfifo j.csv.journal
  refused 2 '^nanopush: error: journal = j\.csv\.journal: is a FIFO' sweep "${fr[@]}" --vary R=1e-8,2e-8 --out j.csv
  [ -p j.csv.journal ] && [ ! -e j.csv ] || fail "the FIFO journal was replaced, or a table written"
  # Fit data through the same reader.
  refused 2 '^nanopush: error: DATA = pipe\.csv: is a FIFO' fit fig3_20 pipe.csv --free surface.mu
  refused 2 '^nanopush: error: DATA = /dev/zero: is a character device' fit fig3_20 /dev/zero --free surface.mu ;;
*) fail "unknown mode $mode" ;;
esac
echo "sweep check $mode: ok"
