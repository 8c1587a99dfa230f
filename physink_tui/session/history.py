"""Undo and redo over immutable documents (a scene and its timeline): every action is one entry; no I/O."""

from __future__ import annotations

from dataclasses import dataclass, field

from physink_tui.scene.components import Scene
from physink_tui.timeline.events import Timeline


@dataclass(frozen=True, slots=True)
class Document:
    """What the user has made: the sketch and, once demonstrated, its timeline.

    Attributes:
        scene: the sketch.
        timeline: the demonstrated timeline, or an adopted simulation's, or None.
        demonstration: when ``timeline`` is an adopted simulation, the demonstrated timeline it was found for
            (kept for comparing them again); None otherwise. Editing the sketch keeps it; demonstrating again
            drops it.
    """

    scene: Scene = field(default_factory=Scene)
    timeline: Timeline | None = None
    demonstration: Timeline | None = None


@dataclass
class History:
    """The documents before each action, for undo, and the ones undone, for redo.

    >>> h = History(Document())
    >>> h.push(Document(Scene().new_id("b")[1]), "stroke"); h.can_undo
    True
    >>> h.undo() == Document(), h.can_redo
    (True, True)
    """

    current: Document
    _undo: list[tuple[Document, str]] = field(default_factory=list)
    _redo: list[tuple[Document, str]] = field(default_factory=list)

    @property
    def can_undo(self) -> bool:
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        return bool(self._redo)

    def push(self, document: Document, description: str) -> None:
        """Record that ``description`` turned the current document into ``document``."""
        self._undo.append((self.current, description))
        self._redo.clear()
        self.current = document

    def amend(self, document: Document) -> None:
        """Replace the current document as part of the last action (its undo still goes back before it)."""
        self.current = document

    def undo(self) -> Document | None:
        """Go back one action; None when there is nothing to undo."""
        if not self._undo:
            return None
        before, description = self._undo.pop()
        self._redo.append((self.current, description))
        self.current = before
        return before

    def redo(self) -> Document | None:
        """Do again the last undone action; None when there is nothing to redo."""
        if not self._redo:
            return None
        after, description = self._redo.pop()
        self._undo.append((self.current, description))
        self.current = after
        return after

    def last_description(self) -> str | None:
        return self._undo[-1][1] if self._undo else None
