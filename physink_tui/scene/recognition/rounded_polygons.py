"""A closed loop read round, or as a polygon of another number of sides, that is a polygon of 3-8 sides whose corners
a hand rounded: its turning gathered at short bends, evenly shared among them, with straight runs between."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from physink_tui.scene.recognition.polygon_checks import overlap
from physink_tui.scene.recognition.primitives import Polygon, Recognition
from physink_tui.scene.recognition.shape_corners import (
    STEPS,
    STRAIGHT_STEP_DEG,
    Bend,
    bend_runs,
    drawn_through,
)
from physink_tui.scene.recognition.stroke_geometry import resample

BEND_STEP_DEG = 4.0
"""A bend runs on over steps turning this much or more (a corner's last step of a few degrees is still its own: an
octagon's corner of 23 degrees turning 18 and 5); a step turning less, or under `shape_corners.STRAIGHT_STEP_DEG`
for the straight share, is straight."""
CORNER_LEAST_DEG = 15.0
"""A bend turning this much or more may be a corner (each must also turn `LEAST_TURN` of a regular polygon's)."""
FEWEST, MOST = 3, 8
"""A rounded polygon has this many corners or more, and at most this many: a loop of more short bends is round."""
AT_CORNERS = 0.75
"""The loop does this share of its turning (or more) at its corners (short bends, `shape_corners.corner_bends`): a
polygon drawn straight between rounded corners turns only there, a round shape all along."""
STRAIGHT_SHARE = 0.45
"""...and runs straight (`shape_corners.STRAIGHT_STEP_DEG`) for this share of its steps or more (as
`shape_corners.STRAIGHT_SHARE` asks of one left open): at 0.4 a person's lumpy circle (hcira klarubbio/s02 circle10,
0.425) read as a pentagon and a Quick, Draw! octagon as a heptagon (0.425)."""
LEAST_TURN = 0.55
"""...and each corner turns at least this share of what a regular polygon's of as many corners does (360 / n degrees):
a lumpy circle's or an egg's bends are uneven."""
SHALLOW_TURN = 0.33
"""...but in a loop read round one corner of five or more may turn as little as this share of it where more than half
the loop's steps run straight (`STRAIGHTER_SHARE`): an irregular octagon drawn in a hurry turns 15-25 degrees at a
corner (the pen models' swept octagons, `tests/penmodels/many_sided`, read round with a weakest corner of 0.31-0.52 of a
regular one's and straight shares of 0.47-0.62), a lumpy circle's bends are spread round it (people's circles in the
design and fourth groups whose bends fail `LEAST_TURN` alone run straight over at most 0.50 of their steps; the two at
0.50, hcira jonathanzhang53/s01 circle5 and itt marcel-moz circle08, turn 0.29 and 0.38 at their weakest bend). A
polygon read with another number of sides keeps its reading (issue 25, session 35: with it, octagons with one corner
rounded read with eight sides lost a shallow corner and read as heptagons)."""
STRAIGHTER_SHARE = 0.525
MOST_TURN = 1.6
"""...and at most this share of it: two corners run together into one bend (an octagon's, whose straight run between
them was rounded away) are not one corner of a polygon of fewer sides."""
LONGEST_BEND = 0.8
"""A bend is a corner when it runs over at most this share of a regular polygon's side of as many corners (plus a
step), and over at most `LONGEST_STEPS`: a hand rounds a corner over up to a third or so of each side meeting there
(a triangle's over up to 10 steps of 40, an octagon's 4); a round shape's turning runs on round it. The bend's run
is counted from its first step to its last turning `shape_corners.STRAIGHT_STEP_DEG` or more (`_core_span`): where a
rounded corner leaves the sides, a step turning 4-6 degrees falls in it or not as the points fall (issue 25, session
33: a heptagon's corner rounded wide, 5, 13, 15, 15, 13, 6, was 6 steps one way and 5 the other)."""
LONGEST_STEPS = 10
"""(9 until session 35: a triangle rounded over 0.4 of each side, drawn by the hurried hand, bent over 8, 9 and 10
steps and read round; no loop of the design and fourth sources reads otherwise at 10.)"""
COVERS = 0.88
"""...and the polygon where the straight runs' lines meet covers the loop this well (intersection over union) or better:
a corner rounded over up to a third of each side leaves out a few hundredths."""
EVEN_AT, EVEN_LEAST, EVEN_MOST = 0.9, 0.75, 1.2
"""Corners evenly shared (issue 25, session 35): a loop doing this share of its turning or more at its corners, each
turning between these shares of a regular polygon's corner, may run straight for as little as `EVEN_STRAIGHT_SHARE`
and be covered as little as `EVEN_COVERS`: a triangle rounded over up to 0.42 of each side runs straight for 0.40-0.45
of its steps and fills 0.79-0.83 of the triangle its sides make, and read round (`benchmarks/bench_rounded_polygons.py`,
tune seeds). Of the design and fourth sources' round shapes (1,164 loops) with three corners, the nearest are hcira
klarubbio/s07 circle05 (0.88 of the turning at its corners, the least 0.72 of an even one, covered 0.76) and a Quick,
Draw! circle (tutorboard seed90210 #94: 0.89, 0.70, 0.78); of five, hcira jd4386/User01 circle10 (0.96, 0.78, 1.20)."""
EVEN_CORNERS = (3,)
"""...of three corners only: a circle whose radius wanders by its 5th or 6th harmonic (`tests/penmodels/rounded_boxes`'
wobbly family, 4-10 % from the mean) turns as evenly at five or six bends, as straight between them (0.30-0.42), as a
pentagon or hexagon rounded over a third of each side, and read as one (27 of 480 on seeds 30-149); none of three."""
EVEN_STRAIGHT_SHARE = 0.3
EVEN_COVERS = 0.78


def _core_span(b: Bend, th: np.ndarray) -> int:
    """How many steps the bend ``b`` of the cyclic turning ``th`` runs over between its first and last turning
    `shape_corners.STRAIGHT_STEP_DEG` or more (one where none does)."""
    m = len(th)
    steps = np.abs(th[(b.first + np.arange((b.last - b.first) % m + 1)) % m]) >= STRAIGHT_STEP_DEG
    core = np.flatnonzero(steps)
    return int(core[-1] - core[0] + 1) if len(core) else 1


SEAM_POINTS = 2
"""A bend turning against the loop's way at no more than this many points either side of its seam (`loop_turning`) is
not a corner but a hook where the pen landed or lifted (its turning still counted in the loop's): a hand on a mouse
drawing a pentagon from a sharp corner turned 20 degrees back before it (issue 25, session 33)."""


def _cyclic_bends(th: np.ndarray) -> list[Bend]:
    """The bends of a closed loop's turning ``th`` (degrees, one a step, cyclic): runs of steps turning
    `BEND_STEP_DEG` or more the same way, their steps counted from the straightest step (which starts the scan)."""
    start = int(np.argmin(np.abs(th)))
    n = len(th)
    return [Bend((b.first + start) % n, (b.last + start) % n, b.degrees)
            for b in bend_runs(np.roll(th, -start).tolist(), BEND_STEP_DEG)]


def loop_turning(loop: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A closed loop resampled to `STEPS` points, the heading (radians) of each step and the turn at the end of each
    (degrees, cyclic). The points sit half a step either side of the middle of the loop's seam and on round, so one
    step runs over the seam, the same drawn either way. The seam is where the loop was closed: the chord from its end
    back to its start, across however the pen landed and lifted (a hook, an overshoot cut beside the first side); that
    step is given the heading halfway between its neighbours', the turn over the seam shared evenly between its two
    ends. Its own heading, at right angles to the path where the ends were cut side by side, made a zigzag of two bends
    turning each way (issue 25, session 33: a Quick, Draw! octagon's -87 and +120 degrees; a triangle drawn from a
    corner, its landing hook's 22 and -126), and points placed from the loop's start fell otherwise drawn the other
    way."""
    seam = (loop[0] + loop[-1]) / 2
    pts = resample(np.vstack([seam, loop, seam]), 2 * STEPS + 1)[1::2]
    d = np.roll(pts, -1, axis=0) - pts
    heading = np.arctan2(d[:, 1], d[:, 0])
    heading[-1] = heading[-2] + ((heading[0] - heading[-2] + math.pi) % (2 * math.pi) - math.pi) / 2
    th = np.degrees((np.roll(heading, -1) - heading + math.pi) % (2 * math.pi) - math.pi)
    return pts, heading, th


def _meet(p: np.ndarray, u: np.ndarray, q: np.ndarray, v: np.ndarray) -> np.ndarray | None:
    """Where the line through ``p`` along ``u`` meets the line through ``q`` along ``v`` (None when nearly parallel)."""
    cross = float(u[0] * v[1] - u[1] * v[0])
    if abs(cross) < 0.05:
        return None
    d = q - p
    return np.asarray(p + u * float(d[0] * v[1] - d[1] * v[0]) / cross)


def _even_enough(turns: np.ndarray, straight: float, shallow: bool) -> bool:
    """Whether the corners turning ``turns`` (degrees, unsigned) share a loop's turning evenly enough for a polygon
    (`LEAST_TURN`; one of five or more down to `SHALLOW_TURN` where the ``straight`` share of the loop's steps is
    `STRAIGHTER_SHARE` or more, where ``shallow``)."""
    regular = 360.0 / len(turns)
    weakest = np.sort(turns)
    if float(weakest[0]) >= LEAST_TURN * regular:
        return True
    return (shallow and len(turns) >= 5 and straight >= STRAIGHTER_SHARE and float(weakest[0]) >= SHALLOW_TURN * regular
            and float(weakest[1]) >= LEAST_TURN * regular)


def rounded_corners(loop: np.ndarray, drawn: np.ndarray | None = None, shallow: bool = False) -> np.ndarray | None:
    """The vertices of the polygon ``loop`` (closed) was drawn as with its corners rounded, or None: `FEWEST` to `MOST`
    short bends (at most `shape_corners.BEND_STEPS` steps of `shape_corners.STEPS` round, each turning
    `shape_corners.CORNER_DEG` or more, `LEAST_TURN` of a regular polygon's corner, all the same way) doing `AT_CORNERS`
    of the turning, straight runs (`STRAIGHT_SHARE`) between them; each vertex where the directions into and out of a
    bend meet, the polygon covering the loop (`COVERS`); corners evenly shared (`EVEN_AT`) ask less of the straight
    runs and the cover. ``drawn``, the stroke's own points where given, must hold a
    point between each two corners clear of both (`shape_corners.drawn_through`): a round loop sampled by a few events
    turns at each. Where ``shallow``, one corner of five or more may turn down to `SHALLOW_TURN` (`_even_enough`)."""
    if len(loop) < 8:
        return None
    pts, heading, th = loop_turning(loop)
    total = float(np.abs(th).sum())
    found = _cyclic_bends(th)
    m = len(th)
    way = float(th.sum()) > 0
    seam = {(m - 1 + j) % m for j in range(-SEAM_POINTS, SEAM_POINTS)}  # the turns at the points either side of it
    corners = [b for b in found if (b.last - b.first) % m < LONGEST_STEPS and abs(b.degrees) >= CORNER_LEAST_DEG
               and not ((b.degrees > 0) != way and {b.first, b.last} <= seam)]
    n = len(corners)
    if not FEWEST <= n <= MOST or total == 0.0 or len({b.degrees > 0 for b in corners}) != 1:
        return None
    turns = np.abs([b.degrees for b in corners])
    spans = np.array([_core_span(b, th) for b in corners])
    straight = float(np.mean(np.abs(th) < STRAIGHT_STEP_DEG))
    even = (n in EVEN_CORNERS and float(turns.sum()) >= EVEN_AT * total
            and float(turns.min()) >= EVEN_LEAST * 360.0 / n and float(turns.max()) <= EVEN_MOST * 360.0 / n)
    if (float(turns.sum()) < AT_CORNERS * total or straight < (EVEN_STRAIGHT_SHARE if even else STRAIGHT_SHARE)
            or not _even_enough(turns, straight, shallow) or float(turns.max()) > MOST_TURN * 360.0 / n
            or int(spans.max()) > LONGEST_BEND * STEPS / n + 1
            or abs(float(th.sum()) - math.copysign(360.0, th.sum())) > 30):
        return None
    vertices = []
    for b in corners:
        before, after = b.first, (b.last + 1) % m  # the steps into and out of the bend
        u = np.array([math.cos(heading[before]), math.sin(heading[before])])
        v = np.array([math.cos(heading[after]), math.sin(heading[after])])
        at = _meet(pts[before], u, pts[after], v)
        if at is None:
            return None
        vertices.append(at)
    poly = np.array(vertices)
    if overlap(poly, loop) < (EVEN_COVERS if even else COVERS):
        return None
    if drawn is not None:
        middles = np.array([(pts[(b.first + 1 + (b.last - b.first) % m // 2) % m]
                             + pts[(b.first + 1 + ((b.last - b.first) % m + 1) // 2) % m]) / 2 for b in corners])
        if not drawn_through(np.vstack([middles, middles[:1]]), drawn):
            return None
    return poly


FEWER_KEPT_FROM = 5
"""A polygon read with two or more vertices more than the rounded corners found keeps its vertices where those are this
many or more: the bends ran two corners together, or missed a shallow one (issue 25, session 33: an octagon drawn
through a coarse device, two corners turning 33 and 24 degrees run together over four steps of under 5, read as a
hexagon); a triangle's rounded corners, on which a polygon fit spends a vertex at each end, are still read as three."""


OtherWay = Callable[[], tuple[bool, np.ndarray]]
"""The stroke's loop as `closed_loops.closed_loop` cuts it drawn from its other end (closed, loop; no ellipse)."""


def polygon_rounded(ranked: Recognition, loop: np.ndarray, raw: np.ndarray,
                    other_way: OtherWay | None = None) -> Recognition:
    """``ranked`` (a circle or an ellipse, or a polygon of another number of vertices) read as the polygon of 3 or 5-8
    sides ``loop`` was drawn as with its corners rounded (`rounded_corners`); ``ranked`` otherwise (four corners are
    a box's or a quad's, which `rounded_corners` and `rounded_boxes` judge). Where ``other_way`` is given, the loop cut
    from the stroke drawn the other way round (its ends overlapping, the part kept is the other end's; the stroke left
    open, ``loop`` reversed) must be that polygon too: a reading does not hang on where the pen started (issue 25,
    session 33: a Quick, Draw! circle, tutorboard seed170731 #69, kept its landing hook as drawn and read round, and
    read as a hexagon drawn from its other end). It is asked only where the reading would change."""
    if ranked.kind not in ("circle", "ellipse", "polygon"):
        return ranked
    shallow = ranked.kind != "polygon"  # a polygon read with other sides keeps them unless every corner is clear
    vertices = rounded_corners(loop, raw, shallow)
    if vertices is None or len(vertices) == 4:
        return ranked
    if isinstance(ranked.geometry, Polygon) and (len(ranked.geometry.points) == len(vertices) or (
            len(vertices) >= FEWER_KEPT_FROM and len(ranked.geometry.points) >= len(vertices) + 2)):
        return ranked
    if other_way is not None:
        closed, back = other_way()
        back_vertices = rounded_corners(back if closed else loop[::-1], raw, shallow)
        if back_vertices is None or len(back_vertices) != len(vertices):
            return ranked
    points = tuple((float(x), float(y)) for x, y in vertices)
    return Recognition("polygon", ranked.confidence, Polygon(points), ((str(ranked.kind), 1.0 - ranked.confidence),))
