"""Rectangles as people other than our designers draw them (issue 25: held-back hcira3 rectangles read 85.7 %): one
family per habit of the pen, in canvas pixels, seeded; no motion, no noise (the pens draw them: the virtual pen,
`penmodels.hurried`).

Every family draws one box (aspect 1-2.5 unless said, 60-400 px across, turned up to 7 degrees unless said) as the
open chain of points the pen means to follow (a `penmodels.shapes.Path`: a pen turns at each point) from one of its
corners, either way round, and changes one thing about it:

- ``plain``: nothing (the control);
- ``tail-past-close``: after closing, the pen runs on along the first side by 0.1-0.5 of it, a little off its line;
- ``tail-hooked-in``: after closing, the pen hooks into the box by 0.1-0.3 of its shorter side;
- ``retraced``: the pen goes round 1.3-2 times, each lap 1-4 % of the box's size off the last;
- ``turned``: the whole box turned 25-40 degrees either way;
- ``wall-askew``: one wall leaned 15-30 degrees from square (less where its corner would slide past 0.6 of the side
  it slides along), its neighbours square: a right trapezoid, its base and top parallel;
- ``wall-askew-by-hand``: the same, every corner placed 3-8 % of the shorter side off (as hcira klarubbio's mouse
  rectangles and jd4386's are drawn: no two sides exactly parallel);
- ``corner-swung``: one corner swung round wide (a radius 0.35-0.8 of the shorter side), as a mouse hand does;
- ``two-corners-swung``: both corners of one side swung round (0.25-0.4 of the shorter side, so a fifth of the side
  or more stays straight: with none a D or a stadium, no box);
- ``corners-rounded``: every corner swung round (0.25-0.45 of the shorter side): a box drawn in one sweep;
- ``mouse-box``: a wall leaned 8-20 degrees, a corner swung round and a tail past the close, all at once;
- ``gap-at-close``: the fourth side stops 0.15-0.4 of its length short of the start;
- ``start-mid-wall``: the pen starts 0.2-0.8 along a side and stops within 3 % of the perimeter of the start;
- ``side-bowed``: one side bowed out or in by 6-12 % of its length;
- ``corner-crossings``: at two to four corners the pen runs past by 4-12 % of the side and crosses back onto the next
  side behind the corner;
- ``thin``: aspect 5-12 (a shelf, a slab), 150-500 px long;
- ``small``: a square or near-square 18-40 px across;
- ``first-side-redrawn``: the pen lands at a corner, runs 0.2-0.6 along the first side, comes back to the corner (to
  within 5 % of the side either way) and draws the box from there, the first side twice over (session 23);
- ``last-side-redrawn``: the same at the close: back 0.2-0.6 along the last side, and on to the corner again;
- ``start-inside``: the pen lands 0.05-0.25 along the first side and 5-12 % of the shorter side off it (inside or
  out), and the last side runs on to the corner, past the start (hcira klarubbio s06, itt Bam33751);
- ``side-kinked``: the longest side drawn in two pieces meeting 0.3-0.7 along it, the meeting point 4-9 % of the side
  off its line: a fifth corner of 8-20 degrees, as a hand regripping mid-side makes (a mouse, a trackpad).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.shapes import Path

Point = tuple[float, float]
CENTRE = (800.0, 500.0)


def _corners(rng: random.Random, aspect: tuple[float, float] = (1.0, 2.5),
             size: tuple[float, float] = (60.0, 400.0)) -> list[Point]:
    """A box's four corners round the origin in drawing order from a random corner, either way round; its larger side
    ``size`` px, the other that over an ``aspect`` drawn from the range, standing or lying."""
    big = rng.uniform(*size)
    small = big / rng.uniform(*aspect)
    w, h = (big, small) if rng.random() < 0.5 else (small, big)
    pts = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
    if rng.random() < 0.5:
        pts = pts[::-1]
    k = rng.randrange(4)
    return pts[k:] + pts[:k]


def _placed(pts: list[Point], angle: float) -> Path:
    c, s = math.cos(angle), math.sin(angle)
    return Path(tuple((CENTRE[0] + x * c - y * s, CENTRE[1] + x * s + y * c) for x, y in pts))


def _upright(rng: random.Random) -> float:
    return math.radians(rng.uniform(-7.0, 7.0))


def _along(a: Point, b: Point, f: float, off: float = 0.0) -> Point:
    """The point ``f`` of the way from ``a`` to ``b``, ``off`` px to its left."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy) or 1.0
    return (a[0] + f * dx - off * dy / n, a[1] + f * dy + off * dx / n)


