"""Collisions over time, from the CSV of `ede-stats collisions`.

Usage: plot_collisions.py COLLISIONS.csv OUT.png|svg
Three panels sharing the time axis: pair collisions per disk; the collision rate per disk (and its
inverse, the mean free time, on the right axis) with Enskog's rate for each interval (dotted, when the
CSV has it: equal disks); the speed classes slow / medium / fast in percent.
"""
import sys

import ede_style as style



def main(path, out):
    c = style.read_columns(path)
    t = c["time"]
    fig, _ = style.figure(height=8)
    fig.clear()
    ax0, ax1, ax2 = fig.subplots(3, 1, sharex=True)
    ax0.plot(t, c["collisions_per_particle"], color=style.COLOURS[0])
    ax0.set_ylabel("collisions per disk")
    ax1.plot(t, c["collision_rate"], color=style.COLOURS[0], label="rate")
    if "enskog_rate" in c and any(v == v for v in c["enskog_rate"]):
        ax1.plot(t, c["enskog_rate"], color=style.COLOURS[2], linestyle=":", label="Enskog 2nσg(σ)√(πkT/m)")
        ax1.legend(fontsize=8, loc="lower right")
    ax1.set_ylabel("collision rate [1/T]")
    right = ax1.twinx()
    right.plot(t, c["mean_free_time"], color=style.COLOURS[1], linestyle="--", label="mean free time")
    right.set_ylabel("mean free time [T]", color=style.COLOURS[1])
    right.grid(False)
    for name, colour in (("slow", style.COLOURS[0]), ("medium", style.COLOURS[2]), ("fast", style.COLOURS[1])):
        ax2.plot(t, c[name + "_percent"], color=colour, label=name)
    ax2.set_ylabel("disks [%]")
    ax2.set_ylim(0, 100)
    ax2.legend(fontsize=9, title="speed vs initial mean v̄0: slow < 0.5 v̄0, fast > 1.5 v̄0", title_fontsize=8)
    ax2.set_xlabel(style.UNITS["time"])
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
