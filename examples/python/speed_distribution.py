#!/usr/bin/env python3
"""Problem 1: disks started at one speed in random directions relax to the 2D Maxwell-Boltzmann law.

Runs examples/speed-distribution.toml, then compares the speed histogram at the start and the end with
p(v) = (m v / kT) exp(-m v^2 / 2kT) at the measured kT, with the Kolmogorov-Smirnov test of the energies."""
import matplotlib.pyplot as plt

import ede
from _common import EXAMPLES, arguments

a = arguments(__doc__.split("\n")[0])
log_path = a.out_dir / "speed-distribution.ede"
overrides = {"species[0].count": 1000, "stop.time": 0.15} if a.quick else {}
ede.run(EXAMPLES / "speed-distribution.toml", log=log_path, set=overrides, progress=not a.quick)

log = ede.open(log_path)
d = ede.distribution(log)  # at the end of the log
print("kT = %.6g, KS D = %.4g, p = %.3g over %d disks" % (d.kT, d.ks.statistic, d.ks.p_value, d.disks))
assert d.ks.p_value > 1e-3, "the speeds should have relaxed to Maxwell-Boltzmann"

centres = 0.5 * (d.edges[1:] + d.edges[:-1])
fig, ax = plt.subplots(figsize=(6, 4))
ax.bar(centres, d.initial_density, width=d.edges[1] - d.edges[0], alpha=0.3, label="t = 0 (one speed)")
ax.step(centres, d.density, where="mid", label="t = %.3g" % log.end_time)
ax.plot(d.curve_x, d.curve_density, "k--", label="2D Maxwell-Boltzmann, kT = %.3g" % d.kT)
ax.set_xlabel("speed v")
ax.set_ylabel("probability density")
ax.set_ylim(0, 1.2 * max(d.curve_density))
ax.legend()
fig.tight_layout()
fig.savefig(a.out_dir / "speed-distribution.png", dpi=120)
print("figure:", a.out_dir / "speed-distribution.png")
