"""Rectangles with the slips `box_habits` does not draw (issue 25, session 24: a wide gap at the close, a box begun
mid-wall and left open, corners rounded and left open, a spur at a corner, a lead-in, two laps apart, a deep bow, a cut
corner), one family per slip, in canvas pixels, seeded; no motion, no noise (the pens draw them).

Every family draws one box as `box_habits` does (aspect 1-2.5, 60-400 px across, turned up to 7 degrees, from one of
its corners, either way round: `box_habits._corners`) and changes one thing about it:

- ``gap-wide``: the fourth side stops 0.4-0.65 of its length short of the start (a hand that lifts once the box is
  plain to see);
- ``mid-wall-open``: the pen lands 0.2-0.6 along the first side, goes round every corner and lifts 0.0-0.1 of a side
  past the corner before the start: all four corners drawn, part of the first side not (itt Bam33751 rectangle_09);
- ``rounded-left-open``: one or two corners swung round (0.2-0.45 of the shorter side) and the fourth side stops
  0.15-0.35 short;
- ``corner-spur``: at one or two corners the pen runs on 5-15 % of the side past the corner and comes back to it
  before turning (an overshoot the hand pulls back, as a mouse stopping late does);
- ``lead-in``: the pen lands 0.1-0.3 of the shorter side away from the first corner, outside the box or inside it,
  and runs into the corner before drawing the box;
- ``laps-apart``: the box gone round twice, the second lap drifting out (or in) from the start, its sides 6-15 % of the
  box's size beside the first's (hcira shriyansnidhish s02);
- ``side-bowed-deep``: one side bowed out or in by 12-20 % of its length;
- ``corner-cut``: one corner (not the first) cut straight across, 0.15-0.3 of the shorter side back along each side.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.box_habits import _along, _corners, _placed, _side, _swung, _upright, bowed_side, cut_corner
from penmodels.shapes import Path

Point = tuple[float, float]


def gap_wide(rng: random.Random) -> Path:
    c = _corners(rng)
    return _placed([*c, _along(c[3], c[0], 1.0 - rng.uniform(0.4, 0.65))], _upright(rng))


def mid_wall_open(rng: random.Random) -> Path:
    c = _corners(rng)
    f = rng.uniform(0.2, 0.6)
    end = _along(c[0], c[1], rng.uniform(0.0, 0.1) * min(1.0, f / 0.2))  # no further than the start
    return _placed([_along(c[0], c[1], f), c[1], c[2], c[3], c[0], end], _upright(rng))


def rounded_left_open(rng: random.Random) -> Path:
    c = _corners(rng)
    which = {rng.randrange(1, 4)} if rng.random() < 0.5 else set(rng.sample((1, 2, 3), 2))
    pts = _swung(c, which, rng, (0.2, 0.45))[:-1]  # without the closing corner
    return _placed([*pts, _along(c[3], c[0], 1.0 - rng.uniform(0.15, 0.35))], _upright(rng))


def corner_spur(rng: random.Random) -> Path:
    c = _corners(rng)
    spurred = set(rng.sample((1, 2, 3), rng.randint(1, 2)))
    pts: list[Point] = [c[0]]
    for i in (1, 2, 3):
        pts.append(c[i])
        if i in spurred:
            before = c[i - 1]
            past = rng.uniform(0.05, 0.15) * _side(before, c[i])
            off = rng.uniform(-0.02, 0.02) * _side(before, c[i])
            pts += [_along(before, c[i], 1.0 + past / _side(before, c[i]), off), c[i]]
    return _placed([*pts, c[0]], _upright(rng))


def lead_in(rng: random.Random) -> Path:
    c = _corners(rng)
    shorter = min(_side(c[0], c[1]), _side(c[1], c[2]))
    reach = rng.uniform(0.1, 0.3) * shorter
    out = (c[0][0], c[0][1])
    heading = math.atan2(out[1], out[0]) + math.radians(rng.uniform(-35.0, 35.0))  # from the box's middle outward
    if rng.random() < 0.5:
        heading += math.pi  # from inside the box
    start = (c[0][0] + reach * math.cos(heading), c[0][1] + reach * math.sin(heading))
    return _placed([start, *c, c[0]], _upright(rng))


def laps_apart(rng: random.Random) -> Path:
    c = _corners(rng)
    grow = 1.0 + rng.choice((-1.0, 1.0)) * rng.uniform(0.12, 0.3)  # each side 6-15 % of the box out (or in)
    second = [(x * grow, y * grow) for x, y in c]
    return _placed([*c, c[0], *second[1:], second[0]], _upright(rng))  # the second lap drifting out from the start


def side_bowed_deep(rng: random.Random) -> Path:
    return bowed_side(rng, 0.12, 0.2)


def corner_cut(rng: random.Random) -> Path:
    c = _corners(rng)
    k = rng.randrange(1, 4)
    pts = cut_corner(c, k, rng.uniform(0.15, 0.3))
    return _placed([*pts, c[0]], _upright(rng))


FAMILIES: dict[str, Callable[[random.Random], Path]] = {
    "gap-wide": gap_wide, "mid-wall-open": mid_wall_open, "rounded-left-open": rounded_left_open,
    "corner-spur": corner_spur, "lead-in": lead_in, "laps-apart": laps_apart, "side-bowed-deep": side_bowed_deep,
    "corner-cut": corner_cut,
}
"""Every family, by name; each is read as a box."""


def drawn(family: str, seed: int) -> Path:
    """The box of ``family`` for ``seed``, from its own generator (``random.Random(f"{family}:{seed}")``)."""
    return FAMILIES[family](random.Random(f"{family}:{seed}"))
