"""ede-view under abuse (issue 36): many pages at once, pages that never read their frames, malformed and
oversized requests to every endpoint, a live run at the disk limit, requests for files outside --logs
(traversal, symlinks, scene keys that name files). Throughout, a probe asks for the run's status and must
be answered within PROBE_S seconds; at the end the server still answers, its memory stayed bounded, and
nothing was written outside --out-dir (every other folder it can reach is compared before and after).
"""
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from viewlib import Server, check, make_log, source_dir, tools_dir  # noqa: E402

PROBE_S = 2.0  # the longest a page may wait for a small answer while others abuse the server


def raw(server, data, read=True, timeout=10):
    """Sends bytes on a fresh connection; (status, body) of the answer, or (None, b'') if none came."""
    host, port = server.url.split("//")[1].split(":")
    s = socket.create_connection((host, int(port)), timeout=timeout)
    try:
        s.sendall(data)
        if not read:
            return None, b""
        answer = b""
        while True:
            try:
                chunk = s.recv(65536)
            except (socket.timeout, ConnectionResetError):
                break
            if not chunk:
                break
            answer += chunk
            head, _, body = answer.partition(b"\r\n\r\n")
            if b"Content-Length:" in head:
                length = int(head.split(b"Content-Length:")[1].split(b"\r\n")[0])
                if len(body) >= length:
                    break
    finally:
        s.close()
    if not answer.startswith(b"HTTP/1.1 "):
        return None, answer
    head, _, body = answer.partition(b"\r\n\r\n")
    return int(head.split()[1]), body


def probe(server):
    """Seconds the run's status took to come back (a small answer every page polls)."""
    t = time.monotonic()
    status, _ = server.json("/api/run/status")
    assert status == 200
    return time.monotonic() - t


