#!/bin/bash
# ede-sweep as a user runs it, one case per ctest (tests/CMakeLists.txt):
#
#   run_sweep_test.sh CASE BUILD_DIR SOURCE_DIR
#
#   local      -j 2 and -j 1 give byte-identical tables (without the wall_seconds column); rerunning a
#              finished sweep runs nothing and leaves every log untouched
#   mpi        mpirun -n 2 gives the local run's tables byte for byte (skipped, exit 77, without mpirun or
#              an ede-sweep built without MPI, and under sanitizers: OpenMPI's own allocations are leaks to
#              LeakSanitizer)
#   kill       kill -9 of a run's process mid-run loses nothing: the run is done again (resumed from its log)
#              and the table is the uninterrupted one's
#   mpi-kill   kill -9 of an MPI worker rank mid-sweep ends the job (OpenMPI aborts it); running the sweep
#              again finishes it, and the table is the uninterrupted one's (skipped like mpi)
#   bad        a run stopped by the timeout is a row with its error; the others finish; a sweep with an
#              invalid point is refused before any run, naming the point
#   abuse      a second sweep into a folder another one is writing is refused; the sweep killed mid-way
#              leaves tables saying which runs are pending, and a rerun gives the reference tables; the
#              sweep file edited while it runs: the later runs are "changed", a rerun runs them all again
#   disk-full  the disk filling mid-sweep: (as root, where mount works) the results folder on a 80 KiB tmpfs
#              fills after three runs: the sweep exits 1 naming the table it could not write and every run
#              without a result ("the disk is full"), the tables on disk are the last complete ones (every
#              run pending, none wrong); with room again a rerun reuses the three and gives the reference
#              tables. Then (anyone; skipped under sanitizers) prlimit --fsize=16000 on the sweep and its
#              runs, a stand-in for a full disk that EFBIG and SIGXFSZ give without root: the runs whose logs
#              outgrow it are rows 'killed' naming signal 25 (File size limit exceeded), the others ok and
#              right, no row twice; a rerun without the limit gives the reference tables
#   collapse   a run that falls into inelastic collapse is a row with its status and the library's remedy,
#              measured all the same; the other run finishes; a rerun keeps the row (the run's own outcome)
set -u
case_name=$1 build=$2 src=$3
SWEEP=$build/tools/ede-sweep
HERE=$src/tests/tools/sweep
T=$(mktemp -d "${TMPDIR:-/tmp}/ede-sweep-test-XXXXXX")
trap 'rm -rf "$T"' EXIT
cd "$T" || exit 1
fail() { echo "FAIL: $*"; exit 1; }

need_mpi() {
  if [ -n "${EDE_SANITIZED:-}" ]; then echo "skipped: OpenMPI under a sanitizer build"; exit 77; fi
  MPIRUN=$(command -v mpirun) || { echo "skipped: no mpirun (apt-get install openmpi-bin libopenmpi-dev)"; exit 77; }
  ldd "$SWEEP" | grep -q libmpi || { echo "skipped: ede-sweep was built without MPI (CMake found none)"; exit 77; }
  MPI="timeout 120 $MPIRUN -n 2 --oversubscribe --allow-run-as-root"
}

# The pid of the process running run K of the sweep whose ede-sweep has pid $1 (waits up to 60 s for it
# to have written part of its log).
child_of() {
  local parent=$1 run=$2 log=$3
  for _ in $(seq 600); do
    for p in $(pgrep -P "$parent"); do
      if tr '\0' ' ' <"/proc/$p/cmdline" 2>/dev/null | grep -q -- "--child $run "; then
        if [ -s "$log" ]; then echo "$p"; return 0; fi
      fi
    done
    sleep 0.1
  done
  return 1
}

