"""Open marks as a person means them (issue 25): curly braces, question marks, square brackets and pigtails, in canvas
pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from dataclasses import dataclass

Point = tuple[float, float]
EXPECTED = {"brace": "curve", "angular-brace": "curve", "question": "curve", "bracket": "polyline",
            "rounded-bracket": "polyline", "pigtail": "curve"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: braces, question marks and pigtails are curves, square
brackets polylines, their corners sharp or rounded)."""


@dataclass(frozen=True, slots=True)
class Mark:
    """A mark of ``family`` as meant: its ``points`` (dense along a smooth mark, its corners for a sharp bracket), in
    drawing order; ``smooth`` when a pen should follow it as a curve, not turn at its points as corners."""

    family: str
    points: tuple[Point, ...]
    smooth: bool


def _bezier(p0: Point, p1: Point, p2: Point, p3: Point, n: int) -> list[Point]:
    """A cubic from ``p0`` to ``p3``, ``n`` points after ``p0``."""
    out = []
    for k in range(1, n + 1):
        u = k / n
        a, b, c, d = (1 - u) ** 3, 3 * u * (1 - u) ** 2, 3 * u * u * (1 - u), u ** 3
        out.append((a * p0[0] + b * p1[0] + c * p2[0] + d * p3[0], a * p0[1] + b * p1[1] + c * p2[1] + d * p3[1]))
    return out


def _arc(centre: Point, radius: float, start: float, sweep: float, n: int) -> list[Point]:
    """``n`` points after the start of an arc (radians, y down: a positive sweep turns clockwise on screen)."""
    return [(centre[0] + radius * math.cos(start + sweep * k / n), centre[1] + radius * math.sin(start + sweep * k / n))
            for k in range(1, n + 1)]


def _placed(rng: random.Random, pts: list[Point], turned: bool) -> tuple[Point, ...]:
    """``pts`` (round the origin) mirrored half the time, drawn the other way half the time, turned a random angle
    (``turned``) or up to 12 degrees, and moved to a random place on the 1600 x 1000 canvas."""
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]
    if rng.random() < 0.5:
        pts = pts[::-1]
    angle = rng.uniform(0, 2 * math.pi) if turned else math.radians(rng.uniform(-12, 12))
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in pts)


def brace(seed: int) -> Mark:
    """A curly brace 120-320 px tall: curled ends, arms nearly straight (bowed up to 4 % of their length) and a point
    in the middle, pointed or rounded; either way round, drawn from either end, turned half the time."""
    rng = random.Random(seed)
    h = rng.uniform(120, 320)
    w = rng.uniform(0.08, 0.2) * h  # how far the curls stand from the spine
    tip = rng.uniform(0.6, 1.2) * w  # how far the point stands out the other way
    curl = rng.uniform(0.08, 0.18) * h
    approach = rng.uniform(0.06, 0.14) * h  # the arm's length given to the bend into the point
    sharp = rng.uniform(0.0, 1.0)  # 0: the point a cusp, 1: rounded
    bow = rng.uniform(-0.04, 0.04) * h
    half: list[Point] = [(w, -h / 2)]
    half += _bezier(half[-1], (0.2 * w, -h / 2), (0, -h / 2 + 0.3 * curl), (0, -h / 2 + curl), 12)
    arm_end = (0.0, -approach)
    mid = (bow, (half[-1][1] + arm_end[1]) / 2)
    half += _bezier(half[-1], (mid[0], half[-1][1] + 0.3 * (arm_end[1] - half[-1][1])),
                    (mid[0], half[-1][1] + 0.7 * (arm_end[1] - half[-1][1])), arm_end, 16)
    lead = 0.3 + 0.4 * sharp
    half += _bezier(arm_end, (0, -approach * lead), (-tip * lead, -0.15 * sharp * approach), (-tip, 0.0), 10)
    pts = half + [(x, -y) for x, y in reversed(half[:-1])]
    return Mark("brace", _placed(rng, pts, rng.random() < 0.5), True)


def angular_brace(seed: int) -> Mark:
    """A curly brace as a mouse draws one, 120-320 px tall: straight runs between cusps (each end's curl a short
    run, each arm a long one, the point two short ones); drawn as `brace` is placed, its corners turned as a pen turns
    any corner. Still a brace: a curve (`open_shapes.BRACE_TIP`)."""
    rng = random.Random(seed)
    return Mark("angular-brace", _placed(rng, angular_brace_corners(rng), rng.random() < 0.5), False)


def angular_brace_corners(rng: random.Random) -> list[tuple[float, float]]:
    """The corners of a brace of straight runs 120-320 px tall, its point to the left of its arms, about the origin."""
    h = rng.uniform(120, 320)
    w = rng.uniform(0.1, 0.25) * h
    tip = rng.uniform(0.6, 1.5) * w
    curl = rng.uniform(0.06, 0.18) * h
    approach = rng.uniform(0.03, 0.12) * h
    return [(w, -h / 2), (0.0, -h / 2 + curl), (0.0, -approach), (-tip, 0.0), (0.0, approach), (0.0, h / 2 - curl),
            (w * rng.uniform(0.8, 1.2), h / 2)]


