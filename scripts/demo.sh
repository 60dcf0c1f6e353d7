#!/bin/sh
# The README's main command: install what is missing, build, run the default scene examples/gas.toml.
# Writes the event log out/gas.ede, prints the run's summary (kept in out/gas-summary.txt), and rebuilds
# the exact final state from the log into out/gas-final.csv.
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/tools/ede-sim examples/gas.toml -o out/gas.ede | tee out/gas-summary.txt
build/tools/ede-replay out/gas.ede --at end -o out/gas-final.csv
echo "demo: wrote out/gas.ede, out/gas-summary.txt and out/gas-final.csv"
