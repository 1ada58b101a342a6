#!/usr/bin/env bash
# The layer check finds what it must: a small tree with one violation of each kind it guards
# (a cxx layer including a higher one, a layer other than engines including the F77 bridge,
# bindings including the bridge, the C API using an F77 module, a F77 source using a module,
# a bridge header including a C++ header, an unknown top-level folder). Usage: SCRIPT DIR
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
t=$1/layers_selftest
rm -rf "$t"
mkdir -p "$t"/cxx/numerics "$t"/cxx/models "$t"/cxx/engines "$t"/bindings "$t"/fortran/bridge "$t"/drivers "$t"/stray
echo '#include "nanopush/models/friction.hpp"' > "$t"/cxx/numerics/a.hpp      # upward
echo '#include "f77_bsint.h"'                  > "$t"/cxx/models/b.cpp        # bridge outside engines
echo '#include "f77_bsint.h"'                  > "$t"/cxx/engines/ok.cpp      # allowed
echo '#include "f77_rough.h"'                  > "$t"/bindings/capi_x.cpp     # bridge from bindings
printf '  use nanopush_f77_icor\n'             > "$t"/bindings/nanopush.f90   # F77 module in the API
printf '      use foo\n'                       > "$t"/fortran/x.f             # module in F77
echo '#include "nanopush/models/icor.hpp"'     > "$t"/fortran/bridge/f77_x.h  # C++ in a bridge header
out=$(bash "$here"/check_layers.sh "$t")
echo "$out"
n=$(echo "$out" | grep -c '^layer violation')
[ "$n" -eq 7 ] && echo "layers selftest: ok ($n violations found)"
