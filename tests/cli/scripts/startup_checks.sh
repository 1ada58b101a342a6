#!/usr/bin/env bash
# The plain command line loads no MPI: `nanopush --version` and a run neither link nor load
# libmpi (ldd, and the loader's own account: LD_DEBUG=libs), while nanopush-mpi, when built,
# does (so the check can see it). A run loads no toml++ either (compiled into the library). Usage: startup_checks.sh NANOPUSH WORKDIR
set -euo pipefail
np=$1 dir=$2
np_mpi="$(dirname "$np")/nanopush-mpi"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail() { echo "FAIL: $*"; exit 1; }
# The shared objects the loader initialises for a command (LD_DEBUG=libs: "calling init: PATH").
loaded() { LD_DEBUG=libs LD_DEBUG_OUTPUT=ld "$@" > /dev/null 2>&1 || true; cat ld.* | grep -o 'calling init: .*' | sort -u; rm -f ld.*; }

# ldd's output is captured before grep reads it: `ldd | grep -q` under pipefail fails at random
# when grep exits at its first match and ldd dies of SIGPIPE.
deps=$(ldd "$np")
! grep -q 'libmpi' <<< "$deps" || fail "nanopush links libmpi: $(grep libmpi <<< "$deps")"
libs=$(loaded "$np" --version)
[ -n "$libs" ] || fail "LD_DEBUG=libs reported nothing for nanopush --version"
! grep -q 'libmpi\|libopen-pal\|libopen-rte\|libpmix' <<< "$libs" || fail "nanopush --version loads MPI: $(grep mpi <<< "$libs")"
echo "nanopush --version loads $(wc -l <<< "$libs") shared objects, none of MPI"
libs=$(loaded "$np" run fig3_6a --out run.csv)
[ -s run.csv ] || fail "nanopush run wrote no trajectory"
! grep -q 'libmpi' <<< "$libs" || fail "nanopush run loads libmpi"
# toml++ is compiled into the scenes library: reading the scene loads no toml++ shared object.
! grep -q 'libtomlplusplus' <<< "$libs" || fail "nanopush run loads libtomlplusplus"
if [ -x "$np_mpi" ]; then
  deps_mpi=$(ldd "$np_mpi")
  grep -q 'libmpi' <<< "$deps_mpi" || fail "nanopush-mpi does not link libmpi"
  grep -q 'libmpi' <<< "$(loaded "$np_mpi" --version)" || fail "LD_DEBUG=libs does not show nanopush-mpi loading libmpi"
  # The same commands: the help texts agree.
  cmp <("$np" --help) <("$np_mpi" --help | sed 's/nanopush-mpi/nanopush/g') || fail "nanopush and nanopush-mpi list different commands"
fi
echo "startup check: ok"
