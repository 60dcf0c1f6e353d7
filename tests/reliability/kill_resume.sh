#!/bin/bash
# kill -9 in the middle of a run, then ede-sim --resume (again and again until it finishes): the finished
# log must be byte-identical to an uninterrupted run's. KILLS kills at random moments (default 3).
# Run by run_case.sh (cases.txt: kill-9-and-resume) and by scripts/soak.sh with a longer run.
set -u
scene=${SCENE:-$FIX/long.toml}
events=${EVENTS:-3000000}
kills=${KILLS:-3}
$SIM "$scene" --set stop.events=$events -o whole.ede -q >/dev/null || exit 8
$SIM "$scene" --set stop.events=$events -o cut.ede -q >/dev/null 2>&1 &
pid=$!
done_kills=0
for k in $(seq "$kills"); do
  # a random moment: 0.1-0.9 s, times SLEEP_SCALE (the soak spreads its kills over a longer run)
  sleep "$(awk -v r=$RANDOM -v s="${SLEEP_SCALE:-1}" 'BEGIN { printf "%.2f", (0.1 + (r % 9) / 10) * s }')"
  if kill -0 $pid 2>/dev/null; then
    kill -KILL $pid; wait $pid 2>/dev/null; done_kills=$((done_kills + 1))
  else
    break
  fi
  $SIM --resume cut.ede -q >/dev/null 2>resume.err &
  pid=$!
done
wait $pid
status=$?
for _ in $(seq $((kills + 10))); do
  [ $status -eq 0 ] && break
  if grep -q "already finished" resume.err 2>/dev/null; then status=0; break; fi
  $SIM --resume cut.ede -q >/dev/null 2>resume.err
  status=$?
done
echo "kills: $done_kills"
if cmp -s whole.ede cut.ede; then echo "logs identical after $done_kills kills"; exit 0; fi
echo "logs DIFFER after $done_kills kills"; cmp whole.ede cut.ede | head -2
exit 1
