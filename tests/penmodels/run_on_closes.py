"""Closed shapes whose ends run on past where they started (issue 25, session 30: tutorboard seed90210's triangle
#247): the pen lands a little before the first corner, goes round and runs on past that corner, so the ends cross
and a tail sticks out, straight on or hooking off; in canvas pixels, seeded; no motion, no noise (the pens draw them:
`penmodels.hurried`, the virtual pen; `benchmarks/bench_run_on_closes.py`).

Every family draws one closed shape (60-200 px in radius, turned any way, either way round) and, for each seed,
``lead`` (0-0.25 of the first side: where the pen lands, on the first side's line behind its first corner) and
``tail`` (0-0.5 of the last side: how far the last side runs on past that corner), the tail straight half the time
and hooking off by 20-70 degrees over its length, either way, the other half:

- ``triangle-run-on``, ``box-run-on`` (aspect 1-2), ``diamond-run-on`` (a box turned about 45 degrees, its diagonals
  1-1.6 of each other), ``pentagon-run-on``, ``hexagon-run-on`` (corners up to a tenth of the spacing off even);
- ``ellipse-run-on``: a circle or ellipse (up to 2:1) whose pen comes in along the rim's tangent from ``lead`` of the
  radius outside, goes round 360 degrees and leaves along the tangent again for ``tail`` of the radius (the side of
  the hexagon the rim holds), so the two cross where it started.

Two families draw the ends crossing round a triangle, the pen landing 0-0.15 of the first side before the crossing (so
its start lies on the path; session 31, wt-tails):

- ``triangle-long-tail``: a triangle (as ``triangle-run-on``) whose last side runs on past its first corner by 0.5-0.85
  of itself (people's triangles run on so far: hcira klarubbio/s02 triangle06 0.85), straight or hooking off; read as
  a polygon;
- ``x-run-past``: an x or a delete mark drawn in one stroke, the crossing's angle 50-110 degrees, its arms 0.7-1.4 of
  each other, the loop's third side across their far ends, the last arm running on past the crossing by 1.05-1.5 of
  itself (an x's second diagonal out to its far corner: hcira klarubbio/s07 x05 1.14); read as a polyline.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.many_sided import _placed  # the same placement on the canvas
from penmodels.open_marks import Mark, Point

EXPECTED: dict[str, str | tuple[str, ...]] = {
    "triangle-run-on": "polygon", "box-run-on": "box", "diamond-run-on": ("box", "polygon"),
    "pentagon-run-on": "polygon", "hexagon-run-on": "polygon", "ellipse-run-on": ("circle", "ellipse"),
    "triangle-long-tail": "polygon", "x-run-past": "polyline"}
"""The kind (or kinds) each family is read as (benchmarks/label_kinds.tsv: a triangle is a polygon, a rectangle a box,
a diamond a box or a polygon, a circle or oval round)."""
TAIL = (0.0, 0.5)
"""How far the pen runs on past the first corner, as a share of the last side (of the radius, round)."""
LEAD = (0.0, 0.25)
"""How far before the first corner the pen lands, as a share of the first side (of the radius, round)."""
TAILS = {"triangle-long-tail": (0.5, 0.85), "x-run-past": (1.05, 1.5)}
"""The families whose tails are drawn from their own range (of the last side), not from `TAIL`."""
LEADS = {"triangle-long-tail": (0.0, 0.15), "x-run-past": (0.0, 0.15)}
"""The families whose pen lands from their own range (of the first side), not from `LEAD`."""


def _regular(rng: random.Random, sides: int, jitter: float) -> list[Point]:
    """The corners of a convex polygon of ``sides`` 60-200 px in radius, each corner's angle round the centre moved
    by up to ``jitter`` of the even spacing."""
    radius, step, start = rng.uniform(60, 200), 2 * math.pi / sides, rng.uniform(0, 2 * math.pi)
    return [(radius * math.cos(start + step * (k + rng.uniform(-jitter, jitter))),
             radius * math.sin(start + step * (k + rng.uniform(-jitter, jitter)))) for k in range(sides)]


def _triangle(rng: random.Random) -> list[Point]:
    while True:  # every angle at least 30 degrees, as `triangle_habits` draws them
        c = _regular(rng, 3, 0.25)
        sides = [math.dist(c[i], c[(i + 1) % 3]) for i in range(3)]
        cosines = [(sides[i - 1] ** 2 + sides[i] ** 2 - sides[i - 2] ** 2) / (2 * sides[i - 1] * sides[i])
                   for i in range(3)]
        if max(cosines) <= math.cos(math.radians(30.0)):
            return c


def _x_half(rng: random.Random) -> list[Point]:
    """An x's or a delete mark's loop: the crossing, then the arms' far ends (the arms 0.7-1.4 of each other, 60-200 px,
    50-110 degrees apart)."""
    a = rng.uniform(60, 200)
    b = a * rng.uniform(0.7, 1.4)
    turn, at = math.radians(rng.uniform(50, 110)), rng.uniform(0, 2 * math.pi)
    return [(0.0, 0.0), (a * math.cos(at), a * math.sin(at)), (b * math.cos(at + turn), b * math.sin(at + turn))]


def _box(rng: random.Random) -> list[Point]:
    w = rng.uniform(120, 400)
    h = w / rng.uniform(1.0, 2.0)
    return [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]


def _diamond(rng: random.Random) -> list[Point]:
    a = rng.uniform(60, 200)
    b = a / rng.uniform(1.0, 1.6)
    return [(a, 0.0), (0.0, b), (-a, 0.0), (0.0, -b)]


CORNERS: dict[str, Callable[[random.Random], list[Point]]] = {
    "triangle-run-on": _triangle, "box-run-on": _box, "diamond-run-on": _diamond,
    "pentagon-run-on": lambda rng: _regular(rng, 5, 0.1), "hexagon-run-on": lambda rng: _regular(rng, 6, 0.1),
    "triangle-long-tail": _triangle, "x-run-past": _x_half}
FIXED_START = ("x-run-past",)
"""Families whose pen starts at the loop's first corner (the crossing), not at a corner drawn at random."""


