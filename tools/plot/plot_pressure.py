"""Pressure per block vs time, from the CSV of `ede-stats pressure -o`.

Each block's wall pressure (walled boxes) and virial pressure as points at the block's middle, the mean of
each as a line with its ± standard-error band, and the ideal gas and Henderson's equation of state dashed
(theory, ede_style.THEORY). The means and errors come from the command line (ede-stats computed them);
the script only draws.

usage: plot_pressure.py CSV OUT --ideal P --henderson P --virial MEAN ERR [--wall MEAN ERR] [--walled]
                        [--title TEXT]
"""
import argparse
import csv

import ede_style


def read_blocks(path):
    rows = list(csv.DictReader(open(path, newline="")))
    mid = [(float(r["t0"]) + float(r["t1"])) / 2 for r in rows]
    half = [(float(r["t1"]) - float(r["t0"])) / 2 for r in rows]
    def column(name):
        return [float(r[name]) if r[name] != "" else None for r in rows]
    return mid, half, column("P_wall"), column("P_virial")


def band(ax, x0, x1, mean, err, colour, label):
    ax.axhline(mean, color=colour, linewidth=1.2)
    ax.axhspan(mean - err, mean + err, color=colour, alpha=0.15, linewidth=0, label=label)


def ideal_in_view(ax, ideal, values):
    """Scales the axis to the data and Henderson when the ideal-gas line lies far off that range (a dense
    gas), instead of squashing the data into a thin line; returns where the line went ("" if in view)."""
    lo, hi = min(values), max(values)
    span = max(hi - lo, 1e-12 * max(abs(hi), 1.0))
    if lo - 2 * span <= ideal <= hi + 2 * span:
        return ""
    ax.set_ylim(lo - 0.3 * span, hi + 0.3 * span)
    return " (off scale, below)" if ideal < lo else " (off scale, above)"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csv")
    p.add_argument("out")
    p.add_argument("--ideal", type=float, required=True)
    p.add_argument("--henderson", type=float, required=True)
    p.add_argument("--virial", type=float, nargs=2, required=True)
    p.add_argument("--wall", type=float, nargs=2)
    p.add_argument("--walled", action="store_true", help="the box has walls: theory lines use A_v")
    p.add_argument("--title", default="")
    a = p.parse_args()

    mid, half, wall, virial = read_blocks(a.csv)
    fig, ax = ede_style.figure()
    x0, x1 = (mid[0] - half[0], mid[-1] + half[-1]) if mid else (0, 1)
    series = [("virial", virial, a.virial, ede_style.COLOURS[0])]
    if a.wall is not None:
        series.insert(0, ("wall", wall, a.wall, ede_style.COLOURS[1]))
    for name, values, (mean, err), colour in series:
        pts = [(t, v) for t, v in zip(mid, values) if v is not None]
        ax.plot([t for t, _ in pts], [v for _, v in pts], "o", color=colour, markersize=4,
                label=f"P_{name} per block")
        band(ax, x0, x1, mean, err, colour, f"P_{name} = {mean:.5g} ± {err:.2g}")
    area = "A_v" if a.walled else "A"
    data = [v for _, values, _, _ in series for v in values if v is not None] + [a.henderson]
    where = ideal_in_view(ax, a.ideal, data)
    ax.axhline(a.ideal, **dict(ede_style.THEORY, color="#555555"),
               label=f"ideal gas N kT / {area} = {a.ideal:.5g}{where}")
    ax.axhline(a.henderson, **ede_style.THEORY, label=f"Henderson Z(φ) N kT / {area} = {a.henderson:.5g}")
    ax.set_xlim(x0, x1)
    ax.set_xlabel(ede_style.UNITS["time"])
    ax.set_ylabel(ede_style.UNITS["pressure"])
    if a.title:
        ax.set_title(a.title, fontsize=10)
    ax.legend(fontsize=8, loc="best")
    ede_style.save(fig, a.out)


if __name__ == "__main__":
    main()
