"""Rectangles and squares with all four corners rounded, and circles and ellipses drawn as people draw them (issue 25):
what each means, in canvas pixels, seeded; no motion, no noise (the pens draw them: the virtual pen,
`penmodels.hurried`).

Rounded boxes (each a closed `penmodels.shapes.Path` from a point on a side, either way round, turned up to 7 degrees;
aspect 1-1.15 (a square) or 1.15-4 (a rectangle), equally often; 60-400 px along the longer side). Every corner is
rounded with a radius of its own drawn from the family's band, as a share of the shorter side:

- ``arc-10-25``, ``arc-25-40``, ``arc-40-50``: each corner a quarter circle (a rounded rectangle as a drawing program
  makes it; at 0.5 of a square's side there is no side left: a circle);
- ``swung-10-25``, ``swung-25-40``, ``swung-40-50``: each corner swung round as a hand does (`box_habits._bend`: a
  bend tangent to both sides, ``r`` back along each: flatter in its middle than an arc, so a corner stays).

Round shapes people draw, which must stay round (each a smooth `penmodels.shapes.Curve`, 20-200 px in radius):

- ``wobbly``: a circle whose radius wanders by the 2nd to 6th harmonics round it, 4-10 % from the mean in all;
- ``flattened``: an ellipse of aspect 1.15-3 whose radius wanders by 0-3 %;
- ``egg``: an oval of aspect 1-1.8 one end of which is 10-30 % fatter than the other;
- ``overshoot``: a circle or an ellipse (aspect 1-2) drawn on past its start by 15-60 degrees, the second pass 2-8 %
  of the radius outside or inside the first (as a hand closing a circle in a hurry).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.shapes import Curve, Path

Point = tuple[float, float]
CENTRE = (800.0, 500.0)
ARC_POINTS = 9
"""Points on each corner's bend (as `box_habits._bend` draws one)."""
ROUND_POINTS = 72
"""Points round a round shape (as `closed_shape_families.egg` and `lumpy_circle` draw one)."""


def _turn(pts: list[Point], angle: float) -> list[Point]:
    c, s = math.cos(angle), math.sin(angle)
    return [(CENTRE[0] + x * c - y * s, CENTRE[1] + x * s + y * c) for x, y in pts]


def _bend(corner: Point, a: Point, b: Point, circular: bool) -> list[Point]:
    """The corner at ``corner`` rounded from ``a`` (on the side before it) to ``b`` (on the side after it), both as
    far from it: a quarter circle tangent to both sides (``circular``) or a quadratic bend with the corner as its
    control point, as `box_habits._bend` swings one."""
    ts = [j / (ARC_POINTS - 1) for j in range(ARC_POINTS)]
    if not circular:
        return [((1 - t) ** 2 * a[0] + 2 * t * (1 - t) * corner[0] + t * t * b[0],
                 (1 - t) ** 2 * a[1] + 2 * t * (1 - t) * corner[1] + t * t * b[1]) for t in ts]
    centre = (a[0] + b[0] - corner[0], a[1] + b[1] - corner[1])  # a right-angled corner: the arc's centre
    r = math.dist(a, centre)
    start = math.atan2(a[1] - centre[1], a[0] - centre[0])
    turn = math.atan2(b[1] - centre[1], b[0] - centre[0]) - start
    turn = (turn + math.pi) % (2 * math.pi) - math.pi  # the quarter turn, either way
    return [(centre[0] + r * math.cos(start + turn * t), centre[1] + r * math.sin(start + turn * t)) for t in ts]


def _toward(p: Point, q: Point, d: float) -> Point:
    n = math.dist(p, q) or 1.0
    return (p[0] + (q[0] - p[0]) * d / n, p[1] + (q[1] - p[1]) * d / n)


def rounded_box(band: tuple[float, float], circular: bool) -> Callable[[random.Random], Path]:
    """A box of aspect 1-1.15 or 1.15-4 with every corner rounded by a share ``band`` of its shorter side (each its
    own), drawn from a point on a side, either way round."""
    def make(rng: random.Random) -> Path:
        big = rng.uniform(60.0, 400.0)
        small = big / (rng.uniform(1.0, 1.15) if rng.random() < 0.5 else rng.uniform(1.15, 4.0))
        w, h = (big, small) if rng.random() < 0.5 else (small, big)
        corners = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
        if rng.random() < 0.5:
            corners = corners[::-1]
        ring: list[Point] = []
        for i, corner in enumerate(corners):
            r = rng.uniform(*band) * small
            before, after = corners[i - 1], corners[(i + 1) % 4]
            ring += _bend(corner, _toward(corner, before, r), _toward(corner, after, r), circular)
        # start on a side: between one corner's bend and the next, part of the way along
        k = rng.randrange(4)
        (ax, ay), (bx, by) = ring[(k + 1) * ARC_POINTS - 1], ring[((k + 1) * ARC_POINTS) % len(ring)]
        f = rng.uniform(0.2, 0.8)
        start = (ax + f * (bx - ax), ay + f * (by - ay))
        cut = ((k + 1) * ARC_POINTS) % len(ring)
        pts = [start, *ring[cut:], *ring[:cut], start]
        return Path(tuple(_turn(pts, math.radians(rng.uniform(-7.0, 7.0)))))
    return make


