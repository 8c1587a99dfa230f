"""Stars' outlines as the Quick, Draw! players drew them in a hurry (issue 25): points and dents in turn, left open by
a side, and the marks they must not be taken for (a zig-zag, a crown left open); in canvas pixels, seeded; no motion,
no noise (the pens draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_open_stars.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.many_sided import _placed
from penmodels.open_marks import Mark, Point

EXPECTED: dict[str, str | tuple[str, ...]] = {
    "star-left-open": "polygon", "star-closed": "polygon", "zigzag-row": "polyline", "crown-left-open": "polyline"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a star is a polygon, a zig-zag a polyline; a crown's
rim drawn without its base is an open chain of straight sides)."""


def _star(rng: random.Random) -> list[Point]:
    """The corners of a star of 5 points (or 4, one in five), round the origin: points 60-200 px out, each up to 12 %
    nearer or farther, dents 0.3-0.5 of that in (a regular five-pointed star's 0.38), every corner's angle up to a
    tenth of the spacing off even, the star up to 15 % flatter one way; points and dents in turn. (A star of six points
    has twelve corners, more than a polygon candidate may have: `candidates.MAX_SIDES`.)"""
    points = rng.choices((4, 5), (1, 4))[0]
    radius, dent, flat = rng.uniform(60, 200), rng.uniform(0.3, 0.5), rng.uniform(0.85, 1.0)
    step = math.pi / points
    start = rng.uniform(0, 2 * math.pi)
    out = []
    for k in range(2 * points):
        a = start + step * (k + rng.uniform(-0.1, 0.1))
        r = radius * rng.uniform(0.88, 1.12) * (1.0 if k % 2 == 0 else dent)
        out.append((r * math.cos(a), r * flat * math.sin(a)))
    return out


def _along(a: Point, b: Point, share: float) -> Point:
    return (a[0] + (b[0] - a[0]) * share, a[1] + (b[1] - a[1]) * share)


def star_left_open(seed: int) -> Mark:
    """A star's outline (`_star`) drawn round from a corner, or from up to 0.4 along a side, and left open by about a
    side: the pen lifts at the corner before its start or up to 0.4 along the last side (tutorboard seed260730 #102:
    five points and four dents drawn, the game guessing before the pen came home)."""
    rng = random.Random(f"star-left-open:{seed}")
    corners = _star(rng)[::rng.choice((1, -1))]
    shift = rng.randrange(len(corners))
    corners = corners[shift:] + corners[:shift]
    first = _along(corners[0], corners[1], rng.choice((0.0, rng.uniform(0.0, 0.4))))
    last = _along(corners[-1], corners[0], rng.choice((0.0, rng.uniform(0.0, 0.4))))
    return Mark("star-left-open", _placed(rng, [first, *corners[1:], last]), False)


def star_closed(seed: int) -> Mark:
    """A star's outline (`_star`) drawn round to its start, 0-6 % of a side short of it: it must stay a polygon."""
    rng = random.Random(f"star-closed:{seed}")
    corners = _star(rng)[::rng.choice((1, -1))]
    return Mark("star-closed", _placed(rng, [*corners, _along(corners[0], corners[-1], rng.uniform(0.0, 0.06))]),
                False)


def zigzag_row(seed: int) -> Mark:
    """A zig-zag of 4-8 teeth, each 0.7-1.3 of the others' width and 0.5-1.5 of its width high: its turns alternate as
    a star's do, but its ends lie a row of teeth apart (it must stay a polyline)."""
    rng = random.Random(f"zigzag-row:{seed}")
    teeth = rng.randint(4, 8)
    width = rng.uniform(25, 60)
    pts: list[Point] = []
    x = 0.0
    for k in range(teeth + 1):
        pts.append((x, (0.0 if k % 2 == 0 else width * rng.uniform(0.5, 1.5))))
        x += width * rng.uniform(0.7, 1.3)
    mid = x / 2
    return Mark("zigzag-row", _placed(rng, [(px - mid, py) for px, py in pts]), False)


def crown_left_open(seed: int) -> Mark:
    """A crown's rim without its base: a wall up, 3-5 teeth along the top, a wall down, the pen lifting there (its
    turns alternate along the teeth, but the base left out spans the whole crown: it must stay a polyline)."""
    rng = random.Random(f"crown-left-open:{seed}")
    teeth = rng.randint(3, 5)
    width, wall = rng.uniform(120, 300), rng.uniform(0.3, 0.6)
    tooth = width / teeth
    height = rng.uniform(0.25, 0.5) * width
    pts: list[Point] = [(0.0, 0.0), (0.0, -wall * width)]
    for k in range(teeth):
        pts.append(((k + 0.5) * tooth, -wall * width - height * rng.uniform(0.8, 1.2)))
        pts.append(((k + 1) * tooth, -wall * width))
    pts.append((width, 0.0))
    return Mark("crown-left-open", _placed(rng, [(x - width / 2, y) for x, y in pts]), False)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "star-left-open": star_left_open, "star-closed": star_closed, "zigzag-row": zigzag_row,
    "crown-left-open": crown_left_open}
"""Every family; each is read as `EXPECTED` says."""
