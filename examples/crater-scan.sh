#!/bin/sh
# Crater depth against projectile mass: 4 masses x 3 seeds of examples/crater.toml (the full 5000-disk bed),
# 12 runs (in-process, 2 at a time), then every log measured; about 15 s on 2 cores. See docs/crater.md, "Scans".
#
#   examples/crater-scan.sh [OUT_DIR]          (default: crater-scan; set BUILD=... for another build dir)
#
# Writes OUT_DIR/v<i>-s<seed>.ede (the logs), OUT_DIR/scan.csv (one row per run), OUT_DIR/scan-aggregate.csv
# (mean and standard error per mass) and OUT_DIR/depth.png. The masses stop at 50: at 125 the projectile
# reaches the bottom wall (the bed is 0.5 deep) and the runs take 10x longer grinding grains against it.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build}
out=${1:-crater-scan}
"$build/tools/ede-crater" scan "$root/examples/crater.toml" \
  --param species.projectile.mass --values 5,10,25,50 --seeds 3 -j 2 \
  --out-dir "$out" --metric depth --plot "$out/depth.png"
