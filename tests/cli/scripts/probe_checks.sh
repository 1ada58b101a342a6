#!/usr/bin/env bash
# Defects a command-line probe found (docs/errors.md), each case from its reproducer: options
# checked before any work or output, every output target checked before the first is written,
# a file path ending in '/' refused before anything is made, gnuplot given paths it cannot read
# as options, forces' flags named, a table cut short refused, messages that name what was
# written, and the lines stderr holds on an error.
# Usage: probe_checks.sh MODE NANOPUSH WORKDIR
set -euo pipefail
mode=$1 np=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir/work" && cd "$dir/work"
fail() { echo "FAIL: $*"; exit 1; }
# expect CODE REGEX COMMAND...: exit status CODE, stderr matching REGEX (grep -E), and the
# working directory as it was before (no file made, none removed: no partial output).
expect() {
  local code=$1 re=$2; shift 2
  local before; before=$(find . | sort)
  set +e; "$@" > ../out.txt 2> ../err.txt; local rc=$?; set -e
  [ "$rc" = "$code" ] || fail "$* -> exit $rc, expected $code; stderr: $(head -c 600 ../err.txt)"
  grep -Eq -- "$re" ../err.txt || fail "$* -> stderr lacks /$re/: $(head -c 600 ../err.txt)"
  local after; after=$(find . | sort)
  [ "$before" = "$after" ] || fail "$* changed the working directory: $(diff <(echo "$before") <(echo "$after") || true)"
}
# first_line_is_error: an option refused before any work prints nothing before its error line.
first_line_is_error() {
  head -1 ../err.txt | grep -q '^nanopush: error: ' || fail "something came before the error line: $(head -3 ../err.txt)"
}
goal=(tip_push_nanorod --goal 6e-8,4e-8,0.3)
# fit: data of a short run of fig3_20 (21 samples over 0.4 ns)
short=(--set solver.t_end=0.4e-9 --set solver.samples=21)
fit_data() { "$np" fit fig3_20 "${short[@]}" --synthesize ../data.csv --sigma x=1e-9 --seed 3 > /dev/null 2>&1; }

case $mode in
plan_options)  # every option of plan is checked before planning, and its outputs too
  expect 2 '^nanopush: error: --mu-range = 0.1: must be LO:HI' "$np" plan "${goal[@]}" --out p --check 3 --mu-range 0.1
  first_line_is_error
  expect 2 '^nanopush: error: --mu-range = 0:0.1: must be LO:HI with 0 < LO <= HI <= 10' \
    "$np" plan "${goal[@]}" --out p --check 3 --mu-range 0:0.1
  first_line_is_error
  expect 2 '^nanopush: error: --tip-mu-range = 0.1:0.2:0.3: must be LO:HI' \
    "$np" plan "${goal[@]}" --out p --check 3 --tip-mu-range 0.1:0.2:0.3
  first_line_is_error
  expect 2 '^nanopush: error: --noise = x=-1: must be x=SX,y=SY,theta=ST' "$np" plan "${goal[@]}" --out p --check 3 --noise x=-1
  first_line_is_error
  # options of --check without --check are not ignored
  expect 2 '^nanopush: error: --mu-range = 0.1:0.2: is for --check N' "$np" plan "${goal[@]}" --out p --mu-range 0.1:0.2
  expect 2 '^nanopush: error: --tip-mu-range = 0:0.2: is for --check N or --robust' \
    "$np" plan "${goal[@]}" --out p --tip-mu-range 0:0.2
  expect 2 '^nanopush: error: --check = 3: the closed loop re-plans from each image' \
    "$np" plan "${goal[@]}" --out p --check 3 --closed-loop
  # a goal no push sequence of the bar reaches: named, with the range
  expect 2 '^nanopush: error: --goal = 1e\+308,0,0: must be within 1e6 bar lengths of the bar.s start: \|\(X, Y\) - \(0, 0\)\| <= 0.59 m' \
    "$np" plan tip_push_nanorod --goal 1e308,0,0
  first_line_is_error
  # outputs: a directory where a file goes, a file where the directory goes; before planning
  mkdir -p p/plan.json
  expect 5 '^nanopush: system error: output = p/plan.json: is a directory' "$np" plan "${goal[@]}" --out p
  first_line_is_error_5() { head -1 ../err.txt | grep -q '^nanopush: system error: ' || fail "before the error: $(head -3 ../err.txt)"; }
  first_line_is_error_5
  rm -r p && mkdir -p p/check.json
  expect 5 '^nanopush: system error: output = p/check.json: is a directory' "$np" plan "${goal[@]}" --out p --check 2
  first_line_is_error_5
  rm -r p && touch p
  expect 5 '^nanopush: system error: output = p: is not a directory' "$np" plan "${goal[@]}" --out p
  first_line_is_error_5
  rm p
  # and what is right still runs: the plan and its check
  "$np" plan "${goal[@]}" --out p --check 2 --mu-range 0.1:0.2 --quiet
  for f in plan.csv plan.json tip_path.csv poses.csv check.csv check.json; do [ -f p/$f ] || fail "plan --check wrote no p/$f"; done ;;
