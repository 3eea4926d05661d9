"""Integration tests of --modbus and --modbus-client against a real Modbus
peer (pymodbus as client and as device, raw sockets for hostile frames).

    modbus_test.py STRUN CASE      CASE: server | client | hostile | config

Each case starts strun on the real clock, talks to it, and checks what it
answers and what its --dump says at the end. No assertion on wall-clock
speed: waits are generous upper bounds, never measurements."""
import atexit
import json
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

from pymodbus.client import ModbusTcpClient

HERE = os.path.dirname(os.path.abspath(__file__))
STRUN = sys.argv[1]
CASE = sys.argv[2]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what, flush=True)


def wait_until(predicate, seconds=5.0):
    end = time.time() + seconds
    while time.time() < end:
        try:
            if predicate():
                return True
        except Exception:  # the peer not ready yet
            pass
        time.sleep(0.01)
    return False


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


class Strun:
    """strun run ... with --modbus 127.0.0.1:0; learns the port from stderr."""

    def __init__(self, args, serve=True):
        cmd = [STRUN, "run", "--dump"] + (["--modbus", "127.0.0.1:0"] if serve else []) + args
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        atexit.register(lambda: self.proc.poll() is None and self.proc.kill())  # a case that dies early
        self.stderr = []
        self.port = None
        ready = threading.Event()

        def drain():
            for line in self.proc.stderr:
                self.stderr.append(line)
                m = re.match(r"strun: serving modbus tcp://[0-9.]+:(\d+)/", line)
                if m:
                    self.port = int(m.group(1))
                    ready.set()
            ready.set()

        threading.Thread(target=drain, daemon=True).start()
        if serve:
            ready.wait(60)
            if self.port is None:
                raise SystemExit("strun did not start serving: " + "".join(self.stderr))

    def client(self):
        c = ModbusTcpClient("127.0.0.1", port=self.port, timeout=3, retries=0)
        c.connect()
        return c

    def finish(self, interrupt=True):
        # The interactive cases run strun with a long --for and end it with
        # Ctrl-C once their checks are done (docs/cli.md: SIGINT ends a run
        # cleanly, with its --dump): on a loaded machine a short --for ran
        # out while the checks were still waiting for the peer.
        if interrupt and self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        out, _ = self.proc.communicate(timeout=120)
        time.sleep(0.1)
        try:
            return json.loads(out)
        except ValueError:
            raise SystemExit("no --dump JSON; stderr: " + "".join(self.stderr))


def raw_request(port, pdu, unit=1, tid=7):
    """One Modbus TCP request built by hand (for function codes pymodbus does not send); the answer's PDU."""
    s = socket.create_connection(("127.0.0.1", port), timeout=3)
    s.sendall(struct.pack(">HHHB", tid, 0, len(pdu) + 1, unit) + pdu)
    head = s.recv(7)
    length = struct.unpack(">H", head[4:6])[0]
    body = b""
    while len(body) < length - 1:
        body += s.recv(length - 1 - len(body))
    s.close()
    return body


