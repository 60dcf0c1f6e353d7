"""Two panels from the CSV of ede-stats impacts: the density of |b|/(r_i + r_j) at pair collisions against
the uniform law, and of the relative speed g against the flux-weighted Maxwellian (both dashed).

Usage: plot_impacts.py TABLE.csv OUT.png|svg TITLE
"""
import csv
import sys

import matplotlib.pyplot as plt

import ede_style as style


def main(path, out, title):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    col = {name: [float(r[name]) if r[name] else float("nan") for r in rows] for name in rows[0].keys()}
    plt.rcParams.update({"font.size": 11, "axes.grid": True, "grid.alpha": 0.3, "savefig.dpi": 150})
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2), constrained_layout=True)
    for ax, p, xlabel in ((left, "b", "impact parameter |b| / (r_i + r_j)"), (right, "g", "relative speed g [L/T]")):
        edges = col[p + "_left"] + col[p + "_right"][-1:]
        ax.stairs(col[p + "_density"], edges, color=style.COLOURS[0], label="measured")
        mids = [(a + b) / 2 for a, b in zip(col[p + "_left"], col[p + "_right"])]
        ax.plot(mids, col[p + "_law"], label="equilibrium law", **style.THEORY)
        ax.set_xlabel(xlabel)
        ax.set_ylabel("probability density")
        ax.legend(fontsize=9)
    fig.suptitle(title, fontsize=10)
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