def rss_mb(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    return 0.0


def tree(folder):
    """Every file under folder with its size and modification time (symlinks not followed)."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in files + dirs:
            p = os.path.join(root, name)
            st = os.lstat(p)
            out[os.path.relpath(p, folder)] = (st.st_size, st.st_mtime_ns)
    return out


def outside_files(server):
    """The files outside --logs that the abuse below tries to reach."""
    outside = os.path.join(server.dir, "outside")
    os.makedirs(outside)
    make_log(os.path.join(outside, "secret.ede"), sets=["species[0].count=50", "stop.time=0.1"])
    with open(os.path.join(outside, "secret.csv"), "w") as f:
        f.write("SECRET-LINE-1\nSECRET-LINE-2\n")
    os.symlink(os.path.join(outside, "secret.ede"), os.path.join(server.logs, "link.ede"))
    os.symlink(outside, os.path.join(server.logs, "dirlink"))
    os.symlink("loop.ede", os.path.join(server.logs, "loop.ede"))
    return outside


def refused(server, path, body=None):
    """A request for something outside the served folders: 4xx with a JSON error that quotes nothing of the
    file (its secret line), never 200."""
    if body is None:
        status, raw_body, _ = server.get(path)
    else:
        status, raw_body, _ = server.get(path, data=json.dumps(body).encode(), method="POST",
                                         headers={"Content-Type": "application/json"})
    message = json.loads(raw_body).get("error", "") if raw_body.startswith(b"{") else ""
    check(400 <= status < 500 and message and b"SECRET" not in raw_body,
          f"{(path + ' ' + json.dumps(body) if body else path)[:110]} -> {status}: {message[:90]}")


def files_outside_logs(server, outside):
    for name in ["0:../outside/secret.ede", "0:..%2Foutside%2Fsecret.ede", "0:%2e%2e/outside/secret.ede",
                 "0:sub/../../outside/secret.ede", "0:link.ede", "0:dirlink/secret.ede", "0:loop.ede",
                 os.path.join(outside, "secret.ede"), "0:" + os.path.join(outside, "secret.ede"),
                 "0:gas.ede%00.toml", "0:" + "a/" * 600 + "x.ede", "-1:gas.ede", "99999:gas.ede", "0:",
                 "0:..\\outside\\secret.ede"]:
        refused(server, f"/api/log/info?name={name}")
        refused(server, f"/api/log/frame?name={name}&t=0")
    for name in ["0:../../etc/passwd", "0:../outside/secret.csv", os.path.join(outside, "x.toml")]:
        refused(server, f"/api/scene?name={name}")
        refused(server, "/api/run/setup", {"scene": name})
    _, logs = server.json("/api/logs")
    check(not any("link" in n or "loop" in n or "secret" in n for n in logs["logs"]),
          f"/api/logs lists no symlink that leads out of the folder: {logs['logs']}")
    # A scene's keys that name files: the page may not point a live run at a file elsewhere.
    for key in [f"start.from={outside}/secret.ede", f"start.csv={outside}/secret.csv", "start.from=../../x.ede",
                "start.csv=/etc/passwd"]:
        refused(server, "/api/run/setup", {"scene": "0:gas.toml", "set": [key]})


ENDPOINTS = [("GET", "/"), ("GET", "/view.js"), ("GET", "/api/logs"), ("GET", "/api/log/info?name=0:gas.ede"),
             ("GET", "/api/log/frame?name=0:gas.ede&t=0"), ("GET", "/api/scenes"), ("GET", "/api/scene?name=0:gas.toml"),
             ("POST", "/api/run/setup"), ("POST", "/api/run/go"), ("POST", "/api/run/pause"),
             ("POST", "/api/run/reverse"), ("POST", "/api/run/finish"), ("POST", "/api/run/pace?pace=1"),
             ("GET", "/api/run/status"), ("GET", "/api/run/frame")]


def malformed(server):
    """Every endpoint with an oversized URI, header and body, bad encodings and numbers, a lying
    Content-Length, the wrong method: each gets a 4xx status (no 5xx, no dropped connection), or its normal
    answer where the bad part is one cpp-httplib ignores."""
    bad = 0
    for method, path in ENDPOINTS:
        cases = {
            "URI of 9 KB": f"{method} {path}{'&' if '?' in path else '?'}x={'a' * 9000} HTTP/1.1\r\nHost: localhost\r\n"
                           "Content-Length: 0\r\n\r\n",
            "header of 9 KB": f"{method} {path} HTTP/1.1\r\nHost: localhost\r\nX-Big: {'b' * 9000}\r\n"
                              "Content-Length: 0\r\n\r\n",
            "body of 100 KB": f"{method} {path} HTTP/1.1\r\nHost: localhost\r\nContent-Length: 100000\r\n\r\n"
                              + "{" * 100000,
            "Content-Length of 10^12": f"{method} {path} HTTP/1.1\r\nHost: localhost\r\n"
                                       "Content-Length: 1000000000000\r\n\r\n{",
            "negative Content-Length": f"{method} {path} HTTP/1.1\r\nHost: localhost\r\nContent-Length: -5\r\n\r\n",
            "bad percent-encoding": f"{method} {path}{'&' if '?' in path else '?'}name=%zz%&t=%ff HTTP/1.1\r\n"
                                    "Host: localhost\r\nContent-Length: 0\r\n\r\n",
            "wrong method": f"DELETE {path} HTTP/1.1\r\nHost: localhost\r\n\r\n",
            "garbage line": f"{method}{path} HTTP/9\r\n\r\n",
            "binary bytes": "\x00\x01\x02\xff\r\n\r\n",
            "header without colon": f"{method} {path} HTTP/1.1\r\nHost localhost\r\nContent-Length: 0\r\n\r\n",
        }
        for what, text in cases.items():
            status, body = raw(server, text.encode("latin-1"))
            # What cpp-httplib ignores may be answered normally: a GET's body (never read: the connection is
            # closed after the answer) and a header line without a colon (skipped).
            ignored = what == "header without colon" or (method == "GET" and ("ength" in what or what.startswith("body")))
            ok = status is not None and (400 <= status < 500 or (status == 200 and (ignored or what == "bad percent-encoding")))
            if not ok:
                bad += 1
                print(f"  {method} {path} with a {what}: {status} {body[:100]!r}")
    check(bad == 0, f"malformed and oversized requests to all {len(ENDPOINTS)} endpoints get a 4xx answer")
    check(probe(server) < PROBE_S, "the server answers after them")


def many_pages(server, log_name):
    """60 idle connections (a page's spare sockets), 20 that trickle a request byte by byte, and 16 tabs
    fetching frames as fast as they can: a probe is answered within PROBE_S each time."""
    stop = threading.Event()
    socks = []
    host, port = server.url.split("//")[1].split(":")
    for _ in range(60):
        socks.append(socket.create_connection((host, int(port))))
    trickle = [socket.create_connection((host, int(port))) for _ in range(20)]

    def trickler():
        text = b"GET /api/run/status HTTP/1.1\r\nHost: localhost\r\n"
        k = 0
        while not stop.is_set():
            for s in trickle:
                try:
                    s.send(text[k % len(text):k % len(text) + 1])
                except OSError:
                    pass
            k += 1
            time.sleep(0.5)

    errors = []

    def tab():
        while not stop.is_set():
            status, _, _ = server.get(f"/api/log/frame?name={log_name}&t=0.05")
            if status != 200 and status != 503:
                errors.append(status)

    threads = [threading.Thread(target=trickler)] + [threading.Thread(target=tab) for _ in range(16)]
    for t in threads:
        t.start()
    worst = 0.0
    try:
        for _ in range(16):
            worst = max(worst, probe(server))
            time.sleep(0.5)
    finally:
        stop.set()
        for t in threads:
            t.join()
        for s in socks + trickle:
            s.close()
    check(not errors, f"16 tabs fetching frames get them (or 503 busy): {errors[:5]}")
    check(worst < PROBE_S, f"with 60 idle, 20 trickling and 16 busy connections a page is answered within "
                           f"{PROBE_S} s (slowest {worst:.2f} s)")


def never_reading(server, log_name, frame_bytes):
    """40 pages that ask for a large exact frame and never read it: the probe is answered, and the server's
    memory stays within its frame budget (--frame-memory 32: at most 32 MiB of frames in flight, plus the
    frame being packed and its state) instead of holding every frame asked for."""
    host, port = server.url.split("//")[1].split(":")
    for t in ("0.01", "0.4"):  # the log opened and its reading buffers grown: what one page costs
        server.get(f"/api/log/frame?name={log_name}&t={t}&exact=1&max=100000000")
    base = rss_mb(server.proc.pid)
    print(f"  the server's memory with the log open: {base:.0f} MB")
    socks = []
    for k in range(40):
        s = socket.socket()
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        s.connect((host, int(port)))
        s.sendall(f"GET /api/log/frame?name={log_name}&t={0.01 * (k + 1)}&exact=1&max=100000000 HTTP/1.1\r\n"
                  f"Host: localhost\r\n\r\n".encode())
        socks.append(s)
    peak, worst = 0.0, 0.0
    for _ in range(8):
        peak = max(peak, rss_mb(server.proc.pid))
        worst = max(worst, probe(server))
        time.sleep(0.5)
    for s in socks:
        s.close()
    grown = peak - base
    check(worst < PROBE_S, f"40 pages that never read a {frame_bytes / 1e6:.1f} MB frame: others are answered within "
                           f"{PROBE_S} s (slowest {worst:.2f} s)")
    if os.environ.get("EDE_SANITIZED"):
        print("skipped: the memory bound (AddressSanitizer's quarantine keeps freed memory)")
    else:
        check(grown < 80, f"... and the server's memory grew by {grown:.0f} MB (< 80 MB; 40 frames would be "
                          f"{40 * frame_bytes / 1e6:.0f} MB)")
    status, body, _ = server.get(f"/api/log/frame?name={log_name}&t=0&exact=1")
    check(status == 200, "the frames are served again once those pages are gone")


def disk_limit(server):
    """--max-disks 20000: a run of exactly that many works; one more, or 10^12, is refused at once."""
    status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=20000",
                                                                              "species[0].radius=0.001"], "until": 0.05})
    check(status == 200 and st["disks"] == 20000, f"a live run of exactly --max-disks disks is made: {status}")
    server.post("/api/run/pace?pace=0")
    server.post("/api/run/go")
    for _ in range(300):
        _, st = server.json("/api/run/status")
        if st["status"].startswith("ended"):
            break
        time.sleep(0.1)
    check(st["status"] == "ended: reached stop.time", f"... and runs to its end: {st['status']}")
    for count in ["20001", "1000000000000"]:
        t = time.monotonic()
        status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": [f"species[0].count={count}"]})
        check(status == 400 and ("--max-disks" in st["error"] or "species[0].count" in st["error"]) and
              time.monotonic() - t < PROBE_S, f"{count} disks: refused at once ({st.get('error', '')[:110]})")


def main():
    cwd = tempfile.mkdtemp(prefix="ede-view-cwd-")
    server = Server(extra=["--max-disks", "20000", "--frame-memory", "32"], cwd=cwd)
    try:
        gas = os.path.join(server.logs, "gas.ede")
        make_log(gas, sets=["species[0].count=400", "stop.time=2"])
        big = os.path.join(server.logs, "big.ede")
        make_log(big, sets=["species[0].count=200000", "species[0].radius=0.0005", "stop.time=0.5",
                            "log.keyframe_interval=200000"])
        os.makedirs(os.path.join(server.logs, "sub"))
        outside = outside_files(server)
        before = {d: tree(d) for d in (server.logs, outside, os.path.join(source_dir(), "examples"))}

        files_outside_logs(server, outside)
        malformed(server)
        many_pages(server, "0:gas.ede")
        never_reading(server, "0:big.ede", 200000 * 25)
        disk_limit(server)

        after = {d: tree(d) for d in before}
        check(after == before, "nothing was written in --logs, outside it or in --scenes")
        check(not os.listdir(cwd), "nothing was written in the server's working folder")
        runs = os.listdir(os.path.join(server.dir, "runs"))
        check(all(n.startswith("live-") and n.endswith(".ede") for n in runs),
              f"--out-dir holds only the live runs' logs: {sorted(runs)[:5]}")
        check(probe(server) < PROBE_S, "the server still answers at the end")
    finally:
        code = server.close()
    check(code in (0, 143), f"ede-view stops on SIGTERM (exit {code})")


if __name__ == "__main__":
    main()
