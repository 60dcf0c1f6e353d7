#!/usr/bin/env python3
"""The scattering angle of a light disk off a heavy one, against theory (course problem).

Runs examples/scattering.toml at 20 impact parameters b (the light disk starts at y = 0.5 + b), reads the
pair collision from each log (ede-replay events: the light disk's post-collision velocity) and plots the
angle theta = atan2(vy, vx) against b / R12 with theta(b) = pi - 2 asin(b / R12) dashed.

usage: scattering.py TOOLS_DIR OUT_DIR
"""
import csv
import io
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "plot"))
import ede_style  # noqa: E402

R_HEAVY, R_LIGHT = 0.1, 0.001
R12 = R_HEAVY + R_LIGHT


def run(tools, out, b):
    scene = os.path.join(os.path.dirname(__file__), "..", "scattering.toml")
    log = os.path.join(out, "scattering.ede")
    subprocess.run([os.path.join(tools, "ede-sim"), scene, "-q", "-o", log,
                    "--set", f"species.light.placement.positions=[[0.2, {0.5 + b!r}]]"],
                   check=True, stdout=subprocess.DEVNULL)
    events = subprocess.run([os.path.join(tools, "ede-replay"), "events", log, "--from", "0", "--to", "0.35"],
                            check=True, capture_output=True, text=True).stdout
    for row in csv.DictReader(io.StringIO(events)):
        if row["kind"] == "pair":
            # disk 0 is the heavy one, disk 1 the light one (species order)
            light = "i" if row["i"] == "1" else "j"
            return math.atan2(float(row["v" + light + "y"]), float(row["v" + light + "x"]))
    raise RuntimeError(f"no collision at b = {b}")


def main():
    tools, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    ratios = [(k + 0.5) / 20 for k in range(20)]
    angles = [run(tools, out, r * R12) for r in ratios]
    worst = max(abs(a - (math.pi - 2 * math.asin(r))) for r, a in zip(ratios, angles))
    with open(os.path.join(out, "scattering.csv"), "w") as f:
        f.write("b_over_R12,theta,theta_theory\n")
        for r, a in zip(ratios, angles):
            f.write(f"{r!r},{a!r},{math.pi - 2 * math.asin(r)!r}\n")
    fig, ax = ede_style.figure()
    fine = [k / 400 for k in range(401)]
    ax.plot(fine, [math.pi - 2 * math.asin(x) for x in fine], label="theory: π − 2 asin(b/R₁₂)", **ede_style.THEORY)
    ax.plot(ratios, angles, "o", color=ede_style.COLOURS[0], label="ede (from the logs)")
    ax.set_xlabel("impact parameter b / R₁₂")
    ax.set_ylabel("scattering angle θ [rad]")
    ax.set_title(f"light disk off a heavy one (mass ratio 10⁶)\nlargest deviation from theory {worst:.1e} rad",
                 fontsize=11)
    ax.legend()
    ede_style.save(fig, os.path.join(out, "scattering.png"))
    os.remove(os.path.join(out, "scattering.ede"))
    print(f"scattering: 20 impact parameters, largest deviation from theory {worst:.2e} rad")


if __name__ == "__main__":
    main()
