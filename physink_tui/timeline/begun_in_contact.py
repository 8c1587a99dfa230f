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

One body *drives into* the other when it moves towards the other, mostly along the line between them
(`DRIVE_SHARE`) and faster than the recorder's moving speed: the cup the ball lands in pressing the platform it
stands on down, the egg pushed down through the paddles it rests on. Its own velocity counts, not the two bodies'
relative one: a cup pressing a platform down carries the platform with it at its own speed from the first step.
That is a contact, as between bodies that met during the demonstration; once a pair has had a contact, or an
end-contact, it is like any other pair (contacts that begin and end during a demonstration get no end-contact).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from physink_tui.scene.physics.state import Motion
from physink_tui.timeline.qualitative import BodyOutline, hull_gap

SEPARATION_GAP = 4.0
"""Canvas units by which two bodies that began in contact must get further apart than they began (drawn a few
pixels apart, or touching) to have come apart."""
DRIVE_SHARE = 0.5
"""The least share of the mover's speed that must point from one body towards the other for it to drive into it
(60 degrees off the line between them at most)."""


def drives_into(mover: Motion, other: Motion, normal: tuple[float, float] | None, speed: float) -> bool:
    """Whether ``mover`` drives into ``other``: its velocity towards it along ``normal`` (pointing from the mover
    to the other; None: from centre to centre) faster than ``speed`` and at least `DRIVE_SHARE` of its speed.

    >>> drives_into((0, 0, 0, 0, 100, 0), (0, 50, 0, 0, 100, 0), None, 5.0)  # pressing down what is below
    True
    >>> drives_into((0, 50, 0, 600, -3, 0), (0, 0, 0, 0, 0, 0), None, 5.0)  # sliding out from under it
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
