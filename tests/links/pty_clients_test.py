#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue #14 on the real binary: `robuterd --sim --pty A --pty B`. A client on A leaves; then
one-shot clients (`printf … > A`) still stop and move the robot, each one starts a fresh session,
a second robuterd on A is refused (flock), and a killed robuterd leaves nothing that stops the
next one. The robot's state is read on B (XE, and the XS status stream's wheel speeds). Waits
are liveness bounds only."""
import os
import select
import signal
import subprocess
import sys
import tempfile
import time
import tty

robuterd = os.path.abspath(sys.argv[1])
T0 = time.time()
tmp = tempfile.mkdtemp(prefix="robuter-links-")
A, B = os.path.join(tmp, "a.pty"), os.path.join(tmp, "b.pty")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from check import Checks  # noqa: E402  (tests/support/check.py)

check = Checks()


class Client:
    """A client holding a pty open: line requests, and the status stream's lines."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self.fd)
        self.buf = b""
        self.sent = []  # (seconds since start, line) written, for a failure's transcript
        self.got = []   # (seconds since start, line) read: replies and stream lines

    def transcript(self, last=24):
        """The last lines written and read, and how many stream lines came: what a failure shows."""
        stream = [t for t, line in self.got if line.startswith("@")]
        out = [f"{len(self.sent)} lines sent, {len(self.got)} read ({len(stream)} stream lines"
               + (f", last at {stream[-1]:.2f} s)" if stream else ")")]
        lines = [(t, ">", line) for t, line in self.sent] + [(t, "<", line) for t, line in self.got]
        out += [f"  {way} {t:7.2f} {line}" for t, way, line in sorted(lines, key=lambda x: x[0])[-last:]]
        return "\n".join(out)

    def lines(self, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline:
            while b"\r" in self.buf:
                line, self.buf = self.buf.split(b"\r", 1)
                self.got.append((time.time() - T0, line.decode(errors="replace")))
                yield self.got[-1][1]
            r, _, _ = select.select([self.fd], [], [], 0.05)
            if r:
                try:
                    self.buf += os.read(self.fd, 4096)
                except BlockingIOError:
                    pass

    def ask(self, line, timeout=10.0):
        self.sent.append((time.time() - T0, line))
        os.write(self.fd, line.encode() + b"\r")
        for reply in self.lines(timeout):
            if not reply.startswith("@"):
                return reply
        return None

    def wheels_become(self, left, right, timeout=10.0):
        """True once a stream line shows these wheel speeds (XS must be on)."""
        for line in self.lines(timeout):
            f = line.split()
            if f and f[0] == "@" and len(f) == 9 and (int(f[5]), int(f[6])) == (left, right):
                return True
        return False

    def close(self):
        os.close(self.fd)


def printf(text, path):
    """What the issue types: a shell's one-shot redirection (open, write, close)."""
    subprocess.run(["sh", "-c", f"printf '{text}' > '{path}'"], check=True)


def start(*extra):
    """Starts robuterd and waits until it says its links are made: a killed robuterd's links
    dangle, and their /dev/pts/N may meanwhile belong to another program."""
    log_path = os.path.join(tmp, "robuterd.log")
    before = open(log_path).read().count("link on") if os.path.exists(log_path) else 0
    p = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--pty", A, "--pty", B, "--log-level", "info", *extra],
                         stdout=open(log_path, "a"), stderr=subprocess.STDOUT)
    for _ in range(600):
        if open(log_path).read().count("link on") >= before + 2:
            break
        time.sleep(0.05)
    return p


def cause(client):
    xe = client.ask("XE") or ""
    f = xe.split()
    return f[3] if len(f) >= 4 else xe


def turn(b):
    """XR, ASN, AM 20 -20, each asked again until acknowledged: XR is refused while the robot
    still brakes, and a request right after XR may still meet the latch (docs/SAFETY.md §4)."""
    for line in ("XR", "ASN", "AM 20 -20"):
        for _ in range(50):
            if b.ask(line) == "ack":
                break
            time.sleep(0.1)
    return b.wheels_become(20, -20)


