#!/usr/bin/python3
"""ede-view's benchmark: frames per second it serves and the page draws, and seek times in a large log.

  scripts/bench_view.py [--build build] [--seconds 5] [--events 10000000 (0: no seeks)] [--sizes 10000,100000,1000000]

1. Live runs of examples/bench/gas-N{10^4,10^5,10^6}-phi0.3-walls.toml at full engine speed: frames
   fetched back to back over HTTP for --seconds (what one tab polling as fast as it can gets), their size,
   and the engine's events/s while watched against while nobody watches (the worker copies a state only
   when a page asked for one, so watching should cost the engine little).
2. The same scenes in headless chromium (if installed), once per drawing path (?draw=2d: the 2D canvas's
   pixel path; ?draw=webgl: gl_draw.js; the page's default picks one of them, said in the table): frames
   the page draws per second (fetch, parse, draw, histograms), the median of the rates of each second of
   the window, the median time of the page's own drawing code per frame (edeView.drawMs), and the
   engine's rate meanwhile (what watching in a browser costs it).
3. Seeks: a log of --events events at N = 10^4, frames at 50 random times (median and worst, HTTP
   included, each a fresh keyframe seek + replay).
Prints a markdown table (docs/view.md holds one, measured under load on the project's shared machine).
Rejected: an ede-bench subcommand (ede-bench links the library's internals; this measures the server and
the browser from outside, as a user meets them).
"""
import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../tests/tools/view"))
import viewlib  # noqa: E402


def wait_running(server, seconds=120):
    """Until the engine has processed events (10^6 disks take seconds to place and predict under load)."""
    end = time.time() + seconds
    while time.time() < end:
        _, st = server.json("/api/run/status")
        if st["events"] > 0 and st["events_per_second"] > 0:
            return
        time.sleep(0.2)


def live(server, scene, seconds):
    server.json("/api/run/setup", {"scene": "0:" + scene, "until": 1e6})
    server.post("/api/run/pace?pace=0")
    server.post("/api/run/go")
    wait_running(server)
    time.sleep(1.0)
    _, st = server.json("/api/run/status")
    ev_unwatched = st["events_per_second"]
    n, size, start = 0, 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        _, raw, _ = server.get("/api/run/frame")
        n += 1
        size += len(raw)
    elapsed = time.perf_counter() - start
    _, st = server.json("/api/run/status")
    server.post("/api/run/pause")
    return n / elapsed, size / n, ev_unwatched, st["events_per_second"]


def browser_fps(server, scene, seconds, draw):
    """(median frames/s over 1-s windows, median drawMs, drawer used, renderer, the engine's median M events/s
    meanwhile) or None without chromium."""
    try:
        browser = viewlib.Browser()
    except SystemExit:
        return None
    try:
        browser.goto(server.url + "/?draw=" + draw)
        browser.eval(f"document.getElementById('scene').value = '0:{scene}'")
        browser.eval("document.getElementById('scene').dispatchEvent(new Event('change'))")
        time.sleep(0.5)
        browser.eval("document.getElementById('setup').click()")
        browser.wait("edeView.last && edeView.last.info.status === 'paused'", 120)
        browser.eval("document.getElementById('fastest').click()")
        browser.eval("document.getElementById('go').click()")
        wait_running(server)
        time.sleep(1.0)
        rates, draw_ms, engine = [], [], []
        f0, t0 = browser.eval("edeView.frames"), time.perf_counter()
        end = t0 + seconds
        while time.perf_counter() < end:
            time.sleep(1.0)
            f1, t1 = browser.eval("edeView.frames"), time.perf_counter()
            rates.append((f1 - f0) / (t1 - t0))
            draw_ms.append(browser.eval("edeView.drawMs"))
            engine.append(server.json("/api/run/status")[1]["events_per_second"] / 1e6)
            f0, t0 = f1, t1
        drawer = browser.eval("edeView.drawer")
        renderer = browser.eval("edeView.renderer")
        browser.eval("document.getElementById('go').click()")
        return statistics.median(rates), statistics.median(draw_ms), drawer, renderer, statistics.median(engine)
    finally:
        browser.close()


