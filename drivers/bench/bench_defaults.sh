#!/usr/bin/env bash
# How long `nanopush bench PRESET` takes with its defaults, for every preset (issue 24: each
# within 60 s). A benchmark, never a test: it writes a CSV (preset, law, exit status, wall
# seconds, rows) and prints a summary.
#   bash drivers/bench/bench_defaults.sh NANOPUSH [OUT.csv] [PRESET ...]
set -uo pipefail
np=${1:?usage: bench_defaults.sh NANOPUSH [OUT.csv] [PRESET ...]}
out=${2:-bench_defaults.csv}
shift $(( $# >= 2 ? 2 : 1 ))
presets=("$@")
if [ ${#presets[@]} -eq 0 ]; then
  mapfile -t presets < <("$np" presets | awk '$1 !~ /^#/ && $1 != "name" && NF > 1 {print $2}')
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tmp="$out.tmp.$$"
trap 'rm -rf "$work" "$tmp"' EXIT
echo "preset,exit,wall_s,rows" > "$tmp"
for p in "${presets[@]}"; do
  start=$(date +%s.%N)
  "$np" bench "$p" --quiet --no-plot --out "$work/$p.csv" > /dev/null 2> "$work/$p.err"
  rc=$?
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  rows=$( [ -f "$work/$p.csv" ] && grep -vc '^#' "$work/$p.csv" || echo 0)
  printf '%s,%d,%.1f,%s\n' "$p" "$rc" "$wall" "$rows" | tee -a "$tmp"
  [ $rc -eq 0 ] || tail -2 "$work/$p.err" | sed "s|^|  $p: |" >&2
done
mv "$tmp" "$out"
awk -F, 'NR > 1 { n++; if ($3 > m) { m = $3; w = $1 } if ($3 > 60) over++ }
         END { printf "bench_defaults: %d presets, slowest %s %.1f s, %d over 60 s\n", n, w, m, over }' "$out"
