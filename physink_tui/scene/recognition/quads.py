"""Four-cornered loops: a box a hand drew askew, or a rhombus or trapezoid meant as drawn; geometry only, no I/O.

A quad within a box's corner tolerance (`beautify.box_geometry`, 24 degrees) is squared into a box unless squaring
it would change the outline drawn, the box overlapping it (intersection over union) by under `KEEPS` (the 0.90 an
outline must keep, issue 25), *and* it is a figure of its own:

- a **trapezoid**: one pair of sides parallel and both legs turned in towards each other (`LEG_INWARD`), so the
  parallel sides differ in length (squared into the box of its mean width, a trapezoid of parallel sides b > t
  overlaps it by (1 - r) / (1 + r), r = (b - t) / (4 (b + t)): under 0.90 once t < 0.65 b);
- a **rhombus** (a diamond): four equal sides (`RHOMBUS_SIDES`), opposite ones parallel, standing on a point (its
  long diagonal along the page, `ON_A_POINT`).

What a hurried hand does to a box stays a box whatever the overlap: it leans the upright sides (a shear: opposite
sides parallel, neighbours of unequal length, `tests/test_closed_marks.py`), or sends one wall askew (a right
trapezoid: one leg square to its neighbours, the other off by up to 20-30 degrees in people's rectangles: hcira jd4386
User04 rectangle03, sinarest1608 Subject5 rectangle6), or pulls a corner of a square drawn on its side (hat359 user1
rectangle01: equal sides, but its diagonals at 45 degrees to the page). Past the box's tolerance, a quad with one wall
askew by up to `WALL_ASKEW`, the wall opposite square and no two sides parallel, every side straight, is still a box
(`askew_box`); with its base and top parallel it is a right trapezoid, kept as drawn.

The quad is judged where its sides lie (`side_corners`: each side's line through its middle points, as
`candidates._box_from_sides` places a box), not on the fit's vertices, which a rounded or cut corner moves inside;
a quad kept has those corners.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np

from physink_tui.scene.recognition import linalg_cores
from physink_tui.scene.recognition.beautify import box_geometry
from physink_tui.scene.recognition.polygon_checks import BOX_OVERLAP, overlap
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Box

KEEPS = 0.90
"""A box squared from a quad must overlap the quad by this much (IoU) for a trapezoid or a rhombus to become one."""
PARALLEL = 6.0
"""Degrees: two sides within this of each other's direction are parallel, as a hand draws them."""
LEG_INWARD = 11.0
"""Degrees each leg of a trapezoid turns in from square to its parallel sides (at least). A quad with one leg square
is a box with the other wall askew (see above); people's rectangles drawn with both walls turned in, squared, overlap
under 0.90 with the lesser leg at 4.7-9.3 degrees (hcira pixelfac user01 rectangle1, jd4386 User04 rectangle07,
jonathanzhang53 s03 rectangle8, klarubbio s04 rectangle04), trapezoids drawn by the pen models at 13 or more."""
SHORT_LEG = 0.25
"""A leg this share of the base or shorter has no direction to judge (a thin box's ends are a few points long, as
`beautify.box_geometry` allows): such a quad is not taken for a trapezoid (nor would squaring a flat one move much)."""
RHOMBUS_SIDES = 0.95
"""A rhombus's shorter pair of sides is at least this share of the longer (a box leaning has unequal sides)."""
ON_A_POINT = 20.0
"""Degrees: a diamond stands on a point: its long diagonal within this of the page's vertical or horizontal."""


