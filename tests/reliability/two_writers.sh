#!/bin/bash
# Two ede-sim on one log path at once: the second must be refused (the first holds the log's lock) and the
# first's log must stay intact and resumable. Run by run_case.sh (cases.txt: two-writers-one-log).
$SIM "$FIX/long.toml" -o run.ede -q 2>first.err &
first=$!
for _ in $(seq 200); do [ -s run.ede ] && break; sleep 0.05; done
$SIM "$FIX/tiny.toml" -o run.ede -q
second=$?
sleep 0.5
kill -TERM $first
wait $first
echo "first run's exit status: $? (143 expected)"
$REPLAY info run.ede >/dev/null 2>&1 || { echo "the first run's log no longer reads"; exit 9; }
exit $second
