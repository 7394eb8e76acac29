# SPDX-License-Identifier: GPL-3.0-or-later
"""pytest fixtures for lab scripts and tests: ``robuterd`` (a fresh ``robuterd --sim`` on a
temporary pty) and ``robot`` (a ``Robot`` connected to it). Load with ``-p robuter.pytest_plugin``
or ``pytest_plugins = ["robuter.pytest_plugin"]`` in a conftest.py.

Options of the simulated robot come from a marker on the test::

    @pytest.mark.robuterd(world="empty", args=["--seed", "3"])
    def test_drive(robot): ...

The environment variable ROBUTER_TIMEOUT sets the reply time-out in seconds (default 10: a
liveness bound, generous for sanitizer builds)."""
import os

import pytest

from . import sim
from .client import Robot


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "robuterd(**options): options of robuter.sim.start() for the test's robuterd")


def reply_timeout() -> float:
    return float(os.environ.get("ROBUTER_TIMEOUT", "10"))


@pytest.fixture
def robuterd(request):
    """A fresh simulated robuterd; after the test it must end cleanly (exit status 0)."""
    marker = request.node.get_closest_marker("robuterd")
    options = dict(marker.kwargs) if marker else {}
    running = sim.start(**options)
    try:
        yield running
    finally:
        status = running.stop()
    assert status == 0, f"robuterd exit status {status}:\n{running.log_text}"


@pytest.fixture
def robot(robuterd):
    """A Robot on the fresh simulated robuterd (verbose errors on)."""
    with Robot(robuterd.port, timeout=reply_timeout()) as connected:
        yield connected
