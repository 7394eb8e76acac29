#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Installs the robuterd .deb, checks its files, and starts robuterd.service's command as systemd would."""
# Usage (as root): tools/test/package_test.py build-deb/robuterd_<version>_<arch>.deb
#
# systemd is not PID 1 where this runs (containers, CI), so the service is started the way the
# service manager would: RuntimeDirectory= created and owned by User=, Environment= then
# EnvironmentFile= applied, $VAR words split as systemd splits them, ExecStartPre= then
# ExecStart= run under User=/Group= with the user's supplementary groups (setpriv). What this
# does not exercise is written in docs/INSTALL.md, "What the package test covers".
import os
import pwd
import grp
import re
import shlex
import signal
import subprocess
import sys
import time

import serial  # python3-serial

PACKAGE = "robuterd"
UNIT = "/lib/systemd/system/robuterd.service"
EXPECTED_FILES = [
    "/usr/bin/robuterd", "/usr/bin/robuterctl", "/usr/bin/robuter-plan", "/usr/bin/robuter-sim",
    "/usr/bin/robuter-doors-run", "/usr/bin/robuter-can-nodes", "/etc/robuterd/robuterd.toml", "/etc/default/robuterd", UNIT,
    "/usr/lib/sysusers.d/robuterd.conf", "/usr/share/robuterd/worlds/default.toml",
    "/usr/share/robuterd/udev/99-robuterd.rules", "/usr/share/doc/robuterd/INSTALL.md.gz",
]
EXPECTED_CONFFILES = ["/etc/robuterd/robuterd.toml", "/etc/default/robuterd"]

passed = 0
failed = 0


# One check's verdict, printed as it happens; the last line adds them up.
def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print(f"ok   {what}", flush=True)
    else:
        failed += 1
        print(f"FAIL {what}", flush=True)
    return ok


# Runs a command, echoing it; its output is returned for the checks.
def run(cmd, **kw):
    print("+ " + " ".join(shlex.quote(c) for c in cmd), flush=True)
    return subprocess.run(cmd, text=True, capture_output=True, **kw)


def installed():
    r = subprocess.run(["dpkg-query", "-W", "-f=${Status}", PACKAGE], text=True, capture_output=True)
    return r.stdout.strip() == "install ok installed"


# The [Service] section as a dict of lists (a key may repeat, e.g. Environment=).
def parse_unit(path):
    section, out = None, {}
    for raw in open(path, encoding="utf-8"):
        line = raw.strip()
        if not line or line[0] in "#;":
            continue
        if line.startswith("["):
            section = line.strip("[]")
            continue
        key, _, value = line.partition("=")
        out.setdefault((section, key.strip()), []).append(value.strip())
    return out


# Environment=: space-separated assignments, each possibly in double quotes (systemd.exec(5)).
def parse_environment(values, env):
    for value in values:
        for word in shlex.split(value):
            k, _, v = word.partition("=")
            env[k] = v


# EnvironmentFile=: KEY=VALUE lines, # comments, optional quotes; a leading "-" means optional.
def parse_environment_file(spec, env):
    optional = spec.startswith("-")
    path = spec.lstrip("-")
    if not os.path.exists(path):
        return optional
    for raw in open(path, encoding="utf-8"):
        line = raw.strip()
        if not line or line[0] in "#;":
            continue
        k, _, v = line.partition("=")
        words = shlex.split(v) if v else [""]
        env[k.strip()] = " ".join(words)
    return True


# systemd's command-line expansion: a word that is just $NAME becomes the value split at
# whitespace (zero or more words); ${NAME} inside a word is replaced as one string.
def expand(line, env):
    out = []
    for word in shlex.split(line):
        m = re.fullmatch(r"\$([A-Za-z_][A-Za-z0-9_]*)", word)
        if m:
            out.extend(env.get(m.group(1), "").split())
            continue
        out.append(re.sub(r"\$\{([A-Za-z_][A-Za-z0-9_]*)\}", lambda g: env.get(g.group(1), ""), word))
    return out


