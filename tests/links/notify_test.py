#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Issue #14, systemd notification on the real binary, with a fake NOTIFY_SOCKET (a datagram
socket bound in a temporary folder) and WATCHDOG_USEC=200000: READY=1 arrives once the loop
ticks; WATCHDOG=1 keeps arriving (every 100 ms); none while robuterd is stopped with SIGSTOP,
again after SIGCONT; STOPPING=1 at a clean stop. With JOURNAL_STREAM naming its stderr, log lines
carry journald priorities (<4> for a warning). Waits are liveness bounds only."""
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time

robuterd = os.path.abspath(sys.argv[1])
tmp = tempfile.mkdtemp(prefix="robuter-notify-")
path = os.path.join(tmp, "notify")
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from check import Checks  # noqa: E402  (tests/support/check.py)

check = Checks()


def receive(sock, want, timeout):
    """Messages until one equals or starts with `want` (returned with those before it), or None."""
    got, deadline = [], time.time() + timeout
    while time.time() < deadline:
        sock.settimeout(max(0.01, deadline - time.time()))
        try:
            msg = sock.recv(4096).decode()
        except socket.timeout:
            break
        got.append(msg)
        if msg.startswith(want):
            return got
    return None


def drain(sock):
    n = 0
    sock.setblocking(False)
    try:
        while True:
            sock.recv(4096)
            n += 1
    except BlockingIOError:
        return n


sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
sock.bind(path)
log_path = os.path.join(tmp, "robuterd.log")
env = {**os.environ, "NOTIFY_SOCKET": path, "WATCHDOG_USEC": "200000"}
env.pop("WATCHDOG_PID", None)
proc = subprocess.Popen([robuterd, "--sim", "--sonar-model", "ideal", "--log-level", "info"], env=env, stdout=open(log_path, "w"),
                        stderr=subprocess.STDOUT)
try:
    first = receive(sock, "READY=1", 30)
    check("READY=1 once the loop ticks", first is not None and first[0].startswith("READY=1"), f"{first}")
    pings = 0
    for _ in range(5):
        pings += receive(sock, "WATCHDOG=1", 5) is not None
    check("WATCHDOG=1 keeps arriving", pings == 5, f"{pings}/5")

    proc.send_signal(signal.SIGSTOP)
    time.sleep(0.2)
    drain(sock)
    time.sleep(0.8)  # four watchdog periods
    silent = drain(sock)
    check("none while robuterd is stopped (SIGSTOP)", silent == 0, f"{silent} messages")
    proc.send_signal(signal.SIGCONT)
    check("WATCHDOG=1 again after SIGCONT", receive(sock, "WATCHDOG=1", 10) is not None)

    proc.send_signal(signal.SIGTERM)
    check("STOPPING=1 at a clean stop", receive(sock, "STOPPING=1", 30) is not None)
    check("exit 0", proc.wait(timeout=30) == 0)

    # Journald priorities: stderr is "the journal" when JOURNAL_STREAM names it; a READY=1 that
    # nobody takes is a warning.
    jlog = os.path.join(tmp, "journal.log")
    with open(jlog, "w") as out:
        st = os.fstat(out.fileno())
        jenv = {**os.environ, "JOURNAL_STREAM": f"{st.st_dev}:{st.st_ino}", "NOTIFY_SOCKET": os.path.join(tmp, "none")}
        rc = subprocess.run([robuterd, "--sim", "--sonar-model", "ideal", "--ticks", "20", "--log-level", "info"], env=jenv, stdout=out,
                            stderr=out, timeout=60).returncode
    text = open(jlog).read()
    check("journal: warnings carry <4>, information <6>",
          rc == 0 and "<4>[" in text and "notify: READY=1 not taken" in text and "<6>[" in text, text[:300])
finally:
    if proc.poll() is None:
        proc.send_signal(signal.SIGCONT)
        proc.kill()
    if check.failed:
        print(open(log_path).read())
    sock.close()
    subprocess.run(["rm", "-rf", tmp])
check.exit()
