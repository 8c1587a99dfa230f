"""A one-line progress bar with counts and ETA for long commands on a terminal; silent elsewhere, knows no task."""

from __future__ import annotations

import shutil
import sys
import time
from collections.abc import Callable
from typing import Protocol, TextIO

REDRAW_INTERVAL = 0.1
"""Seconds between two redraws of the bar; the first and the last update always draw."""


class Progress(Protocol):
    """Told how far a long task has come: ``done`` of ``total`` units, called from the task's own thread."""

    def __call__(self, done: int, total: int, /) -> None: ...


class ProgressBar:
    """Rewrites one line of ``stream`` in place (``label [####....] 120/300 frames 40% ETA 0:03``).

    Writes nothing at all when ``stream`` is not a terminal (a pipe, a file, a test's captured stderr), so a
    command can always pass one. Use as a context manager, or call `close` to end the line.

    Args:
        label: what is being done, e.g. ``"Exporting demo.mp4"``.
        unit: the plural name of one step, e.g. ``"frames"``.
        stream: where to draw; ``sys.stderr`` when None.
        clock: seconds from an arbitrary origin (``time.monotonic``), replaceable in tests.
    """

    def __init__(self, label: str, unit: str = "steps", stream: TextIO | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.label = label
        self.unit = unit
        self.stream = sys.stderr if stream is None else stream
        self.clock = clock
        self.enabled = _is_terminal(self.stream)
        self._start: float | None = None
        self._last_draw = -1.0
        self._drawn = False

    def __call__(self, done: int, total: int) -> None:
        if not self.enabled:
            return
        now = self.clock()
        if self._start is None:
            self._start = now
        if done < total and self._drawn and now - self._last_draw < REDRAW_INTERVAL:
            return
        self._last_draw = now
        self._drawn = True
        width = shutil.get_terminal_size((80, 24)).columns
        self.stream.write("\r" + format_line(self.label, self.unit, done, total, now - self._start, width) + "\x1b[K")
        self.stream.flush()

    def close(self) -> None:
        """Ends the bar's line so that what follows starts on a fresh one."""
        if self.enabled and self._drawn:
            self.stream.write("\n")
            self.stream.flush()
            self._drawn = False

    def __enter__(self) -> ProgressBar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def format_line(label: str, unit: str, done: int, total: int, elapsed: float, width: int = 80) -> str:
    """The bar's text for ``done`` of ``total`` after ``elapsed`` seconds, fitted into ``width`` columns.

    >>> format_line("Export", "frames", 150, 300, 5.0, width=60)
    'Export [##########..........] 150/300 frames  50% ETA 0:05'
    """
    total = max(total, 1)
    done = min(max(done, 0), total)
    fraction = done / total
    eta = "" if done == 0 else f" ETA {_clock_text(elapsed * (total - done) / done)}"
    tail = f" {done}/{total} {unit} {fraction:4.0%}{eta}"
    room = width - len(label) - len(tail) - 4
    if room < 5:
        return (label + tail)[: max(width - 1, 0)]
    bar_width = min(room, 40)
    filled = round(fraction * bar_width)
    return f"{label} [{'#' * filled}{'.' * (bar_width - filled)}]{tail}"


def _clock_text(seconds: float) -> str:
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes}:{secs:02d}"


def _is_terminal(stream: TextIO) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False
