#!/usr/bin/env bash
# Sweeps in bounded memory and plans that cannot lie (docs/sweeps.md): grid values as numpy
# computes them, the peak memory of a long streamed sweep, --points read by index, numeric
# --vary values checked before any point, journals and shards of another plan refused naming
# the difference. Usage: sweep_stream_checks.sh MODE NANOPUSH WORKDIR [PYTHON]
set -euo pipefail
mode=$1 np=$2 dir=$3 python=${4:-}
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
if [ -z "$python" ]; then  # a Python with NumPy (the package's interpreter may not be configured yet)
  for p in python3 /usr/bin/python3; do
    if command -v "$p" > /dev/null && "$p" -c 'import numpy' 2> /dev/null; then python=$p; break; fi
  done
fi
status() { set +e; "$@"; local rc=$?; set -e; echo $rc; }

case $mode in
linspace)  # every grid value the double numpy.linspace / numpy.geomspace gives (the oracle)
  [ -n "$python" ] || fail "no Python with NumPy given"
  specs=("R=-45e-9:45e-9:19" "R=0:45e-9:10" "R=0.02:0.2:10" "R=0:1:10" "R=0.1:0.7:7" "R=1e-9:1e-6:50" "R=-3:7:1001" "R=5e-324:1e-322:7"
         "R=1e300:-1e300:5" "R=2:2:3" "R=0.3:0.1:4")
  logs=("R=1e-9:1e-6:50" "R=-1e-3:-10:13" "R=3:7:9" "R=1e-300:1e300:61")
  # numpy's power ufunc (geomspace's 10^x) takes an AVX-512 (SVML) path on CPUs that have it,
  # within ~1 ulp but not correctly rounded, so its last bit depends on the machine; nanopush
  # uses the C library's pow, as numpy's portable path does. The oracle is that portable path:
  # numpy with its AVX-512 features disabled, where the CPU has them.
  npy_off=$(grep -m1 -o -w -E 'avx512(f|cd|bw|dq|vl)' /proc/cpuinfo 2> /dev/null | head -1 || true)
  [ -z "$npy_off" ] || export NPY_DISABLE_CPU_FEATURES="AVX512F AVX512CD AVX512_SKX AVX512_CLX AVX512_CNL AVX512_ICL"
  for s in "${specs[@]}" "${logs[@]/#/log:}"; do
    if [[ $s == log:* ]]; then opt=--vary-log; s=${s#log:}; kind=geomspace; else opt=--vary; kind=linspace; fi
    "$np" sweep --task friction "$opt" "$s" --out t.csv --quiet || [ $? -ge 64 ] || fail "sweep $opt $s"
    "$python" - "$s" "$kind" t.csv <<'PY' || fail "$opt $s: values differ from numpy.$kind"
import csv, sys
import numpy as np
spec, kind, path = sys.argv[1], sys.argv[2], sys.argv[3]
a, b, n = spec.split("=", 1)[1].split(":")
want = getattr(np, kind)(float(a), float(b), int(n))
got = [float(r["R"]) for r in csv.DictReader(open(path))]
bad = [(i, g, w) for i, (g, w) in enumerate(zip(got, want)) if g != w]
if len(got) != len(want) or bad:
    print(spec, kind, "first differences (i, nanopush, numpy):", [(i, repr(g), repr(float(w))) for i, g, w in bad[:5]])
    sys.exit(1)
PY
  done
  # the documented case: yn = 0:45e-9:10 holds 5e-9 exactly, as numpy.linspace does
  "$np" sweep --task icor --vary yn=0:45e-9:10 --out yn.csv --quiet || [ $? -ge 64 ] || fail "icor sweep"
  grep -q '^1,5e-09,' yn.csv || fail "5e-9 is not point 1: $(sed -n 2p yn.csv)" ;;
rss)  # a streamed sweep of 1e6 points: peak resident memory far below what holding it would take
  "$python" - "$np" <<'PY' || fail "peak RSS"
import resource, subprocess, sys
np_ = sys.argv[1]
cmd = [np_, "sweep", "--task", "friction", "--vary", "R=1e-8:1e-6:1000", "--vary", "alpha=0:3:1000",
       "--out", "big.csv", "--quiet"]
