"""The closed shapes `bench_closed_shapes` draws with the pen models, each from its own seeded generator (sizes 40-400
px across, turned, stretched): regular and irregular polygons, polygons with every corner rounded, quads, rounded and
cut boxes, stars, crossed triangles, circles, ovals, eggs and lumpy circles; no drawing, no reading."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.shapes import Curve as PenCurve
from penmodels.shapes import Outline, Oval, Shape
from penmodels.shapes import Path as PenPath

Point = tuple[float, float]
CENTRE = (800.0, 500.0)


def _turned(points: list[Point], angle: float) -> tuple[Point, ...]:
    c, s = math.cos(angle), math.sin(angle)
    return tuple((CENTRE[0] + x * c - y * s, CENTRE[1] + x * s + y * c) for x, y in points)


def _fit_size(points: list[Point], size: float) -> list[Point]:
    """``points`` scaled so the larger side of their bounds is ``size`` px, centred on the origin."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    k = size / max(max(xs) - min(xs), max(ys) - min(ys))
    return [((x - cx) * k, (y - cy) * k) for x, y in points]


def _convex(points: list[Point]) -> bool:
    signs = set()
    n = len(points)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = points[i], points[(i + 1) % n], points[(i + 2) % n]
        signs.add((bx - ax) * (cy - by) - (by - ay) * (cx - bx) > 0)
    return len(signs) == 1


def regular(sides: int) -> Callable[[random.Random], Shape]:
    def make(rng: random.Random) -> Shape:
        phase = rng.uniform(0, 2 * math.pi)
        pts = [(math.cos(phase + 2 * math.pi * k / sides), math.sin(phase + 2 * math.pi * k / sides))
               for k in range(sides)]
        return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), 0.0))
    return make


def irregular(sides: int) -> Callable[[random.Random], Shape]:
    """A convex polygon: corners at jittered angles (up to 0.3 of a step) and radii (0.8-1.2), stretched 0.7-1."""
    def make(rng: random.Random) -> Shape:
        step = 2 * math.pi / sides
        while True:
            phase = rng.uniform(0, 2 * math.pi)
            stretch = rng.uniform(0.7, 1.0)
            pts = [(r * math.cos(a), stretch * r * math.sin(a))
                   for a, r in ((phase + step * (k + rng.uniform(-0.3, 0.3)), rng.uniform(0.8, 1.2))
                                for k in range(sides))]
            if _convex(pts):
                return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(0, math.pi)))
    return make


def rhombus(rng: random.Random) -> Shape:
    """A diamond standing on a point: diagonals 1 : 1-2 (either way up), turned up to 0.25 rad."""
    ratio = rng.uniform(1.0, 2.0)
    w, h = (1.0, ratio) if rng.random() < 0.5 else (ratio, 1.0)
    pts = [(0.0, -h), (w, 0.0), (0.0, h), (-w, 0.0)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.25, 0.25)))


