"""The time slider: where the playback clock is in the demonstration, and a click to seek; one line, no state of
its own beyond the last view's clock and duration.
"""

from __future__ import annotations

from dataclasses import dataclass

from rich.text import Text
from textual import events
from textual.message import Message
from textual.widget import Widget

from physink_tui.session.view import SessionView

LABEL = 18
"""Cells kept at the right for the ``clock / duration`` text."""


class TimeSlider(Widget):
    """A bar from 0 to the timeline's duration with a knob at the clock; clicking posts `TimeSlider.Seek`."""

    @dataclass
    class Seek(Message):
        """Play back from timeline time ``t`` (seconds)."""

        t: float

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.clock = 0.0
        self.duration = 0.0
        self.mode = "sketch"

    def show(self, view: SessionView) -> None:
        state = (min(view.clock, view.duration), view.duration, view.mode)  # the clock can step past the end
        if state != (self.clock, self.duration, self.mode):
            self.clock, self.duration, self.mode = state
            self.refresh()

    def _bar_width(self) -> int:
        return max(4, self.size.width - LABEL)

    def render(self) -> Text:
        width = self._bar_width()
        if self.duration <= 0:
            return Text("─" * width + "  no demonstration", style="dim")
        knob = min(width - 1, round(self.clock / self.duration * (width - 1)))
        text = Text()
        text.append("━" * knob, style="bold")
        text.append("●", style="bold")
        text.append("─" * (width - knob - 1), style="dim")
        text.append(f" {self.clock:5.2f} / {self.duration:.2f} s" + ("" if self.mode == "demo" else " (sketch)"))
        return text

    def on_click(self, event: events.Click) -> None:
        width = self._bar_width()
        if self.duration > 0 and 0 <= event.x < width:
            self.post_message(self.Seek(round(event.x / (width - 1) * self.duration, 6)))
