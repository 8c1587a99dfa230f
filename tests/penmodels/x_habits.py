"""An x drawn in one stroke as people we have not seen draw it (issue 25: held-back people read one-stroke x's 92 %
where design people read 98-99 %): a diagonal, a side, the other diagonal, with the habits the design people's x's
show (diagonals crossing off their middles, a loop or a round bend at a turn, long tails, a hook where the second
diagonal starts, arms of unequal length, the whole tilted); in canvas pixels, seeded; no motion, no noise (the pens
draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_bracket_habits.py --marks x`)."""

from __future__ import annotations

import itertools
import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _arc, _placed

EXPECTED = {"offset-x": "polyline", "looped-turn-x": "polyline", "rounded-turn-x": "polyline",
            "long-tail-x": "polyline", "hooked-x": "polyline", "unequal-x": "polyline", "round-side-x": "polyline"}
"""An x in one stroke is straight sides joined by a diagonal: a polyline (benchmarks/label_kinds.tsv), whatever its
turns look like."""


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


def _run(a: Point, b: Point, step: float) -> list[Point]:
    """Points after ``a`` along the segment to ``b``, about ``step`` apart (``b`` the last)."""
    n = max(2, math.ceil(math.dist(a, b) / step))
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def _unit(a: Point, b: Point) -> Point:
    d = math.dist(a, b)
    return ((b[0] - a[0]) / d, (b[1] - a[1]) / d)


def _fillet(prev: Point, corner: Point, nxt: Point, back: float, step: float) -> tuple[Point, Point, list[Point]]:
    """A corner at ``corner`` between the sides from ``prev`` and to ``nxt`` rounded off by a circle tangent to both
    ``back`` from the corner: where the round bend starts and ends, and its points after the start."""
    u, v = _unit(corner, prev), _unit(corner, nxt)
    half = math.acos(max(-1.0, min(1.0, u[0] * v[0] + u[1] * v[1]))) / 2
    radius = back * math.tan(half)
    start, end = (corner[0] + u[0] * back, corner[1] + u[1] * back), (corner[0] + v[0] * back, corner[1] + v[1] * back)
    bis = _unit((0.0, 0.0), (u[0] + v[0], u[1] + v[1]))
    centre = (corner[0] + bis[0] * radius / math.sin(half), corner[1] + bis[1] * radius / math.sin(half))
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    sweep = (a1 - a0 + math.pi) % (2 * math.pi) - math.pi
    n = max(4, math.ceil(abs(sweep) * radius / step))
    return start, end, _arc(centre, radius, a0, sweep, n)


def _corners(rng: random.Random, h: float) -> list[Point]:
    """The four vertices of an x 0.6-1.2 as wide as ``h`` is tall, its diagonals crossing at their middles: the first
    diagonal's start, the side's two ends, the second diagonal's end."""
    w = h * rng.uniform(0.6, 1.2)
    return [(-w / 2, -h / 2), (w / 2, h / 2), (w / 2, -h / 2), (-w / 2, h / 2)]


def looped_turn_x(seed: int) -> Mark:
    """An x 120-300 px tall whose pen, at one turn of the side or both, runs past the corner and loops round into the
    next side (an alpha at the turn: a loop 0.06-0.15 of the x's height across, swung the long way round, against the
    corner's own turn) instead of making a sharp corner; straight sides otherwise; either way round, from either end,
    turned half the time."""
    rng = random.Random(f"looped-turn-x:{seed}")
    h = rng.uniform(120, 300)
    a, p, q, d = _corners(rng, h)
    step = h / 60
    which = rng.choice(((True, False), (False, True), (True, True)))
    pts: list[Point] = [a]
    for corner, prev, nxt, looped in ((p, a, q, which[0]), (q, p, d, which[1])):
        if not looped:
            pts += _run(pts[-1], corner, step)
            continue
        # the loop: instead of turning the short way at the corner the pen swings the long way round a circle
        # tangent to the side at the corner (crossing its own path), and leaves heading along the next side
        r = rng.uniform(0.03, 0.075) * h
        u, v = _unit(prev, corner), _unit(corner, nxt)
        turn = math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])
        swing = -1.0 if turn > 0 else 1.0  # the loop turns against the corner's own turn
        centre = (corner[0] - swing * u[1] * r, corner[1] + swing * u[0] * r)
        pts += _run(pts[-1], corner, step)
        a0 = math.atan2(corner[1] - centre[1], corner[0] - centre[0])
        pts += _arc(centre, r, a0, swing * (2 * math.pi - abs(turn)), 40)
    pts += _run(pts[-1], d, step)
    return Mark("looped-turn-x", _placed(rng, pts, rng.random() < 0.5), True)


