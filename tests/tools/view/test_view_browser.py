"""ede-view in a real headless browser (Debian's chromium over the DevTools protocol): SETUP and GO
animate the disks (the canvas's pixels change between screenshots), the speed histogram converges to 2D
Maxwell-Boltzmann, scrubbing a log shows exactly the state `ede-replay --at` prints (the page reports the
positions it drew in window.edeView.last), and bad requests show clean errors. Skipped (exit 77) without
chromium or under sanitizers.

With EDE_VIEW_SCREENSHOTS=DIR it also saves the page's screenshots there (docs/img/view-*.png are made so).

Tolerance of the Maxwell-Boltzmann check: the total-variation distance between the histogram of N = 2000
speeds (40 bins) and the law at the measured kT is ~0.06 from sampling noise alone for an equilibrium gas;
the test asks < 0.15 after 20 collisions per disk, and > 0.8 at the start (every disk at speed 1).
"""
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(__file__))
from viewlib import Browser, Server, check, chromium_or_skip, make_log, replay_at  # noqa: E402


def tv_distance(info):
    """Total variation between the page's speed histogram and 2D MB at the page's kT (one mass)."""
    h, kT, m = info["speed_hist"], info["kT"], info["mass"]
    counts = h["counts"]
    n = sum(counts) + h["outside"]
    width = (h["hi"] - h["lo"]) / len(counts)
    cdf = lambda v: 1 - math.exp(-m * v * v / (2 * kT))  # noqa: E731
    inside = sum(abs(c / n - (cdf((k + 1) * width) - cdf(k * width))) for k, c in enumerate(counts))
    return 0.5 * (inside + abs(h["outside"] / n - (1 - cdf(h["hi"]))))


