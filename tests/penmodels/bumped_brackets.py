"""Square brackets whose spine has a bump, a dent or a jog about halfway and whose last arm the pen may flick back at
the lift (hcira pixelfac/user01's left bracket 5: its spine bulges toward the opening; jonathanzhang53/s02's left
bracket 1: its spine dented in, its lower arm flicked back), and curly braces wobbled and flicked alike (still braces);
in canvas pixels, seeded; no motion, no noise (the pens draw them: `benchmarks/bench_bumped_brackets.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.bracket_habits import _bracket, _corner_radii, _flicked, _frame, _verts
from penmodels.open_marks import Mark, Point, _bezier, _placed

EXPECTED = {"dented-spine-bracket": "polyline", "bumped-spine-bracket": "polyline",
            "jogged-spine-bracket": "polyline", "wobbly-brace": "curve"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a square bracket is three straight sides, a polyline,
however its spine wobbles; a curly brace a curve)."""


def _moved(pts: list[Point], h: float, offset: Callable[[float], float]) -> list[Point]:
    """``pts`` (a left bracket about the origin, y down, its spine on x = 0 from -``h``/2 to ``h``/2) with each point
    moved sideways by ``offset`` of its place down the spine (0 at the top corner, 1 at the bottom), in pixels:
    positive toward the opening (the arms' side)."""
    return [(x + offset(min(max((y + h / 2) / h, 0.0), 1.0)), y) for x, y in pts]


def _flick_end(rng: random.Random, pts: list[Point], arm: float) -> list[Point]:
    """``pts`` with the pen flicked on at the lift half the time (`bracket_habits._flicked`): 0.1-0.3 of the last arm
    (at least 8 px) turning 90-170 degrees either way, back along the arm or off it."""
    if rng.random() < 0.5:
        return pts
    return _flicked(pts, max(8.0, rng.uniform(0.1, 0.3) * arm), rng.choice((-1.0, 1.0)) * rng.uniform(90, 170))


def dented_spine_bracket(seed: int) -> Mark:
    """A bracket whose spine is dented toward the opening: two straight pieces meeting at 0.35-0.65 of its length, the
    meeting point standing in so that the spine turns back 20-60 degrees there (against the corners' way: a brace's
    point turns with them, away from the opening); corners sharp or rounded over up to 0.4 of the arm, arms 0.25-0.5
    of the spine; the last arm flicked back half the time (jonathanzhang53/s02's left bracket 1)."""
    rng = random.Random(f"dented-spine-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    at = rng.uniform(0.35, 0.65)
    # the pieces meet at an angle of 180 minus the dent: the point stands off by that angle's half-tangent
    depth = math.tan(math.radians(rng.uniform(20, 60)) / 2) * at * (1 - at) * h
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.4), (0.0, 0.0, 0.0))
    pts = _moved(pts, h, lambda u: depth * (u / at if u <= at else (1 - u) / (1 - at)))
    return Mark("dented-spine-bracket", _placed(rng, _flick_end(rng, pts, a2), rng.random() < 0.5), True)


