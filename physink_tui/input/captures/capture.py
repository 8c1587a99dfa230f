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
from dataclasses import dataclass

import numpy as np

from physink_tui.input.captures.capture_types import (
    BAD_TEXT_MAX,
    GLITCH_SECONDS,
    MAX_SECONDS,
    BadLine,
    CaptureColumns,
    CaptureDevice,
    CaptureEvent,
)
from physink_tui.input.captures.parser import parse_capture_file, parse_capture_text

__all__ = ["BAD_TEXT_MAX", "GLITCH_SECONDS", "MAX_SECONDS", "BadLine", "Capture", "CaptureColumns", "CaptureDevice",
           "CaptureEvent"]


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
        return _from_columns(parse_capture_text(text, path))

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> Capture:
        """Reads and parses a capture file (UTF-8; undecodable bytes become U+FFFD).

        Raises:
            OSError: the file cannot be read.
            CaptureFormatError: as `from_text`.
        """
        name = os.fspath(path)
        with open(name, "rb") as f:
            return _from_columns(parse_capture_file(f, name))

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


def _from_columns(cols: CaptureColumns) -> Capture:
    """A `Capture` of events from its columns."""
    data = cols.reports(np.arange(len(cols)))
    events = tuple(map(CaptureEvent, cols.t.tolist(), data, cols.line.tolist(), cols.device.tolist()))
    return Capture(cols.devices, events, cols.bad_lines, cols.path)