def _side(a: Point, b: Point) -> float:
    return math.dist(a, b)


def cut_corner(c: list[Point], k: int, share: float) -> list[Point]:
    """The four corners ``c`` with corner ``k`` cut off ``share`` of the shorter side along both its sides."""
    cut = share * min(_side(c[0], c[1]), _side(c[1], c[2]))
    pts: list[Point] = []
    for i, corner in enumerate(c):
        if i == k:
            pts += [_along(corner, c[i - 1], cut / _side(corner, c[i - 1])),
                    _along(corner, c[(i + 1) % 4], cut / _side(corner, c[(i + 1) % 4]))]
        else:
            pts.append(corner)
    return pts


def plain(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, c[0]], _upright(rng))


def tail_past_close(rng: random.Random) -> Path:
    c = _corners(rng)
    off = rng.uniform(-0.04, 0.04) * min(_side(c[0], c[1]), _side(c[1], c[2]))
    tail = _along(c[0], c[1], rng.uniform(0.1, 0.5), off)
    return _placed([*c, c[0], tail], _upright(rng))


def tail_hooked_in(rng: random.Random) -> Path:
    c = _corners(rng)
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]))
    length = rng.uniform(0.1, 0.3) * shorter
    # into the box from the closing corner, between the two sides' directions (towards the box's middle, give or take)
    mid = (-c[0][0], -c[0][1])
    heading = math.atan2(mid[1] - c[0][1], mid[0] - c[0][0]) + math.radians(rng.uniform(-30.0, 30.0))
    hook = (c[0][0] + length * math.cos(heading), c[0][1] + length * math.sin(heading))
    return _placed([*c, c[0], hook], _upright(rng))


def retraced(rng: random.Random) -> Path:
    c = _corners(rng)
    size = math.hypot(c[2][0] - c[0][0], c[2][1] - c[0][1])
    laps = rng.uniform(1.3, 2.0)
    pts: list[Point] = [c[0]]
    grow = 1.0
    for k in range(1, int(laps * 4) + 1):
        if k % 4 == 0:  # a new lap: a little wider or narrower than the last, as a hand going round again
            grow += rng.choice((-1.0, 1.0)) * rng.uniform(0.01, 0.04) * 2
        x, y = c[k % 4]
        pts.append((x * grow + rng.uniform(-0.01, 0.01) * size, y * grow + rng.uniform(-0.01, 0.01) * size))
    rest = laps * 4 - int(laps * 4)
    a = pts[-1]
    x, y = c[(int(laps * 4) + 1) % 4]
    pts.append(_along(a, (x * grow, y * grow), rest))
    return _placed(pts, _upright(rng))


def turned(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, c[0]], rng.choice((-1.0, 1.0)) * math.radians(rng.uniform(25.0, 40.0)))


def wall_askew(rng: random.Random) -> Path:
    """One corner slid along its side so that the wall ending there leans 15-30 degrees; the others stay square."""
    c = _askew(rng)
    return _placed([*c, c[0]], _upright(rng))


def _askew(rng: random.Random) -> list[Point]:
    c = _corners(rng)
    k = rng.randrange(4)
    a, b, prev = c[k], c[(k + 1) % 4], c[k - 1]  # side a-b keeps its line; the wall prev-a leans
    wall = _side(prev, a)
    slide = wall * math.tan(math.radians(rng.uniform(15.0, 30.0))) * rng.choice((-1.0, 1.0))
    slide = max(-0.6 * _side(a, b), min(0.6 * _side(a, b), slide))  # no corner slid past the far one
    c[k] = _along(a, b, slide / _side(a, b))
    return c


def wall_askew_by_hand(rng: random.Random) -> Path:
    """A `wall_askew` box whose every corner the hand placed 3-8 % of the shorter side off where it meant (in any
    direction), so that, as in people's boxes, its sides are no longer exactly parallel or square."""
    c = _askew(rng)
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]), _side(c[2], c[3]), _side(c[3], c[0]))
    moved = []
    for x, y in c:
        r, a = rng.uniform(0.03, 0.08) * shorter, rng.uniform(0.0, 2 * math.pi)
        moved.append((x + r * math.cos(a), y + r * math.sin(a)))
    return _placed([*moved, moved[0]], _upright(rng))