def rounded_turn_x(seed: int) -> Mark:
    """An x 120-300 px tall whose side's two turns are round bends (each a circle tangent to both sides 0.1-0.3 of the
    side from the corner), its diagonals and the rest of the side straight; either way round, from either end, turned
    half the time."""
    rng = random.Random(f"rounded-turn-x:{seed}")
    h = rng.uniform(120, 300)
    a, p, q, d = _corners(rng, h)
    step = h / 60
    side = math.dist(p, q)
    s1, e1, bend1 = _fillet(a, p, q, rng.uniform(0.1, 0.3) * side, step)
    s2, e2, bend2 = _fillet(p, q, d, rng.uniform(0.1, 0.3) * side, step)
    pts = [a, *_run(a, s1, step), *bend1, *_run(e1, s2, step), *bend2, *_run(e2, d, step)]
    return Mark("rounded-turn-x", _placed(rng, pts, rng.random() < 0.5), True)


def long_tail_x(seed: int) -> Mark:
    """An x 120-300 px tall whose diagonals run on past the crossing for 1.2-2 times the triangle they close (the side
    short: 0.35-0.6 of the x's height), each tail its own length; either way round, from either end, turned half the
    time."""
    rng = random.Random(f"long-tail-x:{seed}")
    h = rng.uniform(120, 300)
    side = rng.uniform(0.35, 0.6) * h
    depth = side * rng.uniform(0.8, 1.6)  # from the crossing to the side
    p, q = (depth, side / 2), (depth, -side / 2)
    t1, t2 = rng.uniform(1.2, 2.0), rng.uniform(1.2, 2.0)
    a, d = (-t1 * p[0], -t1 * p[1]), (-t2 * q[0], -t2 * q[1])
    pts: list[Point] = [a, p, q, d]
    mid = (sum(x for x, _ in pts) / 4, sum(y for _, y in pts) / 4)
    pts = [(x - mid[0], y - mid[1]) for x, y in pts]
    return Mark("long-tail-x", _placed(rng, pts, rng.random() < 0.5), False)


def hooked_x(seed: int) -> Mark:
    """An x 120-300 px tall whose second diagonal starts with a hook: the pen runs on past the side's end by 0.04-0.1
    of the height, then turns back into the diagonal (a spike at the turn); either way round, from either end, turned
    half the time."""
    rng = random.Random(f"hooked-x:{seed}")
    h = rng.uniform(120, 300)
    a, p, q, d = _corners(rng, h)
    u = _unit(p, q)
    over = rng.uniform(0.04, 0.1) * h
    lean = rng.uniform(-0.5, 0.5) * over  # the spike leans off the side's line, either way
    hook = (q[0] + u[0] * over - u[1] * lean, q[1] + u[1] * over + u[0] * lean)
    pts = [a, p, hook, d]
    return Mark("hooked-x", _placed(rng, pts, rng.random() < 0.5), False)


