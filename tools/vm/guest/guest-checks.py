#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""make test-vm's checks, inside the Debian 12 guest: robuterd installed from its .deb and started
by systemd (PID 1) on a real kernel's SocketCAN (vcan0), with the simulated CiA 402 drives and
ultrasonic nodes as their own process (robuter-can-nodes --script). Prints one line per check,
`figure NAME: VALUE UNIT` lines, and a last line `N passed, N failed`."""
# Usage (in the guest, as root): guest-checks.py PAYLOAD_DIR
import glob
import os
import re
import signal
import subprocess
import sys
import time

import serial  # python3-serial

PAYLOAD = sys.argv[1] if len(sys.argv) > 1 else "/mnt/payload"
PTY = "/run/robuterd/robuter.pty"
CONFIG = "/etc/robuterd/robuterd.toml"
NODES_LOG = "/tmp/robuter-can-nodes.log"
CANDUMP_LOG = "/tmp/candump.log"
HOST_HEARTBEAT_MS = 50      # [can] host_heartbeat_ms (the package's default configuration)
DRIVE_WATCHDOG_MS = 300     # [can] drive_watchdog_ms: the drives' consumer heartbeat time
RESTART_SEC = 5             # robuterd.service's RestartSec=
WATCHDOG_SEC = 5            # robuterd.service's WatchdogSec=
# How long to wait for what is not measured (a reply, a log line, a drive enabled): a liveness
# bound only. The figures with limits are the drives' stop (on the node process's clock) and
# systemd's restarts; on an overloaded host an emulated guest can miss those (measure unloaded).
LIVENESS_S = 30.0

passed = 0
failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
    print(f"{'ok  ' if ok else 'FAIL'} {what}", flush=True)
    return ok


def figure(name, value, unit):
    print(f"figure {name}: {value} {unit}", flush=True)


def sh(cmd, timeout=60):
    r = subprocess.run(cmd, shell=True, text=True, capture_output=True, timeout=timeout)
    return r.returncode, (r.stdout + r.stderr).strip()


def finish():
    print(f"{passed} passed, {failed} failed", flush=True)
    sys.exit(0 if failed == 0 else 1)


def main_pid():
    _, out = sh("systemctl show -p MainPID --value robuterd")
    return int(out or "0")


class Link:
    """The operator's link: robuterd's pty, opened again whenever robuterd made a new one."""

    def __init__(self):
        self.port = None
        self.target = None

    def ask(self, line, timeout=3.0):
        try:
            target = os.path.realpath(PTY)
            if self.port is None or target != self.target:
                self.close()
                self.port = serial.Serial(PTY, 9600, timeout=timeout)
                self.target = target
            self.port.reset_input_buffer()
            self.port.write(line.encode() + b"\r")
            reply = self.port.read_until(b"\r")
            return reply.decode(errors="replace").strip() if reply.endswith(b"\r") else None
        except (OSError, serial.SerialException):
            self.close()
            return None

    def close(self):
        if self.port is not None:
            try:
                self.port.close()
            except (OSError, serial.SerialException):
                pass
        self.port = None


def wait_for(pred, seconds, step=0.05):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        v = pred()
        if v:
            return v
        time.sleep(step)
    return pred()


def posture(link):
    m = re.fullmatch(r"S (-?\d+) (-?\d+) (-?\d+) ([01]) (\d+)", link.ask("BO") or "")
    return tuple(int(g) for g in m.groups()) if m else None


def log_lines():
    with open(NODES_LOG, errors="replace") as f:
        return f.read().splitlines()


# ---- the system itself
check(open("/proc/1/comm").read().strip() == "systemd", "systemd is PID 1")
debs = [d for d in glob.glob(f"{PAYLOAD}/robuterd_*.deb") if "dbgsym" not in d]
if not check(len(debs) == 1, f"one robuterd package on the payload disk: {debs}"):
    finish()
t0 = time.monotonic()
rc, out = sh(f"dpkg -i {debs[0]}", timeout=300)
if not check(rc == 0, f"dpkg -i {os.path.basename(debs[0])} ({time.monotonic() - t0:.1f} s)"):
    print(out)
    finish()
if not check(os.access("/usr/bin/robuterd", os.X_OK) and os.access("/usr/bin/robuter-can-nodes", os.X_OK),
             "the package holds /usr/bin/robuterd and /usr/bin/robuter-can-nodes"):
    finish()
rc, out = sh("systemctl is-active robuterd")
check(out == "active", f"the package's service runs the simulated robot after installation: {out}")
rc, out = sh("modprobe vcan && ip link add dev vcan0 type vcan && ip link set up vcan0 && ip -details link show vcan0")
if not check(rc == 0 and "vcan" in out, "a real kernel's SocketCAN: vcan0 up"):
    print(out)
    finish()

# ---- the bus: candump's capture, the simulated nodes (scripted ranges, faults)
candump = subprocess.Popen(["candump", "-L", "vcan0"], stdout=open(CANDUMP_LOG, "w"), stderr=subprocess.STDOUT)
nodes = subprocess.Popen(["robuter-can-nodes", "--bus", "vcan0", "--script"], stdin=subprocess.PIPE,
                         stdout=open(NODES_LOG, "w"), stderr=subprocess.STDOUT, text=True)


def node(cmd):
    nodes.stdin.write(cmd + "\n")
    nodes.stdin.flush()
    return wait_for(lambda: any(line.startswith(f"robuter-can-nodes: {cmd}: ") for line in log_lines()), LIVENESS_S)


check(node("range 2000"), "robuter-can-nodes takes its script: every transducer 2000 mm")

# ---- robuterd on the CAN hardware, started by systemd
with open(CONFIG) as f:
    cfg = f.read()
cfg = re.sub(r'(?m)^drive = "none"', 'drive = "can"', cfg)
cfg = re.sub(r'(?m)^sonar = "none"', 'sonar = "can"', cfg)
cfg = re.sub(r'(?m)^interface = "can0"', 'interface = "vcan0"', cfg)
with open(CONFIG, "w") as f:
    f.write(cfg)
with open("/etc/default/robuterd", "w") as f:
    f.write('ROBUTERD_ARGS="--pty /run/robuterd/robuter.pty"\n')
link = Link()
t0 = time.monotonic()
rc, out = sh("systemctl restart robuterd")
check(rc == 0, f"systemctl restart robuterd with [hardware] drive = \"can\", sonar = \"can\" on vcan0 {out}")
first = wait_for(lambda: posture(link), LIVENESS_S)
started = time.monotonic() - t0
if not check(first is not None, f"BO answered on {PTY} {started:.2f} s after the restart: {first}"):
    print(sh("journalctl -u robuterd --no-pager -n 30")[1])
    finish()
figure("start (systemctl restart to the first BO answer)", f"{started:.2f}", "s")

# ---- the operator's commands over CAN
check(link.ask("ASN") == "ack", "ASN (servo on) acked")
servo = wait_for(lambda: (p := posture(link)) is not None and p[3] == 1 and p, LIVENESS_S)
check(servo, f"BO says servo on: the drives enabled over CAN: {servo}")
check(link.ask("AM 10 10") == "ack", "AM 10 10 acked")
time.sleep(3.0)
a = posture(link)
time.sleep(1.0)
b = posture(link)
check(a is not None and b is not None and b[0] > a[0] > 0,
      f"BO follows the drives' encoder counts: x {a and a[0]} then {b and b[0]} one second later")
if a and b:
    figure("speed from BO while AM 10 10", f"{(b[0] - a[0]) / 100.0:.1f}", "cm/s (asked 10; BO's x in 0.1 mm)")
check(link.ask("AM 0 0") == "ack", "AM 0 0 acked")
check(node("range 700"), "every transducer now 700 mm")
u = wait_for(lambda: (m := re.fullmatch(r"U ((?:\d+ ){24})([01]) (\d+)", link.ask("BU") or "")) and
             any(abs(int(v) - 700) <= 30 for v in m.group(1).split()) and m.group(0), LIVENESS_S)
check(u, f"BU reports the nodes' 700 mm: {u}")

# ---- candump: the frames on the real bus
time.sleep(0.5)
with open(CANDUMP_LOG) as f:
    frames = [m.group(1) for m in re.finditer(r"vcan0 ([0-9A-F]{3})#", f.read())]
ids = {}
for i in frames:
    ids[i] = ids.get(i, 0) + 1
want = {"77F": "robuterd's heartbeat (node 127)", "701": "left drive's heartbeat", "702": "right drive's heartbeat",
        "201": "RPDO1 to the left drive (controlword)", "181": "TPDO1 of the left drive (statusword)",
        "710": "ultrasonic node 16's heartbeat", "000": "NMT"}
for i, what in want.items():
    check(ids.get(i, 0) > 0, f"candump saw 0x{i} ({what}): {ids.get(i, 0)} frames")
figure("frames captured by candump", len(frames), f"({len(ids)} identifiers)")


# ---- kill -9 of robuterd while driving: the drives stop on their own, systemd restarts it
def drive_stop_after(mark, what):
    """The nodes' own report: ms from robuterd's last heartbeat to standing still, per drive."""
    def stops():
        got = {}
        for line in log_lines()[mark:]:
            m = re.search(r"node (\d+): standing still, ([\d.]+) ms after node 127's last heartbeat", line)
            if m:
                got.setdefault(m.group(1), float(m.group(2)))
        return got if len(got) == 2 else None
    got = wait_for(stops, LIVENESS_S)
    limit = DRIVE_WATCHDOG_MS + 2 * HOST_HEARTBEAT_MS
    worst = max(got.values()) if got else None
    check(got is not None and worst <= limit,
          f"{what}: both drives standing still {got} ms after robuterd's last heartbeat (limit {limit})")
    if worst is not None:
        figure(f"drive stop after {what}", f"{worst:.1f}", "ms after the last heartbeat")


def moving_lines(mark):
    """The nodes' "moving" lines since `mark`, without their time stamp ("node N: moving, ...")."""
    return [line.split(" ", 1)[1] for line in log_lines()[mark:] if ": moving," in line]