def question(seed: int) -> Mark:
    """A question mark 120-300 px tall: a hook turning 200-300 degrees over the top, its size 0.25-0.55 of the height,
    then a stem straight down from a bend, or bent (an S into the stem); mirrored half the time (a hand's slip, still
    a curve), turned a little."""
    rng = random.Random(seed)
    height = rng.uniform(120, 300)
    r = rng.uniform(0.25, 0.55) * height / 2
    start = math.radians(rng.uniform(150, 200))  # on the left of the hook (y down: 180 is the left)
    sweep = math.radians(rng.uniform(200, 300))  # clockwise on screen: up, over the top, down
    pts: list[Point] = [(r * math.cos(start), r * math.sin(start))]
    pts += _arc((0.0, 0.0), r, start, sweep, 40)
    end = start + sweep
    heading = (-math.sin(end), math.cos(end))  # the hook's direction where it ends
    stem = height - 2 * r
    foot = (pts[-1][0] + rng.uniform(-0.15, 0.15) * stem, pts[-1][1] + stem)
    lead = rng.uniform(0.05, 0.15) if rng.random() < 0.5 else rng.uniform(0.3, 0.5)  # a bend, or an S
    pts += _bezier(pts[-1], (pts[-1][0] + heading[0] * lead * stem, pts[-1][1] + heading[1] * lead * stem),
                   (foot[0], foot[1] - lead * stem), foot, 20)
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]
    angle, cx, cy = math.radians(rng.uniform(-12, 12)), rng.uniform(500, 1100), rng.uniform(350, 650)
    return Mark("question", tuple((cx + x, cy + y) for x, y in _turned(pts, angle)), True)


def _turned(pts: list[Point], angle: float) -> list[Point]:
    c, s = math.cos(angle), math.sin(angle)
    return [(x * c - y * s, x * s + y * c) for x, y in pts]


def bracket(seed: int) -> Mark:
    """A square bracket 120-320 px tall, its arms 0.2-0.5 of its spine, sharp corners (the pen turns them as it
    turns any corner); either way round, from either end, turned half the time."""
    rng = random.Random(seed)
    h = rng.uniform(120, 320)
    a = rng.uniform(0.2, 0.5) * h
    pts = [(a, -h / 2), (0.0, -h / 2), (0.0, h / 2), (a * rng.uniform(0.85, 1.15), h / 2)]
    return Mark("bracket", _placed(rng, pts, rng.random() < 0.5), False)


def rounded_bracket(seed: int) -> Mark:
    """A square bracket as `bracket` whose corners are rounded off, each over 0.2-0.6 of its arm (a hand in a hurry
    swinging round them): still three straight sides, a bracket."""
    rng = random.Random(seed)
    h = rng.uniform(120, 320)
    a = rng.uniform(0.25, 0.5) * h
    a2 = a * rng.uniform(0.85, 1.15)
    r1, r2 = rng.uniform(0.2, 0.6) * a, rng.uniform(0.2, 0.6) * a2
    pts: list[Point] = [(a, -h / 2), (r1, -h / 2)]
    pts += _bezier(pts[-1], (0.45 * r1, -h / 2), (0.0, -h / 2 + 0.45 * r1), (0.0, -h / 2 + r1), 10)
    pts += [(0.0, -h / 2 + r1 + k * (h - r1 - r2) / 8) for k in range(1, 9)]
    pts += _bezier(pts[-1], (0.0, h / 2 - 0.45 * r2), (0.45 * r2, h / 2), (r2, h / 2), 10)
    pts += [(r2 + k * (a2 - r2) / 4, h / 2) for k in range(1, 5)]
    return Mark("rounded-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def pigtail(seed: int) -> Mark:
    """A pigtail 100-260 px across: a stroke running in, round one loop and out (a prolate cycloid's arch: x = c t -
    r sin t, y = -r cos t, c / r 0.2-0.5); either way, turned half the time."""
    rng = random.Random(seed)
    size = rng.uniform(100, 260)
    ratio = rng.uniform(0.2, 0.5)  # c / r: the loop's width against its tails
    reach = rng.uniform(1.05, 1.35) * math.pi
    ts = [-reach + 2 * reach * k / 80 for k in range(81)]
    raw = [(ratio * t - math.sin(t), -math.cos(t)) for t in ts]
    xs, ys = [p[0] for p in raw], [p[1] for p in raw]
    scale = size / math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    return Mark("pigtail", _placed(rng, [(x * scale, y * scale) for x, y in raw], rng.random() < 0.5), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "brace": brace, "angular-brace": angular_brace, "question": question, "bracket": bracket,
    "rounded-bracket": rounded_bracket, "pigtail": pigtail}
