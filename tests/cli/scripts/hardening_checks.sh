#!/usr/bin/env bash
# Hardening (docs/errors.md): bad input of every kind gets exit 2 and a message naming what
# was written and what is allowed; nothing is written outside --out or the working directory;
# an interrupt leaves no temporary and no result that looks finished.
# Usage: hardening_checks.sh MODE NANOPUSH WORKDIR
set -euo pipefail
mode=$1 np=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir/work" && cd "$dir/work"
fail() { echo "FAIL: $*"; exit 1; }
# expect CODE REGEX COMMAND...: the exit status is CODE, stderr matches REGEX (grep -E), and
# the working directory holds no file afterwards (no partial output under any name).
expect() {
  local code=$1 re=$2; shift 2
  set +e; "$@" > out.txt 2> err.txt; local rc=$?; set -e
  [ "$rc" = "$code" ] || fail "$* -> exit $rc, expected $code; stderr: $(head -c 600 err.txt)"
  grep -Eq -- "$re" err.txt || fail "$* -> stderr lacks /$re/: $(head -c 600 err.txt)"
  local left; left=$(ls -A | grep -v '^out.txt$\|^err.txt$' || true)
  [ -z "$left" ] || fail "$* left files: $left"
  rm -f out.txt err.txt
}

case $mode in
options)  # every real option rejects NaN and Inf; counts have bounds; messages name the value
  expect 2 '^nanopush: error: --atol = nan: must be a finite number >= 0' "$np" run fig3_6a --atol nan
  expect 2 '^nanopush: error: --rtol = nan: must be a finite number > 0' "$np" deck fig3_6a --rtol nan
  expect 2 '^nanopush: error: --tolerance = nan: must be a finite number > 0' "$np" compare fig3_6a --tolerance nan
  expect 2 '^nanopush: error: --rtol = inf: must be a finite number > 0' "$np" run fig3_6a --rtol inf
  expect 2 '^nanopush: error: --rtol = abc: must be a finite number > 0$' "$np" run fig3_6a --rtol abc
  expect 2 '^nanopush: error: --n = 1000000000: must be a whole number in \[1, 1000000\]' "$np" icor formulas --n 1000000000
  expect 2 '^nanopush: error: --n = 2147483647: must be a whole number in \[0, 1000000\]' "$np" icor roots --n 2147483647
  expect 2 '^nanopush: error: --force = -1: must be a finite number > 0' "$np" icor estimate-mu --force -1 --yn 1e-8
  expect 2 '^nanopush: error: --sense = 0: must be 1 or -1' "$np" friction --sense 0
  expect 2 '^nanopush: error: --mu = nan: must be a finite number' "$np" icor formulas --mu nan
  expect 2 "^nanopush: error: unknown subcommand 'frobnicate'; the subcommands are: run, " "$np" frobnicate
  expect 2 '^nanopush: error: SCENE is required' "$np" run
  expect 2 '^nanopush: error: method = modern: the f77 engine has one method' "$np" run fig3_6a --engine f77 --method modern
  expect 2 '^nanopush: error: R = nan: must be a finite number' "$np" sweep --task friction --vary R=nan,1e-8 --out t.csv
  expect 2 '^nanopush: error: surface.mu = inf: must be a finite number' "$np" sweep fig3_18 --vary surface.mu=0.1,inf --out t.csv
  expect 2 '^nanopush: error: body.hamaker = "" \(empty\): must be a number' "$np" run fig3_18 --set body.hamaker=
  # The help states the ranges.
  "$np" icor formulas --help | grep -q 'whole number in \[1, 1000000\]' || fail "--help shows no count range" ;;
