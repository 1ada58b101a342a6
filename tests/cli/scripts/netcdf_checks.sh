#!/usr/bin/env bash
# sweep --out chooses the table's format by extension (docs/data.md): .csv (or none) CSV and
# its sidecar; .nc netCDF-4 converted from the finished CSV, nothing else left beside it; -
# the CSV on standard output, no file; any other extension refused (exit 2) with nothing
# written; and the netCDF library is loaded only by the command that writes a .nc.
# Usage: netcdf_checks.sh NANOPUSH WORKDIR
set -euo pipefail
np=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
status() { set +e; "$@"; local rc=$?; set -e; echo $rc; }
# A sweep that ends with a table: exit 0, or 64 + its failed points (this grid has two).
table() { set +e; "$@"; local rc=$?; set -e; [ $rc = 0 ] || { [ $rc -gt 64 ] && [ $rc -lt 128 ]; } || fail "exit $rc: $*"; }
grid=(fig3_18 --vary surface.mu=0.05,0.1,0.2 --vary push.yn=0,2e-8 --quiet --jobs 2)

[ "$(status "$np" sweep "${grid[@]}" --out t.parquet 2> err.txt)" = 2 ] || fail "an unknown extension must be bad input"
grep -q "\-\-out = t.parquet: unknown extension '.parquet'" err.txt || fail "message: $(cat err.txt)"
[ -z "$(ls)" ] || [ "$(ls)" = err.txt ] || fail "a refused sweep left files: $(ls)"

table "$np" sweep "${grid[@]}" --out t.csv
table "$np" sweep "${grid[@]}" --out - > stdout.csv
cmp t.csv stdout.csv || fail "--out - differs from the CSV file"
[ ! -e ./- ] || fail "--out - wrote a file named -"

LD_DEBUG=libs LD_DEBUG_OUTPUT=ld table "$np" sweep "${grid[@]}" --out t.nc
grep -q 'calling init: .*libnetcdf' ld.* || fail "writing a .nc did not load libnetcdf"
rm -f ld.*
[ -s t.nc ] || fail "no t.nc"
[ "$(head -c 4 t.nc | od -An -c | tr -d ' ')" = '211HDF' ] || fail "t.nc is not netCDF-4 (HDF5): $(head -c 8 t.nc | od -c)"
[ "$(ls | grep -c '^t\.nc')" = 1 ] || fail "files left beside t.nc: $(ls)"
LD_DEBUG=libs LD_DEBUG_OUTPUT=ld table "$np" sweep "${grid[@]}" --out t2.csv
! grep -q 'calling init: .*libnetcdf' ld.* || fail "a CSV sweep loaded libnetcdf"
rm -f ld.*
echo "netcdf check: ok"
