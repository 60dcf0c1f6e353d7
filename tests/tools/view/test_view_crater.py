"""ede-view's crater view: a crater log (examples/crater.toml: a bed and a projectile) is recognised in its
summary, and its frames asked with ?crater=1 carry the bed's surface profiles and the crater's metrics,
which equal what `ede-crater measure LOG --at T -o profiles.csv` writes (the same library analysis on the
same states: the heights to 1e-12, the metrics derived from the CSV's columns to 1e-12); a gas log is not
a crater scene; a bad ?crater= gets 400. ?before=T compares with the bed at T, as ede-crater --before T.
"""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(__file__))
from test_view_http import parse_frame  # noqa: E402
from viewlib import Server, check, make_log, tools_dir  # noqa: E402


def close(a, b):
    return abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))


def main():
    server = Server()
    try:
        crater_log = os.path.join(server.logs, "crater.ede")
        make_log(crater_log, "examples/crater.toml")
        make_log(os.path.join(server.logs, "gas.ede"), sets=["species[0].count=200", "stop.collisions_per_particle=2"])
        _, info = server.json("/api/log/info?name=0:crater.ede")
        check(info.get("crater", {}).get("bed") == ["bed"], f"a crater log's summary names its bed: {info.get('crater')}")
        _, info_gas = server.json("/api/log/info?name=0:gas.ede")
        check("crater" not in info_gas, "a gas log is not a crater scene")
        status, raw, _ = server.get("/api/log/frame?name=0:gas.ede&t=0&crater=1")
        check(status == 200 and "crater" not in parse_frame(raw)[0], "a gas log's frames carry no crater, asked or not")
        status, raw, _ = server.get("/api/log/frame?name=0:crater.ede&t=0&crater=2")
        check(status == 400, "?crater=2 gets 400")

        status, raw, _ = server.get("/api/log/frame?name=0:crater.ede&t=0&crater=1&before=9")
        check(status == 400 and "before" in raw.decode(), f"?before= past the log's end gets 400: {raw[:160]!r}")
        status, raw, _ = server.get("/api/log/frame?name=0:crater.ede&t=0&crater=1&before=x")
        check(status == 400, "?before=x gets 400")

        for t, before in [("0.1", None), ("end", None), ("end", "0.05")]:
            ask = f"&before={before}" if before else ""
            status, raw, _ = server.get(f"/api/log/frame?name=0:crater.ede&t={t}&crater=1&colour=displacement{ask}")
            c = parse_frame(raw)[0]["crater"]
            out = os.path.join(server.dir, f"profile-{t}-{before}.csv")
            r = subprocess.run([os.path.join(tools_dir(), "ede-crater"), "measure", crater_log, "--at", t, "-o", out] +
                               (["--before", before] if before else []), capture_output=True, text=True)
            check(r.returncode == 0 and c["before_time"] == float(before or 0),
                  f"ede-crater measures the log at {t} (before: {before or 'the start'})")
            t = t + (f", before {before}" if before else "")
            rows = list(csv.DictReader(open(out)))
            same = len(rows) == len(c["before"]) == len(c["after"]) and all(
                close(float(row["h_before"]), c["before"][k]) and close(float(row["h_after"]), c["after"][k])
                for k, row in enumerate(rows))
            check(same, f"t = {t}: the frame's surface profiles are ede-crater's ({len(rows)} bins)")
            drops = [float(row["drop"]) for row in rows]
            inside = [row for row in rows if row["in_crater"] == "1"]
            width = sum(float(row["x_right"]) - float(row["x_left"]) for row in inside)
            area = sum((float(row["x_right"]) - float(row["x_left"])) * float(row["drop"]) for row in inside)
            check(close(c["depth"], max(drops)) and c["has_crater"] == bool(inside) and close(c["width"], width) and
                  abs(c["area"] - area) <= 1e-9 * max(area, 1e-300),
                  f"t = {t}: depth {c['depth']:.6g}, width {c['width']:.6g}, area {c['area']:.6g} are ede-crater's")
            check(f"displaced         {c['displaced']} of {c['bed_disks']} bed disks" in r.stdout,
                  f"t = {t}: {c['displaced']} of {c['bed_disks']} bed disks displaced, as ede-crater counts them")
    finally:
        code = server.close()
    check(code in (0, 143), f"ede-view stops on SIGTERM (exit {code})")


if __name__ == "__main__":
    main()
