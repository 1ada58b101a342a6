#!/usr/bin/env bash
# Build the libFuzzer target for the scene parser and --set (tests/fuzz/fuzz_scene.cpp) with
# clang, ASan and UBSan, and run it for SECONDS (default 60) over the corpus in the
# repository. Exit 0 when it finds nothing; a finding leaves its input in the work directory
# (printed) and exits non-zero. Usage: tests/fuzz/run.sh [SECONDS] [BUILD_DIR]
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
cmake --build "$build" --target fuzz_scene -j2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
# New inputs go to ./new (the first corpus directory); the repository's corpus is only read.
mkdir new
set +e
"$build/tests/fuzz/fuzz_scene" -max_total_time="$secs" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 new "$src/tests/fuzz/corpus" 2>&1 | tail -25
rc=${PIPESTATUS[0]}
set -e
if [ "$rc" != 0 ]; then
  keep=$(mktemp -d /tmp/nanopush-fuzz-finding-XXXXXX)
  cp -r "$work"/* "$keep"/ 2>/dev/null || true
  echo "fuzz: finding (libFuzzer exit $rc); inputs kept in $keep" >&2
  exit 1
fi
echo "fuzz: no finding in ${secs} s"
