"""Turns one pen source's items into journal entries and submits them as they arrive; reads no device, no thread.

A `SourcePump` hands its source a queue whose ``put`` converts and submits on the source's own thread, so an
item is stamped the moment the source has it:

- `RawReport` -> `HidEntry` (the report's own time is dropped: the runner stamps arrivals; with ``keep_time``
  the entry carries it, for a driver whose clock is the source's own, the kiosk replaying a capture);
- `SampleReady` -> `PenEntry`, in canvas coordinates: given a `TabletMapping` (a serial tablet, whose samples
  are in tablet space) the pump maps them with it, without one the samples are taken as canvas ones already
  (mouse, scripts); positions and pressure are clamped into [0, 1];
- `SourceEnded` is not submitted (a journal has no such line). A pen still in range over a sample source is
  lifted with one out-of-range `PenEntry` at its last position, so its stroke ends. A HID device that comes back
  after an error (`physink_tui.input.reconnecting`) is announced again with a `DeviceEntry` before its first
  report, which the session takes as a reconnection. ``on_ended`` hears of every end (a status line; the kiosk
  ends its session when a replayed capture ends).
"""

from __future__ import annotations

import queue
import threading
from collections.abc import Callable

from physink_tui.formats.journal.entries import DeviceEntry, HidEntry, JournalDevice, JournalEntry, PenEntry
from physink_tui.input.pen.mapping import TabletMapping
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.sources import PenSource, RawReport, SampleReady, SourceEnded, SourceItem

Submit = Callable[[JournalEntry], object]
"""Where entries go: `physink_tui.session.runner.SessionRunner.submit` (stamps them with its clock)."""


class SourcePump:
    """Connects one `PenSource` to a runner.

    Args:
        source: the source, not started.
        submit: called with each entry, on the source's thread.
        mapping: the session's tablet-to-canvas mapping when the source's samples are in tablet space (serial
            tablets); None when they are canvas positions already. HID reports are mapped by the session.
        device: the HID device as the journal header has it (its id is the source's), announced again with a
            `DeviceEntry` when the device comes back after an error; None for sample sources (or to announce
            nothing, in which case a returning device's reports simply carry on).
        on_ended: called on the source's thread with every `SourceEnded`.
        keep_time: a `HidEntry` carries its report's own time (else 0.0; the runner stamps it either way).
    """

    def __init__(self, source: PenSource, submit: Submit, *, mapping: TabletMapping | None = None,
                 device: JournalDevice | None = None, on_ended: Callable[[SourceEnded], None] | None = None,
                 keep_time: bool = False) -> None:
        if device is not None and device.id != source.device_id:
            raise ValueError(f"device {device.id!r} is announced for source {source.device_id!r}: the ids must match")
        self.source = source
        self._submit = submit
        self._mapping = mapping
        self._device = device
        self._on_ended = on_ended
        self._keep_time = keep_time
        self._lock = threading.Lock()  # keeps a device announcement and the report after it in order
        self._lost = False  # the device ended with an error: announce it again before its next report
        self._last_pen: PenEntry | None = None

    def start(self) -> None:
        """Start the source, its items going to ``submit``."""
        self.source.start(_SubmittingQueue(self.take))

    def stop(self) -> None:
        """Stop the source (idempotent); its `SourceEnded` still lifts a pen in range."""
        self.source.stop()

    def take(self, item: SourceItem) -> None:
        """Convert one item and submit what it becomes (the queue given to the source calls this)."""
        with self._lock:
            if isinstance(item, RawReport):
                if self._lost and self._device is not None:
                    self._submit(DeviceEntry(0.0, (self._device,)))
                self._lost = False
                self._submit(HidEntry(item.t if self._keep_time else 0.0, item.device, item.data))
            elif isinstance(item, SampleReady):
                self._lost = False
                self._last_pen = self._pen_entry(item.sample)
                self._submit(self._last_pen)
            elif isinstance(item, SourceEnded):
                self._lost = self._lost or item.error is not None
                pen = self._last_pen
                if pen is not None and (pen.range or pen.tip):
                    self._last_pen = PenEntry(0.0, pen.x, pen.y, 0.0, False, False, pen.eraser, False, False)
                    self._submit(self._last_pen)
                if self._on_ended is not None:
                    self._on_ended(item)
            else:
                raise TypeError(f"not a source item: {item!r}")

    def _pen_entry(self, sample: PenSample) -> PenEntry:
        x, y = sample.x, sample.y
        if self._mapping is not None:
            x, y = self._mapping.to_canvas(x, y)
        return PenEntry(0.0, _unit(x), _unit(y), _unit(sample.p), bool(sample.tip), bool(sample.range),
                        bool(sample.eraser), bool(sample.b1), bool(sample.b2))


def _unit(value: float) -> float:
    """``value`` brought into [0, 1], as a journal ``pen`` line requires (a mouse dragged past the canvas edge)."""
    return min(1.0, max(0.0, float(value)))


class _SubmittingQueue(queue.Queue[SourceItem]):
    """The queue a source puts its items on: ``put`` hands each to the pump at once; nothing is ever queued."""

    def __init__(self, take: Callable[[SourceItem], None]) -> None:
        super().__init__()
        self._take = take

    def put(self, item: SourceItem, block: bool = True, timeout: float | None = None) -> None:
        self._take(item)