# The service's process as systemd starts it: its user, group and the user's groups, "/" as the
# working directory, standard input from /dev/null, the environment assembled above.
def as_service(cmd, user, group, env):
    return ["setpriv", f"--reuid={user}", f"--regid={group}", "--init-groups", "--"] + cmd, env


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    deb = os.path.abspath(sys.argv[1])
    if os.geteuid() != 0:
        print("package test: must run as root (it installs the package with dpkg)", file=sys.stderr)
        return 2
    was_installed = installed()
    if was_installed:
        print("note: robuterd was installed before the test; it is replaced and purged at the end")

    # 1. Install (apt-get resolves the Depends; the dpkg lock is waited for, never taken away).
    r = run(["apt-get", "install", "-y", "-q", "--no-remove", "-o", "DPkg::Lock::Timeout=300", deb],
            env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    if not check(r.returncode == 0 and installed(), f"package installs ({os.path.basename(deb)})"):
        print(r.stdout[-3000:], r.stderr[-3000:])
        return 1
    proc = None
    runtime_dir = None
    try:
        # 2. The files, conffiles, user and enablement the package promises.
        for f in EXPECTED_FILES:
            check(os.path.isfile(f), f"installed: {f}")
        for f in ["/usr/bin/robuterd", "/usr/bin/robuterctl", "/usr/bin/robuter-plan", "/usr/bin/robuter-sim",
                  "/usr/bin/robuter-doors-run", "/usr/bin/robuter-can-nodes"]:
            check(os.access(f, os.X_OK), f"executable: {f}")
        conf = run(["dpkg-query", "-W", "-f=${Conffiles}", PACKAGE]).stdout
        for f in EXPECTED_CONFFILES:
            check(f in conf, f"conffile: {f}")
        try:
            pw = pwd.getpwnam("robuterd")
            check(True, f"system user robuterd (uid {pw.pw_uid}) created by the package")
            check("robuterd" in grp.getgrnam("dialout").gr_mem, "robuterd is in dialout")
        except KeyError:
            check(False, "system user robuterd created by the package")
            return 1
        check(os.path.islink("/etc/systemd/system/multi-user.target.wants/robuterd.service"),
              "robuterd.service enabled (multi-user.target.wants)")
        v = run(["/usr/bin/robuterd", "--version"])
        check(v.returncode == 0 and v.stdout.startswith("robuterd "), f"robuterd --version: {v.stdout.strip()}")
        c = run(["/usr/bin/robuterd", "--check-config", "--config", "/etc/robuterd/robuterd.toml"])
        check(c.returncode == 0, "the installed configuration is valid: " + c.stdout.strip())
        d = run(["/usr/bin/robuter-doors-run", "--world", "door90", "--seed", "1"], cwd="/")
        check(d.returncode == 0 and "doors crossed" in d.stdout,
              "robuter-doors-run crosses the installed worlds' door90: " + (d.stdout + d.stderr).strip())

        unit = parse_unit(UNIT)
        svc = lambda k: unit.get(("Service", k), [])  # noqa: E731
        check(svc("Restart") == ["on-failure"], "unit: Restart=on-failure")
        check(unit.get(("Install", "WantedBy")) == ["multi-user.target"], "unit: WantedBy=multi-user.target")
        if os.path.exists("/usr/bin/systemd-analyze"):
            a = run(["systemd-analyze", "verify", UNIT])
            # Without systemd as PID 1 verify still loads and checks the unit file offline.
            check(a.returncode == 0, "systemd-analyze verify " + UNIT + (": " + a.stderr.strip() if a.stderr.strip() else ""))
        else:
            print("skip systemd-analyze verify (not installed)")

        # 3. Start the service as the service manager would.
        user, group = svc("User")[0], svc("Group")[0]
        runtime_dir = "/run/" + svc("RuntimeDirectory")[0]
        mode = int(svc("RuntimeDirectoryMode")[0], 8) if svc("RuntimeDirectoryMode") else 0o755
        os.makedirs(runtime_dir, exist_ok=True)
        os.chmod(runtime_dir, mode)
        os.chown(runtime_dir, pwd.getpwnam(user).pw_uid, grp.getgrnam(group).gr_gid)
        env = {"PATH": "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin", "LANG": "C.UTF-8",
               "HOME": "/", "USER": user, "LOGNAME": user, "RUNTIME_DIRECTORY": runtime_dir}
        parse_environment(svc("Environment"), env)
        for spec in svc("EnvironmentFile"):
            check(parse_environment_file(spec, env), f"EnvironmentFile={spec}")
        for pre in svc("ExecStartPre"):
            cmd, e = as_service(expand(pre, env), user, group, env)
            r = run(cmd, env=e, cwd="/", stdin=subprocess.DEVNULL)
            check(r.returncode == 0, f"ExecStartPre exits 0: {r.stdout.strip()}{r.stderr.strip()}")
        start = expand(svc("ExecStart")[0], env)
        cmd, e = as_service(start, user, group, env)
        print("+ " + " ".join(shlex.quote(c) for c in cmd), flush=True)
        log = open(os.path.join("/tmp", f"robuterd-package-test-{os.getpid()}.log"), "w+")
        proc = subprocess.Popen(cmd, env=e, cwd="/", stdin=subprocess.DEVNULL, stdout=log, stderr=log)
        pty = next((a.split("=", 1)[1] if "=" in a else start[i + 1]
                    for i, a in enumerate(start) if a.startswith("--pty")), None)
        check(pty == "/run/robuterd/robuter.pty", f"the default service serves its link on {pty}")
        for _ in range(200):
            if os.path.islink(pty) or proc.poll() is not None:
                break
            time.sleep(0.05)
        if not check(os.path.islink(pty) and proc.poll() is None, f"robuterd running, {pty} -> {os.path.realpath(pty)}"):
            log.seek(0)
            print(log.read()[-3000:])
            return 1
        status = open(f"/proc/{proc.pid}/status").read()
        uid = int(re.search(r"^Uid:\s+(\d+)", status, re.M).group(1))
        check(uid == pwd.getpwnam(user).pw_uid, f"robuterd runs as {user} (uid {uid})")

        # 4. Talk to it over its pty: BO answered with the posture.
        with serial.Serial(pty, 9600, timeout=3) as s:
            s.write(b"BO\r")
            reply = s.read_until(b"\r")
            check(re.fullmatch(rb"S -?\d+ -?\d+ -?\d+ [01] \d+\r", reply) is not None, f"BO answered: {reply!r}")
            s.write(b"BC\r")
            first = s.read_until(b"\r")
            check(re.fullmatch(rb"C \d+\r", first) is not None, f"BC answered: {first!r}")
            time.sleep(1.0)  # the service's kernel keeps ticking on its real-time clock
            s.write(b"BC\r")
            later = s.read_until(b"\r")
            check(re.fullmatch(rb"C \d+\r", later) is not None and int(later[2:]) > int(first[2:]),
                  f"its clock advances: {first!r} then {later!r} a second later")

        # 5. Stop it as systemctl stop does (KillSignal=SIGTERM): a clean exit, which
        # Restart=on-failure does not restart.
        proc.send_signal(signal.SIGTERM)
        try:
            code = proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            code = None
        check(code == 0, f"SIGTERM stops robuterd cleanly (exit {code})")
        proc = None
        log.seek(0)
        text = log.read()
        check("starting" in text and "stopped" in text, "its log shows start and stop")
        check("sim: world /usr/share/robuterd/worlds/default.toml" in text,
              "the installed robuterd simulates the installed default world")
        log.close()
        if failed == 0:
            os.unlink(log.name)
        else:
            print(f"robuterd's output: {log.name}")
    finally:
        if proc is not None:
            proc.kill()
            proc.wait()
        if runtime_dir and os.path.isdir(runtime_dir):
            subprocess.run(["rm", "-rf", runtime_dir])  # RuntimeDirectory= goes with the service
        # 6. Purge: the package's files and conffiles go (the system user stays, as Debian's do).
        r = run(["dpkg", "--purge", PACKAGE])
        check(r.returncode == 0 and not installed(), "package purges")
        check(not os.path.exists("/usr/bin/robuterd") and not os.path.exists("/etc/robuterd/robuterd.toml"),
              "files and conffiles gone after purge")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
