#!/bin/sh
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (Clang build in build-asan):
# any memory error, leak or undefined behaviour aborts the test that triggers it. Used by scripts/test.sh.
set -eu
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEDE_SANITIZE=ON >/dev/null
cmake --build build-asan -j "$(nproc)" >/dev/null
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$PWD/tests/lsan.supp" ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
