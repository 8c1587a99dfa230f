"""What one picture shows, as frozen values (`FrameContent`), and the frame times of a video; no drawing, no files.

A frame is built from a snapshot (`frames.demonstration_frame`, `frames.view_frame`), never from a live world, and
drawn by `renderer.Renderer`. Coordinates are canvas units with y down, angles radians, times seconds of timeline
time, as in the scene and the timeline.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from physink_tui.scene.components import Body, Scene
from physink_tui.scene.physics.state import Pose

Point = tuple[float, float]
Stroke = tuple[Point, ...]
TRAIL_KINDS = ("demonstration", "simulation")


@dataclass(frozen=True, slots=True)
class Trail:
    """The path a body's origin has taken up to now.

    Attributes:
        points: the whole recorded path, canvas units; the same tuple in every frame of a video, so a renderer
            can extend what it drew last frame instead of starting again.
        kind: ``demonstration`` (drawn green) or ``simulation`` (drawn red).
        shown: how many of ``points`` are reached by now (0 .. len(points)).
        head: where the body is now when that is between two recorded points, else None.
    """

    points: tuple[Point, ...]
    kind: str
    shown: int
    head: Point | None = None

    def __post_init__(self) -> None:
        if self.kind not in TRAIL_KINDS:
            raise ValueError(f"trail kind: expected one of {TRAIL_KINDS}, got {self.kind!r}")
        if not 0 <= self.shown <= len(self.points):
            raise ValueError(f"trail shown: expected 0..{len(self.points)}, got {self.shown!r}")

    def visible(self) -> tuple[Point, ...]:
        """The points drawn now: the ones reached, then the head."""
        reached = self.points[: self.shown]
        return (*reached, self.head) if self.head is not None else reached


@dataclass(frozen=True, slots=True)
class ContactMarker:
    """A contact that has happened by the frame's time.

    Attributes:
        point: where the bodies touched, canvas units.
        sides: the sides that touched, named as the timeline's text names them (``ball bottom / lever top``).
        t: when it happened (seconds of timeline time).
        recent: whether it happened just now (drawn emphasised, with its sides written beside it).
    """

    point: Point
    sides: str
    t: float
    recent: bool


@dataclass(frozen=True, slots=True)
class TimeBar:
    """Where the frame is in the demonstration: ``t`` of ``duration`` seconds, a tick at each event's start."""

    t: float
    duration: float
    ticks: tuple[float, ...] = ()


@dataclass(frozen=True, slots=True)
class FrameContent:
    """Everything one picture shows.

    Attributes:
        scene: the components as drawn (their positions are where bodies not in ``poses`` are shown).
        canvas: (width, height) of the canvas, canvas units.
        poses: where bodies are shown now, by id; joints, springs and rope ends follow their bodies.
        ink: strokes being drawn (and finished ones waiting, such as half an X), canvas units.
        trails: the paths bodies have taken up to now.
        contacts: the contacts that have happened by now.
        subtitle: the narration of the current event, or None.
        time_bar: where the frame is in the demonstration, or None for no bar.
        highlight: ids of bodies outlined for attention (the TUI's chosen timeline event); none by default.
    """

    scene: Scene
    canvas: tuple[float, float]
    poses: Mapping[str, Pose] = field(default_factory=lambda: MappingProxyType({}))
    ink: tuple[Stroke, ...] = ()
    trails: tuple[Trail, ...] = ()
    contacts: tuple[ContactMarker, ...] = ()
    subtitle: str | None = None
    time_bar: TimeBar | None = None
    highlight: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        if not isinstance(self.poses, MappingProxyType):
            object.__setattr__(self, "poses", MappingProxyType(dict(self.poses)))

    def pose(self, body: Body) -> Pose:
        """Where ``body`` is shown: its pose in ``poses``, else where the scene has it."""
        found = self.poses.get(body.id)
        return found if found is not None else Pose(body.position[0], body.position[1], body.angle)


def frame_times(duration: float, fps: float) -> tuple[float, ...]:
    """The times of a video's frames: 0, 1/fps, 2/fps ... and the end itself, once.

    Raises:
        ValueError: ``duration`` is negative or not finite, or ``fps`` is not a positive finite rate.

    >>> frame_times(0.5, 4)
    (0.0, 0.25, 0.5)
    >>> frame_times(0.6, 4)
    (0.0, 0.25, 0.5, 0.6)
    """
    if not (isinstance(fps, int | float) and math.isfinite(fps) and fps > 0):
        raise ValueError(f"fps: expected a positive number of frames per second, got {fps!r}")
    if not (isinstance(duration, int | float) and math.isfinite(duration) and duration >= 0):
        raise ValueError(f"duration: expected a finite number of seconds >= 0, got {duration!r}")
    count = math.floor(duration * fps + 1e-9)
    times = [i / fps for i in range(count + 1)]
    if duration - times[-1] > 1e-9:
        times.append(float(duration))
    return tuple(times)
