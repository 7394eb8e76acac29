# SPDX-License-Identifier: GPL-3.0-or-later
"""The client on its own: reply decoding, and pairing by protocol against a fake robot on a pty
(stale input flushed on open, status lines kept apart, any reply terminator). No robuterd."""
import os
import select
import threading
import tty

import pytest

from robuter import Emergency, Posture, ProtocolError, Ranges, Robot, RobuterError, Status, crc16


def test_decodes_the_replies_of_protocol_md():
    assert Posture.parse("S 1204 -3 12 1 1540") == Posture(1204, -3, 12, True, 1540)
    assert Posture.parse("S 10000 0 9000 0 1").theta_deg == 90.0
    r = Ranges.parse("U " + " ".join(str(i * 10) for i in range(1, 25)) + " 1 1544")
    assert r.sensor(1) == 10 and r.sensor(24) == 240 and r.servo and r.clock == 1544
    assert Status.parse("@ 1204 -3 12 1 10 10 0 1603") == Status(1204, -3, 12, True, 10, 10, 0,
                                                               1603, "@ 1204 -3 12 1 10 10 0 1603")
    with pytest.raises(ProtocolError):
        Posture.parse("S 1 2 3")
    with pytest.raises(ProtocolError):
        Posture.parse("C 1523")


def test_emergency_keeps_the_fields_after_the_clock():
    assert Emergency.parse("E 0 1 obstacle 7 18234") == Emergency(False, True, "obstacle", 7, 18234)
    e = Emergency.parse("E 1 0 none 3 55 later-field 42")
    assert (e.held, e.latched, e.cause, e.mask, e.clock) == (True, False, "none", 3, 55)
    assert e.extra == ("later-field", "42")
    p = Emergency.parse("E 0 0 none 7 18530 0 envelope 1")
    assert (p.granted, p.rule, p.protective) == (0, "envelope", True)
    assert not Emergency.parse("E 0 0 none 7 18234 42 envelope 0").protective
    assert Emergency.parse("E 0 1 obstacle 7 18234").granted is None


def test_errors_carry_code_and_word():
    e = RobuterError("AM 10", "error 2 bad-parameter-count")
    assert (e.code, e.word, e.line) == (2, "bad-parameter-count", "AM 10")
    bare = RobuterError("Zz", "error")
    assert (bare.code, bare.word) == (None, None)


def test_crc_is_ccitt_false():
    assert crc16(b"123456789") == 0x29B1
    assert f"{crc16(b'BC'):04X}" == "0E06"  # docs/PROTOCOL.md §9


class FakeRobot:
    """The master side of a pty: answers each line with ``answer(line)`` (bytes to write)."""

    def __init__(self, answer):
        self.master, self.slave = os.openpty()
        tty.setraw(self.master)
        self.path = os.ttyname(self.slave)
        self.answer = answer
        self.lines = []
        self._stop = False
        self._thread = threading.Thread(target=self._serve, daemon=True)

    def start(self):
        self._thread.start()

    def _serve(self):
        buf = b""
        while not self._stop:
            if not select.select([self.master], [], [], 0.05)[0]:
                continue
            buf += os.read(self.master, 4096)
            while b"\r" in buf:
                line, buf = buf.split(b"\r", 1)
                self.lines.append(line.decode())
                os.write(self.master, self.answer(line.decode()))

    def close(self):
        self._stop = True
        if self._thread.is_alive():
            self._thread.join()
        os.close(self.master)
        os.close(self.slave)


@pytest.fixture
def fake():
    made = []

    def make(answer):
        f = FakeRobot(answer)
        made.append(f)
        return f
    yield make
    for f in made:
        f.close()


def test_stale_input_is_flushed_on_open(fake):
    peer = fake(lambda line: b"S 1 2 3 0 5\r" if line == "BO" else b"error\r")
    os.write(peer.master, b"C 444\r")  # a reply an earlier client left unread
    with Robot(peer.path, timeout=10, verbose=False) as robot:
        peer.start()
        assert robot.posture() == Posture(1, 2, 3, False, 5)


def test_status_lines_are_never_replies(fake):
    def answer(line):
        if line == "BO":
            return b"@ 7 0 0 1 10 10 0 99\r@ 8 0 0 1 10 10 2 100\rS 8 0 0 1 100\r"
        return b"ack\r"
    peer = fake(answer)
    peer.start()
    seen = []
    with Robot(peer.path, timeout=10, on_status=seen.append) as robot:
        assert robot.posture().x == 8
        assert [s.x for s in robot.status] == [7, 8] and seen == list(robot.status)
        assert robot.status[-1].emergency == 2
    assert peer.lines == ["XB1", "BO"]


@pytest.mark.parametrize("terminator", [b"\r", b"\n", b"\r\n"])
def test_any_reply_terminator(fake, terminator):
    peer = fake(lambda line: (b"C 7" if line == "BC" else b"ack") + terminator)
    peer.start()
    with Robot(peer.path, timeout=10) as robot:
        assert [robot.clock() for _ in range(3)] == [7, 7, 7]


def test_error_reply_raises_with_code(fake):
    peer = fake(lambda line: b"ack\r" if line == "XB1" else b"error 2 bad-parameter-count\r")
    peer.start()
    with Robot(peer.path, timeout=10) as robot:
        assert robot.send("AM 10") == "error 2 bad-parameter-count"
        with pytest.raises(RobuterError) as e:
            robot.move(10, 10)
        assert (e.value.code, e.value.word) == (2, "bad-parameter-count")


def test_no_reply_is_a_protocol_error(fake):
    peer = fake(lambda line: b"ack\r" if line == "XB1" else b"")
    peer.start()
    with Robot(peer.path, timeout=0.3) as robot:
        with pytest.raises(ProtocolError):
            robot.send("BO")
        # A late reply would answer the next line: the client refuses to guess.
        with pytest.raises(ProtocolError):
            robot.send("BC")
        with pytest.raises(ValueError):
            robot.send("BC\rBO")