def _bend(corner: Point, before: Point, after: Point, cut: float, n: int = 9) -> list[Point]:
    """A corner swung round: a quadratic bend tangent to both sides, ``cut`` px back along each."""
    a, b = _along(corner, before, cut / _side(corner, before)), _along(corner, after, cut / _side(corner, after))
    return [((1 - t) ** 2 * a[0] + 2 * t * (1 - t) * corner[0] + t * t * b[0],
             (1 - t) ** 2 * a[1] + 2 * t * (1 - t) * corner[1] + t * t * b[1]) for t in (j / (n - 1) for j in range(n))]


def _swung(c: list[Point], which: set[int], rng: random.Random, share: tuple[float, float]) -> list[Point]:
    """The box's corners in drawing order, those in ``which`` swung round (a radius ``share`` of the shorter side)."""
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]))
    pts: list[Point] = []
    for i, corner in enumerate(c):
        pts += _bend(corner, c[i - 1], c[(i + 1) % 4], rng.uniform(*share) * shorter) if i in which else [corner]
    return [*pts, c[0]]


def corner_swung(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed(_swung(c, {rng.randrange(1, 4)}, rng, (0.35, 0.8)), _upright(rng))  # not the starting corner


def two_corners_swung(rng: random.Random) -> Path:
    c = _corners(rng)
    k = rng.randrange(1, 3)
    return _placed(_swung(c, {k, k + 1}, rng, (0.25, 0.4)), _upright(rng))  # one side's two corners


def corners_rounded(rng: random.Random) -> Path:
    """Every corner swung round (a radius 0.25-0.45 of the shorter side, each its own): a box drawn in one sweep."""
    c = _corners(rng)
    return _placed(_swung(c, {0, 1, 2, 3}, rng, (0.25, 0.45)), _upright(rng))


def mouse_box(rng: random.Random) -> Path:
    """Three habits at once, as a mouse hand in a hurry (hcira klarubbio s06): a wall leaned 8-20 degrees, a corner
    swung round (0.25-0.5 of the shorter side), and a tail on past the close (0.1-0.4 of the first side)."""
    c = _corners(rng)
    a, b, prev = c[1], c[2], c[0]
    slide = _side(prev, a) * math.tan(math.radians(rng.uniform(8.0, 20.0))) * rng.choice((-1.0, 1.0))
    c[1] = _along(a, b, max(-0.5, min(0.5, slide / _side(a, b))))
    pts = _swung(c, {rng.choice((2, 3))}, rng, (0.25, 0.5))
    off = rng.uniform(-0.04, 0.04) * _side(c[0], c[1])
    return _placed([*pts, _along(c[0], c[1], rng.uniform(0.1, 0.4), off)], _upright(rng))


def gap_at_close(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, _along(c[3], c[0], 1.0 - rng.uniform(0.15, 0.4))], _upright(rng))


def start_mid_wall(rng: random.Random) -> Path:
    c = _corners(rng)
    f = rng.uniform(0.2, 0.8)
    start = _along(c[0], c[1], f)
    perimeter = 2 * (_side(c[0], c[1]) + _side(c[1], c[2]))
    miss = rng.uniform(-0.03, 0.03) * perimeter / _side(c[0], c[1])  # short of the start, or on past it
    return _placed([start, c[1], c[2], c[3], c[0], _along(c[0], c[1], f + miss)], _upright(rng))


def side_bowed(rng: random.Random) -> Path:
    return bowed_side(rng, 0.06, 0.12)


def bowed_side(rng: random.Random, least: float, most: float) -> Path:
    """A box with one side bowed out or in by ``least``-``most`` of its length (a sine's half wave)."""
    c = _corners(rng)
    k = rng.randrange(4)
    a, b = c[k], c[(k + 1) % 4]
    bow = rng.choice((-1.0, 1.0)) * rng.uniform(least, most) * _side(a, b)
    pts: list[Point] = []
    for i in range(4):
        pts.append(c[i])
        if i == k:
            pts += [_along(a, b, j / 10, bow * math.sin(math.pi * j / 10)) for j in range(1, 10)]
    return _placed([*pts, c[0]], _upright(rng))