def seen_on(client):
    """What a failed check on B shows: the robot's state as B asks it, then B's transcript."""
    def checked(name, ok):
        if ok:
            check(name, True)
            return
        state = ", ".join(f"{q} -> {client.ask(q, 3.0)!r}" for q in ("XE", "XD", "BO"))
        check(name, False, state + "\n" + client.transcript())
    return checked


proc = start()
try:
    a = Client(A)
    check("first client on A answered", (a.ask("BO") or "").startswith("S "))
    a.close()
    b = Client(B)
    check("XS on B", b.ask("XS10") == "ack")
    on_b = seen_on(b)
    on_b("B turns the robot", turn(b))

    for i in range(3):
        printf("\\030", A)
        ok = b.wheels_become(0, 0, 5.0)
        on_b(f"one-shot stop byte on A after a client left ({i + 1}/3)", ok and cause(b) == "stop-byte")
        on_b(f"B turns the robot again ({i + 1}/3)", turn(b))

    printf("AM 0 0\\r", A)
    on_b("one-shot 'AM 0 0' on A stops the robot", b.wheels_become(0, 0, 5.0))

    printf("ASN\\rAM 20 -20\\r", A)
    on_b("one-shot 'ASN, AM 20 -20' on A turns the robot at once", b.wheels_become(20, -20, 5.0))
    printf("AM 0 0\\r", A)
    on_b("and 'AM 0 0' stops it", b.wheels_become(0, 0, 5.0))

    fresh = 0
    for _ in range(10):
        printf("XB1\\r", A)
        time.sleep(0.05)
        c = Client(A)
        reply = c.ask("Zz")
        c.close()
        fresh += reply == "error"
    check("XB1 of a one-shot client never reaches the next client", fresh == 10, f"{fresh}/10 bare 'error'")
    printf("AM 10", A)  # a half line, then the client leaves
    time.sleep(0.05)
    c = Client(A)
    reply = c.ask("BC")
    c.close()
    check("a half line never reaches the next client", (reply or "").startswith("C "), reply)

    second = subprocess.run([robuterd, "--sim", "--sonar-model", "ideal", "--pty", A, "--ticks", "10"], capture_output=True, text=True,
                            timeout=60)
    check("a second robuterd on A is refused", second.returncode == 2 and "in use by another robuterd" in second.stderr,
          second.stderr.strip())
    check("the first still serves B", (b.ask("BC") or "").startswith("C "))
    c = Client(A)
    check("and A", (c.ask("BC") or "").startswith("C "))
    c.close()
    b.close()

    twice = subprocess.run([robuterd, "--sim", "--sonar-model", "ideal", "--pty", os.path.join(tmp, "c.pty"), "--pty",
                            os.path.join(tmp, ".", "c.pty"), "--ticks", "10"], capture_output=True, text=True,
                           timeout=60)
    check("--pty X --pty X is refused", twice.returncode == 2 and "given twice" in twice.stderr, twice.stderr.strip())

    proc.kill()  # SIGKILL: no clean-up at all
    proc.wait()
    proc = start()
    c = Client(A)
    check("after kill -9 a new robuterd takes the same path", (c.ask("BC") or "").startswith("C "))
    c.close()
    proc.send_signal(signal.SIGINT)
    rc = proc.wait(timeout=30)
    left = sorted(os.listdir(tmp))
    check("clean stop removes the links and their locks", rc == 0 and left == ["robuterd.log"], f"rc {rc}, {left}")
finally:
    if proc.poll() is None:
        proc.kill()
    if check.failed:
        print(open(os.path.join(tmp, "robuterd.log")).read())
    subprocess.run(["rm", "-rf", tmp])
check.exit()
