#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue #14, the drive-side watchdog on the real binaries: robuter-can-nodes (the simulated CiA 402
drives and ultrasonic nodes as their own process) on a Unix-socket bus, robuterd on it
([can] interface = "unix:PATH"). The robot drives; `kill -9` of robuterd: both drives quick-stop
and stand still within their consumer heartbeat time (measured by the node process on its own
clock); a new robuterd brings them back; SIGSEGV in a driving robuterd: the fatal handler's quick
stop reaches the drives at once, before their watchdog would. Then the node process's script
(--script, lines on its stdin; make test-vm drives it the same way): the ranges it answers reach
BU, a bad line is refused and changes nothing, a silenced drive's heartbeat makes XE say
heartbeat-lost. Waits are liveness bounds only."""
import os
import re
import select
import signal
import subprocess
import sys
import tempfile
import time
import tty

robuterd, nodes_tool = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
tmp = tempfile.mkdtemp(prefix="robuter-can-nodes-")
bus, pty, cfg = os.path.join(tmp, "bus"), os.path.join(tmp, "robuter.pty"), os.path.join(tmp, "can.toml")
WATCHDOG_MS = 300
with open(cfg, "w") as f:
    f.write(f'[hardware]\ndrive = "can"\nsonar = "can"\n[can]\ninterface = "unix:{bus}"\n'
            f"drive_watchdog_ms = {WATCHDOG_MS}\n")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from check import Checks  # noqa: E402  (tests/support/check.py)

check = Checks()


class Lines:
    """Lines of a child's stdout, read without blocking."""

    def __init__(self, fd):
        self.fd, self.buf, self.seen = fd, b"", []
        os.set_blocking(fd, False)

    def wait_for(self, pattern, timeout):
        deadline = time.time() + timeout
        rx = re.compile(pattern)
        while True:
            while b"\n" in self.buf:
                line, self.buf = self.buf.split(b"\n", 1)
                text = line.decode(errors="replace")
                self.seen.append(text)
                m = rx.search(text)
                if m:
                    return m
            left = deadline - time.time()
            if left <= 0:
                return None
            r, _, _ = select.select([self.fd], [], [], min(left, 0.05))
            if r:
                try:
                    self.buf += os.read(self.fd, 65536)
                except BlockingIOError:
                    pass


starts = 0


