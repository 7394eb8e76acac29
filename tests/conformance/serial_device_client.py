#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Serial transport: robuterd opens a tty (hal/linux SerialStream, 8N1); this test holds the other
end of a pty pair as 'the wire', then removes nothing and checks the exchange. It waits for robuterd to answer before checking, never for a fixed time."""
import os
import subprocess
import sys
import time
import tty

robuterd = sys.argv[1]
master, slave = os.openpty()
tty.setraw(master)
tty.setraw(slave)
path = os.ttyname(slave)
proc = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--serial", path, "--baud", "115200", "--log-level", "warn"],
                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


def ask(line, wait=3.0):
    os.write(master, (line + "\r").encode())
    buf = b""
    deadline = time.time() + wait
    while not buf.endswith(b"\r") and time.time() < deadline:
        os.set_blocking(master, False)
        try:
            buf += os.read(master, 256)
        except BlockingIOError:
            time.sleep(0.005)
    return buf.decode(errors="replace")


def drain(quiet=0.2):
    """Reads and drops what arrives until the line has been quiet this long."""
    last = time.time()
    while time.time() - last < quiet:
        try:
            if os.read(master, 256):
                last = time.time()
        except BlockingIOError:
            time.sleep(0.005)


# robuterd is ready when it answers: a probe is asked until it does (a loaded machine, or a
# sanitizer build, may take seconds to open the tty; what was written before it opened and set
# the line up may be flushed), then the answers of earlier probes are drained.
os.set_blocking(master, False)
for _ in range(60):
    if ask("UN", wait=0.5).endswith("\r") or proc.poll() is not None:
        break
drain()


checks = [("BT", "T 33\r"), ("UN", "N 3\r"), ("AM 10", "error\r"), ("AX", "ack\r")]
failed = 0
for line, want in checks:
    got = ask(line)
    if got != want:
        print(f"FAIL {line!r}: got {got!r}, want {want!r}")
        failed += 1
rc = proc.wait(timeout=5)
if rc != 0:
    print(f"FAIL robuterd exit {rc}: {proc.stdout.read().decode()}")
    failed += 1
print(f"{len(checks) + 1 - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
