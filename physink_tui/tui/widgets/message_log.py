"""The narration log: every message the session told (`SessionView.messages`: what each stroke became, what was
refused, what SIMULATE found), oldest first, each with its input time, wrapped to the log's width; appends only what
is new, decides nothing.
"""

from __future__ import annotations

from rich.text import Text
from textual.widgets import RichLog

from physink_tui.session.view import Message, SessionView

MAX_LINES = 2000
"""Messages kept in the log (the oldest go first)."""


def line(message: Message) -> str:
    """How the log shows one message: its input time, then the text on one line."""
    return f"{message.t:6.1f} s  {message.text}".replace("\n", " ")


class MessageLog(RichLog):
    """The session's messages, scrolled to the newest unless the user scrolled up."""

    def __init__(self, **kwargs) -> None:
        super().__init__(max_lines=MAX_LINES, wrap=True, min_width=20, markup=False, highlight=False, **kwargs)
        self.told: tuple[Message, ...] = ()
        """The messages the log shows (the view's)."""
        self.written: list[str] = []
        """The lines written, one a message (the last `MAX_LINES`; tests read it)."""

    def show(self, view: SessionView) -> None:
        messages = view.messages
        shown = len(self.told)
        if messages is self.told or (len(messages) == shown and (not shown or messages[-1] is self.told[-1])):
            return
        if len(messages) < shown or (shown and messages[shown - 1] != self.told[-1]):  # another session's: afresh
            self.clear()
            self.written.clear()
            shown = 0
        for message in messages[shown:]:
            text = line(message)
            self.write(Text(text))
            self.written.append(text)
        del self.written[:-MAX_LINES]
        self.told = messages
