#!/usr/bin/env python3
"""Problem 4: a heavy projectile fired into a bed of resting disks leaves a crater.

Runs examples/crater.toml until 10% of the energy is left, measures the crater as ede-crater does and
draws the disks with the surface before and after."""
import matplotlib.pyplot as plt
from matplotlib.collections import EllipseCollection

import ede
from _common import EXAMPLES, arguments

a = arguments(__doc__.split("\n")[0])
log_path = a.out_dir / "crater.ede"
overrides = {"species[0].count": 1500, "species[0].placement.packing_fraction": 0.5,
             "stop.time": 0.3} if a.quick else {}
ede.run(EXAMPLES / "crater.toml", log=log_path, set=overrides, progress=not a.quick)

log = ede.open(log_path)
c = ede.crater(log)
print("measured at t = %.4g (%s)" % (c.time, c.when))
print("crater: depth %.4g, width %.4g, area %.4g, %d disks displaced" % (c.depth, c.width, c.area, c["count"]))

s = log.state(c.time)
fig, ax = plt.subplots(figsize=(6, 6))
d = 2 * s.radius.astype(float)
ax.add_collection(EllipseCollection(d, d, 0, units="xy", offsets=list(zip(s.x, s.y)), transOffset=ax.transData,
                                    facecolors=["tab:red" if n == "projectile" else "0.7"
                                                for n in (s.species_names[k] for k in s.species)]))
ax.plot(c.profile_x, c.height_before, "b-", lw=1, label="surface before")
ax.plot(c.profile_x, c.height_after, "k-", lw=1.5, label="surface at t = %.3g" % c.time)
ax.set_xlim(0, s.lx)
ax.set_ylim(0, s.ly)
ax.set_aspect("equal")
ax.legend(loc="upper right")
fig.tight_layout()
fig.savefig(a.out_dir / "crater.png", dpi=120)
print("figure:", a.out_dir / "crater.png")
