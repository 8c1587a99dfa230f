"""Marks as a hand on a mouse or a trackpad draws them (issue 25: the held-back people who drew with a mouse and a
trackpad read rectangles 85.7 %, square brackets 89-90 %): what the hand does on such a device (klarubbio/s06's and
pixelfac/user01's mouse strokes among the design sources), one family per habit, in canvas pixels, seeded; no motion,
no noise (the pens draw them: `penmodels.hurried`, the virtual pen, and the hurried hand through a mouse's stair-stepped
whole pixels, bursts and repeats, `benchmarks/bench_mouse_habits.py`).

- ``splayed-bracket``: a mouse is swung from the wrist, so a bracket's arms splay out, each turned 8-20 degrees away
  from square (the heading turns 140-164 degrees in all, under a drawn bracket's half turn), and its corners are
  rounded over 0.3-0.7 of each arm (a mouse swings round a corner it cannot stop at);
- ``wrist-arc-bracket``: the spine swung as the wrist's arc (bowed 5-9 % of its length, out or in) and both corners
  rounded over 0.3-0.6 of the arm;
- ``slow-corner-bracket``: sharp corners at which the mouse stops and the hand re-grips (one corner's arm overshot
  3-8 px and pulled back onto the spine), arms splayed up to 12 degrees;
- ``crossed-close-box``: a rectangle drawn from off its first corner (the first side starts 0.05-0.25 of itself before
  the corner) whose last side runs on across the first by 0.05-0.25 of itself: a hash at the start corner, as a
  mouse hand makes who aims for the corner and overshoots it both times;
- ``rounded-mouse-box``: a rectangle whose four corners the mouse swings round by 0.12-0.25 of the shorter side,
  one wall leaned 4-12 degrees (no two sides exactly parallel).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.bracket_habits import _bracket, _frame, _verts
from penmodels.open_marks import Mark, Point, _placed

EXPECTED = {"splayed-bracket": "polyline", "wrist-arc-bracket": "polyline", "slow-corner-bracket": "polyline",
            "crossed-close-box": "box", "rounded-mouse-box": "box"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a square bracket is a polyline, a rectangle a box)."""


def splayed_bracket(seed: int) -> Mark:
    """A bracket whose arms splay out 8-20 degrees each, its corners rounded over 0.3-0.7 of each arm."""
    rng = random.Random(f"splayed-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    tilts = (-rng.uniform(8, 20), -rng.uniform(8, 20))
    radii = (rng.uniform(0.3, 0.7) * a1, rng.uniform(0.3, 0.7) * a2)
    pts = _bracket(_verts(h, a1, a2, *tilts), radii, (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("splayed-bracket", _placed(rng, pts, False), True)


def wrist_arc_bracket(seed: int) -> Mark:
    """A bracket whose spine is the wrist's arc (bowed 5-9 % either way), its corners rounded over 0.3-0.6 of the
    arm, its arms turned up to 8 degrees off square either way."""
    rng = random.Random(f"wrist-arc-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    tilts = (rng.uniform(-8, 8), rng.uniform(-8, 8))
    radii = (rng.uniform(0.3, 0.6) * a1, rng.uniform(0.3, 0.6) * a2)
    bow = rng.choice((-1.0, 1.0)) * rng.uniform(0.05, 0.09)
    pts = _bracket(_verts(h, a1, a2, *tilts), radii, (0.0, bow, 0.0))
    return Mark("wrist-arc-bracket", _placed(rng, pts, False), True)


def slow_corner_bracket(seed: int) -> Mark:
    """A bracket with sharp corners, one of which the mouse overshoots by 3-8 px along the arm's line and is pulled
    back onto the spine; arms splayed up to 12 degrees each."""
    rng = random.Random(f"slow-corner-bracket:{seed}")
    h, a1, a2 = _frame(rng)
    e0, c1, c2, e3 = _verts(h, a1, a2, -rng.uniform(0, 12), -rng.uniform(0, 12))
    over = rng.uniform(3, 8)
    if rng.random() < 0.5:
        d = math.dist(e0, c1)
        past = (c1[0] + (c1[0] - e0[0]) * over / d, c1[1] + (c1[1] - e0[1]) * over / d)
        pts = [e0, past, c1, c2, e3]
    else:
        d = math.dist(c1, c2)
        past = (c2[0] + (c2[0] - c1[0]) * over / d, c2[1] + (c2[1] - c1[1]) * over / d)
        pts = [e0, c1, past, c2, e3]
    return Mark("slow-corner-bracket", _placed(rng, pts, False), False)


def _box(rng: random.Random) -> list[Point]:
    """A rectangle's corners round the origin (aspect 1-2.5, the larger side 80-360 px), drawn from a random corner,
    either way round."""
    big = rng.uniform(80, 360)
    small = big / rng.uniform(1.0, 2.5)
    w, h = (big, small) if rng.random() < 0.5 else (small, big)
    c = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
    if rng.random() < 0.5:
        c = c[::-1]
    k = rng.randrange(4)
    return c[k:] + c[:k]


def _along(a: Point, b: Point, f: float) -> Point:
    return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))


def crossed_close_box(seed: int) -> Mark:
    """A rectangle begun 0.05-0.25 of its first side before the first corner and closed 0.05-0.25 of its last side
    past the first side: the pen crosses its own start."""
    rng = random.Random(f"crossed-close-box:{seed}")
    c = _box(rng)
    pts = [_along(c[1], c[0], 1 + rng.uniform(0.05, 0.25)), c[1], c[2], c[3], _along(c[3], c[0], 1 + rng.uniform(
        0.05, 0.25))]
    return Mark("crossed-close-box", _placed(rng, pts, False), False)


def _rounded(c: list[Point], share: float) -> list[Point]:
    """The closed outline through ``c`` with every corner cut by ``share`` of the shorter side into a quadratic bend
    (nine points), from the middle of the first side round to it again."""
    short = min(math.dist(c[0], c[1]), math.dist(c[1], c[2]))
    out: list[Point] = [_along(c[0], c[1], 0.5)]
    for i in range(1, 5):
        v, before, after = c[i % 4], c[i - 1], c[(i + 1) % 4]
        a = _along(v, before, share * short / math.dist(v, before))
        b = _along(v, after, share * short / math.dist(v, after))
        out += [((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * v[0] + u * u * b[0],
                 (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * v[1] + u * u * b[1]) for u in (k / 8 for k in range(9))]
    out.append(out[0])
    return out


def rounded_mouse_box(seed: int) -> Mark:
    """A rectangle with every corner swung round by 0.12-0.25 of the shorter side and one wall leaned 4-12 degrees."""
    rng = random.Random(f"rounded-mouse-box:{seed}")
    c = _box(rng)
    lean = math.radians(rng.uniform(4, 12)) * rng.choice((-1.0, 1.0))
    slide = math.dist(c[0], c[1]) * math.tan(lean)
    c[1] = _along(c[1], c[2], slide / math.dist(c[1], c[2]))
    return Mark("rounded-mouse-box", _placed(rng, _rounded(c, rng.uniform(0.12, 0.25)), False), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "splayed-bracket": splayed_bracket, "wrist-arc-bracket": wrist_arc_bracket,
    "slow-corner-bracket": slow_corner_bracket, "crossed-close-box": crossed_close_box,
    "rounded-mouse-box": rounded_mouse_box}
