#!/usr/bin/env bash
# netCDF wherever a table is written (docs/data.md), beyond `sweep` (netcdf_checks.sh):
#  - the commands that write a table file (bench --out, friction --bench-csv, fit --synthesize,
#    icor estimate-mu --out): FILE.nc read back by `netcdf_readback --compare` against the CSV
#    the same command writes as FILE.csv, bit for bit (timings, measured anew, for all but their
#    values), nothing left beside it; an unknown extension refused (exit 2) before any work,
#    naming what was written and the allowed extensions, nothing written; only a .nc loads
#    libnetcdf;
#  - the commands that write a directory of tables (plan, fit-icor, bench-friction, run's
#    trajectory, a reproduce step's grid with blank lines): `nanopush convert` turns each table into its .nc
#    twin, compared the same way; its refusals are exit 2 with nothing written.
# Usage: netcdf_commands.sh NANOPUSH NETCDF_READBACK WORKDIR
set -euo pipefail
np=$1 rb=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
status() { set +e; "$@" > /dev/null 2> err.txt; local rc=$?; set -e; echo $rc; }
same() { "$rb" --compare "$@" || fail "$2 does not hold $1"; }
# refused CMD...: exit 2 naming the extension, nothing but err.txt written.
refused() {
  mkdir -p refused && (cd refused && [ "$(status "$np" "$@")" = 2 ]) || fail "not exit 2: $*"
  grep -q "unknown extension '.parquet'" refused/err.txt || fail "message of $*: $(cat refused/err.txt)"
  grep -q "FILE.csv.*FILE.nc" refused/err.txt || fail "the allowed extensions not named: $(cat refused/err.txt)"
  [ "$(ls refused)" = err.txt ] || fail "a refused $1 left files: $(ls refused)"
  rm -rf refused
}
only() { [ "$(ls "$1" | tr '\n' ' ')" = "$2" ] || fail "$1 holds $(ls "$1" | tr '\n' ' '), not $2"; }

# ---- fit --synthesize FILE (seeded: the two runs agree bit for bit)
synth=(fit fig3_20 --set solver.t_end=0.4e-9 --set solver.samples=41 --sigma x=1e-9 --sigma theta=0.01 --quiet)
mkdir synth
"$np" "${synth[@]}" --synthesize synth/d.csv
"$np" "${synth[@]}" --synthesize synth/d.nc
only synth "d.csv d.nc d.schema.json "
same synth/d.csv synth/d.nc
# The checker itself: one value one ulp off (1e-9 -> the next double) is caught.
sed '2s/,1e-09,/,1.0000000000000002e-09,/' synth/d.csv > off.csv && cp synth/d.schema.json off.schema.json
! cmp -s synth/d.csv off.csv || fail "no value changed in off.csv"
! "$rb" --compare off.csv synth/d.nc > /dev/null 2>&1 || fail "netcdf_readback --compare missed a value one ulp off"
rm off.csv off.schema.json
refused "${synth[@]}" --synthesize d.parquet

# ---- friction --bench --bench-csv FILE (timings: all but the values); only a .nc loads libnetcdf
fb=(friction --bench --bench-seconds 0.001)
mkdir fb
"$np" "${fb[@]}" --bench-csv fb/b.csv > /dev/null
LD_DEBUG=libs LD_DEBUG_OUTPUT=ld "$np" "${fb[@]}" --bench-csv fb/b.nc > /dev/null
grep -q 'calling init: .*libnetcdf' ld.* || fail "friction --bench-csv b.nc did not load libnetcdf"
rm -f ld.*
LD_DEBUG=libs LD_DEBUG_OUTPUT=ld "$np" "${fb[@]}" --bench-csv fb/c.csv > /dev/null
! grep -q 'calling init: .*libnetcdf' ld.* || fail "friction --bench-csv c.csv loaded libnetcdf"
rm -f ld.* fb/c.csv fb/c.schema.json
only fb "b.csv b.nc b.schema.json "
same fb/b.csv fb/b.nc --measured evaluation_rate,evaluations,time
refused "${fb[@]}" --bench-csv b.parquet

