# SPDX-License-Identifier: GPL-3.0-or-later
"""robuter — a Python client for robuterd, the Robuter firmware (docs/PYTHON.md).

    from robuter import Robot
    with Robot("/tmp/robuter.pty") as robot:
        robot.servo(True)
        robot.move(10, 10)
        print(robot.posture(), robot.ranges().sensor(1))
"""
from .client import (Emergency, Posture, ProtocolError, Ranges, Robot, RobuterError, Status,
                     crc16)

__all__ = ["Robot", "RobuterError", "ProtocolError", "Posture", "Ranges", "Emergency", "Status",
           "crc16"]
__version__ = "0.1.0"
