"""The SIMULATE progress line: rollouts done of the budget in a progress bar, the best distances so far, and a
Cancel button; shown only while a search runs. It draws what the screen's search worker reports and posts the
cancel; the search is the worker's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from textual.app import ComposeResult
from textual.containers import Horizontal
from textual.message import Message
from textual.widgets import Button, Label, ProgressBar

from physink_tui.session.search_job import Progress


class SearchBar(Horizontal):
    """``Simulating  [████░░░░] 12/200 rollouts  best: qualitative 2, quantitative 35.1  [Cancel]``."""

    @dataclass
    class Cancel(Message):
        """The user asked to stop the search (keeping the best so far)."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.progress: Progress | None = None

    def compose(self) -> ComposeResult:
        yield Label("Simulating", id="search-title")
        yield ProgressBar(total=1, show_eta=False, show_percentage=False, id="search-progress")
        yield Label("", id="search-text")
        yield Button("Cancel", id="search-cancel", compact=True)

    def begin(self, budget: int) -> None:
        """A search of at most ``budget`` rollouts starts: the line shows, empty."""
        self.show(Progress(0, budget))
        self.display = True

    def end(self) -> None:
        self.display = False
        self.progress = None

    def show(self, progress: Progress) -> None:
        self.progress = progress
        self.query_one(ProgressBar).update(total=progress.budget, progress=progress.rollouts)
        best = ""
        if math.isfinite(progress.qualitative):
            best = f"  best: qualitative {progress.qualitative:g}, quantitative {progress.quantitative:.1f}"
        self.query_one("#search-text", Label).update(f"{progress.rollouts}/{progress.budget} rollouts{best}")

    def on_button_pressed(self, event: Button.Pressed) -> None:
        event.stop()
        self.post_message(self.Cancel())
