"""`strun debug` and the run it debugs, through real DAP sessions: the stack
of a task preempted by the stopped one, writes through the live control
plane (setVariable), pause of a run the control plane holds (--paused), a
debugger that watches statements only while something can stop there, and
a long stop on the real clock that must not trip the watchdog.
Usage: dap_runtime_test.py STRUN"""
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dap_test import Dap, line_of  # noqa: E402

TASKS = """PROGRAM Slow
VAR
    i : INT;
    n : INT;
END_VAR
FOR i := 1 TO 50 DO
    n := n + 1;
END_FOR;
END_PROGRAM

PROGRAM Fast
VAR
    k : INT;
END_VAR
k := k + 1;
END_PROGRAM

CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK SlowTask (INTERVAL := T#200ms, PRIORITY := 10);
        TASK FastTask (INTERVAL := T#10ms, PRIORITY := 1);
        PROGRAM S WITH SlowTask : Slow;
        PROGRAM F WITH FastTask : Fast;
    END_RESOURCE
END_CONFIGURATION
"""

WRITES = """FUNCTION Twice : INT
VAR_INPUT
    x : INT;
END_VAR
VAR
    tmp : INT;
END_VAR
tmp := x * 2;
Twice := tmp;
END_FUNCTION

PROGRAM Main
VAR
    count : INT;
    doubled : INT;
    nested : DINT;
END_VAR
count := count + 1;
doubled := Twice(count);
nested := nested + 1;
END_PROGRAM
"""

WATCHDOG = """PROGRAM Main
VAR
    count : INT;
END_VAR
count := count + 1;
END_PROGRAM

CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK Work (INTERVAL := T#50ms, PRIORITY := 1, WATCHDOG := T#40ms);
        PROGRAM P WITH Work : Main;
    END_RESOURCE
END_CONFIGURATION
"""


