#!/bin/bash
# Every problem of the course texts and of the GasLab model, run and drawn: logs from ede-sim, every
# number and figure from the logs (ede-stats, ede-crater, ede-render, ede-replay), into one folder.
#
#   examples/run-all.sh [OUT_DIR]        (default out/figures; BUILD=... for another build directory)
#
# A few minutes on a 2-core machine. Each section prints what it shows; docs/examples.md describes the
# figures and what to look for.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD:-$root/build}
out=${1:-$root/out/figures}
tools=$build/tools
logs=$out/logs
mkdir -p "$out" "$logs"
py=/usr/bin/python3
[ -x "$py" ] || py=python3
sim() { "$tools/ede-sim" "$@" -q > /dev/null; }
# The lines of an ede-stats hist report that say how well Maxwell-Boltzmann fits.
fit() { grep -E '^(times|kT|KS vs MB|initial)' || true; }
section() { printf '\n== %s\n' "$1"; }
start=$(date +%s)

section "the default gas: speeds relax from one speed to Maxwell-Boltzmann (examples/gas.toml)"
sim "$root/examples/gas.toml" -o "$logs/gas.ede"
"$tools/ede-stats" hist "$logs/gas.ede" --from 0.4 --every 0.1 --plot "$out/gas-speeds.png" | fit
"$tools/ede-render" "$logs/gas.ede" --at end --color speed -o "$out/gas-picture.png"

section "scattering angle of a light disk off a heavy one (examples/scattering.toml)"
"$py" "$root/examples/scripts/scattering.py" "$tools" "$out"

section "speed distribution, 5000 disks and 10^5 disks (examples/speed-distribution.toml)"
sim "$root/examples/speed-distribution.toml" -o "$logs/speeds-5000.ede"
"$tools/ede-stats" hist "$logs/speeds-5000.ede" --from 0.1 --every 0.02 --plot "$out/speeds-5000.png" | fit
"$tools/ede-stats" collisions "$logs/speeds-5000.ede" --plot "$out/speeds-5000-classes.png" > /dev/null
sim "$root/examples/speed-distribution.toml" --set species.gas.count=100000 --set stop.time=0.12 \
  -o "$logs/speeds-100000.ede"
"$tools/ede-stats" hist "$logs/speeds-100000.ede" --at end --bins 60 --plot "$out/speeds-100000.png" | fit
"$tools/ede-render" "$logs/speeds-5000.ede" --at 0 --color speed -o "$out/speeds-start.png"
"$tools/ede-render" "$logs/speeds-5000.ede" --at end --color speed -o "$out/speeds-end.png"

section "two masses m0 and 4 m0: equal mean energies, speeds in ratio 2 (examples/two-masses.toml)"
sim "$root/examples/two-masses.toml" -o "$logs/two-masses.ede"
"$tools/ede-stats" species "$logs/two-masses.ede" --at end
"$tools/ede-stats" hist "$logs/two-masses.ede" --species light --from 0.2 --every 0.02 --plot "$out/two-masses-light.png" > /dev/null
"$tools/ede-stats" hist "$logs/two-masses.ede" --species heavy --from 0.2 --every 0.02 --plot "$out/two-masses-heavy.png" > /dev/null
"$tools/ede-stats" energy "$logs/two-masses.ede" --plot "$out/two-masses-energy.png" > /dev/null

section "energy curves for restitution 1, 0.9 and 0.8 (examples/cooling.toml)"
for xi in 1 0.9 0.8; do
  sim "$root/examples/cooling.toml" --set physics.restitution=$xi -o "$logs/cooling-$xi.ede"
done
"$tools/ede-stats" energy "$logs/cooling-1.ede" "$logs/cooling-0.9.ede" "$logs/cooling-0.8.ede" \
  --plot "$out/cooling-energy.png" | tail -n 5

section "crater: a heavy projectile into a bed of resting disks (examples/crater.toml)"
sim "$root/examples/crater.toml" -o "$logs/crater.ede"
"$tools/ede-crater" "$logs/crater.ede" --plot "$out/crater-profile.png" | tail -n 8
"$tools/ede-render" "$logs/crater.ede" --at 0 --color displacement -o "$out/crater-start.png"
"$tools/ede-render" "$logs/crater.ede" --at end --color displacement -o "$out/crater-end.png"
"$tools/ede-crater" scan "$root/examples/crater.toml" --param species.projectile.mass --values 5,10,25,50 \
  --seeds 3 --out-dir "$logs/crater-scan" --metric depth --plot "$out/crater-depth-vs-mass.png" -q | tail -n 6

