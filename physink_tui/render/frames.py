"""Builds `FrameContent` from snapshots: a demonstration at any time t (its recorded tape, no physics re-run) or a
session view; no drawing, no files.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

from physink_tui.render.frame import ContactMarker, FrameContent, Point, TimeBar, Trail
from physink_tui.scene.components import Scene
from physink_tui.scene.physics.state import Pose
from physink_tui.session.modes.base import ModeName
from physink_tui.session.view import SessionView
from physink_tui.timeline.events import Timeline, TrajectoryPoint, event_label
from physink_tui.timeline.tape import Tape

RECENT = 0.5
"""A contact is drawn emphasised, its sides written, for this long after it happens (seconds)."""


@dataclass(frozen=True, slots=True)
class _Track:
    """One movement's recorded path: its times and points (the points tuple is shared by every frame)."""

    trajectory: tuple[TrajectoryPoint, ...]
    times: tuple[float, ...]
    points: tuple[Point, ...]

    @classmethod
    def of(cls, trajectory: tuple[TrajectoryPoint, ...]) -> _Track:
        return cls(trajectory, tuple(p.t for p in trajectory), tuple((p.x, p.y) for p in trajectory))


class Demonstration:
    """A scene's timeline prepared for frames at any time: its tape, trails, contacts and narration, built once.

    Poses come from `Tape`, the playback the session's seek uses: a body with recorded motion is where the tape
    has it at t (held at its first or last frame outside them), any other body where it was drawn.

    ``previous``: a demonstration of an earlier snapshot of the same recording, whose paths are reused for the
    movements that have not changed (so a renderer keeps what it drew of them).
    """

    def __init__(self, scene: Scene, timeline: Timeline, canvas: tuple[float, float],
                 previous: Demonstration | None = None) -> None:
        self.scene = scene
        self.timeline = timeline
        self.canvas = (float(canvas[0]), float(canvas[1]))
        self.tape = Tape(timeline)
        self.duration = self.tape.duration
        names = scene.names()
        known = {id(track.trajectory): track for track in previous._tracks} if previous is not None else {}
        self._tracks: tuple[_Track, ...] = tuple(
            known[id(ev.trajectory)] if id(ev.trajectory) in known else _Track.of(ev.trajectory)
            for ev in timeline.events if ev.type == "movement" and len(ev.trajectory) >= 2)
        self._contacts = sorted(
            ((ev.t0, ev.point, " / ".join(f"{names.get(c) or c} {side}" for c, side in ev.sides))
             for ev in timeline.events if ev.type == "contact" and ev.point is not None),
            key=lambda c: c[0])
        shown = [(ev.t0, i, event_label(ev, names)) for i, ev in enumerate(timeline.events) if ev.type != "start"]
        shown.sort()
        self._said_at = [t for t, _, _ in shown]
        self._said = [text for _, _, text in shown]
        self.ticks = tuple(sorted({round(ev.t0, 6) for ev in timeline.events if ev.type != "start"}))

    def poses_at(self, t: float) -> dict[str, Pose]:
        """Every recorded body's pose at ``t``."""
        return {body: self.tape.pose(body, t) for body in self.tape.bodies}

    def trails_at(self, t: float, kind: str = "demonstration") -> tuple[Trail, ...]:
        """The paths taken up to ``t``: each movement's points reached, and where its body is between them."""
        trails = []
        for track in self._tracks:
            shown = bisect.bisect_right(track.times, t)
            if shown == 0:
                continue
            head = None
            if shown < len(track.times):
                (t0, t1), (a, b) = track.times[shown - 1: shown + 1], track.points[shown - 1: shown + 1]
                f = (t - t0) / (t1 - t0) if t1 > t0 else 0.0
                head = (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))
            trails.append(Trail(track.points, kind, shown, head))
        return tuple(trails)

    def contacts_at(self, t: float) -> tuple[ContactMarker, ...]:
        """The contacts that have happened by ``t``, those of the last `RECENT` seconds marked recent."""
        return tuple(ContactMarker(point, sides, at, t - at <= RECENT)
                     for at, point, sides in self._contacts if at <= t)

    def subtitle_at(self, t: float) -> str | None:
        """The narration of the event begun last by ``t`` (the start event excluded), or None before any."""
        i = bisect.bisect_right(self._said_at, t)
        return self._said[i - 1] if i else None

    def frame(self, t: float, *, with_trails: bool = True) -> FrameContent:
        """The frame at timeline time ``t`` (clamped to 0 .. duration: past the end shows the end)."""
        t = min(max(float(t), 0.0), self.duration)
        return FrameContent(
            scene=self.scene,
            canvas=self.canvas,
            poses=self.poses_at(t),
            trails=self.trails_at(t) if with_trails else (),
            contacts=self.contacts_at(t),
            subtitle=self.subtitle_at(t),
            time_bar=TimeBar(t, self.duration, self.ticks),
        )


def demonstration_frame(scene: Scene, timeline: Timeline, canvas: tuple[float, float], t: float, *,
                        with_trails: bool = True) -> FrameContent:
    """The frame of a demonstration at timeline time ``t``; for many frames build one `Demonstration` instead."""
    return Demonstration(scene, timeline, canvas).frame(t, with_trails=with_trails)


_prepared: list[Demonstration] = []
"""The last demonstration `view_frame` prepared: a view arrives many times per timeline, and preparing one (the
tape, the trails) costs more than a frame. Only a memo: a stale or raced entry is rebuilt, never wrong."""


def _demonstration(scene: Scene, timeline: Timeline, canvas: tuple[float, float]) -> Demonstration:
    """The demonstration of this scene and timeline, the last one prepared when it is the same."""
    last = _prepared[0] if _prepared else None
    if last is not None and last.scene is scene and last.timeline is timeline \
            and last.canvas == (float(canvas[0]), float(canvas[1])):
        return last
    demo = Demonstration(scene, timeline, canvas, previous=last)
    _prepared[:] = [demo]
    return demo


def view_frame(view: SessionView, canvas: tuple[float, float]) -> FrameContent:
    """The frame of a session view: bodies where its mode's world shows them, the ink being drawn, and in demo
    mode the trails, contacts, narration and time bar of the timeline at its clock."""
    ink = (*view.ink, *view.pending)
    canvas = (float(canvas[0]), float(canvas[1]))
    if view.mode != ModeName.DEMO or view.timeline is None or not view.timeline.events:
        return FrameContent(view.scene, canvas, view.poses, ink,
                            time_bar=TimeBar(view.clock, view.duration) if view.mode == ModeName.DEMO else None)
    demo = _demonstration(view.scene, view.timeline, canvas)
    t = min(max(view.clock, 0.0), demo.duration)
    return FrameContent(
        scene=view.scene,
        canvas=canvas,
        poses=view.poses,
        ink=ink,
        trails=demo.trails_at(t),
        contacts=demo.contacts_at(t),
        subtitle=demo.subtitle_at(t),
        time_bar=TimeBar(t, demo.duration, demo.ticks),
    )
