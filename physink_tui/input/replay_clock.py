"""The input time of a replay paced in real time (the TUI's journal feed): a clock that runs with the wall clock but
waits at the next recorded input's time until that input has been handed over; reads no file, decodes nothing.

A runner stamps each input with its clock when the input arrives (`physink_tui.session.runner`). A replay paced by
the wall clock hands its inputs over late on a loaded machine, and stamped on arrival their times would be the
machine's: a stall between a pen-down and the next report would read as the pen held still (a dwell), one between an
X's strokes as the X left half drawn. With `ReplayClock` as the runner's clock and the replay calling `hold_at` with
each input's time before waiting for it, every input is stamped with its recorded time, and nothing that reads the
clock meanwhile (a dwell's timer, an idle timeout) sees time pass that the recording did not have.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Callable


class ReplayClock:
    """Seconds on ``base``, never past the time `hold_at` last named.

    Args:
        base: the clock it runs on (seconds; `time.monotonic` by default, a test's own clock).

    >>> wall = iter([100.0, 103.0, 103.0, 108.0]).__next__  # base readings: at construction, then one per call
    >>> clock = ReplayClock(wall)
    >>> clock.hold_at(2.0)
    >>> clock(), clock()  # 3 s on, held at 2; then running free again once released
    (2.0, 2.0)
    >>> clock.release(); clock()
    8.0
    """

    def __init__(self, base: Callable[[], float] = time.monotonic) -> None:
        self._base = base
        self._start = base()
        self._ceiling = math.inf
        self._lock = threading.Lock()

    def running(self) -> float:
        """The time as the base clock says, held or not."""
        return self._base() - self._start

    def __call__(self) -> float:
        reading = self.running()
        with self._lock:
            return min(reading, self._ceiling)

    def hold_at(self, t: float) -> None:
        """Let the clock run no further than ``t`` (the next input's time) until the next call (or `release`).
        Holds only move forward: a ``t`` before the last one is taken as the last one."""
        with self._lock:
            self._ceiling = t if self._ceiling == math.inf else max(t, self._ceiling)

    def release(self) -> None:
        """Run free again (the replay has handed over its last input)."""
        with self._lock:
            self._ceiling = math.inf

    def wait_until(self, t: float, stop: threading.Event) -> bool:
        """Wait until the base clock has run to ``t`` (or ``stop`` is set: returns True then)."""
        while (left := t - self.running()) > 0:
            if stop.wait(left):
                return True
        return stop.is_set()
