"""Rectangles one side of which a hurried hand bowed (issue 25, session 25: a side bowed 16-20 % read as a low
pentagon; quickdraw squares whose right side and its corners were swung round in one sweep), and the low pentagons
and notched boxes they must not swallow; one family per habit, in canvas pixels, seeded; no motion, no noise (the pens
draw them).

Every family draws one box as `box_habits` does (aspect 1-2.5, 60-400 px across, turned up to 7 degrees, from one of
its corners, either way round: `box_habits._corners`) and changes one side of it (not the first or last drawn, so the
bow is not cut where the stroke starts):

- ``bowed-out``: the side bowed out of the box by 14-24 % of its length, its deepest point 0.35-0.65 along it (a
  lopsided half wave: a hand swinging the side round faster at one end);
- ``bowed-in``: the same, bowed into the box;
- ``bow-swung``: the side bowed out by 6-16 % and both its corners swung round (a radius 0.15-0.3 of the shorter side)
  in the same sweep: the box drawn as a D on one side (quickdraw BG #4526069946253312, tutorboard seed90210 #221);
- ``side-swept``: the side and both its corners drawn as one round sweep (half an ellipse, fuller or flatter:
  ``sin(pi t) ** q``, q 0.5-0.8) from the wall before it to the wall after it, the walls stopping 0.18-0.3 of the side
  short of the corners and the sweep reaching 0-6 % of the side past where the side was (session 34: tutorboard
  seed90210 #232, its sweep 0.38 of the chord between the walls it joins, and quickdraw BG #4526069946253312, 0.26:
  deeper than the 0.25 `recognition.bowed_sides.MAX_BOW` was; it is 0.3 since);

and, read as polygons (what the bowed boxes must not take in):

- ``house``: a roof instead of the side, its ridge 12-25 % of the side out at 0.35-0.65 along: a low pentagon, its
  roof's two sides straight and meeting at a sharp corner;
- ``house-in``: the roof pushed into the box (a swallowtail's notch), 12-25 %;
- ``cut-deep``: one corner cut straight across, 0.5-0.7 of the shorter side back along each side (a cut longer than
  half the wall is a pentagon's side: session 24).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.box_habits import _along, _bend, _corners, _placed, _side, _upright, cut_corner
from penmodels.shapes import Path

Point = tuple[float, float]
STEPS = 12
"""Points a bowed side is drawn through (the pen turns at each)."""


def _bowed(rng: random.Random, least: float, most: float, inward: bool) -> list[Point]:
    """The box's corners with side 1-2 (or 2-3) bowed by ``least``-``most`` of its length, out of the box or into it,
    its deepest point 0.35-0.65 along (``sin(pi * t ** p)``)."""
    c = _corners(rng)
    k = rng.choice((1, 2))
    a, b = c[k], c[k + 1]
    outward = _outward(c, k)
    bow = (-1.0 if inward else 1.0) * outward * rng.uniform(least, most) * _side(a, b)
    p = math.log(0.5) / math.log(rng.uniform(0.35, 0.65))  # (t ** p) = 0.5 where the bow is deepest
    pts: list[Point] = []
    for i in range(4):
        pts.append(c[i])
        if i == k:
            pts += [_along(a, b, j / STEPS, bow * math.sin(math.pi * (j / STEPS) ** p)) for j in range(1, STEPS)]
    return [*pts, c[0]]


def _outward(c: list[Point], k: int) -> float:
    """+1 where the left of side ``k`` (from corner ``k`` to the next) is outside the box, else -1."""
    a, b = c[k], c[(k + 1) % 4]
    centre = (sum(x for x, _ in c) / 4, sum(y for _, y in c) / 4)
    left = (b[0] - a[0]) * (centre[1] - a[1]) - (b[1] - a[1]) * (centre[0] - a[0])
    return -1.0 if left > 0 else 1.0


def bowed_out(rng: random.Random) -> Path:
    return _placed(_bowed(rng, 0.14, 0.24, inward=False), _upright(rng))


def bowed_in(rng: random.Random) -> Path:
    return _placed(_bowed(rng, 0.14, 0.24, inward=True), _upright(rng))


def bow_swung(rng: random.Random) -> Path:
    """Side k bowed out by 6-16 % and its two corners swung round (0.15-0.3 of the shorter side) in one sweep."""
    return _swept(rng, (0.06, 0.16), (0.15, 0.3))


def side_swept(rng: random.Random) -> Path:
    """Side k and its two corners drawn as one round sweep from wall to wall (see the module's docstring)."""
    c = _corners(rng)
    k = rng.choice((1, 2))
    a, b = c[k], c[k + 1]
    side = _side(a, b)
    short = rng.uniform(0.18, 0.3) * side  # how far short of the corners the walls stop
    reach = short + rng.uniform(0.0, 0.06) * side  # how far from the chord between the walls' ends the sweep reaches
    q = rng.uniform(0.5, 0.8)
    before, after = c[k - 1], c[(k + 2) % 4]
    start, end = _along(a, before, short / _side(a, before)), _along(b, after, short / _side(b, after))
    out = _outward(c, k) * reach
    sweep = [_along(start, end, j / STEPS, out * math.sin(math.pi * j / STEPS) ** q) for j in range(STEPS + 1)]
    pts: list[Point] = []
    for i in range(4):
        if i == k:
            pts += sweep
        elif i != k + 1:
            pts.append(c[i])
    return _placed([*pts, c[0]], _upright(rng))


def _swept(rng: random.Random, bowed: tuple[float, float], swung: tuple[float, float]) -> Path:
    """Side k bowed out by ``bowed`` of its length and its two corners swung round (``swung`` of the shorter side)."""
    c = _corners(rng)
    k = rng.choice((1, 2))
    a, b = c[k], c[k + 1]
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]))
    cut = rng.uniform(*swung) * shorter
    bow = _outward(c, k) * rng.uniform(*bowed) * _side(a, b)
    f = cut / _side(a, b)
    side = [_along(a, b, f + (1 - 2 * f) * j / STEPS, bow * math.sin(math.pi * j / STEPS)) for j in range(STEPS + 1)]
    pts: list[Point] = []
    for i in range(4):
        if i == k:
            pts += _bend(a, c[k - 1], b, cut) + side[1:-1]  # the bend ends where the side begins
        elif i == k + 1:
            pts += _bend(b, a, c[(k + 2) % 4], cut)
        else:
            pts.append(c[i])
    return _placed([*pts, c[0]], _upright(rng))


