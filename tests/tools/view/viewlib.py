"""What the ede-view tests share: start ede-view on a free port, talk HTTP to it, make a log with ede-sim,
and drive Debian's chromium headless over the DevTools protocol (python3-websocket).

The server is started with --port 0 and prints the port it bound, so tests never race for a fixed port.
Every HTTP request bypasses proxies (a proxy set in the environment would otherwise see 127.0.0.1).
Rejected: puppeteer-core from npm (a second package manager for CI, and a Chromium version it must
match); Selenium (chromedriver is one more binary to keep in step with chromium).
"""
import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

SKIP = 77


def tools_dir():
    return os.environ.get("EDE_TOOLS_DIR") or os.path.join(os.path.dirname(__file__), "../../../build/tools")


def source_dir():
    return os.environ.get("EDE_SOURCE_DIR") or os.path.abspath(os.path.join(os.path.dirname(__file__), "../../.."))


def check(condition, message):
    if not condition:
        print("FAILED: " + message, file=sys.stderr)
        sys.exit(1)
    print("ok: " + message)


_opener = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def request(url, data=None, headers=None, method=None):
    """(status, body bytes, content type) of one request; 4xx and 5xx are returned, not raised."""
    req = urllib.request.Request(url, data=data, headers=headers or {}, method=method)
    try:
        with _opener.open(req, timeout=30) as res:
            return res.status, res.read(), res.headers.get("Content-Type", "")
    except urllib.error.HTTPError as e:
        return e.code, e.read(), e.headers.get("Content-Type", "")


def make_log(path, scene="examples/gas.toml", sets=()):
    cmd = [os.path.join(tools_dir(), "ede-sim"), os.path.join(source_dir(), scene), "-o", path, "-q"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def replay_at(log, t):
    """ede-replay LOG --at T as a list of rows (dicts of the CSV's columns, as text)."""
    out = subprocess.run([os.path.join(tools_dir(), "ede-replay"), log, "--at", t], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    header = out[0].split(",")
    return [dict(zip(header, line.split(","))) for line in out[1:]]


class Server:
    """ede-view on a free port of 127.0.0.1, in a temporary folder (its --out-dir is there too)."""

    def __init__(self, logs_dir=None, extra=(), cwd=None):
        self.dir = tempfile.mkdtemp(prefix="ede-view-test-")
        self.logs = logs_dir or os.path.join(self.dir, "logs")
        os.makedirs(self.logs, exist_ok=True)
        cmd = [os.path.join(tools_dir(), "ede-view"), "--port", "0", "--logs", self.logs,
               "--scenes", os.path.join(source_dir(), "examples"), "--out-dir", os.path.join(self.dir, "runs"), *extra]
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd)
        line = self.proc.stdout.readline()
        if "http://" not in line:
            raise RuntimeError("ede-view did not start: " + line + self.proc.stderr.read())
        self.url = line.split()[-1].rstrip("/")

    def get(self, path, **kw):
        return request(self.url + path, **kw)

    def json(self, path, body=None):
        """GET (no body) or POST a JSON body; (status, parsed JSON answer)."""
        if body is None:
            status, raw, _ = request(self.url + path)
        else:
            status, raw, _ = request(self.url + path, data=json.dumps(body).encode(), method="POST",
                                     headers={"Content-Type": "application/json"})
        return status, json.loads(raw)

    def post(self, path, body=b""):
        status, raw, _ = request(self.url + path, data=body, method="POST")
        return status, json.loads(raw)

    def close(self):
        self.proc.terminate()
        try:
            status = self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            status = self.proc.wait()
        err = self.proc.stderr.read()
        if status not in (0, 143) or "ERROR" in err or "runtime error" in err:
            print("ede-view's stderr:\n" + err, file=sys.stderr)  # a sanitizer's report, for one
        shutil.rmtree(self.dir, ignore_errors=True)
        return status


def chromium_or_skip():
    """The chromium binary, or exit 77 (skipped) where there is none or under sanitizers."""
    if os.environ.get("EDE_SANITIZED"):
        print("skipped: the browser tests do not run in the sanitizer build")
        sys.exit(SKIP)
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    print("skipped: no chromium (apt-get install chromium)")
    sys.exit(SKIP)


class Browser:
    """One headless chromium page, driven over the DevTools protocol."""

    def __init__(self, width=1400, height=790):
        import websocket  # python3-websocket
        self.profile = tempfile.mkdtemp(prefix="ede-view-chromium-")
        self.proc = subprocess.Popen(
            [chromium_or_skip(), "--headless=new", "--no-sandbox", "--disable-gpu", "--no-proxy-server",
             "--no-first-run", "--disable-extensions", "--remote-debugging-port=0", "--remote-allow-origins=*",
             f"--user-data-dir={self.profile}", f"--window-size={width},{height}", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(self.profile, "DevToolsActivePort")
        for _ in range(300):
            if os.path.exists(port_file) and open(port_file).read().count("\n") >= 1:
                break
            time.sleep(0.1)
        port = open(port_file).read().split()[0]
        pages = []
        for _ in range(100):
            _, raw, _ = request(f"http://127.0.0.1:{port}/json/list")
            pages = [p for p in json.loads(raw) if p.get("type") == "page"]
            if pages:
                break
            time.sleep(0.1)
        self.ws = websocket.create_connection(pages[0]["webSocketDebuggerUrl"], timeout=60, suppress_origin=True)
        self.next_id = 0
        self.send("Page.enable")
        self.send("Runtime.enable")
        self.send("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)

    def send(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                return msg.get("result", {})

    def goto(self, url):
        self.send("Page.navigate", url=url)
        self.wait("window.edeView && window.edeView.ready === true", 30)

    def eval(self, expression):
        r = self.send("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in r:
            raise RuntimeError(f"{expression}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def wait(self, expression, seconds):
        end = time.time() + seconds
        while time.time() < end:
            if self.eval(f"!!({expression})"):
                return True
            time.sleep(0.1)
        raise RuntimeError(f"timed out after {seconds} s waiting for {expression}")

    def screenshot(self, selector=None):
        """PNG bytes of the page, or of one element."""
        params = {"format": "png"}
        if selector:
            box = self.eval(f"(() => {{ const r = document.querySelector('{selector}').getBoundingClientRect();"
                            " return {x: r.x, y: r.y, width: r.width, height: r.height}; })()")
            params["clip"] = {**box, "scale": 1}
        return base64.b64decode(self.send("Page.captureScreenshot", **params)["data"])

    def close(self):
        try:
            self.ws.close()
        finally:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
            shutil.rmtree(self.profile, ignore_errors=True)
