#!/usr/bin/env python3
"""The shear viscosity of a dilute hard-disk gas from sheared runs, and its zero-shear limit against Enskog.

Runs examples/shear/viscosity-gas.toml (400 disks at packing 0.1 in a Lees-Edwards box, the thermostat
drawing about the flow) at three shear rates, measures each run's eta = -<P_xy> / rate from the exact
stress integral after the start-up (ede.sheared_viscosity), fits eta* = eta0* + b rate*^2 over the three
(ede.zero_shear_viscosity) and draws eta* against rate*^2 with Enskog's eta_E* (docs/analysis.md, "Shear
viscosity from a sheared run"). The full run takes ~15 s; --quick (what CI runs) a tenth of the time, with
errors about three times as large."""
import matplotlib.pyplot as plt
import numpy as np

import ede
from _common import EXAMPLES, arguments

a = arguments(__doc__.split("\n")[0])
until, start = (2000.0, 400.0) if a.quick else (20000.0, 2000.0)
runs = []
for rate in (0.02, 0.04, 0.06):
    log_path = a.out_dir / ("sheared-%g.ede" % rate)
    ede.run(EXAMPLES / "shear" / "viscosity-gas.toml", log=log_path,
            set={"box.shear_rate": rate, "stop.time": until}, progress=not a.quick)
    v = ede.sheared_viscosity(ede.open(log_path), t0=start)
    print("rate %g: kT %.3f, eta %.4f +- %.4f, eta/eta_E %.3f, eta* %.4f at rate* %.4f" %
          (rate, v["kT"], v["viscosity"], v["viscosity_error"], v["viscosity"] / v["enskog"],
           v["reduced_viscosity"], v["reduced_rate"]))
    # Under shear the stress is negative; eta within 4 of its errors plus 5 % of Enskog's (as the library's
    # test allows at this density).
    assert v["shear_stress"] < 0
    assert abs(v["viscosity"] / v["enskog"] - 1) < 0.05 + 4 * v["viscosity_error"] / v["enskog"]
    runs.append(v)
fit = ede.zero_shear_viscosity(runs)
print("zero shear: eta0* = %.4f +- %.4f, Enskog eta_E* = %.4f, ratio %.3f +- %.3f (chi2 %.2f)" %
      (fit["reduced_viscosity"], fit["reduced_viscosity_error"], fit["enskog_reduced"],
       fit["reduced_viscosity"] / fit["enskog_reduced"], fit["reduced_viscosity_error"] / fit["enskog_reduced"],
       fit["chi2"]))

x = np.array([r["reduced_rate"] ** 2 for r in runs])
fig, ax = plt.subplots(figsize=(6, 4))
ax.errorbar(x, [r["reduced_viscosity"] for r in runs], yerr=[r["reduced_viscosity_error"] for r in runs],
            fmt="o", capsize=3, label="sheared runs")
xs = np.linspace(0, x.max() * 1.05, 50)
ax.plot(xs, fit["reduced_viscosity"] + fit["slope"] * xs, "-", lw=1, label="fit eta0* + b rate*^2")
ax.axhline(fit["enskog_reduced"], ls="--", color="black", label="Enskog")
ax.set_xlabel("(rate sigma sqrt(m / kT))^2")
ax.set_ylabel("eta sigma / sqrt(m kT)")
ax.legend()
fig.tight_layout()
fig.savefig(a.out_dir / "shear-viscosity.png", dpi=120)
print("figure:", a.out_dir / "shear-viscosity.png")