def main():
    chromium_or_skip()
    shots = os.environ.get("EDE_VIEW_SCREENSHOTS")
    server = Server()
    browser = None
    try:
        log = os.path.join(server.logs, "gas.ede")
        make_log(log, sets=["species[0].count=600", "log.keyframe_interval=3000"])
        browser = Browser()
        browser.goto(server.url + "/")
        check(browser.eval("document.getElementById('scene').value") == "0:gas.toml", "the page lists the scenes, gas.toml chosen")

        # SETUP shows the initial state; GO animates it.
        browser.eval("document.getElementById('setup').click()")
        browser.wait("edeView.last && edeView.last.info.status === 'paused'", 20)
        check(browser.eval("edeView.last.n") == 2000, "SETUP draws the scene's 2000 disks")
        before = browser.screenshot("#disks")
        tv0 = tv_distance(browser.eval("edeView.last.info"))
        check(tv0 > 0.8, f"at the start every disk has speed 1: far from MB (TV distance {tv0:.3f})")
        browser.eval("document.getElementById('go').click()")
        browser.wait("edeView.last.info.status === 'running' && edeView.last.time > 0.05", 20)
        time.sleep(0.5)
        after = browser.screenshot("#disks")
        check(before != after, "GO animates the disks: the canvas differs between two screenshots")
        t1 = browser.eval("edeView.last.time")
        time.sleep(0.5)
        check(browser.eval("edeView.last.time") > t1, "time advances while running")
        # Fastest pace until 20 collisions per disk: the histogram is then Maxwell-Boltzmann.
        browser.eval("document.getElementById('fastest').click()")
        browser.wait("edeView.last.info.collisions_per_disk > 20", 60)
        info = browser.eval("edeView.last.info")
        tv = tv_distance(info)
        check(tv < 0.15, f"after {info['collisions_per_disk']:.0f} collisions per disk the speeds are MB (TV distance {tv:.3f} < 0.15)")
        check(abs(info["kT"] - 0.5) < 1e-9, f"kT stays 0.5 in an elastic gas ({info['kT']})")
        frames = browser.eval("edeView.frames")
        check(frames > 10, f"the page drew {frames} frames")
        if shots:
            browser.eval("document.getElementById('fastest').click()")
            time.sleep(0.5)
            open(os.path.join(shots, "view-live.png"), "wb").write(browser.screenshot())
        browser.eval("document.getElementById('go').click()")  # PAUSE
        browser.wait("edeView.last.info.status === 'paused'", 20)
        time.sleep(1.0)  # the page fetches the state the run stopped at once more, 0.3 s after PAUSE
        p1 = browser.screenshot("#disks")
        time.sleep(0.4)
        check(browser.screenshot("#disks") == p1, "PAUSE stops the disks: two screenshots are the same")

        # Scrubbing a log: the exact state of ede-replay --at, at times between keyframes (exact frames,
        # float64, as the page asks for them with edeView.exact or ?exact=1), and the compact frames the
        # page asks for by default within half a 16-bit step of it.
        end = browser.eval("(async () => (await (await fetch('/api/log/info?name=0:gas.ede')).json()).end)()")
        browser.eval("edeView.exact = true")
        for t in ["0.5", repr(end * 0.731), "0"]:
            browser.eval(f"edeView.openLog('0:gas.ede', '{t}')")
            browser.wait(f"edeView.last && edeView.last.t_request === '{t}'", 20)
            drawn = browser.eval("edeView.drawn()")
            rows = replay_at(log, t)
            same = drawn["packing"] == "exact" and len(rows) == drawn["n"] and all(
                float(row["x"]) == drawn["x"][i] and float(row["y"]) == drawn["y"][i] for i, row in enumerate(rows))
            check(same, f"the page drew at t = {t} exactly the positions of ede-replay --at {t} ({len(rows)} disks, float64)")
        browser.eval("edeView.exact = false")
        t = repr(end * 0.4)
        browser.eval(f"edeView.openLog('0:gas.ede', '{t}')")
        browser.wait(f"edeView.last && edeView.last.t_request === '{t}'", 20)
        drawn, rows = browser.eval("edeView.drawn()"), replay_at(log, t)
        half = 0.5 * drawn["info"]["lx"] / 65535 * 1.0001 + 1e-7  # + the float32 the page draws
        err = max(max(abs(float(row["x"]) - drawn["x"][i]), abs(float(row["y"]) - drawn["y"][i])) for i, row in enumerate(rows))
        check(drawn["packing"] == "compact" and err <= half,
              f"compact frames (the default): the page drew within {err:.1e} <= {half:.1e} of ede-replay --at {t}")
        # The crater view: a crater log opens coloured by displacement, with its surface profiles drawn and
        # the crater's metrics in the monitors (their numbers: test_view_crater.py).
        make_log(os.path.join(server.logs, "crater.ede"), "examples/crater.toml")
        browser.eval("edeView.openLog('0:crater.ede', 'end')")
        browser.wait("edeView.last.t_request === 'end' && edeView.last.info.crater", 20)
        time.sleep(0.3)
        monitors = browser.eval("document.getElementById('monitors').textContent")
        colour = browser.eval("document.getElementById('colour').value")
        depth = browser.eval("edeView.last.info.crater.depth")
        check("crater depth" in monitors and "bed disks displaced" in monitors and colour == "displacement" and depth > 0.1,
              f"a crater log opens in the crater view (depth {depth:.3f} in the monitors, coloured by {colour})")
        if shots:
            open(os.path.join(shots, "view-log.png"), "wb").write(browser.screenshot())
        # Bonded clusters: a square-well log may be coloured by them (the legend in the monitors, the groups
        # the frame's ranks); a log without a well disables the option, says why, and falls back to speed.
        make_log(os.path.join(server.logs, "wells.ede"), "examples/square-well.toml",
                 sets=["stop.time=1", "species[0].velocity.temperature=1.5"])
        browser.eval("edeView.openLog('0:wells.ede', '0.9')")
        browser.wait("edeView.last.t_request === '0.9'", 20)
        browser.eval("const c = document.getElementById('colour'); c.value = 'clusters';"
                     " c.dispatchEvent(new Event('change'))")
        browser.wait("edeView.last.info.colour.by === 'clusters'", 20)
        time.sleep(0.3)
        monitors = browser.eval("document.getElementById('monitors').textContent")
        legend = browser.eval("edeView.last.info.colour")
        check(f"{legend['clusters']}, largest {legend['largest']} disks" in monitors and legend["clusters"] >= 2,
              f"clusters: the legend in the monitors ({legend['clusters']} clusters, the largest {legend['largest']})")
        if shots:
            open(os.path.join(shots, "view-clusters.png"), "wb").write(browser.screenshot())
        browser.eval("edeView.openLog('0:gas.ede', '0.5')")
        browser.wait("edeView.last.t_request === '0.5'", 20)
        why = browser.eval("document.querySelector('#colour option[value=clusters]').title")
        check(browser.eval("document.querySelector('#colour option[value=clusters]').disabled") and "square well" in why
              and browser.eval("document.getElementById('colour').value") == "speed" and
              browser.eval("edeView.last.info.colour.by") == "speed class",
              f"a log without a well: the option is disabled, saying why ({why!r}), and the page colours by speed")
        browser.eval("edeView.openLog('0:crater.ede', 'end')")
        browser.wait("edeView.last.t_request === 'end' && edeView.last.info.crater", 20)

        # Playing the log backward from its end, then forward, at a chosen speed (simulated time per second).
        end = browser.eval("edeView.last.time")
        browser.eval(f"document.getElementById('play-speed').value = '{end / 4!r}'; document.getElementById('back').click()")
        browser.wait(f"edeView.last.time < {end * 0.9!r}", 20)
        t1 = browser.eval("edeView.last.time")
        time.sleep(0.5)
        t2 = browser.eval("edeView.last.time")
        browser.eval("document.getElementById('stop').click(); document.getElementById('fwd').click()")
        time.sleep(0.8)
        t3 = browser.eval("edeView.last.time")
        browser.eval("document.getElementById('stop').click()")
        check(end > t1 > t2 and t3 > t2, f"play back from the end goes back in time ({end:.3f} > {t1:.3f} > {t2:.3f}),"
              f" play forward forward ({t3:.3f})")

        # The WebGL disk layer (forced: the page prefers its 2D pixels where WebGL is software, as here):
        # it draws the disks (lit pixels about the disks' area) and they move.
        browser.goto(server.url + "/?draw=webgl")
        browser.eval("document.getElementById('setup').click()")
        browser.wait("edeView.last && edeView.last.info.status === 'paused'", 20)
        lit_js = ("(() => { const g = document.getElementById('disks-gl'), c = document.createElement('canvas');"
                  " c.width = g.width; c.height = g.height; const x = c.getContext('2d'); x.drawImage(g, 0, 0);"
                  " const d = x.getImageData(0, 0, c.width, c.height).data; let n = 0;"
                  " for (let i = 0; i < d.length; i += 4) if (d[i] || d[i + 1] || d[i + 2]) n++; return n; })()")
        if browser.eval("edeView.drawer") == "webgl":
            lit = browser.eval(lit_js)
            info = browser.eval("edeView.last.info")
            scale = 720 / max(info["lx"], info["ly"])
            area = sum(math.pi * (r * scale) ** 2 for r in browser.eval("edeView.drawn().r"))
            check(0.6 * area < lit < 1.4 * area, f"WebGL draws the disks: {lit} lit pixels, their area {area:.0f}")
            before = browser.screenshot("#disks")
            browser.eval("document.getElementById('go').click()")
            browser.wait("edeView.last.time > 0.05", 20)
            time.sleep(0.3)
            check(browser.screenshot("#disks") != before, "WebGL: the disks move")
            browser.eval("document.getElementById('go').click()")
        else:
            check(browser.eval("edeView.renderer").startswith("none"), "no WebGL2 here: the 2D canvas draws (checked above)")

        # Bad requests, as the page sees them.
        browser.eval("edeView.openLog('0:nope.ede')")
        browser.wait("document.getElementById('error').textContent.includes('no file')", 10)
        check(True, "an unknown log shows the server's message on the page")
        got = browser.eval("(async () => { const r = await fetch('/api/log/frame?name=0:..%2F..%2F..%2Fetc%2Fpasswd&t=0');"
                           " return [r.status, (await r.json()).error]; })()")
        check(got[0] == 403 and "outside" in got[1], f"path traversal from the page: 403 {got[1]}")
        got = browser.eval("(async () => { const r = await fetch('/api/run/setup', {method: 'POST', body: 'x'.repeat(70000)});"
                           " return [r.status, (await r.json()).error]; })()")
        check(got[0] == 413, f"an oversized body from the page: 413 {got[1]}")
    finally:
        if browser:
            browser.close()
        server.close()


if __name__ == "__main__":
    main()
