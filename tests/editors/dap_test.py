"""`strun debug` driven through real Debug Adapter Protocol sessions over
stdin/stdout: every request of the contract, a TwinCAT file, a runtime fault
caught as an exception stop, a step across the end of an activation,
malformed input. Usage: dap_test.py STRUN"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from protocol_client import Client  # noqa: E402

STRUN = sys.argv[1]

PROGRAM = """TYPE E_Mode : (Idle, Busy); END_TYPE

FUNCTION_BLOCK FB_Step
VAR_INPUT
    inc : INT;
END_VAR
VAR_OUTPUT
    acc : INT;
END_VAR
acc := acc + inc;
END_FUNCTION_BLOCK

PROGRAM Main
VAR
    i : INT;
    total : DINT;
    zero : INT := 0;
    r : INT;
    fb : FB_Step;
    arr : ARRAY[1..3] OF INT;
    mode : E_Mode := E_Mode.Idle;
    t : TIME := T#1s500ms;
    name : STRING := 'pump';
END_VAR
(* the first statement is the next line *)

i := i + 1;
total := total + i;
fb(inc := 2);
arr[1] := i;
IF i = 4 THEN
    r := 10 / zero;
END_IF
mode := E_Mode.Busy;
END_PROGRAM
"""

TWINCAT = """<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="MAIN" Id="{2b0c3a7e-5a61-4c1b-9d0e-7f3a6b2c1d4e}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
    nCount : INT;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[nCount := nCount + 1;
nCount := nCount + 10;]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"""


def line_of(text, needle):
    return text[:text.index(needle)].count("\n") + 1


class Dap:
    def __init__(self):
        self.c = Client([STRUN, "debug"])
        self.seq = 0

    def send(self, command, arguments=None):
        self.seq += 1
        m = {"seq": self.seq, "type": "request", "command": command}
        if arguments is not None:
            m["arguments"] = arguments
        self.c.send(m)
        return self.seq

    def request(self, command, arguments=None, ok=True):
        seq = self.send(command, arguments)
        r = self.c.wait(lambda m: m.get("type") == "response" and m.get("request_seq") == seq, 30, command)
        if ok:
            assert r["success"], r
        return r

    def event(self, name, timeout=30):
        return self.c.wait(lambda m: m.get("type") == "event" and m.get("event") == name, timeout, name + " event")

    def stopped(self, reason):
        e = self.event("stopped")
        assert e["body"]["reason"] == reason, e
        return e["body"]

    def top_frame(self, thread=1):
        frames = self.request("stackTrace", {"threadId": thread})["body"]["stackFrames"]
        return frames

    def start(self, program, args, stop_on_entry=False, breakpoints=None, faults=False):
        caps = self.request("initialize", {"adapterID": "strun", "linesStartAt1": True, "columnsStartAt1": True})["body"]
        assert caps["supportsConfigurationDoneRequest"] and caps["supportsConditionalBreakpoints"], caps
        assert any(f["filter"] == "runtime-fault" for f in caps["exceptionBreakpointFilters"]), caps
        self.event("initialized")
        self.request("launch", {"program": program, "args": args, "stopOnEntry": stop_on_entry})
        results = {}
        for path, bps in (breakpoints or {}).items():
            results[path] = self.request("setBreakpoints", {"source": {"path": path}, "breakpoints": bps})["body"]["breakpoints"]
        self.request("setExceptionBreakpoints", {"filters": ["runtime-fault"] if faults else []})
        self.request("configurationDone")
        return results

    def variables(self, ref):
        return {v["name"]: v for v in self.request("variables", {"variablesReference": ref})["body"]["variables"]}

    def scopes(self, frame_id):
        return {s["name"]: s for s in self.request("scopes", {"frameId": frame_id})["body"]["scopes"]}

    def finish(self):
        self.request("disconnect", {"terminateDebuggee": True})
        assert self.c.proc.wait(timeout=30) == 0


def main():
    work = tempfile.mkdtemp(prefix="strun_dap_")
    src = os.path.join(work, "main.st")
    with open(src, "w") as f:
        f.write(PROGRAM)
    first = line_of(PROGRAM, "i := i + 1;")
    comment = line_of(PROGRAM, "(* the first statement")
    call = line_of(PROGRAM, "fb(inc := 2);")
    last = line_of(PROGRAM, "mode := E_Mode.Busy;")
    fault = line_of(PROGRAM, "r := 10 / zero;")

    # ---- 1. entry, moved breakpoint, variables, evaluate, setVariable, steps, exception
    d = Dap()
    bps = d.start(src, ["--virtual", "--cycles", "10"], stop_on_entry=True, faults=True,
                  breakpoints={src: [{"line": comment}, {"line": last}]})[src]
    assert bps[0]["verified"] and bps[0]["line"] == first, bps  # moved from the comment to the statement
    assert bps[1]["verified"] and bps[1]["line"] == last, bps
    threads = d.request("threads")["body"]["threads"]
    assert threads == [{"id": 1, "name": "MainTask"}], threads
    entry = d.stopped("entry")
    assert entry["threadId"] == 1 and entry["allThreadsStopped"], entry
    frames = d.top_frame()
    assert frames[0]["name"] == "Main" and frames[0]["line"] == first and frames[0]["source"]["path"] == src, frames
    # The entry stop was on the first statement already: the next stop is the
    # last statement of this activation, then the first of the next one.
    d.request("continue", {"threadId": 1})
    body = d.stopped("breakpoint")
    assert body["hitBreakpointIds"] == [bps[1]["id"]] and d.top_frame()[0]["line"] == last, body
    d.request("continue", {"threadId": 1})
    body = d.stopped("breakpoint")
    assert body["hitBreakpointIds"] == [bps[0]["id"]], body
    frames = d.top_frame()
    scopes = d.scopes(frames[0]["id"])
    assert {"Locals", "Globals"} <= set(scopes), scopes
    local = d.variables(scopes["Locals"]["variablesReference"])
    assert local["t"]["value"] == "T#1s500ms" and local["mode"]["value"] == "E_Mode#Busy", local
    assert local["name"]["value"] == "'pump'" and local["i"]["type"] == "INT", local
    assert local["arr"]["variablesReference"] > 0 and local["fb"]["variablesReference"] > 0, local
    arr = d.variables(local["arr"]["variablesReference"])
    assert list(arr) == ["[1]", "[2]", "[3]"], arr
    fb = d.variables(local["fb"]["variablesReference"])
    assert "inc" in fb and "acc" in fb, fb
    i_now = int(local["i"]["value"])
    assert i_now == 1, local
    ev = d.request("evaluate", {"expression": "i * 2 + 1", "frameId": frames[0]["id"], "context": "watch"})["body"]
    assert ev["result"] == str(i_now * 2 + 1) and ev["type"] == "INT", ev
    bad = d.request("evaluate", {"expression": "nosuch + 1", "frameId": frames[0]["id"], "context": "repl"}, ok=False)
    assert "undeclared identifier 'nosuch'" in bad["message"], bad
    bad = d.request("evaluate", {"expression": "i +* )", "frameId": frames[0]["id"], "context": "hover"}, ok=False)
    assert bad["message"], bad
    sv = d.request("setVariable", {"variablesReference": scopes["Locals"]["variablesReference"], "name": "i", "value": "2"})["body"]
    assert sv["value"] == "2", sv
    bad = d.request("setVariable", {"variablesReference": scopes["Locals"]["variablesReference"], "name": "i", "value": "TRUE"}, ok=False)
    assert bad["message"], bad
    # next: statement by statement; stepIn into the FB; stepOut back.
    d.request("next", {"threadId": 1})
    d.stopped("step")
    assert d.top_frame()[0]["line"] == first + 1
    d.request("next", {"threadId": 1})
    d.stopped("step")
    assert d.top_frame()[0]["line"] == call
    d.request("stepIn", {"threadId": 1})
    d.stopped("step")
    frames = d.top_frame()
    assert [f["name"] for f in frames] == ["FB_Step", "Main"] and frames[0]["line"] == line_of(PROGRAM, "acc := acc + inc;"), frames
    assert frames[1]["line"] == call, frames
    inputs = d.variables(d.scopes(frames[0]["id"])["Inputs"]["variablesReference"])
    assert inputs["inc"]["value"] == "2", inputs
    d.request("stepOut", {"threadId": 1})
    d.stopped("step")
    frames = d.top_frame()
    assert len(frames) == 1 and frames[0]["line"] == call + 1, frames
    # The step past the last statement stops at the first of the next activation.
    d.request("setBreakpoints", {"source": {"path": src}, "breakpoints": [{"line": last}]})
    d.request("continue", {"threadId": 1})
    d.stopped("breakpoint")
    assert d.top_frame()[0]["line"] == last
    d.request("next", {"threadId": 1})
    d.stopped("step")
    assert d.top_frame()[0]["line"] == first
    # The runtime fault: i was set to 2, so i = 4 in the next activation.
    d.request("setBreakpoints", {"source": {"path": src}, "breakpoints": []})
    d.request("continue", {"threadId": 1})
    body = d.stopped("exception")
    assert body["text"] == "DIV_BY_ZERO" and "DIV_BY_ZERO" in body["description"], body
    frames = d.top_frame()
    assert frames[0]["line"] == fault, frames
    local = d.variables(d.scopes(frames[0]["id"])["Locals"]["variablesReference"])
    assert local["r"]["value"] == "0" and local["i"]["value"] == "4", local  # before the substitute divisor is used
    d.request("continue", {"threadId": 1})
    out = d.event("exited")
    assert out["body"]["exitCode"] == 0, out
    d.event("terminated")
    d.finish()

    # ---- 2. conditions, hit counts, log points; pause; malformed input
    d = Dap()
    bps = d.start(src, ["--virtual"], breakpoints={src: [
        {"line": first + 1, "logMessage": "i is {i} and t is {t}"},
        {"line": call, "condition": "i = 3"},
        {"line": last, "hitCondition": "5"},
        {"line": first, "condition": "i = "},
    ]})[src]
    assert [b["verified"] for b in bps] == [True, True, True, False], bps
    out = d.c.wait(lambda m: m.get("event") == "output" and "i is" in m["body"]["output"])
    assert out["body"]["output"] == "i is 1 and t is T#1s500ms\n", out
    d.stopped("breakpoint")
    frames = d.top_frame()
    assert frames[0]["line"] == call
    ev = d.request("evaluate", {"expression": "i", "frameId": frames[0]["id"]})["body"]
    assert ev["result"] == "3", ev
    d.request("continue", {"threadId": 1})
    d.stopped("breakpoint")
    frames = d.top_frame()
    assert frames[0]["line"] == last
    ev = d.request("evaluate", {"expression": "i", "frameId": frames[0]["id"]})["body"]
    assert ev["result"] == "5", ev  # the fifth time the line was reached
    d.request("setBreakpoints", {"source": {"path": src}, "breakpoints": []})
    d.request("continue", {"threadId": 1})
    # Garbage on the wire: reported and skipped; the session goes on.
    d.c.send_raw(b"Content-Length: 9\r\n\r\n{garbage}")
    d.c.send_raw(b"no header at all\r\n\r\n")
    d.request("pause", {"threadId": 1})
    d.stopped("pause")
    d.request("threads")
    d.finish()

    # ---- 3. a project that does not compile
    broken = os.path.join(work, "broken.st")
    with open(broken, "w") as f:
        f.write("PROGRAM Main\nVAR x : INT; END_VAR\nx := y;\nEND_PROGRAM\n")
    d = Dap()
    d.request("initialize", {"adapterID": "strun"})
    r = d.request("launch", {"program": broken, "args": ["--virtual"]}, ok=False)
    assert "undeclared identifier 'y'" in r["message"] and "broken.st:3:6" in r["message"], r
    d.c.wait(lambda m: m.get("event") == "output" and "undeclared" in m["body"]["output"])
    d.finish()
    # The run options are checked as `strun run` checks them (cli::buildRunOptions): --start past 2116.
    d = Dap()
    d.request("initialize", {"adapterID": "strun"})
    fine = os.path.join(work, "fine.st")
    with open(fine, "w") as f:
        f.write("PROGRAM Main\nVAR x : INT; END_VAR\nx := x + 1;\nEND_PROGRAM\n")
    r = d.request("launch", {"program": fine, "args": ["--virtual", "--start", "DT#2200-01-01-00:00:00"]}, ok=False)
    assert "the PLC calendar runs from" in r["message"], r
    d.finish()

    # ---- 4. TwinCAT: breakpoints and frames on the XML file's lines
    tc = os.path.join(work, "MAIN.TcPOU")
    with open(tc, "w") as f:
        f.write(TWINCAT)
    second = line_of(TWINCAT, "nCount := nCount + 10;")
    d = Dap()
    # --force goes through the live control plane, as under `strun run`: the
    # value is written when every activation starts.
    bps = d.start([tc], ["--virtual", "--cycles", "3", "--force", "MAIN.nCount=5"], breakpoints={tc: [{"line": second}]})[tc]
    assert bps[0]["verified"] and bps[0]["line"] == second, bps
    d.stopped("breakpoint")
    frames = d.top_frame()
    assert frames[0]["line"] == second and frames[0]["source"]["path"] == tc, frames
    local = d.variables(d.scopes(frames[0]["id"])["Locals"]["variablesReference"])
    assert local["nCount"]["value"] == "6", local
    d.request("terminate")
    assert d.c.proc.wait(timeout=30) == 0
    # ---- 5. breakpoints set before launch: verified once the project is compiled
    d = Dap()
    d.request("initialize", {"adapterID": "strun"})
    d.event("initialized")
    early = d.request("setBreakpoints", {"source": {"path": src}, "breakpoints": [{"line": comment}]})["body"]["breakpoints"]
    assert not early[0]["verified"], early
    d.request("launch", {"program": src, "args": ["--virtual", "--cycles", "2"]})
    changed = d.event("breakpoint")["body"]["breakpoint"]
    assert changed["verified"] and changed["line"] == first and changed["id"] == early[0]["id"], changed
    d.request("configurationDone")
    d.stopped("breakpoint")
    d.finish()
    print("dap: all checks passed")


if __name__ == "__main__":
    main()
