"""Triangles as people other than our designers draw them (issue 25: quickdraw's triangles read as polylines where the
pen left a gap at a corner or started along a side): one family per habit of the pen, in canvas pixels, seeded; no
motion, no noise (the pens draw them: the virtual pen, `penmodels.hurried`).

Every family draws one triangle (its corners on a circle 60-400 px across, every angle at least 30 degrees, turned any
way) as the open chain of points the pen means to follow (a `penmodels.shapes.Path`) from one of its corners, either
way round, and changes one thing about it:

- ``plain``: nothing (the control);
- ``gap-at-close``: the last side stops 0.15-0.4 of its length short of the start;
- ``start-short``: the pen lands 0.15-0.45 along the first side and the last side runs to the corner and 0-10 % past
  it (quickdraw's triangles begun along a side);
- ``tail-past-close``: after closing, the pen runs on along the first side by 0.1-0.4 of it, a little off its line;
- ``crossing-close``: the pen lands 0.05-0.2 along the first side and the last side runs 5-25 % past the corner,
  across the first;
- ``both-ends-past`` (session 27, tutorboard seed90210's triangle #247): the pen lands 5-20 % of the first side
  before its corner, on its line outside the triangle, and the last side runs 5-25 % past that corner, across the
  first: the two sides cross at the corner as an X;
- ``start-short-run-past`` (session 27, tutorboard seed90210's triangle #309): the pen lands 0.1-0.35 along the first
  side and the last side runs 10-30 % past the corner, so the end passes the start outside the triangle;
- ``start-short-overshoot`` (session 28, tutorboard seed90210's triangle #309 measured again: the pen lands 0.18 along
  the first side, and the last side runs on past the corner by 0.43 of its length up to it): the pen lands 0.1-0.35
  along the first side and the last side runs 30-70 % past the corner, its end far from the start and not pointing
  home;
- ``start-mid-side``: the pen starts 0.2-0.8 along a side and stops within 5 % of that side of the start;
- ``first-side-redrawn``: the pen runs 0.2-0.6 along the first side, back to the corner and along it again;
- ``start-inside``: the pen lands 0.05-0.25 along the first side, 5-12 % of the shortest side off it.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.box_habits import CENTRE, Point, _along, _side
from penmodels.shapes import Path

MIN_ANGLE = 30.0
"""Degrees: the sharpest corner a triangle of these families has."""


def _angles(pts: list[Point]) -> list[float]:
    out = []
    for i in range(3):
        a, b = pts[i - 1], pts[(i + 1) % 3]
        u, v = (a[0] - pts[i][0], a[1] - pts[i][1]), (b[0] - pts[i][0], b[1] - pts[i][1])
        cos = (u[0] * v[0] + u[1] * v[1]) / (math.hypot(*u) * math.hypot(*v))
        out.append(math.degrees(math.acos(max(-1.0, min(1.0, cos)))))
    return out


def _corners(rng: random.Random) -> list[Point]:
    """A triangle's three corners round the origin in drawing order from a random corner, either way round."""
    radius = rng.uniform(30.0, 200.0)
    while True:
        turns = sorted(rng.uniform(0.0, 2 * math.pi) for _ in range(3))
        pts = [(radius * math.cos(t), radius * math.sin(t)) for t in turns]
        if min(_angles(pts)) >= MIN_ANGLE:
            break
    if rng.random() < 0.5:
        pts = pts[::-1]
    k = rng.randrange(3)
    return pts[k:] + pts[:k]


def _placed(pts: list[Point]) -> Path:
    return Path(tuple((CENTRE[0] + x, CENTRE[1] + y) for x, y in pts))


def plain(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, c[0]])


def gap_at_close(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, _along(c[2], c[0], 1.0 - rng.uniform(0.15, 0.4))])


def start_short(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([_along(c[0], c[1], rng.uniform(0.15, 0.45)), c[1], c[2],
                    _along(c[2], c[0], 1.0 + rng.uniform(0.0, 0.1))])


def tail_past_close(rng: random.Random) -> Path:
    c = _corners(rng)
    off = rng.uniform(-0.04, 0.04) * _side(c[0], c[1])
    return _placed([*c, c[0], _along(c[0], c[1], rng.uniform(0.1, 0.4), off)])


def crossing_close(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([_along(c[0], c[1], rng.uniform(0.05, 0.2)), c[1], c[2],
                    _along(c[2], c[0], 1.0 + rng.uniform(0.05, 0.25))])


def both_ends_past(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([_along(c[0], c[1], -rng.uniform(0.05, 0.2)), c[1], c[2],
                    _along(c[2], c[0], 1.0 + rng.uniform(0.05, 0.25))])


def start_short_run_past(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([_along(c[0], c[1], rng.uniform(0.1, 0.35)), c[1], c[2],
                    _along(c[2], c[0], 1.0 + rng.uniform(0.1, 0.3))])


def start_short_overshoot(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([_along(c[0], c[1], rng.uniform(0.1, 0.35)), c[1], c[2],
                    _along(c[2], c[0], 1.0 + rng.uniform(0.3, 0.7))])


def start_mid_side(rng: random.Random) -> Path:
    c = _corners(rng)
    f = rng.uniform(0.2, 0.8)
    return _placed([_along(c[0], c[1], f), c[1], c[2], c[0], _along(c[0], c[1], f + rng.uniform(-0.05, 0.05))])


def first_side_redrawn(rng: random.Random) -> Path:
    c = _corners(rng)
    out = _along(c[0], c[1], rng.uniform(0.2, 0.6), rng.uniform(-0.03, 0.03) * _side(c[0], c[1]))
    return _placed([c[0], out, _along(c[0], c[1], rng.uniform(-0.05, 0.05)), c[1], c[2], c[0]])


def start_inside(rng: random.Random) -> Path:
    c = _corners(rng)
    shortest = min(_side(c[0], c[1]), _side(c[1], c[2]), _side(c[2], c[0]))
    off = rng.choice((-1.0, 1.0)) * rng.uniform(0.05, 0.12) * shortest
    return _placed([_along(c[0], c[1], rng.uniform(0.05, 0.25), off), c[1], c[2], c[0]])


FAMILIES: dict[str, Callable[[random.Random], Path]] = {
    "plain": plain, "gap-at-close": gap_at_close, "start-short": start_short, "tail-past-close": tail_past_close,
    "crossing-close": crossing_close, "both-ends-past": both_ends_past, "start-short-run-past": start_short_run_past,
    "start-short-overshoot": start_short_overshoot, "start-mid-side": start_mid_side,
    "first-side-redrawn": first_side_redrawn, "start-inside": start_inside,
}
"""Every family, by name; each is read as a polygon (benchmarks/label_kinds.tsv: a triangle is a polygon)."""


def drawn(family: str, seed: int) -> Path:
    """The triangle of ``family`` for ``seed``, from its own generator (``random.Random(f"triangle {family}:{seed}")``).
    """
    return FAMILIES[family](random.Random(f"triangle {family}:{seed}"))
