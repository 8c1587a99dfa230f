"""A loop read as a polygon that is a box one of whose sides a hand bowed out or in; geometry only, no I/O.

A hurried hand draws three sides of a box straight and square and swings the fourth round in a bow (out, or in), or
swings round the fourth side's two corners and the side between them in one sweep (a D drawn square on one side). A
bow deeper than about 15 % of its chord is no side to the polygonal fits (`polygon_checks.BOW_SHARE`), which spend a
fifth or sixth side on it and read a low pentagon, and the box of its corners covers it by too little for
`rounded_corners.box_as_drawn` (a side bowed by 0.2 changes a 2.5:1 box's area by a fifth). What tells such a bow from a
pentagon's roof or a notch is its shape across the chord between the walls it joins (`bow_of`): it stays on one
side of that chord, runs along it without turning back, reaches no further from it than `MAX_BOW` of it, fills the
strip between the chord and its deepest point as a round bow does, not as a roof's two straight sides do
(`ROUND_FILL`), and bends round at its deepest point, not at a corner (`ROUND_BEND`).

The loop is that box when three consecutive sides of a fit of five or six sides run straight for `STRAIGHT_SHARE` of the
box's sides (`rounded_corners.straight_part`), the middle one stands square to both others (`quads.SQUARE_WALL`, 12
degrees, as an askew box's square wall: a regular pentagon's sides turn 18 off square), the two corners between them are
turned sharply (`polygon_checks.SHARP_CORNER`: a box's corners drawn, not a round loop's or an octagon's cut corners),
the box of their lines and the bow's chord meets near right angles (`beautify.box_geometry`), and the rest of the loop
between the first and third sides' straight parts is such a bow.
The box keeps the loop's own area: its fourth side lies parallel to the chord, where the area the bow adds (or takes)
is given back (a bow's middle, not its corners: the box a person sees in it).
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import box_geometry
from physink_tui.scene.recognition.candidates import Pending
from physink_tui.scene.recognition.polygon_checks import BOW_SHARE, SHARP_CORNER, corner_roundness_closed, crossings
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Box, Polygon, Recognition
from physink_tui.scene.recognition.quads import SQUARE_WALL
from physink_tui.scene.recognition.ranking import BOX_MARGIN, bounds, inside
from physink_tui.scene.recognition.rounded_corners import STRAIGHT_SHARE, Part, lines_meet, straight_parts

SHALLOWEST = 2 * BOW_SHARE
"""A bow reaches more than this share of its chord from it (0.12): a shallower one is a side to the box rules already
(`rounded_corners.box_as_drawn`; `box_habits` side-bowed, 6-12 %: every one a box), and a straight side a device's few
events bend (a trapezoid's leg through a coarse device: 0.11) is no bow."""
MAX_BOW = 0.3
"""A bow reaches at most this share of its chord from it: a round bow so deep leaves the walls it joins 50-62 degrees
off its chord's line (a parabola's, a circle's arc), past half way from a side to a wall; deeper, it is a D's half round
or an arch (0.5), or a deep cut corner the hurried hand rounds (`penmodels.box_bows` cut-deep through a coarse device,
tuning seed 21: 0.38), no side of a box. Until session 34 this was 0.25 (45-53 degrees), which kept Quick, Draw! BG
square #4526069946253312 a polygon: its right side and both its corners swung round in one sweep 0.26 of its chord
(`tests/test_box_bows.py`). At 0.4 tutorboard seed90210 square #232 (0.38) is a box too, but two held-seed houses and
that cut corner turn into boxes; no other design or fourth-group reading changes up to 0.5."""
ROUND_FILL = 0.55
"""A bow fills at least this share of the strip between its chord and the line through its deepest point (the mean
of its depth over the chord, over its greatest depth): a round bow 2/pi (a sine's half wave) to 2/3 (a parabola, a
circle's arc), more where the hand swings its corners round too; a roof's two straight sides meeting at a corner fill
half of it, a notch less."""
ROUND_BEND = 0.45
"""A bow does 80 % of the turning between the midpoints of its halves over at least this share of half its length
(`stroke_features.corner_roundness` at its deepest point, measured against half the bow rather than its shorter half,
which a cut corner's short stretch would make look round): a round bow 0.7 (a sine's half wave) to 0.8 (a parabola, a
circle's arc); a drawn corner within a tenth or two, a hurried hand's rounded corner within a third
(`polygon_checks.SHARP_CORNER`)."""
SIDES = (5, 6)
"""Fits of these many sides are judged: three kept as the box's straight sides, the others taken for the bow."""


def _area(ring: np.ndarray) -> float:
    x, y = ring[:, 0], ring[:, 1]
    return 0.5 * float(np.dot(x, sg.succ(y)) - np.dot(y, sg.succ(x)))


def _off_square(d: np.ndarray, e: np.ndarray) -> float:
    """Degrees two unit directions are off square."""
    return 90.0 - math.degrees(math.acos(min(1.0, abs(float(d @ e)))))


def bow_of(run: np.ndarray, noise: float) -> tuple[float, float, float] | None:
    """How deep the bow ``run`` (the loop's points between two walls' straight parts, in order) reaches from its own
    chord, as a share of the chord, how much of the strip to its deepest point it fills (`ROUND_FILL`) and how round it
    bends there (`ROUND_BEND`); None where it is no bow: it crosses its chord by more than a side may bow
    (`polygon_checks.BOW_SHARE` of the chord and twice the ``noise``), turns back along it by as much, is deepest at
    an end, or is too short to tell."""
    if len(run) < 5:
        return None
    chord = run[-1] - run[0]
    length = float(np.hypot(*chord))
    if length <= 0.0:
        return None
    unit = chord / length
    rel = run - run[0]
    along = rel @ unit
    across = rel[:, 0] * unit[1] - rel[:, 1] * unit[0]
    slack = BOW_SHARE * length + 2 * noise
    side = 1.0 if float(across.max()) >= -float(across.min()) else -1.0
    depth = side * across
    if float(depth.min()) < -slack or float((np.maximum.accumulate(along) - along).max()) > slack:
        return None
    deepest = float(depth.max())
    if deepest <= 0.0:
        return None
    order = np.argsort(along, kind="stable")
    t, h = np.clip(along[order], 0.0, length), np.clip(depth[order], 0.0, None)
    filled = float(np.sum((t[1:] - t[:-1]) * (h[1:] + h[:-1]) / 2)) / (length * deepest)
    apex = int(np.argmax(depth))
    if not 2 <= apex <= len(run) - 3:
        return None
    steps = np.hypot(*np.diff(run, axis=0).T)
    before, after = float(steps[:apex].sum()), float(steps[apex:].sum())
    # the length of path doing the bend's turning, over half the bow's (not the shorter part's: a cut corner's)
    roundness = sf.corner_roundness(run, [0, apex, len(run) - 1])[0] * min(before, after) / ((before + after) / 2)
    return deepest / length, filled, roundness


def _bowed_box(fit: PolygonFit, first: int, parts: list[Part], loop_area: float, noise: float) -> Box | None:
    """The box three consecutive sides of ``fit`` (from side ``first``; ``parts`` their straight parts) and the bow
    round the rest of the loop make, or None (see the module's docstring)."""
    pts, idx = fit.points, fit.indices
    ring = pts[:-1]
    m, k = len(ring), len(idx) - 1
    a, b, c = parts
    if max(_off_square(a[1], b[1]), _off_square(b[1], c[1])) > SQUARE_WALL:
        return None  # the side between the walls not square to both: a pentagon's, a trapezoid's leg
    start, end = idx[(first + 2) % k] + c[4], idx[first] + a[3]
    run = ring[np.arange(start, end + (m if end < start else 0) + 1) % m]
    roundness = corner_roundness_closed(fit)
    if max(roundness[(first + 1) % k], roundness[(first + 2) % k]) >= SHARP_CORNER:
        return None  # the walls' corners are not turned sharply: a round shape's, an octagon's
    bow = bow_of(run, noise)
    if bow is None or not SHALLOWEST < bow[0] <= MAX_BOW or bow[1] < ROUND_FILL or bow[2] < ROUND_BEND:
        return None
    chord = run[-1] - run[0]
    d = chord / float(np.hypot(*chord))
    q1, q2 = lines_meet(a[0], a[1], b[0], b[1]), lines_meet(b[0], b[1], c[0], c[1])
    q3, q0 = lines_meet(c[0], c[1], run[0], d), lines_meet(run[0], d, a[0], a[1])
    if q0 is None or q1 is None or q2 is None or q3 is None:
        return None
    quad = np.array([q0, q1, q2, q3])
    if box_geometry(quad) is None:
        return None
    sides = np.hypot(*(sg.succ(quad) - quad).T)
    if any(part[2] < STRAIGHT_SHARE * side for part, side in zip(parts, sides[:3], strict=True)):
        return None
    # the fourth side moved parallel to the chord, away from the second side or towards it, to keep the loop's area
    width = float(np.hypot(*(q3 - q0)))
    if width <= 0.0:
        return None
    normal = np.array([-d[1], d[0]])
    normal = normal if float((run[0] - b[0]) @ normal) > 0 else -normal
    base = run[0] + normal * (abs(loop_area) - abs(_area(quad))) / width
    q3, q0 = lines_meet(c[0], c[1], base, d), lines_meet(base, d, a[0], a[1])
    if q0 is None or q3 is None:
        return None
    quad = np.array([q0, q1, q2, q3])
    return box_geometry(quad)


def box_with_a_bowed_side(ranked: Recognition, polygons: list[Pending], loop: np.ndarray, raw: np.ndarray,
                          noise: float, diag: float) -> Recognition:
    """``ranked`` (a polygon of four sides or more) read as the box it is with one side bowed (`_bowed_box` of a fit
    of `SIDES` sides of ``loop``, within the stroke's bounds as any box: `ranking.BOX_MARGIN`; ``polygons``: every
    closed polygonal fit, ``raw``: the stroke's own points, ``diag`` their diagonal, ``noise`` the pen's in their
    units); ``ranked`` where none makes one. A quad is asked too (session 35): a sweep round a side and its corners
    pulls the best four-sided fit's fourth side askew, past a box's tolerance, while the fits of five or six sides
    still find the three walls and the bow (`penmodels.box_bows` side-swept through a noisy pen)."""
    if (ranked.kind != "polygon" or not isinstance(ranked.geometry, Polygon) or len(ranked.geometry.points) < 4
            or crossings(ranked.geometry.points) > 1):
        return ranked
    lo, hi = bounds(raw, noise, diag, BOX_MARGIN)
    loop_area = _area(loop)
    for pending in polygons:
        if pending.params // 2 not in SIDES:
            continue
        for fit in pending.fits:
            parts = straight_parts(fit, noise)
            k = len(parts)
            for first in range(k):
                three = [parts[(first + j) % k] for j in range(3)]
                if any(p is None for p in three):
                    continue
                box = _bowed_box(fit, first, [p for p in three if p is not None], loop_area, noise)
                if box is not None and inside(box, lo, hi):
                    return Recognition("box", ranked.confidence, box, ((str(ranked.kind), 1.0 - ranked.confidence),))
    return ranked