r = subprocess.run(cmd)
peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
rows = sum(1 for _ in open("big.csv")) - 1
print(f"1e6-point sweep: exit {r.returncode}, {rows} rows, peak RSS {peak_mb:.1f} MB")
if r.returncode not in (0,) or rows != 1000000:
    sys.exit("the sweep did not complete")
if peak_mb > 200:  # holding the rows took ~1.35 kB each (1.3 GB); streamed, tens of MB
    sys.exit(f"peak RSS {peak_mb:.1f} MB > 200 MB")
PY
  head -1 big.csv | grep -q '^point,R,alpha,fx,fy,mf,status,message$' || fail "header"
  sed -n '2p;1000001p' big.csv | cut -d, -f1 | tr '\n' ' ' | grep -q '^0 999999 $' || fail "first/last rows" ;;
points)  # a --points file read by index (past several checkpoints) gives the grid's table
  "$np" sweep --task friction --vary R=1e-8:1e-6:50 --vary alpha=0:3:61 --out grid.csv --quiet
  { echo R,alpha; cut -d, -f2,3 grid.csv | tail -n +2; } > pts.csv
  "$np" sweep --task friction --points pts.csv --out list.csv --jobs 2 --quiet
  cmp grid.csv list.csv || fail "--points table differs from the grid's"
  # resumed from a journal cut after 1000 records: the same bytes
  "$np" sweep --task friction --points pts.csv --out cut.csv --quiet
  [ "$(status "$np" sweep --task friction --points pts.csv --out cut.csv --quiet)" = 0 ] || fail "rerun" ;;
vary_range)  # a numeric --vary value out of its key's range: exit 2 before any point
  [ "$(status "$np" sweep fig3_18 --vary surface.mu=0.1,-1 --out m.csv --quiet 2> err.txt)" = 2 ] || fail "exit"
  grep -q -- '--vary surface.mu = -1: out of range: must be' err.txt || fail "message: $(cat err.txt)"
  [ ! -e m.csv ] && [ ! -e m.csv.journal ] || fail "a refused sweep left files"
  [ "$(status "$np" sweep fig3_18 --vary-log object.length=-1e-7:-2e-7:3 --out m.csv --quiet 2> err.txt)" = 2 ] || fail "exit (log)"
  grep -q -- '--vary object.length = -1e-07: out of range: must be > 0' err.txt || fail "message: $(cat err.txt)" ;;
foreign)  # a journal or a shard of another plan is refused, the difference named
  grid=(fig3_18 --set surface.law=coulomb --vary surface.mu=0.02:0.2:3 --quiet)
  other=(fig3_18 --set surface.law=thesis --vary surface.mu=0.02:0.2:3 --quiet)
  "$np" sweep "${grid[@]}" --shard 0/2 --out s0.csv
  "$np" sweep "${other[@]}" --shard 1/2 --out s1.csv
  [ "$(status "$np" sweep --merge s0.csv s1.csv --out m.csv 2> err.txt)" = 2 ] || fail "merge of two plans"
  grep -q 'is a shard of another sweep than s0.csv (.*law: thesis there, coulomb here' err.txt || fail "merge message: $(cat err.txt)"
  record() { python3 -c 'import json, sys; print(json.dumps(json.load(open(sys.argv[1]))["nanopush"]["run"]["plan_record"]))' "$1"; }
  rec=$(record s0.schema.json)
  grep -q '^{"task": "run", "scene": "fig3_18", "scene_hash": "' <<< "$rec" || fail "sidecar plan record: $rec"
  grep -q '"axis 1": "surface.mu=0.02:0.2:3"' <<< "$rec" || fail "sidecar axis: $rec"
  grep -q '"set": "surface.law=coulomb"' <<< "$rec" || fail "sidecar set: $rec"
  # a journal of another sweep (its header's hash differs) is refused before any point
  printf 'nanopush-sweep-journal 1 0000000000000000\n' > j.csv.journal
  [ "$(status "$np" sweep "${grid[@]}" --out j.csv 2> err.txt)" = 2 ] || fail "a foreign journal must be refused"
  grep -q 'journal = j.csv.journal: belongs to a different sweep' err.txt || fail "journal message: $(cat err.txt)" ;;
*) fail "unknown mode $mode" ;;
esac
echo "sweep check $mode: ok"
