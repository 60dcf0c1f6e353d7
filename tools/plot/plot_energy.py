"""Kinetic energy over time, one curve per log, from the CSV of `ede-stats energy`.

Usage: plot_energy.py ENERGY.csv OUT.png|svg
Top: E(t)/E(0) per run (label column: the scene's restitution), with Haff's law dashed for inelastic runs
(haff_ratio column); a logarithmic axis when the energy falls by more than a factor 20. Bottom, when a run
has several species: each species' mean kinetic energy (the equipartition check of a mixture), on a
logarithmic axis when they span more than a factor 100 (one fast disk in a slow gas).
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
            run = runs.setdefault(row["label"], {"time": [], "ratio": [], "haff": [], "species": {s: [] for s in species}})
            run["time"].append(number(row["time"]))
            run["ratio"].append(number(row["energy_ratio"]))
            run["haff"].append(number(row.get("haff_ratio")))
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
    lowest = 1.0
    for k, (label, r) in enumerate(runs.items()):
        colour = style.COLOURS[k % len(style.COLOURS)]
        ax.plot(r["time"], r["ratio"], color=colour, label=label)
        if any(h == h for h in r["haff"]):
            ax.plot(r["time"], r["haff"], linestyle="--", linewidth=1.4, color=colour, alpha=0.8,
                    label=f"Haff's law, {label}")
        lowest = min([lowest] + [v for v in r["ratio"] if v == v and v > 0])
    if lowest < 0.05:
        ax.set_yscale("log")
    else:
        ax.ticklabel_format(axis="y", useOffset=False, style="plain")
        if max(abs(v - 1) for r in runs.values() for v in r["ratio"] if v == v) < 1e-6:
            ax.set_ylim(0.9, 1.1)  # conserved to round-off: show it as the flat line it is
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
        values = [v for _, r in mixtures for vs in r["species"].values() for v in vs if v == v and v > 0]
        if values and max(values) > 100 * min(values):
            ax2.set_yscale("log")
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
