"""The cost of --serve on a running PLC (issue 25's figures; not a test:
timing depends on the machine). Usage: overhead.py STRUN [SECONDS]

1. A 1 ms real-clock task (fast_task.st) for SECONDS: without --serve, then
   with --serve and a client polling /api/vars at 10 Hz plus an SSE client;
   the task's average and maximum execution time and overruns (--dump).
2. 10 000 variables (many_vars.st) with --serve and an SSE client watching
   all of them: the process's resident memory, against the same run without."""
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))


def start(strun, args, prog):
    p = subprocess.Popen([strun, "run", *args, os.path.join(HERE, prog)], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    url = None
    if "--serve" in args:
        while True:
            line = p.stderr.readline().decode()
            m = re.search(r"serving (http://\S+)/", line)
            if m:
                url = m.group(1)
                break
            if not line:
                raise SystemExit("no serving line")
    threading.Thread(target=lambda: p.stderr.read(), daemon=True).start()
    return p, url


def poll_vars(url, stop):
    try:
        while not stop.is_set():
            urllib.request.urlopen(url + "/api/vars", timeout=10).read()
            time.sleep(0.1)
    except OSError:
        pass  # the run (and its server) has ended


def sse(url, stop, watch=""):
    try:
        with urllib.request.urlopen(url + "/api/events?every=100ms" + watch, timeout=30) as r:
            while not stop.is_set() and r.readline():
                pass
    except OSError:
        pass


def rss(pid):
    with open(f"/proc/{pid}/status") as f:
        return next(int(l.split()[1]) for l in f if l.startswith("VmRSS:"))


def task_figures(strun, seconds, serve):
    args = ["--for", f"{seconds}s", "--dump"] + (["--serve", "127.0.0.1:0"] if serve else [])
    p, url = start(strun, args, "fast_task.st")
    stop = threading.Event()
    threads = []
    if serve:
        threads = [threading.Thread(target=poll_vars, args=(url, stop), daemon=True),
                   threading.Thread(target=sse, args=(url, stop), daemon=True)]
        for t in threads:
            t.start()
    out, _ = p.communicate(timeout=seconds + 60)
    stop.set()
    task = json.loads(out)["tasks"][0]
    return task


def main():
    strun = sys.argv[1]
    seconds = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    for serve in (False, True, False, True):
        t = task_figures(strun, seconds, serve)
        print(f"{'--serve + 10 Hz /api/vars + SSE' if serve else 'plain                          '}: "
              f"cycles {t['cycles']}, avg exec {t['avg_exec_us']} us, max exec {t['max_exec_us']} us, overruns {t['overruns']}")
    for serve in (False, True):
        args = ["--for", "8s"] + (["--serve", "127.0.0.1:0"] if serve else [])
        p, url = start(strun, args, "many_vars.st")
        stop = threading.Event()
        if serve:
            threading.Thread(target=sse, args=(url, stop), daemon=True).start()
            threading.Thread(target=poll_vars, args=(url, stop), daemon=True).start()
        time.sleep(5)
        r = rss(p.pid)
        stop.set()
        p.send_signal(signal.SIGINT)
        p.communicate(timeout=30)
        print(f"10 000 variables, {'--serve + SSE all + 10 Hz /api/vars' if serve else 'plain'}: RSS {r} KiB")


main()
