#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""robuterctl against a live `robuterd --sim --pty` (issue #15).

Every case is a friction an operator met with the old robuterctl: a stale reply taken as the
answer, `@` stream lines taken as replies, checksums breaking the pairing, Ctrl-X swallowed, the
emergency shown only after the next command, `help` sent to the robot, Ctrl-C killing the
console; in script mode: stopping at the first failure, leaving the robot moving or latched.

The console runs in a private tmux server (send-keys / capture-pane). Waits poll the pane with
generous time-outs; no wall-clock threshold decides a pass.

    console_test.py console|script|options ROBUTERD ROBUTERCTL
"""
import fcntl
import os
import re
import shutil
import subprocess
import sys
import tempfile
import termios
import time
import tty

WAIT = 30.0  # generous: a loaded 2-core machine
FAILS = []
OPEN = []  # daemons and tmux servers to end whatever happens


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what, flush=True)
    if not cond:
        FAILS.append(what)
    return cond


class Robuterd:
    def __init__(self, exe, tmp, name="r"):
        self.pty = os.path.join(tmp, name + ".pty")
        self.obs = os.path.join(tmp, name + "-observer.pty")  # a second link, to watch the robot
        self.log = open(os.path.join(tmp, name + ".log"), "w")
        OPEN.append(self)
        self.proc = subprocess.Popen([exe, "--sim", "--sonar-model", "ideal", "--pty", self.pty, "--pty", self.obs, "--log-level", "warn"],
                                     stdout=self.log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + WAIT
        while not (os.path.islink(self.pty) and os.path.islink(self.obs)):
            if time.monotonic() > deadline or self.proc.poll() is not None:
                raise SystemExit("robuterd did not create " + self.pty)
            time.sleep(0.05)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(2)
            try:
                self.proc.wait(20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        if not self.log.closed:
            self.log.close()


class Raw:
    """A plain client of the link (what a lab script would do)."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)
        self.buf = b""

    def send(self, line):
        os.write(self.fd, line.encode() + b"\r")

    def reply(self, timeout=WAIT):
        """The next line that is not a stream line."""
        import select
        deadline = time.monotonic() + timeout
        while True:
            while b"\r" in self.buf or b"\n" in self.buf:
                i = min(x for x in (self.buf.find(b"\r"), self.buf.find(b"\n")) if x >= 0)
                line, self.buf = self.buf[:i].decode(), self.buf[i + 1:]
                if line and not line.startswith("@"):
                    return line
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            if select.select([self.fd], [], [], left)[0]:
                self.buf += os.read(self.fd, 4096)

    def ask(self, line):
        self.send(line)
        return self.reply()

    def unread(self):
        n = fcntl.ioctl(self.fd, termios.FIONREAD, b"\0\0\0\0")
        return int.from_bytes(n, sys.byteorder)

    def close(self):
        os.close(self.fd)


class Pane:
    """robuterctl in a private tmux server."""

    def __init__(self, tmp, command, name="c"):
        OPEN.append(self)
        self.sock = os.path.join(tmp, name + ".tmux")
        env = dict(os.environ, HOME=tmp)
        env.pop("TMUX", None)
        self.env = env
        self.status = os.path.join(tmp, name + ".status")
        wrapped = f"{command}; echo $? > {self.status}; sleep 600"
        self.tmux("new-session", "-d", "-x", "160", "-y", "50", wrapped)

    def tmux(self, *args):
        return subprocess.run(["tmux", "-S", self.sock, *args], env=self.env, check=True,
                              capture_output=True, text=True).stdout

    def keys(self, *keys):
        self.tmux("send-keys", "-t", "0", *keys)

    def type(self, line):
        self.tmux("send-keys", "-t", "0", "-l", line)
        self.tmux("send-keys", "-t", "0", "Enter")

    def screen(self):
        return self.tmux("capture-pane", "-p", "-J", "-S", "-2000", "-t", "0")

    def wait(self, pattern, after=0, timeout=WAIT):
        """Waits for `pattern` (a regex) in the screen after offset `after`; the match or None."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            m = re.compile(pattern, re.M).search(self.screen(), after)
            if m:
                return m
            time.sleep(0.05)
        print("---- screen ----\n" + self.screen() + "----------------", flush=True)
        return None

    def mark(self):
        """Where new output starts: at the prompt's line, which printing above it rewrites."""
        s = self.screen().rstrip()
        return s.rfind("\n") + 1

    def exit_status(self, timeout=WAIT):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if os.path.exists(self.status):
                text = open(self.status).read().strip()
                if text:
                    return int(text)
            time.sleep(0.05)
        return None

    def close(self):
        subprocess.run(["tmux", "-S", self.sock, "kill-server"], env=self.env, capture_output=True)


