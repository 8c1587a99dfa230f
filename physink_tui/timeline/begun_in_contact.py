"""Movable bodies that begin a demonstration in contact (thesis 3.3.1, figure 3-9): when touching them again is a
push, and when it is only the jostle of a pair already in contact; pure kinematics, no events.

A pair of movable bodies of two mechanisms drawn touching, within `demo_setup.TOUCHING` of each other or
overlapping (as drawn, or once pushed clear) *begins in contact*: the start event names it
(`events.Event.in_contact`). Until the pair comes apart or one drives into the other, its contact is the one it
began with, so the physics' reports of it (a 2 px overlap resolved on the first step, the stopper grazing the
ball as it slides out from under it) are no new contact, and a body of it moving while its partner moves without
driving into it is jostled, not set moving. When a demonstrated movement takes the two apart, the recorder
inserts an end-contact caused by that movement, which causes a movement of each (figure 3-9: the stopper pulled
out from under the ball; the cup dispenser's platform weighed down away from the peg).

One body *drives into* the other when it moves towards the other faster than `DRIVE_SPEED` and not almost across
the line between them (`DRIVE_SHARE`): the cup the ball lands in pressing the platform it
stands on down, the egg pushed down through the paddles it rests on. Its own velocity counts, not the two bodies'
relative one: a cup pressing a platform down carries the platform with it at its own speed from the first step.
That is a contact, as between bodies that met during the demonstration; once a pair has had a contact, or an
end-contact, it is like any other pair (contacts that begin and end during a demonstration get no end-contact).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from shapely.geometry import Point, Polygon
from shapely.ops import nearest_points

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.qualitative import BodyOutline, hull_gap, placed

SEPARATION_GAP = 4.0
"""Canvas units by which two bodies that began in contact must get further apart than they began (drawn a few
pixels apart, or touching) to have come apart."""
DRIVE_SPEED = 30.0
"""Canvas units per second towards its partner above which a body drives into it: the hook of a hurried pen taking
hold of a stopper moves it up into the ball at up to 15 units/s (the hurried hand of tests/penmodels, 30 drawings
of figure 3-9), a cup the ball lands in presses its platform down at 65-80 units/s (the cup dispenser demonstrated,
and in SIMULATE's rollouts). A slower press is not told from a jostle: its pair stays in the contact it began in."""
DRIVE_SHARE = 0.2
"""The least share of the mover's speed that must point towards the other for it to drive into it (about 78 degrees
off the line between them at most): a cup knocked sideways by the ball landing in it still presses its platform
down (in SIMULATE's rollouts 65 of its 216 units/s); a stopper pulled out sideways from under a ball, wobbling a
few units/s up and down with the pen, slides along it."""


def drives_into(mover: Motion, other: Motion, normal: tuple[float, float] | None,
                speed: float = DRIVE_SPEED) -> bool:
    """Whether ``mover`` drives into ``other``: its velocity towards it along ``normal`` (pointing from the mover
    to the other; None: from centre to centre) faster than ``speed`` and at least `DRIVE_SHARE` of its speed.

    >>> drives_into((0, 0, 0, 0, 100, 0), (0, 50, 0, 0, 100, 0), None)  # pressing down what is below
    True
    >>> drives_into((0, 50, 0, 600, -3, 0), (0, 0, 0, 0, 0, 0), None)  # sliding out from under it
    False
    >>> drives_into((0, 50, 0, 6, -15, 0), (0, 0, 0, 0, -15, 0), None)  # the pen's hook as it takes hold
    False
    """
    if normal is None:
        dx, dy = other[0] - mover[0], other[1] - mover[1]
        d = math.hypot(dx, dy)
        if d == 0:
            return False
        normal = (dx / d, dy / d)
    vx, vy = mover[3], mover[4]
    approach = vx * normal[0] + vy * normal[1]
    return approach > speed and approach >= DRIVE_SHARE * math.hypot(vx, vy)


def facing(mover: BodyOutline, pose: Motion, other: Motion) -> tuple[float, float] | None:
    """The direction from ``mover`` towards ``other``'s centre across their contact: from the point of the mover's
    hull nearest that centre (a ball resting near one end of a long stopper is above it, not beside its middle);
    None when the centre is within the hull or the hull has no area (then centre to centre serves).

    >>> plank = BodyOutline("p", ((-120, -20), (120, -20), (120, 20), (-120, 20)), False)
    >>> facing(plank, (0, 0, 0, 0, 0, 0), (100, -60, 0, 0, 0, 0))
    (0.0, -1.0)
    """
    hull = placed(mover, pose)
    if len(hull) < 3:
        return None
    polygon, centre = Polygon(hull), Point(other[0], other[1])
    if polygon.area == 0 or polygon.covers(centre):
        return None
    near = nearest_points(polygon.exterior, centre)[0]
    dx, dy = other[0] - near.x, other[1] - near.y
    d = math.hypot(dx, dy)
    return (dx / d, dy / d) if d > 0 else None


def parted(outlines: Mapping[str, BodyOutline], pair: frozenset[str], poses: Mapping[str, Motion],
           began: dict[frozenset[str], float]) -> bool:
    """Whether the two bodies of ``pair`` have come apart: their hulls more than `SEPARATION_GAP` further apart
    than when first asked (``began`` keeps that gap, by pair). A body not in ``poses`` (fixed) cannot tell."""
    a, b = sorted(pair)
    pa, pb = poses.get(a), poses.get(b)
    if pa is None or pb is None:
        return False
    if pair not in began:
        began[pair] = hull_gap(outlines[a], pa, outlines[b], pb)
    limit = began[pair] + SEPARATION_GAP
    return hull_gap(outlines[a], pa, outlines[b], pb, limit) > limit
