"""Circles whose ends do not meet as a closed outline's do (issue 25: held-back people read circles 93 %): the pen
lands inside and runs out to the rim first, or curls in past where it started at the end, or both, or draws its first
arc twice over; in canvas pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen;
`benchmarks/bench_round_habits.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point

EXPECTED = ("circle", "ellipse")
"""What every family is read as (benchmarks/label_kinds.tsv: a circle is round, a circle or an ellipse)."""


def _rim(rng: random.Random) -> tuple[float, float]:
    """A circle's radius (40-200 px) and how much flatter one way it is drawn (up to 20 %)."""
    return rng.uniform(40, 200), rng.uniform(0.8, 1.0)


def _round(radius: float, flat: float, start: float, sweep: float, shrink_from: float = math.inf,
           shrink_to: float = 1.0) -> list[Point]:
    """Points every 2 degrees round an ellipse of ``radius`` (``flat`` across), from angle ``start`` turning by
    ``sweep`` (radians, signed); past ``shrink_from`` radians of it the radius eases down to ``shrink_to`` of itself
    by the end (a curl inwards)."""
    n = max(8, int(abs(math.degrees(sweep)) / 2))
    out = []
    for k in range(n + 1):
        done = abs(sweep) * k / n
        scale = 1.0
        if done > shrink_from:
            u = (done - shrink_from) / (abs(sweep) - shrink_from)
            scale = 1.0 - (1.0 - shrink_to) * (1 - math.cos(math.pi * u)) / 2
        a = start + math.copysign(done, sweep)
        out.append((radius * scale * math.cos(a), radius * flat * scale * math.sin(a)))
    return out


def _placed(rng: random.Random, pts: list[Point]) -> tuple[Point, ...]:
    """``pts`` (round the origin) turned a random angle and moved to a random place on the 1600 x 1000 canvas."""
    angle = rng.uniform(0, 2 * math.pi)
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in pts)


def _lead_in(rng: random.Random, radius: float, flat: float, start: float, way: float) -> list[Point]:
    """A lead from a landing 0.15-0.7 of the radius in from the rim out to the rim at angle ``start``, straight or
    swung the way the circle turns (``way``: +1 or -1), ending where the round begins."""
    depth = rng.uniform(0.15, 0.7)
    end = (radius * math.cos(start), radius * flat * math.sin(start))
    back = start - way * rng.uniform(0.0, 0.8)  # the landing sits behind the start, or straight in from it
    land = ((1 - depth) * radius * math.cos(back), (1 - depth) * radius * flat * math.sin(back))
    n = max(4, int(math.dist(land, end) / 4))
    return [(land[0] + (end[0] - land[0]) * k / n, land[1] + (end[1] - land[1]) * k / n) for k in range(n)]


def lead_in_circle(seed: int) -> Mark:
    """A circle whose pen lands inside it (0.15-0.7 of the radius in) and runs out to the rim, then goes round by
    290-370 degrees (itt lvht1203's circle: landing near the middle, a straight lead out, round, stopping short)."""
    rng = random.Random(f"lead-in-circle:{seed}")
    radius, flat = _rim(rng)
    way = rng.choice((-1.0, 1.0))
    start = rng.uniform(0, 2 * math.pi)
    pts = _lead_in(rng, radius, flat, start, way)
    pts += _round(radius, flat, start, way * math.radians(rng.uniform(290, 370)))
    return Mark("lead-in-circle", _placed(rng, pts), True)


def curled_in_circle(seed: int) -> Mark:
    """A circle that goes round by 290-540 degrees, its last 90-220 degrees curling in to 0.45-0.85 of the radius, so
    that its end lies inside, past or short of its start (dollar1 s02's, klarubbio/s06's and jonathanzhang53/s04's
    circles: a spiral's last turn; drawn from its inner end, a spiral's first)."""
    rng = random.Random(f"curled-in-circle:{seed}")
    radius, flat = _rim(rng)
    sweep = math.radians(rng.uniform(290, 540))
    curl = math.radians(rng.uniform(90, 220))
    pts = _round(radius, flat, rng.uniform(0, 2 * math.pi), rng.choice((-1.0, 1.0)) * sweep, sweep - curl,
                 rng.uniform(0.45, 0.85))
    if rng.random() < 0.5:
        pts = pts[::-1]
    return Mark("curled-in-circle", _placed(rng, pts), True)


def both_ends_in(seed: int) -> Mark:
    """A circle with a lead in from inside (`lead_in_circle`) and a last 60-120 degrees curling in to 0.7-0.9 of the
    radius (`curled_in_circle`), going round 300-380 degrees."""
    rng = random.Random(f"both-ends-in:{seed}")
    radius, flat = _rim(rng)
    way = rng.choice((-1.0, 1.0))
    start = rng.uniform(0, 2 * math.pi)
    sweep = math.radians(rng.uniform(300, 380))
    pts = _lead_in(rng, radius, flat, start, way)
    pts += _round(radius, flat, start, way * sweep, sweep - math.radians(rng.uniform(60, 120)), rng.uniform(0.7, 0.9))
    return Mark("both-ends-in", _placed(rng, pts), True)


def first_arc_redrawn(seed: int) -> Mark:
    """A circle whose pen lands on the rim, runs 30-90 degrees round it, comes back to where it landed (to within 5
    degrees either way) and goes round from there by 345-375 degrees (closing within 15 degrees): its first arc drawn
    twice over (session 23)."""
    rng = random.Random(f"first-arc-redrawn:{seed}")
    radius, flat = _rim(rng)
    way = rng.choice((-1.0, 1.0))
    start = rng.uniform(0, 2 * math.pi)
    out = way * math.radians(rng.uniform(30, 90))
    again = start + math.radians(rng.uniform(-5, 5))
    pts = _round(radius, flat, start, out) + _round(radius, flat, start + out, again - start - out)[1:]
    pts += _round(radius, flat, again, way * math.radians(rng.uniform(345, 375)))[1:]
    return Mark("first-arc-redrawn", _placed(rng, pts), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "lead-in-circle": lead_in_circle, "curled-in-circle": curled_in_circle, "both-ends-in": both_ends_in,
    "first-arc-redrawn": first_arc_redrawn}
"""Every family; each is read as a circle or an ellipse (`EXPECTED`)."""