# ---------------------------------------------------------------- server
def case_server():
    run = Strun(["--for", "120s", "--set", "%IX0.3=TRUE", "--set", "%IW5=1234", "--force", "%QW300=7",
                 os.path.join(HERE, "server_image.st")])
    c = run.client()
    # FC 3: the counter of a 1 ms task moves.
    first = c.read_holding_registers(0, 1, slave=1).registers[0]
    check(wait_until(lambda: c.read_holding_registers(0, 1, slave=1).registers[0] != first), "FC3: holding register 0 (%QW0) counts")
    # FC 2 and FC 4: the inputs set with --set, as the program saw them.
    check(wait_until(lambda: c.read_discrete_inputs(0, 8, slave=1).bits[3] is True), "FC2: discrete input 3 is %IX0.3")
    check(wait_until(lambda: c.read_input_registers(5, 1, slave=1).registers[0] == 1234), "FC4: input register 5 is %IW5")
    # FC 1: coil 48 (%QX6.0) is what the program copied from %IX0.3.
    check(wait_until(lambda: c.read_coils(48, 1, slave=1).bits[0] is True), "FC1: coil 48 is %QX6.0")
    check(wait_until(lambda: c.read_holding_registers(12, 1, slave=1).registers[0] == 1234), "holding 12 (%QW12) = %IW5")
    # FC 5: a write to coil 32 (%QX4.0) reaches the program (coil 33 copies it).
    check(not c.write_coil(32, True, slave=1).isError(), "FC5 answered")
    check(wait_until(lambda: c.read_coils(32, 2, slave=1).bits[:2] == [True, True]), "FC5: coil 32 written, program copied it to 33")
    # FC 6: holding 1024 is %MW0; the program answers %MW0 + 1 in holding 10.
    check(not c.write_register(1024, 41, slave=1).isError(), "FC6 answered")
    check(wait_until(lambda: c.read_holding_registers(10, 1, slave=1).registers[0] == 42), "FC6: %MW0 written, %QW10 = 42")
    # FC 15 / FC 16: values the program does not write stay as written.
    check(not c.write_coils(64, [True, False, True, True, False, False, True, False], slave=1).isError(), "FC15 answered")
    check(wait_until(lambda: c.read_coils(64, 8, slave=1).bits[:8] == [True, False, True, True, False, False, True, False]),
          "FC15: coils 64..71 (%QB8) hold what was written")
    check(not c.write_registers(100, [1, 2, 3, 65535], slave=1).isError(), "FC16 answered")
    check(wait_until(lambda: c.read_holding_registers(100, 4, slave=1).registers == [1, 2, 3, 65535]), "FC16: holding 100..103")
    check(not c.write_registers(1030, [7, 8], slave=1).isError(), "FC16 into %MW answered")
    check(wait_until(lambda: c.read_holding_registers(1030, 2, slave=1).registers == [7, 8]), "FC16: holding 1030..1031 = %MW6..7")
    # FC 23: write then read in one request.
    r = c.readwrite_registers(read_address=200, read_count=2, write_address=200, write_registers=[5, 6], slave=1)
    check(not r.isError() and r.registers == [5, 6], "FC23 answers the registers it wrote")
    check(wait_until(lambda: c.read_holding_registers(200, 2, slave=1).registers == [5, 6]), "FC23: the write reached the image")
    # A write is a write, not a force: the program goes on counting from it.
    c.write_register(0, 30000, slave=1)
    check(wait_until(lambda: 30000 < c.read_holding_registers(0, 1, slave=1).registers[0] < 40000), "a write to %QW0 moves the counter once")
    # A force holds against a Modbus write.
    c.write_register(300, 99, slave=1)
    time.sleep(0.1)
    check(c.read_holding_registers(300, 1, slave=1).registers == [7], "a forced %QW300 stays 7 after a Modbus write")
    # The tables overlap where the image does: %QW0 is coils 0..15.
    c.write_register(400, 0x8001, slave=1)
    check(wait_until(lambda: c.read_coils(6400, 16, slave=1).bits[:16] == [True] + [False] * 14 + [True]),
          "holding 400 (%QW400) is coils 6400..6415 (%QX800.0..%QX801.7), bit 0 first")
    # Exceptions: illegal data address outside the tables, illegal function for a code not served.
    for what, r in [("holding 2048", c.read_holding_registers(2048, 1, slave=1)),
                    ("holding 2040..2055", c.read_holding_registers(2040, 16, slave=1)),
                    ("input register 1024", c.read_input_registers(1024, 1, slave=1)),
                    ("coil 8192", c.read_coils(8192, 1, slave=1)),
                    ("discrete input 8192", c.read_discrete_inputs(8192, 1, slave=1)),
                    ("write holding 2048", c.write_register(2048, 1, slave=1))]:
        check(r.isError() and r.exception_code == 2, what + ": exception 2 (illegal data address)")
    answer = raw_request(run.port, bytes([0x41, 0, 0, 0, 1]))
    check(answer == bytes([0xC1, 0x01]), "function 0x41: exception 1 (illegal function), got " + answer.hex())
    # Consistency: 40 registers written in one activation are never half old, half new.
    mixed = 0
    reads = 0
    end = time.time() + 1.5
    while time.time() < end:
        regs = c.read_holding_registers(20, 40, slave=1).registers
        reads += 1
        if len(set(regs)) != 1:
            mixed += 1
    check(reads > 50 and mixed == 0, "consistency: %d of %d reads of holding 20..59 mixed two activations" % (mixed, reads))
    # 16 clients at once, each with its own connection.
    clients = [run.client() for _ in range(16)]
    results = []

    def poll(cl):
        ok = all(not cl.read_holding_registers(0, 10, slave=1).isError() for _ in range(20))
        results.append(ok)

    threads = [threading.Thread(target=poll, args=(cl,)) for cl in clients]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    check(results == [True] * 16, "16 clients at once: every request answered")
    for cl in clients:
        cl.close()
    c.close()
    dump = run.finish()
    check(run.proc.returncode == 0 and dump["state"] == "RUN", "the run ends in RUN, exit 0")
    print("cycles", dump["tasks"][0]["cycles"], "overruns", dump["tasks"][0]["overruns"])


