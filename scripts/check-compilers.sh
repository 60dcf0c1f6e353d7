#!/bin/sh
# Determinism across compilers: builds ede with Clang beside the GCC build (build/) and runs every example
# scene with both. The logs must describe identical runs (ede-replay diff: every event bit for bit; and
# the content digests) and the final states must be byte-identical CSVs. The headers differ only in the
# compiler and flags they record. Used by scripts/test.sh (CI).
set -eu
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ cmake -S . -B build-clang -DCMAKE_BUILD_TYPE=Release -DEDE_BUILD_TESTS=OFF >/dev/null
cmake --build build-clang -j "$(nproc)" --target ede-sim ede-replay >/dev/null
out=build/compiler-check
mkdir -p "$out"
status=0
for scene in examples/gas.toml examples/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  build/tools/ede-sim "$scene" -q -o "$out/gcc-$name.ede" --final-state "$out/gcc-$name.csv" >/dev/null
  build-clang/tools/ede-sim "$scene" -q -o "$out/clang-$name.ede" --final-state "$out/clang-$name.csv" >/dev/null
  if ! cmp -s "$out/gcc-$name.csv" "$out/clang-$name.csv"; then
    echo "check-compilers: $name: final states differ between GCC and Clang"
    status=1
  elif ! build/tools/ede-replay diff "$out/gcc-$name.ede" "$out/clang-$name.ede" >"$out/diff-$name.txt" 2>&1; then
    echo "check-compilers: $name: the logs differ:"
    cat "$out/diff-$name.txt"
    status=1
  else
    echo "check-compilers: $name: GCC and Clang runs identical"
  fi
done
exit $status