def restarted_after(pid, t_event, what, limit):
    def up():
        p = main_pid()
        return p != 0 and p != pid and posture(link) is not None and p
    newpid = wait_for(up, limit + 20.0, 0.1)
    took = time.monotonic() - t_event
    check(newpid and took <= limit, f"{what}: systemd restarted robuterd (pid {pid} -> {newpid}) and it answers, "
                                    f"{took:.1f} s after (limit {limit} s)")
    figure(f"restart after {what}", f"{took:.1f}", "s")
    return newpid


def drive_again(what):
    """Waits for the drives to be ready (XE cause none twice, 0.5 s apart; an XR for what their
    bring-up latched), then ASN and AM 20 20; both drives report moving."""
    calm, replies = 0, []
    for _ in range(40):
        xe = link.ask("XE") or ""
        replies.append(xe)
        calm = calm + 1 if " none " in xe else 0
        if calm == 2:
            break
        if xe.startswith("E 0 1") or xe.startswith("E 1 1"):
            replies.append(link.ask("XR"))
        time.sleep(0.5)
    mark = len(log_lines())
    ok = link.ask("ASN") == "ack" and link.ask("AM 20 20") == "ack"
    check(ok, f"{what}: ASN, AM 20 20 acked (XE before: {replies[-1:]})")
    ok = ok and wait_for(lambda: {l.split(":")[0] for l in moving_lines(mark)} >= {"node 1", "node 2"}, LIVENESS_S)
    check(ok, f"{what}: both drives moving")
    return ok


