"""A chevron (two straight sides meeting at one corner) whose corner the hand rounded over part of each side."""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import shape_turning
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg

SIDE_SHARE = (0.4, 0.6)
"""The point (where the stroke stands farthest from the line joining its ends) lies within this share of the path
from either end: a chevron's two sides are about alike (the ST5022 writers' chevrons read as curves 0.45-0.54,
10th-90th; a tick's short arm is `bracket_marks.rounded_point`'s). A parenthesis curling tightly near one end
(`penmodels.paren_habits.lopsided_paren`) stands farthest from its ends' line 0.62-0.67 of the way along."""
OUTER = 0.6
"""The part of each side, from its end towards the point, that must be straight: a rounded corner may take up to
the 40 % of each side nearest the point (the sign set's ST5022 writers round 20-40 % of each side)."""
STRAIGHT = 0.06
"""Each side's outer part bows by at most this share of its chord (`stroke_geometry.chord_deviation`). An arc or a
parenthesis turning as much, evenly, bows its outer parts tan(turn * 0.3 / 4) / 2 (0.06 at 90 degrees, 0.08 at 120,
0.1 at 150: the shallower ones are told by `SHARP_BEND`); the design
group's braces, question marks and parentheses the rules read as curves with one bend and sides alike bow 0.167 or
more; the sign set's chevrons that read as polylines bow 0.012-0.072 (5th-95th percentile), its ST5022 writers'
chevrons read as curves 0.021-0.064 (10th-90th), their `curve_*` gestures (not scored) 0.063-0.171."""
SIDES_MEET = (80.0, 150.0)
"""The two outer parts' chords turn by this much (degrees) between them: a chevron, not a stroke bent a little (a
bowed line) nor a U whose sides run back side by side."""
CORNER_REACH = 0.4
"""Where the two outer parts' lines meet lies at most this share of the shorter side (from that meeting to its end)
from the stroke's point: the rounding cuts the corner; a pigtail's crossing sides meet far from where it turns
(0.65 or more on the design group's); the ST5022 writers' chevrons read as curves 0.19-0.38 (10th-90th), their
`curve_*` gestures 0.36-0.66."""
BEND_SPAN = 0.15
SHARP_BEND = 0.55
"""At least this share of the sides' turn is made within `BEND_SPAN` of the path (`stroke_geometry.sharpest_turn`):
the corner is rounded, not the whole stroke bowed (the ST5022 writers' chevrons read as curves 0.48-0.69, 10th-90th;
their `curve_*` gestures 0.29-0.54)."""


def rounded_chevron(work: np.ndarray, noise: float,
                    coarse: np.ndarray | None = None) -> tuple[tuple[float, float], ...] | None:
    """The start, corner and end of a chevron whose corner is a round bend, or None.

    A hand drawing a chevron quickly swings round its corner: the stroke turns one way (one lobe at the coarse scale,
    `stroke_features.turn_lobes`), its point (farthest from the line joining its ends) about halfway
    (`SIDE_SHARE`), and the outer `OUTER` of each side straight (`STRAIGHT`) with the two sides' lines turning
    `SIDES_MEET` and meeting near the point (`CORNER_REACH`), the stroke turning at a rounded corner, not bowed all
    along (`SHARP_BEND`). The corner is where those lines meet, drawn back towards the point only as far as the
    stroke's bounds need. A stroke hooked at an end so that it turns more than one way is left a curve (cutting such
    hooks read as many of the set's curve gestures polylines as chevrons). ``work``: the stroke as
    `open_shapes.classify_open` judges it; ``noise``: the pen's jitter in its units; ``coarse``: its
    `shape_turning.coarse_turning` at that noise, where already measured."""
    if len(work) < 12 or len(sf.turn_lobes(shape_turning.coarse_turning(work, noise) if coarse is None
                                           else coarse)) != 1:
        return None
    found = point_and_sides(work)
    if found is None:
        return None
    k, along, first, second = found
    start, end, length = work[0], work[-1], float(along[-1])
    if not SIDE_SHARE[0] <= along[k] / length <= SIDE_SHARE[1]:
        return None
    if max(sg.chord_deviation(first), sg.chord_deviation(second)) > STRAIGHT:
        return None
    u, v = first[-1] - first[0], second[-1] - second[0]
    turn = abs(math.degrees(math.atan2(float(u[0] * v[1] - u[1] * v[0]), float(u @ v))))
    if (not SIDES_MEET[0] <= turn <= SIDES_MEET[1]
            or sg.sharpest_turn(work, BEND_SPAN * length) < SHARP_BEND * turn):
        return None
    s = np.linalg.solve(np.array([u, -v]).T, second[0] - first[0])[0]  # the turn keeps the lines apart from parallel
    corner = first[0] + s * u
    shorter = min(float(np.hypot(*(corner - start))), float(np.hypot(*(corner - end))))
    if shorter == 0.0 or float(np.hypot(*(corner - work[k]))) > CORNER_REACH * shorter:
        return None
    corner = _within(corner, work[k], work)
    return tuple((float(p[0]), float(p[1])) for p in (start, corner, end))


def point_and_sides(work: np.ndarray) -> tuple[int, np.ndarray, np.ndarray, np.ndarray] | None:
    """Where ``work``'s point is (the index of the point farthest from the line joining its ends), every point's place
    along the path, and the outer `OUTER` of each side (from each end towards the point); None where the ends meet."""
    start, end = work[0], work[-1]
    d = end - start
    if float(np.hypot(*d)) == 0.0:
        return None
    rel = work - start
    k = int(np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0]).argmax())
    along = sg.along(work)
    length = float(along[-1])
    first = work[:max(int(np.searchsorted(along, OUTER * along[k])), 2)]
    second = work[min(int(np.searchsorted(along, along[k] + (1.0 - OUTER) * (length - along[k]))), len(work) - 2):]
    return k, along, first, second


BOUNDS_SHARE = 0.04
"""The corner stays within the stroke's bounds grown by this share of its diagonal (`ranking.BOUNDS_MARGIN` is 0.05):
where the sides' lines meet farther out, it is drawn back along the way to the stroke's point."""


def _within(corner: np.ndarray, point: np.ndarray, work: np.ndarray) -> np.ndarray:
    """``corner``, or the farthest point towards it from ``point`` within the stroke's bounds (`BOUNDS_SHARE`)."""
    low, high = work.min(axis=0), work.max(axis=0)
    margin = BOUNDS_SHARE * float(np.hypot(*(high - low)))
    low, high = low - margin, high + margin
    step = corner - point
    t = 1.0
    for axis in range(2):
        if step[axis] > 0 and corner[axis] > high[axis]:
            t = min(t, float((high[axis] - point[axis]) / step[axis]))
        elif step[axis] < 0 and corner[axis] < low[axis]:
            t = min(t, float((low[axis] - point[axis]) / step[axis]))
    moved: np.ndarray = point + max(t, 0.0) * step
    return moved
