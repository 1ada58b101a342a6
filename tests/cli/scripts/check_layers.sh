#!/usr/bin/env bash
# The layers link only downward (docs/architecture.md), checked over every top-level folder
# that holds code:
#   cxx/<layer>   nanopush headers of its own layer and the layers below; only engines may
#                 include the F77 bridge (f77_*.h); no driver, binding or Python header.
#   fortran/      the FORTRAN 77 library: no module, no include of anything of ours.
#   fortran/bridge  bind(C) shims: only the F77 interfaces module and intrinsic modules; its C
#                 headers include nothing of ours.
#   bindings/     the C API and the Fortran module: cxx layers (fitting and below), never the
#                 bridge, a driver, or Python; nanopush.f90 uses no F77 module.
#   python/src/   pybind11 module: cxx layers and the bridge, never a driver or the C API's
#                 internals.
#   drivers/, tests/  everything below them (checked: nothing includes a test file).
# Usage: check_layers.sh SOURCE_DIR
set -euo pipefail
shopt -s nullglob
root=$1
cd "$root"
layers="numerics models scenes engines outputs sweeps fitting planning"
allowed() {  # the cxx layers a cxx layer may include
  case $1 in
    numerics) echo "numerics" ;;
    models)   echo "numerics models" ;;
    scenes)   echo "numerics models scenes" ;;
    engines)  echo "numerics models scenes engines" ;;
    outputs)  echo "numerics models scenes outputs" ;;
    sweeps)   echo "numerics models scenes engines outputs sweeps" ;;
    fitting)  echo "numerics models scenes engines outputs fitting" ;;
    planning) echo "numerics models scenes engines outputs sweeps planning" ;;
    front)    echo "$layers" ;;   # bindings, python, drivers, tests
  esac
}
bad=0 checked=0
violation() { echo "layer violation: $*"; bad=$((bad + 1)); }
# Header names that belong to drivers/, bindings/ internals and python/src: nobody below may
# include them.
driver_headers=$( [ -d drivers ] && cd drivers && find . -name '*.hpp' -o -name '*.h' | sed 's@^\./@@' | sort -u)
includes_of() { grep -hE '^#include [<"][^">]+[">]' "$1" | sed -E 's@^#include [<"]([^">]+)[">].*@\1@' || true; }
is_driver_header() { echo "$driver_headers" | grep -qxF "$1"; }

check_cxx_includes() {  # FILE OWNER-LAYER: nanopush/<layer>/ includes against allowed()
  local f=$1 owner=$2 ok inc dep
  ok=$(allowed "$owner")
  while IFS= read -r inc; do
    [ -n "$inc" ] || continue
    case $inc in
      nanopush/*/*)
        dep=$(echo "$inc" | sed -E 's@^nanopush/([a-z_]+)/.*@\1@')
        echo " $ok " | grep -q " $dep " || violation "$f ($owner) includes $inc" ;;
    esac
  done < <(includes_of "$f")
}

# cxx/: every file belongs to a layer.
for layer in $layers; do
  for f in $(find "cxx/$layer" "cxx/include/nanopush/$layer" -name '*.cpp' -o -name '*.hpp' 2>/dev/null); do
    checked=$((checked + 1))
    check_cxx_includes "$f" "$layer"
    while IFS= read -r inc; do
      [ -n "$inc" ] || continue
      case $inc in
        f77_*) [ "$layer" = engines ] || violation "$f ($layer) includes the F77 bridge $inc (only engines may)" ;;
        nanopush.h|capi_internal.hpp|common.hpp) violation "$f ($layer) includes $inc (bindings or python)" ;;
        *) if is_driver_header "$inc"; then violation "$f ($layer) includes the driver header $inc"; fi ;;
      esac
    done < <(includes_of "$f")
  done
done
stray=$(cd cxx && find . -name '*.cpp' -o -name '*.hpp' | grep -vE '^\./(include/nanopush/)?(numerics|models|scenes|engines|outputs|sweeps|fitting|planning)/' || true)
[ -z "$stray" ] || violation "files under cxx/ outside the layers: $stray"

# fortran/: the F77 library uses no module and includes nothing.
for f in fortran/*.f; do
  checked=$((checked + 1))
  if grep -qiE '^ {6}[^!]*\buse +[a-z_]' "$f" || grep -qiE '^ *#? *include' "$f"; then
    violation "$f (F77 library) uses a module or includes a file"
  fi
done
# fortran/bridge/: only the F77 interfaces and intrinsic modules; headers include nothing of ours.
for f in fortran/bridge/*.f90; do
  checked=$((checked + 1))
  while IFS= read -r mod; do
    case $mod in
      iso_c_binding|ieee_arithmetic|iso_fortran_env|nanopush_f77_interfaces) ;;
      *) violation "$f (bridge) uses module $mod" ;;
    esac
  done < <(grep -iE '^ *use\b' "$f" | sed -E 's@^ *use *(, *intrinsic *::)? *([A-Za-z0-9_]+).*@\2@' | tr 'A-Z' 'a-z')
done
for f in fortran/bridge/*.h fortran/bridge/*.hpp; do
  checked=$((checked + 1))
  while IFS= read -r inc; do
    [ -n "$inc" ] || continue
    case $inc in
      f77_*) ;;                              # its own headers
      nanopush/*|nanopush.h|*.hpp) violation "$f (bridge) includes $inc" ;;
    esac
  done < <(includes_of "$f")
done

# bindings/: cxx layers, never the bridge, a driver or Python.
for f in bindings/*.cpp bindings/*.hpp bindings/*.h; do
  checked=$((checked + 1))
  check_cxx_includes "$f" front
  while IFS= read -r inc; do
    [ -n "$inc" ] || continue
    case $inc in
      f77_*) violation "$f (bindings) includes the F77 bridge $inc" ;;
      common.hpp) violation "$f (bindings) includes python/src/common.hpp" ;;
      *) if is_driver_header "$inc"; then violation "$f (bindings) includes the driver header $inc"; fi ;;
    esac
  done < <(includes_of "$f")
done
for f in bindings/*.f90; do
  checked=$((checked + 1))
  if grep -qiE '^ *use +nanopush_f77' "$f"; then violation "$f (bindings) uses an F77 bridge module"; fi
done

# python/src/: cxx layers and the bridge; never a driver or the C API's internals.
for f in python/src/*.cpp python/src/*.hpp; do
  checked=$((checked + 1))
  check_cxx_includes "$f" front
  while IFS= read -r inc; do
    [ -n "$inc" ] || continue
    case $inc in
      capi_internal.hpp) violation "$f (python) includes the C API's internals" ;;
      *) if is_driver_header "$inc"; then violation "$f (python) includes the driver header $inc"; fi ;;
    esac
  done < <(includes_of "$f")
done

# drivers/: may include every layer, but no test file.
for f in $(find drivers -name '*.cpp' -o -name '*.hpp' 2>/dev/null); do
  checked=$((checked + 1))
  if includes_of "$f" | grep -qE '^(catch2/|trajectory_checks\.hpp|support/)'; then
    violation "$f (drivers) includes a test header"
  fi
done

# Every folder with code is one of the above.
unknown=$(find . -maxdepth 1 -mindepth 1 -type d ! -name '.*' ! -name build ! -name out \
          -printf '%f\n' | grep -vxE 'cxx|fortran|bindings|python|drivers|tests|docs|cmake|examples' || true)
[ -z "$unknown" ] || violation "top-level folders not in the layer picture: $unknown"

echo "checked $checked files, $bad violations"
[ $bad -eq 0 ] && echo "layers: ok"