# ---- bench --out FILE (timings: all but the values); .nc draws no figure, --plot with it refused
bench=(bench fig3_6a --quick --quiet --engines cxx-faithful)
mkdir bench
"$np" "${bench[@]}" --no-plot --out bench/w.csv > /dev/null
"$np" "${bench[@]}" --out bench/w.nc > bench.md
grep -q "bench/w.nc" bench.md || fail "the report does not name w.nc: $(cat bench.md)"
only bench "w.csv w.nc w.schema.json "
same bench/w.csv bench/w.nc --measured wall_s,rhs_s,overhead_ns_per_rhs,wall_spread,own_ns_per_rhs
refused "${bench[@]}" --out w.parquet
[ "$(status "$np" "${bench[@]}" --out bench/p.nc --plot bench/p.png)" = 2 ] || fail "--plot with a .nc must be exit 2"
grep -q -- "--plot = bench/p.png" err.txt || fail "--plot message: $(cat err.txt)"
only bench "w.csv w.nc w.schema.json "

# ---- icor estimate-mu --out FILE
mu=(icor estimate-mu --force 5e-7 --yn 1e-7)
mkdir mu
"$np" "${mu[@]}" --out mu/e.csv > /dev/null
"$np" "${mu[@]}" --out mu/e.nc > /dev/null
only mu "e.csv e.nc e.schema.json "
same mu/e.csv mu/e.nc
refused "${mu[@]}" --out e.parquet

# ---- nanopush convert: the tables of a directory, each into its .nc twin
mkdir conv
printf 'F,sigma_F,yn,sigma_yn\n8.505610578323183e-07,1.7e-08,5e-08,2e-9\n5.33822956537572e-07,1.1e-08,2e-07,2e-9\n' > conv/pushes.csv
"$np" fit-icor conv/pushes.csv --pressure known --out conv/fit_icor > /dev/null
"$np" plan tip_push_nanorod --goal 60e-9,40e-9,0.3 --tolerance 2e-9,0.02 --quiet --out conv/plan > /dev/null
"$np" reproduce --quick --only fig3_10_11_friction --out conv/repro > /dev/null 2>&1
grid=conv/repro/fig3_10_11_friction_maps.csv
grep -q '^$' "$grid" || fail "$grid: no blank line between its scans (the case to convert)"
"$np" bench-friction --seconds 0.01 --repeats 1 --no-plot --quiet --out conv/bench_friction > /dev/null
tables=(conv/fit_icor/fit_icor.csv conv/plan/*.csv "$grid" conv/bench_friction/*.csv)
LD_DEBUG=libs LD_DEBUG_OUTPUT=ld "$np" convert --quiet "${tables[@]}"
grep -q 'calling init: .*libnetcdf' ld.* || fail "convert did not load libnetcdf"
rm -f ld.*
for t in "${tables[@]}"; do
  [ -s "${t%.csv}.schema.json" ] || fail "convert removed the sidecar of $t"
  same "$t" "${t%.csv}.nc"
done
# A trajectory with its times as the dimension; written elsewhere with --out.
"$np" run fig3_17 --quiet --out conv/r.csv
"$np" convert conv/r.csv --axis t --out conv/traj.nc 2> convert.txt
grep -q "conv/r.csv -> conv/traj.nc" convert.txt || fail "convert names no file: $(cat convert.txt)"
same conv/r.csv conv/traj.nc
"$np" run fig3_17 --quiet --out conv/r2.nc
same conv/r.csv conv/r2.nc
# Refused, nothing written: an unknown --out extension, a name that is not a CSV table, a table
# without its sidecar, a column that is not the table's, two tables to one --out.
cp conv/r.csv conv/bare.csv
before=$(ls conv | tr '\n' ' ')
[ "$(status "$np" convert conv/r.csv --out conv/r.parquet)" = 2 ] || fail "convert --out r.parquet: not exit 2"
grep -q -- "--out = conv/r.parquet: unknown extension '.parquet'" err.txt || fail "message: $(cat err.txt)"
[ "$(status "$np" convert conv/r.csv --out conv/r.csv.out)" = 2 ] || fail "convert --out r.csv.out: not exit 2"
[ "$(status "$np" convert conv/r.txt)" = 2 ] || fail "convert r.txt: not exit 2"
[ "$(status "$np" convert conv/bare.csv)" = 2 ] || fail "convert of a table without a sidecar: not exit 2"
grep -q "has no sidecar" err.txt || fail "message: $(cat err.txt)"
[ "$(status "$np" convert conv/r.csv --axis nope)" = 2 ] || fail "convert --axis nope: not exit 2"
[ "$(status "$np" convert conv/r.csv conv/r.csv --out conv/x.nc)" = 2 ] || fail "two tables, one --out: not exit 2"
[ "$(ls conv | tr '\n' ' ')" = "$before" ] || fail "a refused convert wrote: $(ls conv | tr '\n' ' ') (was $before)"
echo "netcdf commands: ok"
