"""Parses hid-recorder capture lines, chunk by chunk, into compact columns; decodes no reports.

Well-formed ``E:`` lines (``E: <seconds> <length> <hex bytes>`` with single spaces) take a fast path that
converts a whole chunk of them at once; every other line goes through the checks `physink_tui.input.captures.capture`
documents. Reports are kept as one byte string and offsets, so memory grows by the reports' bytes, not by a
Python object per line.
"""

from __future__ import annotations

import re
from array import array
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

from physink_tui.errors import CaptureFormatError
from physink_tui.input.captures.capture_types import (
    BAD_TEXT_MAX,
    GLITCH_SECONDS,
    MAX_SECONDS,
    BadLine,
    CaptureColumns,
    CaptureDevice,
)

if TYPE_CHECKING:
    import numpy as np

_TIME = re.compile(r"\d+(?:\.\d+)?\Z", re.ASCII)
_HEX_TOKEN = re.compile(r"[0-9a-fA-F]{2}\Z")
_HEX_NUMBER = re.compile(r"[0-9a-fA-F]+\Z")
_FAST_EVENTS = re.compile(r"^E: (\d+(?:\.\d+)?) (\d+)((?: [0-9a-fA-F]{2})*)[ \t\r]*$", re.ASCII | re.MULTILINE)
"""A run of well-formed ``E:`` lines, one match per line (the hex group keeps each byte's leading space)."""
_KINDS = "#, D:, R:, N:, P:, I: or E:"
CHUNK_BYTES = 1 << 20
"""Bytes of whole lines read and parsed at a time from a file."""


class Readable(Protocol):
    """What the parser reads a capture from: an open binary file, or anything with its ``read``."""

    def read(self, size: int = -1, /) -> bytes: ...


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


def iter_line_chunks(f: Readable, size: int = CHUNK_BYTES) -> Iterator[list[str]]:
    """Whole lines of a binary file, about ``size`` bytes at a time, decoded as UTF-8 (bad bytes U+FFFD)."""
    first, rest = True, b""
    while True:
        block = f.read(size)
        if not block:
            break
        cut = block.rfind(b"\n") + 1
        if not cut:
            rest += block
            continue
        text = (rest + block[:cut]).decode("utf-8", errors="replace")
        rest = block[cut:]
        if first:
            text, first = text.removeprefix("\ufeff"), False
        yield text.split("\n")[:-1]
    if rest:
        yield rest.decode("utf-8", errors="replace").removeprefix("\ufeff" if first else "").split("\n")


