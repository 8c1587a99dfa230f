"""Whether a polygonal fit's vertices are real corners, and flat ends for thin walls drawn as hairpins; no
ranking, no I/O.

A person's polygon turns by a real angle at every vertex, its sides are nearly straight, a short side between
two gentle turns is a rounded corner cut off, and an outline never doubles back along itself at one vertex:
the end of a thin wall (a basket's rim) is two corners a wall's thickness apart. `corners_of` says which of
these a fit passes; `split_hairpins` turns each doubled-back vertex into that flat end.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely

from physink_tui.scene.recognition import linalg_cores
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.polygon_fit import PolygonFit, run_lines
from physink_tui.scene.recognition.stroke_features import roundness_along, walk

MIN_CORNER_DEG = 35.0
"""Every vertex of a polyline or polygon turns the path at least this much (a bowed side is not two sides)."""
HAIRPIN_DEG = 150.0
HAIRPIN_GAP = 0.35
"""A closed outline that turns back by more than `HAIRPIN_DEG` at a vertex whose two sides then run closer than
`HAIRPIN_GAP` of their length is a thin wall's end (a star's tip, whose sides part, is a corner)."""
CHAMFER = 0.5
CHAMFER_OF_LONGER = 0.1
CHAMFER_TURN_DEG = 62.0
"""A closed outline's side shorter than ``CHAMFER`` of its shorter neighbour (or ``CHAMFER_OF_LONGER`` of the
longer), turning less than this at both ends and
about a right angle in all, is a corner rounded or cut back by a hurried hand, not a side."""
SPUR = 0.2
SPUR_TURN_DEG = 130.0
"""A closed outline's side shorter than ``SPUR`` of its longer neighbour, where the outline turns back by more than
``SPUR_TURN_DEG`` at one end and by less than a right angle at the other, is a hook (the pen doubling back where it
landed or lifted, then going on round), not a side: a box drawn with a hooked start is four-sided. The far ends of
its neighbours lie farther apart than the shorter neighbour is long (a thin box's end joins two long sides that run
side by side)."""
BOW_SHARE = 0.06
"""Most points of a side (four in five) lie within this share of its length (plus the pen's noise) of the
side's own line: a side bowed by more than about 15 % of its length is a curve, not a side."""


BOX_OVERLAP = 0.92
"""A polygon of five sides or more is a four-sided one drawn by a hurried hand when its best four sides overlap it by
this much (intersection over union): a hook, a bowed side or a cut corner changes a quad's area by a few per cent.
Above the 0.90 an outline must keep (issue 25): a notched slab, a T, an L or a golf tee keeps its corners."""


def crossings(vertices: Sequence[tuple[float, float]] | np.ndarray) -> int:
    """How many times a closed outline's sides cross one another (a star drawn in one stroke: five times; a box
    whose hook's spike crosses a side: once)."""
    a = np.asarray(vertices, dtype=float)
    b = sg.succ(a)
    i, j = _side_pairs(len(a))

    def side(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
        u, w = q - p, r - p
        turn: np.ndarray = np.sign(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        return turn

    apart_j = side(a[i], b[i], a[j]) * side(a[i], b[i], b[j]) < 0
    apart_i = side(a[j], b[j], a[i]) * side(a[j], b[j], b[i]) < 0
    return int(np.count_nonzero(apart_i & apart_j))


@functools.lru_cache(maxsize=64)
def _side_pairs(m: int) -> tuple[np.ndarray, np.ndarray]:
    """The pairs of an ``m``-sided outline's sides that `crossings` tests: not neighbours (the same for every outline of
    that many sides: made once, read only)."""
    i, j = np.triu_indices(m, 2)
    keep = ~((i == 0) & (j == m - 1))  # the last side meets the first at a vertex
    i, j = i[keep], j[keep]
    i.flags.writeable = False
    j.flags.writeable = False
    return i, j


def overlap(a: Sequence[tuple[float, float]] | np.ndarray, b: Sequence[tuple[float, float]] | np.ndarray) -> float:
    """Intersection over union of two closed outlines given by their vertices (0 when either has no area)."""
    pa, pb = shapely.make_valid(shapely.Polygon(a)), shapely.make_valid(shapely.Polygon(b))
    union = float(shapely.union(pa, pb).area)
    return float(shapely.intersection(pa, pb).area) / union if union > 0 else 0.0


OUTLINE_FAR = 0.08
OUTLINE_LEFT_OUT = 0.1
"""A box leaves out part of what was drawn when more than `OUTLINE_LEFT_OUT` of the closed loop's points lie farther
than `OUTLINE_FAR` of the loop's diagonal from the box's sides: the wide top of a golf tee drawn on its narrow stem is
not a box the size of the stem (people's and hurried boxes, thin ones included, leave out under 2 % of their
points; such a tee's wings are a quarter of its points)."""


def follows_the_outline(corners: Sequence[tuple[float, float]] | np.ndarray, drawn: np.ndarray) -> bool:
    """Whether the closed outline through ``corners`` (a box's) follows the whole loop ``drawn`` (`OUTLINE_FAR`,
    `OUTLINE_LEFT_OUT`)."""
    diag = float(np.hypot(*(drawn.max(axis=0) - drawn.min(axis=0))))
    a = np.asarray(corners, dtype=float)
    b = sg.succ(a)
    ab = b - a
    rel = drawn[:, None, :] - a[None, :, :]  # each point against each side
    u = np.clip((rel * ab).sum(axis=2) / np.maximum((ab * ab).sum(axis=1), 1e-300), 0.0, 1.0)
    gap = np.hypot(*(rel - u[:, :, None] * ab).transpose(2, 0, 1)).min(axis=1)
    return float(np.count_nonzero(gap > OUTLINE_FAR * diag)) <= OUTLINE_LEFT_OUT * len(drawn)


@dataclass(frozen=True, slots=True)
class Corners:
    """A fit whose vertices are corners; ``hairpins`` are the vertices (positions in the fit's vertex list)
    where a closed outline doubles back along itself."""

    hairpins: tuple[int, ...]
    vertices: np.ndarray
    """The fit's vertices (`PolygonFit.vertices`), kept."""


def _side_line(run: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    centre = run.mean(axis=0)
    return centre, linalg_cores.svd_vt(run - centre)


def corners_of(fit: PolygonFit, *, closed: bool, noise: float, min_corner_deg: float = MIN_CORNER_DEG,
               ) -> Corners | None:
    """The fit's verdict: None when a vertex is no real corner (turning less than ``min_corner_deg``, or a cut-off
    corner, a hook) or a side is bowed, else its hairpins."""
    pts, idx = fit.points, fit.indices
    corners = fit.vertices
    verts = np.concatenate([corners, corners[:1]]) if closed else corners
    sides = verts[1:] - verts[:-1]  # as np.diff, without its per-call overhead (every fit is judged)
    lengths = np.hypot(*sides.T)
    if (lengths == 0).any():
        return None
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    if closed:
        heading = np.concatenate([heading, heading[:1]])  # `np.append(heading, heading[0])`
    degrees = np.degrees(np.abs((heading[1:] - heading[:-1] + np.pi) % (2 * np.pi) - np.pi))
    if len(degrees) and float(degrees.min()) < min_corner_deg:
        return None
    hairpins: list[int] = []
    if closed:
        m = len(lengths)
        # the same numbers as Python floats: the walks below compare them one at a time
        side, turned = lengths.tolist(), degrees.tolist()
        for v in np.flatnonzero(degrees >= HAIRPIN_DEG).tolist():  # the turn at the end of side v: at vertex v + 1
            apart = float(np.hypot(*(verts[v] - verts[(v + 2) % m])))  # the far ends of the sides meeting there
            if apart < HAIRPIN_GAP * min(side[v], side[(v + 1) % m]):
                hairpins.append((v + 1) % m)
        for s in range(m):  # a short side between two gentle turns is a rounded corner cut off
            shorter = min(side[s - 1], side[(s + 1) % m])
            longer = max(side[s - 1], side[(s + 1) % m])
            short = side[s] < CHAMFER * shorter or side[s] < CHAMFER_OF_LONGER * longer
            if (short and max(turned[s - 1], turned[s]) < CHAMFER_TURN_DEG
                    and 60.0 <= turned[s - 1] + turned[s] <= 120.0):  # together, about a right angle's turn
                return None
            ends = sorted((turned[s - 1], turned[s]))
            if (side[s] < SPUR * longer and ends[1] > SPUR_TURN_DEG and ends[0] < 90.0
                    and float(np.hypot(*(corners[(s - 1) % m] - corners[(s + 2) % m]))) > shorter):
                return None  # a hook: the pen doubled back and went on round (a thin box's end is no hook)
    if _bowed(pts, np.asarray(idx), lengths, noise, fit.sums, closed):
        return None
    return Corners(tuple(hairpins), corners)


FEW_POINTS = 16
THIN_END = 0.2
"""A closed outline's side of fewer than `FEW_POINTS` points and under this share of both sides beside it (a thin
shape's end: a box 5 or more times as long as wide, `penmodels.box_habits` ``thin``) is judged for a bow without the
points at its two corners (`_bowed`): smoothing rounds a corner over its own point, and two such points are more than
the fifth of a short end's points a bow may leave out (TutorBoard's captured 8:1 rectangle #95: its 9-point ends
straight, both corner points 0.01-0.03 of its size off them, ends 0.10-0.13 of its long sides). A round end (a
stadium's) stays bowed without them; a side nearer its neighbours' length, or of more points, is judged whole (an egg's
blunt end cut as a pentagon's short side still bows: the captured ellipse #72; hcira shriyansnidhish s02's brace drawn
twice over, resampled to 200 points, has curled ends 0.24 of its sides that a box would square)."""


def _bowed(pts: np.ndarray, idx: np.ndarray, chords: np.ndarray, noise: float,
           sums: np.ndarray | None = None, closed: bool = False) -> bool:
    """Whether a side's points stray from the side's own line: four in five of them by more than `BOW_SHARE`
    of its length plus twice the noise (a hook is a few points; a short side's bow is only where its corners'
    points fell, so sides under 10 noise widths or 6 points are not judged, and a thin outline's end of few points
    without its corners' own: `THIN_END`)."""
    a, b = idx[:-1], idx[1:]
    judged = (b - a > 5) & (chords > 10 * noise)
    if not judged.any():
        return False
    few = judged & (b - a < FEW_POINTS)
    if closed and len(chords) >= 4 and few.any():
        beside = np.minimum(np.concatenate([chords[-1:], chords[:-1]]), sg.succ(chords))  # the shorter neighbour
        end = (few & (chords < THIN_END * beside))[judged]
        a, b, chords = a[judged] + end, b[judged] - end, chords[judged]
    else:
        a, b, chords = a[judged], b[judged], chords[judged]
    centres, dirs = run_lines(pts, a, b + 1, sums)
    sizes = b - a + 1
    run = np.repeat(np.arange(len(a)), sizes)
    point = np.concatenate([np.arange(lo, hi + 1) for lo, hi in zip(a, b, strict=True)])
    rel = pts[point] - centres[run]
    off = np.abs(rel[:, 0] * dirs[run, 1] - rel[:, 1] * dirs[run, 0])
    order = np.lexsort((off, run))  # by run, then by distance within it
    starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    q80 = off[order][starts + (0.8 * (sizes - 1)).astype(int)]
    return bool((q80 > BOW_SHARE * chords + 2 * noise).any())


def split_hairpins(fit: PolygonFit, corners: Corners) -> np.ndarray:
    """The fit's vertices with each hairpin replaced by a flat end: the point of the outline that reaches
    farthest along the wall, projected onto each of the wall's two sides."""
    pts, idx = fit.points, fit.indices
    verts, hairpins = list(corners.vertices), corners.hairpins
    m = len(idx) - 1
    out: list[np.ndarray] = []
    for v in range(m):
        if v not in hairpins:
            out.append(verts[v])
            continue
        before = pts[idx[v - 1]:idx[v] + 1] if v > 0 else pts[idx[m - 1]:idx[m] + 1]
        after = pts[idx[v]:idx[v + 1] + 1]
        (c1, vt1), (c2, vt2) = _side_line(before), _side_line(after)
        along = vt1[0] if float((before[-1] - before[0]) @ vt1[0]) > 0 else -vt1[0]  # towards the wall's end
        near = np.concatenate([before[-max(3, len(before) // 5):], after[:max(3, len(after) // 5)]])
        tip = near[int(np.argmax(near @ along))]
        out.append(c1 + float((tip - c1) @ vt1[0]) * vt1[0])
        out.append(c2 + float((tip - c2) @ vt2[0]) * vt2[0])
    return np.array(out)



SHARP_CORNER = 0.4
"""A closed loop's polygon fit turns at its corners, not round between them, when at three in four of its vertices
(`SHARP_SHARE`) the path does 80 % of the turning between the midpoints of the neighbouring sides within this share of
the shorter side (`stroke_features.corner_roundness`). A round loop spreads its turning evenly, so it needs about 0.8
of a side for that (a regular k-gon's sides through a circle: 0.8 whatever k; the pen models' ovals: 0.8 or more at
most vertices); a drawn corner turns within a tenth or two of its sides, a hurried hand's rounded corner (a radius up
to 0.15 of the side) within a third."""
SHARP_SHARE = 0.75
"""The share of a polygon's vertices that must be sharp (`SHARP_CORNER`): a corner in four may look round where the
hand overshot it and cut back (the hurried pen model's octagons: up to 2 of 8), while a lumpy circle's polygon has as
many round bends as sharp ones (people's lumpy circles in the design sets: 4 of 8 at 0.4 or more)."""
MAX_STEP_OF_SHORTEST_SIDE = 0.25
"""Corners are judged only on points at least four to the shortest side (half the stroke drawn in steps between its
own points no longer than this share of it, `typical_step`): a circle given as 8-25 points round it (a mouse, a
coarse event rate, events in bursts) is straight between them and as sharp at each as a polygon drawn."""
SHALLOW_CORNER_DEG = 15.0
"""A vertex of a closed polygon turning less than `MIN_CORNER_DEG` but at least this much is still a corner where the
turn is sharp (`SHARP_CORNER` at that vertex itself): an irregular octagon's flattest corners turn 15-35 degrees, and a
bowed side, which `MIN_CORNER_DEG` keeps from being read as two, spreads its turning along the side."""


def typical_step(drawn: np.ndarray) -> float:
    """The step between the stroke's points that half its length is drawn in steps at least as long as (a median
    weighted by length: events in bursts, a few points close together then a long gap, have short steps but draw
    the path in the gaps' long ones)."""
    steps = np.sort(sg.step_lengths(drawn))
    if not len(steps) or steps[-1] == 0.0:
        return math.inf
    covered = np.add.accumulate(steps[::-1])  # the longest first
    return float(steps[::-1][int(np.searchsorted(covered, covered[-1] / 2))])


def corner_roundness_closed(fit: PolygonFit) -> np.ndarray:
    """`stroke_features.corner_roundness` at each vertex of a closed fit, in the order of its vertices (measured once
    a fit, on a walk round the loop measured once for all fits of its points: `PolygonFit.memo`, `PolygonFit.walks`;
    read-only)."""
    found = fit.memo.get("roundness_closed")
    if found is not None:
        return found
    ring = fit.points[:-1]
    m, idx = len(ring), [int(i) % len(ring) for i in fit.indices[:-1]]
    walked = fit.walks.get("ring thrice")
    if walked is None:  # every vertex with both neighbours, across the loop's start
        walked = fit.walks["ring thrice"] = walk(np.concatenate([ring, ring, ring]))
    corners = [idx[-1], *(m + i for i in idx), 2 * m + idx[0]]
    found = np.asarray(roundness_along(walked, corners))
    found.flags.writeable = False
    fit.memo["roundness_closed"] = found
    return found


def dense_enough(fit: PolygonFit, step: float) -> bool:
    """Whether the stroke's own points are dense enough to tell a corner of the closed fit from a round bend
    (`MAX_STEP_OF_SHORTEST_SIDE`; ``step``: `typical_step` of the stroke's own points, in the fit's units)."""
    verts = fit.vertices
    sides = np.diff(np.concatenate([verts, verts[:1]]), axis=0)
    return step <= MAX_STEP_OF_SHORTEST_SIDE * float(np.hypot(*sides.T).min())


def sharp_corners(fit: PolygonFit, step: float) -> bool:
    """Whether the vertices of a closed fit are corners the pen turned at (`SHARP_CORNER`), on points dense enough to
    tell a corner from a round bend (`dense_enough`); any vertex turning less than `MIN_CORNER_DEG` must be sharp
    itself (`SHALLOW_CORNER_DEG`)."""
    if not dense_enough(fit, step):
        return False
    verts = fit.vertices
    sides = np.diff(np.concatenate([verts, verts[:1]]), axis=0)
    roundness = corner_roundness_closed(fit)
    heading = np.arctan2(sides[:, 1], sides[:, 0])
    before = np.concatenate([heading[-1:], heading[:-1]])  # `np.roll(heading, 1)`: the side before each vertex
    turns = np.degrees(np.abs((heading - before + np.pi) % (2 * np.pi) - np.pi))  # at each vertex
    shallow = turns < MIN_CORNER_DEG
    round_ones = int(np.count_nonzero(roundness >= SHARP_CORNER))
    return round_ones <= (1.0 - SHARP_SHARE) * len(roundness) and bool((roundness[shallow] < SHARP_CORNER).all())