def _tail(rng: random.Random, start: Point, heading: float, length: float, hooked: bool) -> list[Point]:
    """A tail ``length`` long from ``start`` along ``heading``: straight, or hooking off by 20-70 degrees in all
    over its second half (points every few pixels, so that a pen follows it round)."""
    if length <= 0.0:
        return []
    if not hooked:
        return [(start[0] + length * math.cos(heading), start[1] + length * math.sin(heading))]
    bend = rng.choice((-1.0, 1.0)) * math.radians(rng.uniform(20, 70))
    n = max(6, int(length / 3))
    pts, (x, y) = [], start
    for k in range(1, n + 1):
        h = heading + bend * max(0.0, (k / n - 0.5) * 2) ** 2
        x, y = x + length / n * math.cos(h), y + length / n * math.sin(h)
        pts.append((x, y))
    return pts


def run_on(family: str, seed: int, tails: tuple[float, float] | None = None) -> tuple[Mark, float, bool, float]:
    """The ``family``'s shape for ``seed``, its tail's share (drawn from ``tails``, the family's range unless given:
    the same shape, its tail scaled; `TAIL`, `TAILS`), whether the tail hooks, and its lead's share (`LEAD`,
    `LEADS`)."""
    rng = random.Random(f"{family}:{seed}")
    lead = rng.uniform(*LEADS.get(family, LEAD))
    tail, hooked = rng.uniform(*(tails or TAILS.get(family, TAIL))), rng.random() < 0.5
    if family == "ellipse-run-on":
        return _ellipse(rng, lead, tail, hooked), tail, hooked, lead
    c = CORNERS[family](rng)
    if rng.random() < 0.5:
        c = [c[0], *c[:0:-1]] if family in FIXED_START else c[::-1]
    k = 0 if family in FIXED_START else rng.randrange(len(c))
    c = c[k:] + c[:k]
    first, last = (c[1][0] - c[0][0], c[1][1] - c[0][1]), (c[0][0] - c[-1][0], c[0][1] - c[-1][1])
    land = (c[0][0] - lead * first[0], c[0][1] - lead * first[1])
    pts = [land, *c, c[0]]
    pts += _tail(rng, c[0], math.atan2(last[1], last[0]), tail * math.hypot(*last), hooked)
    return Mark(family, _placed(rng, pts), False), tail, hooked, lead


def _ellipse(rng: random.Random, lead: float, tail: float, hooked: bool) -> Mark:
    radius = rng.uniform(60, 200)
    flat = 1.0 / rng.uniform(1.0, 2.0)
    way, at = rng.choice((-1.0, 1.0)), rng.uniform(0, 2 * math.pi)
    n = 180
    rim = [(radius * math.cos(at + way * 2 * math.pi * k / n), radius * flat * math.sin(at + way * 2 * math.pi * k / n))
           for k in range(n + 1)]
    tangent = (-radius * math.sin(at) * way, radius * flat * math.cos(at) * way)
    norm = math.hypot(*tangent)
    ux, uy = tangent[0] / norm, tangent[1] / norm
    back = lead * radius
    lead_in = [(rim[0][0] - back * ux * (1 - j / 4), rim[0][1] - back * uy * (1 - j / 4)) for j in range(4)]
    pts = (lead_in if back > 1.0 else []) + rim
    if tail * radius > 1.0:
        pts += _tail(rng, rim[-1], math.atan2(uy, ux), tail * radius, hooked) if hooked else [
            (rim[-1][0] + tail * radius * ux * j / 4, rim[-1][1] + tail * radius * uy * j / 4) for j in range(1, 5)]
    return Mark("ellipse-run-on", _placed(rng, pts), True)


def _family(name: str) -> Callable[[int], Mark]:
    def draw(seed: int) -> Mark:
        return run_on(name, seed)[0]
    return draw


FAMILIES: dict[str, Callable[[int], Mark]] = {name: _family(name) for name in EXPECTED}
"""Every family, by name (`run_on`)."""
