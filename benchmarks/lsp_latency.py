#!/usr/bin/env python3
"""Latencies of `strun lsp` on a generated 30 000-line project
(benchmarks/generated_project.sh: 435 function blocks and functions of ~70 lines, one
file each, and a Main calling them all).

usage: benchmarks/lsp_latency.py [path-to-strun] [repeats]

Prints, in milliseconds (best and median of the repeats): the diagnostics
refresh after a change to one file (didChange -> publishDiagnostics), hover,
definition, references, completion after `name.`, and the first compile
after initialize."""
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "editors"))
from protocol_client import Client  # noqa: E402

def main():
    strun = sys.argv[1] if len(sys.argv) > 1 else "build/strun"
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    blocks = 435
    work = tempfile.mkdtemp(prefix="strun_lsp_bench_")
    generator = os.path.join(os.path.dirname(os.path.abspath(__file__)), "generated_project.sh")
    subprocess.run(["bash", generator, "files", str(blocks), work], check=True)
    total_lines = 0
    for name in os.listdir(work):
        with open(os.path.join(work, name)) as f:
            total_lines += f.read().count("\n")
    main_path = os.path.join(work, "main.st")
    with open(main_path) as f:
        main_text = f.read()
    uri = "file://" + main_path
    c = Client([strun, "lsp"])
    ids = [0]

    def request(method, params):
        ids[0] += 1
        rid = ids[0]
        t0 = time.perf_counter()
        c.send({"jsonrpc": "2.0", "id": rid, "method": method, "params": params})
        m = c.wait(lambda m: m.get("id") == rid and "method" not in m, 120, method)
        return (time.perf_counter() - t0) * 1000, m.get("result")

    t0 = time.perf_counter()
    request("initialize", {"processId": None, "rootUri": "file://" + work, "capabilities": {}})
    c.send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
    c.send({"jsonrpc": "2.0", "method": "textDocument/didOpen",
            "params": {"textDocument": {"uri": uri, "languageId": "st", "version": 1, "text": main_text}}})
    c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics", 120, "first diagnostics")
    first = (time.perf_counter() - t0) * 1000
    results = {"diagnostics after a change": [], "hover": [], "definition": [], "references": [], "completion": []}
    call_line = main_text.split("\n").index("b7(enable := TRUE, setpoint := Scale7(raw := total, low := 0, high := 1000));")
    for r in range(repeats):
        edited = main_text + ("\n" * (r % 2))  # a change the project compiles again for
        t0 = time.perf_counter()
        c.send({"jsonrpc": "2.0", "method": "textDocument/didChange",
                "params": {"textDocument": {"uri": uri, "version": r + 2}, "contentChanges": [{"text": edited}]}})
        c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"].get("version") == r + 2, 120, "diagnostics")
        results["diagnostics after a change"].append((time.perf_counter() - t0) * 1000)
        pos = {"line": call_line, "character": 1}
        ms, res = request("textDocument/hover", {"textDocument": {"uri": uri}, "position": pos})
        assert res and "Block7" in res["contents"]["value"], res
        results["hover"].append(ms)
        ms, res = request("textDocument/definition", {"textDocument": {"uri": uri}, "position": {"line": call_line, "character": 33}})
        assert res and res["uri"].endswith("block7.st"), res
        results["definition"].append(ms)
        ms, res = request("textDocument/references", {"textDocument": {"uri": uri}, "position": pos, "context": {"includeDeclaration": True}})
        assert len(res) == 3, res  # the declaration and two uses
        results["references"].append(ms)
    typing = main_text.replace("END_PROGRAM", "b7.\nEND_PROGRAM")
    c.send({"jsonrpc": "2.0", "method": "textDocument/didChange",
            "params": {"textDocument": {"uri": uri, "version": 1000}, "contentChanges": [{"text": typing}]}})
    line = typing.split("\n").index("b7.")
    for r in range(repeats):
        ms, res = request("textDocument/completion", {"textDocument": {"uri": uri}, "position": {"line": line, "character": 3}})
        assert any(i["label"] == "setpoint" for i in res["items"]), res
        results["completion"].append(ms)
    request("shutdown", None)
    c.send({"jsonrpc": "2.0", "method": "exit"})
    c.proc.wait(timeout=30)
    print("strun lsp on %d files, %d lines; %d repeats (ms)" % (blocks + 1, total_lines, repeats))
    print("%-28s %8.1f" % ("initialize -> diagnostics", first))
    for name, values in results.items():
        print("%-28s best %7.1f  median %7.1f" % (name, min(values), statistics.median(values)))


if __name__ == "__main__":
    main()
