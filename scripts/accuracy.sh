#!/bin/sh
# Regenerates the accuracy study (docs/accuracy.md): builds ede (Release), then runs every measurement of
# `ede-bench accuracy` and writes docs/accuracy/ (engine.csv, time_stepped.csv, log.csv, tables.md,
# accuracy.png). About 15 minutes on a 2-core machine; run it on a quiet one (the timings are medians, but
# the ratios are only as steady as the machine). Extra arguments go to ede-bench accuracy (--repeat 5,
# --set stop.events=N, ...).
set -eu
cd "$(dirname "$0")/.."
scripts/build.sh
exec build/tools/ede-bench accuracy --out-dir docs/accuracy --scenes examples/accuracy "$@"
