"""Two panels from the CSV of ede-stats impacts: the density of |b|/(r_i + r_j) at pair collisions against
the uniform law, and of the relative speed g against the flux-weighted Maxwellian (both dashed).

Usage: plot_impacts.py TABLE.csv OUT.png|svg TITLE
"""
import sys

import ede_style as style


def main(path, out, title):
    col = style.read_columns(path)
    fig, _ = style.figure(width=10, height=4.2)
    fig.clear()
    left, right = fig.subplots(1, 2)
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