def bumped_spine_bracket(seed: int) -> Mark:
    """A bracket whose spine bulges toward the opening halfway (a raised cosine 2-6 % of the spine high, over 0.25-0.5
    of it, centred at 0.35-0.65), its corners rounded as a mouse swings round them, over 0.1-0.9 of each arm, arms
    0.25-0.5 of the spine; the last arm flicked back half the time (pixelfac/user01's left bracket 5)."""
    rng = random.Random(f"bumped-spine-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    radii = (rng.uniform(0.1, 0.9) * a1, rng.uniform(0.1, 0.9) * a2)
    high, width, at = rng.uniform(0.02, 0.06) * h, rng.uniform(0.25, 0.5), rng.uniform(0.35, 0.65)
    pts = _bracket(_verts(h, a1, a2), radii, (0.0, 0.0, 0.0))
    pts = _moved(pts, h, lambda u: high * (1 + math.cos(math.pi * min(abs(u - at) / (width / 2), 1.0))) / 2)
    return Mark("bumped-spine-bracket", _placed(rng, _flick_end(rng, pts, a2), rng.random() < 0.5), True)


def jogged_spine_bracket(seed: int) -> Mark:
    """A bracket whose spine steps sideways halfway (the hand re-grips: a smooth step of 3-8 % of the spine, either
    way, over 0.08-0.2 of it, at 0.35-0.65), the pieces above and below straight; corners sharp or rounded over up to
    0.4 of the arm, arms 0.25-0.5 of the spine; the last arm flicked back half the time."""
    rng = random.Random(f"jogged-spine-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    step = rng.choice((-1.0, 1.0)) * rng.uniform(0.03, 0.08) * h
    width, at = rng.uniform(0.08, 0.2), rng.uniform(0.35, 0.65)
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.4), (0.0, 0.0, 0.0))

    def jog(u: float) -> float:
        s = min(max((u - at) / width + 0.5, 0.0), 1.0)
        return step * s * s * (3 - 2 * s)

    # the step's half taken off everywhere keeps the arms where they were, the two pieces either side of the spine
    return Mark("jogged-spine-bracket", _placed(rng, _flick_end(rng, _moved(pts, h, lambda u: jog(u) - step / 2),
                                                                  a2), rng.random() < 0.5), True)


def wobbly_brace(seed: int) -> Mark:
    """A curly brace 120-320 px tall (curled ends, nearly straight halves, a point pointed or rounded, as
    `open_marks.brace`) whose halves carry a bump or a step of 2-6 % of its height (one half or both), its last curl
    flicked on half the time: a brace still, whose point turns with its curls, away from them."""
    rng = random.Random(f"wobbly-brace:{seed}")
    h = rng.uniform(120, 320)
    w = rng.uniform(0.08, 0.2) * h
    tip = rng.uniform(0.6, 1.2) * w
    curl = rng.uniform(0.08, 0.18) * h
    approach = rng.uniform(0.06, 0.14) * h
    sharp = rng.uniform(0.0, 1.0)
    half: list[Point] = [(w, -h / 2)]
    half += _bezier(half[-1], (0.2 * w, -h / 2), (0, -h / 2 + 0.3 * curl), (0, -h / 2 + curl), 12)
    top = half[-1][1]
    half += [(0.0, top + (-approach - top) * k / 16) for k in range(1, 17)]
    lead = 0.3 + 0.4 * sharp
    half += _bezier(half[-1], (0, -approach * lead), (-tip * lead, -0.15 * sharp * approach), (-tip, 0.0), 10)
    pts = half + [(x, -y) for x, y in reversed(half[:-1])]
    for at in (rng.uniform(0.15, 0.35), rng.uniform(0.65, 0.85)) if rng.random() < 0.5 else (
            rng.choice((rng.uniform(0.15, 0.35), rng.uniform(0.65, 0.85))),):
        size, width = rng.choice((-1.0, 1.0)) * rng.uniform(0.02, 0.06) * h, rng.uniform(0.08, 0.2)
        if rng.random() < 0.5:  # a bump
            pts = _moved(pts, h, lambda u, a=at, s=size, wd=width: s * (
                1 + math.cos(math.pi * min(abs(u - a) / (wd / 2), 1.0))) / 2)
        else:  # a step: the rest of the brace drawn that much aside
            pts = _moved(pts, h, lambda u, a=at, s=size, wd=width: s * _smoothstep((u - a) / wd + 0.5))
    return Mark("wobbly-brace", _placed(rng, _flick_end(rng, pts, curl), rng.random() < 0.5), True)


def _smoothstep(s: float) -> float:
    s = min(max(s, 0.0), 1.0)
    return s * s * (3 - 2 * s)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "dented-spine-bracket": dented_spine_bracket, "bumped-spine-bracket": bumped_spine_bracket,
    "jogged-spine-bracket": jogged_spine_bracket, "wobbly-brace": wobbly_brace}
