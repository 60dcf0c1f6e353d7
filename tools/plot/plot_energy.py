"""Kinetic energy over time, one curve per log, from the CSV of `ede-stats energy`.

Usage: plot_energy.py ENERGY.csv OUT.png|svg
Top: E(t)/E(0) per run (label column: the scene's restitution). Bottom, when a run has several species:
each species' mean kinetic energy (the equipartition check of a mixture).
"""
import csv
import sys

import ede_style as style


def number(text):
    return float(text) if text not in ("", None) else float("nan")


def read_runs(path):
    runs = {}
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        species = [c.split(":", 1)[1] for c in reader.fieldnames if c.startswith("mean_kinetic_energy:")]
        for row in reader:
            run = runs.setdefault(row["label"], {"time": [], "ratio": [], "species": {s: [] for s in species}})
            run["time"].append(number(row["time"]))
            run["ratio"].append(number(row["energy_ratio"]))
            for s in species:
                run["species"][s].append(number(row["mean_kinetic_energy:" + s]))
    return runs


def main(path, out):
    runs = read_runs(path)
    mixtures = [(label, r) for label, r in runs.items()
                if sum(1 for v in r["species"].values() if v and v[0] == v[0]) > 1]
    fig, ax = style.figure(height=6.4 if mixtures else 4.2)
    if mixtures:
        fig.clear()
        ax, ax2 = fig.subplots(2, 1, sharex=True)
    for k, (label, r) in enumerate(runs.items()):
        ax.plot(r["time"], r["ratio"], color=style.COLOURS[k % len(style.COLOURS)], label=label)
    ax.set_ylabel("E(t) / E(0)")
    ax.set_title("kinetic energy", fontsize=10)
    ax.legend(fontsize=9)
    if mixtures:
        styles = ["-", "--", ":", "-."]
        for k, (label, r) in enumerate(mixtures):
            for j, (name, values) in enumerate(r["species"].items()):
                if values and values[0] == values[0]:
                    ax2.plot(r["time"], values, color=style.COLOURS[j % len(style.COLOURS)],
                             linestyle=styles[k % len(styles)], label=f"{name} ({label})")
        ax2.set_ylabel("mean kinetic energy [M L²/T²]")
        ax2.set_title("per species", fontsize=10)
        ax2.legend(fontsize=9)
        ax2.set_xlabel(style.UNITS["time"])
    else:
        ax.set_xlabel(style.UNITS["time"])
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
