"""ede-view's "reverse time" on scenes that schedule their own actions, by time and by collisions per disk.

A live reversal is one more reverse_velocities action in the run's scene, in the scene's own schedule:
by collisions per disk (examples/schedules/reverse-after-collisions.toml) it fires right after the latest
pair collision P before the press, at that collision's time t_P. The test reverses both kinds of scene
while they run, lets them run to their end, and checks that the log holds the reversal as an action event
right after pair collision P (by collisions), that `ede-replay verify` passes, that at 2 t_P every disk is
back where it started (within 1e-5, as the plain gas's test in test_view_http.py: round-off amplified by
a few collisions per disk of chaos stays far below), and that the scene's own action still fires. A
reversal that cannot be scheduled (a paused run at t = 0, or before any pair collision) is refused with a
409 that says why, and the run is left as it was. Before this fix the collision-scheduled scene could not
even be set up (its sampling was refused) and its reversal became time = 0 actions the loader refused.
"""
import csv
import io
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from test_view_http import parse_frame  # noqa: E402
from viewlib import Server, check, tools_dir  # noqa: E402


def wait_status(server, predicate, seconds=60):
    end = time.time() + seconds
    while time.time() < end:
        _, st = server.json("/api/run/status")
        if predicate(st):
            return st
        time.sleep(0.05)
    return st


def actions_and_pairs(log):
    """The log's action events as (time, pair collisions before them), from ede-replay events."""
    out = subprocess.run([os.path.join(tools_dir(), "ede-replay"), "events", log], check=True,
                         capture_output=True, text=True).stdout
    pairs, found, previous = 0, [], None
    for row in csv.DictReader(io.StringIO(out)):
        if row["kind"] == "action":
            found.append((float(row["time"]), pairs, previous))
        previous = row["kind"]
        pairs += row["kind"] == "pair"
    return found


def reverse_live(server, scene, until, press_at):
    """SETUP, GO at a pace, reverse at >= press_at, then full speed to `until`; the final status."""
    status, st = server.json("/api/run/setup", {"scene": "0:" + scene, "until": until})
    check(status == 200, f"{scene}: SETUP ({st.get('error', st.get('status'))})")
    status, st = server.post("/api/run/reverse")
    check(status == 409 and "reverse time" in st["error"] and "GO" in st["error"],
          f"{scene}: reverse at t = 0 (paused) is refused, saying why: {st.get('error')}")
    _, st = server.json("/api/run/status")
    check(st["status"] == "paused" and st["reversals"] == [], f"{scene}: ... and the run is left as it was")
    server.post("/api/run/pace?pace=0.2")
    server.post("/api/run/go")
    wait_status(server, lambda st: st["time"] >= press_at)
    server.post("/api/run/reverse")
    server.post("/api/run/pace?pace=0")
    st = wait_status(server, lambda st: st["status"].startswith("ended"), 120)
    check(st["status"] == "ended: reached stop.time" and len(st["reversals"]) == 1 and not st["message"],
          f"{scene}: the reversed run goes on to its end: {st['status']} {st['message']!r}, reversed at "
          f"{st['reversals']} (pairs {st['reversal_pairs']})")
    r = subprocess.run([os.path.join(tools_dir(), "ede-replay"), "verify", st["log_path"]], capture_output=True, text=True)
    check(r.returncode == 0 and "verified" in r.stdout, f"{scene}: ede-replay verify passes: {r.stdout.strip()[:160]}")
    return st


def back_at_start(server, st, t_back, label):
    name = "1:" + st["log"]
    start = parse_frame(server.get(f"/api/log/frame?name={name}&t=0&exact=1")[1])[1]
    status, raw, _ = server.get(f"/api/log/frame?name={name}&t={t_back!r}&exact=1")
    check(status == 200, f"{label}: the log reads at 2 t_P = {t_back!r}")
    back = parse_frame(raw)[1]
    err = max(max(abs(back["x"][i] - start["x"][i]), abs(back["y"][i] - start["y"][i])) for i in range(len(start["x"])))
    check(err < 1e-5, f"{label}: at twice the reversal's time every disk is back at its start (largest error {err:.1e} < 1e-5)")


def main():
    server = Server()
    try:
        # By collisions per disk: the scene reverses itself at 10 collisions per disk (pair 2500, t ~ 0.32);
        # the live reversal comes first (t ~ 0.05, ~1.5 per disk), so that the gas is back at its start (pair
        # ~2P, t = 2 t_P) before the scene reverses it again.
        scene = "schedules/reverse-after-collisions.toml"
        st = reverse_live(server, scene, until=0.8, press_at=0.05)
        p = st["reversal_pairs"][0]
        actions = actions_and_pairs(st["log_path"])
        check(len(actions) == 2, f"{scene}: the log holds two actions, the live one and the scene's own: {actions}")
        t_p, pairs_before, previous = actions[0]
        check(pairs_before == p and previous == "pair" and t_p <= st["reversals"][0],
              f"{scene}: the live reversal is right after pair collision {p} (the latest before the press), "
              f"at its time {t_p!r} <= {st['reversals'][0]!r}")
        check(actions[1][1] >= 2500, f"{scene}: the scene's own reversal fires after pair collision 2500 "
              f"(at {actions[1][1]}, t = {actions[1][0]:.4f})")
        back_at_start(server, st, 2 * t_p, scene)

        # By time: examples/time-reversal.toml reverses itself at t = 0.5; the live reversal at ~0.05.
        scene = "time-reversal.toml"
        st = reverse_live(server, scene, until=0.7, press_at=0.05)
        actions = actions_and_pairs(st["log_path"])
        check(len(actions) == 2 and actions[0][0] == st["reversals"][0] and actions[1][0] == 0.5,
              f"{scene}: the log holds the live reversal at its time and the scene's at 0.5: {actions}")
        back_at_start(server, st, 2 * st["reversals"][0], scene)

        # Before any pair collision a collision-scheduled reversal cannot be placed: refused, run unchanged.
        server.json("/api/run/setup", {"scene": "0:schedules/reverse-after-collisions.toml", "until": 1})
        server.post("/api/run/pace?pace=0.0001")
        server.post("/api/run/go")
        time.sleep(0.3)
        server.post("/api/run/pause")
        st = wait_status(server, lambda st: st["status"] == "paused")
        time.sleep(0.3)
        _, raw, _ = server.get("/api/run/frame")
        info = parse_frame(raw)[0]
        if info["collisions_per_disk"] == 0 and info["time"] > 0:
            status, answer = server.post("/api/run/reverse")
            check(status == 409 and "none yet" in answer["error"],
                  f"before any pair collision (t = {info['time']:.2g}) reverse is refused: {answer.get('error')}")
        else:
            print(f"note: the slow run had a pair collision already (t = {info['time']:.2g}): that check skipped")
    finally:
        code = server.close()
    check(code in (0, 143), f"ede-view stops on SIGTERM (exit {code})")


if __name__ == "__main__":
    main()
