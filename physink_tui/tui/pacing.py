"""When the UI draws a view: at once while it keeps up, and at a lower, steady rate while views reach it late (the
UI thread behind on a starved machine), so that keys are handled between frames; no Textual, no clock of its own.

A view is late when it waits longer than `LATE` between the runner posting it and the UI taking it. While views
are late the UI draws at most one every `SLOW_INTERVAL`; the view it passes over is drawn by a catch-up when that
interval is up (the caller's timer), so the screen always ends on the latest view.
"""

from __future__ import annotations

LATE = 0.025
"""Seconds a view may wait for the UI before the UI counts as behind."""
SLOW_INTERVAL = 1 / 32
"""Seconds between frames while behind (above the 30 frames a second the scene view is to keep)."""


class FramePacer:
    """Decides, view by view, whether to draw now (times in seconds on one monotonic clock)."""

    def __init__(self, late: float = LATE, slow_interval: float = SLOW_INTERVAL) -> None:
        if not (late > 0 and slow_interval > 0):
            raise ValueError(f"late and slow_interval must be > 0, got {late!r} and {slow_interval!r}")
        self.late = late
        self.slow_interval = slow_interval
        self.drawn_at = float("-inf")
        self.passed = 0
        """Views passed over so far (benchmarks, tests)."""

    def draw_now(self, posted: float, now: float) -> bool:
        """Whether a view posted at ``posted`` and taken at ``now`` is drawn now; if so, it counts as drawn."""
        if now - posted <= self.late or now - self.drawn_at >= self.slow_interval:
            self.drawn_at = now
            return True
        self.passed += 1
        return False

    def catch_up_in(self, now: float) -> float:
        """Seconds until a view passed over at ``now`` is to be drawn."""
        return max(0.0, self.drawn_at + self.slow_interval - now)

    def drew(self, now: float) -> None:
        """A catch-up drew at ``now``."""
        self.drawn_at = now
