"""Records a demonstration as causal events from per-step observations of the world; no physics, no clock.

Fed after every physics step with the bodies' poses and velocities, the contacts that began and the body the
pen holds, it keeps one open movement per moving body and builds the timeline as the thesis does (3.3.1):
the pen's grab is the start (an exogenous force) that causes the grabbed body's movement; a contact is caused
by the movements of the bodies in it and causes a new movement of each movable body in it; contacts of the
same pair within 15 frames are one; a body that stops ends its movement. End-contacts, qualitative regions,
playback and concurrent movement are left to the rest of issue 6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from physink_tui.timeline.events import Event, Timeline, TrajectoryPoint

MOVING_SPEED = 5.0
"""Canvas units per second above which a body counts as moving."""
STILL_FRAMES = 12
"""Frames below `MOVING_SPEED` after which a movement ends."""
SAME_CONTACT_FRAMES = 15
"""Repeated reports of one pair within this many frames are one contact (DESIGN.md)."""

Pose = tuple[float, float, float, float, float]  # x, y, angle, vx, vy


def side_of(centre: tuple[float, float], point: tuple[float, float]) -> str:
    """Which side of a body (y down) a contact point lies on: top, bottom, left or right.

    >>> side_of((0, 0), (0, -5)), side_of((0, 0), (4, 1))
    ('top', 'right')
    """
    dx, dy = point[0] - centre[0], point[1] - centre[1]
    if abs(dy) >= abs(dx):
        return "top" if dy < 0 else "bottom"
    return "right" if dx > 0 else "left"


@dataclass
class _Open:
    event_id: str
    frames: list[TrajectoryPoint] = field(default_factory=list)
    still: int = 0


@dataclass
class Recorder:
    """Builds a `Timeline` from observations; `timeline` is always the events so far (open movements included).

    Attributes:
        movable: ids of the bodies that can move (fixed bodies never get movement events).
    """

    movable: frozenset[str]
    timeline: Timeline = field(default_factory=lambda: Timeline(()))
    frame: int = 0
    _next: int = 1
    _open: dict[str, _Open] = field(default_factory=dict)
    _last_contact: dict[frozenset[str], tuple[int, str]] = field(default_factory=dict)
    _start: str | None = None
    _grabbed: str | None = None

    def _new_id(self) -> str:
        self._next += 1
        return f"e{self._next - 1}"

    def observe(self, t: float, poses: dict[str, Pose], contacts: list[tuple[str, str, tuple[float, float]]],
                grabbed: str | None) -> None:
        """One physics step: the pose of every movable body, contacts begun ``(a, b, point)``, the pen's body."""
        self.frame += 1
        if grabbed is not None and grabbed != self._grabbed and grabbed in self.movable:
            self._grab(t, grabbed, poses[grabbed])
        self._grabbed = grabbed
        for a, b, point in contacts:
            self._contact(t, a, b, point, poses)
        for body_id in sorted(self.movable):
            pose = poses.get(body_id)
            if pose is None:
                continue
            moving = math.hypot(pose[3], pose[4]) > MOVING_SPEED or body_id == grabbed
            current = self._open.get(body_id)
            if current is not None:
                current.frames.append(TrajectoryPoint(t, *pose))
                current.still = 0 if moving else current.still + 1
                if current.still >= STILL_FRAMES:
                    self._close(body_id)

    @property
    def moving(self) -> bool:
        """Whether any movement is still open (timeline time runs on while bodies move)."""
        return bool(self._open)

    def snapshot(self) -> Timeline:
        """The timeline so far, open movements written up to now."""
        self._sync()
        return self.timeline

    def finish(self) -> Timeline:
        for body_id in list(self._open):
            self._close(body_id)
        return self.timeline

    # -- events --------------------------------------------------------------------------------

    def _grab(self, t: float, body_id: str, pose: Pose) -> None:
        if self._start is None:
            self._start = self._new_id()
            self.timeline = self.timeline.add(Event(self._start, "start", (), (), t, t))
        self._close(body_id)
        self._open_movement(t, body_id, (self._start,), pose)

    def _contact(self, t: float, a: str, b: str, point: tuple[float, float], poses: dict[str, Pose]) -> None:
        pair = frozenset((a, b))
        previous = self._last_contact.get(pair)
        if previous is not None and self.frame - previous[0] <= SAME_CONTACT_FRAMES:
            self._last_contact[pair] = (self.frame, previous[1])
            return
        causes = tuple(self._open[c].event_id for c in sorted(pair) if c in self._open)
        if not causes:
            return  # two still bodies touching (drawn so): no behaviour to explain
        cid = self._new_id()
        sides = tuple((c, side_of(poses[c][:2], point)) for c in sorted(pair) if c in poses)
        self.timeline = self.timeline.add(Event(cid, "contact", tuple(sorted(pair)), causes, t, t, sides=sides,
                                                point=point))
        self._last_contact[pair] = (self.frame, cid)
        for c in sorted(pair):
            if c in self.movable and c in poses:
                self._close(c)  # a contact splits the movement it interrupts
                self._open_movement(t, c, (cid,), poses[c])

    def _open_movement(self, t: float, body_id: str, causes: tuple[str, ...], pose: Pose) -> None:
        mid = self._new_id()
        self.timeline = self.timeline.add(Event(mid, "movement", (body_id,), causes, t, t,
                                                trajectory=(TrajectoryPoint(t, *pose),)))
        self._open[body_id] = _Open(mid, [TrajectoryPoint(t, *pose)])

    def _close(self, body_id: str) -> None:
        current = self._open.pop(body_id, None)
        if current is not None:
            self._write(current)

    def _sync(self) -> None:
        for current in self._open.values():
            self._write(current)

    def _write(self, current: _Open) -> None:
        event = self.timeline.event(current.event_id)
        frames = tuple(current.frames)
        if frames and (event.trajectory != frames):
            self.timeline = self.timeline.update(replace(event, t1=frames[-1].t, trajectory=frames))