def unequal_x(seed: int) -> Mark:
    """An x 120-300 px tall whose diagonals are of unequal length (the shorter 0.55-0.8 of the longer: the side
    slants), crossing 0.35-0.65 along each, tilted 15-40 degrees either way; from either end."""
    rng = random.Random(f"unequal-x:{seed}")
    h = rng.uniform(120, 300)
    along1, along2 = rng.uniform(0.35, 0.65), rng.uniform(0.35, 0.65)
    ratio = rng.uniform(0.55, 0.8)
    spread = math.radians(rng.uniform(60, 100))  # the angle between the diagonals
    d1 = (math.cos(spread / 2), math.sin(spread / 2))
    d2 = (math.cos(spread / 2), -math.sin(spread / 2))
    long_, short = h, h * ratio
    if rng.random() < 0.5:
        long_, short = short, long_
    a, p = (-along1 * long_ * d1[0], -along1 * long_ * d1[1]), ((1 - along1) * long_ * d1[0],
                                                                 (1 - along1) * long_ * d1[1])
    q, d = ((1 - along2) * short * d2[0], (1 - along2) * short * d2[1]), (-along2 * short * d2[0],
                                                                          -along2 * short * d2[1])
    tilt = math.radians(rng.choice((-1.0, 1.0)) * rng.uniform(15, 40))
    c, s = math.cos(tilt), math.sin(tilt)
    pts = [(x * c - y * s, x * s + y * c) for x, y in (a, p, q, d)]
    return Mark("unequal-x", _placed(rng, pts, False), False)


def _cut_corners(pts: list[Point], times: int) -> list[Point]:
    """``pts`` with every inner vertex cut (Chaikin: each side replaced by its points a quarter and three quarters
    along), ``times`` over; the first and last points kept."""
    for _ in range(times):
        cut = [pts[0]]
        for p, q in itertools.pairwise(pts):
            cut += [(0.75 * p[0] + 0.25 * q[0], 0.75 * p[1] + 0.25 * q[1]),
                    (0.25 * p[0] + 0.75 * q[0], 0.25 * p[1] + 0.75 * q[1])]
        pts = [*cut[:1], *cut[2:-1], pts[-1]]
    return pts


def round_side_x(seed: int) -> Mark:
    """An x 120-300 px tall whose side is one round loop (hcira jd4386 User05's x's, 7 of 10: an alpha or fish): the
    diagonals straight and crossing at 0.4-0.6 of each, the side bowed out by 0.1-0.35 of its length and rounded into
    both diagonals from 0.65-0.85 of their length on, so that no corner is left; either way round, from either end,
    turned half the time (session 30: today's rules read it as a curve, as they read a pigtail, whose loop it is)."""
    rng = random.Random(f"round-side-x:{seed}")
    h = rng.uniform(120, 300)
    w = h * rng.uniform(0.6, 1.2)
    c1, c2 = rng.uniform(0.4, 0.6), rng.uniform(0.4, 0.6)  # where each diagonal crosses the other, along it
    p, q = (w / 2, h / 2), (w / 2, -h / 2)  # the side's ends; the crossing at the origin
    a, d = (-p[0] * c1 / (1 - c1), -p[1] * c1 / (1 - c1)), (-q[0] * c2 / (1 - c2), -q[1] * c2 / (1 - c2))
    r1, r2 = rng.uniform(0.65, 0.85), rng.uniform(0.65, 0.85)  # where the round part starts along each diagonal
    start, end = (a[0] + (p[0] - a[0]) * r1, a[1] + (p[1] - a[1]) * r1), (q[0] + (d[0] - q[0]) * (1 - r2),
                                                                        q[1] + (d[1] - q[1]) * (1 - r2))
    bow = rng.uniform(0.1, 0.35) * h
    side = [start, p, (p[0] + bow, p[1] * 0.5), (q[0] + bow, q[1] * 0.5), q, end]
    step = h / 60
    pts = [a, *_run(a, start, step)[:-1], *_cut_corners(side, 4), *_run(end, d, step)]
    mid = (sum(x for x, _ in (a, p, q, d)) / 4, sum(y for _, y in (a, p, q, d)) / 4)
    pts = [(x - mid[0], y - mid[1]) for x, y in pts]
    return Mark("round-side-x", _placed(rng, pts, rng.random() < 0.5), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "offset-x": offset_x, "looped-turn-x": looped_turn_x, "rounded-turn-x": rounded_turn_x,
    "long-tail-x": long_tail_x, "hooked-x": hooked_x, "unequal-x": unequal_x, "round-side-x": round_side_x}
