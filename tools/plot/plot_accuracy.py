"""What accuracy costs in time: the figure of `ede-bench accuracy`, from its CSV files.

Usage: plot_accuracy.py DIR OUT.png|svg   (DIR holds engine.csv, time_stepped.csv, log.csv)
Top row and bottom left, one point per setting and scene: ns per event (x) against the energy drift, the
largest overlap, the time-reversal error and the collisions per disk until runs one ulp apart part.
Colour: the scalar type; filled: stable contact root, open: textbook root; marker: the scene. Zeros (no
overlap seen) are drawn on the lower edge as triangles, twins that had not parted by the cap as arrows. Bottom middle: the time-stepped simulation, CPU
seconds against its errors, one point per dt (labelled in mean free times), with the event-driven
engine's cost and the spread between samples (the event-driven engine on another seed of the same gas). Bottom right: the log's keyframe interval, bytes per event
against the time to seek to a state.
"""
import csv
import math
import os
import sys

from matplotlib import ticker

import ede_style as style

PRECISIONS = ["float", "double", "long_double", "__float128"]
MARKERS = {"gas": "o", "dense": "s", "crystal": "^"}


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if not r.get("failure")]


def colour(precision):
    return style.COLOURS[PRECISIONS.index(precision) % len(style.COLOURS)]


def log_axes(ax, y=True):
    """Logarithmic axes with labels on the decades only (minor labels collide)."""
    ax.set_xscale("log")
    ax.xaxis.set_minor_formatter(ticker.NullFormatter())
    if y:
        ax.set_yscale("log")
        ax.yaxis.set_minor_formatter(ticker.NullFormatter())


def setting_panel(ax, engine, column, ylabel, title, log=True, cap=None):
    """One point per row; zeros (log) on the lower edge as triangles, -1 (not reached) at `cap` as arrows."""
    values = [number(r[column]) for r in engine if number(r[column]) > 0]
    floor = min(values) / 10 if values else 1e-20
    for r in engine:
        y = number(r[column])
        if not math.isfinite(y):
            continue
        marker = MARKERS.get(r["scene"], "o")
        if log and y <= 0:
            y, marker = floor, "v"
        elif not log and y < 0:
            y, marker = cap, r"$\uparrow$"
        c = colour(r["precision"])
        ax.plot(number(r["ns_per_event"]), y, marker=marker, linestyle="none", color=c,
                markerfacecolor=c if r["contact"] == "stable" else "none", markersize=7)
    log_axes(ax, log)
    ax.set_xlabel("ns per event")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=10)


def legend(ax, engine):
    handles = []
    for p in PRECISIONS:
        if any(r["precision"] == p for r in engine):
            handles.append(ax.plot([], [], "o", color=colour(p), label=p.replace("long_double", "long double").lstrip("_"))[0])
    handles.append(ax.plot([], [], "o", color="grey", markerfacecolor="none", label="textbook root")[0])
    for scene, m in MARKERS.items():
        if any(r["scene"] == scene for r in engine):
            handles.append(ax.plot([], [], m, color="grey", label=scene)[0])
    ax.legend(handles=handles, fontsize=8, loc="best")


def stepped_panel(ax, stepped):
    ts = [r for r in stepped if r["method"] == "time-stepped"]
    ed = [r for r in stepped if r["method"] == "event-driven"]
    other = [r for r in stepped if r["method"] == "event-driven (other seed)"]
    if not ts or not ed:
        ax.text(0.5, 0.5, "no time-stepped rows", ha="center", transform=ax.transAxes)
        return
    for key, cpu, c, label in (("rate_error", "cpu_seconds", style.COLOURS[0], "collision rate (ξ = 1)"),
                               ("cooling_error", "cooling_cpu_seconds", style.COLOURS[1], "E(t)/E0 (ξ = 0.9)")):
        xs = [number(r[cpu]) for r in ts]
        ys = [max(number(r[key]), 1e-6) for r in ts]
        ax.plot(xs, ys, "o-", color=c, label="time-stepped: " + label)
        for r, x, y in zip(ts, xs, ys):
            ax.annotate(f"dt={number(r['dt_over_tau']):g}τ", (x, y), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
        ax.axvline(number(ed[0][cpu]), color=c, linestyle=":", linewidth=1.2)
        if other:
            ax.axhline(max(number(other[0][key]), 1e-6), color=c, linestyle="--", linewidth=1)
    ax.plot([], [], ":", color="grey", label="event-driven CPU time")
    if other:
        ax.plot([], [], "--", color="grey", label="event-driven on another seed (sample spread)")
    log_axes(ax)
    ax.set_xlabel("CPU seconds (same simulated time)")
    ax.set_ylabel("relative error vs event-driven")
    ax.set_title("time-stepped at several dt", fontsize=10)
    ax.legend(fontsize=7)


def log_panel(ax, log_rows):
    on = [r for r in log_rows if number(r["bytes_per_event"]) > 0]
    for k, r in enumerate(on):
        x, y = number(r["bytes_per_event"]), 1e3 * number(r["seek_median_seconds"])
        ax.plot(x, y, "o", color=style.COLOURS[k % len(style.COLOURS)])
        ax.annotate(f"{r['configuration'].replace('keyframe every ', '')}, ×{number(r['ratio_to_off']):.2f} time",
                    (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.set_yscale("log")
    ax.set_xlabel("log bytes per logged event")
    ax.set_ylabel("seek to a state, median [ms]")
    ax.set_title("the log: keyframe interval", fontsize=10)


def main(folder, out):
    engine = rows(os.path.join(folder, "engine.csv"))
    stepped = rows(os.path.join(folder, "time_stepped.csv"))
    log_rows = rows(os.path.join(folder, "log.csv"))
    fig, axes = style.figure(width=15, height=9)
    fig.clear()
    axes = fig.subplots(2, 3)
    setting_panel(axes[0][0], engine, "energy_drift", "|E − E0| / E0", "energy drift (elastic)")
    setting_panel(axes[0][1], engine, "largest_overlap", "largest overlap / contact distance", "largest overlap")
    legend(axes[0][1], engine)
    c = "10" if any("reversal_rms_c10" in r for r in engine) else "5"
    setting_panel(axes[0][2], engine, "reversal_rms_c" + c, "RMS distance from start / diameter",
                  f"time reversal after {c} collisions per disk")
    cap = max([number(r["divergence_cap"]) for r in engine] + [0])
    setting_panel(axes[1][0], engine, "divergence_path_collisions", "collisions per disk",
                  f"runs one ulp apart: until a free path apart (↑: not by {cap:g})", log=False, cap=cap)
    stepped_panel(axes[1][1], stepped)
    log_panel(axes[1][2], log_rows)
    fig.suptitle("what accuracy costs in time (ede-bench accuracy)")
    style.save(fig, out)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(*sys.argv[1:])
