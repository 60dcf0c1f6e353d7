#!/bin/sh
# Writes the golden logs of this folder that do not exist yet, with the states and digest they must decode
# to (tests/log/test_golden_logs.cpp reads them back in CI, with today's reader and with the reference
# reader). Run it once, when a format version is born: for each NAME.toml without NAME.ede it writes
#   NAME.ede          the log (ede-sim NAME.toml -o NAME.ede)
#   NAME.expect       what it was written by, its content digest, the middle event and the middle time
#   NAME.end.csv      the state at the end           (ede-replay state NAME.ede --at end)
#   NAME.event.csv    the state after the middle event (a chunk boundary: the reference reader stops there)
#   NAME.time.csv     the state at the middle time
# It never rewrites an existing log: a golden log is a promise (schema/FORMAT.md, "Versioning and the
# promise"). A fixture of format version 1 (tests/log/fixtures) gets its .expect and .csv files the same
# way with --expect-only NAME.ede.
# Usage: tests/log/golden/make-golden.sh BUILD_DIR [--expect-only LOG...]
set -eu
build=$(cd "$1" && pwd)
shift
sim=$build/tools/ede-sim
replay=$build/tools/ede-replay

expect() {  # expect LOG: the .expect and .csv files of one log
  log=$1
  name=${log%.ede}
  info=$("$replay" info --digest "$log")
  digest=$(printf '%s\n' "$info" | sed -n 's/^content digest *//p')
  chunk_events=$(printf '%s\n' "$info" | sed -n 's/^chunks *[0-9]* (up to \([0-9]*\) events each).*/\1/p')
  chunks=$(printf '%s\n' "$info" | sed -n 's/^chunks *\([0-9]*\).*/\1/p')
  final=$(printf '%s\n' "$info" | sed -n 's/^time *0 to \([^;]*\);.*/\1/p')
  event=$(( chunk_events * (chunks / 2) ))
  time=$(awk -v t="$final" 'BEGIN { printf "%.6g", t / 2 }')
  "$replay" state "$log" --at end -o "$name.end.csv"
  "$replay" state "$log" --event "$event" -o "$name.event.csv"
  "$replay" state "$log" --at "$time" -o "$name.time.csv"
  {
    echo "# The golden log $log: $(printf '%s\n' "$info" | sed -n 's/^engine *//p'), $(date -u +%Y-%m-%d)."
    echo "# Its decoded states must never change (schema/FORMAT.md, \"Versioning and the promise\"): never regenerate."
    echo "digest $digest"
    echo "event $event"
    echo "time $time"
  } > "$name.expect"
  echo "make-golden: $name.expect (event $event, time $time)"
}

if [ "${1:-}" = "--expect-only" ]; then
  shift
  for log in "$@"; do expect "$log"; done
  exit 0
fi
cd "$(dirname "$0")"
for scene in *.toml; do
  name=${scene%.toml}
  [ -e "$name.ede" ] && continue
  "$sim" "$scene" -q --check-exactness -o "$name.ede" >/dev/null
  expect "$name.ede"
done
