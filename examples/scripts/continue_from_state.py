#!/usr/bin/env python3
"""Continuing a finished run with changed physics, and the kinetic-theory references, from logs.

Runs examples/continue.toml (an elastic gas) to t = 0.15, then `ede-sim --continue` twice: cooled
(physics.restitution = 0.8, for 1.0 time units) and reversed (start.reverse_velocities = true, for 0.15:
the gas runs back to this run's start). Reads everything back from the logs with ede-stats and
ede-replay: the energy per disk and the collision rate per disk against Enskog's (ede-stats collisions),
with Haff's law for the cooled part (tau from Enskog's rate at its start, ede-stats energy), and the
reversed run's RMS distance from the base run's start. Writes continue.png and continue.csv.

usage: continue_from_state.py TOOLS_DIR OUT_DIR
"""
import csv
import io
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "plot"))
import ede_style  # noqa: E402


def tool(tools, name, *args):
    return subprocess.run([os.path.join(tools, name), *args], check=True, capture_output=True, text=True).stdout


def table(tools, out, name, *args):
    path = os.path.join(out, name)
    tool(tools, "ede-stats", *args, "-o", path)
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text not in ("", None) else float("nan")


def positions(tools, log, at):
    rows = csv.DictReader(io.StringIO(tool(tools, "ede-replay", log, "--at", at)))
    return [(float(r["x"]), float(r["y"])) for r in rows]


def main():
    tools, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    scene = os.path.join(os.path.dirname(__file__), "..", "continue.toml")
    base, cooled, back = (os.path.join(out, n + ".ede") for n in ("continue-base", "continue-cooled", "continue-back"))
    tool(tools, "ede-sim", scene, "-q", "-o", base)
    tool(tools, "ede-sim", "--continue", base, "-q", "-o", cooled, "--set", "physics.restitution=0.8",
         "--set", "stop.time=1.0")
    tool(tools, "ede-sim", "--continue", base, "-q", "-o", back, "--set", "start.reverse_velocities=true")

    start, returned = positions(tools, base, "0"), positions(tools, back, "end")
    rms = math.sqrt(sum((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 for a, b in zip(start, returned)) / len(start))
    n = len(start)

    parts = []  # (label, time offset, energy rows, collision rows)
    for label, log, offset in (("elastic (base run)", base, 0.0), ("continued, ξ = 0.8", cooled, 0.15)):
        energy = table(tools, out, os.path.basename(log) + "-energy.csv", "energy", log, "--points", "101")
        coll = table(tools, out, os.path.basename(log) + "-collisions.csv", "collisions", log)
        parts.append((label, offset, energy, coll))

    fig, _ = ede_style.figure(height=7)
    fig.clear()
    ax0, ax1 = fig.subplots(2, 1, sharex=True)
    with open(os.path.join(out, "continue.csv"), "w") as f:
        f.write("part,time,energy_per_disk,haff_energy_per_disk,collision_rate,enskog_rate\n")
        for k, (label, offset, energy, coll) in enumerate(parts):
            t = [offset + number(r["time"]) for r in energy]
            e = [number(r["kinetic_energy"]) / n for r in energy]
            haff = [number(r["haff_ratio"]) * e[0] for r in energy]
            ax0.plot(t, e, color=ede_style.COLOURS[k], label=label)
            if any(h == h for h in haff):
                ax0.plot(t, haff, color=ede_style.COLOURS[2], linestyle="--", label="Haff, τ from Enskog at the start")
            tc = [offset + number(r["time"]) for r in coll]
            rate, enskog = [number(r["collision_rate"]) for r in coll], [number(r["enskog_rate"]) for r in coll]
            ax1.plot(tc, rate, color=ede_style.COLOURS[k], label="measured" if k == 0 else None)
            ax1.plot(tc, enskog, color="black", linestyle=":", label="Enskog 2nσg(σ)√(πkT/m)" if k == 0 else None)
            for r, h in zip(energy, haff):
                f.write(f"{label},{offset + number(r['time'])!r},{number(r['kinetic_energy']) / n!r},{h!r},,\n")
            for r in coll:
                f.write(f"{label},{offset + number(r['time'])!r},,,{r['collision_rate']},{r['enskog_rate']}\n")
    ax0.set_ylabel("kinetic energy per disk")
    ax0.legend(fontsize=8)
    ax0.set_title(f"reversed continuation: back to the start within {rms:.2g} (RMS)", fontsize=9)
    ax1.set_ylabel("pair collisions per disk per time")
    ax1.set_xlabel(ede_style.UNITS["time"])
    ax1.legend(fontsize=8)
    ede_style.save(fig, os.path.join(out, "continue.png"))
    print(f"reversed continuation: RMS distance from the start {rms:.3g}; figure {os.path.join(out, 'continue.png')}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main()
