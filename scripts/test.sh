#!/bin/sh
# The README's test command: install what is missing, build and install everything (scripts/build.sh), run
# the whole test suite on every core (ctest starts the slow tests first). The checks that build ede again
# with Clang (the GCC/Clang comparison, the suite under the sanitizers, the fuzzers) are
# scripts/check-deep.sh, which CI runs after this (.ci/run; docs/testing.md).
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