scene)  # scene files and --set: names, file kinds, sizes, magnitudes
  expect 2 'scene.name = "\.\./\.\./x": must be an identifier' "$np" run fig3_6a --set 'scene.name=../../x'
  expect 2 'scene.name = "a/b": must be an identifier' "$np" run fig3_6a --set 'scene.name=a/b'
  expect 2 'scene.name = "/tmp/x": must be an identifier' "$np" run fig3_6a --set 'scene.name=/tmp/x'
  expect 2 'SCENE = /dev/zero: not a regular file' "$np" run /dev/zero
  expect 2 'SCENE = /dev/urandom: not a regular file' "$np" run /dev/urandom
  mkdir ../fifo && mkfifo ../fifo/f
  expect 2 'SCENE = \.\./fifo/f: not a regular file' timeout 10 "$np" run ../fifo/f
  expect 2 'SCENE = \.\./fifo/f: not a regular file' timeout 10 "$np" forces ../fifo/f
  # A non-ASCII character outside strings and comments (toml++ 3.3 must not see it: cxx/scenes/toml_text.cpp).
  printf '[environment]\nmedium = "air"\nfoo\302\247 = 1\n' > ../non_ascii.toml
  expect 2 'non_ascii.toml:3:4: TOML syntax: the character U\+00A7 stands outside a string' "$np" forces ../non_ascii.toml
  sect=$(printf '\302\247')
  sed "s/^description = .*/description = \"$sect ok\" # $sect/" "$NANOPUSH_SCENES/thesis/fig3_6a.toml" > ../non_ascii_ok.toml
  "$np" run ../non_ascii_ok.toml --out ../ok.csv --quiet || fail "non-ASCII in a string and a comment refused"
  mkdir ../adir
  expect 2 'SCENE = \.\./adir: is a directory' "$np" run ../adir
  { cat "$NANOPUSH_SCENES/thesis/fig3_6a.toml"; head -c 1100000 /dev/zero | tr '\0' '#'; echo; } > ../big.toml
  expect 2 'SCENE = \.\./big.toml: larger than a scene file may be \(1 MiB\)' "$np" run ../big.toml
  expect 2 'push.force = 1e\+308: outside the magnitudes the integrators represent' "$np" run fig3_6a --set push.force=1e308
  expect 2 'object.length = 1e\+308: outside the magnitudes' "$np" run fig3_6a --set object.length=1e308
  expect 2 'initial.theta = 1e\+308: outside the magnitudes.*\(rad\)' "$np" run fig3_6a --set initial.theta=1e308
  expect 2 'solver.t_end = 1e\+308: outside the magnitudes' "$np" run fig3_6a --set solver.t_end=1e308
  expect 2 'object.density = 1e\+308: outside the magnitudes' "$np" run fig3_18 --set object.density=1e308
  expect 2 'push.yn = inf: must be a finite number' "$np" run fig3_6a --set push.yn=inf
  expect 2 'solver.method = "modern": with solver.engine = "f77" there is one method' "$np" run fig3_6a --set solver.engine=f77 --set solver.method=modern
  # A good name writes only into the working directory.
  "$np" run fig3_6a --set scene.name=ok_name-1.2 --quiet
  [ -f ok_name-1.2.cxx-faithful.csv ] || fail "no output for a good name: $(ls)"
  rm -f ok_name-1.2.* ;;
programs)  # external programs: a failure is said on stderr with a decoded status
  expect 3 'the legacy program /bin/false exited with status 1' "$np" legacy fig3_17 --program /bin/false
  # A coulomb-law failure carries the integrator's status (it said "non-finite state").
  expect 3 'too many steps: coulomb law: more than 20000 steps' "$np" run fig3_29 --law coulomb --method faithful --set solver.samples=2000000 --out x.csv --quiet ;;
interrupt)  # every catchable signal: temporaries removed, exit 128 + signal, a line on stderr
  for sig in TERM INT HUP PIPE QUIT USR1 USR2; do
    # (env --default-signal: HUP and PIPE as a terminal gives them, even if this shell's caller ignored them)
    env --default-signal=HUP,PIPE "$np" run fig3_6a --set solver.samples=1000000 --set solver.max_steps=10000000 --method modern --out big.csv --quiet 2> err.txt &
    pid=$!
    for _ in $(seq 1 1000); do ls | grep -q 'big.csv.tmp' && break; sleep 0.01; done
    ls | grep -q 'big.csv.tmp' || fail "no temporary seen (the run was too quick to interrupt)"
    kill -$sig $pid
    set +e; wait $pid; rc=$?; set -e
    want=$((128 + $(kill -l $sig)))
    [ "$rc" = "$want" ] || fail "run after SIG$sig exited $rc, expected $want"
    grep -q 'outputs not yet complete were removed' err.txt || fail "no line on stderr: $(cat err.txt)"
    left=$(ls -A | grep -v '^err.txt$' || true)
    [ -z "$left" ] || fail "SIG$sig left: $left"
  done
  # SIGKILL cannot be caught: its temporary is swept up by the next run of the same output.
  "$np" run fig3_6a --set solver.samples=1000000 --set solver.max_steps=10000000 --method modern --out big.csv --quiet 2> err.txt &
  pid=$!
  for _ in $(seq 1 1000); do ls | grep -q 'big.csv.tmp' && break; sleep 0.01; done
  ls | grep -q 'big.csv.tmp' || fail "no temporary seen before SIGKILL"
  kill -KILL $pid
  set +e; wait $pid; set -e
  ls | grep -q "big.csv.tmp.$pid" || fail "SIGKILL left no temporary to sweep (test assumption)"
  "$np" run fig3_6a --out big.csv --quiet
  [ -f big.csv ] || fail "the run after SIGKILL wrote no big.csv"
  left=$(ls -A | grep 'tmp' || true)
  [ -z "$left" ] || fail "a stale temporary survived the next run: $left"
  rm -f big.csv big.schema.json err.txt
  # reproduce: interrupted, the directory says it is incomplete and has no report.md.
  "$np" reproduce --quick --out R > /dev/null 2> err.txt &
  pid=$!
  for _ in $(seq 1 1000); do [ -n "$(ls R 2>/dev/null | grep csv)" ] && break; sleep 0.01; done
  kill -TERM $pid
  set +e; wait $pid; rc=$?; set -e
  [ "$rc" = 143 ] || fail "reproduce after SIGTERM exited $rc"
  [ -f R/INCOMPLETE ] || fail "no INCOMPLETE marker"
  [ ! -e R/report.md ] || fail "report.md of an interrupted reproduce"
  grep -q 'R is incomplete' err.txt || fail "no note on stderr: $(cat err.txt)"
  [ -z "$(find R -name '*.tmp*')" ] || fail "temporaries left: $(find R -name '*.tmp*')" ;;
*) fail "unknown mode $mode" ;;
esac
echo "hardening check $mode: ok"
