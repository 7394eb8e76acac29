#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Acceptance (issue #8) on the real binary: robuterd --serial DEV where DEV is a symbolic link
to a pty slave; BO answered; the pty closed and DEV removed (device gone): robuterd keeps
running; a new pty at DEV: BO answered again, no restart. Waits are liveness bounds only."""
import re
import os
import pty
import select
import subprocess
import sys
import tempfile
import time
import tty

robuterd, config = sys.argv[1], sys.argv[2]
tmp = tempfile.mkdtemp(prefix="robuter-replug-")
dev = os.path.join(tmp, "robuter-link")


def plug():
    master, slave = pty.openpty()
    tty.setraw(master)
    os.set_blocking(master, False)
    name = os.ttyname(slave)
    os.close(slave)
    if os.path.lexists(dev):
        os.unlink(dev)
    os.symlink(name, dev)
    return master


def ask(master, line, timeout=30.0):
    """Sends line (again every second until answered) and returns the first reply line."""
    buf = b""
    deadline = time.time() + timeout
    next_send = 0.0
    while time.time() < deadline:
        if time.time() >= next_send:
            os.write(master, line.encode() + b"\r")
            next_send = time.time() + 1.0
        r, _, _ = select.select([master], [], [], 0.05)
        if r:
            try:
                buf += os.read(master, 1024)
            except OSError:  # EAGAIN: readable for another reason (the slave opened or closed)
                time.sleep(0.01)
            if b"\r" in buf:
                return buf.split(b"\r")[0].decode(errors="replace")
    return None


failed = 0


def check(name, ok, detail=""):
    global failed
    print(("ok   " if ok else "FAIL ") + name + (f": {detail}" if detail else ""))
    failed += 0 if ok else 1


master = plug()
log = open(os.path.join(tmp, "log"), "w+")
proc = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--config", config, "--serial", dev, "--log-level", "info"],
                        stdout=log, stderr=log)
first = ask(master, "BO")
check("BO before", first is not None and first.startswith("S "), repr(first))
os.close(master)
os.unlink(dev)
time.sleep(0.5)
check("running after the device went away", proc.poll() is None)
master = plug()
again = ask(master, "BO")
check("BO after the device came back", again is not None and again.startswith("S "), repr(again))
check("running", proc.poll() is None)
proc.terminate()
rc = proc.wait(timeout=10)
check("clean stop", rc == 0, f"exit {rc}")
log.seek(0)
text = log.read()
# Whichever the firmware sees first names the loss: the pty's master hung up, a read's EIO, or
# the device node removed (the sanitizer tree, slower, logged the last two): each is the device gone.
check("loss logged", re.search(r"lost \((hung up|Input/output error|device node removed or replaced)\); "
                               r"looking for it again", text) is not None)
check("return logged", "is back" in text)
if failed:
    print(text)
os.close(master)
os.unlink(dev)
print(f"{failed} failed")
sys.exit(1 if failed else 0)