case $case_name in
local)
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir a -j 2 --no-timing -q >out 2>&1 || { cat out; fail "the sweep failed"; }
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir b -j 1 --no-timing -q >/dev/null 2>&1 || fail "the -j 1 sweep failed"
  cmp a/runs.csv b/runs.csv && cmp a/points.csv b/points.csv || fail "-j 2 and -j 1 tables differ"
  [ "$(wc -l <a/runs.csv)" = 9 ] || fail "runs.csv should have 8 rows and a header"
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir d --dry-run --pilot-seconds 0.2 >dry 2>&1 || { cat dry; fail "--dry-run failed"; }
  cat dry
  grep -q "8 runs (4 points x 2 seeds)" dry && grep -q "^estimate: .* min on [0-9]* workers, .* MiB of logs" dry ||
    fail "--dry-run did not print the runs and the estimate"
  [ ! -e d/runs.csv ] || fail "--dry-run ran the sweep"
  [ "$(wc -l <a/points.csv)" = 5 ] || fail "points.csv should have 4 rows and a header"
  head -1 a/runs.csv | grep -q "^run,name,physics.restitution,physics.tc,species.grains.velocity.speed,seed,energy@0.25," ||
    fail "runs.csv header: $(head -1 a/runs.csv)"
  grep -c ",ok,," a/runs.csv | grep -q 8 || fail "every run should be ok"
  before=$(stat -c '%Y.%N' a/runs/*.ede | md5sum)
  sleep 1
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir a -j 2 --no-timing >again 2>&1 || { cat again; fail "the rerun failed"; }
  cat again
  grep -q "8 runs: 8 ok (0 run now, 8 reused)" again || fail "the rerun ran something"
  [ "$(stat -c '%Y.%N' a/runs/*.ede | md5sum)" = "$before" ] || fail "the rerun touched a log"
  cmp a/runs.csv b/runs.csv || fail "the rerun's table differs"
  # Another collect list: every finished log is measured again, none is run again.
  sed -e "s|^scene = .*|scene = \"$src/examples/cooling.toml\"|" \
      -e 's|^collect = .*|collect = ["energy@0.5", "collisions_per_particle"]|' "$HERE/small.sweep.toml" >more.sweep.toml
  "$SWEEP" more.sweep.toml --out-dir a -j 2 --no-timing -q >/dev/null 2>&1 || fail "the sweep with another collect list failed"
  [ "$(stat -c '%Y.%N' a/runs/*.ede | md5sum)" = "$before" ] || fail "another collect list ran the runs again"
  head -1 a/runs.csv | grep -q ",seed,energy@0.5,collisions_per_particle,status," || fail "the new columns: $(head -1 a/runs.csv)"
  column() { python3 -c "import csv,sys; print([r[sys.argv[2]] for r in csv.DictReader(open(sys.argv[1]))])" "$@"; }
  [ "$(column a/runs.csv collisions_per_particle)" = "$(column b/runs.csv collisions_per_particle)" ] ||
    fail "a quantity measured again differs from the first measurement"
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir a --plot a/plot.png --quantity energy@0.25 --against species.grains.velocity.speed -q >/dev/null 2>err ||
    { cat err; fail "--plot failed"; }
  [ "$(head -c 4 a/plot.png | tail -c 3)" = PNG ] || fail "--plot wrote no PNG"
  ;;
mpi)
  need_mpi
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir local -j 2 --no-timing -q >/dev/null 2>&1 || fail "the local sweep failed"
  $MPI "$SWEEP" "$HERE/small.sweep.toml" --out-dir mpi --no-timing >out 2>&1 || { cat out; fail "the MPI sweep failed"; }
  cat out
  grep -q "8 runs: 8 ok (8 run now, 0 reused)" out || fail "the MPI sweep did not run every run"
  cmp local/runs.csv mpi/runs.csv && cmp local/points.csv mpi/points.csv || fail "MPI and local tables differ"
  $MPI "$SWEEP" "$HERE/small.sweep.toml" --out-dir mpi --no-timing >again 2>&1 || fail "the MPI rerun failed"
  grep -q "(0 run now, 8 reused)" again || fail "the MPI rerun ran something"
  ;;
kill)
  "$SWEEP" "$HERE/long.sweep.toml" --out-dir ref -j 1 --no-timing -q >/dev/null 2>&1 || fail "the reference sweep failed"
  "$SWEEP" "$HERE/long.sweep.toml" --out-dir k -j 1 --no-timing >out 2>&1 &
  sweep=$!
  victim=$(child_of $sweep 1 k/runs/p0-s2.ede) || { kill $sweep; fail "run 1's process never appeared"; }
  kill -9 "$victim" || fail "could not kill run 1's process"
  echo "killed run 1's process $victim"
  wait $sweep || { cat out; fail "the sweep failed after a run's process was killed"; }
  cat out
  cmp ref/runs.csv k/runs.csv && cmp ref/points.csv k/points.csv || fail "a killed run changed the table"
  ;;
mpi-kill)
  need_mpi
  "$SWEEP" "$HERE/long.sweep.toml" --out-dir ref -j 1 --no-timing -q >/dev/null 2>&1 || fail "the reference sweep failed"
  $MPI "$SWEEP" "$HERE/long.sweep.toml" --out-dir m --no-timing >out 2>&1 &
  job=$!
  # The worker rank is the ede-sweep (child of mpirun) whose own child runs run 1.
  victim=""
  for _ in $(seq 600); do
    for rank in $(pgrep -P "$(pgrep -P $job | head -1)" 2>/dev/null) $(pgrep -P $job); do
      if child_of_rank=$(pgrep -P "$rank") && [ -n "$child_of_rank" ] && [ -s m/runs/p0-s2.ede ]; then
        victim=$rank; break 2
      fi
    done
    sleep 0.1
  done
  [ -n "$victim" ] || { kill $job; fail "no worker rank running run 1 was found"; }
  orphans=$(pgrep -P "$victim")
  kill -9 "$victim"
  echo "killed the worker rank $victim"
  wait $job && fail "the MPI job went on after a rank died (it should abort)"
  # The rank's run process gets SIGTERM when its parent dies (PR_SET_PDEATHSIG) and stops at its next
  # check, closing its log; until then it holds the log's lock, and a rerun started at once would be
  # refused for it (rightly). Wait for it as a user would, at most 30 s.
  for pid in $orphans; do
    for _ in $(seq 300); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && fail "the killed rank's run process $pid is still running after 30 s"
  done
  # Rank 0 keeps the tables current while it runs: what the aborted job left marks its unfinished runs pending.
  if [ -f m/runs.csv ]; then grep -q ',pending,' m/runs.csv || fail "the aborted job's table marks no run pending"; fi
  $MPI "$SWEEP" "$HERE/long.sweep.toml" --out-dir m --no-timing >again 2>&1 || { cat again; fail "the rerun failed"; }
  cat again
  grep -q "reused)" again || fail "no line about reused runs"
  cmp ref/runs.csv m/runs.csv && cmp ref/points.csv m/points.csv || fail "the resumed MPI sweep's table differs"
  ;;
bad)
  "$SWEEP" "$HERE/bad.sweep.toml" --out-dir bad -j 2 -q >out 2>&1
  status=$?
  cat out bad/runs.csv
  [ $status = 3 ] || fail "exit status $status, expected 3 (some runs did not end ok)"
  grep -q "3 runs: 2 ok, 1 timeout" out || fail "the closing line"
  grep -q "^1,p1,1.0,1e+06,,,timeout,stopped after the sweep's timeout of 2 s" bad/runs.csv || fail "the timed-out row"
  grep -q "^0,p0,.*,ok," bad/runs.csv && grep -q "^2,p2,.*,ok," bad/runs.csv || fail "the good points"
  # A point whose scene is invalid (restitution 1.5) is found before any run starts: nothing runs, and the
  # message names the point, the key and the fix.
  sed -e "s|^scene = .*|scene = \"$src/examples/cooling.toml\"|" \
      -e 's|^values = \[\[0.9, 0.5\], |values = [[0.9, 0.5], [1.5, 0.5], |' "$HERE/bad.sweep.toml" >badpoint.sweep.toml
  grep -q "\[1.5, 0.5\]" badpoint.sweep.toml || fail "the test could not add the bad point"
  "$SWEEP" badpoint.sweep.toml --out-dir bp -j 2 -q >out 2>&1; status=$?
  cat out
  [ $status = 1 ] || fail "a sweep with an invalid point: exit status $status, expected 1"
  grep -q "badpoint.sweep.toml: 1 of the 4 points give a scene that does not load, so nothing was run" out &&
    grep -q "point 1 (physics.restitution = 1.5, stop.time = 0.5): .*physics.restitution: must be in \[0, 1\], got 1.5" out &&
    grep -q "^Fix: change those values" out || fail "the invalid point's message"
  [ -z "$(ls bp/runs 2>/dev/null)" ] || fail "a run started although a point was invalid: $(ls bp/runs)"
  # A bad sweep file is refused before anything runs, naming the file, the place and the fix.
  printf 'scene = "%s"\ncolect = []\n' "$src/examples/cooling.toml" >typo.sweep.toml
  "$SWEEP" typo.sweep.toml >out 2>&1; status=$?
  cat out
  [ $status = 1 ] && grep -q "typo.sweep.toml:2: unknown key 'colect'. Fix:" out || fail "an unknown key in a sweep file"
  printf 'scene = "%s"\ncollect = ["energy@soon"]\n' "$src/examples/cooling.toml" >q.sweep.toml
  "$SWEEP" q.sweep.toml >out 2>&1; status=$?
  [ $status = 1 ] && grep -q "collect: 'energy@soon': the time after @ is not a number" out || fail "a bad quantity: $(cat out)"
  printf 'scene = "%s"\n[[parameter]]\nkey = "physics.restitution"\nrange = { from = 1.0, count = 3 }\n' \
    "$src/examples/cooling.toml" >r.sweep.toml
  "$SWEEP" r.sweep.toml >out 2>&1; status=$?
  [ $status = 1 ] && grep -q "a range needs from, to (numbers) and count" out || fail "a bad range: $(cat out)"
  [ ! -e sweep-results ] || fail "a refused sweep file made a results folder"
  ;;
abuse)
  # Two sweeps into one folder, the sweep itself killed mid-way, its file edited between runs.
  sed -e "s|^scene = .*|scene = \"$src/examples/cooling.toml\"|" "$HERE/long.sweep.toml" >long.sweep.toml
  "$SWEEP" long.sweep.toml --out-dir ref -j 1 --no-timing -q >/dev/null 2>&1 || fail "the reference sweep failed"
  "$SWEEP" long.sweep.toml --out-dir a -j 1 --no-timing -q >first 2>&1 &
  first=$!
  victim=$(child_of $first 0 a/runs/p0-s1.ede) || { kill $first; fail "the first sweep's run never started"; }
  "$SWEEP" long.sweep.toml --out-dir a -j 1 --no-timing -q >second 2>&1; status=$?
  cat second
  [ $status = 1 ] && grep -q "a: another ede-sweep (pid $first) is writing this results folder now" second &&
    grep -q "Fix: wait for it to end, or give this sweep another folder (--out-dir)" second ||
    fail "a second sweep into the same folder was not refused (status $status)"
  kill -9 $first; wait $first 2>/dev/null
  for _ in $(seq 300); do kill -0 "$victim" 2>/dev/null || break; sleep 0.1; done
  cat a/runs.csv
  [ -f a/runs.csv ] || fail "the sweep killed mid-way left no table"
  grep -q '^0,p0-s1,1,,,pending,"not finished when this table was written' a/runs.csv ||
    fail "the killed sweep's table should say run 0 is pending and why"
  [ "$(grep -c ',pending,' a/runs.csv)" = 3 ] || fail "every run of the killed sweep should be pending"
  "$SWEEP" long.sweep.toml --out-dir a -j 1 --no-timing -q >again 2>&1 || { cat again; fail "the rerun failed"; }
  cmp ref/runs.csv a/runs.csv && cmp ref/points.csv a/points.csv || fail "the rerun's tables differ from the reference"
  # Edited while it runs: the runs not started yet are refused ("changed"), none silently runs the new file.
  "$SWEEP" long.sweep.toml --out-dir e -j 1 --no-timing -q >edited 2>&1 &
  sweep=$!
  child_of $sweep 0 e/runs/p0-s1.ede >/dev/null || { kill $sweep; fail "the edited sweep's run never started"; }
  sed -i 's|stop.time=6.0|stop.time=5.0|' long.sweep.toml
  wait $sweep; status=$?
  cat edited e/runs.csv
  [ $status = 3 ] || fail "a sweep edited while it ran: exit status $status, expected 3"
  grep -q "3 runs: 2 changed, 1 ok" edited || fail "the edited sweep's closing line"
  grep -q '^1,p0-s2,2,,,changed,"not run: long.sweep.toml or its scene .* changed while the sweep ran' e/runs.csv ||
    fail "the runs after the edit should be 'changed' with the reason"
  "$SWEEP" long.sweep.toml --out-dir e -j 1 --no-timing >again 2>&1 || { cat again; fail "the rerun after the edit failed"; }
  cat again
  grep -q "3 runs: 3 ok (3 run now, 0 reused)" again || fail "the rerun after the edit reused a run of the old file"
  ;;
disk-full)
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir ref -j 1 --no-timing -q >/dev/null 2>&1 || fail "the reference sweep failed"
  mkdir full
  if [ "$(id -u)" = 0 ] && mount -t tmpfs -o size=80k tmpfs full 2>/dev/null; then
    trap 'umount "$T/full" 2>/dev/null; rm -rf "$T"' EXIT
    "$SWEEP" "$HERE/small.sweep.toml" --out-dir full/r -j 1 --no-timing -q >out 2>&1; status=$?
    cat out full/r/runs.csv
    [ $status = 1 ] || fail "a sweep on a full disk: exit status $status, expected 1"
    grep -q "full/r/runs.csv: cannot write the table (No space left on device)" out ||
      fail "the error should name the table it could not write and the system's reason"
    [ "$(grep -c 'the disk is full' out)" -ge 1 ] || fail "the runs without a result should say the disk is full"
    [ "$(grep -c '^[0-9]' full/r/runs.csv)" = 8 ] && [ "$(cut -d, -f1 full/r/runs.csv | sort | uniq -d | wc -l)" = 0 ] ||
      fail "the table on disk should hold every run once"
    while IFS= read -r row; do
      case $row in *,ok,*) grep -qxF "$row" ref/runs.csv || fail "a row that is not the reference's: $row" ;; esac
    done <full/r/runs.csv
    mount -o remount,size=4m full || fail "could not make room on the tmpfs"
    "$SWEEP" "$HERE/small.sweep.toml" --out-dir full/r -j 1 --no-timing -q >again 2>&1 || { cat again; fail "the rerun failed"; }
    cat again
    grep -q "8 runs: 8 ok (5 run now, 3 reused)" again || fail "the rerun should reuse the three finished runs"
    cmp ref/runs.csv full/r/runs.csv && cmp ref/points.csv full/r/points.csv || fail "the rerun's tables differ from the reference"
    umount full
  else
    echo "the tmpfs part needs root and mount (skipped); the file-size limit below stands in for it"
  fi
  if [ -n "${EDE_SANITIZED:-}" ]; then echo "skipped: the file-size limit under a sanitizer build"; exit 77; fi
  # 16000 bytes: the logs of the points with speed 1 take ~15 KB, those with speed 4 ~23 KB.
  prlimit --fsize=16000 "$SWEEP" "$HERE/small.sweep.toml" --out-dir p -j 1 --no-timing -q >out 2>&1; status=$?
  cat out p/runs.csv
  [ $status = 3 ] || fail "a sweep whose runs outgrow the file-size limit: exit status $status, expected 3"
  grep -q "8 runs: 4 killed, 4 ok (8 run now, 0 reused)" out || fail "the closing line"
  [ "$(grep -c ',killed,"the run.s process was killed by signal 25 (File size limit exceeded) without a result, 3 times' p/runs.csv)" = 4 ] ||
    fail "the four runs with large logs should be 'killed' rows naming SIGXFSZ"
  [ "$(cut -d, -f1 p/runs.csv | sort | uniq -d | wc -l)" = 0 ] || fail "a run appears twice"
  for row in $(grep ',ok,' p/runs.csv | cut -d, -f1-12); do
    grep -q "^$row" ref/runs.csv || fail "an ok row differs from the reference: $row"
  done
  "$SWEEP" "$HERE/small.sweep.toml" --out-dir p -j 1 --no-timing -q >again 2>&1 || { cat again; fail "the rerun failed"; }
  grep -q "8 runs: 8 ok (4 run now, 4 reused)" again || fail "the rerun should reuse the four finished runs: $(cat again)"
  cmp ref/runs.csv p/runs.csv && cmp ref/points.csv p/points.csv || fail "the rerun's tables differ from the reference"
  ;;
collapse)
  "$SWEEP" "$HERE/collapse.sweep.toml" --out-dir c -j 2 -q >out 2>&1
  status=$?
  cat out c/runs.csv c/points.csv
  [ $status = 3 ] || fail "exit status $status, expected 3 (a run did not end ok)"
  grep -q "2 runs: 1 collapsed, 1 ok (2 run now, 0 reused)" out || fail "the closing line"
  grep -q "^0,p0,1e-06,,[0-9.e-]*,[0-9.e-]*,ok,," c/runs.csv || fail "the run with the TC model should be ok"
  grep -q '^1,p1,0.0,,[0-9.e-]*,[0-9.e-]*,collapsed,"inelastic collapse.*Enable the TC model' c/runs.csv ||
    fail "the collapsed run's row: its status, its message with the remedy (TC) and its measured quantities"
  grep -q "^1,0.0,1,0,," c/points.csv || fail "the collapsed point's aggregate (1 run, 0 ok, no mean)"
  "$SWEEP" "$HERE/collapse.sweep.toml" --out-dir c -j 2 -q >again 2>&1
  grep -q "(0 run now, 2 reused)" again || fail "a rerun should keep the collapsed run's row: $(cat again)"
  ;;
*) fail "no case $case_name" ;;
esac
echo ok
