"""Contacts in the physics world: records where contacts begin and gives each contact its material; no stepping.

The world's pymunk space calls a `ContactListener` when a contact begins and ends: ``begin`` appends a frozen
`ContactRecord` (one per pair of components per step), counts the pair as touching until ``separate``, and gives a
contact that begins faster than `BOUNCE_THRESHOLD` the larger restitution of its two surfaces (build.py gives
shapes no elasticity, so every other contact and every later step of this one is inelastic). `set_friction` is the
pre-solve callback the world registers for the pairs of surfaces whose friction Chipmunk's product gets wrong.
"""

from __future__ import annotations

from dataclasses import dataclass

import pymunk

from physink_tui.scene.components import Point

BOUNCE_THRESHOLD = 50.0
"""Slowest approach (canvas units/s) that bounces; slower contacts and contacts that persist are inelastic.

Chipmunk re-applies restitution every step a contact lasts, so a body resting on a fully elastic box (restitution
1.0) is bounced by the speed gravity gave it in the last step and a pile never settles. Box2D, which the thesis
used, bounces only approaches faster than ``b2_velocityThreshold`` (1 m/s); this is its counterpart here: a ball
that would bounce less than 50² / (2 * 900) ~ 1.4 units high under gravity stays down.
"""

@dataclass(frozen=True, slots=True)
class ContactRecord:
    """Two components started touching.

    Attributes:
        step: the step (1-based, counted over the world's life) in which the contact began.
        a_id, b_id: the body or rope ids, in the order pymunk reported the pair.
        point: a contact point on ``a``'s surface, canvas units.
        normal: unit vector from ``a`` towards ``b``.
    """

    step: int
    a_id: str
    b_id: str
    point: Point
    normal: Point


class ContactListener:
    """Collision callbacks for one world: contact records, and the materials of each contact."""

    def __init__(self, owner: dict[pymunk.Shape, str], bounces: dict[tuple[int, int], float]) -> None:
        self._owner = owner
        self._bounces = bounces
        self._records: list[ContactRecord] = []
        self._touched: set[tuple[str, str]] = set()
        self._touching: dict[frozenset[str], int] = {}
        self.step = 0

    def next_step(self) -> None:
        """A new step begins: pairs may report a contact again."""
        self.step += 1
        self._touched.clear()

    def take(self) -> list[ContactRecord]:
        out, self._records = self._records, []
        return out

    def touching(self) -> frozenset[frozenset[str]]:
        """The pairs of components whose shapes touch now."""
        return frozenset(pair for pair, n in self._touching.items() if n > 0)

    def begin(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        sa, sb = arbiter.shapes
        points = None
        restitution = self._bounces[sa.collision_type, sb.collision_type]
        if restitution > 0.0:
            points = arbiter.contact_point_set
            body_a, body_b = sa.body, sb.body
            assert body_a is not None and body_b is not None  # shapes in a collision are on bodies
            if _approach_speed(body_a, body_b, points) > BOUNCE_THRESHOLD:
                # Chipmunk multiplies the shapes' elasticities (0.0) again on the contact's next step: one bounce.
                arbiter.restitution = restitution
        a, b = self._owner.get(sa), self._owner.get(sb)
        if a is None or b is None:
            return
        pair = frozenset((a, b))
        self._touching[pair] = self._touching.get(pair, 0) + 1
        if (a, b) in self._touched or (b, a) in self._touched:
            return  # a polygon's triangles or a polyline's segments: one contact per pair per step
        self._touched.add((a, b))
        if points is None:
            points = arbiter.contact_point_set
        at = points.points[0].point_a if points.points else _position(sa)
        self._records.append(ContactRecord(self.step, a, b, (at[0], at[1]), (points.normal.x, points.normal.y)))

    def separate(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        sa, sb = arbiter.shapes
        a, b = self._owner.get(sa), self._owner.get(sb)
        if a is None or b is None:
            return
        pair = frozenset((a, b))
        left = self._touching.get(pair, 0) - 1
        if left > 0:
            self._touching[pair] = left
        else:
            self._touching.pop(pair, None)


def touching_record(step: int, a: pymunk.Body, b: pymunk.Body, a_id: str, b_id: str) -> ContactRecord | None:
    """The contact between bodies ``a`` and ``b`` touching now, as a record of one begun in ``step`` (a contact
    point on ``a``'s surface, the normal from ``a`` towards ``b``); None when no contact joins them."""
    arbiters: list[pymunk.Arbiter] = []
    a.each_arbiter(arbiters.append)
    for arbiter in arbiters:
        sa, sb = arbiter.shapes
        points = arbiter.contact_point_set
        if b in (sa.body, sb.body) and points.points:
            first = sa.body is a  # Chipmunk gives a body's own shape first; checked all the same
            at = points.points[0].point_a if first else points.points[0].point_b
            n = points.normal if first else -points.normal
            return ContactRecord(step, a_id, b_id, (at.x, at.y), (n.x, n.y))
    return None


def set_friction(arbiter: pymunk.Arbiter, space: pymunk.Space, friction: float) -> None:
    """Pre-solve callback for one pair of surfaces (``friction`` is its mean): Chipmunk sets the product each step."""
    arbiter.friction = friction


def _position(shape: pymunk.Shape) -> pymunk.Vec2d:
    """Where the body of a shape in a collision is."""
    body = shape.body
    assert body is not None  # shapes in a collision are on bodies
    return body.position


def _approach_speed(a: pymunk.Body, b: pymunk.Body, points: pymunk.ContactPointSet) -> float:
    """How fast bodies ``a`` and ``b`` close along the contact normal at the first contact point (> 0: approaching)."""
    if not points.points:
        return 0.0
    at = points.points[0].point_a
    va, vb = a.velocity_at_world_point(at), b.velocity_at_world_point(at)
    return (va.x - vb.x) * points.normal.x + (va.y - vb.y) * points.normal.y
