#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue #14, signals and crashes, on the real binary (`robuterd --sim --pty P`, the robot turning):
SIGHUP, SIGQUIT and SIGTERM stop it cleanly (drive stopped, servo off, exit 0, pty link removed);
SIGUSR1 and SIGUSR2 are logged and ignored, SIGPIPE ignored; SIGSEGV, SIGABRT, SIGBUS and SIGFPE
raised from the periodic path (ROBUTERD_TEST_RAISE) stop the drive in the handler, say so on
stderr and end with the signal's own status. Waits are liveness bounds only."""
import os
import resource
import select
import signal
import subprocess
import sys
import tempfile
import time
import tty

robuterd = os.path.abspath(sys.argv[1])
tmp = tempfile.mkdtemp(prefix="robuter-signals-")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from check import Checks  # noqa: E402  (tests/support/check.py)

check = Checks()


class Robuterd:
    def __init__(self, tag, env=None):
        self.pty = os.path.join(tmp, f"{tag}.pty")
        self.log_path = os.path.join(tmp, f"{tag}.log")
        no_core = lambda: resource.setrlimit(resource.RLIMIT_CORE, (0, 0))  # noqa: E731
        self.proc = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--pty", self.pty, "--log-level", "info"],
                                     stdout=open(self.log_path, "w"), stderr=subprocess.STDOUT,
                                     env={**os.environ, **(env or {})}, preexec_fn=no_core, cwd=tmp)
        for _ in range(600):
            if os.path.islink(self.pty):
                break
            time.sleep(0.05)
        self.fd = os.open(self.pty, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self.fd)
        self.buf = b""

    def send(self, *lines):
        os.write(self.fd, b"".join(line.encode() + b"\r" for line in lines))

    def lines(self, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline:
            while b"\r" in self.buf:
                line, self.buf = self.buf.split(b"\r", 1)
                yield line.decode(errors="replace")
            r, _, _ = select.select([self.fd], [], [], 0.05)
            if r:
                try:
                    chunk = os.read(self.fd, 4096)
                except BlockingIOError:
                    continue
                except OSError:  # EIO: robuterd is gone
                    return
                if not chunk:
                    return
                self.buf += chunk

    def turning(self, timeout=20.0):
        for line in self.lines(timeout):
            f = line.split()
            if f and f[0] == "@" and len(f) == 9 and (f[5], f[6]) == ("20", "-20"):
                return True
        return False

    def start_turning(self):
        self.send("XS10", "ASN", "AM 20 -20")

    def log(self):
        return open(self.log_path).read()


for sig in (signal.SIGHUP, signal.SIGQUIT, signal.SIGTERM):
    r = Robuterd(sig.name)
    r.start_turning()
    moving = r.turning()
    r.proc.send_signal(sig)
    rc = r.proc.wait(timeout=30)
    log = r.log()
    check(f"{sig.name}: clean stop of a turning robot",
          moving and rc == 0 and "zero speed (was 20 -20 cm/s), servo off (was on)" in log
          and f"{sig.name} received: stopped cleanly" in log and not os.path.lexists(r.pty),
          f"moving {moving}, rc {rc}")
    os.close(r.fd)

r = Robuterd("ignored")
r.start_turning()
moving = r.turning()
for sig in (signal.SIGUSR1, signal.SIGUSR2, signal.SIGPIPE):
    r.proc.send_signal(sig)
r.send("BC")
answered = any(line.startswith("C ") for line in r.lines(10.0))
check("SIGUSR1, SIGUSR2, SIGPIPE: still running and answering", moving and answered and r.proc.poll() is None)
r.proc.send_signal(signal.SIGINT)
rc = r.proc.wait(timeout=30)
log = r.log()
check("SIGUSR1 and SIGUSR2 are logged", "SIGUSR1 received: ignored" in log and "SIGUSR2 received: ignored" in log
      and rc == 0, f"rc {rc}")
os.close(r.fd)

# Fatal signals from the periodic path at tick 300 (3 s), the four at once; their clients are
# read side by side (a dead robuterd's pty loses what was not read).
fatal = [signal.SIGSEGV, signal.SIGABRT, signal.SIGBUS, signal.SIGFPE]
runs = [Robuterd(s.name, {"ROBUTERD_TEST_RAISE": f"{int(s)}:300"}) for s in fatal]
for r in runs:
    r.start_turning()
moving = [False] * len(runs)
deadline = time.time() + 60
while not all(moving) and time.time() < deadline:
    for i, r in enumerate(runs):
        if not moving[i]:
            moving[i] = r.turning(0.05)
for sig, r, was_moving in zip(fatal, runs, moving):
    rc = r.proc.wait(timeout=60)
    log = r.log()
    line = f"robuterd: fatal signal {sig.name}: drive stopped (simulated drive: zero speed, servo off)"
    check(f"{sig.name}: drive stopped by the handler, status {128 + int(sig)}", was_moving and rc == -int(sig)
          and line in log, f"moving {was_moving}, rc {rc}")
    os.close(r.fd)

if check.failed:
    for f in sorted(os.listdir(tmp)):
        if f.endswith(".log"):
            print(f"--- {f}\n" + open(os.path.join(tmp, f)).read())
subprocess.run(["rm", "-rf", tmp])
check.exit()