# ---------------------------------------------------------------- client
def device(port, values):
    p = subprocess.Popen([sys.executable, os.path.join(HERE, "device.py"), str(port), json.dumps(values)],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    check(p.stdout.readline().strip() == "ready", "the device starts")
    return p


def case_client():
    port = free_port()
    mapping = {"devices": [{"name": "plant", "host": "127.0.0.1", "port": port, "unit": 1,
                            "period": "T#20ms", "timeout": "T#200ms",
                            "read": [{"table": "discrete_inputs", "start": 0, "count": 8, "to": "%IX0.0"},
                                     {"table": "input_registers", "start": 0, "count": 2, "to": "%IW2"}],
                            "write": [{"table": "coils", "start": 0, "count": 8, "from": "%QX0.0"},
                                      {"table": "holding_registers", "start": 0, "count": 1, "from": "%QW2"}]}]}
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(mapping, f)
    dev = device(port, {"di": [1, 0, 1, 1, 0, 0, 0, 1], "ir": [111, 222]})
    run = Strun(["--for", "120s", "--modbus-client", f.name, os.path.join(HERE, "client_copy.st")])
    peer = ModbusTcpClient("127.0.0.1", port=port, timeout=3, retries=0)
    peer.connect()
    check(wait_until(lambda: peer.read_holding_registers(0, 1, slave=1).registers[0] == 333),
          "inputs read from the device, outputs written back: holding 0 = 111 + 222")
    check(wait_until(lambda: peer.read_coils(0, 8, slave=1).bits[:8] == [True, False, True, True, False, False, False, True]),
          "coils 0..7 = discrete inputs 0..7 through %IB0 -> %QB0")
    peer.close()
    # The device stops: strun keeps the inputs it had (seen through --modbus).
    dev.kill()
    dev.wait()
    time.sleep(1.0)
    served = run.client()
    check(served.read_input_registers(2, 2, slave=1).registers == [111, 222], "during the outage %IW2..3 keep 111, 222")
    time.sleep(0.5)
    # It comes back with other values: strun reconnects and uses them.
    dev = device(port, {"di": [0] * 8, "ir": [1000, 5]})
    peer = ModbusTcpClient("127.0.0.1", port=port, timeout=3, retries=0)
    peer.connect()
    check(wait_until(lambda: peer.read_holding_registers(0, 1, slave=1).registers[0] == 1005, 10),
          "after the device is back, strun reconnects: holding 0 = 1000 + 5")
    check(served.read_input_registers(2, 2, slave=1).registers == [1000, 5], "%IW2..3 follow the device again")
    peer.close()
    served.close()
    dump = run.finish()
    dev.kill()
    faults = [d for d in dump["diagnostics"] if d["code"] == "IO_FAULT"]
    check(len(faults) == 1, "IO_FAULT once per outage (got %d)" % len(faults))
    check(all("plant" in d["message"] for d in faults), "the IO_FAULT message names the device")
    check(dump["state"] == "RUN" and run.proc.returncode == 0, "the PLC kept running")
    os.unlink(f.name)


# ---------------------------------------------------------------- hostile
def case_hostile():
    run = Strun(["--for", "120s", os.path.join(HERE, "server_image.st")])
    good = run.client()
    check(not good.read_holding_registers(0, 1, slave=1).isError(), "a good client is answered")
    attacks = {
        "garbage": bytes(range(256)) * 2,
        "wrong protocol id": struct.pack(">HHHB", 1, 0x1234, 6, 1) + bytes([3, 0, 0, 0, 1]),
        "length says more than comes": struct.pack(">HHHB", 1, 0, 200, 1) + bytes([3, 0, 0, 0, 1]),
        "zero length": struct.pack(">HHHB", 1, 0, 0, 1),
    }
    for what, frame in attacks.items():
        s = socket.create_connection(("127.0.0.1", run.port), timeout=3)
        s.sendall(frame)
        s.settimeout(3)
        try:
            data = s.recv(300)
            closed = data == b"" or s.recv(300) == b""
        except socket.timeout:
            closed = False
        except ConnectionResetError:
            closed = True
        s.close()
        check(closed, "malformed frame (%s): its connection is closed" % what)
        check(not good.read_holding_registers(0, 1, slave=1).isError(), "after '%s' the good client is still answered" % what)
    # A request that is well framed but inconsistent (100 registers, 1 byte of data): an exception, not a write.
    answer = raw_request(run.port, bytes([16, 0, 0, 0, 100, 1, 9]))
    check(answer[:1] == bytes([0x90]), "FC16 with a byte count that does not match: an exception answer, got " + answer.hex())
    # A frame trickled byte by byte holds its own connection only.
    slow = socket.create_connection(("127.0.0.1", run.port), timeout=5)
    slow.sendall(struct.pack(">HHHB", 1, 0, 6, 1)[:3])
    check(not good.read_holding_registers(0, 1, slave=1).isError(), "a trickled frame does not hold other clients")
    slow.close()
    # A flood of connections: the ones over the limit are closed, the run goes on.
    flood = []
    for _ in range(200):
        try:
            flood.append(socket.create_connection(("127.0.0.1", run.port), timeout=3))
        except OSError:
            break
    check(len(flood) > 32, "the flood's connections are accepted (and the extra ones closed)")
    for s in flood:
        s.close()
    check(wait_until(lambda: not run.client().read_holding_registers(0, 1, slave=1).isError(), 10),
          "after the flood a new client is answered")
    # A request flood on one connection is answered at a bounded rate, the others too.
    t_end = time.time() + 1.0
    n = 0
    while time.time() < t_end:
        good.read_holding_registers(0, 100, slave=1)
        n += 1
    check(n > 10, "a request flood is still answered (%d in 1 s)" % n)
    good.close()
    dump = run.finish()
    check(dump["state"] == "RUN" and run.proc.returncode == 0, "the PLC kept running through every attack")
    print("cycles", dump["tasks"][0]["cycles"], "overruns", dump["tasks"][0]["overruns"], "(not asserted: shared CI machines)")


# ---------------------------------------------------------------- config
def case_config():
    prog = os.path.join(HERE, "client_copy.st")

    def strun(args):
        p = subprocess.run([STRUN, "run"] + args + [prog], capture_output=True, text=True, timeout=60)
        return p.returncode, p.stderr

    def mapping(text):
        f = tempfile.NamedTemporaryFile("w", suffix=".json", delete=False)
        f.write(text)
        f.close()
        return f.name

    code, err = strun(["--virtual", "--modbus", "5020"])
    check(code == 2 and "--virtual" in err, "--modbus with --virtual exits 2")
    good = '{"devices": [{"name": "p", "host": "127.0.0.1", "port": 5020, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]}]}'
    code, err = strun(["--virtual", "--modbus-client", mapping(good)])
    check(code == 2 and "--virtual" in err, "--modbus-client with --virtual exits 2")
    code, err = strun(["--modbus", "nothing"])
    check(code == 2, "--modbus with a bad PORT exits 2")
    cases = [
        ('{"devices": [\n  {"name": "p",\n   "host": }]}', r":3:\d+: invalid JSON", "invalid JSON names the line"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "registers", "start": 0, "count": 1, "to": "%IW0"}]}]}',
         r"devices\[0\]\.read\[0\]\.table", "a wrong table"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "write": [{"table": "input_registers", "start": 0, "count": 1, "from": "%QW0"}]}]}',
         r"devices\[0\]\.write\[0\]\.table", "an input table to write"),
        ('{"devices": [{"name": "p", "host": "h", "port": 70000, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]}]}',
         r"devices\[0\]\.port", "a port out of range"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%ZX0.0"}]}]}',
         r"devices\[0\]\.read\[0\]\.to", "an unknown address"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "coils", "start": 0, "count": 1, "to": "%QX0.0"}]}]}',
         r"devices\[0\]\.read\[0\]\.to", "a read into outputs"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "input_registers", "start": 0, "count": 4, "to": "%IW0"},'
         '{"table": "input_registers", "start": 10, "count": 1, "to": "%IW3"}]}]}',
         r"devices\[0\]\.read\[1\]: overlaps", "overlapping reads"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "input_registers", "start": 0, "count": 10, "to": "%IW32767"}]}]}',
         r"devices\[0\]\.read\[0\]\.to", "a range past the image"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "period": "fast", "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]}]}',
         r"devices\[0\]\.period", "a period that is no duration"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "perod": "T#1s", "read": [{"table": "coils", "start": 0, "count": 1, "to": "%IX0.0"}]}]}',
         r"devices\[0\]\.perod: unknown field", "an unknown field"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "coils", "start": 65535, "count": 2, "to": "%IX0.0"}]}]}',
         r"devices\[0\]\.read\[0\]\.count", "start + count past 65535"),
        ('{"devices": [{"name": "p", "host": "h", "port": 5020, "read": [{"table": "coils", "start": 0, "count": 0, "to": "%IX0.0"}]}]}',
         r"devices\[0\]\.read\[0\]\.count", "a count of 0"),
    ]
    for text, pattern, what in cases:
        code, err = strun(["--modbus-client", mapping(text)])
        check(code == 2 and re.search(pattern, err) is not None, what + ": exit 2 naming it (got %d: %s)" % (code, err.strip()))
        check(err.count("\n") == 1, what + ": one line")


