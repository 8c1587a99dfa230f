"""What every mode offers the session (`Mode`) and what the session offers a mode (`Host`); no behaviour."""

from __future__ import annotations

from collections.abc import Mapping
from enum import StrEnum
from typing import Protocol

from physink_tui.input.pen.gestures import Gesture
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.session.history import Document
from physink_tui.timeline.events import Timeline


class ModeName(StrEnum):
    """Which mode a session is in (a string, so views, logs and journals read the same)."""

    SKETCH = "sketch"
    """Strokes become components."""
    ADJUST = "adjust"
    """A body is being moved by the pen (sketching resumes when it is put down)."""
    DEMO = "demo"
    """Moving bodies by hand records a demonstration's timeline."""


class Host(Protocol):
    """The session as a mode sees it: the document, the canvas, and the ways a mode changes them."""

    canvas: tuple[float, float]

    @property
    def document(self) -> Document: ...

    def tell(self, text: str, t: float | None = None, kind: str = "note") -> None:
        """Tell the user ``text`` (stamped ``t``, default the session's time); ``kind`` is `view.Message`'s."""

    def commit(self, document: Document, description: str) -> None:
        """``document`` is the result of an action the user can undo."""

    def amend(self, document: Document) -> None:
        """``document`` finishes the last action (one undo still takes all of it back)."""

    def select(self, component_id: str | None) -> None:
        """The user chose ``component_id`` (None: nothing)."""


class Mode(Protocol):
    """One mode of the session. ``name`` is what a view shows."""

    name: ModeName

    @property
    def finished(self) -> bool:
        """The mode has ended by itself (an adjustment put down): the session goes back to sketching."""

    def gesture(self, g: Gesture) -> Mode | None:
        """Act on one pen gesture; return the mode to continue in when it changes (adjusting begins or ends)."""

    def advance(self, t: float) -> bool:
        """Time passes to input time ``t`` (never earlier than before); True when anything changed."""

    def close(self, t: float) -> None:
        """The mode ends at ``t`` (another begins, or undo, redo, clear or the session's end): what it was doing
        is finished and committed, so the document holds all of it."""

    def poses(self) -> Mapping[str, Pose]:
        """Where every body is shown now."""

    def timeline(self) -> Timeline | None:
        """The timeline as it stands now (a demonstration's, while recording)."""

    def scene(self) -> Scene:
        """The scene being shown."""
