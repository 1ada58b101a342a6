#!/usr/bin/env bash
# Build the libFuzzer targets with clang, ASan and UBSan -- the scene parser and --set
# (tests/fuzz/fuzz_scene.cpp, corpus tests/fuzz/corpus) and the table readers: --points, merge
# tables and sidecars, journals, fit data (fuzz_tables.cpp, corpus tests/fuzz/corpus_tables)
# -- and run them for SECONDS in all (default 60: two thirds to the scenes, a third to the
# tables) over the corpora in the repository. Exit 0 when they find nothing; a finding leaves
# its input in a kept directory (printed) and exits non-zero.
# Usage: tests/fuzz/run.sh [SECONDS] [BUILD_DIR]
set -euo pipefail
secs=${1:-60}
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${2:-$src/build/fuzz}
if ! command -v clang++ > /dev/null; then
  echo "fuzz: clang++ not found: install the Debian packages clang and libclang-rt-14-dev (.ci/setup does)" >&2
  exit 1
fi
# <quadmath.h> (the __float128 scalar) is GCC's: clang gets that header alone (GCC's whole
# include directory would replace clang's intrinsics headers).
quadinc="$build-quadmath"
mkdir -p "$quadinc"
for h in quadmath.h quadmath_weak.h; do
  [ -f "$(gcc -print-file-name=include)/$h" ] && ln -sf "$(gcc -print-file-name=include)/$h" "$quadinc/$h"
done
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
flags+=" -isystem $quadinc"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$flags" \
  -DNANOPUSH_FUZZ=ON -DNANOPUSH_TESTS=OFF -DNANOPUSH_DRIVERS=OFF -DNANOPUSH_MPI=OFF > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log" >&2; exit 1; }
cmake --build "$build" --target fuzz_scene fuzz_tables -j2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# fuzz TARGET SECONDS CORPUS: new inputs go to ./TARGET (the first corpus directory); the
# repository's corpus is only read.
fuzz() {
  mkdir -p "$1"
  set +e
  TMPDIR="$work" "$build/tests/fuzz/$1" -max_total_time="$2" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 "$1" "$src/tests/fuzz/$3" 2>&1 | tail -25
  local rc=${PIPESTATUS[0]}
  set -e
  if [ "$rc" != 0 ]; then
    keep=$(mktemp -d /tmp/nanopush-fuzz-finding-XXXXXX)
    cp -r "$work"/* "$keep"/ 2>/dev/null || true
    echo "fuzz: finding in $1 (libFuzzer exit $rc); inputs kept in $keep" >&2
    exit 1
  fi
}
tables=$((secs / 3 > 0 ? secs / 3 : 1))
fuzz fuzz_scene $((secs - tables > 0 ? secs - tables : 1)) corpus
fuzz fuzz_tables "$tables" corpus_tables
echo "fuzz: no finding in ${secs} s"
