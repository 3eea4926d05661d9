"""Hostile HTTP clients against --serve while a 10 ms task runs: slowloris,
1000 connections, huge bodies and heads, header floods, junk, malformed JSON,
invalid UTF-8, a client that never reads its event stream. Each must leave
the server answering others, the scan running, and memory bounded. (No
assertion on timing: the task's overruns are printed, not checked.)
Usage: hostile_test.py STRUN"""
import json
import resource
import socket
import sys
import threading
import time

from live_harness import Failure, Strun, check, run_cases


def rss_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def connect(s):
    host, port = s.url.split("//")[1].split(":")
    c = socket.create_connection((host, int(port)), timeout=10)
    return c


def answer(c, limit=1 << 16):
    data = b""
    try:
        while b"\r\n\r\n" not in data and len(data) < limit:
            chunk = c.recv(4096)
            if not chunk:
                break
            data += chunk
    except (ConnectionResetError, socket.timeout):
        pass
    return data


def status_of(data):
    try:
        return int(data.split(b" ", 2)[1])
    except (IndexError, ValueError):
        return None


def healthy(s, what):
    st = s.get("/api/state")
    check(st["state"] == "RUN", f"after {what}: {st['state']}")
    return st["tasks"][0]["cycles"]


def case_all(strun):
    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    resource.setrlimit(resource.RLIMIT_NOFILE, (min(hard, 8192), hard))
    s = Strun(strun, ["--serve", "127.0.0.1:0"])
    try:
        s.wait_for(lambda: s.value("Main.counter"), lambda v: v > 5)
        rss_before = rss_kib(s.proc.pid)
        cycles = healthy(s, "start")

        # -- slowloris: 300 heads that never end, a byte now and then
        slow = []
        for _ in range(300):
            c = connect(s)
            c.sendall(b"GET /api/state HTTP/1.1\r\nHost: x\r\n")
            slow.append(c)
        for _ in range(6):
            for c in slow:
                try:
                    c.sendall(b"X")
                except OSError:
                    pass
            healthy(s, "slowloris")  # others are still answered
            time.sleep(0.3)
        for c in slow:
            c.close()
        cycles_after = healthy(s, "slowloris")
        check(cycles_after > cycles, "the scan went on")

        # -- 1000 connections at once, idle
        idle = [connect(s) for _ in range(1000)]
        healthy(s, "1000 idle connections")
        for c in idle:
            c.close()

        # -- a huge body announced: 413 without reading it
        c = connect(s)
        c.sendall(b"POST /api/write HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 200000000\r\n\r\n")
        check(status_of(answer(c)) == 413, "huge body: 413")
        c.close()
        # -- and one actually sent (4 MB), the server stops reading it
        c = connect(s)
        c.sendall(b"POST /api/write HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 4000000\r\n\r\n")
        try:
            c.sendall(b"x" * 4_000_000)
        except OSError:
            pass
        check(status_of(answer(c)) in (413, None), "huge body sent")
        c.close()
        # -- chunked bodies are refused
        c = connect(s)
        c.sendall(b"POST /api/write HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n5\r\nhello\r\n0\r\n\r\n")
        check(status_of(answer(c)) == 411, "chunked: 411")
        c.close()

        # -- a head line that never ends (8 MB), and a flood of header lines
        c = connect(s)
        try:
            c.sendall(b"GET /api/state HTTP/1.1\r\nX-Long: " + b"a" * 8_000_000)
        except OSError:
            pass
        check(status_of(answer(c)) in (431, None), "endless header line")
        c.close()
        c = connect(s)
        try:
            c.sendall(b"GET /api/state HTTP/1.1\r\n" + b"".join(b"X-%d: v\r\n" % i for i in range(20000)) + b"\r\n")
        except OSError:
            pass
        check(status_of(answer(c)) in (431, None), "header flood")
        c.close()
        c = connect(s)
        c.sendall(b"GET /api/state HTTP/1.1\r\n" + b"".join(b"X-%d: v\r\n" % i for i in range(100)) + b"\r\n")
        check(status_of(answer(c)) == 431, "too many header lines: 431")
        c.close()

        # -- junk
        for junk in (b"\x00\xff\xfe garbage\r\n\r\n", b"GET\r\n\r\n", b"GET /api/state HTTP/9.9\r\n\r\n", b"GET api/state HTTP/1.1\r\n\r\n",
                     b"GET /api/state HTTP/1.1\r\nno colon here\r\n\r\n"):
            c = connect(s)
            c.sendall(junk)
            code = status_of(answer(c))
            check(code in (400, 505), f"junk {junk[:20]!r}: {code}")
            c.close()
        healthy(s, "junk")

        # -- malformed JSON and invalid UTF-8, many times over one connection each
        for body in (b'{"name": ', b'{"name": "\xc3\x28", "value": "1"}', b'{"name": "Main.\xed\xa0\x80", "value": "1"}',
                     b'"just a string"', b'{"name": 5, "value": "1"}', b'{' * 100000):
            st, _, data = s.request("POST", "/api/write", raw=body, headers={"Content-Type": "application/json"})
            check(st in (400, 413) and "error" in json.loads(data), f"bad JSON {body[:30]!r}: {st}")

        # -- a client that subscribes to events and never reads
        sinks = []
        for _ in range(20):
            c = connect(s)
            c.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
            c.sendall(b"GET /api/events?every=10ms HTTP/1.1\r\nHost: x\r\n\r\n")
            sinks.append(c)
        time.sleep(1.0)
        healthy(s, "clients that never read")
        for c in sinks:
            c.close()

        # -- many quick requests in parallel
        errors = []

        def hammer():
            try:
                for _ in range(50):
                    s.get("/api/vars?watch=Main.*")
            except Exception as e:  # collected below
                errors.append(e)

        threads = [threading.Thread(target=hammer) for _ in range(8)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        check(not errors, f"parallel clients: {errors[:3]}")

        end_cycles = healthy(s, "everything")
        check(end_cycles > cycles_after, "the scan went on throughout")
        rss_after = rss_kib(s.proc.pid)
        grown = rss_after - rss_before
        st = s.get("/api/state")
        print(f"     rss {rss_before} KiB -> {rss_after} KiB; task Fast: {st['tasks'][0]['cycles']} cycles, "
              f"{st['tasks'][0]['overruns']} overruns, max exec {st['tasks'][0]['max_exec_us']} us")
        check(grown < 64 * 1024, f"memory grew by {grown} KiB")
    finally:
        code, _ = s.stop()
    check(code == 0, f"exit {code}")


if __name__ == "__main__":
    run_cases([("hostile_clients", case_all)], sys.argv[1])
