"""Undo and redo over immutable scenes: every sketch action is one entry; no I/O."""

from __future__ import annotations

from dataclasses import dataclass, field

from physink_tui.scene.components import Scene


@dataclass
class History:
    """The scenes before each action, for undo, and the ones undone, for redo.

    >>> h = History(Scene())
    >>> h.push(Scene().new_id("b")[1], "stroke"); h.can_undo
    True
    >>> h.undo() == Scene(), h.can_redo
    (True, True)
    """

    current: Scene
    _undo: list[tuple[Scene, str]] = field(default_factory=list)
    _redo: list[tuple[Scene, str]] = field(default_factory=list)

    @property
    def can_undo(self) -> bool:
        return bool(self._undo)

    @property
    def can_redo(self) -> bool:
        return bool(self._redo)

    def push(self, scene: Scene, description: str) -> None:
        """Record that ``description`` turned the current scene into ``scene``."""
        self._undo.append((self.current, description))
        self._redo.clear()
        self.current = scene

    def amend(self, scene: Scene) -> None:
        """Replace the current scene as part of the last action (its undo still goes back before it)."""
        self.current = scene

    def undo(self) -> Scene | None:
        """Go back one action; None when there is nothing to undo."""
        if not self._undo:
            return None
        before, description = self._undo.pop()
        self._redo.append((self.current, description))
        self.current = before
        return before

    def redo(self) -> Scene | None:
        """Do again the last undone action; None when there is nothing to redo."""
        if not self._redo:
            return None
        after, description = self._redo.pop()
        self._undo.append((self.current, description))
        self.current = after
        return after

    def last_description(self) -> str | None:
        return self._undo[-1][1] if self._undo else None
