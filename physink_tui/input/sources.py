"""What every input source hands on: timestamped raw reports, pen samples and its own end; no reading.

Readers (hidraw, hidapi, pyusb, serial, capture replay, the TUI's mouse, scripts) run on their own
thread and put these frozen items on a `queue.Queue`; exactly one consumer takes them off in order (a
`session.source_pump.SourcePump`, which stamps them as journal entries for the session's runner, or a
`PenInput`). A reader never raises into its consumer: it ends with a `SourceEnded` whose ``error`` says why
(None for a clean stop or the end of a file).
"""

from __future__ import annotations

import queue
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from physink_tui.errors import DeviceError
from physink_tui.input.pen.sample import PenSample


@dataclass(frozen=True, slots=True)
class RawReport:
    """One HID input report as read.

    Attributes:
        t: seconds on the reader's monotonic clock (``time.monotonic()`` when read live; the
            capture's time when replayed).
        data: the report bytes, report id first when the device uses ids.
        device: the source's id (a journal header's device key, e.g. ``"tablet0"``).
    """

    t: float
    data: bytes
    device: str


@dataclass(frozen=True, slots=True)
class SampleReady:
    """A pen sample from a source that decodes by itself (serial ISDV4, mouse, scripts).

    Attributes:
        sample: x and y in 0..1 of the source's own area (tablet or canvas, as the source says).
        device: the source's id.
    """

    sample: PenSample
    device: str


@dataclass(frozen=True, slots=True)
class SourceEnded:
    """The source stopped: ``error`` is None for a clean stop or end of file, else why it ended.

    Attributes:
        t: seconds on the reader's clock when it ended.
        device: the source's id.
        error: the device error (vanished, permission denied, read failed), or None.
    """

    t: float
    device: str
    error: DeviceError | None = None


SourceItem = RawReport | SampleReady | SourceEnded


@runtime_checkable
class PenSource(Protocol):
    """A started source puts `SourceItem`s on ``out`` from its own thread until stopped or ended."""

    device_id: str

    def start(self, out: queue.Queue[SourceItem]) -> None:
        """Begin reading on a thread of its own; return at once."""

    def stop(self) -> None:
        """Ask the thread to end, wait for it, and release the device (idempotent)."""
