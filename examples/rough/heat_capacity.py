#!/usr/bin/env python3
"""Heat capacity (c = k smooth, 3k/2 rough) and the ideal-gas law, from logs (issue 18, item 3).

1. Energy against temperature (examples/rough/equipartition.toml). A small sweep of the starting
   temperature T0: each run starts with its energy E in translation only, runs until it has relaxed,
   and its temperature is read from the translational velocities alone (the thermometer:
   kT = <m (v - V)^2> / 2 over the second half of the run, V the centre-of-mass velocity). Smooth
   disks (roughness = -1) keep E = N kT: c = dE/dT = k per disk. Perfectly rough elastic disks
   (roughness = 1) share E with rotation, E = (3/2) N kT: c = 3k/2. The slope of E/N against kT is c.
2. P against T and N at low density (examples/rough/ideal-gas.toml, packing fraction ~0.01, walls):
   the pressure on the walls (ede's wall-impulse measurement) against the ideal-gas law P A = N kT,
   with A the area the centres can reach (A_v, docs/pressure.md), and Henderson's hard-disk correction.

Checks: c within 5 % of 1 and 3/2; P A_v / (N kT) within 5 % of Henderson's Z (~1.02 here).

usage: heat_capacity.py [--out-dir DIR] [--quick]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "python"))
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ede  # noqa: E402
from _common import EXAMPLES, arguments  # noqa: E402

a = arguments(__doc__.split("\n")[0])
here = EXAMPLES / "rough"
small = {"species[0].count": 300} if a.quick else {}


def translational_kt(log, times):
    """kT from the translational velocities (2 degrees of freedom, centre of mass at rest), averaged."""
    values = []
    for t in times:
        s = log.state(float(t))
        m = s.mass.astype(float)
        vx, vy = s.vx.astype(float), s.vy.astype(float)
        vx, vy = vx - np.average(vx, weights=m), vy - np.average(vy, weights=m)
        values.append(np.sum(m * (vx * vx + vy * vy)) / (2 * (len(s) - 1)))
    return float(np.mean(values))


def total_energy(log):
    s = log.state(0.0)
    e = np.sum(s.kinetic_energy.astype(float)) + np.sum(s.rotational_energy.astype(float))
    m = s.mass.astype(float)
    # Less the centre of mass's kinetic energy: what the thermometer sees is the motion relative to it.
    px, py = np.sum(m * s.vx.astype(float)), np.sum(m * s.vy.astype(float))
    return (e - (px * px + py * py) / (2 * np.sum(m))) / len(s)


fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
slopes = {}
for roughness, label in ((-1.0, "smooth (beta = -1)"), (1.0, "rough (beta = 1)")):
    kts, energies = [], []
    for t0 in (0.5, 1.0, 2.0, 4.0):
        log_path = a.out_dir / ("heat-%s-T%g.ede" % ("rough" if roughness > 0 else "smooth", t0))
        ede.run(here / "equipartition.toml", log=log_path,
                set={"physics.roughness": roughness, "species[0].velocity.temperature": t0, **small},
                progress=False)
        log = ede.open(log_path)
        end = float(log.info["end_time"])
        kts.append(translational_kt(log, np.linspace(end / 2, end, 20)))
        energies.append(total_energy(log))
    slope, intercept = np.polyfit(kts, energies, 1)
    slopes[roughness] = slope
    print("%-18s E/N against kT: slope c = %.4f k (expected %s), intercept %.2g" %
          (label, slope, "1" if roughness < 0 else "3/2", intercept))
    line, = ax1.plot(kts, energies, "o", label="%s: c = %.3f k" % (label, slope))
    grid = np.linspace(0, max(kts) * 1.05, 10)
    ax1.plot(grid, (1.0 if roughness < 0 else 1.5) * grid, "--", lw=1, color=line.get_color())
ax1.set_xlabel("kT (from the translational velocities)")
ax1.set_ylabel("energy per disk E/N")
ax1.set_title("heat capacity: dashed E = N kT and E = 3/2 N kT")
ax1.legend()

rows = []
for t0, count in ((0.5, 400), (1.0, 400), (2.0, 400), (1.0, 200), (1.0, 800)):
    if a.quick and count > 400:
        continue
    log_path = a.out_dir / ("ideal-T%g-N%d.ede" % (t0, count))
    ede.run(here / "ideal-gas.toml", log=log_path,
            set={"species[0].velocity.temperature": t0, "species[0].count": count}, progress=False)
    p = ede.pressure(ede.open(log_path))
    n_kt_over_a = count * p["kT"]["mean"] / p["virial_area"]
    rows.append((t0, count, p["kT"]["mean"], p["wall"]["mean"], p["wall"]["error"], n_kt_over_a, p["henderson"]))
    print("T0 = %g, N = %d: kT = %.4f, P = %.2f +- %.2f, N kT / A_v = %.2f, P A_v/(N kT) = %.4f (Henderson %.4f)"
          % (t0, count, p["kT"]["mean"], p["wall"]["mean"], p["wall"]["error"], n_kt_over_a,
             p["wall"]["mean"] / n_kt_over_a, p["henderson"] / n_kt_over_a))
x = np.array([r[5] for r in rows])
ax2.errorbar(x, [r[3] for r in rows], yerr=[r[4] for r in rows], fmt="o", label="P on the walls (from the logs)")
grid = np.linspace(0, x.max() * 1.05, 10)
ax2.plot(grid, grid, "--", lw=1, label="ideal gas P = N kT / A")
for t0, count, kt, pw, err, nkta, hend in rows:
    ax2.annotate("T0=%g N=%d" % (t0, count), (nkta, pw), fontsize=7, xytext=(3, -10), textcoords="offset points")
ax2.set_xlabel("N kT / A_v")
ax2.set_ylabel("P")
ax2.set_title("ideal-gas law at packing fraction ~0.01")
ax2.legend()
fig.tight_layout()
fig.savefig(a.out_dir / "heat-capacity.png", dpi=120)
print("figure:", a.out_dir / "heat-capacity.png")

assert abs(slopes[-1.0] - 1.0) < 0.05, "smooth disks: c departs from k"
assert abs(slopes[1.0] - 1.5) < 0.05 * 1.5, "rough disks: c departs from 3k/2"
for t0, count, kt, pw, err, nkta, hend in rows:
    assert abs(pw / hend - 1) < 0.05, "P departs from the hard-disk equation of state by more than 5 %"
