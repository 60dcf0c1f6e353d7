"""Histogram of speeds or kinetic energies against Maxwell-Boltzmann, from the CSVs of `ede-stats hist`.

Usage: plot_hist.py HIST.csv CURVE.csv OUT.png|svg speed|energy TITLE
Left panel: the initial (t = 0) histogram, lighter. Right panel: the histogram at the chosen time(s)
with the Maxwell-Boltzmann density at the measured kT dashed. Both panels share the bins and the axes.
"""
import sys

import ede_style as style



def main(hist_path, curve_path, out, quantity, title):
    h = style.read_columns(hist_path)
    curve = style.read_columns(curve_path)
    left, right = h["bin_left"], h["bin_right"]
    widths = [b - a for a, b in zip(left, right)]
    fig, _ = style.figure(width=10, height=4.2)
    fig.clear()
    ax0, ax1 = fig.subplots(1, 2, sharex=True)
    ax0.bar(left, h["initial_density"], width=widths, align="edge", color=style.INITIAL, alpha=0.6,
            edgecolor=style.INITIAL, label="initial, t = 0")
    ax1.bar(left, h["density"], width=widths, align="edge", color=style.COLOURS[0], alpha=0.75, label="log")
    ax1.plot(curve["x"], curve["mb_density"], label="Maxwell-Boltzmann at measured kT", **style.THEORY)
    ax1.set_ylim(0, 1.15 * max(max(h["density"]), max(curve["mb_density"])))
    for ax in (ax0, ax1):
        ax.set_xlabel(style.UNITS[quantity])
        ax.set_ylabel(style.UNITS["density_" + quantity])
        ax.legend(loc="upper right", fontsize=9)
    ax0.set_title("initial distribution", fontsize=10)
    ax1.set_title(title, fontsize=10)
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    main(*sys.argv[1:])