def _core(run: np.ndarray) -> np.ndarray:
    k = len(run)
    return run[k // 6: k - k // 6] if k >= 6 else run


def side_corners(points: np.ndarray, indices: tuple[int, ...]) -> np.ndarray | None:
    """The corners of a closed four-sided fit where its sides lie: consecutive sides' lines (each through the middle
    of its run of points, ``indices`` as `polygon_fit.PolygonFit`'s) intersected; None where two are parallel."""
    lines = []
    for a, b in itertools.pairwise(indices):
        run = _core(points[a:b + 1])
        centre = run.mean(axis=0)
        vt = linalg_cores.svd_vt(run - centre)
        lines.append((centre, vt[0]))
    if len(lines) != 4:
        return None
    corners = []
    for (p, d), (q, e) in zip(lines[-1:] + lines[:-1], lines, strict=True):
        det = float(e[0] * d[1] - d[0] * e[1])
        if abs(det) < 1e-9:
            return None
        t = float(e[0] * (q - p)[1] - (q - p)[0] * e[1]) / det
        corners.append(p + t * d)
    return np.array(corners)


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    """Degrees between the directions of two sides, 0-90 (a side's direction has no sign)."""
    cos = abs(float(a @ b)) / float(np.hypot(*a) * np.hypot(*b))
    return math.degrees(math.acos(min(1.0, cos)))


def _leg_inward(leg: np.ndarray, base: np.ndarray, into: np.ndarray) -> float:
    """Degrees by which ``leg`` (from a corner of ``base`` to the far parallel side; ``into``: towards the quad's
    inside along the base) turns in from square to the base; negative where it turns out."""
    unit = base / float(np.hypot(*base))
    along = float(leg @ unit) * (1.0 if float(into @ unit) > 0 else -1.0)
    across = abs(float(leg[0] * unit[1] - leg[1] * unit[0]))
    return math.degrees(math.atan2(along, across))


def trapezoid(corners: np.ndarray) -> bool:
    """One pair of opposite sides parallel, both other sides (the legs) turned in towards each other."""
    sides = [corners[(i + 1) % 4] - corners[i] for i in range(4)]
    for i in range(4):  # each side in turn the longer parallel one (the base)
        base, top, left, right = sides[i], sides[(i + 2) % 4], sides[(i + 3) % 4], sides[(i + 1) % 4]
        width = float(np.hypot(*base))
        if (_angle(base, top) > PARALLEL or float(np.hypot(*top)) >= width
                or min(float(np.hypot(*left)), float(np.hypot(*right))) <= SHORT_LEG * width):
            continue
        # the legs run from the base's ends to the top: the left one backwards (corner i to i - 1), the right forwards
        start, end = corners[i], corners[(i + 1) % 4]
        if min(_leg_inward(-left, base, end - start), _leg_inward(right, base, start - end)) >= LEG_INWARD:
            return True
    return False


def rhombus(corners: np.ndarray) -> bool:
    """Four equal sides, opposite ones parallel, standing on a point (its longer diagonal along the page)."""
    sides = [corners[(i + 1) % 4] - corners[i] for i in range(4)]
    if max(_angle(sides[0], sides[2]), _angle(sides[1], sides[3])) > PARALLEL:
        return False
    lengths = [float(np.hypot(*s)) for s in sides]
    pairs = (lengths[0] + lengths[2], lengths[1] + lengths[3])
    if min(pairs) < RHOMBUS_SIDES * max(pairs):
        return False
    long = max((corners[2] - corners[0], corners[3] - corners[1]), key=lambda d: float(np.hypot(*d)))
    return min(_angle(long, np.array([1.0, 0.0])), _angle(long, np.array([0.0, 1.0]))) <= ON_A_POINT


def convex(corners: np.ndarray) -> bool:
    """Whether a closed outline turns the same way at every corner (a quad crossing itself, a bow tie, does not)."""
    sides = np.diff(np.concatenate([corners, corners[:2]]), axis=0)
    turns = sides[:-1, 0] * sides[1:, 1] - sides[:-1, 1] * sides[1:, 0]
    return bool((turns > 0).all() or (turns < 0).all())


def kept_as_drawn(points: np.ndarray, indices: tuple[int, ...], squared: Sequence[tuple[float, float]]) -> bool:
    """Whether a closed four-sided fit within a box's tolerance is kept as the quad drawn: the box ``squared`` from
    it (its corners) overlaps it (where its sides meet, `side_corners`) by under `KEEPS` and it is a trapezoid or a
    rhombus."""
    corners = side_corners(points, indices)
    if corners is None or not convex(corners) or not (trapezoid(corners) or rhombus(corners)):
        return False  # the shapes asked first: the overlap costs more, and most boxes drawn are neither
    return overlap(squared, corners) < KEEPS



WALL_ASKEW = 34.0
"""Degrees: past a box's corner tolerance (`beautify.box_geometry`, 24), a quad with a wall this far from square is
still a box a hand drew with that wall askew when no two of its sides are parallel (`PARALLEL`: no trapezoid, no
parallelogram, no rhombus, which keep two sides parallel) and one wall stands square to both its neighbours
(`SQUARE_WALL`; a kite's square corners are opposite). People's rectangles drawn so read as quads: hcira jd4386 User06
rectangle, klarubbio s06 (a mouse), itt uniUbungsAccount, a wall 27-29 degrees out, no sides within 9 degrees of
parallel (issue 25, session 21). A right trapezoid (a square leg, the other leaning, its base and top parallel) is
the trapezoid drawn, as the pen models draw it (`tests/test_quads_kept.py`)."""
SQUARE_WALL = 12.0
"""Degrees: the wall opposite an askew one meets both its neighbours this near square (a hand's right angle)."""
STRAIGHT_WALLS = 0.03
"""Four in five of each side's points lie within this share of its chord of the side's line (its middle points'): an
askew wall is a straight one, while a side bent in its middle is two sides (a pentagon whose shallow corner no fit
of five sides passes, fitted with four: 0.056-0.059 of the chord in `benchmarks/bench_closed_shapes.py`'s irregular and
rounded pentagons; people's askew rectangles 0.006-0.022, the pen models' `wall-askew-by-hand` boxes under
0.013)."""


def _corner_angles(corners: np.ndarray) -> list[float]:
    """Each corner's angle in degrees, in order."""
    out = []
    for i in range(4):
        a, b = corners[i - 1] - corners[i], corners[(i + 1) % 4] - corners[i]
        cos = float(a @ b) / float(np.hypot(*a) * np.hypot(*b))
        out.append(math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    return out


def askew_box(points: np.ndarray, indices: tuple[int, ...]) -> Box | None:
    """The box a closed four-sided fit stands for when a wall of it is askew by up to `WALL_ASKEW`, the wall opposite
    square to its neighbours (`SQUARE_WALL`) and no two sides parallel, judged where its sides lie (`side_corners`);
    None for a quad of any other shape (a trapezoid, a rhombus, a parallelogram, a kite: the quad drawn)."""
    corners = side_corners(points, indices)
    if corners is None or not convex(corners):
        return None
    angles = _corner_angles(corners)
    off = [abs(a - 90.0) for a in angles]
    if max(off) > WALL_ASKEW or not any(off[i] <= SQUARE_WALL and off[(i + 1) % 4] <= SQUARE_WALL for i in range(4)):
        return None
    # opposite sides parallel where the corners along either side between them add up to a half turn
    if min(abs(angles[0] + angles[1] - 180.0), abs(angles[1] + angles[2] - 180.0)) <= PARALLEL:
        return None
    if not _straight_sides(points, indices):
        return None
    return box_geometry(corners, tolerance_deg=WALL_ASKEW)


def _straight_sides(points: np.ndarray, indices: tuple[int, ...]) -> bool:
    """Whether each side of a closed fit runs straight (`STRAIGHT_WALLS`) along the line through its middle points."""
    for a, b in itertools.pairwise(indices):
        run = points[a:b + 1]
        core = _core(run)
        centre = core.mean(axis=0)
        vt = linalg_cores.svd_vt(core - centre)
        rel = run - centre
        off = np.abs(rel[:, 0] * vt[0][1] - rel[:, 1] * vt[0][0])
        if float(np.quantile(off, 0.8)) > STRAIGHT_WALLS * float(np.hypot(*(run[-1] - run[0]))):
            return False
    return True


def four_sides_cover(fit: PolygonFit, drawn: Sequence[tuple[float, float]]) -> bool:
    """Whether a closed four-sided fit covers the polygon ``drawn`` nearly as drawn (`BOX_OVERLAP`): its vertices'
    quad does, or the quad where its sides meet (a corner cut by a short fifth side lies on those sides' lines, not
    on the fit's vertex across the cut: hcira jonathanzhang53 s04 rectangle7, 0.88 by its vertices, 0.97 so)."""
    if overlap(fit.vertices, drawn) >= BOX_OVERLAP:
        return True
    corners = side_corners(fit.points, fit.indices)
    return corners is not None and convex(corners) and overlap(corners, drawn) >= BOX_OVERLAP
