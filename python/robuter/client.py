# SPDX-License-Identifier: GPL-3.0-or-later
"""A client for robuterd's command link (docs/PROTOCOL.md), for lab scripts.

Replies are paired by the protocol, never by count: every line sent gets exactly one reply line;
lines starting with ``@`` are the status stream (``XS``) and are kept apart in ``Robot.status``
(and handed to ``on_status``), never taken as a reply. Replies may end with CR, LF or CR LF
(``XL``); checksums (``XC1``) are added and checked when switched on through this client.
"""
from __future__ import annotations

import collections
import dataclasses
import time
from typing import Callable, Deque, List, Optional, Tuple

import serial  # python3-serial

STOP_BYTE = b"\x18"


class RobuterError(Exception):
    """The robot answered ``error``. ``code`` and ``word`` come from a verbose error
    (``error 2 bad-parameter-count``, docs/PROTOCOL.md §7); both are None for a bare ``error``."""

    def __init__(self, line: str, reply: str):
        self.line = line
        self.reply = reply
        fields = reply.split()
        self.code: Optional[int] = None
        self.word: Optional[str] = None
        if len(fields) >= 2 and fields[1].lstrip("-").isdigit():
            self.code = int(fields[1])
        if len(fields) >= 3:
            self.word = fields[2]
        detail = f" {self.code} {self.word}" if self.code is not None else ""
        super().__init__(f"{line!r} answered error{detail}")


class ProtocolError(Exception):
    """A reply that does not have the shape the protocol gives it, or no reply in time."""


def _fields(reply: str, letter: str, least: int) -> List[str]:
    """The fields after the reply's letter; at least ``least`` of them (more are allowed: a later
    firmware may append fields)."""
    f = reply.split()
    if not f or f[0] != letter or len(f) < least + 1:
        raise ProtocolError(f"expected {letter!r} and {least} fields, got {reply!r}")
    return f[1:]


def _ints(fields: List[str], reply: str) -> List[int]:
    try:
        return [int(x) for x in fields]
    except ValueError:
        raise ProtocolError(f"expected integers in {reply!r}") from None


def _int_fields(reply: str, letter: str, count: int) -> List[int]:
    """The first ``count`` fields after the reply's letter, as integers."""
    return _ints(_fields(reply, letter, count)[:count], reply)


@dataclasses.dataclass(frozen=True)
class _Pose:
    """The posture fields that ``BO`` and the status stream both start with: x, y in 0.1 mm, theta
    in 0.01°, and the servo (brake) state."""
    x: int
    y: int
    theta: int
    servo: bool

    @property
    def x_m(self) -> float:
        return self.x / 10000.0

    @property
    def y_m(self) -> float:
        return self.y / 10000.0

    @property
    def theta_deg(self) -> float:
        return self.theta / 100.0


@dataclasses.dataclass(frozen=True)
class Posture(_Pose):
    """``BO`` → ``S <x> <y> <theta> <servo> <clock>``: x, y in 0.1 mm, theta in 0.01°."""
    clock: int

    @classmethod
    def parse(cls, reply: str) -> "Posture":
        v = _int_fields(reply, "S", 5)
        return cls(v[0], v[1], v[2], v[3] != 0, v[4])


@dataclasses.dataclass(frozen=True)
class Ranges:
    """``BU`` → ``U <u1> … <u24> <servo> <clock>``: ranges in mm, sensor 1 first (0: inactive or
    no echo yet). ``mm[i]`` is sensor i + 1."""
    mm: Tuple[int, ...]
    servo: bool
    clock: int

    @classmethod
    def parse(cls, reply: str) -> "Ranges":
        v = _int_fields(reply, "U", 26)
        return cls(tuple(v[:24]), v[24] != 0, v[25])

    def sensor(self, number: int) -> int:
        """The range of sensor ``number`` (1 … 24), mm."""
        return self.mm[number - 1]


