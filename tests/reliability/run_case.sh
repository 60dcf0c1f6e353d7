#!/bin/bash
# One case of the reliability corpus (cases.txt): runs its command in a fresh directory and checks the exit
# status and that the output (stdout and stderr together) contains the expected message fragment.
#
#   run_case.sh NAME CASES_FILE BUILD_DIR SOURCE_DIR
#
# The command runs under bash in the temporary directory $T, with $SIM, $REPLAY, $STATS, $CRATER, $RENDER
# (the tools of BUILD_DIR), $FIX (tests/reliability/fixtures) and $SRC (the source tree) set.
set -u
name=$1 cases=$2 build=$3 src=$4
line=$(grep -E "^$name \|" "$cases" | head -1)
if [ -z "$line" ]; then echo "no case named $name in $cases"; exit 1; fi
IFS='|' read -r _ status fragment command <<<"$line"
status=$(echo "$status" | tr -d ' ')
# A sanitizer build reserves terabytes of address space for its shadow memory: an address-space limit
# (prlimit --as) stops such a program before main, so those cases only mean something in a normal build.
if [ -n "${EDE_SANITIZED:-}" ] && grep -q "prlimit" <<<"$command"; then
  echo "skipped: $name limits the address space, which a sanitizer build cannot run under"
  exit 77
fi
fragment=$(echo "$fragment" | sed 's/^ *//; s/ *$//')
T=$(mktemp -d "${TMPDIR:-/tmp}/ede-reliability-XXXXXX")
trap 'rm -rf "$T"' EXIT
export T SRC=$src FIX=$src/tests/reliability/fixtures
export SIM=$build/tools/ede-sim REPLAY=$build/tools/ede-replay STATS=$build/tools/ede-stats
export CRATER=$build/tools/ede-crater RENDER=$build/tools/ede-render
cd "$T" || exit 1
output=$(bash -c "$command" 2>&1)
got=$?
echo "case:     $name"
echo "command: $command"
echo "status:   $got (expected $status)"
echo "output:"
echo "$output" | head -40
if [ "$got" != "$status" ]; then echo "FAIL: exit status $got, expected $status"; exit 1; fi
if ! grep -qF -- "$fragment" <<<"$output"; then echo "FAIL: the output does not contain: $fragment"; exit 1; fi
echo "ok"