def default_drawer(server, scene):
    """The path the page picks by itself for this scene (its first frame after SETUP)."""
    try:
        browser = viewlib.Browser()
    except SystemExit:
        return None
    try:
        browser.goto(server.url + "/")
        browser.eval(f"document.getElementById('scene').value = '0:{scene}'")
        browser.eval("document.getElementById('scene').dispatchEvent(new Event('change'))")
        time.sleep(0.5)
        browser.eval("document.getElementById('setup').click()")
        browser.wait("edeView.last && edeView.last.info.status === 'paused'", 120)
        return browser.eval("edeView.drawer")
    finally:
        browser.close()


def seeks(server, name, end, count=50):
    rng = random.Random(1)
    times = []
    for _ in range(count):
        t = repr(rng.uniform(0, end))
        start = time.perf_counter()
        status, _, _ = server.get(f"/api/log/frame?name={name}&t={t}")
        times.append(time.perf_counter() - start)
        assert status == 200
    return statistics.median(times), max(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(HERE, "../build"))
    ap.add_argument("--seconds", type=float, default=5)
    ap.add_argument("--events", type=int, default=10_000_000)
    ap.add_argument("--sizes", default="10000,100000,1000000")
    a = ap.parse_args()
    os.environ["EDE_TOOLS_DIR"] = os.path.join(os.path.abspath(a.build), "tools")
    os.environ.setdefault("EDE_SOURCE_DIR", os.path.abspath(os.path.join(HERE, "..")))
    server = viewlib.Server()
    rows = []
    try:
        for n in (int(x) for x in a.sizes.split(",")):
            scene = f"bench/gas-N{n}-phi0.3-walls.toml"
            fps, size, ev0, ev1 = live(server, scene, a.seconds)
            pages = {draw: browser_fps(server, scene, a.seconds, draw) for draw in ("2d", "webgl")}
            rows.append((n, fps, size / 1e6, ev0 / 1e6, ev1 / 1e6, pages, default_drawer(server, scene)))
        if a.events > 0:
            log = os.path.join(server.logs, "large.ede")
            start = time.perf_counter()
            viewlib.make_log(log, "examples/bench/gas-N10000-phi0.3-walls.toml", [f"stop.events={a.events}"])
            made = time.perf_counter() - start
            _, info = server.json("/api/log/info?name=0:large.ede")
            med, worst = seeks(server, "0:large.ede", info["end"])
    finally:
        server.close()
    print("| disks | frames/s served (HTTP, back to back) | MB/frame | engine M events/s unwatched | watched |"
          " page frames/s, 2D path (draw ms; engine M events/s meanwhile) | page frames/s, WebGL (the same) |"
          " the page's default |")
    print("|---:|---:|---:|---:|---:|---:|---:|---|")
    renderer = "-"
    for n, fps, mb, ev0, ev1, pages, default in rows:
        cells = []
        for draw in ("2d", "webgl"):
            p = pages[draw]
            cells.append("-" if p is None else f"{p[0]:.0f} ({p[1]:.1f}; {p[2]}; engine {p[4]:.2f})")
            if p is not None and draw == "webgl":
                renderer = p[3]
        print(f"| {n} | {fps:.0f} | {mb:.2f} | {ev0:.2f} | {ev1:.2f} | {cells[0]} | {cells[1]} | {default} |")
    print()
    print(f"WebGL renderer: {renderer}")
    if a.events <= 0:
        return
    print()
    print(f"Seeks in a log of {info['events']} events, N = {info['disks']} (written in {made:.0f} s, "
          f"{info['keyframes']} keyframes): frame at a random time, HTTP included: median {med * 1e3:.0f} ms, "
          f"worst {worst * 1e3:.0f} ms (50 times).")


if __name__ == "__main__":
    main()
