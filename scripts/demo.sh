#!/bin/sh
# The README's main command: install what is missing, build, run the default scene examples/gas.toml.
# Writes out/gas-summary.json and out/gas-final.csv and prints the run's summary.
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/tools/ede-sim examples/gas.toml --final-state out/gas-final.csv
build/tools/ede-sim examples/gas.toml --json --quiet > out/gas-summary.json
echo "demo: wrote out/gas-final.csv and out/gas-summary.json"
