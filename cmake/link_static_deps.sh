#!/bin/sh
# Link launcher of the plain `nanopush` command line (drivers/CMakeLists.txt, RULE_LAUNCH_LINK):
# runs the link command it is given with the third-party numerics libraries taken from their
# static archives where the system has them (SUNDIALS, reference LAPACK/BLAS, the Fortran run
# time), so the process maps 6 shared objects instead of 12 and starts in about 2 ms less CPU
# (docs/performance.md, "Process start"). A library without its archive stays shared; the
# libraries' code is the same (Debian builds both from one source), so results do not change.
# Usage: link_static_deps.sh COMPILER ARGS...
set -eu
first=1
for a in "$@"; do
  if [ $first = 1 ]; then set --; first=0; fi
  case $a in
    *.so | *.so.[0-9]*)
      base=${a%%.so*}
      real=$(readlink -f "$a" 2> /dev/null || true)
      if [ -f "$base.a" ]; then a=$base.a
      elif [ -n "$real" ] && [ -f "${real%%.so*}.a" ]; then a=${real%%.so*}.a
      fi ;;
    -lgfortran | -lquadmath)
      archive=$("$1" -print-file-name="lib${a#-l}.a" 2> /dev/null || true)
      [ -f "$archive" ] && a=$archive ;;
  esac
  set -- "$@" "$a"
done
exec "$@"
