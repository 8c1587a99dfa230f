"""A pigtail (the $1 set's loop in an open stroke) drawn as people we have not seen draw it (issue 25: held-back people
read pigtails 94 %): its loop round and big between short tails, tall and narrow, or small between long tails of their
own lengths; in canvas pixels, seeded; no motion, no noise (the pens draw them, fast too:
`benchmarks/bench_bracket_habits.py --marks pigtail`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _placed

EXPECTED = {"round-loop-pigtail": "curve", "narrow-loop-pigtail": "curve", "long-tail-pigtail": "curve"}
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


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "round-loop-pigtail": round_loop_pigtail, "narrow-loop-pigtail": narrow_loop_pigtail,
    "long-tail-pigtail": long_tail_pigtail}
