"""The TUI's dialogs: help (every key binding), an error, a yes/no question, a line of text, the timeline as
text; each returns what the user chose through ``dismiss`` and decides nothing else.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import ClassVar

from textual.app import ComposeResult
from textual.binding import Binding, BindingType
from textual.containers import Horizontal, Vertical, VerticalScroll
from textual.screen import ModalScreen
from textual.widgets import Button, Input, Label, Static


class HelpScreen(ModalScreen[None]):
    """What to draw (the drawing vocabulary, `physink_tui.tui.drawing_help`) and every key binding of the control
    panel, with what each does."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape,q,question_mark,f1", "dismiss", "close")]

    def __init__(self, bindings: Iterable[tuple[str, str]], drawing: Iterable[str] = ()) -> None:
        super().__init__()
        self._keys = list(bindings)
        self._drawing = list(drawing)

    def compose(self) -> ComposeResult:
        drawing = ["What to draw (left mouse button or the pen):", "", *self._drawing] if self._drawing else []
        lines = ["Keys:", "", *(f"  {keys:<16} {what}" for keys, what in self._keys)]
        mouse = ["", "  mouse in the scene: left button draws (hold still to dwell, then drag to move a body),",
                 "  right button erases; in demo mode dragging a body demonstrates its movement.",
                 "  timeline: choose an event to play back from it.", "", "  escape closes this help"]
        with Vertical(id="dialog", classes="help"):
            yield Label("PhysInk — drawing and keys", classes="title")
            with VerticalScroll():
                yield Static("\n".join(drawing + lines + mouse), id="help-text", markup=False)

class ErrorModal(ModalScreen[None]):
    """A `PhysinkError` (or any failure a user caused), in words; the work is kept."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape,enter", "dismiss", "close")]

    def __init__(self, title: str, message: str) -> None:
        super().__init__()
        self._title, self._message = title, message

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog", classes="error"):
            yield Label(self._title, classes="title")
            yield Static(self._message, id="error-text")
            yield Static("Your work is kept.", classes="hint")
            yield Button("OK", id="ok", variant="primary")

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.dismiss(None)


class ConfirmModal(ModalScreen[bool]):
    """A yes/no question."""

    BINDINGS: ClassVar[list[BindingType]] = [
        Binding("escape,n", "answer(False)", "no"), Binding("y", "answer(True)", "yes")]

    def __init__(self, question: str, yes: str = "Yes", no: str = "No") -> None:
        super().__init__()
        self._question, self._yes, self._no = question, yes, no

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Static(self._question, id="question")
            with Horizontal(classes="buttons"):
                yield Button(self._yes, id="yes", variant="primary")
                yield Button(self._no, id="no")

    def on_button_pressed(self, event: Button.Pressed) -> None:
        self.dismiss(event.button.id == "yes")

    def action_answer(self, answer: bool) -> None:
        self.dismiss(answer)


class PromptModal(ModalScreen[str | None]):
    """One line of text (a label, a file name); None when cancelled."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape", "cancel", "cancel")]

    def __init__(self, question: str, value: str = "", placeholder: str = "") -> None:
        super().__init__()
        self._question, self._value, self._placeholder = question, value, placeholder

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog"):
            yield Label(self._question, classes="title")
            yield Input(self._value, placeholder=self._placeholder, id="prompt-input")
            yield Static("enter: OK   escape: cancel", classes="hint")

    def on_input_submitted(self, event: Input.Submitted) -> None:
        self.dismiss(event.value.strip() or None)

    def action_cancel(self) -> None:
        self.dismiss(None)


class TextScreen(ModalScreen[None]):
    """A text to read (the timeline as the thesis narrates it)."""

    BINDINGS: ClassVar[list[BindingType]] = [Binding("escape,q,t", "dismiss", "close")]

    def __init__(self, title: str, text: str) -> None:
        super().__init__()
        self._title, self._text = title, text

    def compose(self) -> ComposeResult:
        with Vertical(id="dialog", classes="text"):
            yield Label(self._title, classes="title")
            with VerticalScroll():
                yield Static(self._text, id="text-body", markup=False)
            yield Static("escape closes", classes="hint")