# ---------------------------------------------------------------- bench
def case_bench():
    """programs/modbus_bench: the tank device and its controller, on a free port."""
    bench = os.path.join(HERE, "..", "..", "programs", "modbus_bench")
    port = free_port()
    mapping = json.load(open(os.path.join(bench, "mapping.json")))
    mapping["devices"][0]["port"] = port
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
        json.dump(mapping, f)
    plant = subprocess.Popen([sys.executable, os.path.join(bench, "plant.py"), str(port)], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True)
    check(plant.stdout.readline().startswith("plant:"), "the plant starts")
    run = Strun(["--for", "12s", "--modbus-client", f.name, os.path.join(bench, "tank_control.st")], serve=False)
    dump = run.finish(interrupt=False)
    plant.kill()
    tank = dump["programs"]["Tank"]
    print("pumpStarts", tank["pumpStarts"], "minLevel", tank["minLevel"], "maxLevel", tank["maxLevel"])
    check(tank["pumpStarts"] >= 1, "the controller started the pump")
    check(35.0 <= tank["minLevel"] and tank["maxLevel"] <= 65.0, "the level stayed in the 40..60 % band (give or take a poll)")
    check(not [d for d in dump["diagnostics"] if d["code"] == "IO_FAULT"], "no IO_FAULT")
    os.unlink(f.name)


{"bench": case_bench, "server": case_server, "client": case_client, "hostile": case_hostile, "config": case_config}[CASE]()
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("ok")
