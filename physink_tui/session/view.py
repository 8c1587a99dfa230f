"""What a view is given: `SessionView`, an immutable snapshot of a session (`snapshot`, for `Session.view`),
and `Message` (SIMULATE's `SearchResult` is `simulation`'s); no drawing."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType

from physink_tui.input.pen.gestures import StrokePoint
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.session.history import History
from physink_tui.session.modes.base import Mode, ModeName
from physink_tui.session.modes.demo import DemoMode
from physink_tui.session.modes.sketch import PendingStroke
from physink_tui.session.simulation import SearchResult
from physink_tui.timeline.events import Timeline

Stroke = tuple[tuple[float, float], ...]


@dataclass(frozen=True, slots=True)
class Message:
    """Something the user should be told, at input time ``t``.

    Attributes:
        t: input time (seconds since the session start).
        text: what to tell, one line.
        kind: ``outcome`` for what a stroke or a label made of the sketch ("circle → body b3", "erased box b4 — u
            to undo"), one per stroke; ``note`` for everything else (repairs, refusals, odd cases).
    """

    t: float
    text: str
    kind: str = "note"


@dataclass(frozen=True, slots=True)
class SessionView:
    """Everything a view shows, at one moment; every field is immutable.

    Attributes:
        revision: grows whenever the session changed (a view drawn at the same revision is up to date).
        t: the input time reached (seconds since the session start).
        mode: the mode the session is in.
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
        search: what the last ``simulate`` found for the document shown, or None (none ran since the document last
            changed).
        pens: for each input device, its pen state (`PenState` value, e.g. ``"touching"``) and the pressure
            (0..1) of the stroke being drawn, 0 when none (the status bar).
        demonstration: when ``timeline`` is an adopted simulation, the demonstration it was found for (kept in the
            project so the two can be compared again); None otherwise, and while a new take is being recorded.
    """

    revision: int
    t: float
    mode: ModeName
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
    search: SearchResult | None = None
    pens: Mapping[str, tuple[str, float]] = field(default_factory=lambda: MappingProxyType({}))
    demonstration: Timeline | None = None


def snapshot(revision: int, t: float, mode: Mode, scene: Scene, canvas: tuple[float, float],
             ink: Sequence[Sequence[StrokePoint]], pending: PendingStroke | None, selected: str | None,
             history: History, messages: Sequence[Message], search: SearchResult | None = None,
             pens: Mapping[str, tuple[str, float]] | None = None) -> SessionView:
    """The view of a session in ``mode`` (``ink``: the strokes being drawn, in canvas fractions; ``search``: the
    document's SIMULATE result; ``pens``: each device's pen state and pressure)."""
    width, height = canvas
    timeline = mode.timeline()
    demo = mode if isinstance(mode, DemoMode) else None
    return SessionView(
        revision=revision,
        t=t,
        mode=mode.name,
        scene=scene,
        poses=MappingProxyType(dict(mode.poses())),
        ink=tuple(tuple((p.x * width, p.y * height) for p in stroke) for stroke in ink),
        pending=(pending.points,) if pending is not None else (),
        selected=selected,
        can_undo=history.can_undo or (demo is not None and demo.has_take),
        can_redo=history.can_redo,
        timeline=timeline,
        clock=demo.clock if demo else 0.0,
        duration=max((ev.t1 for ev in timeline.events), default=0.0) if timeline else 0.0,
        playing=demo.playing if demo else False,
        messages=tuple(messages),
        search=search,
        pens=MappingProxyType(dict(pens or {})),
        demonstration=None if demo is not None and demo.has_take else history.current.demonstration,
    )