def parallelogram(rng: random.Random) -> Shape:
    """Sides of aspect 1-2.5, the upright ones slanted 25-45 degrees (past a box's tolerance), turned."""
    w, h = rng.uniform(1.0, 2.5), 1.0
    shift = h * math.tan(math.radians(rng.uniform(25, 45))) * rng.choice((-1, 1))
    pts = [(0.0, 0.0), (w, 0.0), (w + shift, h), (shift, h)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def trapezoid(rng: random.Random) -> Shape:
    """A base 1-2 times as wide as tall, the top 0.35-0.75 of it, centred or slid a little."""
    base, h = rng.uniform(1.0, 2.0), 1.0
    top = rng.uniform(0.35, 0.75) * base
    off = (base - top) / 2 + rng.uniform(-0.15, 0.15) * base
    pts = [(0.0, h), (base, h), (off + top, 0.0), (off, 0.0)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def rounded_rectangle(rng: random.Random) -> Shape:
    """Aspect 1-2.5, corners rounded with a radius 0.1-0.25 of the short side (each corner an arc of 8 points)."""
    w, h = rng.uniform(1.0, 2.5), 1.0
    r = rng.uniform(0.1, 0.25) * h
    pts: list[Point] = []
    for cx, cy, a0 in ((w - r, r, -math.pi / 2), (w - r, h - r, 0.0), (r, h - r, math.pi / 2), (r, r, math.pi)):
        pts += [(cx + r * math.cos(a0 + math.pi / 2 * k / 8), cy + r * math.sin(a0 + math.pi / 2 * k / 8))
                for k in range(9)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def _corner_arc(corner: Point, before: Point, after: Point, cut: float, rounded: bool) -> list[Point]:
    """The corner at ``corner`` (sides from ``before`` and on to ``after``) taken off ``cut`` along each side: a bend
    of 9 points tangent to both sides where ``rounded``, else a straight chamfer (its two ends)."""
    def toward(p: Point, d: float) -> Point:
        n = math.hypot(p[0] - corner[0], p[1] - corner[1])
        return (corner[0] + (p[0] - corner[0]) * d / n, corner[1] + (p[1] - corner[1]) * d / n)
    a, b = toward(before, cut), toward(after, cut)
    if not rounded:
        return [a, b]
    # a bend tangent to both sides whatever the corner's angle: a quadratic Bezier with the corner as its control point
    return [((1 - t) ** 2 * a[0] + 2 * t * (1 - t) * corner[0] + t * t * b[0],
             (1 - t) ** 2 * a[1] + 2 * t * (1 - t) * corner[1] + t * t * b[1]) for t in (k / 8 for k in range(9))]


def box_corners_off(rounded: bool) -> Callable[[random.Random], Shape]:
    """A box (aspect 1-2.5, its upright sides leaned up to 12 degrees, within a box's tolerance, as people's are) drawn
    by a hurried hand that swung round one or two of its corners (``rounded``: an arc of radius 0.2-0.4 of the short
    side) or cut one short (a chamfer 0.15-0.35 of the short side along each side). Issue 25: people's rectangles so
    drawn read as pentagons, hexagons or ellipses."""
    def make(rng: random.Random) -> Shape:
        w, h = rng.uniform(1.0, 2.5), 1.0
        lean = h * math.tan(math.radians(rng.uniform(-12.0, 12.0)))  # the upright sides leaned, as people's are
        square = [(0.0, 0.0), (w, 0.0), (w + lean, h), (lean, h)]
        off = rng.sample(range(4), rng.choice((1, 2)) if rounded else 1)
        pts: list[Point] = []
        for i, corner in enumerate(square):
            if i in off:
                share = rng.uniform(0.2, 0.4) if rounded else rng.uniform(0.15, 0.35)
                pts += _corner_arc(corner, square[i - 1], square[(i + 1) % 4], share * h, rounded)
            else:
                pts.append(corner)
        return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))
    return make


def star(points: int) -> Callable[[random.Random], Shape]:
    """A star's outline drawn round in one stroke, as the Quick, Draw! players drew theirs: ``points`` tips at radius
    0.85-1.15, the inner corners at 0.35-0.75 of it (each apart: a hurried hand makes some nearly flat), every corner
    up to 0.15 of a step off its place, stretched 0.75-1, turned."""
    def make(rng: random.Random) -> Shape:
        step = math.pi / points
        phase = rng.uniform(0, 2 * math.pi)
        stretch = rng.uniform(0.75, 1.0)
        pts = [(r * math.cos(a), stretch * r * math.sin(a))
               for a, r in ((phase + step * (k + rng.uniform(-0.15, 0.15)),
                             rng.uniform(0.85, 1.15) * (1.0 if k % 2 == 0 else rng.uniform(0.35, 0.75)))
                            for k in range(2 * points))]
        return Outline(_turned(_fit_size(pts, rng.uniform(60, 400)), rng.uniform(0, math.pi)))
    return make


def crossed_triangle(rng: random.Random) -> Shape:
    """A triangle closed in a hurry, as Quick, Draw! players drew some: the stroke lands a little before its first
    corner, on the line of its first side, goes round, and runs on past that corner along the last side's line, the
    two tails crossing there (each 0.05-0.2 of its longest side beyond it). Drawn as the open path it is (a
    `penmodels.shapes.Path`); the outline meant is the triangle (`outline_of`)."""
    while True:
        pts = [(math.cos(a), math.sin(a)) for a in (rng.uniform(0, 2 * math.pi) for _ in range(3))]
        (ax, ay), (bx, by), (cx, cy) = pts
        if abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) > 0.8:  # no sliver: twice its area on the unit circle
            break
    a, b, c = _fit_size(pts, rng.uniform(60, 400))
    size = max(math.dist(a, b), math.dist(b, c), math.dist(c, a))

    def beyond(p: Point, q: Point, share: float) -> Point:  # past p on the line from q through p
        d = math.dist(p, q)
        return (p[0] + (p[0] - q[0]) * share * size / d, p[1] + (p[1] - q[1]) * share * size / d)

    start, end = beyond(a, b, rng.uniform(0.05, 0.2)), beyond(a, c, rng.uniform(0.05, 0.2))
    return PenPath(_turned([start, b, c, end], rng.uniform(0, math.pi)))


