"""The control panel's buttons (thesis figure 2-9: Sketch/Demo, Play/Pause, Stop, Clear, Save, Load, Timeline,
Simulate, and the rest); each posts the action it names for the screen to run, nothing else.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.message import Message
from textual.widgets import Button

BUTTONS: tuple[tuple[str, str], ...] = (
    ("sketch", "Sketch"), ("demo", "Demo"), ("play_pause", "Play"), ("stop", "Stop"),
    ("undo", "Undo"), ("redo", "Redo"), ("clear", "Clear"), ("label", "Label"), ("save", "Save"),
    ("load", "Load"), ("timeline", "Timeline"), ("simulate", "Simulate"), ("export", "Video"), ("picture", "Picture"),
    ("help", "Help"),
)
"""(action, label) of each button, left to right; the button's id is ``do-<action>``."""


class Controls(Horizontal):
    """A row of compact buttons."""

    @dataclass
    class Action(Message):
        """Run the screen's action ``name``."""

        name: str

    def compose(self) -> ComposeResult:
        for action, label in BUTTONS:
            yield Button(label, id=f"do-{action}", compact=True)

    def on_button_pressed(self, event: Button.Pressed) -> None:
        event.stop()
        if event.button.id and event.button.id.startswith("do-"):
            self.post_message(self.Action(event.button.id[3:]))
