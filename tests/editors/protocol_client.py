"""A minimal client of the base protocol LSP and DAP share (Content-Length
framing over a child process's stdin/stdout), for the tests of `strun lsp`
and `strun debug`. Reads on a thread so that a test can wait for a given
message with a timeout instead of hanging."""
import json
import queue
import subprocess
import threading


class Client:
    def __init__(self, argv, cwd=None):
        self.proc = subprocess.Popen(argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=cwd)
        self.messages = queue.Queue()
        self.seen = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        out = self.proc.stdout
        while True:
            length = None
            while True:
                line = out.readline()
                if not line:
                    self.messages.put(None)
                    return
                line = line.strip()
                if not line:
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value.strip())
            if length is None:
                raise AssertionError("a message without Content-Length from the server")
            body = out.read(length)
            self.messages.put(json.loads(body))

    def send_raw(self, data):
        self.proc.stdin.write(data)
        self.proc.stdin.flush()

    def send(self, message):
        body = json.dumps(message).encode()
        self.send_raw(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def wait(self, predicate, timeout=20, what="message"):
        """The first message (seen before or arriving) that satisfies predicate."""
        for m in self.seen:
            if predicate(m):
                self.seen.remove(m)
                return m
        while True:
            try:
                m = self.messages.get(timeout=timeout)
            except queue.Empty:
                raise AssertionError("timed out waiting for " + what + "; unclaimed: " + json.dumps(self.seen)[:2000])
            if m is None:
                raise AssertionError("the server closed its output while waiting for " + what +
                                     "; stderr: " + self.proc.stderr.read().decode(errors="replace")[:2000])
            if predicate(m):
                return m
            self.seen.append(m)

    def close(self, timeout=20):
        try:
            self.proc.stdin.close()
        except BrokenPipeError:
            pass
        return self.proc.wait(timeout=timeout)
