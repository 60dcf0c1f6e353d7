#!/usr/bin/env python3
"""Problem 2: a mixture of masses m0 and 4 m0 started at the same speed shares its energy equally.

Runs examples/two-masses.toml and plots the mean kinetic energy per disk of each species over time:
both reach the same kT (equipartition), although the heavy disks started with 4 times the energy."""
import matplotlib.pyplot as plt
import numpy as np

import ede
from _common import EXAMPLES, arguments

a = arguments(__doc__.split("\n")[0])
log_path = a.out_dir / "two-masses.ede"
overrides = {"species[0].count": 300, "species[1].count": 300, "stop.time": 0.3} if a.quick else {}
ede.run(EXAMPLES / "two-masses.toml", log=log_path, set=overrides, progress=not a.quick)

log = ede.open(log_path)
e = ede.energy_series(log, points=200)
counts = dict(log.species)
fig, ax = plt.subplots(figsize=(6, 4))
for name, energy in e.species_energy.items():
    ax.plot(e.time, energy / counts[name], label="%s (m = %g)" % (name, log.info["scene"]["species"][
        [s[0] for s in log.species].index(name)]["mass"]))
ax.plot(e.time, e.kinetic_energy / log.info["disks"], "k--", label="all")
ax.set_xlabel("time")
ax.set_ylabel("mean kinetic energy per disk")
ax.legend()
fig.tight_layout()
fig.savefig(a.out_dir / "two-masses.png", dpi=120)

rows = ede.species_stats(log, [log.end_time])
for r in rows:
    print("%-6s N = %5d  <v> = %.4f  kT = %.4f +- %.4f" % (r.species, r.n, r.mean_speed, r.kT,
                                                           r.mean_kinetic_energy_error))
light, heavy = rows[0], rows[1]
gap = abs(light.kT - heavy.kT) / np.hypot(light.mean_kinetic_energy_error, heavy.mean_kinetic_energy_error)
print("equipartition: kT(light) - kT(heavy) = %.2f standard errors" % gap)
assert gap < 5, "the two species should share the energy"
print("figure:", a.out_dir / "two-masses.png")
