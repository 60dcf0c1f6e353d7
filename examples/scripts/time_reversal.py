#!/usr/bin/env python3
"""Time reversal: how far a gas comes back to its start, against the time before the reversal.

For each T, runs examples/time-reversal.toml forward to T, reverses every velocity, runs to 2T; reads the
states at t = 0 and t = 2T from the log (ede-replay --at) and measures the RMS distance between them (the
walls box has no periodic images). The error grows exponentially with the collisions per disk before the
reversal: round-off amplified by chaos. The scalar type can be compared: --set engine.scalar=float etc.

usage: time_reversal.py TOOLS_DIR OUT_DIR
"""
import csv
from decimal import Decimal
import io
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "plot"))
import ede_style  # noqa: E402

SCALARS = [("float", "float"), ("double", "double"), ("long double", '"long double"')]


def state(tools, log, at):
    # Decimal keeps every digit of the CSV (21 for long double): differences below a double's resolution
    # would otherwise read as 0.
    text = subprocess.run([os.path.join(tools, "ede-replay"), log, "--at", at],
                          check=True, capture_output=True, text=True).stdout
    return [(Decimal(r["x"]), Decimal(r["y"])) for r in csv.DictReader(io.StringIO(text))]


def run(tools, out, t, scalar):
    scene = os.path.join(os.path.dirname(__file__), "..", "time-reversal.toml")
    log = os.path.join(out, "time-reversal.ede")
    summary = subprocess.run([os.path.join(tools, "ede-sim"), scene, "-q", "--json", "-o", log,
                              "--set", f"actions[0].time={t!r}", "--set", f"stop.time={2 * t!r}",
                              "--set", f"engine.scalar={scalar}"],
                             check=True, capture_output=True, text=True).stdout
    pairs = json.loads(summary)["events_by_kind"]["pair"]
    start, end = state(tools, log, "0"), state(tools, log, "end")
    rms = math.sqrt(float(sum((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 for a, b in zip(start, end)) / len(start)))
    os.remove(log)
    return pairs / 2 * 2 / len(start), rms  # collisions per disk before the reversal (half the run), distance


def main():
    tools, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    times = [0.02 * 1.5 ** k for k in range(12)]
    fig, ax = ede_style.figure()
    with open(os.path.join(out, "time-reversal.csv"), "w") as f:
        f.write("scalar,T,collisions_per_disk_before_reversal,rms_return_distance\n")
        for k, (name, value) in enumerate(SCALARS):
            points = [run(tools, out, t, value) for t in times]
            for t, (c, d) in zip(times, points):
                f.write(f"{name},{t!r},{c!r},{d!r}\n")
            shown = [(c, d) for c, d in points if d > 0]  # 0: came back exactly, nothing to draw on a log scale
            ax.semilogy([c for c, _ in shown], [d for _, d in shown], "o-", color=ede_style.COLOURS[k], label=name)
    ax.axhline(0.01, **ede_style.THEORY, label="disk radius (no longer comes back)")
    ax.set_xlabel("collisions per disk before the reversal")
    ax.set_ylabel("RMS distance from the start after returning [L]")
    ax.set_title("time reversal: round-off amplified by chaos (500 disks, walls)")
    ax.legend()
    ede_style.save(fig, os.path.join(out, "time-reversal.png"))
    print("time reversal: figure with float, double and long double")


if __name__ == "__main__":
    main()
