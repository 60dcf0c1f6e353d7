#!/bin/sh
# The README's first command: install what is missing, build the four tools the demo runs (only those:
# scripts/build.sh builds and installs the rest later, reusing their objects), run the default scene
# examples/gas.toml. Writes the event log out/gas.ede, prints the run's summary (kept in
# out/gas-summary.txt), rebuilds the exact final state from the log into out/gas-final.csv, and draws from
# the log the speed histogram against Maxwell-Boltzmann (out/gas-speeds.png) and a picture of the gas
# (out/gas-picture.png).
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh ede-sim ede-replay ede-stats ede-render
mkdir -p out
build/tools/ede-sim examples/gas.toml -o out/gas.ede | tee out/gas-summary.txt
build/tools/ede-replay out/gas.ede --at end -o out/gas-final.csv
build/tools/ede-stats hist out/gas.ede --from 0.4 --every 0.1 --plot out/gas-speeds.png
build/tools/ede-render out/gas.ede --at end --color speed -o out/gas-picture.png
echo "demo: wrote out/gas.ede, out/gas-summary.txt, out/gas-final.csv, out/gas-speeds.png, out/gas-picture.png"
echo "demo: scripts/build.sh builds and installs everything else (the tools on the PATH, the library)"