def _round(rng: random.Random, rx: float, ry: float, wobble: Callable[[float], float],
           past: float = 0.0, drift: float = 0.0) -> Curve:
    """A round shape of semi-axes ``rx``, ``ry`` whose radius is scaled by ``wobble(t)``, from a random start, either
    way round, turned anyhow; ``past``: radians drawn on past the start, the radius growing by ``drift`` (a share)
    over the second pass."""
    start = rng.uniform(0.0, 2 * math.pi)
    way = rng.choice((-1.0, 1.0))
    steps = int(ROUND_POINTS * (1 + past / (2 * math.pi)))
    pts = []
    for j in range(steps + 1):
        t = 2 * math.pi * j / ROUND_POINTS
        grow = 1.0 + (drift * (t - 2 * math.pi) / max(past, 1e-9) if t > 2 * math.pi else 0.0)
        a = start + way * t
        k = wobble(a) * grow
        pts.append((rx * k * math.cos(a), ry * k * math.sin(a)))
    return Curve(tuple(_turn(pts, rng.uniform(0.0, 2 * math.pi))))


def _harmonics(rng: random.Random, orders: range, total: tuple[float, float]) -> Callable[[float], float]:
    """A radius that wanders by the harmonics ``orders`` (random phases), ``total`` a share from the mean in all."""
    waves = [(m, rng.uniform(0.0, 1.0), rng.uniform(0.0, 2 * math.pi)) for m in orders]
    spread = sum(amp for _, amp, _ in waves) or 1.0
    want = rng.uniform(*total)
    return lambda a: 1.0 + sum(want * amp / spread * math.cos(m * a + ph) for m, amp, ph in waves)


def wobbly(rng: random.Random) -> Curve:
    r = rng.uniform(20.0, 200.0)
    return _round(rng, r, r, _harmonics(rng, range(2, 7), (0.04, 0.10)))


def flattened(rng: random.Random) -> Curve:
    rx = rng.uniform(20.0, 200.0)
    return _round(rng, rx, rx / rng.uniform(1.15, 3.0), _harmonics(rng, range(2, 6), (0.0, 0.03)))


def egg(rng: random.Random) -> Curve:
    rx = rng.uniform(20.0, 200.0)
    fat = rng.uniform(0.1, 0.3)
    ry = rx / rng.uniform(1.0, 1.8)
    # the half-width grows from one end to the other: y scaled by 1 + fat cos(a) (as `closed_shape_families.egg`)
    return _egg(rng, rx, ry, fat)


def _egg(rng: random.Random, rx: float, ry: float, fat: float) -> Curve:
    start = rng.uniform(0.0, 2 * math.pi)
    way = rng.choice((-1.0, 1.0))
    pts = [(rx * math.cos(a), ry * math.sin(a) * (1 + fat * math.cos(a)))
           for a in (start + way * 2 * math.pi * j / ROUND_POINTS for j in range(ROUND_POINTS + 1))]
    return Curve(tuple(_turn(pts, rng.uniform(0.0, 2 * math.pi))))


def overshoot(rng: random.Random) -> Curve:
    rx = rng.uniform(20.0, 200.0)
    return _round(rng, rx, rx / rng.uniform(1.0, 2.0), _harmonics(rng, range(2, 5), (0.0, 0.04)),
                  past=math.radians(rng.uniform(15.0, 60.0)), drift=rng.choice((-1.0, 1.0)) * rng.uniform(0.02, 0.08))


BOXES: dict[str, Callable[[random.Random], Path]] = {
    f"{'arc' if circular else 'swung'}-{round(lo * 100)}-{round(hi * 100)}": rounded_box((lo, hi), circular)
    for circular in (True, False) for lo, hi in ((0.10, 0.25), (0.25, 0.40), (0.40, 0.50))
}
"""The rounded boxes, each read as a box (benchmarks/label_kinds.tsv: a rectangle or a square is a box)."""
ROUND: dict[str, Callable[[random.Random], Curve]] = {
    "wobbly": wobbly, "flattened": flattened, "egg": egg, "overshoot": overshoot,
}
"""The round shapes, each read as a circle or an ellipse."""
FAMILIES: dict[str, Callable[[random.Random], Path | Curve]] = {**BOXES, **ROUND}


def drawn(family: str, seed: int) -> Path | Curve:
    """The shape of ``family`` for ``seed``, from its own generator (``random.Random(f"{family}:{seed}")``)."""
    return FAMILIES[family](random.Random(f"{family}:{seed}"))
