#!/bin/bash
# ede-sweep's throughput: runs per minute for 200 short runs with 1 and 2 workers, and the overhead per run
# against running ede-sim directly (a shell loop of the same 200 runs, each with its log).
#
#   study/sweep_bench.sh BUILD_DIR [RUNS]
#
# The runs: examples/cooling.toml shrunk to 200 disks and t = 0.2 (~1 500 collisions, a few ms each), so
# the sweep's own cost per run dominates: a process start, the reuse check, the run's log digest (a replay
# of the log) and its row file. No quantities are collected (collect is empty), so the comparison with
# ede-sim is the sweep machinery alone. Each configuration runs once (200 runs is its own average); the
# machine is shared, so report the numbers as measured under load. Results: docs/sweeps.md, "Throughput".
set -eu
build=$(cd "${1:?usage: sweep_bench.sh BUILD_DIR [RUNS]}" && pwd)
runs=${2:-200}
src=$(cd "$(dirname "$0")/.." && pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/ede-sweep-bench-XXXXXX")
trap 'rm -rf "$T"' EXIT
cat >"$T/bench.toml" <<EOT
scene = "$src/examples/cooling.toml"
set = ["species.grains.count=200", "stop.time=0.2"]
seeds = $runs
EOT
now() { date +%s.%N; }
rate() { awk -v n="$runs" -v t="$1" 'BEGIN { printf "%.0f runs/min (%.1f ms per run)", 60 * n / t, 1000 * t / n }'; }

t0=$(now); "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j1" -j 1 -q >/dev/null; t1=$(now)
j1=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
t0=$(now); "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j2" -j 2 -q >/dev/null; t1=$(now)
j2=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
t0=$(now); "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j2" -j 2 -q >/dev/null; t1=$(now)
rerun=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')
mkdir -p "$T/sim"
t0=$(now)
for s in $(seq "$runs"); do
  "$build/tools/ede-sim" "$src/examples/cooling.toml" --set species.grains.count=200 --set stop.time=0.2 --set seed="$s" \
    -o "$T/sim/$s.ede" -q >/dev/null
done
t1=$(now)
sim=$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')

echo "ede-sweep, $runs short runs (200 disks, t = 0.2), measured under load on $(nproc) cores:"
echo "  ede-sim loop (1 at a time):  $(rate "$sim")"
echo "  ede-sweep -j 1:              $(rate "$j1")"
echo "  ede-sweep -j 2:              $(rate "$j2")   scaling $(awk -v a="$j1" -v b="$j2" 'BEGIN { printf "%.2f", a / b }')x"
echo "  rerun (all reused):          $(rate "$rerun")"
echo "  overhead per run, -j 1 vs the ede-sim loop: $(awk -v a="$j1" -v b="$sim" -v n="$runs" 'BEGIN { printf "%.1f ms", 1000 * (a - b) / n }')"