@dataclasses.dataclass(frozen=True)
class Emergency:
    """``XE`` → ``E <held> <latched> <cause> <enabled> <clock> …``. Fields after the clock are
    kept in ``extra`` (a later firmware may add some)."""
    held: bool
    latched: bool
    cause: str
    mask: int
    clock: int
    extra: Tuple[str, ...] = ()

    @classmethod
    def parse(cls, reply: str) -> "Emergency":
        f = _fields(reply, "E", 5)
        held, latched = _ints(f[:2], reply)
        mask, clock = _ints(f[3:5], reply)
        return cls(held != 0, latched != 0, f[2], mask, clock, tuple(f[5:]))

    @property
    def granted(self) -> Optional[int]:
        """Share of the requested speeds granted now, % (``XE``'s sixth field; None if absent)."""
        return int(self.extra[0]) if self.extra and self.extra[0].isdigit() else None

    @property
    def rule(self) -> Optional[str]:
        """The obstacle rule: ``envelope`` (the default) or ``seed`` (None if absent)."""
        return self.extra[1] if len(self.extra) > 1 else None

    @property
    def protective(self) -> bool:
        """A protective stop is in force: stopped short of an obstacle, nothing latched, no ``XR``."""
        return len(self.extra) > 2 and self.extra[2] == "1"


@dataclasses.dataclass(frozen=True)
class Status(_Pose):
    """A status stream line (``XS``): ``@ <x> <y> <theta> <servo> <left> <right> <emergency>
    <clock>``; ``emergency`` is 0 clear, +1 motion held, +2 latched, +4 protective stop."""
    left: int
    right: int
    emergency: int
    clock: int
    line: str

    @classmethod
    def parse(cls, line: str) -> "Status":
        v = _int_fields(line, "@", 8)
        return cls(v[0], v[1], v[2], v[3] != 0, v[4], v[5], v[6], v[7], line)


def crc16(data: bytes) -> int:
    """CRC-16/CCITT-FALSE, the line checksum of ``XC1`` (docs/PROTOCOL.md §9)."""
    crc = 0xFFFF
    for b in data:
        crc ^= b << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) if crc & 0x8000 else (crc << 1)
            crc &= 0xFFFF
    return crc




