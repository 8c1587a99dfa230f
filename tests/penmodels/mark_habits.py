"""Open marks as people of the design sets drew them (issue 25, session 23): a tick swung round its point whose pen
landed with a hook curling back into the short arm, and a question mark whose hook meets its stem at a corner; in
canvas pixels, seeded, no noise (the pens draw them: `penmodels.hurried`, the virtual pen)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, _arc, _bezier

Point = tuple[float, float]
EXPECTED = {"hooked-swung-tick": "polyline", "cornered-question": "curve"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a check or a tick is a polyline, a question mark a
curve)."""


def _rotated(v: Point, angle: float) -> Point:
    c, s = math.cos(angle), math.sin(angle)
    return (v[0] * c - v[1] * s, v[0] * s + v[1] * c)


def _placed(rng: random.Random, pts: list[Point]) -> tuple[Point, ...]:
    """``pts`` (round the origin) mirrored half the time (a left hand's mark), turned up to 12 degrees (a person draws
    these about upright) and moved to a random place on the 1600 x 1000 canvas."""
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]
    angle = math.radians(rng.uniform(-12, 12))
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x, cy + y) for x, y in (_rotated(p, angle) for p in pts))


def _hook(rng: random.Random, start: Point, heading: Point, reach: float) -> list[Point]:
    """A hook where the pen landed, ending at ``start`` heading along ``heading`` (a unit vector): an arc of ``reach``
    path turning 100-160 degrees into the heading, curling either way (the points before ``start``)."""
    sweep = math.radians(rng.uniform(100, 160)) * (1 if rng.random() < 0.5 else -1)
    r = reach / abs(sweep)
    normal = (-heading[1], heading[0]) if sweep > 0 else (heading[1], -heading[0])  # the curl's centre side
    centre = (start[0] + r * normal[0], start[1] + r * normal[1])
    a_end = math.atan2(start[1] - centre[1], start[0] - centre[0])
    back = _arc(centre, r, a_end, -sweep, 8)  # from ``start`` back along the hook
    return back[::-1]


def hooked_swung_tick(seed: int) -> Mark:
    """A tick as pixelfac/user02's check7 (hcira): a long arm 140-300 px going up at 40-60 degrees, a short arm
    0.25-0.45 of it coming down at 35-55 degrees, the point swung round by an arc tangent to both taking 0.5-0.8 of the
    short arm (`tests/test_tick_marks.swung_tick`'s tick, `bracket_marks.rounded_point`), and where the pen landed a
    hook of 4-8 % of the path curling back 100-160 degrees into the short arm (a mouse or finger set down moving); a
    hook where it lifted too, a third of the time."""
    rng = random.Random(f"hooked-swung-tick:{seed}")
    long_arm = rng.uniform(140, 300)
    short_arm = rng.uniform(0.25, 0.45) * long_arm
    down, up = math.radians(rng.uniform(35, 55)), math.radians(rng.uniform(40, 60))
    inner = math.pi - down - up  # the angle between the arms at the point
    t = rng.uniform(0.5, 0.8) * short_arm  # from the point to where the round bend meets each arm
    r = t * math.tan(inner / 2)
    d_in, d_out = (math.cos(down), math.sin(down)), (math.cos(up), -math.sin(up))  # y down: in goes down, out up
    start = (-short_arm * d_in[0], -short_arm * d_in[1])
    enter, leave = (-t * d_in[0], -t * d_in[1]), (t * d_out[0], t * d_out[1])
    normal = (d_in[1], -d_in[0])  # y down: the point turns anticlockwise on screen, its centre above the heading in
    centre = (enter[0] + r * normal[0], enter[1] + r * normal[1])
    a0 = math.atan2(enter[1] - centre[1], enter[0] - centre[0])
    a1 = math.atan2(leave[1] - centre[1], leave[0] - centre[0])
    if a1 > a0:
        a1 -= 2 * math.pi
    length = short_arm + long_arm
    pts = _hook(rng, start, d_in, rng.uniform(0.04, 0.08) * length)
    pts += [start, *[(start[0] + (enter[0] - start[0]) * k / 6, start[1] + (enter[1] - start[1]) * k / 6)
                     for k in range(1, 6)]]
    pts += [enter, *_arc(centre, r, a0, a1 - a0, 12)]
    end = (long_arm * d_out[0], long_arm * d_out[1])
    pts += [(leave[0] + (end[0] - leave[0]) * k / 12, leave[1] + (end[1] - leave[1]) * k / 12) for k in range(1, 13)]
    if rng.random() < 1 / 3:  # a hook where the pen lifted, curling back from the long arm's end
        lift = _hook(rng, end, (-d_out[0], -d_out[1]), rng.uniform(0.03, 0.06) * length)
        pts += lift[::-1][1:]
    return Mark("hooked-swung-tick", _placed(rng, pts), True)


def cornered_question(seed: int) -> Mark:
    """A question mark 120-300 px tall as itt:MaximilianKilger's (mouse) and dollar1's: a round hook 0.3-0.55 of the
    height across turning 230-290 degrees over the top and round into the middle, then a stem leaving it at a corner
    (turning 40-110 degrees where hook and stem meet) and running straight down, or bowed a little (up to 6 % of its
    length); mirrored half the time (a hand's slip, still a question mark), turned a little."""
    rng = random.Random(f"cornered-question:{seed}")
    height = rng.uniform(120, 300)
    r = rng.uniform(0.3, 0.55) * height / 2
    start = math.radians(rng.uniform(160, 200))  # on the left of the hook (y down: 180 is the left)
    sweep = math.radians(rng.uniform(230, 290))  # clockwise on screen: up, over the top, down and round
    pts: list[Point] = [(r * math.cos(start), r * math.sin(start))]
    pts += _arc((0.0, 0.0), r, start, sweep, 40)
    stem = height - 2 * r * rng.uniform(0.8, 1.0)
    foot = (pts[-1][0] + rng.uniform(-0.12, 0.12) * stem, pts[-1][1] + stem)
    bow = rng.uniform(-0.06, 0.06) * stem
    a, b = pts[-1], foot
    normal = ((a[1] - b[1]) / stem, (b[0] - a[0]) / stem)
    mid = ((a[0] + b[0]) / 2 + 2 * bow * normal[0], (a[1] + b[1]) / 2 + 2 * bow * normal[1])
    pts += _bezier(a, ((2 * a[0] + mid[0]) / 3, (2 * a[1] + mid[1]) / 3), ((2 * b[0] + mid[0]) / 3,
                   (2 * b[1] + mid[1]) / 3), b, 20)
    return Mark("cornered-question", _placed(rng, pts), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {"hooked-swung-tick": hooked_swung_tick,
                                              "cornered-question": cornered_question}