def start_robuterd():
    """Starts robuterd and opens its pty once robuterd says it made it: a killed robuterd's link
    dangles, and its /dev/pts/N may meanwhile belong to another program."""
    global starts
    starts += 1
    log = os.path.join(tmp, f"robuterd-{starts}.log")
    p = subprocess.Popen([robuterd, "--config", cfg, "--pty", pty, "--log-level", "info"],
                         stdout=open(log, "w"), stderr=subprocess.STDOUT,
                         preexec_fn=lambda: __import__("resource").setrlimit(__import__("resource").RLIMIT_CORE, (0, 0)))
    for _ in range(600):
        if "link on" in open(log).read():
            break
        time.sleep(0.05)
    try:
        fd = os.open(pty, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    except OSError:
        p.kill()  # never leave a robuterd behind
        raise
    tty.setraw(fd)
    return p, fd


def ask(fd, line, timeout=5.0):
    os.write(fd, line.encode() + b"\r")
    buf, deadline = b"", time.time() + timeout
    while time.time() < deadline:
        r, _, _ = select.select([fd], [], [], 0.05)
        if r:
            try:
                buf += os.read(fd, 4096)
            except (BlockingIOError, OSError):
                pass
            if b"\r" in buf:
                return buf.split(b"\r")[0].decode(errors="replace")
    return None


def drive(fd):
    """Waits for the drives to be ready (XE cause none twice, 0.5 s apart: a drive still in
    bring-up shows only after the first ticks), then ASN and AM 20 20."""
    replies, calm = [], 0
    for _ in range(100):
        xe = ask(fd, "XE") or ""
        replies.append(xe)
        calm = calm + 1 if " none " in xe else 0
        if calm == 2:
            break
        if " 1 " in xe[:6]:
            replies.append(ask(fd, "XR"))
        time.sleep(0.5)
    replies += [ask(fd, "ASN"), ask(fd, "AM 20 20")]
    if replies[-2:] != ["ack", "ack"]:
        print(f"drive: {replies}", flush=True)
        return False
    return True


nodes = subprocess.Popen([nodes_tool, "--bus", f"unix:{bus}", "--script"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT)


def script(line):
    """One line of the node process's script; its reply."""
    nodes.stdin.write(line.encode() + b"\n")
    nodes.stdin.flush()
    m = out.wait_for(rf"robuter-can-nodes: {re.escape(line)}: (.*)", 5)
    return m.group(1) if m else None


def bu_values(fd):
    m = re.fullmatch(r"U ((?:\d+ ){24})[01] \d+", ask(fd, "BU") or "")
    return [int(v) for v in m.group(1).split()] if m else None


def xe_cause(fd):
    m = re.fullmatch(r"E \d \d (\S+) .*", ask(fd, "XE") or "")
    return m.group(1) if m else None

out = Lines(nodes.stdout.fileno())
proc = None
try:
    check("node process up", out.wait_for(r"robuter-can-nodes: unix .*drives 1 and 2", 20) is not None)
    proc, fd = start_robuterd()
    check("the drives watch robuterd's heartbeat",
          out.wait_for(rf"node 1: watches node 127's heartbeat, {WATCHDOG_MS} ms, reaction 0x6007=3", 20) is not None)
    check("robuterd drives them", drive(fd) and out.wait_for(r"node [12]: moving", 20) is not None)
    out.wait_for(r"node [12]: moving", 5)
    proc.kill()  # kill -9: no clean-up, no last frame
    proc.wait()
    os.close(fd)
    stops = {}
    for _ in range(2):
        m = out.wait_for(r"node ([12]): standing still, ([0-9.]+) ms after node 127's last heartbeat", 10)
        if m:
            stops[m.group(1)] = float(m.group(2))
    lost = [line for line in out.seen if "heartbeat of node 127 lost" in line]
    check(f"kill -9: both drives stand still within their heartbeat time ({WATCHDOG_MS} ms)",
          len(stops) == 2 and all(v <= WATCHDOG_MS + 100 for v in stops.values()) and len(lost) >= 2,
          f"standing still after {stops} ms; {len(lost)} heartbeat events")
    print(f"figure: drive stopped {max(stops.values(), default=-1):.1f} ms after robuterd's last heartbeat "
          f"(kill -9), consumer time {WATCHDOG_MS} ms", flush=True)

    proc, fd = start_robuterd()
    check("a new robuterd brings the drives back and drives them",
          drive(fd) and out.wait_for(r"node [12]: moving", 20) is not None)
    out.wait_for(r"node [12]: moving", 5)
    mark = len(out.seen)
    proc.send_signal(signal.SIGSEGV)  # a crash: the fatal handler sends the quick stop itself
    rc = proc.wait(timeout=30)
    os.close(fd)
    qs = {}
    for _ in range(2):
        m = out.wait_for(r"node ([12]): state quick-stop-active \(([0-9.-]+) ms since", 10)
        if m:
            qs[m.group(1)] = float(m.group(2))
    early = [line for line in out.seen[mark:] if "heartbeat of node 127 lost" in line]
    log = open(os.path.join(tmp, f"robuterd-{starts}.log")).read()
    check("SIGSEGV: the fatal handler's quick stop reaches both drives before their watchdog",
          rc == -signal.SIGSEGV and len(qs) == 2 and all(v < WATCHDOG_MS for v in qs.values())
          and "fatal signal SIGSEGV: drives sent quick stop" in log,
          f"rc {rc}, quick stop {qs} ms after the last heartbeat, lines before: {early}")

    # The script: ranges, a refused line, a silenced drive.
    proc, fd = start_robuterd()
    check("a third robuterd drives them", drive(fd))
    check("script: range 700 acknowledged", script("range 700") == "ok")
    seen = None
    for _ in range(50):
        seen = bu_values(fd)
        if seen and any(abs(v - 700) <= 30 for v in seen):
            break
        time.sleep(0.1)
    check("BU reports the 700 mm the nodes answer", seen and any(abs(v - 700) <= 30 for v in seen), f"BU {seen}")
    check("script: a bad line is refused", (script("range 25 1") or "").startswith("error"))
    check("script: an unknown word is refused", (script("busy left") or "").startswith("error"))
    check("the refused lines changed nothing: XE none", xe_cause(fd) == "none", ask(fd, "XE"))
    check("script: silent left 1 acknowledged", script("silent left 1") == "ok")
    cause = None
    for _ in range(50):
        cause = xe_cause(fd)
        if cause not in (None, "none"):
            break
        time.sleep(0.1)
    check("a silenced drive: XE cause heartbeat-lost", cause == "heartbeat-lost", f"XE cause {cause}")
    check("script: quit", script("quit") == "ok")
    check("the node process ends on quit", nodes.wait(timeout=10) == 0)
finally:
    if proc and proc.poll() is None:
        proc.kill()
    nodes.send_signal(signal.SIGTERM)
    try:
        nodes.wait(timeout=10)
    except subprocess.TimeoutExpired:
        nodes.kill()
    if check.failed:
        print("--- robuter-can-nodes\n" + "\n".join(out.seen))
        for i in range(1, starts + 1):
            print(f"--- robuterd {i}\n" + open(os.path.join(tmp, f"robuterd-{i}.log")).read())
    subprocess.run(["rm", "-rf", tmp])
check.exit()
