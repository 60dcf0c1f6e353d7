#!/usr/bin/env python3
"""Problem 3: energy over time for restitution xi = 1, 0.9 and 0.8, against Haff's law.

Runs examples/cooling.toml three times with physics.restitution overridden, and plots E(t)/E(0) of
each with Haff's law (1 + t/tau)^-2, tau from Enskog's collision rate at t = 0 (not fitted; the tau
calibrated on the collision count only where Enskog does not apply), as ede-stats energy draws it."""
import matplotlib.pyplot as plt
import numpy as np

import ede
from _common import EXAMPLES, arguments

a = arguments(__doc__.split("\n")[0])
fig, ax = plt.subplots(figsize=(6, 4))
for xi in (1.0, 0.9, 0.8):
    log_path = a.out_dir / ("cooling-xi%g.ede" % xi)
    overrides = {"physics.restitution": xi}
    if a.quick:
        overrides.update({"species[0].count": 500, "stop.time": 0.5})
    ede.run(EXAMPLES / "cooling.toml", log=log_path, set=overrides, progress=not a.quick)
    e = ede.energy_series(ede.open(log_path), points=200)
    ratio = e.kinetic_energy / e.initial_energy
    line, = ax.plot(e.time, ratio, label="xi = %g" % xi)
    if np.isfinite(e.haff_tau):
        tau = e.enskog_tau if np.isfinite(e.enskog_tau) else e.haff_tau  # the tau haff_ratio uses
        ax.plot(e.time, e.haff_ratio, "--", color=line.get_color(), lw=1)
        print("xi = %g: E(end)/E(0) = %.4f, Haff (tau = %.4g) says %.4f" % (xi, ratio[-1], tau, e.haff_ratio[-1]))
    else:
        print("xi = %g: E(end)/E(0) = %.17g (elastic: conserved)" % (xi, ratio[-1]))
        assert abs(ratio[-1] - 1) < 1e-12
ax.set_yscale("log")
ax.set_xlabel("time")
ax.set_ylabel("E(t) / E(0)")
ax.legend(title="dashed: Haff's law")
fig.tight_layout()
fig.savefig(a.out_dir / "cooling.png", dpi=120)
print("figure:", a.out_dir / "cooling.png")