def rounded_polygon(sides: int) -> Callable[[random.Random], Shape]:
    """An `irregular` polygon whose every corner a hand rounded a little: an arc tangent to both sides taking off
    0.08-0.2 of the shorter side at each (`_corner_arc`), straight runs between."""
    def make(rng: random.Random) -> Shape:
        corners = list(irregular(sides)(rng).vertices)  # type: ignore[union-attr]
        pts: list[Point] = []
        for i, corner in enumerate(corners):
            before, after = corners[i - 1], corners[(i + 1) % sides]
            shorter = min(math.dist(before, corner), math.dist(corner, after))
            pts += _corner_arc(corner, before, after, rng.uniform(0.08, 0.2) * shorter, True)
        return Outline(tuple(pts))
    return make


def egg(rng: random.Random) -> Shape:
    """An egg: an oval of aspect 1.2-2 whose one end is fatter than the other (the half-width grows by 10-25 % of
    itself from the narrow end to the wide one: ``y = b sin t (1 + k cos t)``), turned; drawn as a smooth closed
    curve (72 points, the start repeated)."""
    a = rng.uniform(20, 200)
    b = a / rng.uniform(1.2, 2.0)
    k = rng.uniform(0.1, 0.25)
    pts = [(a * math.cos(t), b * math.sin(t) * (1 + k * math.cos(t)))
           for t in (2 * math.pi * j / 72 for j in range(73))]
    start = rng.randrange(72)
    return PenCurve(_turned([*pts[start:72], *pts[:start + 1]], rng.uniform(0, 2 * math.pi)))


def lumpy_circle(rng: random.Random) -> Shape:
    """A circle drawn unevenly, as people's are: its radius wanders by the 2nd to 5th harmonics round it, each of
    amplitude up to 3 % (in all 4-8 % from the mean), so it bulges and flattens but turns one way all round; drawn as
    a smooth closed curve (72 points, the start repeated)."""
    r = rng.uniform(20, 200)
    waves = [(m, rng.uniform(0.0, 0.03), rng.uniform(0, 2 * math.pi)) for m in (2, 3, 4, 5)]
    spread = sum(amp for _, amp, _ in waves)
    want = rng.uniform(0.04, 0.08)
    waves = [(m, amp * want / spread, ph) for m, amp, ph in waves]
    pts = [(r * (1 + sum(amp * math.cos(m * t + ph) for m, amp, ph in waves)) * math.cos(t),
            r * (1 + sum(amp * math.cos(m * t + ph) for m, amp, ph in waves)) * math.sin(t))
           for t in (2 * math.pi * j / 72 for j in range(73))]
    return PenCurve(_turned(pts, rng.uniform(0, 2 * math.pi)))


def circle(rng: random.Random) -> Shape:
    return Oval(CENTRE, rng.uniform(20, 200), 0.0)


def oval(low: float, high: float) -> Callable[[random.Random], Shape]:
    def make(rng: random.Random) -> Shape:
        rx = rng.uniform(20, 200)
        return Oval(CENTRE, rx, rx / rng.uniform(low, high), rng.uniform(0, math.pi))
    return make