fit_outputs)  # every output of fit is checked before the fit
  fit_data
  mkdir adir
  expect 5 '^nanopush: system error: output = adir: is a directory' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --json adir
  expect 5 '^nanopush: system error: output = adir/: ends in /' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --json adir/
  mkdir -p o/fig3_20.fit.csv
  expect 5 '^nanopush: system error: output = o/fig3_20.fit.csv: is a directory' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --out o
  rm -r o && mkdir -p o/fig3_20.fit.schema.json
  expect 5 '^nanopush: system error: output = o/fig3_20.fit.schema.json: is a directory' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --out o
  rm -r o && mkdir -p o/fig3_20.fit.png
  expect 5 '^nanopush: system error: output = o/fig3_20.fit.png: is a directory' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --out o
  rm -r o && touch o
  expect 5 '^nanopush: system error: output = o: is not a directory' \
    "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --out o
  rm o adir -r
  # what is right still runs
  "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --no-plot --out o --json o/fit.json --quiet > /dev/null
  for f in o/fig3_20.fit.csv o/fig3_20.fit.schema.json o/fit.json; do [ -f $f ] || fail "fit wrote no $f"; done ;;
trailing_slash)  # a file output path that ends in '/' is refused before anything is made or computed
  expect 5 '^nanopush: system error: output = x.csv/: ends in /' "$np" run fig3_6a --out x.csv/
  expect 5 '^nanopush: system error: output = sub/x.csv/: ends in /' "$np" run fig3_6a --out sub/x.csv/ --quiet
  expect 5 '^nanopush: system error: output = x.nc/: ends in /' "$np" run fig3_6a --out x.nc/ --quiet
  expect 5 '^nanopush: system error: output = y.csv/: ends in /' \
    "$np" sweep --task friction --set a=27.5e-9 --set b=50e-9 --set muN=1 --vary R=1e-9:1e-6:6 --quiet --out y.csv/
  grep -q 'sweep: ' ../err.txt && fail "the sweep computed points: $(cat ../err.txt)"
  expect 5 '^nanopush: system error: output = d.csv/: ends in /' \
    "$np" fit fig3_20 "${short[@]}" --synthesize d.csv/ --sigma x=1e-9
  # a directory that exists, with or without its '/': refused as before
  mkdir adir
  expect 5 '^nanopush: system error: output = adir: is a directory' "$np" run fig3_6a --out adir --quiet
  expect 5 '^nanopush: system error: output = adir/: ends in /' "$np" run fig3_6a --out adir/ --quiet ;;
dash_dir)  # an output directory named '-' (or starting with '-'): gnuplot reads its script path as a path
  "$np" plan "${goal[@]}" --out - --quiet || fail "plan --out - failed: exit $?"
  for f in plan.csv plan.json plan.gp plan.png; do [ -f ./-/$f ] || fail "plan --out - wrote no -/$f"; done
  "$np" plan "${goal[@]}" --out -x --quiet || fail "plan --out -x failed"
  [ -f ./-x/plan.png ] || fail "plan --out -x wrote no -x/plan.png"
  fit_data
  "$np" fit fig3_20 ../data.csv "${short[@]}" --free surface.mu --out -f --quiet > /dev/null || fail "fit --out -f failed"
  [ -f ./-f/fig3_20.fit.png ] || fail "fit --out -f wrote no -f/fig3_20.fit.png"
  # the kept script re-runs from its folder
  (cd ./-x && rm plan.png && gnuplot plan.gp 2> ../../gp_err.txt) || fail "gnuplot -x/plan.gp: $(cat ../gp_err.txt)"
  [ -f ./-x/plan.png ] || fail "the kept script drew no plan.png" ;;
