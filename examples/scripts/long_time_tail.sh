#!/bin/sh
# The 2D long-time tail of the velocity autocorrelation (Alder and Wainwright 1970), exactly from the log:
# N hard disks at phi = 0.3 in a periodic box, C(t)/C(0) on log-log axes (a slope of -1 after the Enskog
# decay, until sound crosses the box at t ~ L/c), and the MSD with D against Enskog.
# Default N = 10^4 (box 5 x 5): ~30 s to simulate and ~1.5 min of CPU for the VACF up to lag 4 (measured
# under load); N=40000 L=10 scales it up (the tail then lasts twice as long). Finite size: the box's sound
# modes end the tail near t = L/c, and D grows as ln t in 2D, so D depends on the lag range and on L.
# usage: long_time_tail.sh TOOLS_DIR OUT_DIR   (env: N, L)
set -e
tools=${1:?usage: long_time_tail.sh TOOLS_DIR OUT_DIR}
out=${2:?usage: long_time_tail.sh TOOLS_DIR OUT_DIR}
n=${N:-10000}
l=${L:-5.0}
r=$(python3 -c "import math; print(math.sqrt(0.3 * $l * $l / ($n * math.pi)))")
here=$(dirname "$0")
mkdir -p "$out"
"$tools/ede-sim" "$here/../scenes/periodic.toml" -q -o "$out/tail.ede" --set "box.size=[$l,$l]" \
    --set species.gas.count=$n --set species.gas.radius=$r --set stop.time=12
"$tools/ede-stats" vacf "$out/tail.ede" --from 2 --max-lag 4 --lag-step 0.01 --loglog -o "$out/vacf.csv" \
    --plot "$out/vacf-tail.png"
"$tools/ede-stats" msd "$out/tail.ede" --from 2 --max-lag 4 -o "$out/msd.csv" --plot "$out/msd.png"
