"""What a view is given: `SessionView`, an immutable snapshot of a session (built by `Session.view`), and
`Message`; no drawing."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.timeline.events import Timeline

Stroke = tuple[tuple[float, float], ...]


@dataclass(frozen=True, slots=True)
class Message:
    """Something the user should be told, at input time ``t``."""

    t: float
    text: str


@dataclass(frozen=True, slots=True)
class SearchProgress:
    """How far a SIMULATE search has got (filled by the simulation issue)."""

    rollouts: int
    budget: int
    best_distance: float | None


@dataclass(frozen=True, slots=True)
class SessionView:
    """Everything a view shows, at one moment; every field is immutable.

    Attributes:
        revision: grows whenever the session changed (a view drawn at the same revision is up to date).
        t: the input time reached (seconds since the session start).
        mode: ``sketch``, ``adjust`` or ``demo``.
        scene: the document's scene.
        poses: where each body is shown now (the mode's world: moved while adjusting or demonstrating).
        ink: strokes being drawn now, canvas units, one per pen down.
        pending: finished strokes not yet in the scene (a possible half-X waiting for its other half).
        selected: the selected component, or None.
        can_undo, can_redo: whether undo and redo would do anything.
        timeline: the timeline as it stands (while demonstrating, recorded so far), or None.
        clock: timeline time (demo mode), else 0.
        duration: the timeline's length in seconds.
        playing: whether the recording is playing back.
        messages: everything told so far, oldest first.
        search: SIMULATE's progress, or None when no search runs.
    """

    revision: int
    t: float
    mode: str
    scene: Scene
    poses: Mapping[str, Pose]
    ink: tuple[Stroke, ...]
    pending: tuple[Stroke, ...]
    selected: str | None
    can_undo: bool
    can_redo: bool
    timeline: Timeline | None
    clock: float
    duration: float
    playing: bool
    messages: tuple[Message, ...]
    search: SearchProgress | None = None