class CaptureParser:
    """One pass over the lines, fed in chunks (`feed`), then `finish`; the only mutable state of a parse."""

    def __init__(self, path: str | None) -> None:
        self.path = path
        self.devices: dict[int, _DeviceBuilder] = {}
        self.current: _DeviceBuilder | None = None
        self.pending: list[str] = []  # comments not yet known to belong to a device header
        self.bad: list[BadLine] = []
        self.lineno = 0
        self.t, self.line, self.device, self.lengths = array("d"), array("q"), array("q"), array("q")
        self.blob = bytearray()

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

    def feed(self, lines: list[str]) -> None:
        """Parse the next lines of the file (without their ``\\n``): runs of ``E:`` lines at once, others one by one."""
        base = self.lineno
        others = [k for k, raw in enumerate(lines) if raw[:3] != "E: "]
        start = 0
        for k in [*others, len(lines)]:
            if k > start:
                self.events(lines[start:k], base + start + 1)
            if k < len(lines):
                line = lines[k].strip()
                if line and line[0] == "#":
                    self.pending.append(line[2:] if line.startswith("# ") else line[1:])
                elif line:
                    self.slow_line(base + k + 1, line)
            start = k + 1
        self.lineno = base + len(lines)

    def events(self, lines: list[str], first: int) -> None:
        """A run of lines starting ``"E: "``, the first being line ``first``: all at once when each is well formed."""
        import numpy as np  # here, not at the top: `physink decode`'s plain path reads header lines without numpy

        from physink_tui.input.captures.events import strict_events

        dev = self.current
        if dev is None or not dev.descriptor:  # no descriptor yet: line by line (each says what is missing)
            for k, raw in enumerate(lines):
                self.slow_line(first + k, raw.strip())
            return
        strict = strict_events(lines, MAX_SECONDS)
        if strict is not None:  # the usual case: checked and read a column at a time
            self.pending.clear()
            self.t.frombytes(strict[0].tobytes())
            self.line.frombytes(np.arange(first, first + len(lines), dtype=np.int64).tobytes())
            self.device.frombytes(np.full(len(lines), dev.index, dtype=np.int64).tobytes())
            self.lengths.frombytes(strict[1].tobytes())
            self.blob += strict[2]
            return
        rows = _FAST_EVENTS.findall("\n".join(lines))
        if len(rows) != len(lines):  # something to report: line by line
            for k, raw in enumerate(lines):
                self.slow_line(first + k, raw.strip())
            return
        self.pending.clear()
        stamps, declared, hexes = zip(*rows, strict=True)
        t = np.fromiter(map(float, stamps), np.float64, len(rows))
        want = np.fromiter(map(int, declared), np.int64, len(rows))
        found = np.fromiter(map(len, hexes), np.int64, len(rows)) // 3
        ok = (want == found) & (t <= MAX_SECONDS)
        linenos = np.arange(first, first + len(rows), dtype=np.int64)
        if not ok.all():
            for k in np.flatnonzero(~ok).tolist():  # rare: report them as the line-by-line path would
                self.read_event(first + k, lines[k].strip())
            hexes = tuple(hexes[k] for k in np.flatnonzero(ok).tolist())
            t, found, linenos = t[ok], found[ok], linenos[ok]
        self.t.frombytes(t.tobytes())
        self.line.frombytes(linenos.tobytes())
        self.device.frombytes(np.full(len(t), dev.index, dtype=np.int64).tobytes())
        self.lengths.frombytes(found.tobytes())
        self.blob += bytes.fromhex("".join(hexes))

    def slow_line(self, lineno: int, line: str) -> None:
        kind = line[:2]
        if kind == "E:":
            self.read_event(lineno, line)
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

    def read_event(self, lineno: int, line: str) -> None:
        dev = self.current
        if dev is None or not dev.descriptor:
            dev = self.device_at(lineno)
            raise self.error(f"event before the report descriptor ('R:' line) of device {dev.index}", lineno)
        self.pending.clear()
        parts = line[2:].split(None, 2)
        if len(parts) < 2:
            self.bad_line(lineno, line, "expected 'E: <seconds> <length> <bytes>'")
            return
        stamp, declared = parts[0], parts[1]
        if _TIME.match(stamp) is None:
            self.bad_line(lineno, line, f"timestamp {stamp!r} is not a number")
            return
        if not (declared.isascii() and declared.isdigit()):
            self.bad_line(lineno, line, f"length {declared!r} is not a decimal number")
            return
        hex_part = parts[2] if len(parts) == 3 else ""
        try:
            data = bytes.fromhex(hex_part)
        except ValueError:
            self.bad_line(lineno, line, _hex_problem(hex_part))
            return
        if len(data) != int(declared):
            self.bad_line(lineno, line, f"declared {int(declared)} bytes, found {len(data)}")
            return
        t = float(stamp)
        if not t <= MAX_SECONDS:  # 310 digits make inf; no capture runs for years
            self.bad_line(lineno, line, f"timestamp {stamp[:20]!r}{'...' if len(stamp) > 20 else ''} is "
                                        f"not a time a capture could hold (over {MAX_SECONDS:g} s)")
            return
        self.t.append(t)
        self.line.append(lineno)
        self.device.append(dev.index)
        self.lengths.append(len(data))
        self.blob += data

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

    def drop_glitches(self, t: np.ndarray, device: np.ndarray, line: np.ndarray, lengths: np.ndarray) -> np.ndarray:
        """The rows to keep: single reports whose time jumps ahead by more than `GLITCH_SECONDS` and comes straight
        back are dropped as bad lines (one glitched stamp would otherwise hold every later report's time; time never
        goes back in the gesture engine). Only the rare rows that jump ahead are looked at one by one."""
        import numpy as np

        keep = np.ones(len(t), dtype=bool)
        prev = np.full(len(t), -1, dtype=np.int64)
        for index in self.devices:  # (np.unique here would import numpy.ma: 12 ms of start-up)
            rows = np.flatnonzero(device == index)
            prev[rows[1:]] = rows[:-1]
        has_prev = prev >= 0
        ahead = np.flatnonzero(has_prev & (t - t[np.where(has_prev, prev, 0)] > GLITCH_SECONDS)).tolist()
        nxt: dict[int, int] = {}
        for k in np.flatnonzero(has_prev).tolist() if ahead else ():
            nxt[int(prev[k])] = k
        todo = sorted(ahead)
        seen: set[int] = set()
        while todo:
            k = todo.pop(0)
            if k in seen:
                continue
            seen.add(k)
            before = int(prev[k])
            while before >= 0 and not keep[before]:
                before = int(prev[before])
            if before < 0 or not t[k] - t[before] > GLITCH_SECONDS:
                continue
            window = np.flatnonzero(device[k + 1:k + 50] == device[k])
            after = k + 1 + int(window[0]) if len(window) else None
            if after is not None and t[k] - t[after] > GLITCH_SECONDS:
                keep[k] = False
                self.bad_line(int(line[k]), f"E: {t[k]:.6f} ({int(lengths[k])} bytes)",
                              f"timestamp jumps {t[k] - t[before]:.6g} s ahead of the report before and back")
                if k in nxt:
                    todo = sorted({*todo, nxt[k]})
        return keep

    def finish(self) -> CaptureColumns:
        """The parsed capture.

        Raises:
            CaptureFormatError: no device, or a device without its ``R:`` line.
        """
        import numpy as np

        if not self.devices:
            raise self.error("no report descriptor ('R:' line) in the capture", None)
        for dev in self.devices.values():
            if not dev.descriptor:
                raise self.error(
                    f"device {dev.index} has no report descriptor ('R:' line); it starts here", dev.first_line
                )
        t, line, device, lengths = (np.frombuffer(a, dtype=np.float64 if a.typecode == "d" else np.int64)
                                    for a in (self.t, self.line, self.device, self.lengths))  # views, no copies
        offsets = np.zeros(len(t) + 1, dtype=np.int64)
        np.cumsum(lengths, out=offsets[1:])
        blob = bytes(self.blob)
        del self.blob[:]
        keep = self.drop_glitches(t, device, line, lengths)
        if not keep.all():
            kept = np.flatnonzero(keep)
            starts, ends = offsets[kept], offsets[kept + 1]
            blob = b"".join(blob[a:b] for a, b in zip(starts.tolist(), ends.tolist(), strict=True))
            t, line, device = t[kept], line[kept], device[kept]
            offsets = np.zeros(len(kept) + 1, dtype=np.int64)
            np.cumsum(ends - starts, out=offsets[1:])
        self.bad.sort(key=lambda b: b.line)
        return CaptureColumns(tuple(d.build() for d in self.devices.values()), tuple(self.bad), self.path,
                              t, line, device, offsets, blob)


def parse_capture_file(f: Readable, path: str | None, chunk_bytes: int = CHUNK_BYTES) -> CaptureColumns:
    """Parse an open binary capture file, about ``chunk_bytes`` of lines at a time."""
    parser = CaptureParser(path)
    for lines in iter_line_chunks(f, chunk_bytes):
        parser.feed(lines)
    return parser.finish()


def parse_capture_text(text: str, path: str | None) -> CaptureColumns:
    """Parse a whole capture text."""
    parser = CaptureParser(path)
    parser.feed(text.removeprefix("\ufeff").split("\n"))
    return parser.finish()


def _hex_problem(hex_part: str) -> str:
    """Names the first token that is not a 2-digit hex byte (only called once bytes.fromhex failed)."""
    for token in hex_part.split():
        if _HEX_TOKEN.match(token) is None:
            return f"bad hex byte {token!r}"
    return f"bad hex bytes {hex_part[:20]!r}"
