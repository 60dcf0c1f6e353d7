#!/usr/bin/env python3
"""Effusion through a hole in a divider against kinetic theory (examples/effusion.toml).

Runs the scene, exports its states every 0.5 time units from the log (ede-replay export, extended XYZ),
counts the disks right of the divider, N_right(t), and draws it against the kinetic-theory curve
N/2 (1 - exp(-t / tau)), tau = A / (2 w_eff <v_x+>): in equilibrium the centres cross a line at
n <v_x+> = n sqrt(kT / (2 pi m)) per unit length and time (kT from the kinetic energy, 2D: E = N kT), and
the line is open to centres over w_eff = w - 2r, where a centre stays at least r from both end points of
the hole; A = (1 - 2r)^2 is the area a half offers the centres (docs/examples.md, "Effusion", derives it).
Prints the measured and predicted N_right at the end.

usage: effusion.py TOOLS_DIR OUT_DIR
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "plot"))
import ede_style  # noqa: E402

HOLE, RADIUS = 0.05, 0.0005
AREA = (1 - 2 * RADIUS) ** 2  # a half's area open to the centres


def frames(path):
    """(time, xs, kinetic energy) per frame of an extended XYZ file as ede-replay export writes it."""
    with open(path) as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        n = int(lines[k])
        header = lines[k + 1]
        time = float(header.split("Time=")[1].split()[0])
        props = header.split("Properties=")[1].split()[0].split(":")
        names = props[0::3]
        widths = [int(w) for w in props[2::3]]
        col = {}
        at = 0
        for name, w in zip(names, widths):
            col[name] = at
            at += w
        xs, energy = [], 0.0
        for line in lines[k + 2:k + 2 + n]:
            f_ = line.split()
            x = float(f_[col["pos"]])
            vx, vy = float(f_[col["vel"]]), float(f_[col["vel"] + 1])
            m = float(f_[col["masses"]])
            xs.append(x)
            energy += 0.5 * m * (vx * vx + vy * vy)
        yield time, xs, energy
        k += n + 2


def main():
    tools, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    scene = os.path.join(os.path.dirname(__file__), "..", "effusion.toml")
    log = os.path.join(out, "effusion.ede")
    xyz = os.path.join(out, "effusion.xyz")
    subprocess.run([os.path.join(tools, "ede-sim"), scene, "-q", "-o", log], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([os.path.join(tools, "ede-replay"), "export", log, "-o", xyz, "--every", "0.5"], check=True,
                   stdout=subprocess.DEVNULL)
    ts, right = [], []
    n = kt = None
    for t, xs, energy in frames(xyz):
        n = len(xs)
        kt = energy / n  # 2D, k = 1: E = N kT
        ts.append(t)
        right.append(sum(1 for x in xs if x > 1.0))
    v_plus = math.sqrt(kt / (2 * math.pi))  # <v_x+> for m = 1
    w_eff = HOLE - 2 * RADIUS
    tau = AREA / (2 * w_eff * v_plus)
    theory = [n / 2 * (1 - math.exp(-t / tau)) for t in ts]
    print(f"N = {n}, kT = {kt:.4f}, <v_x+> = {v_plus:.4f}, w_eff = {w_eff:.5f}, tau = {tau:.2f}")
    print(f"initial rate: theory n <v_x+> w_eff = {n / AREA * v_plus * w_eff:.2f} per unit time")
    print(f"N_right at t = {ts[-1]:g}: measured {right[-1]}, kinetic theory {theory[-1]:.1f} "
          f"(+- {math.sqrt(theory[-1]):.1f} counting noise)")
    fig, ax = ede_style.figure()
    ax.plot(ts, right, ".", label="ede (from the log)")
    ax.plot(ts, theory, "--", label=r"kinetic theory $\frac{N}{2}(1 - e^{-t/\tau})$")
    ax.set_xlabel("time")
    ax.set_ylabel("disks right of the divider")
    ax.set_title(f"effusion through a hole of width {HOLE} (N = {n})")
    ax.legend()
    ede_style.save(fig, os.path.join(out, "effusion.png"))
    os.remove(xyz)


if __name__ == "__main__":
    main()
