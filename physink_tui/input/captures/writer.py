"""Writes captures in the hid-recorder text format, exactly as hid-tools' ``hid-recorder`` does; reads none."""

from __future__ import annotations

import os

from physink_tui.formats.atomic_write import write_text_atomic
from physink_tui.input.captures.capture import Capture, CaptureDevice, CaptureEvent  # noqa: F401 (doctest names)


def _one_line(value: str, what: str) -> str:
    if "\n" in value or "\r" in value:
        raise ValueError(f"{what} {value!r} spans several lines; the format has one item per line")
    return value


def _format_time(t: float) -> str:
    if not t >= 0:  # also catches NaN
        raise ValueError(f"event time {t!r} is not a non-negative number of seconds")
    sec, usec = divmod(round(t * 1_000_000), 1_000_000)
    return f"{sec:06d}.{usec:06d}"


def format_capture(capture: Capture) -> str:
    """The capture as hid-recorder text, exactly as the Python ``hid-recorder`` writes it.

    ``D:`` lines are written only when there are several devices (or one whose index is not 0), before
    each device's header and whenever the events switch device. Times are rounded to microseconds.
    `Capture.bad_lines` and comments between events are not written.

    Raises:
        ValueError: a negative time, a multi-line name or comment, or an event for a device the capture
            does not have (values built in code; a parsed capture always formats).

    >>> pen = CaptureDevice(0, "Pen", None, 3, 0x56A, 0x350, b"\\xa1\\xc0")
    >>> c = Capture((pen,), (CaptureEvent(1.5, b"\\x02"),))
    >>> print(format_capture(c), end="")
    R: 2 a1 c0
    N: Pen
    I: 3 056a 0350
    E: 000001.500000 1 02
    """
    out: list[str] = []
    indices = {d.index for d in capture.devices}
    with_ids = len(capture.devices) > 1 or any(d.index != 0 for d in capture.devices)
    for dev in capture.devices:
        if with_ids:
            out.append(f"D: {dev.index}")
        out.extend(f"# {_one_line(c, 'comment')}" if c else "#" for c in dev.comments)
        out.append(_bytes_line("R:", str(len(dev.descriptor)), dev.descriptor))
        if dev.name is not None:
            out.append(f"N: {_one_line(dev.name, 'name')}")
        if dev.phys is not None:
            out.append(f"P: {_one_line(dev.phys, 'phys')}")
        if dev.bus is not None and dev.vid is not None and dev.pid is not None:
            out.append(f"I: {dev.bus:x} {dev.vid:04x} {dev.pid:04x}")
    current: int | None = None if with_ids else 0  # like hid-recorder: a D: before the first event
    for e in capture.events:
        if e.device != current:
            if e.device not in indices:
                raise ValueError(f"event at t={e.t!r} is for device {e.device}, which the capture lacks")
            out.append(f"D: {e.device}")
            current = e.device
        out.append(event_line(e.t, e.data))
    out.append("")
    return "\n".join(out)


def event_line(t: float, data: bytes) -> str:
    """One ``E:`` line (without newline) as hid-recorder writes it; for writers that stream events.

    >>> event_line(1.5, bytes([2, 0x21]))
    'E: 000001.500000 2 02 21'
    """
    return _bytes_line("E:", f"{_format_time(t)} {len(data)}", data)


def _bytes_line(kind: str, head: str, data: bytes) -> str:
    return f"{kind} {head} {data.hex(' ')}" if data else f"{kind} {head}"


def write_capture(capture: Capture, path: str | os.PathLike[str]) -> None:
    """Writes `format_capture` output atomically: a complete new file or the old one untouched.

    Raises:
        OSError: the file cannot be written; `path` is unchanged.
        ValueError: as `format_capture`.
    """
    write_text_atomic(path, format_capture(capture))
