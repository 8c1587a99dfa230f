"""A star's outline left open by a side: its points and dents alternating along straight sides; no ranking, no I/O."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition import open_shapes, shape_corners
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg

STAR_POINTS = 4
"""A star's outline drawn in one stroke turns out at its points and in at its dents, one after the other; left open by a
side (the pen lifting a side short of its start, as Quick, Draw! players hurry on: tutorboard seed260730 #102, five
points and four dents drawn) it shows this many points or more, each between two dents. A zig-zag's teeth alternate
too, but its gap spans the whole row of them (`GAP_SIDES`), and a U, a C or a bracket shows fewer corners."""
GAP_SIDES = 1.5
"""The gap of such an outline is no longer than this many times its longest side drawn (`closed_loops.LEFT_OPEN_GAP`):
about a side missing (a point to the next point, a dent skipped, is 1.6 sides of a regular star: not asked)."""
DENT_DEG = 25.0
"""The corners are found where the path turns this much or more, at every dip (`stroke_geometry.find_corners`; as
`closed_loops.MANY_SIDED_TURN_DEG`): a fat star's dents turn 40-60 degrees, less than a corner finder's default sees."""
DENT_SHARE = 0.75
"""A star's dents turn back less than its points turn out, on the mean at most this share of them: round a star's
outline the points' turns exceed the dents' by a whole turn (a regular five-pointed star's dents 72 degrees to its
points' 144; tutorboard seed260730 #102's 46-111 to 122-142, 0.56 on the mean), where a zig-zag's or a crown's teeth
turn back as sharply as they turn out (0.9-1.0)."""
END_BOW = 0.2
"""The first and last sides may bow this much of their chord (`closed_loops.LAST_SIDE_BOW`)."""
POINT_DEG = 80.0
"""A star's point turns this much or more (a five-pointed star's 144 degrees, a four-pointed one's 90-140; a hurried
hand's widest, 100-110; tutorboard seed260730 #102's 122-142), its point no wider than 100 degrees."""


def star_outline(corners: Sequence[Sequence[float]]) -> bool:
    """Whether a polygon's ``corners`` (in order round it) are a star's: turning once round, out at `STAR_POINTS`
    points or more (each `POINT_DEG` or more) and in at the dents between (less: `DENT_SHARE`), in turn all round but
    for one pair of points side by side (the dent between them cut off where the pen left the outline open and the gap
    was closed)."""
    ring = np.asarray(corners, dtype=float)
    if len(ring) < 2 * STAR_POINTS - 1:
        return False
    turns = sf.ring_turns(np.diff(np.vstack([ring, ring[:1]]), axis=0))
    total = float(turns.sum())
    if abs(abs(total) - 2 * math.pi) > 0.1:
        return False
    signs = np.sign(turns)
    points = np.degrees(np.abs(turns[signs == np.sign(total)]))
    dents = np.degrees(np.abs(turns[signs != np.sign(total)]))
    return (int((signs == np.roll(signs, 1)).sum()) <= 1 and len(points) >= STAR_POINTS and len(dents) > 0
            and bool((points >= POINT_DEG).all()) and float(dents.mean()) <= DENT_SHARE * float(points.mean()))


def star_left_open(work: np.ndarray, length: float, dips: list[int] | None = None,
                   bends: tuple[np.ndarray, np.ndarray, list[shape_corners.Bend]] | None = None) -> bool:
    """Whether an open stroke (``length`` long) is a star's outline left open by a side (`_star_chain`), its corners
    found where the path turns `DENT_DEG` or more (`stroke_geometry.find_corners`, every dip), or else at its short
    bends (`shape_corners.corner_bends`, on `shape_corners.STEPS` points: a dent the hand swept round over a step or
    two, which the finer look sees as two shallow turns). ``dips`` (those corners) and ``bends`` (`shape_corners.bends`
    of ``work``): where already found."""
    corners = sf.drop_end_stubs(work, sg.find_corners(work, DENT_DEG, every_dip=True), length) if dips is None else dips
    if _star_chain(work, corners):
        return True
    pts, _, found = shape_corners.bends(work) if bends is None else bends
    bent = shape_corners.corner_bends(found)
    return _star_chain(pts, [0, *((b.first + b.last) // 2 + 1 for b in bent), len(pts) - 1])


def _star_chain(work: np.ndarray, corners: list[int]) -> bool:
    """Whether ``work`` between its ``corners`` (indices, its ends among them) is a star's outline left open: its sides
    straight (`open_shapes.STRAIGHT`; the first and last up to `END_BOW`, as the hand swings landing and lifting), the
    outline closed through the gap (`GAP_SIDES`) turning once round, its corners between the ends turning out at the
    points (`POINT_DEG`) and in at the dents in turn, `STAR_POINTS` points or more in all (one of them, or a dent, may
    lie at an end or in the gap: the ends' turns, into and out of the gap, are not asked)."""
    if len(corners) < 2 * STAR_POINTS:
        return False
    sides = sf.closing_sides(work, corners, open_shapes.STRAIGHT, END_BOW, GAP_SIDES)
    if sides is None:
        return False
    turns = sf.ring_turns(sides)
    total = float(turns.sum())
    if abs(abs(total) - 2 * math.pi) > 0.1:
        return False
    inner = np.degrees(turns[:-2])  # at the corners between the ends, in the order drawn
    out = np.sign(total)
    if (np.sign(inner[1:]) == np.sign(inner[:-1])).any():
        return False
    points, dents = np.abs(inner[np.sign(inner) == out]), np.abs(inner[np.sign(inner) != out])
    return (len(points) >= STAR_POINTS - 1 and bool((points >= POINT_DEG).all())
            and float(dents.mean()) <= DENT_SHARE * float(points.mean()))
