#!/usr/bin/env bash
# The layers link only downward (docs/architecture.md): each file under cxx/ may include
# nanopush headers of its own layer and of the layers below it, and only the engines layer
# may include the F77 bridge (f77_*.h). Usage: check_layers.sh SOURCE_DIR
set -euo pipefail
cd "$1/cxx"
allowed() {  # the layers a layer may include
  case $1 in
    numerics) echo "numerics" ;;
    models)   echo "numerics models" ;;
    scenes)   echo "numerics models scenes" ;;
    engines)  echo "numerics models scenes engines" ;;
    outputs)  echo "numerics models scenes outputs" ;;
    sweeps)   echo "numerics models scenes engines outputs sweeps" ;;
    fitting)  echo "numerics models scenes engines outputs fitting" ;;
  esac
}
bad=0 checked=0
for layer in numerics models scenes engines outputs sweeps fitting; do
  ok=$(allowed $layer)
  for f in $(find "$layer" "include/nanopush/$layer" -name '*.cpp' -o -name '*.hpp' 2>/dev/null); do
    checked=$((checked + 1))
    while IFS= read -r inc; do
      dep=$(echo "$inc" | sed -E 's@.*nanopush/([a-z_]+)/.*@\1@')
      if ! echo " $ok " | grep -q " $dep "; then
        echo "layer violation: $f ($layer) includes nanopush/$dep/"; bad=$((bad + 1))
      fi
    done < <(grep -E '^#include [<"]nanopush/[a-z_]+/' "$f" || true)
    if [ $layer != engines ] && grep -qE '^#include [<"]f77_' "$f"; then
      echo "layer violation: $f ($layer) includes the F77 bridge (only engines may)"; bad=$((bad + 1))
    fi
    if grep -qE '^#include [<"](bench/|registry\.hpp)' "$f"; then
      echo "layer violation: $f includes a driver header"; bad=$((bad + 1))
    fi
  done
done
# Every file under cxx/ belongs to a layer.
stray=$(find . -name '*.cpp' -o -name '*.hpp' | grep -vE '^\./(include/nanopush/)?(numerics|models|scenes|engines|outputs|sweeps|fitting)/' || true)
[ -z "$stray" ] || { echo "files outside the layers: $stray"; bad=$((bad + 1)); }
echo "checked $checked files, $bad violations"
[ $bad -eq 0 ] && echo "layers: ok"
