"""The values a parsed capture is made of (events, devices, skipped lines) and the parser's limits; no parsing."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np

BAD_TEXT_MAX = 80
"""`BadLine.text` keeps at most this many characters of the offending line."""

MAX_SECONDS = 1e7
"""No capture runs longer than this (about 4 months): a later stamp is a broken line."""
GLITCH_SECONDS = 10.0
"""A report stamped this far after both its neighbours is a glitch (captures pause for a second between
segments, never jump ahead and back)."""


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
class CaptureColumns:
    """A parsed capture with its reports as columns (what `Capture` holds as objects).

    Attributes:
        devices: as `Capture.devices`.
        bad_lines: as `Capture.bad_lines`.
        path: the file, or None.
        t: float64 seconds of each report, file order. line: int64 source lines. device: int64 ``D:`` indexes.
        offsets: int64, ``len(t) + 1`` of them: report ``k`` is ``blob[offsets[k]:offsets[k + 1]]``.
        blob: every report's bytes, concatenated.
    """

    devices: tuple[CaptureDevice, ...]
    bad_lines: tuple[BadLine, ...]
    path: str | None
    t: np.ndarray
    line: np.ndarray
    device: np.ndarray
    offsets: np.ndarray
    blob: bytes

    def __len__(self) -> int:
        return len(self.t)

    def rows_of(self, device_index: int) -> np.ndarray | slice:
        """Positions of one device's reports, in file order (a slice when the capture has one device: no copies)."""
        if len(self.devices) == 1:
            return slice(0, len(self.t)) if self.devices[0].index == device_index else slice(0, 0)
        import numpy as np  # here: the plain decode path imports these types without numpy

        return np.flatnonzero(self.device == device_index)

    def of_device(self, index: int) -> tuple[np.ndarray, np.ndarray, Callable[[int, int], list[bytes]]]:
        """One device's report times, lines, and ``take(a, b)`` giving its reports ``a:b``."""
        rows = self.rows_of(index)
        if isinstance(rows, slice):
            return self.t[rows], self.line[rows], lambda a, b: self.reports(slice(a, b))
        return self.t[rows], self.line[rows], lambda a, b: self.reports(rows[a:b])

    def reports(self, rows: np.ndarray | slice) -> list[bytes]:
        """The reports at ``rows`` (positions or a slice)."""
        blob = self.blob
        if isinstance(rows, slice):
            starts, ends = self.offsets[:-1][rows], self.offsets[1:][rows]
        else:
            starts, ends = self.offsets[rows], self.offsets[rows + 1]
        return [blob[a:b] for a, b in zip(starts.tolist(), ends.tolist(), strict=True)]
