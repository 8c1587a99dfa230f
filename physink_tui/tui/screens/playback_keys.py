"""Where the main screen's playback keys and seek messages send the demonstration's clock: `PlaybackKeys`, a helper
the screen owns. Each → or ← press moves `SEEK_STEP` from where the last one went, even before the session has
handled it (a key held down repeats faster than views come), so every press counts; home and end go to the
timeline's ends. It leaves the session to the screen: each move is a ``seek`` command (after ``mode demo``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from physink_tui.session.simulation import SessionInput
from physink_tui.session.view import SessionView

SEEK_STEP = 0.5
"""Seconds of timeline time the arrow keys move the playback."""


class PlaybackKeys:
    """Seeks for a screen: ``latest`` gives the session's latest view (the runner's: the one drawn may be a frame
    behind), ``command`` sends a command and returns the input it became (None when no session is live)."""

    def __init__(self, latest: Callable[[], SessionView | None],
                 command: Callable[..., SessionInput | None]) -> None:
        self._latest = latest
        self._command: Callable[..., Any] = command
        self._seeking: tuple[SessionInput, float] | None = None  # the last seek sent and its target clock

    def seek(self, t: float) -> None:
        """To timeline time ``t`` (demo mode first, if the session is in another)."""
        view = self._latest()
        if view is not None and view.mode != "demo":
            self._command("mode", "demo")
        entry = self._command("seek", round(t, 6))
        self._seeking = (entry, round(t, 6)) if entry is not None else None

    def step(self, direction: int) -> None:
        """`SEEK_STEP` forward (1) or back (-1) from the clock, or from the last seek not handled yet."""
        view = self._latest()
        if view is None or view.mode != "demo":
            return
        clock = view.clock
        if self._seeking is not None and view.t < self._seeking[0].t:  # the last seek is not handled yet
            clock = self._seeking[1]
        self.seek(min(max(clock + direction * SEEK_STEP, 0.0), view.duration))

    def to_end(self, where: str) -> None:
        """To the timeline's ``start`` or its end."""
        view = self._latest()
        if view is not None and view.mode == "demo":
            self.seek(0.0 if where == "start" else view.duration)