def _roof(rng: random.Random, inward: bool) -> list[Point]:
    c = _corners(rng)
    k = rng.choice((1, 2))
    a, b = c[k], c[k + 1]
    ridge = (-1.0 if inward else 1.0) * _outward(c, k) * rng.uniform(0.12, 0.25) * _side(a, b)
    pts: list[Point] = []
    for i in range(4):
        pts += [c[i], _along(a, b, rng.uniform(0.35, 0.65), ridge)] if i == k else [c[i]]
    return [*pts, c[0]]


def house(rng: random.Random) -> Path:
    return _placed(_roof(rng, inward=False), _upright(rng))


def house_in(rng: random.Random) -> Path:
    return _placed(_roof(rng, inward=True), _upright(rng))


def cut_deep(rng: random.Random) -> Path:
    c = _corners(rng)
    k = rng.choice((1, 2))
    pts = cut_corner(c, k, rng.uniform(0.5, 0.7))
    return _placed([*pts, c[0]], _upright(rng))


BOXES: dict[str, Callable[[random.Random], Path]] = {"bowed-out": bowed_out, "bowed-in": bowed_in,
                                                     "bow-swung": bow_swung, "side-swept": side_swept}
"""The families read as boxes."""
POLYGONS: dict[str, Callable[[random.Random], Path]] = {"house": house, "house-in": house_in, "cut-deep": cut_deep}
"""The families read as polygons (never boxes)."""
FAMILIES = {**BOXES, **POLYGONS}


def drawn(family: str, seed: int) -> Path:
    """The shape of ``family`` for ``seed``, from its own generator (``random.Random(f"{family}:{seed}")``)."""
    return FAMILIES[family](random.Random(f"{family}:{seed}"))
