"""The narration bar (what is happening, in words) and the status bar (mode, the latest message, device, pen,
journal); both only show what the `SessionView` and the drivers say.
"""

from __future__ import annotations

from textual.widgets import Static

from physink_tui.render.frames import Demonstration
from physink_tui.session import simulation
from physink_tui.session.view import Message, SessionView


def latest_told(view: SessionView, verdicts: set[str]) -> Message | None:
    """The latest message of ``view``, passing over a SIMULATE verdict (one of ``verdicts``) once the view no
    longer shows that search (the machine changed since: the verdict is about a machine that is gone)."""
    for message in reversed(view.messages):
        if view.search is None and message.text in verdicts:
            continue
        return message
    return None


class NarrationBar(Static):
    """The narration of the event at the playback clock in demo mode, else the latest message (never the verdict
    of a search whose machine has changed since)."""

    def __init__(self, **kwargs) -> None:
        super().__init__("", **kwargs)
        self._demo: Demonstration | None = None
        self.text = ""
        self.verdicts: set[str] = set()
        """What the session said of each search shown (`simulation.summary`), to pass over once it is gone."""

    def show(self, view: SessionView, canvas: tuple[float, float]) -> None:
        text = ""
        if view.mode == "demo" and view.timeline is not None and view.timeline.events:
            demo = self._demo
            if demo is None or demo.timeline is not view.timeline or demo.scene is not view.scene:
                demo = self._demo = Demonstration(view.scene, view.timeline, canvas)
            said = demo.subtitle_at(min(view.clock, demo.duration))
            if said:
                text = said
        if view.search is not None:
            self.verdicts.add(simulation.summary(view.search))
        told = latest_told(view, self.verdicts)
        if not text and told is not None:
            text = told.text
        if text != self.text:
            self.text = text
            self.update(text, layout=False)  # a fixed size (physink.tcss): a layout of the whole screen is not needed


class StatusBar(Static):
    """One line: mode (in demo mode the clock, never past the duration, and ``● recording`` while the pen moves a
    body), the session's latest message (what the last stroke became), what a worker is doing, pen, device,
    speech, journal."""

    def __init__(self, **kwargs) -> None:
        super().__init__("", **kwargs)
        self.device = "looking for a tablet…"
        self.journal = ""
        self.activity = ""
        self.pen = "pen out of range"
        self.speech = ""
        self.verdicts: set[str] = set()
        """What the session said of each search shown (`simulation.summary`), to pass over once it is gone."""
        self._view: SessionView | None = None
        self._shown = ""

    def show(self, view: SessionView) -> None:
        self._view = view
        self._refresh()

    def set(self, *, device: str | None = None, journal: str | None = None, activity: str | None = None,
            pen: str | None = None, speech: str | None = None) -> None:
        if device is not None:
            self.device = device
        if journal is not None:
            self.journal = journal
        if activity is not None:
            self.activity = activity
        if pen is not None:
            self.pen = pen
        if speech is not None:
            self.speech = speech
        self._refresh()

    def _refresh(self) -> None:
        view = self._view
        parts = []
        if view is not None:
            mode = view.mode.upper()
            if view.mode == "demo":
                holding = any(state in ("touching", "touching with a button pressed") for state, _ in
                              view.pens.values())
                state = "● recording" if holding else "playing" if view.playing else "paused"
                mode += f" {min(view.clock, view.duration):5.2f}/{view.duration:.2f} s {state}"
            parts.append(mode)
            if view.search is not None:
                self.verdicts.add(simulation.summary(view.search))
            told = latest_told(view, self.verdicts)
            if told is not None:
                parts.append(told.text)
        if self.activity:
            parts.append(self.activity)
        parts += [self.pen, self.device]
        if self.speech:
            parts.append(self.speech)
        if self.journal:
            parts.append(self.journal)
        text = "  │  ".join(parts)
        if text != self._shown:  # views come up to 60 a second; most change nothing here
            self._shown = text
            self.update(text, layout=False)  # one line (physink.tcss): repainting it needs no layout of the screen
