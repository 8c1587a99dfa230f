"""A pigtail (the $1 set's loop in an open stroke) drawn as people we have not seen draw it (issue 25: held-back people
read pigtails 94 %): its loop round and big between short tails, tall and narrow, or small between long tails of their
own lengths, or drawn first and left by one long tail; in canvas pixels, seeded; no motion, no noise (the pens draw
them, fast too: `benchmarks/bench_bracket_habits.py --marks pigtail`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _placed
from penmodels.x_habits import _cut_corners, _run

EXPECTED = {"round-loop-pigtail": "curve", "narrow-loop-pigtail": "curve", "long-tail-pigtail": "curve",
            "loop-first-pigtail": "curve", "straight-arm-pigtail": "curve"}
"""A pigtail is a loop in an open smooth stroke: a curve (benchmarks/label_kinds.tsv)."""


def _cycloid(ratio: float, before: float, after: float, tall: float, n: int = 100) -> list[Point]:
    """A prolate cycloid's arch (x = ratio t - sin t, y = -tall cos t) from t = -``before`` to ``after``: a stroke
    running in, round one loop and out, its loop ``tall`` times as high as a circle's."""
    ts = [-before + (before + after) * k / n for k in range(n + 1)]
    return [(ratio * t - math.sin(t), -tall * math.cos(t)) for t in ts]


def _sized(rng: random.Random, raw: list[Point], family: str) -> Mark:
    """``raw`` scaled to 100-260 px across its bounding box's diagonal, placed (`_placed`, turned half the time)."""
    xs, ys = [p[0] for p in raw], [p[1] for p in raw]
    scale = rng.uniform(100, 260) / math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    return Mark(family, _placed(rng, [(x * scale, y * scale) for x, y in raw], rng.random() < 0.5), True)


def round_loop_pigtail(seed: int) -> Mark:
    """A pigtail whose loop is nearly a circle and most of the stroke: tails of 0.05-0.25 pi of the cycloid's phase
    each past the crossing (c / r 0.08-0.2: the tails cross at a shallow angle)."""
    rng = random.Random(f"round-loop-pigtail:{seed}")
    ratio = rng.uniform(0.08, 0.2)
    raw = _cycloid(ratio, math.pi * rng.uniform(1.05, 1.25), math.pi * rng.uniform(1.05, 1.25), 1.0)
    return _sized(rng, raw, "round-loop-pigtail")


def narrow_loop_pigtail(seed: int) -> Mark:
    """A pigtail whose loop is 1.8-3 times as tall as it is wide (an l drawn in a hurry), c / r 0.2-0.5, tails of
    0.05-0.35 pi each."""
    rng = random.Random(f"narrow-loop-pigtail:{seed}")
    ratio = rng.uniform(0.2, 0.5)
    raw = _cycloid(ratio, math.pi * rng.uniform(1.05, 1.35), math.pi * rng.uniform(1.05, 1.35), rng.uniform(1.8, 3.0))
    return _sized(rng, raw, "narrow-loop-pigtail")


def long_tail_pigtail(seed: int) -> Mark:
    """A pigtail whose tails run on well past the loop, each its own length (0.35-0.6 pi of the phase past the
    bottom of the arch), c / r 0.25-0.5."""
    rng = random.Random(f"long-tail-pigtail:{seed}")
    ratio = rng.uniform(0.25, 0.5)
    raw = _cycloid(ratio, math.pi * rng.uniform(1.35, 1.6), math.pi * rng.uniform(1.35, 1.6), 1.0)
    return _sized(rng, raw, "long-tail-pigtail")


def loop_first_pigtail(seed: int) -> Mark:
    """A pigtail drawn loop first (issue 25, session 27: hcira klarubbio/s02 pigtail04, s07 pigtail03): the pen lands
    on an oval 1-2 times as long as wide, goes once round it and 0-40 degrees on past where it landed, and leaves by a
    tail bent 10-40 degrees outwards off the rim, gently curving (up to 25 degrees either way over its length), that
    runs 1.6-3 times the oval's half-length; drawn tail first half the time (`_placed`)."""
    rng = random.Random(f"loop-first-pigtail:{seed}")
    rx, start, way = 1.0, rng.uniform(0, 2 * math.pi), rng.choice((-1.0, 1.0))
    ry = rx / rng.uniform(1.0, 2.0)
    sweep = 2 * math.pi + math.radians(rng.uniform(0, 40))
    n = 90
    raw = [(rx * math.cos(start + way * sweep * k / n), ry * math.sin(start + way * sweep * k / n))
           for k in range(n + 1)]
    (x0, y0), (x1, y1) = raw[-2], raw[-1]
    heading = math.atan2(y1 - y0, x1 - x0)
    outwards = -way * math.radians(rng.uniform(10, 40))  # away from the centre: the loop turns the other way
    bend, length = math.radians(rng.uniform(-25, 25)), rng.uniform(1.6, 3.0) * rx
    steps = 40
    for k in range(1, steps + 1):
        a = heading + outwards + bend * k / steps
        x1, y1 = x1 + length / steps * math.cos(a), y1 + length / steps * math.sin(a)
        raw.append((x1, y1))
    return _sized(rng, raw, "loop-first-pigtail")


def straight_arm_pigtail(seed: int) -> Mark:
    """A pigtail drawn as a ribbon (session 30: hcira hat359 user1 pigtail05, user3 pigtail10, klarubbio s06
    pigtail05): straight tails crossing at 70-110 degrees, each running on straight past the crossing for 0.6-1 of its
    own length before the loop, a round cap bowed out by 0.3-0.6 of the arms' spread, rounded into both arms from
    0.75-0.9 of their length on; the geometry of an x with a round side (`x_habits.round_side_x`), which people also
    draw as a pigtail."""
    rng = random.Random(f"straight-arm-pigtail:{seed}")
    half = math.radians(rng.uniform(35, 55))
    u1, u2 = (math.sin(half), -math.cos(half)), (-math.sin(half), -math.cos(half))  # up the page (y down)
    tail1, tail2 = rng.uniform(0.8, 1.2), rng.uniform(0.8, 1.2)
    run1, run2 = tail1 * rng.uniform(0.6, 1.0), tail2 * rng.uniform(0.6, 1.0)
    a, p = (-u1[0] * tail1, -u1[1] * tail1), (u1[0] * run1, u1[1] * run1)
    q, d = (u2[0] * run2, u2[1] * run2), (-u2[0] * tail2, -u2[1] * tail2)
    r1, r2 = rng.uniform(0.75, 0.9), rng.uniform(0.75, 0.9)
    start = (a[0] + (p[0] - a[0]) * r1, a[1] + (p[1] - a[1]) * r1)
    end = (q[0] + (d[0] - q[0]) * (1 - r2), q[1] + (d[1] - q[1]) * (1 - r2))
    bow = rng.uniform(0.3, 0.6) * math.dist(p, q)
    cap = [start, p, (p[0], p[1] - bow), (q[0], q[1] - bow), q, end]
    step = 0.02
    raw = [a, *_run(a, start, step)[:-1], *_cut_corners(cap, 4), *_run(end, d, step)]
    return _sized(rng, raw, "straight-arm-pigtail")


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "round-loop-pigtail": round_loop_pigtail, "narrow-loop-pigtail": narrow_loop_pigtail,
    "long-tail-pigtail": long_tail_pigtail, "loop-first-pigtail": loop_first_pigtail,
    "straight-arm-pigtail": straight_arm_pigtail}
