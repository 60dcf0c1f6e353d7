"""Per-species temperature and mean speed, from the CSV of `ede-stats species`.

Usage: plot_species.py SPECIES.csv OUT.png|svg
Several times: kT and mean speed per species over time (all disks dashed). One time: bars per species.
"""
import csv
import sys

import ede_style as style


def read(path):
    data = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            s = data.setdefault(row["species"], {"time": [], "kT": [], "mean_speed": []})
            for key in s:
                s[key].append(float(row[key]))
    return data


def main(path, out):
    data = read(path)
    fig, _ = style.figure(width=10)
    fig.clear()
    ax0, ax1 = fig.subplots(1, 2)
    names = list(data)
    several = len(data[names[0]]["time"]) > 1
    for k, name in enumerate(names):
        s = data[name]
        colour = "black" if name == "all" else style.COLOURS[k % len(style.COLOURS)]
        if several:
            line = "--" if name == "all" else "-"
            ax0.plot(s["time"], s["kT"], color=colour, linestyle=line, label=name)
            ax1.plot(s["time"], s["mean_speed"], color=colour, linestyle=line, label=name)
        else:
            ax0.bar(k, s["kT"][0], color=colour, label=name)
            ax1.bar(k, s["mean_speed"][0], color=colour, label=name)
    for ax in (ax0, ax1):
        if several:
            ax.set_xlabel(style.UNITS["time"])
        else:
            ax.set_xticks(range(len(names)), names)
            ax.set_xlabel(f"species at t = {data[names[0]]['time'][0]:.6g} [T]")
        ax.legend(fontsize=9)
    ax0.set_ylabel("kT = <m v²/2> [M L²/T²]")
    ax1.set_ylabel("mean " + style.UNITS["speed"])
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
