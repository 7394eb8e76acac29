# SPDX-License-Identifier: GPL-3.0-or-later
"""Conformance cases written with the client, against a fresh `robuterd --sim` each (the
`robot` fixture). These are the examples for lab scripts: no sleeps, since an `ack` means every
later query sees the command (docs/PROTOCOL.md, "What ack means"); waits for the simulated robot
to move are liveness bounds only."""
import time

import pytest

from robuter import Robot, RobuterError

WAIT = 60.0  # seconds: a liveness bound for the simulated robot to move, never a measurement


def wait_until(condition, what):
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.02)
    pytest.fail(f"not within {WAIT} s: {what}")


def test_servo_on_and_off_show_in_bo(robot):
    assert not robot.posture().servo
    robot.servo(True)
    assert robot.posture().servo
    robot.servo(False)
    assert not robot.posture().servo


@pytest.mark.robuterd(world="empty")
def test_driving_moves_the_posture_and_stop_holds_it(robot):
    start = robot.posture()
    robot.servo(True)
    robot.move(10, 10)
    moved = wait_until(lambda: (p := robot.posture()).x > start.x + 100 and p, "the robot drives")
    assert abs(moved.y) < 50 and abs(moved.theta) < 100  # straight ahead
    robot.stop()
    # At rest: two postures a few ticks apart are the same (every wheel speed 0).
    def at_rest():
        a = robot.posture()
        wait_until(lambda: robot.clock() >= a.clock + 5, "the clock runs")
        return robot.posture().x == a.x
    wait_until(at_rest, "the robot stops")
    assert not robot.emergency().latched


@pytest.mark.robuterd(world="empty")
def test_stop_byte_latches_and_reenable_clears(robot):
    robot.servo(True)
    robot.move(10, 10)
    robot.stop_byte()
    e = robot.emergency()
    assert e.latched and e.cause == "stop-byte"
    assert not robot.posture().servo
    with pytest.raises(RobuterError) as refused:
        robot.move(10, 10)
    assert (refused.value.code, refused.value.word) == (7, "refused-emergency")
    robot.reenable(wait=WAIT)  # accepted once the robot has come to rest
    e = robot.emergency()
    assert not e.latched and e.cause == "none"
    robot.servo(True)
    robot.move(5, 5)  # driving is allowed again
    robot.stop()


@pytest.mark.parametrize("line, code, word", [
    ("AM 10", 2, "bad-parameter-count"),
    ("AM 1.5 2", 3, "not-a-number"),
    ("AM 5000 0", 4, "out-of-range"),
    ("AC 1 2", 2, "bad-parameter-count"),
    ("ASX", 10, "bad-parameter"),
    ("Zz", 1, "unknown-command"),
    ("A", 9, "line-too-short"),
])
def test_a_malformed_line_is_an_error_and_changes_nothing(robot, line, code, word):
    robot.set_posture(1000, 2000, 4500)
    before = robot.posture()
    with pytest.raises(RobuterError) as e:
        robot.command(line)
    assert (e.value.code, e.value.word) == (code, word)
    after = robot.posture()
    assert (after.x, after.y, after.theta, after.servo) == (before.x, before.y, before.theta, False)
    assert not robot.emergency().latched
    assert robot.clock() >= after.clock  # and the link still answers


def test_bare_errors_without_verbose(robuterd):
    with Robot(robuterd.port, timeout=10, verbose=False) as robot:
        assert robot.send("AM 10") == "error"
        with pytest.raises(RobuterError) as e:
            robot.command("Zz")
        assert e.value.code is None


def test_ranges_are_24_sensors(robot):
    ranges = wait_until(lambda: (r := robot.ranges()).mm.count(0) < 24 and r, "a first echo")
    assert len(ranges.mm) == 24 and all(0 <= mm <= 10000 for mm in ranges.mm)


def test_status_stream_is_kept_apart_from_replies(robot):
    robot.stream(10)
    for _ in range(50):  # the stream runs while replies are paired
        assert robot.posture().x == 0
    wait_until(lambda: robot.status or robot.poll_status(0.1), "a status line")
    assert robot.status[0].left == 0 and robot.status[0].emergency == 0
    robot.stream(0)


def test_checksums_and_terminators_on_the_real_firmware(robot):
    assert robot.send("XC1") == "ack"
    assert robot.posture().x == 0  # sent and read with *HHHH
    assert robot.send("XL2") == "ack"
    robot.servo(True)
    assert robot.posture().servo
    assert robot.send("XC0") == "ack"
    assert robot.emergency().cause == "none"


def test_version_names_the_extensions(robot):
    words = robot.version().split()
    assert words[:2] == ["V", "robuterd"]
    assert {"stop", "emergency", "reenable", "stream"} <= set(words[-1].split(","))
