"""Pen sources that need no device: a programmatic pen (TUI mouse, tests) and capture replay; no decoding.

`ProgrammaticPenSource` is pushed to from any thread (the TUI's mouse handler, a test, a script) and
puts `SampleReady` items in canvas coordinates on the consumer's queue. `CaptureReplaySource` plays a
hid-recorder capture's reports through the same queue as a live reader would, from a thread, at full
speed or paced in real time.
"""

from __future__ import annotations

import queue
import threading
import time
from collections.abc import Callable

from physink_tui.input.captures.capture import Capture
from physink_tui.input.pen.sample import PenSample
from physink_tui.input.sources import RawReport, SampleReady, SourceEnded, SourceItem


class ProgrammaticPenSource:
    """A pen driven by code. ``clock`` stamps pushes that give no time (default: the monotonic clock).

    >>> q = queue.Queue()
    >>> pen = ProgrammaticPenSource("mouse", clock=lambda: 1.5)
    >>> pen.start(q); pen.push(0.25, 0.5, p=0.7, tip=True)
    >>> q.get_nowait().sample.t
    1.5
    """

    def __init__(self, device_id: str = "mouse", clock: Callable[[], float] = time.monotonic) -> None:
        self.device_id = device_id
        self._clock = clock
        self._out: queue.Queue[SourceItem] | None = None
        self._lock = threading.Lock()

    def start(self, out: queue.Queue[SourceItem]) -> None:
        self._out = out

    def push(self, x: float, y: float, *, p: float = 0.0, tip: bool = False, in_range: bool = True,
             eraser: bool = False, b1: bool = False, b2: bool = False, t: float | None = None) -> None:
        """One pen position in canvas coordinates (0..1, y down)."""
        stamp = self._clock() if t is None else t
        self.push_sample(PenSample(stamp, x, y, p if tip else 0.0, tip, in_range or tip, eraser, b1, b2,
                                   None, None, 0))

    def push_sample(self, sample: PenSample) -> None:
        with self._lock:
            if self._out is None:
                raise RuntimeError(f"pen source {self.device_id!r} is not started")
            self._out.put(SampleReady(sample, self.device_id))

    def stop(self) -> None:
        with self._lock:
            if self._out is not None:
                self._out.put(SourceEnded(self._clock(), self.device_id, None))
                self._out = None


class CaptureReplaySource:
    """Plays one device of a capture as RawReports, with the capture's times (plus ``t0``); ``realtime`` paces
    them by those times, ``speed`` times faster, waiting out at most ``max_gap`` capture seconds between two
    reports (None: every gap; the reports keep their times either way)."""

    def __init__(self, capture: Capture, device_id: str = "tablet0", device_index: int = 0,
                 realtime: bool = False, t0: float = 0.0, speed: float = 1.0, max_gap: float | None = None) -> None:
        if not speed > 0:
            raise ValueError(f"replay speed must be > 0, got {speed!r}")
        self.device_id = device_id
        self._events = capture.events_for(device_index)
        self._realtime = realtime
        self._speed = speed
        self._max_gap = max_gap
        self._t0 = t0
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self, out: queue.Queue[SourceItem]) -> None:
        self._thread = threading.Thread(target=self._run, args=(out,), name=f"replay-{self.device_id}",
                                        daemon=True)
        self._thread.start()

    def _run(self, out: queue.Queue[SourceItem]) -> None:
        start = time.monotonic()
        first = self._events[0].t if self._events else 0.0
        last_t = self._t0
        previous, skipped = first, 0.0  # capture seconds of the gaps not waited out
        for event in self._events:
            if self._stop.is_set():
                break
            if self._realtime:
                if self._max_gap is not None and event.t - previous > self._max_gap:
                    skipped += event.t - previous - self._max_gap
                previous = event.t
                delay = (event.t - first - skipped) / self._speed - (time.monotonic() - start)
                if delay > 0 and self._stop.wait(delay):
                    break
            last_t = self._t0 + event.t
            out.put(RawReport(last_t, event.data, self.device_id))
        out.put(SourceEnded(last_t, self.device_id, None))

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
