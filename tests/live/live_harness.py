"""Starts `strun run ... --serve 127.0.0.1:0` and talks to it over real HTTP
(urllib): shared by the live tests (tests/live/CMakeLists.txt)."""
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
DEMO = os.path.join(HERE, "live_demo.st")


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


class Strun:
    """A running `strun run --serve`: .url, .get(), .post(), .stop()."""

    def __init__(self, strun, args, token=None, files=(DEMO,)):
        self.token = token
        self.proc = subprocess.Popen([strun, "run", *args, *files], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.stderr_lines = []
        self.url = None
        deadline = time.time() + 30
        while time.time() < deadline:
            line = self.proc.stderr.readline().decode("utf-8", "replace")
            if not line:
                break
            self.stderr_lines.append(line)
            m = re.match(r"strun: serving (http://\S+/)$", line.strip())
            if m:
                self.url = m.group(1).rstrip("/")
                break
        if not self.url:
            self.proc.kill()
            raise Failure("strun did not print 'strun: serving http://HOST:PORT/': " + "".join(self.stderr_lines))
        # Keep draining stderr so that the process never blocks on a full pipe.
        self._drain = threading.Thread(target=self._read_stderr, daemon=True)
        self._drain.start()

    def _read_stderr(self):
        for raw in self.proc.stderr:
            self.stderr_lines.append(raw.decode("utf-8", "replace"))

    def request(self, method, path, body=None, headers=None, raw=None, timeout=40):
        data = raw if raw is not None else (None if body is None else json.dumps(body).encode())
        h = dict(headers or {})
        if body is not None and "Content-Type" not in h:
            h["Content-Type"] = "application/json"
        if self.token and "Authorization" not in h:
            h["Authorization"] = "Bearer " + self.token
        req = urllib.request.Request(self.url + path, data=data, method=method, headers=h)
        try:
            with urllib.request.urlopen(req, timeout=timeout) as res:
                return res.status, res.headers, res.read()
        except urllib.error.HTTPError as e:
            return e.code, e.headers, e.read()

    def get(self, path, **kw):
        status, _, body = self.request("GET", path, **kw)
        check(status == 200, f"GET {path}: status {status}: {body[:300]!r}")
        return json.loads(body)

    def post(self, path, body=None, **kw):
        status, _, data = self.request("POST", path, body=body if body is not None else {}, **kw)
        check(status == 200, f"POST {path} {body}: status {status}: {data[:300]!r}")
        return json.loads(data)

    def post_error(self, path, body, expect, **kw):
        status, _, data = self.request("POST", path, body=body, **kw)
        check(status == expect, f"POST {path} {body}: expected {expect}, got {status}: {data[:300]!r}")
        return json.loads(data) if data else {}

    def value(self, path):
        return self.get("/api/vars?watch=" + urllib.request.quote(path))["values"][path]

    def wait_for(self, what, predicate, timeout=10.0):
        deadline = time.time() + timeout
        last = None
        while time.time() < deadline:
            last = what()
            if predicate(last):
                return last
            time.sleep(0.02)
        raise Failure(f"timed out; last value {last!r}")

    def stop(self, sig=signal.SIGINT, timeout=20):
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        try:
            out, _ = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise Failure("strun did not stop after SIGINT")
        self._drain.join(timeout=5)
        return self.proc.returncode, out.decode("utf-8", "replace")


def run_cases(cases, strun):
    failed = 0
    for name, case in cases:
        started = time.time()
        try:
            case(strun)
            print(f"ok   {name} ({time.time() - started:.1f}s)")
        except Exception as e:  # report every case, then fail
            failed += 1
            print(f"FAIL {name}: {type(e).__name__}: {e}")
    sys.exit(1 if failed else 0)
