"""`strun lsp` driven through a real LSP session over stdin/stdout: every
request of the contract, a TwinCAT file, malformed input.
Usage: lsp_test.py STRUN"""
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from protocol_client import Client  # noqa: E402

STRUN = sys.argv[1]

TYPES_ST = """TYPE E_State : (Idle, Running, Faulted); END_TYPE

TYPE ST_Point :
STRUCT
    x : INT;
    y : INT;
END_STRUCT
END_TYPE

VAR_GLOBAL
    gCount : DINT;
END_VAR

FUNCTION F_Add : INT
VAR_INPUT
    a : INT;
    b : INT;
END_VAR
F_Add := a + b;
END_FUNCTION
"""

BLOCKS_ST = """FUNCTION_BLOCK FB_Counter
VAR_INPUT
    enable : BOOL;
END_VAR
VAR_OUTPUT
    count : INT;
END_VAR
VAR
    state : E_State;
    where : ST_Point;
END_VAR
IF enable THEN
    count := count + 1;
    state := E_State#Running;
END_IF
METHOD Reset : BOOL
VAR_INPUT
    keep : BOOL;
END_VAR
count := 0;
Reset := TRUE;
END_METHOD
ACTION Clear:
    count := 0;
END_ACTION
PROPERTY Total : INT
GET
    Total := count;
END_GET
END_PROPERTY
END_FUNCTION_BLOCK
"""

MAIN_ST = """PROGRAM Main
VAR
    counter : FB_Counter;
    p : ST_Point;
    sum : INT;
END_VAR
counter(enable := TRUE);
p.x := F_Add(a := 1, b := 2);
sum := counter.count + p.x;
gCount := gCount + 1;
END_PROGRAM
"""

TWINCAT = """<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="FB_Valve" Id="{2b0c3a7e-5a61-4c1b-9d0e-7f3a6b2c1d4e}" SpecialFunc="None">
    <Declaration><![CDATA[FUNCTION_BLOCK FB_Valve
VAR_INPUT
    bOpen : BOOL;
END_VAR
VAR_OUTPUT
    bIsOpen : BOOL;
END_VAR
]]></Declaration>
    <Implementation>
      <ST><![CDATA[bIsOpen := bOpen;
gCount := gCount + 2;]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>
"""


def uri(path):
    return "file://" + path


def pos_of(text, needle, nth=0, offset=0):
    """0-based line and character of the nth occurrence of needle (+offset)."""
    at = -1
    for _ in range(nth + 1):
        at = text.index(needle, at + 1)
    at += offset
    line = text.count("\n", 0, at)
    col = at - (text.rfind("\n", 0, at) + 1)
    return {"line": line, "character": col}


