#!/usr/bin/env python3
"""What a debugger costs a run: a benchmark workload run by `strun run` and
by `strun debug` with a DAP client attached and no breakpoint (and with one
breakpoint on a line that is never reached), wall time (best of the repeats).

usage: benchmarks/dap_overhead.py [path-to-strun] [workload] [repeats]"""
import os
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "tests", "editors"))
from protocol_client import Client  # noqa: E402


def debugged(strun, program, args, breakpoint_line=None):
    c = Client([strun, "debug"])
    seq = [0]

    def request(command, arguments):
        seq[0] += 1
        c.send({"seq": seq[0], "type": "request", "command": command, "arguments": arguments})
        s = seq[0]
        r = c.wait(lambda m: m.get("type") == "response" and m.get("request_seq") == s, 600, command)
        assert r["success"], r

    request("initialize", {"adapterID": "strun"})
    request("launch", {"program": program, "args": args})
    if breakpoint_line:
        request("setBreakpoints", {"source": {"path": program}, "breakpoints": [{"line": breakpoint_line}]})
    t0 = time.perf_counter()
    request("configurationDone", {})
    c.wait(lambda m: m.get("event") == "exited", 600, "exited")
    elapsed = time.perf_counter() - t0
    request("disconnect", {})
    c.proc.wait(timeout=60)
    return elapsed


def main():
    strun = sys.argv[1] if len(sys.argv) > 1 else "build/strun"
    workload = sys.argv[2] if len(sys.argv) > 2 else "fb_calls"
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    program = os.path.join(here, "workloads", workload + ".st")
    args = ["--virtual", "--stmt-cost", "0ns", "--cycles", "1", "--task", "Main"]
    plain = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        subprocess.run([strun, "run", *args, "--quiet", program], check=True)
        plain.append(time.perf_counter() - t0)
    attached = [debugged(strun, program, args) for _ in range(repeats)]
    # A breakpoint on a statement that never runs: a copy of the workload
    # with a function nobody calls (a breakpoint on a line without a
    # statement would not be verified, and would cost nothing).
    text = open(program).read() + "\nFUNCTION NeverCalled : INT\nVAR_INPUT x : INT; END_VAR\nNeverCalled := x + 1;\nEND_FUNCTION\n"
    copy = os.path.join(tempfile.mkdtemp(prefix="strun_dap_bench_"), workload + ".st")
    with open(copy, "w") as f:
        f.write(text)
    bp_line = text.split("\n").index("NeverCalled := x + 1;") + 1
    with_bp = [debugged(strun, copy, args, bp_line) for _ in range(repeats)]
    print("%s: run %.3f s, debug attached %.3f s (x%.1f), with an unreached breakpoint %.3f s (x%.1f)" %
          (workload, min(plain), min(attached), min(attached) / min(plain), min(with_bp), min(with_bp) / min(plain)))


if __name__ == "__main__":
    main()