def signal_while_driving(sig, what, restart_what, limit):
    """Drives, then sends `sig` to robuterd: the drives stop, and systemd restarts it within
    `limit` s (checked as `restart_what`). Returns the nodes' log mark taken after the stop."""
    drive_again(f"before {what}")
    pid = main_pid()
    mark = len(log_lines())
    t_sent = time.monotonic()
    os.kill(pid, sig)
    drive_stop_after(mark, what)
    mark = len(log_lines())
    restarted_after(pid, t_sent, restart_what, limit)
    return mark


def nothing_moves_since(mark):
    """After a restart the drives stay still; systemd's failure count is cleared for the next."""
    time.sleep(1.0)
    check(not moving_lines(mark), "after the restart nothing moves by itself")
    sh("systemctl reset-failed robuterd")


node("range 2000")
mark = signal_while_driving(signal.SIGKILL, "kill -9", "kill -9", RESTART_SEC + 5)
nothing_moves_since(mark)

# ---- SIGSTOP (a hung robuterd): the drives stop, systemd's watchdog kills and restarts it
mark = signal_while_driving(signal.SIGSTOP, "SIGSTOP", "SIGSTOP (watchdog)", WATCHDOG_SEC + RESTART_SEC + 5)
rc, out = sh("journalctl -u robuterd --no-pager -o cat | grep -i watchdog | tail -3")
check("watchdog" in out.lower(), f"the journal names systemd's watchdog: {out.splitlines()[-1] if out else ''}")
nothing_moves_since(mark)


# ---- faults injected from the node process: XE names them
def xe_cause():
    m = re.fullmatch(r"E (\d) (\d) (\S+) .*", link.ask("XE") or "")
    return m.group(3) if m else None


drive_again("before the heartbeat loss")
node("silent left 1")
cause = wait_for(lambda: (c := xe_cause()) not in (None, "none") and c, LIVENESS_S)
check(cause == "heartbeat-lost", f"a drive's heartbeat stops: XE cause {cause}")
node("silent left 0")
time.sleep(1.0)
check(link.ask("XR") == "ack", "XR once the drive talks again")
drive_again("before the bus-off")
node("busoff")
cause = wait_for(lambda: (c := xe_cause()) not in (None, "none") and c, LIVENESS_S)
check(cause == "bus-off", f"an error frame says bus-off: XE cause {cause}")
node("restarted")
node("quit")
nodes.wait(timeout=5)
candump.terminate()
finish()
