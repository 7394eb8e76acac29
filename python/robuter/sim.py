# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs robuterd on its simulated robot (``robuterd --sim``) on a pty in a temporary folder.

    from robuter import Robot, sim
    with sim.start(world="empty") as robuterd, Robot(robuterd.port) as robot:
        print(robot.posture())

The binary is the ``binary`` argument, else the environment variable ``ROBUTERD``, else
``build/bin/robuterd`` of the source tree this package sits in, else ``robuterd`` on PATH.
"""
from __future__ import annotations

import os
import pathlib
import shutil
import signal
import subprocess
import tempfile
import time
from typing import Optional, Sequence

_REPO = pathlib.Path(__file__).resolve().parents[2]


class SimError(Exception):
    """robuterd could not be found or did not start."""


def find_binary(binary: Optional[str] = None) -> str:
    """The robuterd to run (see the module's docstring)."""
    for candidate in (binary, os.environ.get("ROBUTERD")):
        if candidate:
            if not os.access(candidate, os.X_OK):
                raise SimError(f"robuterd not executable: {candidate}")
            return os.path.abspath(candidate)
    built = _REPO / "build" / "bin" / "robuterd"
    if os.access(built, os.X_OK):
        return str(built)
    on_path = shutil.which("robuterd")
    if on_path:
        return on_path
    raise SimError("robuterd not found: build it (`make`), or set ROBUTERD=/path/to/robuterd")


def _world_path(world: str) -> str:
    """A path as given, or the name of one of the repository's worlds (``empty``, ``door90``…)."""
    if os.path.exists(world):
        return os.path.abspath(world)
    named = _REPO / "worlds" / (world if world.endswith((".toml", ".env")) else world + ".toml")
    if named.exists():
        return str(named)
    raise SimError(f"no such world: {world}")


class SimulatedRobot:
    """A running ``robuterd --sim``; ``port`` is its pty (a symbolic link in a temporary folder).
    ``stop()`` (or leaving the ``with`` block) ends it with SIGINT and removes the folder."""

    def __init__(self, command: Sequence[str], folder: str, port: str, log_path: str):
        self.command = list(command)
        self.folder = folder
        self.port = port
        self.log_path = log_path
        self.log_text = ""
        self.returncode: Optional[int] = None
        self._log = open(log_path, "wb")
        self.process = subprocess.Popen(self.command, stdin=subprocess.DEVNULL, stdout=self._log,
                                        stderr=subprocess.STDOUT)

    def log(self) -> str:
        """What robuterd has written so far (its log)."""
        if self.returncode is not None:
            return self.log_text
        with open(self.log_path, "rb") as f:
            return f.read().decode(errors="replace")

    def stop(self, timeout: float = 30.0) -> int:
        """Stops robuterd (SIGINT, SIGKILL if it does not end within ``timeout``) and returns
        its exit status; idempotent."""
        if self.returncode is None:
            if self.process.poll() is None:
                self.process.send_signal(signal.SIGINT)
                try:
                    self.process.wait(timeout)
                except subprocess.TimeoutExpired:
                    self.process.kill()
                    self.process.wait()
            self.returncode = self.process.returncode
            self._log.close()
            with open(self.log_path, "rb") as f:
                self.log_text = f.read().decode(errors="replace")
            shutil.rmtree(self.folder, ignore_errors=True)
        return self.returncode

    def __enter__(self) -> "SimulatedRobot":
        return self

    def __exit__(self, *exc) -> None:
        self.stop()


def start(world: Optional[str] = None, config: Optional[str] = None, binary: Optional[str] = None,
          args: Sequence[str] = (), speed: Optional[str] = None, seed: Optional[int] = None,
          log_level: str = "warn", timeout: float = 30.0, sonar_model: str = "ideal") -> SimulatedRobot:
    """Starts ``robuterd --sim --pty <tmp>/robuter.pty`` and waits (up to ``timeout`` s) for its
    pty. ``world``: a path or a name from ``worlds/``; ``config``: a TOML file; ``args``: more
    command-line options; ``sonar_model``: the simulator's sonars (``ideal``, ``stress`` or
    ``realistic``, docs/SIMULATOR.md) — ideal by default, so a script's readings repeat, unlike
    ``robuterd --sim`` alone, whose default is realistic."""
    exe = find_binary(binary)
    folder = tempfile.mkdtemp(prefix="robuter-sim-")
    port = os.path.join(folder, "robuter.pty")
    command = [exe, "--sim", "--sonar-model", sonar_model, "--pty", port, "--log-level", log_level]
    try:
        if world is not None:
            command += ["--world", _world_path(world)]
        if config is not None:
            command += ["--config", os.path.abspath(config)]
        if speed is not None:
            command += ["--speed", str(speed)]
        if seed is not None:
            command += ["--seed", str(seed)]
        command += list(args)
        robot = SimulatedRobot(command, folder, port, os.path.join(folder, "robuterd.log"))
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    deadline = time.monotonic() + timeout
    while not os.path.islink(port):
        if robot.process.poll() is not None or time.monotonic() > deadline:
            robot.stop()
            raise SimError(f"robuterd did not make its pty {port} (exit {robot.returncode}):\n"
                           + robot.log_text)
        time.sleep(0.02)
    return robot