section "crater under gravity: the bed settles, then the projectile falls (examples/crater-gravity.toml)"
sim "$root/examples/crater-gravity.toml" -o "$logs/crater-gravity.ede"
"$tools/ede-crater" "$logs/crater-gravity.ede" --before 0.5 --at end --plot "$out/crater-gravity-profile.png" \
  | grep -E '^(displaced|depth|width)'
for t in 0 0.5 0.6 end; do
  "$tools/ede-render" "$logs/crater-gravity.ede" --at $t --color speed -o "$out/crater-gravity-$t.png"
done

section "polydisperse gas, mass proportional to area (examples/polydisperse.toml)"
sim "$root/examples/polydisperse.toml" -o "$logs/polydisperse.ede"
"$tools/ede-stats" hist "$logs/polydisperse.ede" --quantity energy --from 0.05 --every 0.01 \
  --plot "$out/polydisperse-energies.png" | fit
"$tools/ede-render" "$logs/polydisperse.ede" --at end --color speed -o "$out/polydisperse-picture.png"

section "one fast disk in a slow gas (examples/fast-disk.toml)"
sim "$root/examples/fast-disk.toml" -o "$logs/fast-disk.ede"
"$tools/ede-stats" energy "$logs/fast-disk.ede" --plot "$out/fast-disk-energy.png" > /dev/null
"$tools/ede-stats" hist "$logs/fast-disk.ede" --at end --plot "$out/fast-disk-speeds.png" | fit
"$tools/ede-render" "$logs/fast-disk.ede" --at 0.2 --color speed -o "$out/fast-disk-picture.png"

section "time reversal: forward, reverse, back (examples/time-reversal.toml)"
"$py" "$root/examples/scripts/time_reversal.py" "$tools" "$out"

section "continuing a run: cooled and reversed, against Enskog and Haff (examples/continue.toml)"
"$py" "$root/examples/scripts/continue_from_state.py" "$tools" "$out"

section "effusion through a hole in a divider, against kinetic theory (examples/effusion.toml)"
"$py" "$root/examples/scripts/effusion.py" "$tools" "$out"
"$tools/ede-render" "$out/effusion.ede" --at 20 --color speed -o "$out/effusion-picture.png"

section "rough disks: cooling against Huthmann-Zippelius (examples/rough/cooling.toml)"
PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" "$py" "$root/examples/rough/rough_cooling.py" --out-dir "$out"

section "heat capacity (c = k smooth, 3k/2 rough) and the ideal-gas law (examples/rough/*.toml)"
PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" "$py" "$root/examples/rough/heat_capacity.py" --out-dir "$out"

section "square wells: a crystal below the critical temperature holds together, started hot it evaporates (examples/square-well.toml)"
sim "$root/examples/square-well.toml" --set stop.time=15 -o "$logs/square-well.ede"
sim "$root/examples/square-well.toml" --set stop.time=15 --set 'species[0].velocity.temperature=4.0' \
  -o "$logs/square-well-hot.ede"
for run in square-well square-well-hot; do
  "$tools/ede-stats" energy "$logs/$run.ede" | grep -E '^ *(kinetic|potential|total)'
  "$tools/ede-render" "$logs/$run.ede" --at end --color speed -o "$out/$run.png"
done
"$tools/ede-stats" gr "$logs/square-well.ede" --from 10 --plot "$out/square-well-gr.png" | grep -E '^(g\(r\)|peak|contact)' || true

section "shear viscosity from sheared runs at three rates, and its zero-shear limit (examples/shear/viscosity.sweep.toml)"
"$tools/ede-sweep" "$root/examples/shear/viscosity.sweep.toml" --out-dir "$logs/viscosity-sweep" -q
"$tools/ede-stats" viscosity "$logs"/viscosity-sweep/runs/*.ede --from 2000 --plot "$out/viscosity-sheared.png" |
  grep -E '^(zero shear|Enskog)' || true

printf '\nall figures in %s (%s s)\n' "$out" "$(( $(date +%s) - start ))"
