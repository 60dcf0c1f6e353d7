#!/usr/bin/env python3
"""Benchmark of the Python module against the C++ library in the same run (docs/python.md).

  state   the state of N disks at an arbitrary time into numpy (ede.open(p).state(t)) against the
          library's own Log::state_at for the same state (timed inside C++, no Python), both on a freshly
          opened log: medians of interleaved repeats, and their ratio (target: <= 1.5)
  events  every event of the log into a numpy structured array (log.events()), events per second
          (target: >= 1e7), and with positions and velocities before (the wide rows)
  memory  peak RSS of this process

usage: bench_python.py [--disks N] [--collisions C] [--repeat R] [--log PATH] [--keep]
The log is written by ede.run from examples/bench/gas-N1000000-phi0.5-periodic.toml with the number of
disks and the length overridden (default: 10^6 disks, 2 collisions per disk).
"""
import argparse
import os
import pathlib
import resource
import statistics
import sys
import tempfile
import time

import ede
from ede import _ede

ROOT = pathlib.Path(__file__).resolve().parents[2]


def median_time(f, repeat):
    out = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        out.append(time.perf_counter() - t0)
    return statistics.median(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--disks", type=int, default=1_000_000)
    ap.add_argument("--collisions", type=float, default=2.0)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--log", type=pathlib.Path)
    ap.add_argument("--keep", action="store_true", help="keep the log written")
    a = ap.parse_args()

    tmp = None
    path = a.log
    if path is None or not path.exists():
        if path is None:
            tmp = tempfile.TemporaryDirectory()
            path = pathlib.Path(tmp.name) / "bench.ede"
        scene = ROOT / "examples" / "bench" / "gas-N1000000-phi0.5-periodic.toml"
        t0 = time.perf_counter()
        s = ede.run(scene, log=path, progress=False,
                    set={"species[0].count": a.disks, "stop.collisions_per_particle": a.collisions})
        print("log: %s, %d disks, %d events, written in %.1f s" % (path, s["disks"], s["events"],
                                                                 time.perf_counter() - t0))
    log = ede.open(path)
    info = log.info
    t = info["start_time"] + 0.618 * (info["end_time"] - info["start_time"])  # an arbitrary time

    cpp, py = [], []
    for _ in range(a.repeat):  # interleaved: the machine's drift hits both alike
        cpp.append(_ede.Log._time_state_at(str(path), t, 1))
        fresh = ede.open(path)
        t0 = time.perf_counter()
        state = fresh.state(t)
        py.append(time.perf_counter() - t0)
        del state, fresh
    c, p = statistics.median(cpp), statistics.median(py)
    print()
    print("| measurement | value |")
    print("| --- | ---: |")
    print("| disks, logged events | %d, %d |" % (info["disks"], info["events"]))
    print("| state at t = %.6g: C++ Log::state_at (median of %d) | %.1f ms |" % (t, a.repeat, 1e3 * c))
    print("| state at t: Python log.state(t) into numpy | %.1f ms |" % (1e3 * p))
    print("| ratio Python / C++ (target <= 1.5) | %.2f |" % (p / c))
    n = info["events"]
    e = median_time(lambda: log.events(), a.repeat)
    w = median_time(lambda: log.events(positions=True, before=True), max(1, a.repeat // 2))
    ceiling = statistics.median(_ede._time_for_each_event(log._log) for _ in range(a.repeat))
    print("| C++ Log::for_each_event over every event, callback doing nothing | %.3g events/s |" % ceiling)
    print("| events into numpy, narrow rows (target >= 1e7/s) | %.3g events/s |" % (n / e))
    print("| events into numpy, with positions and velocities before | %.3g events/s |" % (n / w))
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print("| peak RSS of this process | %.0f MB (%.0f B/disk) |" % (rss / 1e6, rss / info["disks"]))
    if a.keep and tmp is not None:
        kept = pathlib.Path.cwd() / "bench.ede"
        os.replace(path, kept)
        print("kept", kept)


if __name__ == "__main__":
    sys.exit(main())