def main():
    work = tempfile.mkdtemp(prefix="strun_lsp_")
    files = {"types.st": TYPES_ST, "blocks.st": BLOCKS_ST, "main.st": MAIN_ST, "FB_Valve.TcPOU": TWINCAT}
    for name, text in files.items():
        with open(os.path.join(work, name), "w") as f:
            f.write(text)
    paths = {name: os.path.join(work, name) for name in files}
    c = Client([STRUN, "lsp"])
    next_id = [0]

    def request(method, params, timeout=20):
        next_id[0] += 1
        rid = next_id[0]
        c.send({"jsonrpc": "2.0", "id": rid, "method": method, "params": params})
        m = c.wait(lambda m: m.get("id") == rid and "method" not in m, timeout, method)
        assert "error" not in m, (method, m)
        return m["result"]

    def notify(method, params):
        c.send({"jsonrpc": "2.0", "method": method, "params": params})

    def diagnostics_for(path, timeout=20):
        return c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri(path),
                      timeout, "diagnostics of " + path)["params"]

    # A request before initialize is refused, not answered.
    c.send({"jsonrpc": "2.0", "id": 999, "method": "textDocument/hover", "params": {}})
    early = c.wait(lambda m: m.get("id") == 999)
    assert early["error"]["code"] == -32002, early

    init = request("initialize", {"processId": None, "rootUri": uri(work), "capabilities": {},
                                  "initializationOptions": {"target": "generic", "strict": False}})
    caps = init["capabilities"]
    for cap in ("hoverProvider", "definitionProvider", "referencesProvider", "documentSymbolProvider"):
        assert caps[cap], cap
    assert "." in caps["completionProvider"]["triggerCharacters"]
    assert "(" in caps["signatureHelpProvider"]["triggerCharacters"]
    notify("initialized", {})

    # ---- diagnostics: an open document with a mistake, the same as `strun check`
    broken = MAIN_ST.replace("sum := counter.count + p.x;", "sum := counter.count + p.z;\n    sum := gCount;")
    notify("textDocument/didOpen", {"textDocument": {"uri": uri(paths["main.st"]), "languageId": "iec-st", "version": 1, "text": broken}})
    d = diagnostics_for(paths["main.st"])
    with open(os.path.join(work, "broken_copy.st"), "w") as f:
        f.write(broken)
    check = subprocess.run([STRUN, "check", "--diagnostics-format", "json", paths["types.st"], paths["blocks.st"],
                            os.path.join(work, "broken_copy.st"), paths["FB_Valve.TcPOU"]], capture_output=True, text=True)
    os.remove(os.path.join(work, "broken_copy.st"))
    expected = [json.loads(l) for l in check.stderr.splitlines() if l.startswith("{")]
    expected = [e for e in expected if e["file"].endswith("broken_copy.st")]
    got = d["diagnostics"]
    assert len(got) == len(expected) and expected, (got, expected)
    for g, e in zip(got, expected):
        assert g["message"] == e["message"], (g, e)
        assert g["code"] == e["code"], (g, e)
        assert g["severity"] == (1 if e["severity"] == "error" else 2), (g, e)
        assert g["range"]["start"] == {"line": e["line"] - 1, "character": e["column"] - 1}, (g, e)
        assert g["range"]["end"]["character"] > g["range"]["start"]["character"], g
    assert any(g["severity"] == 1 for g in got) and any(g["severity"] == 2 for g in got), got
    # Notes come as related information (the undeclared member names its type).
    assert any("relatedInformation" in g for g in got) or all(not e["notes"] for e in expected), got

    # Fixing the text refreshes the diagnostics.
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 2},
                                      "contentChanges": [{"text": MAIN_ST}]})
    d = diagnostics_for(paths["main.st"])
    assert d["diagnostics"] == [] and d["version"] == 2, d

    # An incremental change (a range) works too: `p.x` -> `p.q` on the sum line.
    at = pos_of(MAIN_ST, "p.x;", 0, 2)
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 3},
                                      "contentChanges": [{"range": {"start": at, "end": {"line": at["line"], "character": at["character"] + 1}},
                                                          "text": "q"}]})
    d = diagnostics_for(paths["main.st"])
    assert len(d["diagnostics"]) == 1 and "'q'" in d["diagnostics"][0]["message"], d
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 4},
                                      "contentChanges": [{"text": MAIN_ST}]})
    diagnostics_for(paths["main.st"])

    # ---- only the changed file is parsed again (decision 0270): the syntax
    # error of another open document is reported unchanged after an edit of
    # main.st (its parse kept), and as `strun check` reports it; fixing it
    # brings the project back.
    bad_blocks = BLOCKS_ST.replace("count := count + 1;", "count := count + ;", 1)
    notify("textDocument/didOpen", {"textDocument": {"uri": uri(paths["blocks.st"]), "languageId": "iec-st", "version": 1, "text": bad_blocks}})
    first = diagnostics_for(paths["blocks.st"])["diagnostics"]
    with open(os.path.join(work, "bad_blocks_copy.st"), "w") as f:
        f.write(bad_blocks)
    check = subprocess.run([STRUN, "check", "--diagnostics-format", "json", paths["types.st"], os.path.join(work, "bad_blocks_copy.st"),
                            paths["main.st"], paths["FB_Valve.TcPOU"]], capture_output=True, text=True)
    os.remove(os.path.join(work, "bad_blocks_copy.st"))
    expected = [json.loads(l) for l in check.stderr.splitlines() if l.startswith("{")]
    expected = [(e["message"], e["line"]) for e in expected if e["file"].endswith("bad_blocks_copy.st")]
    assert expected and [(g["message"], g["range"]["start"]["line"] + 1) for g in first] == expected, (first, expected)
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 41},
                                      "contentChanges": [{"text": MAIN_ST + "\n"}]})
    again = c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri(paths["blocks.st"])
                   and m["params"].get("version") == 1, 20, "blocks.st after main.st changed")["params"]["diagnostics"]
    assert again == first, (again, first)
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["blocks.st"]), "version": 2},
                                      "contentChanges": [{"text": BLOCKS_ST}]})
    fixed = diagnostics_for(paths["blocks.st"])
    assert fixed["version"] == 2 and all(g["severity"] == 2 for g in fixed["diagnostics"]), fixed  # warnings only (an unused variable)
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 42},
                                      "contentChanges": [{"text": MAIN_ST}]})
    fixed = c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri(paths["main.st"])
                   and m["params"].get("version") == 42, 20, "main.st v42")["params"]
    assert fixed["diagnostics"] == [], fixed
    c.seen = [m for m in c.seen if m.get("method") != "textDocument/publishDiagnostics"]  # the older refreshes
    # A new document that sorts before every file shifts their indices in the
    # compile: they are parsed again, and positions still come out right.
    first_path = os.path.join(work, "aaa_new.st")
    first_text = "PROGRAM Extra\nVAR\n    c2 : FB_Counter;\nEND_VAR\nc2(enable := FALSE);\nc2.count := nothere;\nEND_PROGRAM\n"
    notify("textDocument/didOpen", {"textDocument": {"uri": uri(first_path), "languageId": "iec-st", "version": 1, "text": first_text}})
    extra = diagnostics_for(first_path)["diagnostics"]
    assert [(g["message"], g["range"]["start"]) for g in extra] == [("undeclared identifier 'nothere'", {"line": 5, "character": 12})], extra
    loc = request("textDocument/definition", {"textDocument": {"uri": uri(first_path)}, "position": {"line": 2, "character": 12}})
    assert loc["uri"] == uri(paths["blocks.st"]) and loc["range"]["start"] == pos_of(BLOCKS_ST, "FB_Counter"), loc
    h = request("textDocument/hover", {"textDocument": {"uri": uri(paths["main.st"])}, "position": pos_of(MAIN_ST, "counter(", 0, 2)})
    assert "counter : FB_Counter" in h["contents"]["value"] and "main.st:3" in h["contents"]["value"], h
    notify("textDocument/didClose", {"textDocument": {"uri": uri(first_path)}})
    c.wait(lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri(first_path)
           and m["params"]["diagnostics"] == [], 20, "aaa_new.st cleared")
    c.seen = [m for m in c.seen if m.get("method") != "textDocument/publishDiagnostics"]

    main_uri = {"uri": uri(paths["main.st"])}

    # ---- hover: a variable's type and where it is declared; a POU's signature
    h = request("textDocument/hover", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "counter(", 0, 2)})
    assert "counter : FB_Counter" in h["contents"]["value"] and "main.st:3" in h["contents"]["value"], h
    h = request("textDocument/hover", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "F_Add(", 0, 1)})
    assert "FUNCTION F_Add(a : INT; b : INT) : INT" in h["contents"]["value"], h
    h = request("textDocument/hover", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "gCount :=", 0, 1)})
    assert "gCount : DINT" in h["contents"]["value"] and "types.st:11" in h["contents"]["value"], h

    # ---- definition across files: a member, a POU, a global, a type
    loc = request("textDocument/definition", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "count +", 0, 1)})
    assert loc["uri"] == uri(paths["blocks.st"]) and loc["range"]["start"] == pos_of(BLOCKS_ST, "count : INT"), loc
    loc = request("textDocument/definition", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "F_Add(")})
    assert loc["uri"] == uri(paths["types.st"]) and loc["range"]["start"] == pos_of(TYPES_ST, "F_Add : INT"), loc
    loc = request("textDocument/definition", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "ST_Point", 0, 3)})
    assert loc["uri"] == uri(paths["types.st"]) and loc["range"]["start"] == pos_of(TYPES_ST, "ST_Point :"), loc
    loc = request("textDocument/definition", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "a := 1")})
    assert loc["uri"] == uri(paths["types.st"]) and loc["range"]["start"] == pos_of(TYPES_ST, "a : INT"), loc
    blocks_uri = {"uri": uri(paths["blocks.st"])}
    loc = request("textDocument/definition", {"textDocument": blocks_uri, "position": pos_of(BLOCKS_ST, "Running;", 0, 2)})
    assert loc["uri"] == uri(paths["types.st"]) and loc["range"]["start"] == pos_of(TYPES_ST, "Running"), loc

    # ---- references: a global used in three files (TwinCAT included)
    refs = request("textDocument/references", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "gCount"),
                                               "context": {"includeDeclaration": True}})
    by_file = sorted((os.path.basename(r["uri"][7:]), r["range"]["start"]["line"]) for r in refs)
    assert ("types.st", 10) in by_file and by_file.count(("main.st", 9)) == 2 and by_file.count(("FB_Valve.TcPOU", 13)) == 2, by_file
    refs = request("textDocument/references", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "gCount"),
                                               "context": {"includeDeclaration": False}})
    assert len(refs) == 4, refs

    # ---- document symbols: POUs and types, methods / actions / properties nested
    syms = request("textDocument/documentSymbol", {"textDocument": blocks_uri})
    assert [s["name"] for s in syms] == ["FB_Counter"], syms
    children = {s["name"]: s["kind"] for s in syms[0]["children"]}
    assert children == {"Reset": 6, "Clear": 6, "Total": 7}, children
    syms = request("textDocument/documentSymbol", {"textDocument": {"uri": uri(paths["types.st"])}})
    assert {s["name"] for s in syms} >= {"E_State", "ST_Point", "F_Add"}, syms

    # ---- completion: members after `name.`, else names in scope and keywords
    typing = MAIN_ST.replace("gCount := gCount + 1;", "gCount := gCount + 1;\ncounter.")
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 5},
                                      "contentChanges": [{"text": typing}]})
    comp = request("textDocument/completion", {"textDocument": main_uri, "position": pos_of(typing, "counter.\n", 0, 8)})
    labels = {i["label"] for i in comp["items"]}
    assert {"enable", "count", "Reset", "Clear", "Total"} <= labels and "state" not in labels, labels
    comp = request("textDocument/completion", {"textDocument": main_uri, "position": pos_of(typing, "sum :=")})
    labels = {i["label"] for i in comp["items"]}
    assert {"counter", "p", "sum", "gCount", "F_Add", "FB_Counter", "ST_Point", "IF", "END_IF"} <= labels, labels

    # ---- signature help inside a call's parentheses
    calling = MAIN_ST.replace("gCount := gCount + 1;", "gCount := F_Add(1, ")
    notify("textDocument/didChange", {"textDocument": {"uri": uri(paths["main.st"]), "version": 6},
                                      "contentChanges": [{"text": calling}]})
    sig = request("textDocument/signatureHelp", {"textDocument": main_uri, "position": pos_of(calling, "F_Add(1, ", 0, 9)})
    assert sig["signatures"][0]["label"].startswith("F_Add(a : INT, b : INT)") and sig["activeParameter"] == 1, sig

    # ---- TwinCAT: positions are the XML file's own
    valve = {"uri": uri(paths["FB_Valve.TcPOU"])}
    h = request("textDocument/hover", {"textDocument": valve, "position": pos_of(TWINCAT, "bOpen;", 0, 1)})
    assert "bOpen : BOOL" in h["contents"]["value"] and "FB_Valve.TcPOU:6" in h["contents"]["value"], h
    assert h["range"]["start"] == pos_of(TWINCAT, "bOpen;"), h
    loc = request("textDocument/definition", {"textDocument": valve, "position": pos_of(TWINCAT, "bOpen;")})
    assert loc["range"]["start"] == pos_of(TWINCAT, "bOpen : BOOL"), loc
    syms = request("textDocument/documentSymbol", {"textDocument": valve})
    assert syms[0]["name"] == "FB_Valve" and syms[0]["selectionRange"]["start"] == pos_of(TWINCAT, "FB_Valve\n"), syms
    notify("textDocument/didOpen", {"textDocument": {"uri": uri(paths["FB_Valve.TcPOU"]), "languageId": "xml", "version": 1,
                                                     "text": TWINCAT.replace("bIsOpen := bOpen;", "bIsOpen := bOpne;")}})
    d = diagnostics_for(paths["FB_Valve.TcPOU"])
    assert len(d["diagnostics"]) == 1 and d["diagnostics"][0]["range"]["start"] == pos_of(TWINCAT, "bOpen;"), d

    # ---- malformed input: the server answers or ignores, and keeps serving
    c.send_raw(b"this is not a header\r\n\r\n")
    err = c.wait(lambda m: m.get("id") is None and "error" in m)
    assert err["error"]["code"] == -32700, err
    c.send_raw(b"Content-Length: 12\r\n\r\n{not json!!}")
    err = c.wait(lambda m: m.get("id") is None and "error" in m)
    assert err["error"]["code"] == -32700, err
    c.send_raw(b"Content-Length: 5\r\n\r\n[1,2]")
    c.wait(lambda m: m.get("id") is None and "error" in m)
    huge = b"x" * (70 << 20)
    c.send_raw(b"Content-Length: %d\r\n\r\n" % len(huge) + huge)
    err = c.wait(lambda m: m.get("id") is None and "error" in m, 60)
    assert "limit" in err["error"]["message"], err
    big_text = "PROGRAM Big\nVAR x : INT; END_VAR\n" + "x := x + 1;\n" * 100000 + "END_PROGRAM\n"
    notify("textDocument/didOpen", {"textDocument": {"uri": uri(os.path.join(work, "big.st")), "languageId": "st", "version": 1, "text": big_text}})
    diagnostics_for(os.path.join(work, "big.st"), 60)
    c.send({"jsonrpc": "2.0", "id": 4242, "method": "no/such/method", "params": {}})
    assert c.wait(lambda m: m.get("id") == 4242)["error"]["code"] == -32601
    c.send({"jsonrpc": "2.0", "id": 4243, "method": "textDocument/hover", "params": {"textDocument": 5}})
    assert c.wait(lambda m: m.get("id") == 4243)["error"]["code"] == -32602
    # Half a message: its header promises more than comes before the next one.
    # Half a message: its header promises more than comes before the next
    # one; the server reports it and serves the next.
    c.send_raw(b"Content-Length: 40\r\n\r\n{\"jsonrpc\": \"2.0\",")
    h = request("textDocument/hover", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "counter(", 0, 2)})
    assert h and "FB_Counter" in h["contents"]["value"], h
    c.wait(lambda m: m.get("id") is None and "error" in m)
    # Garbage without a line end right before a message.
    c.send_raw(b"@@@garbage@@@")
    h = request("textDocument/hover", {"textDocument": main_uri, "position": pos_of(MAIN_ST, "counter(", 0, 2)})
    assert h and "FB_Counter" in h["contents"]["value"], h

    request("shutdown", None)
    notify("exit", None)
    assert c.proc.wait(timeout=20) == 0
    print("lsp: all checks passed")


if __name__ == "__main__":
    main()
