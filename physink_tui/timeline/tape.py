"""Playback of a timeline: where each recorded body is at timeline time t, from the frames of its movements.

A `Tape` gathers every movement's frames (the moving body's trajectory and the tracks of what is tied to it) per
body, in time order, and interpolates between them. Which bodies follow the tape and which the physics moves
is the session's business.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from physink_tui.scene.physics.state import Pose, Velocity
from physink_tui.timeline.events import Timeline


class Tape:
    """The recorded motion of every body of a timeline (optionally leaving some bodies out)."""

    def __init__(self, timeline: Timeline, exclude: Iterable[str] = ()) -> None:
        left_out = set(exclude)
        rows: dict[str, list[tuple[float, float, float, float]]] = {}
        for ev in timeline.events:
            if ev.type != "movement" or not ev.components:
                continue
            for body, frames in ((ev.components[0], ev.trajectory), *ev.tracks):
                if body not in left_out and frames:
                    rows.setdefault(body, []).extend((p.t, p.x, p.y, p.angle) for p in frames)
        self._frames: dict[str, np.ndarray] = {}
        for body, found in rows.items():
            table = np.array(found, dtype=float)
            order = np.argsort(table[:, 0], kind="stable")
            self._frames[body] = table[order]
        self.duration = max((ev.t1 for ev in timeline.events), default=0.0)

    @property
    def bodies(self) -> tuple[str, ...]:
        """The bodies with recorded frames, sorted."""
        return tuple(sorted(self._frames))

    def covers(self, body: str, t: float) -> bool:
        """Whether ``body`` has recorded motion around ``t`` (between its first and last frame)."""
        table = self._frames.get(body)
        return table is not None and table[0, 0] <= t <= table[-1, 0]

    def pose(self, body: str, t: float) -> Pose:
        """Where ``body`` is at ``t``: interpolated between frames, held at the first or last one outside them.

        >>> from physink_tui.timeline.events import Event, TrajectoryPoint
        >>> move = Event("e1", "movement", ("b1",), (), 0.0, 1.0,
        ...              trajectory=(TrajectoryPoint(0, 0, 0, 0, 0, 0), TrajectoryPoint(1, 10, 20, 1, 0, 0)))
        >>> Tape(Timeline((move,))).pose("b1", 0.25)
        Pose(x=2.5, y=5.0, angle=0.25)
        """
        table = self._frames[body]
        ts = table[:, 0]
        return Pose(*(float(np.interp(t, ts, table[:, k])) for k in (1, 2, 3)))

    def velocity(self, body: str, t: float, dt: float) -> Velocity:
        """The recorded velocity (vx, vy, angular) over the step from ``t`` to ``t + dt``."""
        a, b = self.pose(body, t), self.pose(body, t + dt)
        return Velocity((b[0] - a[0]) / dt, (b[1] - a[1]) / dt, (b[2] - a[2]) / dt)