forces)  # forces' flags: ranges named by the flag, each shape's own flags
  expect 2 '^nanopush: error: --inner-radius = -1: must be in \[0, 1.35e-08\) \(m; 0 <= inner radius < --radius\)' \
    "$np" forces --shape tube --inner-radius -1
  expect 2 '^nanopush: error: --inner-radius = 1: must be in \[0, 1.35e-08\)' "$np" forces --shape tube --inner-radius 1
  expect 2 '^nanopush: error: --inner-radius = 1e-9: not used by --shape rod \(only a tube has an inner radius\)' \
    "$np" forces --shape rod --inner-radius 1e-9
  expect 2 '^nanopush: error: --push = -1: must be > 0 \(N\)' "$np" forces --shape rod --push -1
  expect 2 '^nanopush: error: --push = 0: must be > 0 \(N\)' "$np" forces --push 0
  expect 2 '^nanopush: error: --height = \(not given\): a bar needs --width and --height \(m\)' \
    "$np" forces --shape bar --width 1e-7
  expect 2 '^nanopush: error: --width = \(not given\): a bar needs --width and --height \(m\)' \
    "$np" forces --shape bar --height 1e-7
  expect 2 '^nanopush: error: --width = 1e-7: not used by --shape rod' "$np" forces --width 1e-7
  expect 2 '^nanopush: error: --push-height = 1: must be in \[-1.35e-08, 1.35e-08\] \(m; \|h\| <= the radius\)' \
    "$np" forces --push 1e-6 --push-height 1
  expect 2 '^nanopush: error: --mu = -1: must be >= 0' "$np" forces --push 1e-6 --mu -1
  # a value the scene reader refuses is named by the flag the user wrote
  expect 2 '^nanopush: error: --radius = -1e-09: must be > 0 \(m\)' "$np" forces --shape sphere --radius -1e-9
  expect 2 '^nanopush: error: --gap = 0: must be > 0 \(m\)' "$np" forces --gap 0
  expect 2 '^nanopush: error: --material = "bogus": unknown material' "$np" forces --material bogus
  first_line_is_error
  # what is right still runs
  "$np" forces --shape tube --inner-radius 5e-9 > ../out.txt || fail "a tube with an inner radius failed"
  grep -q "body 'body': tube" ../out.txt || fail "no tube report: $(cat ../out.txt)"
  "$np" forces --shape tube --inner-radius 0 --push 3e-6 --push-height -1.35e-8 > ../out.txt || fail "a tube pushed at h = -r failed"
  grep -q 'push F = 3e-06 N at h = -1.35e-08 m' ../out.txt || fail "no push decision: $(cat ../out.txt)" ;;
convert)  # a table cut short (no line end after its last row) is refused, naming file and row
  fit_data  # t, x, sigma_x: its last cell 1e-09
  cp ../data.csv ../whole.csv && cp ../data.csv t.csv && cp ../data.schema.json t.schema.json
  rows=$(wc -l < t.csv)
  tail -c 7 t.csv | grep -q ',1e-09$' || fail "the table does not end in 1e-09: $(tail -1 t.csv)"
  truncate -s -2 t.csv  # the line end and the 9: the row has its cells and 1e-0 reads as a number
  expect 2 "^nanopush: error: table = t.csv:$rows: the last row is cut short \\(no line end\\)" "$np" convert t.csv
  first_line_is_error
  # cut in the middle of a row: the same, not a row of fewer cells
  head -c -15 ../whole.csv > t.csv
  expect 2 "^nanopush: error: table = t.csv:$rows: the last row is cut short \\(no line end\\)" "$np" convert t.csv
  # the whole table converts
  cp ../whole.csv t.csv
  "$np" convert t.csv --quiet || fail "convert of the whole table failed"
  [ -f t.nc ] || fail "convert wrote no t.nc" ;;
messages)  # messages name what the user wrote
  expect 2 '^nanopush: error: tip.speed = 1e-151: outside the magnitudes the integrators represent' \
    "$np" run tip_push_nanorod --set tip.speed=1e-151 --quiet
  grep -q "scales" ../err.txt && fail "the message blames the scene's scales: $(cat ../err.txt)"
  expect 2 '^nanopush: error: L uncertainty = 1e\+308: its contribution to the uncertainty of mu' \
    "$np" icor estimate-mu --force 1e-7 --yn 1e-7 --length-sigma 1e308
  grep -q 'F = 1e-07' ../err.txt && fail "the message blames F and yn: $(cat ../err.txt)"
  expect 2 '^nanopush: error: --goal = 0,1e\+100,0: must be within 1e6 bar lengths' \
    "$np" plan tip_push_nanorod --goal 0,1e100,0 --quiet ;;
stderr_lines)  # docs/errors.md: where the error line stands on stderr
  last_is() { tail -1 ../err.txt | grep -Eq -- "$1" || fail "the last line of stderr is not /$1/: $(tail -3 ../err.txt)"; }
  # without --quiet, run says the scene's normal load first; the error line is the last
  expect 2 '^fig3_28: normal load' "$np" run fig3_28 --method cvode --out o.csv
  last_is '^nanopush: error: method = cvode'
  expect 5 '^fig3_21: normal load' "$np" run fig3_21 --set solver.samples=3 --out /proc/x.csv
  last_is '^nanopush: system error: output = /proc/x.csv'
  # a refused option: the error line, then where the help is
  expect 2 '^nanopush: error: --rtol = abc' "$np" run fig3_6a --rtol abc
  last_is "^Run 'nanopush run --help' for the options and their ranges"
  [ "$(wc -l < ../err.txt)" = 2 ] || fail "a refused option: $(cat ../err.txt)"
  # exit 3: the outcome line, then what was kept
  expect 3 '^nanopush: no_static_friction: ' "$np" run fig3_28 --law thesis --out o.csv
  last_is '^  nothing written \(--keep-partial keeps' ;;
*) fail "unknown mode $mode" ;;
esac
echo "probe check $mode: ok"