def write(work, name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def main():
    work = tempfile.mkdtemp(prefix="strun_dap_rt_")

    # ---- 1. the stack of a preempted task: FastTask stops at its breakpoint
    # while SlowTask is in the middle of its loop (virtual clock, 1 ms per
    # statement: FastTask's second release at 10 ms preempts SlowTask).
    tasks = write(work, "tasks.st", TASKS)
    d = Dap()
    d.start(tasks, ["--virtual", "--stmt-cost", "1ms", "--for", "1s"],
            breakpoints={tasks: [{"line": line_of(TASKS, "k := k + 1;"), "hitCondition": "2"}]})
    body = d.stopped("breakpoint")
    threads = {t["name"]: t["id"] for t in d.request("threads")["body"]["threads"]}
    assert body["threadId"] == threads["FastTask"], (body, threads)
    fast = d.top_frame(threads["FastTask"])
    assert [f["name"] for f in fast] == ["Fast"], fast
    slow = d.top_frame(threads["SlowTask"])
    assert [f["name"] for f in slow] == ["Slow"], slow
    assert slow[0]["line"] in (line_of(TASKS, "FOR i := 1"), line_of(TASKS, "n := n + 1;")), slow
    local = d.variables(d.scopes(slow[0]["id"])["Locals"]["variablesReference"])
    assert 1 <= int(local["i"]["value"]) < 50, local  # preempted mid-loop
    ev = d.request("evaluate", {"expression": "n", "frameId": slow[0]["id"]})["body"]
    assert ev["result"] == local["n"]["value"], ev
    d.finish()

    # ---- 2. setVariable: a program's variable goes through the control
    # plane's write queue (stored when the next activation starts); a
    # function's local, which lives only during the call, is written at once.
    writes = write(work, "writes.st", WRITES)
    d = Dap()
    d.start(writes, ["--virtual", "--cycles", "5"], breakpoints={writes: [{"line": line_of(WRITES, "Twice := tmp;")}]})
    d.stopped("breakpoint")
    frames = d.top_frame()
    assert [f["name"] for f in frames] == ["Twice", "Main"], frames
    locals_ref = d.scopes(frames[0]["id"])["Locals"]["variablesReference"]
    assert d.variables(locals_ref)["tmp"]["value"] == "2", frames
    sv = d.request("setVariable", {"variablesReference": locals_ref, "name": "tmp", "value": "40"})["body"]
    assert sv["value"] == "40", sv
    assert d.variables(locals_ref)["tmp"]["value"] == "40"
    main_ref = d.scopes(frames[1]["id"])["Locals"]["variablesReference"]
    sv = d.request("setVariable", {"variablesReference": main_ref, "name": "nested", "value": "100"})["body"]
    assert sv["value"] == "100", sv
    # Queued: this activation still sees its own value ...
    ev = d.request("evaluate", {"expression": "nested", "frameId": frames[1]["id"]})["body"]
    assert ev["result"] == "0", ev
    bad = d.request("setVariable", {"variablesReference": main_ref, "name": "nested", "value": "'text'"}, ok=False)
    assert bad["message"], bad
    d.request("setBreakpoints", {"source": {"path": writes}, "breakpoints": [{"line": line_of(WRITES, "nested := nested + 1;")}]})
    d.request("continue", {"threadId": 1})
    d.stopped("breakpoint")
    frames = d.top_frame()
    local = d.variables(d.scopes(frames[0]["id"])["Locals"]["variablesReference"])
    assert local["doubled"]["value"] == "40" and local["nested"]["value"] == "0", local  # the call returned the written tmp
    d.request("continue", {"threadId": 1})
    d.stopped("breakpoint")
    frames = d.top_frame()
    local = d.variables(d.scopes(frames[0]["id"])["Locals"]["variablesReference"])
    # ... the next activation started with it: 100, then + 1 in the first activation's last statement was overwritten.
    assert local["nested"]["value"] == "100" and local["count"]["value"] == "2", local
    d.finish()

    # ---- 3. the debugger watches statements only while something can stop:
    # after a continue with no breakpoint left the run goes on unwatched;
    # a pause then stops it with its whole stack.
    d = Dap()
    d.start(writes, ["--virtual"], breakpoints={writes: [{"line": line_of(WRITES, "tmp := x * 2;")}]})
    d.stopped("breakpoint")
    assert [f["name"] for f in d.top_frame()] == ["Twice", "Main"]
    d.request("setBreakpoints", {"source": {"path": writes}, "breakpoints": []})
    d.request("continue", {"threadId": 1})
    time.sleep(0.2)
    d.request("pause", {"threadId": 1})
    d.stopped("pause")
    frames = d.top_frame()
    assert frames and frames[-1]["name"] == "Main", frames
    assert len(frames) == 1 or [f["name"] for f in frames] == ["Twice", "Main"], frames
    d.finish()

    # ---- 4. a run the control plane holds (--paused): pause reports that
    # stop, continue resumes it through the plane.
    d = Dap()
    d.start(writes, ["--virtual", "--paused", "--cycles", "3"])
    time.sleep(0.1)
    d.request("pause", {"threadId": 1})
    d.stopped("pause")
    d.request("continue", {"threadId": 1})
    out = d.event("exited")
    assert out["body"]["exitCode"] == 0, out
    d.finish()

    # ---- 5. a long stop on the real clock: the watchdog (40 ms) does not
    # count it (the activation goes on afterwards); PLC time did go on, so
    # the next releases were overruns.
    dog = write(work, "dog.st", WATCHDOG)
    d = Dap()
    d.start(dog, ["--cycles", "4"], breakpoints={dog: [{"line": line_of(WATCHDOG, "count := count + 1;"), "hitCondition": "2"}]})
    d.stopped("breakpoint")
    time.sleep(0.3)
    d.request("setBreakpoints", {"source": {"path": dog}, "breakpoints": []})
    d.request("continue", {"threadId": 1})
    report = d.c.wait(lambda m: m.get("event") == "output" and "cycles" in m["body"]["output"], 30, "run summary")
    out = d.event("exited")
    assert out["body"]["exitCode"] == 0, (out, report)
    assert "WATCHDOG" not in report["body"]["output"], report
    d.finish()
    print("dap runtime: all checks passed")


if __name__ == "__main__":
    main()
