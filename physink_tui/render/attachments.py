"""Where joints, springs and ropes are drawn when their bodies have moved: rigid transforms and rope shapes; no
drawing, no physics.

The timeline records bodies, not ropes, so a rope is reshaped from its drawn path: its ends move with the bodies
they are tied to, the stretches where it lies on another body (a rope over a pulley) move with that body's centre,
and the points between follow, their displacement blended by distance along the rope. That keeps a rope as drawn
while nothing moves and tied to its bodies while they do, without simulating it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from physink_tui.scene.components import BACKGROUND, Body, Rope, Scene
from physink_tui.scene.physics.state import Pose

Point = tuple[float, float]

ROPE_CONTACT = 12.0
"""How close (canvas units) a rope point must be to a body's outline to count as lying on it."""
ROPE_STEP = 6.0
"""Rope points closer together than this along the rope are thinned out (canvas units)."""


def moved(point: Point, body: Body, pose: Pose | None) -> Point:
    """``point`` (canvas units, on ``body`` as drawn) carried by the body's move to ``pose`` (None: not moved).

    >>> from physink_tui.scene.components import MATERIALS
    >>> b = Body("b1", "circle", (), 5.0, (10.0, 0.0), 0.0, MATERIALS["round"])
    >>> [round(v, 6) for v in moved((12.0, 0.0), b, Pose(0.0, 0.0, math.pi / 2))]
    [0.0, 2.0]
    """
    if pose is None:
        return point
    turn = pose.angle - body.angle
    dx, dy = point[0] - body.position[0], point[1] - body.position[1]
    if turn == 0.0:
        return (pose.x + dx, pose.y + dy)
    c, s = math.cos(turn), math.sin(turn)
    return (pose.x + c * dx - s * dy, pose.y + s * dx + c * dy)


def carried(point: Point, body_id: str | None, scene: Scene, poses: Mapping[str, Pose]) -> Point:
    """``point`` carried by the body ``body_id`` (the background, None or an unknown id: it stays)."""
    if body_id is None or body_id == BACKGROUND:
        return point
    body = scene.components.get(body_id)
    if not isinstance(body, Body):
        return point
    return moved(point, body, poses.get(body_id))


def _near_body(points: np.ndarray, body: Body) -> np.ndarray:
    """Which of ``points`` (n, 2) lie on or within `ROPE_CONTACT` of ``body`` as drawn."""
    centre = np.array(body.position)
    if body.shape == "circle":
        return np.hypot(*(points - centre).T) <= body.radius + ROPE_CONTACT
    if len(body.outline) < 2:
        return np.zeros(len(points), dtype=bool)
    c, s = math.cos(body.angle), math.sin(body.angle)
    outline = np.array([(centre[0] + c * x - s * y, centre[1] + s * x + c * y) for x, y in body.outline])
    reach = np.max(np.hypot(*(outline - centre).T)) + ROPE_CONTACT
    near = np.zeros(len(points), dtype=bool)
    candidates = np.nonzero(np.hypot(*(points - centre).T) <= reach)[0]
    if not len(candidates):
        return near
    closed = body.shape != "polyline"
    starts = outline if closed else outline[:-1]
    ends = np.roll(outline, -1, axis=0) if closed else outline[1:]
    p = points[candidates][:, None, :]
    edge = (ends - starts)[None, :, :]
    length2 = np.maximum((edge ** 2).sum(axis=2), 1e-12)
    u = np.clip(((p - starts[None]) * edge).sum(axis=2) / length2, 0.0, 1.0)
    gap = np.hypot(*(p - starts[None] - u[..., None] * edge).transpose(2, 0, 1)).min(axis=1)
    inside = np.zeros(len(candidates), dtype=bool)
    if closed:  # even-odd crossings of a ray to the right
        x, y = p[:, 0, 0], p[:, 0, 1]
        for (x0, y0), (x1, y1) in zip(starts, ends, strict=True):
            if y0 != y1:
                crosses = ((y0 > y) != (y1 > y)) & (x < x0 + (y - y0) * (x1 - x0) / (y1 - y0))
                inside ^= crosses
    near[candidates] = (gap <= ROPE_CONTACT) | inside
    return near


class RopeShape:
    """A rope's drawn path thinned, with what each point is tied to; `at` gives its points under new poses.

    Attributes:
        rope: the rope as drawn.
        points: the thinned path, (n, 2) canvas units.
        pins: the pinned points' indices, first and last included, and the body each moves with (None: stays).
        rigid: per pin, whether it turns with its body (the rope's ends) or only follows its centre (a support).
    """

    def __init__(self, rope: Rope, scene: Scene) -> None:
        self.rope = rope
        every = np.array(rope.points, dtype=float)
        count = len(every)
        on: list[str | None] = [None] * count
        for body in scene.bodies():
            if body.id in (rope.start_body, rope.end_body):
                continue
            for i in np.nonzero(_near_body(every, body))[0].tolist():
                if 0 < i < count - 1 and on[i] is None:
                    on[i] = body.id
        # Keep the ends, the first and last point of each stretch lying on a body, and points ROPE_STEP apart.
        keep, walked = [0], 0.0
        for i in range(1, count):
            walked += float(np.hypot(*(every[i] - every[i - 1])))
            boundary = i == count - 1 or on[i] != on[i - 1] or on[i] != on[i + 1]
            if boundary or walked >= ROPE_STEP:
                keep.append(i)
                walked = 0.0
        self.points = every[keep]
        pins: list[tuple[int, str | None, bool]] = [(0, rope.start_body, True)]
        for k, i in enumerate(keep[1:-1], start=1):
            if on[i] is not None:
                pins.append((k, on[i], False))
        pins.append((len(keep) - 1, rope.end_body, True))
        self.pins = tuple((k, body) for k, body, _ in pins)
        self.rigid = tuple(r for _, _, r in pins)
        # Each point's displacement blends its neighbouring pins' by distance along the rope.
        along = np.concatenate(([0.0], np.cumsum(np.hypot(*np.diff(self.points, axis=0).T))))
        index = np.array([k for k, _ in self.pins])
        right = np.clip(np.searchsorted(index, np.arange(len(self.points)), side="left"), 1, len(index) - 1)
        left = right - 1
        span = along[index[right]] - along[index[left]]
        weight = np.where(span > 0, (along - along[index[left]]) / np.where(span > 0, span, 1.0), 0.0)
        self._left, self._right = left, right
        self._weight = np.clip(weight, 0.0, 1.0)[:, None]

    def bodies(self) -> tuple[str, ...]:
        """The bodies whose moves reshape the rope."""
        return tuple(sorted({b for _, b in self.pins if b is not None and b != BACKGROUND}))

    def at(self, scene: Scene, poses: Mapping[str, Pose]) -> np.ndarray:
        """The rope's points (n, 2) with its bodies at ``poses``."""
        moves = []
        for (k, body_id), rigid in zip(self.pins, self.rigid, strict=True):
            point = (float(self.points[k, 0]), float(self.points[k, 1]))
            if rigid:
                to = carried(point, body_id, scene, poses)
            else:  # a support: the rope slides over it, so only its centre's move counts
                body = scene.components.get(body_id) if body_id else None
                pose = poses.get(body_id) if body_id else None
                if isinstance(body, Body) and pose is not None:
                    to = (point[0] + pose.x - body.position[0], point[1] + pose.y - body.position[1])
                else:
                    to = point
            moves.append((to[0] - point[0], to[1] - point[1]))
        d = np.array(moves)
        return self.points + d[self._left] * (1.0 - self._weight) + d[self._right] * self._weight