class Robot:
    """A connection to robuterd on a pty or serial device.

    ``timeout`` bounds the wait for each reply (seconds); it is a liveness bound, not a
    performance figure. ``verbose`` switches on verbose errors (``XB1``) so that a
    ``RobuterError`` carries the code and word. ``on_status`` is called with every stream line
    (a ``Status``); the lines are also kept in ``status`` (the latest ``status_keep``)."""

    def __init__(self, port: str, timeout: float = 5.0, baud: int = 9600, verbose: bool = True,
                 on_status: Optional[Callable[[Status], None]] = None, status_keep: int = 1000):
        self.port = port
        self.timeout = timeout
        self.on_status = on_status
        self.status: Deque[Status] = collections.deque(maxlen=status_keep)
        self._buf = b""
        self._checksums = False
        self._lost = False  # a reply did not come in time: pairing unknown from then on
        self._serial = serial.Serial(port, baud, timeout=0.05)
        try:
            # Whatever an earlier client left unread is not ours (robuterd also starts a fresh
            # session for a new client, docs/PROTOCOL.md "Sessions").
            self._serial.reset_input_buffer()
            if verbose:
                self.command("XB1")
        except BaseException:
            self._serial.close()
            raise

    # --- the link --------------------------------------------------------------------------

    def close(self) -> None:
        self._serial.close()

    def __enter__(self) -> "Robot":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _read_line(self, deadline: float) -> Optional[str]:
        """The next non-empty line (CR, LF or CR LF ended), or None at the deadline."""
        while True:
            for i, b in enumerate(self._buf):
                if b in (13, 10):
                    line, self._buf = self._buf[:i], self._buf[i + 1:]
                    if line:
                        return line.decode("ascii", errors="replace")
                    break
            else:
                waiting = self._serial.in_waiting
                if waiting:
                    self._buf += self._serial.read(waiting)
                    continue
                if time.monotonic() >= deadline:
                    return None
                self._buf += self._serial.read(1)  # waits at most the port's 0.05 s
                continue

    def _unwrap(self, line: str) -> str:
        if not self._checksums:
            return line
        if len(line) < 5 or line[-5] != "*":
            raise ProtocolError(f"reply without checksum: {line!r}")
        body, crc = line[:-5], line[-4:]
        if int(crc, 16) != crc16(body.encode("ascii")):
            raise ProtocolError(f"reply with a wrong checksum: {line!r}")
        return body

    def _take_status(self, line: str) -> None:
        status = Status.parse(line)
        self.status.append(status)
        if self.on_status is not None:
            self.on_status(status)

    def poll_status(self, timeout: float = 0.0) -> List[Status]:
        """Reads what has arrived (waiting up to ``timeout`` for a first line) and returns the
        stream lines read. Only for when no reply is awaited: a reply here is a ProtocolError."""
        got: List[Status] = []
        deadline = time.monotonic() + timeout
        while True:
            line = self._read_line(deadline if not got else time.monotonic())
            if line is None:
                return got
            line = self._unwrap(line)
            if not line.startswith("@"):
                raise ProtocolError(f"a reply nobody asked for: {line!r}")
            self._take_status(line)
            got.append(self.status[-1])

    def send(self, line: str) -> str:
        """Sends one line and returns its reply, as written (without terminator and checksum);
        ``error`` replies are returned, not raised."""
        if any(c in line for c in "\r\n\x18"):
            raise ValueError(f"one line without terminator or stop byte, got {line!r}")
        if self._lost:
            raise ProtocolError("a reply did not come in time: which reply answers which line is "
                                "no longer known; open the Robot again")
        text = line
        if self._checksums:
            text = f"{line}*{crc16(line.encode('ascii')):04X}"
        self._serial.write(text.encode("ascii") + b"\r")
        deadline = time.monotonic() + self.timeout
        while True:
            got = self._read_line(deadline)
            if got is None:
                self._lost = True
                raise ProtocolError(f"no reply to {line!r} within {self.timeout} s")
            got = self._unwrap(got)
            if got.startswith("@"):
                self._take_status(got)
                continue
            # Session options apply from the reply after their ack (docs/PROTOCOL.md §8).
            if got == "ack" and line in ("XC1", "XC0"):
                self._checksums = line == "XC1"
            return got

    def command(self, line: str) -> str:
        """Sends one line; raises RobuterError when it is answered ``error``."""
        reply = self.send(line)
        if reply == "error" or reply.startswith("error "):
            raise RobuterError(line, reply)
        return reply

    def _ack(self, line: str) -> None:
        reply = self.command(line)
        if reply != "ack":
            raise ProtocolError(f"{line!r} answered {reply!r}, expected ack")

    # --- typed calls -------------------------------------------------------------------------

    def posture(self) -> Posture:
        """``BO``: the odometry posture, servo state and clock."""
        return Posture.parse(self.command("BO"))

    def ranges(self) -> Ranges:
        """``BU``: the 24 ring ranges, mm."""
        return Ranges.parse(self.command("BU"))

    def clock(self) -> int:
        """``BC``: the internal clock, ticks of 10 ms."""
        reply = self.command("BC")
        return _int_fields(reply, "C", 1)[0]

    def move(self, left: int, right: int) -> None:
        """``AM``: wheel speeds in cm/s (refused with RobuterError while an emergency holds)."""
        self._ack(f"AM {int(left)} {int(right)}")

    def servo(self, on: bool) -> None:
        """``ASN`` / ``ASF``: servo (brake) on / off."""
        self._ack("ASN" if on else "ASF")

    def set_posture(self, x: int, y: int, theta: int) -> None:
        """``AC``: set the odometry posture (0.1 mm, 0.01°)."""
        self._ack(f"AC {int(x)} {int(y)} {int(theta)}")

    def stop(self) -> None:
        """``AM 0 0``: stop the wheels (no latch; the robot may be driven again at once)."""
        self.move(0, 0)

    def stop_byte(self) -> None:
        """The stop byte 0x18: an immediate stop that latches an emergency (cause
        ``stop-byte``) until ``reenable()``. It has no reply."""
        self._serial.write(STOP_BYTE)
        self._serial.flush()

    def emergency(self) -> Emergency:
        """``XE``: the emergency state."""
        return Emergency.parse(self.command("XE"))

    def reenable(self, wait: float = 0.0) -> None:
        """``XR``: clear a latched emergency. Refused (RobuterError, code 7) while its cause is
        still there — for a stop byte or an obstacle, until the robot has come to rest; with
        ``wait`` > 0 the request is repeated for up to ``wait`` seconds while it is refused."""
        deadline = time.monotonic() + wait
        while True:
            try:
                self._ack("XR")
                return
            except RobuterError as e:
                if time.monotonic() >= deadline or e.code not in (7, None):
                    raise
            time.sleep(0.05)

    def version(self) -> str:
        """``XV``: the firmware's version and capabilities line."""
        return self.command("XV")

    def stream(self, period_ticks: int) -> None:
        """``XS``: a status line every ``period_ticks`` × 10 ms (0: off)."""
        self._ack(f"XS{int(period_ticks)}")
