"""Shared look of ede's figures: one place for sizes, fonts, colours and conventions.

Conventions (issue 4): axes labelled with units (ede's units are the scene's: lengths L, times T, masses M);
theory curves dashed; initial distributions shown beside the final ones in a lighter colour.
"""
import csv

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]
INITIAL = "#aaaaaa"     # initial distributions
THEORY = dict(linestyle="--", linewidth=1.6, color="black")  # theory curves

# Units of ede's quantities, for axis labels.
UNITS = {
    "time": "t [T]",
    "speed": "speed v [L/T]",
    "energy": "kinetic energy [M L²/T²]",
    "density_speed": "probability density [T/L]",
    "density_energy": "probability density [T²/(M L²)]",
    "pressure": "pressure [M/T²]  (force per length, 2D)",
    "length": "[L]",
}


def read_columns(path):
    """A CSV table as {column: [floats]} (an empty cell is NaN; no rows: {})."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {key: [float(r[key]) if r[key] != "" else float("nan") for r in rows] for key in rows[0]} if rows else {}


def figure(width=6.4, height=4.2):
    plt.rcParams.update({"font.size": 11, "axes.grid": True, "grid.alpha": 0.3, "savefig.dpi": 150})
    return plt.subplots(figsize=(width, height), constrained_layout=True)


def save(fig, path):
    """Saves as PNG or SVG according to the file name's extension."""
    fmt = "svg" if path.lower().endswith(".svg") else "png"
    fig.savefig(path, format=fmt)
    plt.close(fig)
