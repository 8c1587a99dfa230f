"""Polygons of 3-8 sides whose corners a hand rounded (issue 25, session 32): every corner rounded over a share of the
sides meeting there, or one corner rounded among sharp ones; in canvas pixels, seeded; no motion, no noise (the pens
draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_rounded_polygons.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.many_sided import _corners, _placed
from penmodels.open_marks import Mark, Point

NAMES = {3: "triangle", 4: "box", 5: "pentagon", 6: "hexagon", 7: "heptagon", 8: "octagon"}
ROUNDED = (0.08, 0.35)
"""Every corner of a `rounded` outline is rounded over this share of the shorter side meeting there (each corner its
own share, the outline's own band 0.8-1.2 of one draw): the arc leaves the sides that far from the corner. At 0.5 a
regular polygon's arcs would meet at its sides' middles and draw its inscribed circle; at a tenth a corner is a blunt
point."""
ONE_ROUNDED = (0.2, 0.45)
"""The one rounded corner of a `one_rounded` outline is rounded over this share of the shorter side meeting there (a
box with one corner swung wide: the fit spends a fifth side on it)."""


def _outline(rng: random.Random, sides: int) -> list[Point]:
    """The corners of a rectangle (aspect 1-2.2, 80-360 px long) for four sides, else of a convex polygon of ``sides``
    whose corners sit up to a tenth of the spacing off even round its centre (`many_sided._corners`)."""
    if sides != 4:
        return _corners(rng, sides, 0.1)
    w = rng.uniform(80, 360)
    h = w / rng.uniform(1.0, 2.2)
    return [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]


def _arc(corner: Point, before: Point, after: Point, share: float) -> list[Point]:
    """The corner rounded by a circular arc tangent to both sides, leaving each ``share`` of the shorter side from the
    corner; a point every 15 degrees of its turn or closer, its ends included (the pen follows them as short sides)."""
    d = share * min(math.dist(corner, before), math.dist(corner, after))
    h0 = math.atan2(corner[1] - before[1], corner[0] - before[0])
    h1 = math.atan2(after[1] - corner[1], after[0] - corner[0])
    turn = (h1 - h0 + math.pi) % (2 * math.pi) - math.pi
    a = (corner[0] - d * math.cos(h0), corner[1] - d * math.sin(h0))
    radius = d / math.tan(abs(turn) / 2)
    steps = max(2, math.ceil(abs(math.degrees(turn)) / 15))
    sign = 1.0 if turn > 0 else -1.0
    out = []
    for k in range(steps + 1):
        h = h0 + turn * k / steps
        out.append((a[0] + sign * radius * (math.sin(h) - math.sin(h0)),
                    a[1] - sign * radius * (math.cos(h) - math.cos(h0))))
    return out


def _closed(rng: random.Random, pts: list[Point]) -> list[Point]:
    """``pts`` (drawn from the first) back to the first, ending 0-6 % of the first step short of it or past it."""
    first, after = pts[0], pts[1]
    end = rng.uniform(-0.06, 0.06)
    target = after if end > 0 else pts[-1]
    return [*pts, (first[0] + (target[0] - first[0]) * abs(end), first[1] + (target[1] - first[1]) * abs(end))]


def rounded(sides: int) -> Callable[[int], Mark]:
    """An outline of ``sides`` every corner of which is rounded (`ROUNDED`), drawn from a point 0.2-0.8 along a side,
    either way round."""
    family = f"rounded-{NAMES[sides]}"

    def make(seed: int) -> Mark:
        rng = random.Random(f"{family}:{seed}")
        corners = _outline(rng, sides)[::rng.choice((1, -1))]
        band = rng.uniform(*ROUNDED)
        at = rng.uniform(0.2, 0.8)
        start = (corners[-1][0] + (corners[0][0] - corners[-1][0]) * at,
                 corners[-1][1] + (corners[0][1] - corners[-1][1]) * at)
        pts: list[Point] = [start]
        for k, c in enumerate(corners):
            share = min(0.45, band * rng.uniform(0.8, 1.2))
            pts += _arc(c, corners[k - 1], corners[(k + 1) % sides], share)
        return Mark(family, _placed(rng, _closed(rng, pts)), False)
    make.__doc__ = f"A {NAMES[sides]} every corner of which a hand rounded ({ROUNDED[0]}-{ROUNDED[1]} of a side)."
    return make


def one_rounded(sides: int) -> Callable[[int], Mark]:
    """An outline of ``sides`` drawn from a sharp corner, one other corner of which is rounded (`ONE_ROUNDED`)."""
    family = f"one-rounded-{NAMES[sides]}"

    def make(seed: int) -> Mark:
        rng = random.Random(f"{family}:{seed}")
        corners = _outline(rng, sides)[::rng.choice((1, -1))]
        k0 = rng.randrange(sides)
        corners = corners[k0:] + corners[:k0]
        swung = rng.randrange(1, sides)  # never the first: the pen lands there
        pts: list[Point] = []
        for k, c in enumerate(corners):
            if k == swung:
                pts += _arc(c, corners[k - 1], corners[(k + 1) % sides], rng.uniform(*ONE_ROUNDED))
            else:
                pts.append(c)
        return Mark(family, _placed(rng, _closed(rng, pts)), False)
    make.__doc__ = f"A {NAMES[sides]} with one corner rounded ({ONE_ROUNDED[0]}-{ONE_ROUNDED[1]} of a side)."
    return make


FAMILIES: dict[str, Callable[[int], Mark]] = {
    **{f"rounded-{NAMES[n]}": rounded(n) for n in NAMES}, **{f"one-rounded-{NAMES[n]}": one_rounded(n) for n in NAMES}}
"""Every family: each outline is read as `EXPECTED` says, with `SIDES` vertices where a polygon."""
SIDES = {family: n for n in NAMES for family in (f"rounded-{NAMES[n]}", f"one-rounded-{NAMES[n]}")}
EXPECTED: dict[str, str | tuple[str, ...]] = {family: "box" if n == 4 else "polygon" for family, n in SIDES.items()}
