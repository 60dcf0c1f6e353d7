"""Figures of ede-crater (docs/crater.md), drawn from the CSV files it writes.

  plot_crater.py measure PROFILE.csv ENERGY.csv OUT [--time T] [--fraction F] [--drop-threshold D] [--title S]
      left: the surface profile before and after, the crater region shaded between them;
      right: the kinetic energy fraction over time, the fraction asked for and the measured time marked.
  plot_crater.py scan AGGREGATE.csv OUT --metric NAME [--param KEY]
      the metric's mean against the scanned parameter, error bars one standard error of the mean; the
      axis is logarithmic when the values are positive and span a decade or more.

Only numbers from the CSV files are drawn; nothing is computed here but what is plotted.
"""
import argparse
import csv
import math
import sys

from matplotlib.ticker import NullLocator

import ede_style
from ede_style import COLOURS, INITIAL, plt

UNITS = {
    "count": "displaced bed disks",
    "depth": "crater depth [L]",
    "width": "crater width [L]",
    "area": "crater area [L²]",
    "depth_below_mean": "depth below the initial mean level [L]",
    "deepest_x": "x of the deepest point [L]",
    "removed_area": "area where the surface fell [L²]",
    "raised_area": "area where the surface rose [L²]",
    "detached": "detached bed disks (ejecta)",
}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text not in ("", None) else math.nan


def steps(rows, key):
    """Bin edges and values as a step curve: each bin's value held over [x_left, x_right]."""
    xs, ys = [], []
    for r in rows:
        xs += [number(r["x_left"]), number(r["x_right"])]
        ys += [number(r[key])] * 2
    return xs, ys


def plot_measure(a):
    profile = read_csv(a.profile)
    if a.energy == "-":  # no energy curve (a run under gravity): the profiles alone
        fig, left = ede_style.figure()
        right = None
    else:
        energy = read_csv(a.energy)
        fig, single = ede_style.figure(width=11, height=4.2)  # the shared style; two panels in its figure
        single.remove()
        left, right = fig.subplots(1, 2)
    x, before = steps(profile, "h_before")
    _, after = steps(profile, "h_after")
    left.plot(x, before, color=INITIAL, linewidth=1.6, label="surface before")
    left.plot(x, after, color=COLOURS[0], linewidth=1.4, label="surface after")
    inside = [r["in_crater"] == "1" for r in profile for _ in (0, 1)]
    left.fill_between(x, after, before, where=inside, color=COLOURS[1], alpha=0.3, linewidth=0,
                      label="crater (fell by > %.3g)" % a.drop_threshold if a.drop_threshold else "crater")
    left.set_xlabel("x " + ede_style.UNITS["length"])
    left.set_ylabel("surface height h(x) " + ede_style.UNITS["length"])
    left.set_title("surface profile" + (" at t = %.4g" % a.time if a.time is not None else ""))
    left.legend(loc="lower left", fontsize=9)

    if right is None:
        if a.title:
            left.set_title(a.title + ": " + left.get_title(), fontsize=11)
        ede_style.save(fig, a.out)
        return
    t = [number(r["t"]) for r in energy]
    f = [number(r["energy_fraction"]) for r in energy]
    right.step(t, f, where="post", color=COLOURS[0], linewidth=1.4, label="E(t) / E(0)")
    if a.fraction is not None:
        right.axhline(a.fraction, **ede_style.THEORY, label="fraction %.3g" % a.fraction)
    if a.time is not None:
        right.axvline(a.time, color=COLOURS[1], linewidth=1, label="measured at t = %.4g" % a.time)
    right.set_yscale("log")
    right.set_xlabel(ede_style.UNITS["time"])
    right.set_ylabel("kinetic energy fraction E / E(0)")
    right.set_title("kinetic energy")
    right.legend(loc="lower left", fontsize=9)
    if a.title:
        fig.suptitle(a.title, fontsize=11)
    ede_style.save(fig, a.out)


def plot_scan(a):
    rows = read_csv(a.aggregate)
    mean_key, err_key = a.metric + "_mean", a.metric + "_stderr"
    if not rows or mean_key not in rows[0]:
        sys.exit("no column %s in %s" % (mean_key, a.aggregate))
    numeric = all(r["x"] != "" for r in rows)
    xs = [number(r["x"]) if numeric else k for k, r in enumerate(rows)]
    order = sorted(range(len(rows)), key=lambda k: xs[k])
    x = [xs[k] for k in order]
    y = [number(rows[k][mean_key]) for k in order]
    e = [number(rows[k][err_key]) for k in order]
    e = [0 if math.isnan(v) else v for v in e]
    fig, ax = ede_style.figure()
    ax.errorbar(x, y, yerr=e, fmt="o-", color=COLOURS[0], capsize=4, linewidth=1.4,
                label="mean ± standard error (n = %s)" % "/".join(sorted({r["n"] for r in rows})))
    # Values with runs that ended in inelastic collapse, with a non-finite number or unfinished (the
    # n_suspect column): a red ring and a note, so they are never read as good points beside the others.
    suspect = [k for k in order if int(rows[k].get("n_suspect", "0") or 0) > 0]
    if suspect:
        ax.plot([xs[k] for k in suspect], [number(rows[k][mean_key]) for k in suspect], "o", markersize=13,
                markerfacecolor="none", markeredgecolor="#c0392b", markeredgewidth=1.6,
                label="includes runs ended by inelastic collapse or unfinished (scan.csv run_status)")
    if not numeric:
        ax.set_xticks(x, [rows[k]["value"] for k in order])
    elif min(x) > 0 and max(x) >= 10 * min(x):
        ax.set_xscale("log")  # values spanning a decade or more (masses 5, 25, 125): equal ratios, equal steps
        ax.set_xticks(x, ["%g" % v for v in x])  # ticks at the scanned values, written plainly
        ax.xaxis.set_minor_locator(NullLocator())
    label = a.param or "parameter"
    if numeric and any(r["value"].startswith("[") for r in rows):
        label += " (length of the vector)"
    ax.set_xlabel(label)
    ax.set_ylabel(UNITS.get(a.metric, a.metric))
    ax.set_title("crater %s against %s" % (a.metric, a.param or "the parameter"))
    ax.legend(fontsize=9)
    ede_style.save(fig, a.out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="mode", required=True)
    m = sub.add_parser("measure")
    m.add_argument("profile")
    m.add_argument("energy", help="the energy curve CSV, or - for none (runs under gravity)")
    m.add_argument("out")
    m.add_argument("--time", type=float)
    m.add_argument("--fraction", type=float)
    m.add_argument("--drop-threshold", type=float)
    m.add_argument("--title")
    s = sub.add_parser("scan")
    s.add_argument("aggregate")
    s.add_argument("out")
    s.add_argument("--metric", default="depth")
    s.add_argument("--param")
    a = p.parse_args()
    plot_measure(a) if a.mode == "measure" else plot_scan(a)


if __name__ == "__main__":
    main()
