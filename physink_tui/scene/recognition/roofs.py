"""A loop read as a box that is a pentagon drawn on a box: one side a roof or a swallowtail's notch; geometry only.

A box's four corners with a fifth corner on one side, out of the box (a house's roof, a home plate, a pencil's tip)
or into it (a swallowtail flag, a notch), is a pentagon to any reader once that corner stands clear of the side: the
side's two halves run straight and meet at one sharp turn, where a hurried hand's bow turns gradually along the whole
side (`bowed_sides`). A roof on a long box's short side changes the box's area by a few per cent, so the box rules
(`rounded_corners.box_as_drawn`: overlap 0.92) and the ranker take it for a box; this module gives the pentagon back.

The loop is that pentagon when the best fit of five sides has a vertex (the ridge) whose four others make a box with
corners within `quads.SQUARE_WALL` of square (`beautify.box_geometry`), standing `RIDGE_LOW` to `RIDGE_HIGH` of the
chord between its neighbours off that chord and `RIDGE_PLACE` or more from either end of it, turning at most
`RIDGE_TURN` with each half leaning off the box's side by `RIDGE_LEAN` of that turn (a half running on along the side
makes a cut corner of the other), drawn as sharply as the box's corners beside it, none swung round
(`DRAWN_CORNER`), and the loop between its neighbours one bend across their chord that turns at the ridge, not
all along (`bowed_sides.bow_of` under `bowed_sides.ROUND_BEND`). A box whose side a regripping hand kinked a little
(`box_habits` side-kinked: 4-9 % of the side, a fifth corner of 8-20 degrees) stays a box, and so does a bowed one.
"""

from __future__ import annotations

import math

import numpy as np

from physink_tui.scene.recognition.beautify import box_geometry
from physink_tui.scene.recognition.bowed_sides import ROUND_BEND, bow_of
from physink_tui.scene.recognition.candidates import Pending
from physink_tui.scene.recognition.polygon_checks import corner_roundness_closed
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Polygon, Recognition
from physink_tui.scene.recognition.quads import SQUARE_WALL

RIDGE_LOW = 0.11
"""A ridge stands more than this share of its chord off it (its chord: the side of the box it stands on): a roof 12 %
of the side high leans each half 13-14 degrees off the side's line and turns 27 degrees or more at its ridge, as a
drawn corner; a regripping hand's kink (`box_habits` side-kinked, 4-9 %: 8-20 degrees) is a box's side."""
DRAWN_CORNER = 0.3
"""The ridge and the box's two corners beside it are drawn, not swung round: the path does 80 % of their turning within
this share of the shorter side beside them (`polygon_checks.corner_roundness_closed`; a drawn corner a tenth or two, a
hurried hand's rounded one up to a third, `polygon_checks.SHARP_CORNER` 0.4 taking both). A hand swinging a bowed side
round with its corners (`box_bows` bow-swung, 0.15-0.3 of the shorter side) leaves them at 0.36-0.75, and a hurried
bow drawn lopsided its middle at 0.37-0.40 (`box_bows` bowed-in)."""
RIDGE_PLACE = 0.2
"""A ridge stands at least this share of its chord from either end (a roof's halves both sides of the box's side: a
vertex next to a corner is a hook or a spur there)."""
RIDGE_LEAN = 0.2
"""Each half of a roof leans off the box's side by at least this share of the ridge's turn (a ridge 0.2 along its
chord: 0.26 of it; 0.35 along: 0.35): a half running on along the side is the side, and the other half a corner cut."""
RIDGE_TURN = 65.0
"""A ridge turns at most this many degrees (a roof 25 % of its side high: 53-57; a box's own corner 90)."""
RIDGE_HIGH = 0.4
"""A ridge stands at most this share of its chord off it: further, the corner next to a cut corner (a box's own
right angle, 0.3-0.5 of the chord between its neighbours) would look like one (its four others are no box anyway)."""


def _turn(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> float:
    """Degrees the outline turns at ``b`` between ``a`` and ``c``."""
    d, e = b - a, c - b
    return abs(math.degrees(math.atan2(float(d[0] * e[1] - d[1] * e[0]), float(d @ e))))


def ridge_of(fit: PolygonFit, noise: float) -> tuple[int, float] | None:
    """The vertex of a closed five-sided ``fit`` that stands as a roof (or a notch) on a box made by the other four,
    and its height over the chord between its neighbours (a share of that chord); None where no vertex does (see the
    module's docstring)."""
    ring = fit.points[:-1]
    m = len(ring)
    idx = [int(i) % m for i in fit.indices[:-1]]
    verts = np.asarray(fit.vertices)
    k = len(idx)
    if k != 5 or len(verts) < k:
        return None
    for i in range(k):
        before, ridge, after = verts[(i - 1) % k], verts[i], verts[(i + 1) % k]
        turn = _turn(before, ridge, after)
        if turn > RIDGE_TURN:
            continue  # a box's own corner (beside a cut, or at a bow's end)
        # how far each half leans off the box's side (square to the wall it meets): a roof's both, by a share
        leans = (abs(90.0 - _turn(verts[(i - 2) % k], before, ridge)),
                 abs(90.0 - _turn(ridge, after, verts[(i + 2) % k])))
        if min(leans) < RIDGE_LEAN * turn:
            continue  # one half runs on along the side: a corner cut beside it
        chord = after - before
        length = float(np.hypot(*chord))
        if length <= 0.0:
            continue
        rel = ridge - before
        along = float(rel @ chord) / length ** 2
        height = abs(float(chord[0] * rel[1] - chord[1] * rel[0])) / length ** 2
        if not (RIDGE_PLACE <= along <= 1.0 - RIDGE_PLACE and RIDGE_LOW < height <= RIDGE_HIGH):
            continue
        if box_geometry(np.array([verts[(i + j) % k] for j in range(1, k)]), SQUARE_WALL) is None:
            continue
        roundness = corner_roundness_closed(fit)  # measured once a fit, and only for a ridge standing so far
        if max(roundness[(i - 1) % k], roundness[i], roundness[(i + 1) % k]) >= DRAWN_CORNER:
            continue  # a bow's vertex, or the box's corners beside it swung round with it: no roof drawn
        start, end = idx[(i - 1) % k], idx[(i + 1) % k]
        bend = bow_of(ring[np.arange(start, end + (m if end < start else 0) + 1) % m], noise)
        if bend is None or bend[2] >= ROUND_BEND:
            continue  # not one bend across the chord, or a round one
        return i, height
    return None


def pentagon_on_a_box(ranked: Recognition, polygons: list[Pending], noise: float) -> Recognition:
    """``ranked`` (a box) read as the pentagon drawn where the loop's best five-sided fit has a roof or a notch on a
    box (`ridge_of`; ``polygons``: every closed polygonal fit, ``noise`` the pen's in their units): its vertices, the
    ridge among them (the ridge may turn less than `polygon_checks.MIN_CORNER_DEG`, which a fit's corners are otherwise
    asked to); ``ranked`` otherwise."""
    if ranked.kind != "box":
        return ranked
    fit = next((p.fits[0] for p in polygons if p.params == 10 and p.fits), None)
    if fit is None or ridge_of(fit, noise) is None:
        return ranked
    verts = np.asarray(fit.vertices)[:5]
    return Recognition("polygon", ranked.confidence, Polygon(tuple((float(x), float(y)) for x, y in verts)),
                       (("box", 1.0 - ranked.confidence),))