def console(robuterd, ctl, tmp):
    # ---- a stale reply waits in the pty: BO must not be answered by it ----
    d = Robuterd(robuterd, tmp, "stale")
    holder = Raw(d.pty)
    holder.send("BC")  # its reply `C n` is left unread
    deadline = time.monotonic() + WAIT
    while holder.unread() == 0 and time.monotonic() < deadline:
        time.sleep(0.02)
    check(holder.unread() > 0, "stale: a reply sits unread in the pty")
    p = Pane(tmp, f"{ctl} --port {d.pty} --log {tmp}/console.log", "stale")
    check(p.wait(r"connected") is not None, "stale: robuterctl connects")
    m = p.mark()
    p.type("BO")
    check(p.wait(r"^< S -?\d+ -?\d+ -?\d+ [01] \d+$", m) is not None, "stale: BO answered by S (posture), not the stale C")
    check(re.search(r"^< C ", p.screen(), re.M) is None, "stale: the stale C reply is never shown as a reply")
    p.close()
    holder.close()
    d.stop()

    d = Robuterd(robuterd, tmp, "robot")
    p = Pane(tmp, f"{ctl} --port {d.pty} --history {tmp}/history", "main")
    check(p.wait(r"connected") is not None, "robuterctl connects")

    # ---- help is local ----
    m = p.mark()
    p.type("help")
    check(p.wait(r"Commands \(Tab completes", m) is not None, "help: the local list")
    check(p.wait(r"XM .*map", m) is not None, "help: lists the extensions (XM)")
    m = p.mark()
    p.type("help AM")
    check(p.wait(r"AM <left> <right>", m) is not None, "help AM: its syntax")
    check(re.search(r"^< error", p.screen(), re.M) is None, "help: never sent to the robot")

    # ---- completion offers the extensions ----
    m = p.mark()
    p.keys("X", "Tab", "Tab")
    got = p.wait(r"XM", m)
    check(got is not None and all(w in p.screen()[m:] for w in ("XD", "XG", "XH", "XP", "XL1", "XC1")),
          "completion: XD, XG, XH, XP, XM, XL* offered")
    p.keys("C-c")

    # ---- the status stream on: @ lines are not replies ----
    m = p.mark()
    p.type("XS10")
    check(p.wait(r"^< ack", m) is not None, "stream: XS10 acknowledged")
    for _ in range(3):
        m = p.mark()
        p.type("BO")
        check(p.wait(r"^< S -?\d+ -?\d+ -?\d+ [01] \d+$", m) is not None, "stream: BO answered by S")
    check(re.search(r"^< @", p.screen(), re.M) is None, "stream: no @ line shown as a reply")
    m = p.mark()
    p.type("XS0")
    check(p.wait(r"^< ack", m) is not None, "stream: XS0 acknowledged")

    # ---- checksums on: robuterctl appends and checks them ----
    m = p.mark()
    p.type("XC1")
    check(p.wait(r"^< ack", m) is not None, "checksums: XC1 acknowledged")
    for cmd, rx in (("BC", r"^< C \d+$"), ("XE", r"^< E \d \d \S+ "), ("BT", r"^< T \d+$")):
        m = p.mark()
        p.type(cmd)
        check(p.wait(rx, m) is not None, f"checksums: {cmd} answered and paired")
    check("checksum missing or wrong" not in p.screen() and re.search(r"^< error", p.screen(), re.M) is None,
          "checksums: every reply's checksum right, nothing refused")
    m = p.mark()
    p.type("XC0")
    check(p.wait(r"^< ack$", m) is not None, "checksums: XC0 (sent with its checksum) acknowledged")
    # ---- the terminator modes ----
    for mode in ("XL1", "XL2"):
        m = p.mark()
        p.type(mode)
        p.type("BC")
        check(p.wait(r"^< C \d+$", m) is not None, f"terminator {mode}: BC answered")
    p.type("XL0")

    # ---- Ctrl-C cancels the line, the console lives on ----
    m = p.mark()
    p.keys("AM 5 5")
    p.keys("C-c")
    check(p.wait(r"\^C", m) is not None, "Ctrl-C: the line is cancelled")
    m = p.mark()
    p.type("BC")
    check(p.wait(r"^< C \d+$", m) is not None, "Ctrl-C: the console still answers")
    check(re.search(r"^< ack", p.screen()[m:], re.M) is None, "Ctrl-C: the cancelled AM was not sent")

    # ---- the stop key stops a moving robot, and the banner comes by itself ----
    m = p.mark()
    p.type("ASN")
    p.type("AM 10 -10")  # turning on the spot: no obstacle in the way
    check(p.wait(r"^< ack\n(.*\n)*< ack", m) is not None, "stop key: ASN and AM acknowledged")
    robot = Raw(d.obs)  # a client on robuterd's second link, watching the robot
    m = p.mark()
    p.keys("C-x")
    check(p.wait(r"stop byte sent", m) is not None, "stop key: Ctrl-X sends the stop byte at once")
    check(p.wait(r"EMERGENCY LATCHED: stop-byte", m) is not None,
          "live banner: the emergency and its cause shown without a command")
    # The robot coasts to rest (the drive ramps down; how far it gets before the first BO depends
    # on this machine's load): within 3 s, two postures 0.5 s apart must agree, servo off.
    a = b = None
    deadline = time.monotonic() + 3.0
    while time.monotonic() < deadline:
        a = robot.ask("BO")
        time.sleep(0.5)
        b = robot.ask("BO")
        if a is not None and b is not None and a.split()[1:4] == b.split()[1:4]:
            break
    check(a is not None and b is not None and a.split()[1:4] == b.split()[1:4] and a.split()[4] == "0",
          f"stop key: the robot comes to rest, servo off ({a} / {b})")
    robot.close()
    # ---- XR: cleared, and no banner right after its ack ----
    m = p.mark()
    p.type("XR")
    check(p.wait(r"emergency cleared", m) is not None, "XR: the console says the emergency is cleared")
    time.sleep(1.0)
    check("EMERGENCY LATCHED" not in p.screen()[m:], "XR: no EMERGENCY LATCHED after XR acked")
    # ---- the stop command ----
    m = p.mark()
    p.type("stop")
    check(p.wait(r"EMERGENCY LATCHED: stop-byte", m) is not None, "stop command: the robot stops and latches")
    p.type("XR")

    # ---- decoding: one reply, once ----
    for cmd, words in (("XK", r"kernel: \d+ ticks"), ("XD", r"pan-tilt \S+  gate"), ("XP", r"planner \S+  goal"),
                       ("XV", r"capabilities:"), ("XM", r"map 41 x 41 cells")):
        m = p.mark()
        p.type(cmd)
        check(p.wait(words, m) is not None, f"decoding: {cmd} decoded")
        check(len(re.findall(r"^< " + cmd[1], p.screen()[m:], re.M)) == 1, f"decoding: {cmd}'s reply printed once")

    # ---- Ctrl-D quits, history kept ----
    p.keys("C-d")
    check(p.exit_status() == 0, "Ctrl-D: robuterctl exits 0")
    hist = open(f"{tmp}/history").read() if os.path.exists(f"{tmp}/history") else ""
    check("XR" in hist and "help AM" in hist, "history saved")
    p.close()
    d.stop()

    # ---- an obstacle ahead: a protective stop (no latch), shown live ----
    d = Robuterd(robuterd, tmp, "obstacle")
    p = Pane(tmp, f"{ctl} --port {d.pty}", "obstacle")
    check(p.wait(r"connected") is not None, "obstacle: robuterctl connects")
    m = p.mark()
    p.type("ASN")
    p.type("AM 40 40")
    check(p.wait(r"PROTECTIVE STOP", m, timeout=90) is not None,
          "live banner: a protective stop shown when it happens, nothing typed")
    check("EMERGENCY LATCHED" not in p.screen()[m:], "protective stop: no emergency, nothing latched")
    p.close()
    d.stop()


