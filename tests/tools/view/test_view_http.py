"""ede-view over plain HTTP (no browser): the page and its files are served, a log's frame is the exact
state of `ede-replay --at` (to float32, what the page draws), a live run runs and writes its log, and bad
requests get clean JSON errors with a 4xx status: path traversal, absolute paths, other extensions,
unknown logs, bad numbers, oversized bodies and URIs, a foreign Host header, malformed JSON.
"""
import json
import math
import os
import struct
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from viewlib import Server, check, make_log, replay_at, tools_dir  # noqa: E402


def parse_frame(raw):
    """(JSON header, {column name: tuple of values}) of a frame (tools/ede_view/frame.hpp); compact
    positions and radii are decoded to the box's units (q * scale), exact ones are the float64 sent."""
    assert raw[:4] == b"EDEF"
    (jlen,) = struct.unpack_from("<I", raw, 4)
    info = json.loads(raw[8:8 + jlen])
    (n,) = struct.unpack_from("<I", raw, 8 + jlen)
    at = 16 + jlen
    cols = {}
    for name, kind in info["columns"]:
        code, size = {"u8": ("B", 1), "u16": ("H", 2), "f32": ("f", 4), "f64": ("d", 8)}[kind]
        cols[name] = struct.unpack_from(f"<{n}{code}", raw, at)
        at += (n * size + 7) // 8 * 8
    check(at == len(raw), f"the frame's length is its header plus its {len(cols)} columns ({info['packing']})")
    if info["packing"] == "compact":
        sx, sy, sr = info["scale"]
        cols["x"] = tuple(q * sx for q in cols["x"])
        cols["y"] = tuple(q * sy for q in cols["y"])
        cols["r"] = tuple(q * sr for q in cols["r"]) if "r" in cols else (info["radius"],) * n
    return info, cols


def command_line():
    view = os.path.join(tools_dir(), "ede-view")
    run = lambda *args: subprocess.run([view, *args], capture_output=True, text=True, timeout=60)  # noqa: E731
    r = run("--logs", "/no/such/folder", "--port", "0")
    check(r.returncode == 1 and "--logs /no/such/folder: not a folder" in r.stderr, "a missing --logs folder: exit 1, named")
    r = run("--port", "70000")
    check(r.returncode == 2, "a port out of range: exit 2 (a bad command line)")
    r = run("--help")
    check(r.returncode == 0 and "--logs" in r.stdout, "--help")


