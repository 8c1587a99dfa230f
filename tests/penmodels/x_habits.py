"""An x drawn in one stroke as people we have not seen draw it (issue 25: held-back people read one-stroke x's 92 %
where design people read 98-99 %): a diagonal, a side, the other diagonal, the two diagonals crossing off their
middles (the hand slides the second along the first), so that the crossing closes a triangle between tails of unequal
length; in canvas pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen;
`benchmarks/bench_bracket_habits.py --marks x`)."""

from __future__ import annotations

import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _placed

EXPECTED = {"offset-x": "polyline"}
"""An x in one stroke is straight sides joined by a diagonal: a polyline (benchmarks/label_kinds.tsv)."""


def offset_x(seed: int) -> Mark:
    """An x 120-300 px tall, 0.6-1.2 as wide: a diagonal down, a side up, the other diagonal down, the diagonals
    crossing 0.2-0.4 of the way along each from the stroke's start and end (not at their middles: the tail before the
    crossing shorter than the triangle it closes), each tail its own length; either way round, from either end, turned
    half the time. Its vertices are straight sides' corners: the pens turn them as any corner."""
    rng = random.Random(f"offset-x:{seed}")
    h = rng.uniform(120, 300)
    w = h * rng.uniform(0.6, 1.2)
    first, second = rng.uniform(0.2, 0.4), rng.uniform(0.2, 0.4)
    # the side from (w, 0) to (w, h); the crossing X at ``first`` of the first diagonal from its start A, which runs
    # to (w, 0), and at ``second`` of the second diagonal (from (w, h) to D) from its end D
    cross = (w * 0.0, h * 0.5)
    a = (cross[0] - first / (1 - first) * (w - cross[0]), cross[1] - first / (1 - first) * (h - cross[1]))
    d = (cross[0] - second / (1 - second) * (w - cross[0]), cross[1] + second / (1 - second) * (cross[1]))
    pts: list[Point] = [a, (w, h), (w, 0.0), d]
    mid = (sum(p[0] for p in pts) / 4, sum(p[1] for p in pts) / 4)
    pts = [(x - mid[0], y - mid[1]) for x, y in pts]
    return Mark("offset-x", _placed(rng, pts, rng.random() < 0.5), False)


FAMILIES: dict[str, Callable[[int], Mark]] = {"offset-x": offset_x}