def corner_crossings(rng: random.Random) -> Path:
    c = _corners(rng)
    crossed = set(rng.sample(range(1, 4), rng.randint(2, 3)))
    if rng.random() < 0.5:
        crossed.add(0)  # the closing corner too
    pts: list[Point] = [c[0]]
    for i in range(1, 5):
        v, before, after = c[i % 4], c[i - 1], c[(i + 1) % 4]
        if i % 4 in crossed:
            past = rng.uniform(0.04, 0.12) * _side(before, v)
            behind = rng.uniform(0.04, 0.12) * _side(v, after)
            pts += [_along(before, v, 1.0 + past / _side(before, v)), _along(after, v, 1.0 + behind / _side(v, after))]
            if i == 4:
                pts.append(c[0])
        else:
            pts.append(v)
    return _placed(pts, _upright(rng))


def thin(rng: random.Random) -> Path:
    c = _corners(rng, aspect=(5.0, 12.0), size=(150.0, 500.0))
    return _placed([*c, c[0]], _upright(rng))


def small(rng: random.Random) -> Path:
    c = _corners(rng, aspect=(1.0, 1.6), size=(18.0, 40.0))
    return _placed([*c, c[0]], _upright(rng))


def first_side_redrawn(rng: random.Random) -> Path:
    c = _corners(rng)
    out = _along(c[0], c[1], rng.uniform(0.2, 0.6), rng.uniform(-0.03, 0.03) * _side(c[0], c[1]))
    back = _along(c[0], c[1], rng.uniform(-0.05, 0.05))
    return _placed([c[0], out, back, c[1], c[2], c[3], c[0]], _upright(rng))


def last_side_redrawn(rng: random.Random) -> Path:
    c = _corners(rng)
    out = _along(c[0], c[3], rng.uniform(0.2, 0.6), rng.uniform(-0.03, 0.03) * _side(c[0], c[3]))
    return _placed([*c, c[0], out, _along(c[3], c[0], 1.0 + rng.uniform(-0.05, 0.05))], _upright(rng))


def start_inside(rng: random.Random) -> Path:
    c = _corners(rng)
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]))
    off = rng.choice((-1.0, 1.0)) * rng.uniform(0.05, 0.12) * shorter
    return _placed([_along(c[0], c[1], rng.uniform(0.05, 0.25), off), c[1], c[2], c[3], c[0]], _upright(rng))


def side_kinked(rng: random.Random) -> Path:
    c = _corners(rng)
    k = max(range(4), key=lambda i: _side(c[i], c[(i + 1) % 4]) + 1e-6 * i)
    a, b = c[k], c[(k + 1) % 4]
    kink = _along(a, b, rng.uniform(0.3, 0.7), rng.choice((-1.0, 1.0)) * rng.uniform(0.04, 0.09) * _side(a, b))
    pts: list[Point] = []
    for i in range(4):
        pts += [c[i], kink] if i == k else [c[i]]
    return _placed([*pts, c[0]], _upright(rng))


FAMILIES: dict[str, Callable[[random.Random], Path]] = {
    "plain": plain, "tail-past-close": tail_past_close, "tail-hooked-in": tail_hooked_in, "retraced": retraced,
    "turned": turned, "wall-askew": wall_askew, "wall-askew-by-hand": wall_askew_by_hand, "corner-swung": corner_swung,
    "two-corners-swung": two_corners_swung, "corners-rounded": corners_rounded, "mouse-box": mouse_box,
    "gap-at-close": gap_at_close, "start-mid-wall": start_mid_wall, "side-bowed": side_bowed,
    "corner-crossings": corner_crossings, "thin": thin, "small": small, "first-side-redrawn": first_side_redrawn,
    "last-side-redrawn": last_side_redrawn, "start-inside": start_inside, "side-kinked": side_kinked,
}
"""Every family, by name; each is read as a box (benchmarks/label_kinds.tsv: a rectangle is a box)."""


def drawn(family: str, seed: int) -> Path:
    """The box of ``family`` for ``seed``, from its own generator (``random.Random(f"{family}:{seed}")``)."""
    return FAMILIES[family](random.Random(f"{family}:{seed}"))
