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
# measure NAME CMD...: wall and CPU (user + system, children included) seconds of CMD into $NAME_wall, $NAME_cpu.
measure() {
  local name=$1 t
  shift
  t=$( { TIMEFORMAT='%R %U %S'; time "$@" >/dev/null 2>&1; } 2>&1 | tail -1)
  eval "${name}_wall=$(echo "$t" | awk '{ print $1 }')"
  eval "${name}_cpu=$(echo "$t" | awk '{ print $2 + $3 }')"
}
rate() { awk -v n="$runs" -v t="$1" -v c="$2" 'BEGIN { printf "%5.0f runs/min (%5.1f ms wall, %5.1f ms CPU per run)", 60 * n / t, 1000 * t / n, 1000 * c / n }'; }
sim_loop() {
  mkdir -p "$T/sim"
  for s in $(seq "$runs"); do
    "$build/tools/ede-sim" "$src/examples/cooling.toml" --set species.grains.count=200 --set stop.time=0.2 --set seed="$s" \
      -o "$T/sim/$s.ede" -q || return 1
  done
}

measure sim sim_loop
measure j1 "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j1" -j 1 -q
measure j2 "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j2" -j 2 -q
measure rerun "$build/tools/ede-sweep" "$T/bench.toml" --out-dir "$T/j2" -j 2 -q
echo "ede-sweep, $runs short runs (200 disks, t = 0.2), measured under load on $(nproc) cores:"
echo "  ede-sim loop (1 at a time): $(rate "$sim_wall" "$sim_cpu")"
echo "  ede-sweep -j 1:             $(rate "$j1_wall" "$j1_cpu")"
echo "  ede-sweep -j 2:             $(rate "$j2_wall" "$j2_cpu")"
echo "  rerun (all reused):         $(rate "$rerun_wall" "$rerun_cpu")"
echo "  scaling -j 2 / -j 1: $(awk -v a="$j1_wall" -v b="$j2_wall" 'BEGIN { printf "%.2f", a / b }')x;" \
     "overhead per run of ede-sweep -j 1 against the ede-sim loop: $(awk -v a="$j1_wall" -v b="$sim_wall" -v n="$runs" 'BEGIN { printf "%.1f", 1000 * (a - b) / n }') ms wall," \
     "$(awk -v a="$j1_cpu" -v b="$sim_cpu" -v n="$runs" 'BEGIN { printf "%.1f", 1000 * (a - b) / n }') ms CPU"
