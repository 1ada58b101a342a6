#!/usr/bin/env bash
# Outputs only ever replace their own regular files (docs/errors.md, "Outputs"; issue 34 item 1),
# on the command line: a FIFO or a directory as --out is exit 5 and left as it was (the FIFO
# never blocks the run); a symbolic link is followed and its target replaced (the link kept);
# a character device is written through (made in the scratch directory as root; otherwise the
# machine's /dev/null, only written to); a device that refuses writes (/dev/full's kind) is
# exit 5 and stays a device. Usage: output_targets.sh NANOPUSH WORKDIR
set -euo pipefail
np=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
# run CODE REGEX ARGS...: nanopush ARGS exits CODE (within 30 s) and stderr matches REGEX.
run() {
  local code=$1 re=$2; shift 2
  set +e; timeout 30 "$np" "$@" > out.txt 2> err.txt; local rc=$?; set -e
  [ "$rc" = "$code" ] || fail "nanopush $* -> exit $rc, expected $code; stderr: $(head -c 600 err.txt)"
  [ -z "$re" ] || grep -Eq -- "$re" err.txt || fail "nanopush $* -> stderr lacks /$re/: $(head -c 600 err.txt)"
  rm -f out.txt err.txt
}
no_temporaries() { local t; t=$(find "$dir" -name '*.tmp.*'); [ -z "$t" ] || fail "temporaries left: $t"; }

mkfifo pipe.csv
run 5 '^nanopush: system error: output = pipe.csv: is a FIFO' run fig3_6c --out pipe.csv --quiet
[ -p pipe.csv ] || fail "the FIFO was replaced"
mkdir adir.csv
run 5 '^nanopush: system error: output = adir.csv: is a directory' run fig3_6c --out adir.csv --quiet
[ -d adir.csv ] && [ -z "$(ls -A adir.csv)" ] || fail "the directory was changed"
ln -s pipe.csv sweep_pipe.csv
run 5 'output = sweep_pipe.csv \(a link to pipe.csv\): is a FIFO' sweep --task friction --vary R=1e-8,2e-8 --out sweep_pipe.csv --quiet
[ -p pipe.csv ] && [ -L sweep_pipe.csv ] || fail "the FIFO or its link was replaced"
[ ! -e sweep_pipe.csv.journal ] || fail "the refused sweep started a journal (it ran points)"
rm -f sweep_pipe.csv

mkdir data links
echo old > data/real.csv
ln -s ../data/real.csv links/link.csv
run 0 '' run fig3_6c --out links/link.csv --quiet
[ -L links/link.csv ] || fail "the link was replaced by a file"
[ "$(readlink links/link.csv)" = ../data/real.csv ] || fail "the link changed: $(readlink links/link.csv)"
head -1 data/real.csv | grep -q '^t,x,y,theta' || fail "the link's target holds no trajectory: $(head -c 200 data/real.csv)"
[ -f links/link.schema.json ] || fail "no sidecar beside the name given"

if mknod nul c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null; then
  run 0 '' run fig3_6c --out nul --quiet
  [ -c nul ] || fail "the device node nul was replaced"
  [ ! -e nul.schema.json ] || fail "a sidecar beside a device"
  run 5 '^nanopush: system error: output = full: write failed \(No space left on device\)' run fig3_6c --out full --quiet
  [ -c full ] || fail "the device node full was replaced"
  run 0 '' icor formulas --n 5 --out nul
  [ -c nul ] || fail "icor replaced the device"
  # A sweep's table on a device: its journal goes to the working directory, never beside the device.
  mkdir devs && mknod devs/nul c 1 3
  run 0 '' sweep --task friction --vary R=1e-8,2e-8 --out devs/nul --quiet
  [ -c devs/nul ] && [ "$(ls -A devs)" = nul ] || fail "the sweep wrote beside the device: $(ls -A devs)"
  echo "devices: scratch nodes"
else
  # Not root: no scratch device nodes, and nothing is ever written to the machine's /dev.
  rm -f nul full
  echo "devices: not exercised (not root: no scratch device nodes)"
fi
# A figure through a link: the link kept, its target drawn; a killed run's temporary swept up.
if command -v gnuplot > /dev/null; then
  mkdir -p R/fig3_6 elsewhere
  ln -s ../../elsewhere/fig.svg R/fig3_6/fig3_6.svg
  sh -c 'exit 0' & dead=$!; wait $dead
  echo stale > "R/fig3_6/fig3_6.svg.tmp.$dead.svg"
  run 0 '' reproduce --quick --only fig3_6 --format svg --no-bench --out R
  [ -L R/fig3_6/fig3_6.svg ] || fail "the figure's link was replaced"
  grep -q '<svg' elsewhere/fig.svg || fail "the link's target holds no figure"
  [ ! -e "R/fig3_6/fig3_6.svg.tmp.$dead.svg" ] || fail "a killed run's figure temporary survived"
fi
# The process's own descriptor is written through whatever it is (here a pipe). Named by
# /proc/self/fd/1 rather than /dev/stdout: nothing in /dev is touched, and /proc cannot be
# renamed over.
"$np" run fig3_6c --out /proc/self/fd/1 --quiet | head -1 | grep -q '^t,x,y,theta' || fail "--out /proc/self/fd/1 through a pipe"
no_temporaries
echo "output targets: ok"
