"""A sweep's quantity against one parameter, with error bars, from ede-sweep's points.csv.

Each point's mean with its standard error over the seeds (ede-sweep computed both; this script only
draws); when the sweep has other parameters, one line per combination of their values. A value that is a
number is its own position on the axis; an array of numbers (a velocity vector) sits at its length, as
ede-crater scan places its values. --reference henderson draws Henderson's equation of state for hard
disks, Z = (1 + phi^2/8) / (1 - phi)^2 (the library's ede::henderson_z), against the packing fraction;
--reference-csv LABEL FILE draws a curve the library computed (ede-sweep writes Kolafa and Rottner's and
Henderson's that way: phi,z columns), and --band LO HI LABEL shades a range of x (the phase regions).

usage: plot_sweep.py POINTS_CSV OUT --x KEY --y QUANTITY [--reference NAME] [--reference-csv LABEL FILE]...
                     [--band LO HI LABEL]...
"""
import argparse
import csv
import math

import ede_style


def position(text):
    text = text.strip()
    if text.startswith("["):
        parts = [float(p) for p in text.strip("[]").split(",") if p.strip()]
        return math.sqrt(sum(p * p for p in parts))
    try:
        return float(text)
    except ValueError:
        return float("nan")


def henderson(phi):
    return (1 + phi * phi / 8) / (1 - phi) ** 2


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("out")
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--reference", choices=["henderson"])
    p.add_argument("--reference-csv", nargs=2, action="append", default=[], metavar=("LABEL", "FILE"))
    p.add_argument("--band", nargs=3, action="append", default=[], metavar=("LO", "HI", "LABEL"))
    a = p.parse_args()
    rows = list(csv.DictReader(open(a.csv, newline="")))
    if not rows:
        raise SystemExit(f"{a.csv}: no points")
    if a.x not in rows[0]:
        keys = [k for k in rows[0] if k not in ("point", "runs", "ok") and not k.endswith(("_mean", "_error"))]
        raise SystemExit(f"--against {a.x}: not a parameter of this sweep (its parameters: {', '.join(keys)})")
    if a.y + "_mean" not in rows[0]:
        raise SystemExit(f"--quantity {a.y}: not collected by this sweep")
    others = [k for k in rows[0] if k not in ("point", "runs", "ok", a.x) and not k.endswith(("_mean", "_error"))]
    lines = {}
    for r in rows:
        if r[a.y + "_mean"] == "":
            continue
        label = ", ".join(f"{k} = {r[k]}" for k in others)
        err = float(r[a.y + "_error"]) if r[a.y + "_error"] != "" else 0.0
        lines.setdefault(label, []).append((position(r[a.x]), float(r[a.y + "_mean"]), err))
    fig, ax = ede_style.figure()
    for k, (label, pts) in enumerate(sorted(lines.items())):
        pts.sort()
        ax.errorbar([q[0] for q in pts], [q[1] for q in pts], yerr=[q[2] for q in pts], marker="o", capsize=3,
                    color=ede_style.COLOURS[k % len(ede_style.COLOURS)], label=label or None)
    if a.reference:
        xs = sorted(position(r[a.x]) for r in rows)
        grid = [xs[0] + (xs[-1] - xs[0]) * i / 200 for i in range(201)]
        f = henderson
        ax.plot(grid, [f(x) for x in grid], label=a.reference, **ede_style.THEORY)
    dashes = ["--", ":", "-."]
    for k, (label, path) in enumerate(a.reference_csv):
        pts = [(float(r["phi"]), float(r["z"])) for r in csv.DictReader(open(path, newline=""))]
        xs = sorted(position(r[a.x]) for r in rows)
        lo, hi = xs[0] - 0.02, xs[-1] + 0.02
        pts = [q for q in pts if lo <= q[0] <= hi]
        ax.plot([q[0] for q in pts], [q[1] for q in pts], linestyle=dashes[k % len(dashes)], color="black",
                linewidth=1.2, label=label)
    shades = ["#d9d9d9", "#f0e0c0", "#c0d8f0"]
    for k, (lo, hi, label) in enumerate(a.band):
        ax.axvspan(float(lo), float(hi), color=shades[k % len(shades)], alpha=0.7, label=label, zorder=0)
    ax.set_xlabel(a.x)
    ax.set_ylabel(f"{a.y}  (mean ± s.e., seeds)")
    if any(lines.keys()) or a.reference or a.reference_csv or a.band:
        ax.legend(fontsize=8)
    ede_style.save(fig, a.out)


if __name__ == "__main__":
    main()
