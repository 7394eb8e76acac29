#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Serial transport: robuterd opens a tty (hal/linux SerialStream, 8N1); this test holds the other
end of a pty pair as 'the wire', then removes nothing and checks the exchange."""
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
time.sleep(0.5)


def ask(line):
    os.write(master, (line + "\r").encode())
    buf = b""
    deadline = time.time() + 3
    while not buf.endswith(b"\r") and time.time() < deadline:
        os.set_blocking(master, False)
        try:
            buf += os.read(master, 256)
        except BlockingIOError:
            time.sleep(0.005)
    return buf.decode(errors="replace")


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
