"""What a view is given: `SessionView`, an immutable snapshot of a session (`view_of`), and `Message`; no drawing."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING

from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.timeline.events import Timeline

if TYPE_CHECKING:  # the session builds views; a view never reaches back into it
    from physink_tui.session.session import Session

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


def view_of(session: Session) -> SessionView:
    """The snapshot of ``session`` now."""
    from physink_tui.session.modes.demo import DemoMode

    mode = session.current
    width, height = session.canvas
    ink = tuple(tuple((p.x * width, p.y * height) for p in stroke) for stroke in session.pen.ink())
    pending = session.sketch.pending
    timeline = mode.timeline()
    demo = mode if isinstance(mode, DemoMode) else None
    return SessionView(
        revision=session.revision,
        t=session.t,
        mode=mode.name,
        scene=session.scene,
        poses=MappingProxyType(dict(mode.poses())),
        ink=ink,
        pending=(pending.points,) if pending is not None else (),
        selected=session.selected,
        can_undo=session.history.can_undo or (demo is not None and demo.has_take),
        can_redo=session.history.can_redo,
        timeline=timeline,
        clock=demo.clock if demo else 0.0,
        duration=max((ev.t1 for ev in timeline.events), default=0.0) if timeline else 0.0,
        playing=demo.playing if demo else False,
        messages=tuple(session.messages),
    )