def script(robuterd, ctl, tmp):
    def write(name, text):
        path = os.path.join(tmp, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    d = Robuterd(robuterd, tmp, "script")
    # ---- keep going; closing count; left stopped with AM 0 0 then ASF; transcript ----
    s = write("keep.txt", "> ASN\n< ack\n> AM 10 -10\n< ack\n! sleep 500\n> BC\n< X {int}\n> BT\n< T {int}\n> BC\n< C {int}\n")
    log = os.path.join(tmp, "script.log")
    r = subprocess.run([ctl, "--port", d.pty, "--keep-going", "--log", log, "--script", s],
                       capture_output=True, text=True, timeout=120)
    print(r.stdout, r.stderr)
    check(r.returncode == 1, "keep-going: a failed script exits 1")
    check("4 passed, 1 failed" in r.stdout, "keep-going: the checks after the failure ran; closing N passed, N failed")
    robot = Raw(d.obs)
    # The wheels run down after AM 0 0 (the sim's drive ramps, the servo is then off): wait for
    # the robot to come to rest, then it must stay there with nothing latched.
    deadline = time.monotonic() + WAIT
    while True:
        a = robot.ask("BO")
        time.sleep(0.3)
        b = robot.ask("BO")
        if a is None or b is None or a.split()[1:4] == b.split()[1:4] or time.monotonic() > deadline:
            break
    check(a is not None and b is not None and a.split()[1:4] == b.split()[1:4] and a.split()[4] == "0",
          f"left stopped: at rest, servo off ({a} / {b})")
    xe = robot.ask("XE")
    check(xe is not None and xe.split()[2] == "0", f"left stopped: no emergency latched ({xe})")
    robot.close()
    text = open(log).read()
    check(re.search(r"^\d\d:\d\d:\d\d\.\d{3} > AM 0 0\n\d\d:\d\d:\d\d\.\d{3} < ack\n\d\d:\d\d:\d\d\.\d{3} > ASF$", text, re.M)
          is not None, "transcript: times, and AM 0 0 then ASF at the end")
    check("\\x18" not in text, "left stopped: never with the stop byte")

    # ---- without --keep-going: stops at the first failure, still leaves the robot stopped ----
    r = subprocess.run([ctl, "--port", d.pty, "--script", s], capture_output=True, text=True, timeout=120)
    check(r.returncode == 1 and "2 passed, 1 failed" in r.stdout and "AM 0 0 → ack, ASF → ack" in r.stdout,
          "first failure: stops there, robot left stopped")

    # ---- stream lines are skipped by expectations ----
    s = write("stream.txt", "> XS10\n< ack\n" + "! sleep 150\n> BO\n< S {ints:5}\n" * 4 + "< @ {any}\n> XS0\n< ack\n")
    r = subprocess.run([ctl, "--port", d.pty, "--script", s], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "stream: @ lines are not replies in a script\n" + r.stdout)

    # ---- until: an exchange tried again until the robot has got there, whatever the load ----
    s = write("until.txt", "> AM 0 0\n< ack\n> AC 0 0 0\n< ack\n> ASN\n< ack\n> AM 10 10\n< ack\n"
              "! until 20000\n> BO\n< S {int:300..100000} {int} {int} 1 {int}\n> AM 0 0\n< ack\n")
    r = subprocess.run([ctl, "--port", d.pty, "--script", s], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0 and "6 passed, 0 failed" in r.stdout,
          "until: BO asked again until the robot has moved 3 cm, one check\n" + r.stdout)
    s = write("until_fails.txt", "! until 400\n> BC\n< X {int}\n")
    r = subprocess.run([ctl, "--port", d.pty, "--script", s], capture_output=True, text=True, timeout=120)
    check(r.returncode == 1 and "0 passed, 1 failed" in r.stdout and "got 'C " in r.stdout,
          "until: a reply that never matches fails once, with the last reply\n" + r.stdout)

    # ---- a stale reply left in the pty ----
    holder = Raw(d.pty)
    holder.send("BC")
    deadline = time.monotonic() + WAIT
    while holder.unread() == 0 and time.monotonic() < deadline:
        time.sleep(0.02)
    s = write("stale.txt", "> BO\n< S {ints:5}\n")
    r = subprocess.run([ctl, "--port", d.pty, "--script", s], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "stale: the script's BO is answered by S\n" + r.stdout)
    holder.close()

    # ---- the stop key in script mode (in tmux) ----
    s = write("stopkey.txt", "> XR\n< ack\n> ASN\n< ack\n> AM 10 -10\n< ack\n! sleep 60000\n> XE\n< E {int} 1 stop-byte {any}\n")
    p = Pane(tmp, f"{ctl} --port {d.pty} --script {s}", "stopkey")
    time.sleep(1.0)
    p.keys("C-x")
    check(p.wait(r"stop byte sent") is not None, "script: Ctrl-X sends the stop byte")
    # the sleep is not cut short by the key; Ctrl-C ends it and the robot is left stopped
    p.keys("C-c")
    check(p.wait(r"robot left stopped: AM 0 0 → ack, ASF → ack") is not None, "script: Ctrl-C ends it, robot left stopped")
    check(p.exit_status() == 1, "script: interrupted exits 1")
    p.close()
    d.stop()


def options(robuterd, ctl, tmp):
    r = subprocess.run([ctl, "--version"], capture_output=True, text=True)
    check(r.returncode == 0 and r.stdout.startswith("robuterctl "), "--version")
    r = subprocess.run([ctl, "--no-such-option"], capture_output=True, text=True)
    check(r.returncode == 2, f"unknown option: exit 2 (got {r.returncode})")
    r = subprocess.run([ctl, "--baud", "1234", "--port", "/dev/null"], capture_output=True, text=True)
    check(r.returncode == 2 and "1234" in r.stderr, "--baud 1234: refused, exit 2")
    missing = os.path.join(tmp, "nothing.pty")
    r = subprocess.run([ctl, "--port", missing], capture_output=True, text=True)
    check(r.returncode == 1 and "No such file or directory" in r.stderr and "is robuterd running?" in r.stderr
          and "make run" in r.stderr, "missing port: the reason and the hint")
    d = Robuterd(robuterd, tmp, "opt")
    r = subprocess.run([ctl, "--port", d.pty, "--script", missing], capture_output=True, text=True)
    check(r.returncode == 1 and "No such file or directory" in r.stdout, "missing script: the reason")
    d.stop()


def main():
    which, robuterd, ctl = sys.argv[1:4]
    if shutil.which("tmux") is None and which != "options":
        print("tmux is not installed (tools/deps/debian-packages.txt)")
        return 1
    tmp = tempfile.mkdtemp(prefix="robuterctl-")
    try:
        {"console": console, "script": script, "options": options}[which](robuterd, ctl, tmp)
    finally:
        for thing in reversed(OPEN):
            thing.close() if isinstance(thing, Pane) else thing.stop()
        shutil.rmtree(tmp, ignore_errors=True)
    print(f"{'FAIL' if FAILS else 'ok'}: {len(FAILS)} failed", flush=True)
    return 1 if FAILS else 0


if __name__ == "__main__":
    sys.exit(main())