def main():
    command_line()
    server = Server()
    taken = subprocess.run([os.path.join(tools_dir(), "ede-view"), "--port", server.url.rsplit(":", 1)[1],
                            "--out-dir", os.path.join(server.dir, "runs")], capture_output=True, text=True, timeout=60)
    check(taken.returncode == 1 and "cannot listen" in taken.stderr, "a port in use: exit 1, says so")
    try:
        log = os.path.join(server.logs, "gas.ede")
        make_log(log, sets=["species[0].count=400", "log.keyframe_interval=2000"])
        status, body, ctype = server.get("/")
        check(status == 200 and b"<canvas" in body and ctype.startswith("text/html"), "GET / serves the page")
        check(server.get("/view.js")[0] == 200, "GET /view.js serves the script")
        status, answer = server.json("/api/logs")
        check(status == 200 and answer["logs"] == ["0:gas.ede"], "the log folder's logs are listed")
        status, info = server.json("/api/log/info?name=0:gas.ede")
        check(status == 200 and info["disks"] == 400 and info["keyframes"] > 2, "a log's summary (several keyframes)")

        # Exact frames (?exact=1) are the states of ede-replay --at, seeking through keyframes, to the bit.
        for t in ["0", "0.0123456789", str(info["end"] / 2), "end"]:
            status, raw, ctype = server.get(f"/api/log/frame?name=0:gas.ede&t={t}&exact=1")
            check(status == 200 and ctype == "application/octet-stream", f"frame at t = {t}")
            finfo, cols = parse_frame(raw)
            rows = replay_at(log, t)
            check(finfo["sent"] == len(rows) == 400, f"t = {t}: every disk sent")
            same = all(float(row["x"]) == cols["x"][i] and float(row["y"]) == cols["y"][i] and
                       float(row["radius"]) == cols["r"][i] for i, row in enumerate(rows))
            check(same, f"t = {t}: exact frames: positions and radii equal ede-replay --at {t} (float64, to the bit)")
        # Compact frames (the default): 16-bit positions within half a step (box / 65535) of the exact
        # ones, one colour byte: the speed class of ede-replay's velocities, or the species.
        t = str(info["end"] / 3)
        rows = replay_at(log, t)
        status, raw, _ = server.get(f"/api/log/frame?name=0:gas.ede&t={t}")
        finfo, cols = parse_frame(raw)
        half = 0.5 * finfo["lx"] / 65535 * (1 + 1e-9)
        err = max(max(abs(float(row["x"]) - cols["x"][i]), abs(float(row["y"]) - cols["y"][i])) for i, row in enumerate(rows))
        check(finfo["packing"] == "compact" and [c[0] for c in finfo["columns"]] == ["x", "y", "colour"] and
              err <= half, f"compact frame: x, y within half a step of ede-replay --at (largest {err:.2e} <= {half:.2e}),"
                           f" the radius once (all equal: {finfo['radius']})")
        check(len(raw) <= 16 + len(raw[8:8 + struct.unpack_from('<I', raw, 4)[0]]) + 5 * 400 + 24,
              f"compact frame: 5 bytes a disk plus the JSON ({len(raw)} bytes for 400 disks)")
        lo, hi = finfo["class_speeds"]
        speeds = [math.hypot(float(row["vx"]), float(row["vy"])) for row in rows]
        want = [0 if v < lo else 2 if v > hi else 1 for v in speeds]
        check(list(cols["colour"]) == want and sorted(set(want)) == [0, 1, 2],
              f"colour=speed (default): the byte is the speed class of each disk's velocity in ede-replay --at")
        status, raw, _ = server.get(f"/api/log/frame?name=0:gas.ede&t={t}&colour=species")
        finfo, cols = parse_frame(raw)
        check(list(cols["colour"]) == [finfo["species_names"].index(row["species"]) for row in rows],
              "colour=species: the byte is the species")
        status, raw, _ = server.get(f"/api/log/frame?name=0:gas.ede&t={t}&colour=displacement&exact=1")
        finfo, cols = parse_frame(raw)
        start = replay_at(log, "0")
        disp = [math.hypot(float(a["x"]) - float(b["x"]), float(a["y"]) - float(b["y"])) for a, b in zip(rows, start)]
        check(abs(finfo["colour"]["displacement_max"] - max(disp)) <= 1e-12 and
              all(abs(c - 255 * d / max(disp)) <= 0.5 + 1e-9 for c, d in zip(cols["colour"], disp)),
              "colour=displacement: the byte is the displacement from t = 0 in 255ths of the largest")
        status, raw, _ = server.get("/api/log/frame?name=0:gas.ede&t=0.3&max=100")
        finfo, cols = parse_frame(raw)
        check(finfo["stride"] == 4 and finfo["sent"] == 100 and finfo["disks"] == 400,
              "above ?max= disks every k-th is sent, the monitors still count all")

        # Bad requests: clean JSON errors.
        def error(path, want, **kw):
            status, raw, ctype = server.get(path, **kw)
            ok = status == want and ctype.startswith("application/json") and "error" in json.loads(raw)
            check(ok, f"{path[:60]} -> {want} with a JSON error (got {status}: {raw[:120]!r})")

        error("/api/log/info?name=0:../../../../etc/passwd", 403)
        error("/api/log/info?name=0:..%2f..%2f..%2fetc%2fpasswd", 403)
        error("/api/log/info?name=/etc/passwd", 403)
        error("/api/log/info?name=0:gas.toml", 403)
        error("/api/log/info?name=0:nope.ede", 404)
        error("/api/log/info?name=7:gas.ede", 404)
        error("/api/log/info", 400)
        error("/api/log/frame?name=0:gas.ede&t=abc", 400)
        error("/api/log/frame?name=0:gas.ede&t=1e300", 400)
        error("/api/log/frame?name=0:gas.ede", 400)
        error("/api/log/frame?name=0:gas.ede&t=0&colour=rainbow", 400)
        error("/api/log/frame?name=0:gas.ede&t=0&exact=yes", 400)
        error("/api/scene?name=0:../../../etc/passwd", 403)
        error("/api/no-such-thing", 404)
        error("/" + "a" * 9000, 414)
        error("/api/logs", 403, headers={"Host": "attacker.example:80"})
        error("/api/run/frame", 404)
        error("/api/run/setup", 413, data=b"{" + b" " * 100000 + b"}", method="POST")
        error("/api/run/setup", 400, data=b"not json", method="POST")
        # A file that is not a log, under the logs folder: refused by the reader, named.
        with open(os.path.join(server.logs, "fake.ede"), "wb") as f:
            f.write(b"not a log at all")
        error("/api/log/info?name=0:fake.ede", 422)
        # A symlink out of the folder is outside it.
        os.symlink("/etc", os.path.join(server.logs, "out"))
        error("/api/log/info?name=0:out/passwd.ede", 403)

        # Live: SETUP, GO at full speed, the run ends at its time and its log reads.
        status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=300"], "until": 2})
        check(status == 200 and st["status"] == "paused" and st["disks"] == 300, "SETUP makes a paused run")
        status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].nope=1"]})
        check(status == 400 and "nope" in st["error"], "a bad override is refused with the scene's message")
        status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=300"], "until": 2})
        server.post("/api/run/pace?pace=0")
        status, st = server.post("/api/run/go")
        check(status == 200, "GO")
        for _ in range(300):
            status, st = server.json("/api/run/status")
            if st["status"].startswith("ended"):
                break
            time.sleep(0.1)
        check(st["status"] == "ended: reached stop.time" and st["time"] == 2.0, "the run reaches its time: " + st["status"])
        status, logs = server.json("/api/logs")
        live = [name for name in logs["logs"] if "live-" in name]
        check(len(live) == 1, "the live run's log is listed with the logs: " + str(live))
        status, info = server.json("/api/log/info?name=" + live[0])
        check(status == 200 and info["complete"] and info["disks"] == 300, "the live run's log is complete and reads")
        status, st = server.post("/api/run/go")
        check(status == 409 and "SETUP" in st["error"], "GO after the end says to press SETUP")

        # FINISH: a run stopped early gets a complete log that verifies and ends at the exact state it
        # showed; its frames' impulse sums give the walls' pressure of ede-stats pressure on that log.
        server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=300"], "until": 1000})
        server.post("/api/run/pace?pace=0")

        def paused_frame():
            server.post("/api/run/pause")
            for _ in range(100):
                _, st = server.json("/api/run/status")
                if st["status"] == "paused":
                    break
                time.sleep(0.05)
            time.sleep(0.3)  # the worker publishes the state it paused at
            status, raw, _ = server.get("/api/run/frame?exact=1")
            return parse_frame(raw)

        server.post("/api/run/go")
        time.sleep(0.5)
        a, _ = paused_frame()
        server.post("/api/run/go")
        time.sleep(0.5)
        b, cols = paused_frame()
        check(b["time"] > a["time"] > 0 and b["impulses"]["time"] == b["time"],
              f"the frames carry the run's impulse sums (t = {a['time']:.3f}, {b['time']:.3f})")
        status, st = server.post("/api/run/finish")
        check(status == 200, "FINISH")
        for _ in range(100):
            _, st = server.json("/api/run/status")
            if st["status"].startswith("ended"):
                break
            time.sleep(0.05)
        check(st["status"].startswith("ended: finished here") and st["time"] == b["time"],
              f"FINISH ends the run where it was paused: {st['status']}")
        live_log = st["log_path"]
        _, info = server.json("/api/log/info?name=1:" + st["log"])
        check(info["complete"], "the finished run's log is complete")
        r = subprocess.run([os.path.join(tools_dir(), "ede-replay"), "verify", live_log], capture_output=True, text=True)
        check(r.returncode == 0 and "verified" in r.stdout and "incomplete" not in r.stdout,
              "ede-replay verify passes on the finished run's log: " + r.stdout.strip()[:200])
        end_rows = replay_at(live_log, "end")
        check(len(end_rows) == 300 and all(float(row["x"]) == cols["x"][i] and float(row["y"]) == cols["y"][i]
                                           for i, row in enumerate(end_rows)),
              "the log ends at exactly the state the page was shown at FINISH")
        # Pressure: the page's formula on the two frames' sums, against ede-stats pressure --from a --to b.
        dt = b["time"] - a["time"]
        page_p = (sum(b["impulses"]["wall"]) - sum(a["impulses"]["wall"])) / (2 * (b["lx"] + b["ly"]) * dt)
        csv = os.path.join(server.dir, "pressure.csv")
        r = subprocess.run([os.path.join(tools_dir(), "ede-stats"), "pressure", live_log, "--from", repr(a["time"]),
                            "--to", repr(b["time"]), "--blocks", "4", "-o", csv], capture_output=True, text=True)
        check(r.returncode == 0, "ede-stats pressure reads the finished live log: " + r.stderr[-300:])
        import csv as csvlib
        rows = list(csvlib.DictReader(open(csv)))
        stats_p = sum(float(row["P_wall"]) for row in rows) / len(rows)
        check(abs(page_p - stats_p) <= 1e-9 * abs(stats_p),
              f"the live wall pressure over [{a['time']:.4f}, {b['time']:.4f}] is ede-stats pressure's: {page_p:.9g} vs {stats_p:.9g}")

        # Two tabs watch one run at a pace; then reverse time: the elastic gas comes back to its start.
        server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=300"], "until": 50})
        server.post("/api/run/pace?pace=0.5")
        server.post("/api/run/go")
        seen = {0: [], 1: []}

        def watch(tab):
            for _ in range(8):
                status, raw, _ = server.get("/api/run/frame")
                seen[tab].append(parse_frame(raw)[0]["time"] if status == 200 else -1)
                time.sleep(0.05)

        tabs = [threading.Thread(target=watch, args=(k,)) for k in (0, 1)]
        for t in tabs:
            t.start()
        for t in tabs:
            t.join()
        check(all(seen[k] == sorted(seen[k]) and seen[k][-1] > seen[k][0] >= 0 for k in (0, 1)),
              f"two tabs watch the same run, each sees time advance: {seen[0][-1]:.3f}, {seen[1][-1]:.3f}")
        for _ in range(100):
            _, st = server.json("/api/run/status")
            if st["time"] >= 0.2:
                break
            time.sleep(0.05)
        server.post("/api/run/reverse")
        server.post("/api/run/pace?pace=0")  # then at full speed to its end (t = 50): a complete log
        for _ in range(300):
            _, st = server.json("/api/run/status")
            if st["status"].startswith("ended"):
                break
            time.sleep(0.1)
        check(st["status"] == "ended: reached stop.time" and len(st["reversals"]) == 1,
              f"the reversed run goes on to its end: {st['status']}, reversed at {st['reversals']}")
        t_r = st["reversals"][0]
        log_name = "1:" + st["log"]
        status, raw, _ = server.get(f"/api/log/frame?name={log_name}&t={2 * t_r!r}&exact=1")
        check(status == 200, f"the reversed run's log reads at twice the reversal time: {status} {raw[:300]!r}")
        back = parse_frame(raw)[1]
        start = parse_frame(server.get(f"/api/log/frame?name={log_name}&t=0&exact=1")[1])[1]
        err = max(max(abs(back["x"][i] - start["x"][i]), abs(back["y"][i] - start["y"][i])) for i in range(300))
        check(err < 1e-5, f"reverse time: at 2 t_r every disk is back where it started (largest error {err:.1e} < 1e-5)")
    finally:
        code = server.close()
    check(code in (0, 143), f"ede-view stops on SIGTERM (exit {code})")


if __name__ == "__main__":
    main()
