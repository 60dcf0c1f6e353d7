#!/bin/sh
# The README's test command: install what is missing, build, run the whole test suite, check that a Clang
# build computes exactly what the GCC build computes, run the suite again under ASan and UBSan, and fuzz
# every target briefly (EDE_FUZZ_SECONDS, default 45 s each).
set -eu
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
scripts/check-compilers.sh
scripts/check-sanitizers.sh
scripts/fuzz.sh "${EDE_FUZZ_SECONDS:-45}"
