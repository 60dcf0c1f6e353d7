#!/bin/sh
# The README's test command: install what is missing, build, run the whole test suite, and check that a
# Clang build computes exactly what the GCC build computes.
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
scripts/check-compilers.sh
