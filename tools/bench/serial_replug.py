#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Serial re-open figures: robuterd --sim --serial DEV (DEV a symbolic link to a pty slave);
N times: the pty closed and DEV removed, then a new pty at DEV; measured from the new DEV to the
first reply to BO (re-sent every 5 ms). Bounded by retry_ms + a tick by design."""
import os
import pty
import select
import statistics
import subprocess
import sys
import tempfile
import time
import tty

robuterd, retry_ms, cycles = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
tmp = tempfile.mkdtemp(prefix="robuter-bench-replug-")
dev = os.path.join(tmp, "dev")
cfg = os.path.join(tmp, "cfg.toml")
with open(cfg, "w") as f:
    f.write(f"[links.serial]\nretry_ms = {retry_ms}\n")


def plug():
    m, s = pty.openpty()
    tty.setraw(m)
    os.set_blocking(m, False)
    name = os.ttyname(s)
    os.close(s)
    if os.path.lexists(dev):
        os.unlink(dev)
    os.symlink(name, dev)
    return m


def answer_time(m, limit=10.0):
    t0 = time.monotonic()
    buf = b""
    last = 0.0
    while time.monotonic() - t0 < limit:
        now = time.monotonic()
        if now - last >= 0.005:
            os.write(m, b"BO\r")
            last = now
        r, _, _ = select.select([m], [], [], 0.001)
        if r:
            try:
                buf += os.read(m, 4096)
            except OSError:
                pass
            if b"\r" in buf:
                return time.monotonic() - t0
    return None


m = plug()
proc = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--config", cfg, "--serial", dev, "--log-level", "warn"],
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
answer_time(m)
times, missed = [], 0
for _ in range(cycles):
    os.close(m)
    os.unlink(dev)
    time.sleep(0.05)
    m = plug()
    t = answer_time(m)
    if t is None:
        missed += 1
    else:
        times.append(t * 1000)
    time.sleep(0.02)
alive = proc.poll() is None
proc.terminate()
proc.wait(timeout=10)
os.close(m)
os.unlink(dev)
os.unlink(cfg)
os.rmdir(tmp)
print(f"retry_ms {retry_ms}: {cycles} unplug/replug cycles, answered {len(times)}, missed {missed}, "
      f"robuterd {'kept running' if alive else 'DIED'}; device back -> first reply: "
      f"median {statistics.median(times):.0f} ms, max {max(times):.0f} ms" if times else "no answers")
sys.exit(0 if alive and missed == 0 else 1)
