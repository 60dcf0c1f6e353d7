"""One figure from a CSV of ede-stats gr, sk, psi6, msd or vacf: x against one or more y columns.

Usage: plot_table.py TABLE.csv OUT.png|svg X YS ERROR DASHED TITLE XLABEL YLABEL SCALE
YS and DASHED are comma-separated column names (DASHED: reference curves, drawn dashed); ERROR is a column
of standard errors for the first y ("" for none); SCALE is linear, loglog (|y| on logarithmic axes,
points with y <= 0 drawn hollow: the sign of a long-time tail matters), or points (linear axes, markers
with error bars: one point per run, as ede-stats viscosity on sheared runs writes).
"""
import csv
import sys

import ede_style as style


def number(text):
    return float(text) if text not in ("", None) else float("nan")


def main(path, out, x, ys, error, dashed, title, xlabel, ylabel, scale):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    col = {name: [number(r[name]) for r in rows] for name in rows[0].keys()} if rows else {}
    fig, ax = style.figure()
    xs = col.get(x, [])
    for k, name in enumerate([n for n in ys.split(",") if n]):
        y = col[name]
        colour = style.COLOURS[k % len(style.COLOURS)]
        if scale == "loglog":
            pos = [(a, b) for a, b in zip(xs, y) if a > 0 and b > 0]
            neg = [(a, -b) for a, b in zip(xs, y) if a > 0 and b < 0]
            ax.plot([p[0] for p in pos], [p[1] for p in pos], "o", ms=3, color=colour, label=name)
            if neg:
                ax.plot([p[0] for p in neg], [p[1] for p in neg], "o", ms=3, mfc="none", color=colour,
                        label=f"-{name} (negative)")
        elif scale == "points":
            errors = col[error] if k == 0 and error and error in col else None
            ax.errorbar(xs, y, yerr=errors, fmt="o", ms=4, capsize=3, color=colour, label=name)
        else:
            ax.plot(xs, y, color=colour, label=name)
            if k == 0 and error and error in col:
                lo = [a - b for a, b in zip(y, col[error])]
                hi = [a + b for a, b in zip(y, col[error])]
                ax.fill_between(xs, lo, hi, color=colour, alpha=0.25, linewidth=0)
    for j, name in enumerate([n for n in dashed.split(",") if n]):
        y = col[name]
        pts = [(a, b) for a, b in zip(xs, y) if b == b and (scale != "loglog" or (a > 0 and b > 0))]
        theory = dict(style.THEORY)
        if j > 0:  # a second reference curve in another colour, so the two can be told apart
            theory["color"] = style.COLOURS[(j + 1) % len(style.COLOURS)]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], label=name, **theory)
    if scale == "loglog":
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=9)
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 11:
        sys.exit(__doc__)
    main(*sys.argv[1:])
