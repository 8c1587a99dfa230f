"""A loop read as a polygon or as round that is a box a hand rounded a corner or two of; geometry only, no I/O.

A box is four straight sides meeting near right angles. A hand that swings round a corner (a mouse, in a hurry) draws
the corner's two sides straight only up to where the bend begins; the polygonal fit then spends a fifth or sixth side
on the bend, or puts a vertex in its middle, skewing the quad past a box's corner tolerance, and a mouse's stepped
sides with a corner swung round may look like a lumpy circle. Here four sides of a fit (of four to `MOST_SIDES`
sides; any others taken for a corner's bend) are judged by their straight parts alone (the points within the
straightness `polygon_checks.BOW_SHARE` allows a side, plus twice the pen's noise), and the box is where those straight
parts' lines meet. It stands for the loop when:

- the four lines meet near right angles (`beautify.box_geometry`'s tolerance);
- each side runs straight on the drawn points for at least `STRAIGHT_SHARE` of its length (an octagon's sides, a
  house's roof do not);
- between two sides' straight parts the loop either turns sharply (a corner) or bows out of its own chord (a corner
  rounded off), at least once so; where it runs straight instead it is a side of its own (a pentagon's fifth, a
  hexagon's, a corner cut short), and the polygon's rules stand (a loop read round also needs two sharp corners);
- the loop leaves the box's outline only inside it, at no more than `MAX_CUT` corners, and the quad covers it nearly as
  drawn (`polygon_checks.BOX_OVERLAP`, intersection over union); a trapezoid or a rhombus is kept as `quads` keeps it.

A polygon of five sides or more whose best four sides cover it as nearly is that box too (`box_as_drawn`: a hook, a
bowed side or a cut corner).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from physink_tui.scene.recognition import quads
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import box_geometry, shape_points
from physink_tui.scene.recognition.candidates import Pending
from physink_tui.scene.recognition.polygon_checks import (
    BOW_SHARE,
    BOX_OVERLAP,
    SHARP_CORNER,
    corner_roundness_closed,
    crossings,
    overlap,
)
from physink_tui.scene.recognition.polygon_fit import PolygonFit
from physink_tui.scene.recognition.primitives import Box, Polygon, Recognition
from physink_tui.scene.recognition.ranking import BOX_MARGIN, bounds, inside, keeps_the_outline

STRAIGHT_SHARE = 0.5
"""Each side of the box runs straight on the drawn points for at least this share of its length (a regular octagon's
sides, inside the square round it, for 0.41 of it)."""
MAX_CUT = 2
"""A box may have this many corners rounded off; with more it is a rounded rectangle, which the ranking reads itself
(`tests/stroke_cases.py`), or a round shape."""
MOST_SIDES = 6
"""A fit of up to this many sides is judged (four kept, the others taken for a corner's bend): a bend takes one side of
a fit, or two."""
FEWEST_SIDES = 5
"""Only a polygon of this many sides or more is judged again: a four-sided one is a box or the quad drawn by
`quads`' rules (a trapezoid, a rhombus)."""
SHARP_IF_READ_ROUND = 2
"""A loop the ranking read as a circle or an ellipse is a box only with this many of its corners sharp: its corners are
what the ranking missed, so they must be there to see (a fit is judged only when as many of its vertices turn sharply,
`_sharp_vertices`, and the box only when as many of its corners are turned, not bowed)."""
OFF_SIDE_POINTS = 3
"""A corner counts as rounded where at least this many of the loop's points leave the box's outline there
(one or two are jitter)."""


def _line(run: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The total-least-squares line through ``run``: its centre and unit direction (the points' principal axis, in
    closed form for two dimensions)."""
    centre = run.mean(axis=0)
    rel = run - centre
    sxx, syy, sxy = float(rel[:, 0] @ rel[:, 0]), float(rel[:, 1] @ rel[:, 1]), float(rel[:, 0] @ rel[:, 1])
    angle = 0.5 * math.atan2(2.0 * sxy, sxx - syy)
    return centre, np.array([math.cos(angle), math.sin(angle)])


def _off(run: np.ndarray, centre: np.ndarray, direction: np.ndarray) -> np.ndarray:
    rel = run - centre
    return np.asarray(np.abs(rel[:, 0] * direction[1] - rel[:, 1] * direction[0]))


def _longest(mask: np.ndarray) -> tuple[int, int]:
    """The first and last index of the longest run of True in ``mask`` ((0, -1) where there is none)."""
    best, start, found = 0, 0, (0, -1)
    for i, on in enumerate([*mask.tolist(), False]):
        if on and (i == 0 or not mask[i - 1]):
            start = i
        if not on and i > 0 and mask[i - 1] and i - start > best:
            best, found = i - start, (start, i - 1)
    return found


Part = tuple[np.ndarray, np.ndarray, float, int, int]
"""A side's straight part: its line's centre and direction, its length along the line, and where it starts and ends
(indices into the side's points)."""


def straight_part(run: np.ndarray, noise: float) -> Part | None:
    """The line of a side's straight part (its centre and direction) and that part's length along it: the longest
    stretch of the side's points within `BOW_SHARE` of the side's chord (plus twice the noise) of a line fitted to
    them, found from the side's middle two thirds and refitted twice; None for a side of under six points."""
    k = len(run)
    if k < 6:
        return None
    a, b = k // 6, k - k // 6 - 1
    band = BOW_SHARE * float(np.hypot(*(run[-1] - run[0]))) + 2 * noise
    for _ in range(3):
        centre, direction = _line(run[a:b + 1])
        a, b = _longest(_off(run, centre, direction) <= band)
        if b - a < 2:
            return None
    part = run[a:b + 1]
    centre, direction = _line(part)
    along = (part - centre) @ direction
    return centre, direction, float(along.max() - along.min()), a, b


def lines_meet(p: np.ndarray, d: np.ndarray, q: np.ndarray, e: np.ndarray) -> np.ndarray | None:
    """Where the line through ``p`` along ``d`` meets the line through ``q`` along ``e`` (None where parallel)."""
    met = sg.line_meet(p, d, q, e)
    return None if met is None else met[0]


def _inside(points: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """Whether each point lies inside the convex outline through ``corners``."""
    a, b = corners, sg.succ(corners)
    cross = ((b - a)[None, :, 0] * (points[:, None, 1] - a[None, :, 1])
             - (b - a)[None, :, 1] * (points[:, None, 0] - a[None, :, 0]))
    return np.asarray((cross >= 0).all(axis=1) | (cross <= 0).all(axis=1))


def _gaps(points: np.ndarray, corners: np.ndarray) -> np.ndarray:
    """Each point's distance to each side of the closed outline through ``corners`` (points by sides)."""
    a, b = corners, sg.succ(corners)
    ab = b - a
    rel = points[:, None, :] - a[None, :, :]
    u = np.clip((rel * ab).sum(axis=2) / np.maximum((ab * ab).sum(axis=1), 1e-300), 0.0, 1.0)
    return np.asarray(np.hypot(*(rel - u[:, :, None] * ab).transpose(2, 0, 1)))


def _rounding(corner: np.ndarray, shorter: float, noise: float) -> bool | None:
    """What the loop's points between two sides' straight parts (``corner``, in order) are: None where they are a
    corner turned sharply (no longer than a side may bow: `BOW_SHARE` of the ``shorter`` side, plus twice the noise;
    the sides' straight parts run into it); True where they bow out of their own chord by more than that share of it
    (plus the noise), a corner rounded off; False where they run straight, a side of their own (a pentagon's fifth, a
    corner cut), or in one step (a device's sparse events: no bow to tell a rounding by)."""
    chord = corner[-1] - corner[0]
    length = float(np.hypot(*chord))
    if length <= BOW_SHARE * shorter + 2 * noise:
        return None
    if len(corner) < 3:
        return False
    rel = corner - corner[0]
    bow = float(np.abs(rel[:, 0] * chord[1] - rel[:, 1] * chord[0]).max()) / length
    return bow > BOW_SHARE * length + 2 * noise


def straight_parts(fit: PolygonFit, noise: float) -> list[Part | None]:
    """`straight_part` of each side of ``fit``, in order round the loop."""
    pts, idx = fit.points, fit.indices
    return [straight_part(pts[idx[i]:idx[i + 1] + 1], noise) for i in range(len(idx) - 1)]


def box_of(fit: PolygonFit, kept: tuple[int, ...], loop: np.ndarray, noise: float, sharp: int = 0,
           parts: list[Part | None] | None = None) -> Box | None:
    """The box that four sides of a closed polygonal ``fit`` of ``loop`` (``kept``: which, in order round the loop; any
    others are taken for a corner's bend) stand for, when their straight parts meet near right angles and the loop is
    that box with one to `MAX_CUT` corners rounded off and at least ``sharp`` turned sharply (see the module's
    docstring). ``parts``: the fit's `straight_parts`, when already found."""
    pts, idx = fit.points, fit.indices
    every = straight_parts(fit, noise) if parts is None else parts
    lines = [p for p in (every[i] for i in kept) if p is not None]
    if len(lines) != 4:
        return None
    corners = []
    for (p, d, *_), (q, e, *_) in zip(lines[-1:] + lines[:-1], lines, strict=True):
        corner = lines_meet(p, d, q, e)
        if corner is None:
            return None
        corners.append(corner)
    quad = np.array(corners)
    box = box_geometry(quad)
    if box is None:
        return None
    sides = np.hypot(*(sg.succ(quad) - quad).T)
    if any(part[2] < STRAIGHT_SHARE * side for part, side in zip(lines, sides, strict=True)):
        return None
    ring = pts[:-1]  # the loop from the fit's start, not repeated
    m = len(ring)
    rounded = []
    for j in range(4):  # the points between side j's straight part and the next one's, across the loop's start
        start, end = idx[kept[j]] + lines[j][4], idx[kept[(j + 1) % 4]] + lines[(j + 1) % 4][3]
        between = ring[np.arange(start, end + (m if end < start else 0) + 1) % m]
        rounded.append(_rounding(between, float(min(sides[j], sides[(j + 1) % 4])), noise))
    if False in rounded or True not in rounded or rounded.count(None) < sharp:
        return None  # a corner cut by a side of its own, or none rounded: the polygon's rules stand
    off = (_gaps(loop, quad) > BOW_SHARE * sides + 2 * noise).all(axis=1)  # as far from each side as it may bow
    if (off & ~_inside(loop, quad)).any():
        return None  # the loop strays outside the box: not a corner rounded off
    nearest = np.hypot(*(loop[:, None, :] - quad[None, :, :]).transpose(2, 0, 1)).argmin(axis=1)
    if int(np.count_nonzero(np.bincount(nearest[off], minlength=4) >= OFF_SIDE_POINTS)) > MAX_CUT:
        return None
    if overlap(quad, loop) < BOX_OVERLAP:
        return None  # a notch, a bulge: more than a corner rounded off
    squared = _box_on_sides(box, lines) or box
    if (quads.trapezoid(quad) or quads.rhombus(quad)) and overlap(shape_points(squared), quad) < quads.KEEPS:
        return None  # a trapezoid or a rhombus drawn, kept as drawn (`quads`)
    return squared


def _box_on_sides(box: Box, lines: list[Part]) -> Box | None:
    """``box`` (turned as the quad's sides run) placed where the four sides' straight parts lie, as
    `candidates._box_from_sides` places a box on a fit's sides; None where they do not pair up two by two."""
    c, s = math.cos(box.angle), math.sin(box.angle)
    axes = np.array([[c, s], [-s, c]])
    offsets: list[list[float]] = [[], []]  # sides along u (positions along v), sides along v (along u)
    for centre, direction, *_ in lines:
        along_u = abs(float(direction @ axes[0])) >= abs(float(direction @ axes[1]))
        offsets[0 if along_u else 1].append(float(centre @ axes[1 if along_u else 0]))
    if sorted(map(len, offsets)) != [2, 2]:
        return None
    (v0, v1), (u0, u1) = sorted(offsets[0]), sorted(offsets[1])
    centre = axes[0] * (u0 + u1) / 2 + axes[1] * (v0 + v1) / 2
    return Box((float(centre[0]), float(centre[1])), u1 - u0, v1 - v0, box.angle)


def _sharp_vertices(fit: PolygonFit) -> int:
    """How many of a closed fit's vertices the path turns at within `polygon_checks.SHARP_CORNER` of the shorter side
    (`polygon_checks.corner_roundness_closed`): a corner's turning, not a round bend's."""
    return int(np.count_nonzero(corner_roundness_closed(fit) < SHARP_CORNER))


def box_after_all(ranked: Recognition, polygons: list[Pending], loop: np.ndarray, raw: np.ndarray, noise: float,
                  diag: float) -> Recognition:
    """``ranked`` (a polygon of `FEWEST_SIDES` or more, or a circle or an ellipse) read as the box it is with a corner
    or two rounded off (`box_of` four sides of a fit of ``loop``, within the stroke's bounds as any box:
    `ranking.BOX_MARGIN`; ``polygons``: every closed polygonal fit, ``raw``: the stroke's own points, ``diag`` their
    diagonal, ``noise`` the pen's in their units); ``ranked`` where no fit makes one."""
    round_reading = ranked.kind in ("circle", "ellipse")
    if not round_reading and (ranked.kind != "polygon" or not isinstance(ranked.geometry, Polygon)
                              or len(ranked.geometry.points) < FEWEST_SIDES or crossings(ranked.geometry.points) > 1):
        return ranked
    lo, hi = bounds(raw, noise, diag, BOX_MARGIN)
    for pending in polygons:
        if not 8 <= pending.params <= 2 * MOST_SIDES:
            continue
        for fit in pending.fits:
            if round_reading and _sharp_vertices(fit) < SHARP_IF_READ_ROUND:
                continue  # a round loop turns evenly all round (about 0.8 of a side at every vertex): no corner to see
            parts = straight_parts(fit, noise)  # each side's once, for every four of them
            if sum(p is not None for p in parts) < 4:
                continue
            for kept in itertools.combinations(range(len(fit.indices) - 1), 4):
                box = box_of(fit, kept, loop, noise, SHARP_IF_READ_ROUND if round_reading else 0, parts)
                if box is not None and inside(box, lo, hi):
                    return Recognition("box", ranked.confidence, box, ((str(ranked.kind), 1.0 - ranked.confidence),))
    return ranked


def box_as_drawn(ranked: Recognition, polygons: list[Pending], raw: np.ndarray, noise: float, diag: float,
                 loop: np.ndarray) -> Recognition:
    """A polygon of five sides or more that its best four sides cover nearly as drawn (`polygon_checks.BOX_OVERLAP`,
    `quads.four_sides_cover`), when those four make a box that covers it as nearly (or their quad does): a box with a
    hook, a bowed side or a cut corner, read as the box."""
    if not isinstance(ranked.geometry, Polygon) or len(ranked.geometry.points) < 5:
        return ranked
    drawn = ranked.geometry.points
    if crossings(drawn) > 1:
        return ranked  # a star, or a mark crossing itself: no box (a hook's spike may cross a side once)
    fours = [p for p in polygons if p.params == 8 and any(quads.four_sides_cover(f, drawn) for f in p.fits)]
    # built only where a four-sided fit covers it (judging corners costs more)
    lo, hi = bounds(raw, noise, diag, BOX_MARGIN)
    for box in (c for p in fours for c in p.build() if c.kind == "box"):
        if (inside(box.geometry, lo, hi) and keeps_the_outline(box, loop)
                and box.fallback is not None and isinstance(box.fallback.geometry, Polygon)
                and max(overlap(box.fallback.geometry.points, drawn), overlap(shape_points(box.geometry), drawn))
                >= BOX_OVERLAP):
            return Recognition("box", ranked.confidence, box.geometry, (("polygon", 1.0 - ranked.confidence),))
    return ranked
