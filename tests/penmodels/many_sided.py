"""Many-sided outlines and squiggles as the Quick, Draw! players drew them in a hurry (issue 25): irregular hexagons
and octagons, some of an octagon's shallow corners swept round, and squiggles of uneven humps; in canvas pixels,
seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen;
`benchmarks/bench_many_sided.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point

EXPECTED: dict[str, str | tuple[str, ...]] = {
    "irregular-hexagon": "polygon", "swept-octagon": "polygon", "left-open": "polygon", "uneven-squiggle": "curve",
    "rounded-left-open": "polygon", "round-left-open": ("circle", "ellipse", "arc")}
"""The kind (or kinds) each family is read as (benchmarks/label_kinds.tsv: quickdraw hexagons and octagons are
polygons, squiggles curves; a circle left open is round, or the arc drawn, never a polygon)."""


def _placed(rng: random.Random, pts: list[Point]) -> tuple[Point, ...]:
    """``pts`` (round the origin) turned a random angle and moved to a random place on the 1600 x 1000 canvas."""
    angle = rng.uniform(0, 2 * math.pi)
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in pts)


def _corners(rng: random.Random, sides: int, jitter: float) -> list[Point]:
    """The corners of a convex polygon of ``sides``, 60-200 px in radius, up to 15 % flatter one way, each corner's
    angle round the centre moved by up to ``jitter`` of the even spacing and its radius by up to 12 %."""
    radius, flat = rng.uniform(60, 200), rng.uniform(0.85, 1.0)
    step = 2 * math.pi / sides
    start = rng.uniform(0, 2 * math.pi)
    out = []
    for k in range(sides):
        a = start + step * (k + rng.uniform(-jitter, jitter))
        r = radius * rng.uniform(0.88, 1.12)
        out.append((r * math.cos(a), r * flat * math.sin(a)))
    return out


def _closed(rng: random.Random, corners: list[Point]) -> list[Point]:
    """The corners in drawing order, back to the first, ending 0-6 % of a side short of it or past it."""
    way = rng.choice((1, -1))
    pts = corners[::way]
    first, last = pts[0], pts[-1]
    end = rng.uniform(-0.06, 0.06)  # negative: short of the start; positive: on along the first side
    target = pts[1] if end > 0 else last
    return [*pts, (first[0] + (target[0] - first[0]) * abs(end), first[1] + (target[1] - first[1]) * abs(end))]


def irregular_hexagon(seed: int) -> Mark:
    """A hexagon whose corners sit up to a fifth of the spacing off even round its centre (turns of 35-85 degrees,
    sides 0.6-1.4 of each other; Quick, Draw! hexagons), closed as a hurried hand closes it."""
    rng = random.Random(f"irregular-hexagon:{seed}")
    return Mark("irregular-hexagon", _placed(rng, _closed(rng, _corners(rng, 6, 0.2))), False)


def _swept(corner: Point, before: Point, after: Point, share: float) -> list[Point]:
    """A corner swept round: four points on a quadratic from ``share`` of the way back along the side before it to as
    far along the side after it (the pen follows them as short sides, turning a little at each)."""
    a = (corner[0] + (before[0] - corner[0]) * share, corner[1] + (before[1] - corner[1]) * share)
    b = (corner[0] + (after[0] - corner[0]) * share, corner[1] + (after[1] - corner[1]) * share)
    out = []
    for k in range(5):
        u = k / 4
        out.append(((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * corner[0] + u * u * b[0],
                    (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * corner[1] + u * u * b[1]))
    return out


def swept_octagon(seed: int) -> Mark:
    """An octagon whose corners sit up to a quarter of the spacing off even (turns of 25-65 degrees), one or two of
    its corners swept round over 0.2-0.35 of the sides meeting there (Quick, Draw! octagons read round), closed as a
    hurried hand closes it."""
    rng = random.Random(f"swept-octagon:{seed}")
    corners = _corners(rng, 8, 0.25)
    swept = set(rng.sample(range(1, 8), rng.randint(1, 2)))  # never the first: the pen lands there
    pts: list[Point] = []
    for k, c in enumerate(corners):
        if k in swept:
            pts += _swept(c, corners[k - 1], corners[(k + 1) % 8], rng.uniform(0.2, 0.35))
        else:
            pts.append(c)
    return Mark("swept-octagon", _placed(rng, _closed(rng, pts)), False)


def left_open(seed: int) -> Mark:
    """A hexagon, heptagon or octagon (`irregular_hexagon`'s corners, up to a fifth of the spacing off even) drawn
    round to its last corner and left open there, its last side not drawn (Quick, Draw! hexagons: the game ended as it
    guessed)."""
    rng = random.Random(f"left-open:{seed}")
    corners = _corners(rng, rng.choice((6, 7, 8)), 0.2)
    return Mark("left-open", _placed(rng, corners[::rng.choice((1, -1))]), False)


def uneven_squiggle(seed: int) -> Mark:
    """A squiggle of 2-4 round humps, alternately up and down, each 0.6-1.4 of the others' width and 0.15-0.45 of its
    length high (Quick, Draw! squiggles), 150-400 px long, its ends 0-0.5 of a hump past the first and last bend."""
    rng = random.Random(f"uneven-squiggle:{seed}")
    humps = rng.randint(2, 4)
    widths = [rng.uniform(0.6, 1.4) for _ in range(humps)]
    length = rng.uniform(150, 400)
    scale = length / sum(widths)
    pts: list[Point] = []
    x0 = 0.0
    for h, w in enumerate(widths):
        width, height = w * scale, rng.uniform(0.15, 0.45) * length * (1 if h % 2 == 0 else -1)
        first, last = (rng.uniform(0.0, 0.25) if h == 0 else 0.0), (rng.uniform(0.75, 1.0) if h == humps - 1 else 1.0)
        n = 16
        for k in range(n + 1):
            u = first + (last - first) * k / n
            if pts and k == 0:
                continue
            pts.append((x0 + u * width - length / 2, height * math.sin(math.pi * u)))
        x0 += width
    return Mark("uneven-squiggle", _placed(rng, pts), True)


def rounded_left_open(seed: int) -> Mark:
    """A hexagon, heptagon or octagon (`irregular_hexagon`'s corners, up to a fifth of the spacing off even) every
    corner of which the hand swept round over 0.15-0.35 of the sides meeting there (`_swept`), drawn round to its last
    corner and left open there (Quick, Draw! hexagons and octagons: the game ended as it guessed, the corners rounded
    in the hurry)."""
    rng = random.Random(f"rounded-left-open:{seed}")
    sides = rng.choice((6, 7, 8))
    corners = _corners(rng, sides, 0.2)[::rng.choice((1, -1))]
    pts: list[Point] = [corners[0]]
    for k in range(1, sides - 1):
        pts += _swept(corners[k], corners[k - 1], corners[k + 1], rng.uniform(0.08, 0.2))
    pts.append(corners[-1])
    return Mark("rounded-left-open", _placed(rng, pts), False)


def round_left_open(seed: int) -> Mark:
    """A circle or an oval (up to a fifth flatter one way, 60-200 px in radius) drawn lumpily (its radius wandering by
    up to 8 % in its 2nd-5th harmonics) round 250-330 degrees and left open: what `rounded_left_open` must not take
    for a polygon."""
    rng = random.Random(f"round-left-open:{seed}")
    radius, flat = rng.uniform(60, 200), rng.uniform(0.8, 1.0)
    lumps = [(h, rng.uniform(0.0, 0.08 / h), rng.uniform(0, 2 * math.pi)) for h in range(2, 6)]
    sweep, start, way = math.radians(rng.uniform(250, 330)), rng.uniform(0, 2 * math.pi), rng.choice((1, -1))
    pts: list[Point] = []
    for k in range(int(math.degrees(sweep) / 2) + 1):
        a = start + way * math.radians(2 * k)
        r = radius * (1 + sum(amp * math.cos(h * a + phase) for h, amp, phase in lumps))
        pts.append((r * math.cos(a), r * flat * math.sin(a)))
    return Mark("round-left-open", _placed(rng, pts), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "irregular-hexagon": irregular_hexagon, "swept-octagon": swept_octagon, "left-open": left_open,
    "uneven-squiggle": uneven_squiggle, "rounded-left-open": rounded_left_open, "round-left-open": round_left_open}
"""Every family; each is read as `EXPECTED` says."""
