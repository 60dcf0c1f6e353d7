#!/bin/sh
# The deeper checks, run by CI after the README's test command (.ci/run; docs/testing.md): each builds ede
# again with Clang. A Clang build must compute exactly what the GCC build in build/ computes, on every
# example scene (scripts/check-compilers.sh; needs build/ from scripts/test.sh); the whole suite again under
# AddressSanitizer, LeakSanitizer and UndefinedBehaviorSanitizer (scripts/check-sanitizers.sh); every
# libFuzzer target for EDE_FUZZ_SECONDS (default 45) from its corpus (scripts/fuzz.sh).
set -eu
cd "$(dirname "$0")/.."
scripts/check-compilers.sh
scripts/check-sanitizers.sh
scripts/fuzz.sh "${EDE_FUZZ_SECONDS:-45}"
