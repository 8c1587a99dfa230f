"""Marks drawn fast in one stroke (issue 25): an x swung round at its far side, a tick whose short arm is a few percent
of the stroke, a zig-zag whose sides the hand bowed, and what they must not be taken for: a pigtail whose arms cross as
an x's do; in canvas pixels, seeded;
no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_hurried_marks.py`)."""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _arc, _placed

EXPECTED = {"x": "polyline", "swung-x": "polyline", "hooked-tick": "polyline", "ribbon-pigtail": "curve",
            "bowed-zigzag": "polyline", "check": "polyline"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: an x and a check are polylines, a pigtail a curve)."""


def _line(a: Point, b: Point, n: int) -> list[Point]:
    """``n`` points after ``a`` along the segment to ``b``."""
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def x_mark(seed: int) -> Mark:
    """An x in one stroke as the $1 set draws it, 120-300 px tall, 0.6-1.2 as wide: a diagonal down, a side up, the
    other diagonal down (the diagonals cross at their middles); either way round, drawn from either end."""
    rng = random.Random(f"x:{seed}")
    h = rng.uniform(120, 300)
    w = h * rng.uniform(0.6, 1.2)
    pts = [(-w / 2, -h / 2), (w / 2, h / 2), (w / 2, -h / 2), (-w / 2, h / 2)]
    return Mark("x", _placed(rng, pts, rng.random() < 0.5), False)


def swung_x(seed: int) -> Mark:
    """An x whose side is swung round instead of turned at two corners: two straight diagonals 120-300 px tall, 0.6-1.2
    as wide, crossing at their middles, joined by a round bend that stands off its chord by 0.15-0.45 of it (half an
    ellipse: a half circle stands off 0.5); either way round, drawn from either end, turned half the time."""
    rng = random.Random(f"swung-x:{seed}")
    h = rng.uniform(120, 300)
    w = h * rng.uniform(0.6, 1.2)
    depth = rng.uniform(0.15, 0.45) * h
    a, b = (-w / 2, -h / 2), (w / 2, h / 2)
    pts: list[Point] = [a, *_line(a, b, 24)]
    # the bend: half an ellipse from (w/2, h/2) round to (w/2, -h/2), bulging out by ``depth``
    for k in range(1, 25):
        t = math.pi * k / 24
        pts.append((w / 2 + depth * math.sin(t), (h / 2) * math.cos(t)))
    pts += _line(pts[-1], (-w / 2, h / 2), 24)
    return Mark("swung-x", _placed(rng, pts, rng.random() < 0.5), True)


def hooked_tick(seed: int) -> Mark:
    """A tick drawn fast with a mouse: a long arm 200-360 px going up at 25-50 degrees, bowed by 7-11 % of its length
    either way (ahmadosama's misread Ticks: 9-11 %), after a short arm of 4-7 % of it (at least 14 px: beyond a landing
    hook's reach) coming down at 60-90 degrees; drawn from either end."""
    rng = random.Random(f"hooked-tick:{seed}")
    long_arm = rng.uniform(200, 360)
    short_arm = max(14.0, rng.uniform(0.04, 0.07) * long_arm)
    down, up = math.radians(rng.uniform(60, 90)), math.radians(rng.uniform(25, 50))
    start = (-short_arm * math.cos(down), short_arm * math.sin(down))  # y up: down to the point at the origin
    end = (long_arm * math.cos(up), long_arm * math.sin(up))
    bow = rng.choice((-1.0, 1.0)) * rng.uniform(0.07, 0.11) * long_arm
    normal = (-math.sin(up), math.cos(up))
    pts: list[Point] = [start, *_line(start, (0.0, 0.0), 6)]
    for k in range(1, 41):
        u = k / 40
        off = bow * math.sin(math.pi * u)
        pts.append((end[0] * u + off * normal[0], end[1] * u + off * normal[1]))
    pts = [(x, -y) for x, y in pts]  # y down, as on the canvas
    return Mark("hooked-tick", _placed(rng, pts, False), True)


def ribbon_pigtail(seed: int) -> Mark:
    """A pigtail whose straight arms cross as an x's diagonals do, 100-260 px across: an arm runs in, round a circular
    loop of 240-300 degrees tangent to both arms, and out across itself; either way, turned half the time."""
    rng = random.Random(f"ribbon-pigtail:{seed}")
    r = 1.0
    loop = math.radians(rng.uniform(240, 300))  # how far round the loop goes; the arms cross at 360 - loop degrees
    arm = rng.uniform(2.5, 4.0) * r
    # the circle round the origin, entered at angle -pi/2 - loop/2 heading anticlockwise, left at -pi/2 + loop/2
    a0 = -math.pi / 2 - loop / 2 + math.pi  # point angle at entry (the loop hangs above the crossing)
    enter = (r * math.cos(a0), r * math.sin(a0))
    heading_in = (-math.sin(a0), math.cos(a0))
    start = (enter[0] - arm * heading_in[0], enter[1] - arm * heading_in[1])
    pts: list[Point] = [start, *_line(start, enter, 12)]
    pts += _arc((0.0, 0.0), r, a0, loop, 40)
    leave = pts[-1]
    a1 = a0 + loop
    heading_out = (-math.sin(a1), math.cos(a1))
    pts += _line(leave, (leave[0] + arm * heading_out[0], leave[1] + arm * heading_out[1]), 12)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    scale = rng.uniform(100, 260) / math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    return Mark("ribbon-pigtail", _placed(rng, [(x * scale, y * scale) for x, y in pts], rng.random() < 0.5), True)


def bowed_zigzag(seed: int) -> Mark:
    """A zig-zag drawn in a hurry: 4-7 teeth, 150-450 px long, 0.15-0.35 of that high (`bench_waves.zigzag`'s
    proportions), its points sharp but each side swung by the hand into a bow of 4-12 % of its chord (a circular arc's
    sagitta; the Quick, Draw! players' and klarubbio/s06's zig-zags bow a side by 0.09-0.13), each side its own way;
    drawn from either end, turned half the time."""
    rng = random.Random(f"bowed-zigzag:{seed}")
    length, teeth = rng.uniform(150, 450), rng.randint(4, 7)
    height = rng.uniform(0.15, 0.35) * length
    corners = [((k / teeth - 0.5) * length, height * (0.5 if k % 2 else -0.5)) for k in range(teeth + 1)]
    pts: list[Point] = [corners[0]]
    for a, b in itertools.pairwise(corners):
        bow = rng.choice((-1.0, 1.0)) * rng.uniform(0.04, 0.12) * math.dist(a, b)
        normal = ((a[1] - b[1]) / math.dist(a, b), (b[0] - a[0]) / math.dist(a, b))
        for k in range(1, 17):
            u = k / 16
            off = 4 * bow * u * (1 - u)  # a parabola as near a shallow arc as a hand draws: ``bow`` at the middle
            pts.append((a[0] + (b[0] - a[0]) * u + off * normal[0], a[1] + (b[1] - a[1]) * u + off * normal[1]))
    return Mark("bowed-zigzag", _placed(rng, pts, rng.random() < 0.5), True)


def check(seed: int) -> Mark:
    """A check as people's hurried ones are (dollar1 s04's, sinarest1608/Subject2's, klarubbio/s04's, pixelfac/user05's
    checks): a long arm 120-300 px rising at 40-70 degrees, bowed by up to 6 % of its length either way; a short arm
    0.2-0.6 as long (people's checks and ticks: 0.16-0.58 at the 5th-95th percentile, their arms' chords split at the
    point) coming down to it at 20-60 degrees below the level, swung into a bow of 8-20 % of its chord that turns
    against the point's turn (the hand sets off sideways: the stroke turns both ways); drawn short arm first or, half
    the time, from the long arm's end (a hand that draws its checks backwards: the reading must not depend on it);
    turned up to 12 degrees."""
    rng = random.Random(f"check:{seed}")
    long_arm = rng.uniform(120, 300)
    short_arm = rng.uniform(0.2, 0.6) * long_arm
    down, up = math.radians(rng.uniform(20, 60)), math.radians(rng.uniform(40, 70))
    start = (-short_arm * math.cos(down), -short_arm * math.sin(down))  # y down: the point, at the origin, is lowest
    end = (long_arm * math.cos(up), -long_arm * math.sin(up))
    pts: list[Point] = [start]
    bows = (-rng.uniform(0.08, 0.2), rng.uniform(-0.06, 0.06))  # the short arm's against the point's turn
    for (a, b), bow in zip(((start, (0.0, 0.0)), ((0.0, 0.0), end)), bows, strict=True):
        chord = math.dist(a, b)
        normal = ((a[1] - b[1]) / chord, (b[0] - a[0]) / chord)
        for k in range(1, 25):
            u = k / 24
            off = 4 * bow * chord * u * (1 - u)
            pts.append((a[0] + (b[0] - a[0]) * u + off * normal[0], a[1] + (b[1] - a[1]) * u + off * normal[1]))
    return Mark("check", _placed(rng, pts, False), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "x": x_mark, "swung-x": swung_x, "hooked-tick": hooked_tick, "ribbon-pigtail": ribbon_pigtail,
    "bowed-zigzag": bowed_zigzag, "check": check}
