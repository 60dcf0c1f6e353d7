#!/bin/bash
# The soak of docs/reliability.md: a long run killed with kill -9 at random moments and resumed each time
# must finish with a log byte-identical to an uninterrupted run's (tests/reliability/kill_resume.sh, the
# corpus case kill-9-and-resume, at a size given here).
#
#   scripts/soak.sh [EVENTS] [KILLS]      (defaults 1e8 events, 20 kills; BUILD=... for another build dir)
#
# 1e8 events of tests/reliability/fixtures/long.toml take ~40 s per run on one core of the reference
# machine, so the soak takes a few minutes; it prints the kills made and whether the logs are identical.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build}
work=$(mktemp -d "${TMPDIR:-/tmp}/ede-soak-XXXXXX")
trap 'rm -rf "$work"' EXIT
export SIM=$build/tools/ede-sim FIX=$root/tests/reliability/fixtures EVENTS=${1:-100000000} KILLS=${2:-20}
export SLEEP_SCALE=${SLEEP_SCALE:-1}
cd "$work"
start=$(date +%s)
bash "$root/tests/reliability/kill_resume.sh"
echo "soak: $EVENTS events, $(($(date +%s) - start)) s, in $work"
