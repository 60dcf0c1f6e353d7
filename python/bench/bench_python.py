#!/usr/bin/env python3
"""Benchmark of the Python module against the C++ library in the same run (docs/python.md).

  state   the state of N disks at an arbitrary time into numpy (ede.open(p).state(t)) against the
          library's own Log::state_at for the same state (timed inside C++, no Python), both on a freshly
          opened log: medians of interleaved repeats, and their ratio (target: <= 1.5)
  events  every event of a log into a numpy structured array (log.events()), events per second
          (target: >= 1e7): narrow rows, wide rows (positions and velocities before), and window by window
          into one reused array (out=); on the N-disk log above and on a long log of --events-disks disks
          (default 10^4, 2e6 events), where the walk, not loading the first keyframe, is what is timed
  memory  peak RSS of this process

usage: bench_python.py [--disks N] [--collisions C] [--events-disks M] [--repeat R] [--log PATH] [--keep]
The logs are written by ede.run from examples/bench/gas-N1000000-phi0.5-periodic.toml with the number of
disks and the length overridden (default: 10^6 disks, 2 collisions per disk; 10^4 disks, 400 per disk: 2e6 events).
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


def write_log(path, disks, collisions):
    scene = ROOT / "examples" / "bench" / "gas-N1000000-phi0.5-periodic.toml"
    t0 = time.perf_counter()
    s = ede.run(scene, log=path, progress=False,
                set={"species[0].count": disks, "stop.collisions_per_particle": collisions})
    print("log: %s, %d disks, %d events, written in %.1f s" % (path, s["disks"], s["events"],
                                                             time.perf_counter() - t0))


def event_rates(log, repeat):
    """Events per second: whole log narrow, wide, and in windows of 2^20 rows into one reused array."""
    n = log.info["events"]
    window = 1 << 20
    buf = log.events(first=0, last=window)

    def windows():
        for first in range(0, n, window):
            log.events(first=first, last=first + window, out=buf)

    narrow = n / median_time(lambda: log.events(), repeat)
    wide = n / median_time(lambda: log.events(positions=True, before=True), max(1, repeat // 2))
    reused = n / median_time(windows, repeat)
    return narrow, wide, reused


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--disks", type=int, default=1_000_000)
    ap.add_argument("--collisions", type=float, default=2.0)
    ap.add_argument("--events-disks", type=int, default=10_000)
    ap.add_argument("--events-collisions", type=float, default=400.0)
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
        write_log(path, a.disks, a.collisions)
    log = ede.open(path)
    info = log.info
    long_tmp = tempfile.TemporaryDirectory()
    long_path = pathlib.Path(long_tmp.name) / "events.ede"
    write_log(long_path, a.events_disks, a.events_collisions)
    long_log = ede.open(long_path)
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
    for name, lg in (("%d disks, %d events" % (info["disks"], info["events"]), log),
                     ("%d disks, %d events" % (long_log.info["disks"], long_log.info["events"]), long_log)):
        ceiling = statistics.median(_ede._time_for_each_event(lg._log) for _ in range(a.repeat))
        narrow, wide, reused = event_rates(lg, a.repeat)
        print("| %s: C++ Log::for_each_event, callback doing nothing (one thread) | %.3g events/s |" % (name, ceiling))
        print("| %s: events into numpy, narrow rows (target >= 1e7/s) | %.3g events/s |" % (name, narrow))
        print("| %s: the same in windows of 2^20 rows into one reused array (out=) | %.3g events/s |" % (name, reused))
        print("| %s: events with positions and velocities before | %.3g events/s |" % (name, wide))
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print("| peak RSS of this process | %.0f MB (%.0f B/disk) |" % (rss / 1e6, rss / info["disks"]))
    if a.keep and tmp is not None:
        kept = pathlib.Path.cwd() / "bench.ede"
        os.replace(path, kept)
        print("kept", kept)


if __name__ == "__main__":
    sys.exit(main())
