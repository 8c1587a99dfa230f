"""Reads and writes captures in the hid-recorder text format of hid-tools; decodes no reports.

The format is one item per line, its type given by the first two characters::

    # a comment, allowed anywhere
    D: 1                          device index (only when several hidraw nodes are recorded)
    R: 3 05 0d 09                 report descriptor: decimal length, then that many hex bytes
    N: Wacom Intuos Pro S         device name
    P: usb-0000:00:14.0-1/input0  physical path (optional)
    I: 3 056a 0392                bus, vendor id, product id, all hex
    E: 000001.959698 4 02 00 00 00  one report: seconds.microseconds, decimal length, hex bytes

Both the padded timestamps of the Python ``hid-recorder`` and the unpadded ones of the old C tool are read;
the Python form is written. A broken ``E:``/``I:`` line or an unknown line type is kept as a `BadLine` and
skipped, so one damaged report does not lose a whole recording. What makes the capture undecodable (no
usable report descriptor, a bad ``D:`` index) raises `CaptureFormatError` naming the path and line.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

from physink_tui.errors import CaptureFormatError

BAD_TEXT_MAX = 80
"""`BadLine.text` keeps at most this many characters of the offending line."""

MAX_SECONDS = 1e7
"""No capture runs longer than this (about 4 months): a later stamp is a broken line."""
GLITCH_SECONDS = 10.0
"""A report stamped this far after both its neighbours is a glitch (captures pause for a second between
segments, never jump ahead and back)."""
_TIME = re.compile(r"\d+(?:\.\d+)?\Z", re.ASCII)
_HEX_TOKEN = re.compile(r"[0-9a-fA-F]{2}\Z")
_HEX_NUMBER = re.compile(r"[0-9a-fA-F]+\Z")
_KINDS = "#, D:, R:, N:, P:, I: or E:"


@dataclass(frozen=True, slots=True)
class CaptureEvent:
    """One input report as read from hidraw.

    Attributes:
        t: seconds since the first recorded event (>= 0; not necessarily non-decreasing, the decoder
            counts time going backwards).
        data: the raw report; its first byte is the report id when the descriptor uses report ids.
        line: 1-based source line, 0 when built in code. Not part of equality, so a capture read back
            from its own output compares equal event by event.
        device: index of the device (``D:`` line) the report came from, 0 for a single device.
    """

    t: float
    data: bytes
    line: int = field(default=0, compare=False)
    device: int = 0


@dataclass(frozen=True, slots=True)
class CaptureDevice:
    """One recorded hidraw node: its header lines.

    Attributes:
        index: the ``D:`` index, 0 when the capture has no ``D:`` line.
        name: the ``N:`` name (HID_NAME), or None if absent.
        phys: the ``P:`` physical path, or None if absent.
        bus: the ``I:`` bus type (3 USB, 5 Bluetooth, 0x18 I2C); bus, vid and pid are all set or all None.
        vid: the ``I:`` vendor id, 0..0xffff.
        pid: the ``I:`` product id, 0..0xffff.
        descriptor: the ``R:`` report descriptor bytes, never empty in a parsed capture.
        comments: the ``#`` lines seen before or among this device's header lines, without the leading
            ``"# "``. Comments between events (such as hid-recorder's decoded reports) are not kept.
    """

    index: int
    name: str | None
    phys: str | None
    bus: int | None
    vid: int | None
    pid: int | None
    descriptor: bytes
    comments: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class BadLine:
    """A line that was skipped while reading.

    Attributes:
        line: 1-based line number.
        text: the line, stripped and cut to `BAD_TEXT_MAX` characters.
        reason: what was wrong, e.g. ``"declared 8 bytes, found 7"``.
    """

    line: int
    text: str
    reason: str


@dataclass(frozen=True, slots=True)
class Capture:
    """A whole hid-recorder capture: device headers, reports in file order, and the lines skipped.

    Attributes:
        devices: the devices in order of first appearance; at least one in a parsed capture.
        events: every well-formed ``E:`` line, in file order.
        bad_lines: the lines skipped, in file order.
        path: the file it was read from, or None.
    """

    devices: tuple[CaptureDevice, ...]
    events: tuple[CaptureEvent, ...]
    bad_lines: tuple[BadLine, ...] = ()
    path: str | None = None

    @classmethod
    def from_text(cls, text: str, path: str | None = None) -> Capture:
        """Parses hid-recorder text.

        Args:
            text: the whole file; ``\\n`` or ``\\r\\n`` line ends.
            path: where the text came from, used in errors and kept in `Capture.path`.

        Raises:
            CaptureFormatError: a bad or missing ``R:`` line, an event before its device's ``R:``, or a
                bad ``D:`` index.

        >>> c = Capture.from_text("R: 2 a1 c0\\nE: 0.5 2 01 ff\\n")
        >>> c.devices[0].descriptor, c.events[0].t, c.events[0].data
        (b'\\xa1\\xc0', 0.5, b'\\x01\\xff')
        """
        return _Parser(path).parse(text)

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> Capture:
        """Reads and parses a capture file (UTF-8; undecodable bytes become U+FFFD).

        Raises:
            OSError: the file cannot be read.
            CaptureFormatError: as `from_text`.
        """
        name = os.fspath(path)
        with open(name, "rb") as f:
            raw = f.read()
        return cls.from_text(raw.decode("utf-8", errors="replace"), path=name)

    def events_for(self, device_index: int) -> tuple[CaptureEvent, ...]:
        """The events of one device, in file order."""
        return tuple(e for e in self.events if e.device == device_index)

    def device(self, index: int) -> CaptureDevice:
        """The device with this ``D:`` index.

        Raises:
            KeyError: the capture has no such device.
        """
        for d in self.devices:
            if d.index == index:
                return d
        raise KeyError(index)


@dataclass(slots=True)
class _DeviceBuilder:
    """A device whose header lines are still being read (the only mutable record here)."""

    index: int
    first_line: int  # where the device starts: its D: line, or the first line of an implicit device 0
    r_line: int = 0
    descriptor: bytes = b""
    name: str | None = None
    phys: str | None = None
    bus: int | None = None
    vid: int | None = None
    pid: int | None = None
    comments: list[str] = field(default_factory=list)

    def build(self) -> CaptureDevice:
        ids = (self.bus, self.vid, self.pid)
        return CaptureDevice(self.index, self.name, self.phys, *ids, self.descriptor, tuple(self.comments))


class _Parser:
    """One pass over the lines; the only mutable state of a parse."""

    def __init__(self, path: str | None) -> None:
        self.path = path
        self.devices: dict[int, _DeviceBuilder] = {}
        self.current: _DeviceBuilder | None = None
        self.pending: list[str] = []  # comments not yet known to belong to a device header
        self.events: list[CaptureEvent] = []
        self.bad: list[BadLine] = []

    def error(self, message: str, line: int | None) -> CaptureFormatError:
        return CaptureFormatError(message, path=self.path, line=line)

    def bad_line(self, lineno: int, text: str, reason: str) -> None:
        self.bad.append(BadLine(lineno, text[:BAD_TEXT_MAX], reason))

    def device_at(self, lineno: int) -> _DeviceBuilder:
        """The device the current line belongs to (device 0 when the file has no ``D:``)."""
        if self.current is None:
            self.current = self.devices[0] = _DeviceBuilder(0, lineno)
        return self.current

    def header(self, lineno: int) -> _DeviceBuilder:
        """The current device, now owning the comments seen since the last header or event line."""
        dev = self.device_at(lineno)
        if self.pending:
            dev.comments.extend(self.pending)
            self.pending.clear()
        return dev

    def parse(self, text: str) -> Capture:
        if text.startswith("\ufeff"):
            text = text[1:]
        events_append = self.events.append
        time_match = _TIME.match
        fromhex = bytes.fromhex
        for lineno, raw in enumerate(text.split("\n"), start=1):
            line = raw.strip()
            kind = line[:2]
            if kind == "E:":
                dev = self.current
                if dev is None or not dev.descriptor:
                    dev = self.device_at(lineno)
                    raise self.error(
                        f"event before the report descriptor ('R:' line) of device {dev.index}", lineno
                    )
                self.pending.clear()
                parts = line[2:].split(None, 2)
                if len(parts) < 2:
                    self.bad_line(lineno, line, "expected 'E: <seconds> <length> <bytes>'")
                    continue
                stamp, declared = parts[0], parts[1]
                if time_match(stamp) is None:
                    self.bad_line(lineno, line, f"timestamp {stamp!r} is not a number")
                    continue
                if not (declared.isascii() and declared.isdigit()):
                    self.bad_line(lineno, line, f"length {declared!r} is not a decimal number")
                    continue
                hex_part = parts[2] if len(parts) == 3 else ""
                try:
                    data = fromhex(hex_part)
                except ValueError:
                    self.bad_line(lineno, line, _hex_problem(hex_part))
                    continue
                if len(data) != int(declared):
                    self.bad_line(lineno, line, f"declared {int(declared)} bytes, found {len(data)}")
                    continue
                t = float(stamp)
                if not t <= MAX_SECONDS:  # 310 digits make inf; no capture runs for years
                    self.bad_line(lineno, line, f"timestamp {stamp[:20]!r}{'...' if len(stamp) > 20 else ''} is "
                                                f"not a time a capture could hold (over {MAX_SECONDS:g} s)")
                    continue
                events_append(CaptureEvent(t, data, lineno, dev.index))
            elif not line:
                continue
            elif line[0] == "#":
                self.pending.append(line[2:] if line.startswith("# ") else line[1:])
            elif kind == "R:":
                self.read_descriptor(lineno, line)
            elif kind == "N:":
                self.read_text_field(lineno, line, "name")
            elif kind == "P:":
                self.read_text_field(lineno, line, "phys")
            elif kind == "I:":
                self.read_ids(lineno, line)
            elif kind == "D:":
                self.select_device(lineno, line)
            else:
                self.bad_line(lineno, line, f"unknown line type {kind!r} (expected {_KINDS})")
        return self.finish()

    def read_descriptor(self, lineno: int, line: str) -> None:
        dev = self.header(lineno)
        if dev.descriptor:
            raise self.error(
                f"second 'R:' line for device {dev.index} (the first is at line {dev.r_line})", lineno
            )
        parts = line[2:].split(None, 1)
        if not parts or not (parts[0].isascii() and parts[0].isdigit()):
            found = parts[0] if parts else ""
            raise self.error(f"report descriptor length {found!r} is not a decimal number", lineno)
        declared = int(parts[0])
        hex_part = parts[1] if len(parts) == 2 else ""
        try:
            data = bytes.fromhex(hex_part)
        except ValueError:
            raise self.error(f"report descriptor: {_hex_problem(hex_part)}", lineno) from None
        if len(data) != declared:
            raise self.error(f"report descriptor declared {declared} bytes, found {len(data)}", lineno)
        if not data:
            raise self.error("report descriptor is empty", lineno)
        dev.descriptor = data
        dev.r_line = lineno

    def read_text_field(self, lineno: int, line: str, attr: str) -> None:
        dev = self.header(lineno)
        if getattr(dev, attr) is not None:
            self.bad_line(lineno, line, f"second {line[:2]!r} line for device {dev.index}; the first is kept")
            return
        setattr(dev, attr, line[2:].strip())

    def read_ids(self, lineno: int, line: str) -> None:
        dev = self.header(lineno)
        if dev.bus is not None:
            self.bad_line(lineno, line, f"second 'I:' line for device {dev.index}; the first is kept")
            return
        parts = line[2:].split()
        if len(parts) != 3:
            self.bad_line(lineno, line, f"expected 'I: <bus> <vid> <pid>' in hex, found {len(parts)} fields")
            return
        for part in parts:
            if _HEX_NUMBER.match(part) is None:
                self.bad_line(lineno, line, f"{part!r} is not a hex number")
                return
        bus, vid, pid = (int(p, 16) for p in parts)
        if vid > 0xFFFF or pid > 0xFFFF:
            self.bad_line(lineno, line, "vendor and product ids must fit in 16 bits")
            return
        dev.bus, dev.vid, dev.pid = bus, vid, pid

    def drop_glitches(self) -> None:
        """Drop (as bad lines) single reports whose time jumps ahead by more than `GLITCH_SECONDS` and comes
        straight back: one glitched stamp would otherwise hold every later report's time (time never goes back
        in the gesture engine)."""
        last: dict[int, CaptureEvent] = {}
        glitches: set[int] = set()
        events = self.events
        for k, ev in enumerate(events):
            before = last.get(ev.device)
            ahead = before is not None and ev.t - before.t > GLITCH_SECONDS  # rare: only then look at the next
            after = next((e for e in events[k + 1:k + 50] if e.device == ev.device), None) if ahead else None
            if after is not None and ev.t - after.t > GLITCH_SECONDS:
                glitches.add(k)
                self.bad_line(ev.line, f"E: {ev.t:.6f} ({len(ev.data)} bytes)",
                              f"timestamp jumps {ev.t - before.t:.6g} s ahead of the report before and back")
                continue
            last[ev.device] = ev
        if glitches:
            self.events = [ev for k, ev in enumerate(events) if k not in glitches]
            self.bad.sort(key=lambda b: b.line)

    def select_device(self, lineno: int, line: str) -> None:
        value = line[2:].strip()
        if not (value.isascii() and value.isdigit()):
            raise self.error(f"device index {value!r} is not a decimal number", lineno)
        index = int(value)
        dev = self.devices.get(index)
        if dev is None:
            dev = self.devices[index] = _DeviceBuilder(index, lineno)
            dev.comments.extend(self.pending)
            self.pending.clear()
        self.current = dev

    def finish(self) -> Capture:
        if not self.devices:
            raise self.error("no report descriptor ('R:' line) in the capture", None)
        for dev in self.devices.values():
            if not dev.descriptor:
                raise self.error(
                    f"device {dev.index} has no report descriptor ('R:' line); it starts here", dev.first_line
                )
        self.drop_glitches()
        return Capture(
            devices=tuple(d.build() for d in self.devices.values()),
            events=tuple(self.events),
            bad_lines=tuple(self.bad),
            path=self.path,
        )


def _hex_problem(hex_part: str) -> str:
    """Names the first token that is not a 2-digit hex byte (only called once bytes.fromhex failed)."""
    for token in hex_part.split():
        if _HEX_TOKEN.match(token) is None:
            return f"bad hex byte {token!r}"
    return f"bad hex bytes {hex_part[:20]!r}"
