"""Parentheses as people and devices not seen draw them (issue 25, session 24): one bow, shallow or deep, round or
flat in the middle, small or large, with or without a hook where the pen landed or lifted; in canvas pixels, seeded,
no noise (the pens draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_paren_habits.py`)."""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _arc, _placed

EXPECTED = ("arc", "curve")
"""The kinds a parenthesis may be read as (benchmarks/label_kinds.tsv, laviola: one smooth open bow, an arc, or a
curve where it bends unevenly)."""


def _round_bow(sweep: float, height: float) -> list[Point]:
    """A circular bow turning ``sweep`` radians (y down, from its top down, bulging to -x: a left parenthesis), 48
    points, ``height`` tall (its chord up to a half turn, its diameter past one); 60 degrees stand off the chord 0.13
    of it, 120 degrees 0.29."""
    r = height / (2 * math.sin(sweep / 2)) if sweep <= math.pi else height / 2
    start = math.pi + sweep / 2  # y down: from above the centre's left, anticlockwise on screen through its left
    pts = [(r * math.cos(start), r * math.sin(start))]
    pts += _arc((0.0, 0.0), r, start, -sweep, 48)
    return [(x, -y) for x, y in pts]


def _flat_bow(rng: random.Random, turn: float, height: float) -> list[Point]:
    """A bow flatter in its middle than a circle's, turning ``turn`` radians: x = -depth (1 - |u|^p), p 2.5-4, its ends
    heading ``turn / 2`` off the upright (at most 60 degrees: flatter still, with ends swept nearly level, it is a
    square bracket rounded at its corners), its deepest point up to a fifth of the height off its middle."""
    p = rng.uniform(2.5, 4.0)
    depth = math.tan(min(turn / 2, math.radians(60))) * height / (2 * p)
    shift = rng.uniform(-0.2, 0.2)
    pts = []
    for k in range(49):
        t = 1 - 2 * k / 48  # the top (t = 1) down to the bottom
        u = (t - shift) / (1 - shift) if t >= shift else (t - shift) / (1 + shift)
        pts.append((-depth * (1 - abs(u) ** p), -t * height / 2))
    return pts


def _bow(rng: random.Random, low: float, high: float, sweeps: tuple[float, float]) -> list[Point]:
    """A parenthesis' bow ``low``-``high`` px tall turning ``sweeps`` degrees: round half the time, else flat in the
    middle (turning at most 120 degrees)."""
    height = rng.uniform(low, high)
    sweep = math.radians(rng.uniform(*sweeps))
    return _round_bow(sweep, height) if rng.random() < 0.5 else _flat_bow(rng, sweep, height)


def _lopsided_bow(rng: random.Random, low: float, high: float, sweeps: tuple[float, float]) -> list[Point]:
    """A bow ``low``-``high`` px tall whose deepest point lies 0.15-0.35 of its height from one end (x = -depth (1 -
    |u|^p), p 1.6-2.6, u running from -1 at the near end through 0 at the deepest point to 1 at the far one: the near
    part curls tightly, the far part is a long, gentle sweep), turning about ``sweeps`` degrees in all."""
    height = rng.uniform(low, high)
    turn = math.radians(rng.uniform(*sweeps))
    p = rng.uniform(1.6, 2.6)
    near = rng.uniform(0.15, 0.35)  # the deepest point's place, as a share of the height from the top
    # the near end heads steepest: tan(heading) = depth p / (near height); half the turn is done by each side at most
    depth = math.tan(min(turn / 2, math.radians(70))) * near * height / p
    pts = []
    for k in range(49):
        y = height * k / 48  # the top down
        u = (y - near * height) / (near * height) if y < near * height else (y - near * height) / ((1 - near) * height)
        pts.append((-depth * (1 - abs(u) ** p), y - height / 2))
    return pts


def _hook(rng: random.Random, pts: list[Point]) -> list[Point]:
    """``pts`` with a hook before their first point, where the pen landed moving: 2-6 px and 2-6 % of the path more,
    turning 60-160 degrees into the bow's start, curling either way (on round the bow or against it)."""
    path = sum(math.dist(a, b) for a, b in itertools.pairwise(pts))
    reach = rng.uniform(2.0, 6.0) + rng.uniform(0.02, 0.06) * path
    (x0, y0), (x1, y1) = pts[0], pts[3]
    heading = math.atan2(y1 - y0, x1 - x0)
    bend = math.radians(rng.uniform(60, 160)) * rng.choice((-1.0, 1.0))
    back = [pts[0]]
    for k in range(1, 9):  # walking back from the bow's start, turning away from its heading
        a = heading + math.pi + bend * k / 8
        back.append((back[-1][0] + reach / 8 * math.cos(a), back[-1][1] + reach / 8 * math.sin(a)))
    return back[:0:-1] + pts


def _hooked(rng: random.Random, pts: list[Point]) -> list[Point]:
    """``pts`` with a landing hook at their start, and a lifting hook at their end a third of the time."""
    pts = _hook(rng, pts)
    if rng.random() < 1 / 3:
        pts = _hook(rng, pts[::-1])[::-1]
    return pts


def _paren(name: str, low: float, high: float, sweeps: tuple[float, float], hooked: bool) -> Callable[[int], Mark]:
    def family(seed: int) -> Mark:
        rng = random.Random(f"{name}:{seed}")
        pts = _bow(rng, low, high, sweeps)
        if hooked:
            pts = _hooked(rng, pts)
        return Mark(name, _placed(rng, pts, False), True)
    family.__doc__ = (f"A parenthesis {low:g}-{high:g} px tall turning {sweeps[0]:g}-{sweeps[1]:g} degrees, round or "
                      "flat in the middle (`_bow`)"
                      f"{', with a landing hook (`_hooked`)' if hooked else ''}; left or right, drawn from either end, "
                      "turned up to 12 degrees.")
    return family


def lopsided_paren(seed: int) -> Mark:
    """A parenthesis 40-320 px tall curling tightly near one end and sweeping gently the rest of the way
    (`_lopsided_bow`, 60-160 degrees), a landing hook half the time (`_hooked`); left or right, drawn from either end,
    turned up to 12 degrees."""
    rng = random.Random(f"lopsided-paren:{seed}")
    pts = _lopsided_bow(rng, 40, 320, (60, 160))
    if rng.random() < 0.5:
        pts = _hooked(rng, pts)
    return Mark("lopsided-paren", _placed(rng, pts, False), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "shallow-paren": _paren("shallow-paren", 60, 320, (60, 120), False),
    "deep-paren": _paren("deep-paren", 60, 320, (120, 200), False),
    "small-paren": _paren("small-paren", 15, 60, (60, 200), False),
    "hooked-paren": _paren("hooked-paren", 60, 320, (60, 200), True),
    "small-hooked-paren": _paren("small-hooked-paren", 15, 60, (60, 200), True),
    "lopsided-paren": lopsided_paren,
}
"""The families: shallow (60-120 degrees) and deep (120-200 degrees) bows 60-320 px tall, small ones 15-60 px, and
each size with a hook where the pen landed (and lifted, a third of the time), and lopsided bows curling near one end;
the hurried pens add their own small hooks."""
