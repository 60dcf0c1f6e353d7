#!/bin/sh
# Writes the fuzzers' seed corpora into fuzz/corpus/ (committed): the example scenes and a few edge-case
# scenes for the parser; small logs of every scalar type and effect (walls, periodic with wraps, inelastic
# with TC, a reverse action) for the log reader; a few byte strings for the queue and engine targets.
# Run after a build (needs build/tools/ede-sim). Regenerate when the log format changes.
set -eu
cd "$(dirname "$0")/.."
c=fuzz/corpus
mkdir -p $c/scene $c/log $c/queue $c/engine
cp examples/gas.toml examples/scenes/*.toml $c/scene/
printf 'seed = 1\n[[species]]\nname = "a"\ncount = 2\nradius = 0.1\n[species.placement]\nkind = "explicit"\npositions = [[0.3, 0.5], [0.7, 0.5]]\n[species.velocity]\nkind = "list"\nvalues = [[1.0, 0.0], [-1.0, 0.0]]\n[stop]\ntime = 1\n' > $c/scene/two-disks.toml
printf '[box]\nsize = [1.0, 2.0]\nboundary = "periodic"\n[physics]\nrestitution = 0.5\ntc = 1e-4\n[[species]]\nname = "a"\ncount = 20\nradius = { min = 0.01, max = 0.03 }\ndensity = 2.0\n[species.velocity]\nkind = "maxwell"\ntemperature = 1.0\n[stop]\nevents = 100\n[sampling]\ninterval = 0.1\n[[actions]]\ntime = 0.5\nkind = "reverse_velocities"\n' > $c/scene/everything.toml
small="--set stop.events=300 --set log.chunk_events=64 --set log.keyframe_interval=128 --set engine.rebuild_interval=200 -q"
build/tools/ede-sim examples/scenes/head-on.toml -o $c/log/head-on.ede -q > /dev/null
build/tools/ede-sim $c/scene/everything.toml -o $c/log/everything.ede $small > /dev/null
build/tools/ede-sim $c/scene/everything.toml -o $c/log/everything-float.ede $small --set engine.scalar=float > /dev/null
build/tools/ede-sim $c/scene/everything.toml -o $c/log/everything-long.ede $small --set 'engine.scalar="long double"' > /dev/null
build/tools/ede-sim examples/scenes/periodic.toml -o $c/log/periodic.ede $small --set species.gas.count=30 > /dev/null
head -c 4 "$c/log/head-on.ede" > $c/log/cut-magic.ede
head -c 300 "$c/log/everything.ede" > $c/log/cut-early.ede
for k in 1 2 3 4; do head -c $((64 * k)) /dev/urandom > $c/queue/random-$k; head -c $((100 * k)) /dev/urandom > $c/engine/random-$k; done
# Engine inputs in the big-disk mode (flag bit 4): walls, periodic, inelastic with TC, inelastic walls.
for f in 10:big-walls 11:big-periodic 17:big-periodic-inelastic-tc 1a:big-walls-inelastic; do
  { printf "\x${f%%:*}"; head -c 1400 /dev/urandom; } > $c/engine/${f#*:}
done
echo "fuzz corpus: $(ls $c/scene | wc -l) scenes, $(ls $c/log | wc -l) logs, $(ls $c/queue | wc -l) queue, $(ls $c/engine | wc -l) engine inputs"
