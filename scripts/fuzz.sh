#!/bin/sh
# Builds the libFuzzer targets (Clang, ASan + UBSan) and runs each for a budget (default 45 s; first
# argument to change it), starting from the committed corpus in fuzz/corpus/<target> (read-only here:
# new inputs go to a scratch directory). The targets run side by side, one per core (each keeps its whole
# budget; on 2 cores the five take three budgets, not five). A crash, leak, timeout (10 s per input) or
# out-of-memory (2 GiB) fails the script and leaves the input as build-fuzz/crash-*: turn it into
# tests/fuzz_regressions/.
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-45}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEDE_FUZZ=ON -DEDE_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_scene fuzz_log fuzz_columns fuzz_queue fuzz_engine >/dev/null

# fuzz TARGET: runs one target for the budget; its exit status is libFuzzer's.
fuzz() {
  scratch=$(mktemp -d)
  status=0
  (cd build-fuzz && ./fuzz/fuzz_$1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
     -print_final_stats=1 "$scratch" "../fuzz/corpus/$1" >"fuzz-$1.log" 2>&1) || status=$?
  rm -rf "$scratch"
  return $status
}

targets="scene log columns queue engine"
jobs=$(nproc)
running=0
for target in $targets; do
  (result=0; fuzz "$target" || result=$?; echo "$result" >"build-fuzz/fuzz-$target.status") &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait
    running=0
  fi
done
wait

status=0
for target in $targets; do
  if [ "$(cat "build-fuzz/fuzz-$target.status")" = 0 ]; then
    echo "fuzz: $target: $(grep -E '^stat::number_of_executed_units' build-fuzz/fuzz-$target.log | awk '{print $2}') executions, $(grep -oE 'cov: [0-9]+' build-fuzz/fuzz-$target.log | tail -1), no crash"
  else
    echo "fuzz: $target: FAILED; see build-fuzz/fuzz-$target.log"
    tail -40 "build-fuzz/fuzz-$target.log"
    status=1
  fi
done
exit $status
