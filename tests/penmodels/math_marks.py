"""Radical signs and parentheses as people write them in mathematics (issue 25), in canvas pixels, seeded; no motion,
no noise (the pens draw them: `penmodels.hurried`, the virtual pen; `benchmarks/bench_math_marks.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _bezier

EXPECTED: dict[str, frozenset[str]] = {
    "radical": frozenset({"polyline"}), "round-radical": frozenset({"polyline"}),
    "barless-radical": frozenset({"polyline"}), "parenthesis": frozenset({"arc", "curve"}),
    "hooked-parenthesis": frozenset({"arc", "curve"}), "flicked-parenthesis": frozenset({"arc", "curve"})}
"""The kinds each family may be read as (benchmarks/label_kinds.tsv, laviola: a radical sign is straight sides, open,
a polyline; a parenthesis one smooth open bow, an arc, or a curve where it bends unevenly)."""


def _line(a: Point, b: Point, n: int) -> list[Point]:
    """``n`` points after ``a`` along the segment to ``b``."""
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def _bowed(a: Point, b: Point, bow: float, n: int) -> list[Point]:
    """``n`` points after ``a`` along the segment to ``b`` bowed sideways by ``bow`` (a share of its length) at its
    middle, a half sine."""
    length = math.dist(a, b)
    nx, ny = -(b[1] - a[1]) / length, (b[0] - a[0]) / length
    return [(a[0] + (b[0] - a[0]) * k / n + bow * length * math.sin(math.pi * k / n) * nx,
             a[1] + (b[1] - a[1]) * k / n + bow * length * math.sin(math.pi * k / n) * ny) for k in range(1, n + 1)]


def _round_corner(route: list[Point], corner: Point, nxt: Point, share: float, n: int) -> None:
    """Appends to ``route`` (its last point the side's start) a corner at ``corner`` rounded off over ``share`` of the
    shorter side either side of it, stopping where the rounding meets the next side."""
    prev = route[-1]
    r = share * min(math.dist(prev, corner), math.dist(corner, nxt))
    a = _toward(corner, prev, r)
    b = _toward(corner, nxt, r)
    route += _line(prev, a, max(2, round(math.dist(prev, a) / 6)))
    route += _bezier(a, _toward(a, corner, 0.55 * r), _toward(b, corner, 0.55 * r), b, n)


def _toward(a: Point, b: Point, d: float) -> Point:
    """The point ``d`` from ``a`` towards ``b``."""
    length = math.dist(a, b) or 1.0
    return (a[0] + (b[0] - a[0]) * d / length, a[1] + (b[1] - a[1]) * d / length)


def _placed(rng: random.Random, pts: list[Point], tilt_deg: float) -> tuple[Point, ...]:
    """``pts`` (y up) turned to y down, tilted by up to ``tilt_deg`` either way and moved to a random place on the
    1600 x 1000 canvas (the middle of their extent)."""
    mx = (min(x for x, _ in pts) + max(x for x, _ in pts)) / 2
    my = (min(y for _, y in pts) + max(y for _, y in pts)) / 2
    pts = [(x - mx, y - my) for x, y in pts]
    angle = math.radians(rng.uniform(-tilt_deg, tilt_deg))
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy - (x * s + y * c)) for x, y in pts)


def _radical_corners(rng: random.Random, bar: bool) -> tuple[list[Point], float]:
    """A radical's corners (y up, its point at the origin): a start hook's start half the time (the pen comes up into
    the tick), the tick's start, the point, the top of the rise and, with ``bar``, the bar's end; and its height."""
    h = rng.uniform(80, 260)  # the rise
    tick = rng.uniform(0.15, 0.45) * h
    down = math.radians(rng.uniform(40, 80))  # the tick's fall below the horizontal
    lean = math.radians(rng.uniform(5, 35))  # the rise from the vertical
    start = (-tick * math.cos(down), tick * math.sin(down))
    top = (h * math.tan(lean), h)
    corners = [start, (0.0, 0.0), top]
    if bar:
        length = rng.uniform(0.3, 2.5) * h  # over what the sign covers
        tip = math.radians(rng.uniform(-5, 5))
        corners.append((top[0] + length * math.cos(tip), top[1] + length * math.sin(tip)))
    if rng.random() < 0.5:  # a serif: a short stroke up into the tick, turned sharply there
        serif = rng.uniform(0.05, 0.15) * h
        up = math.radians(rng.uniform(10, 50))
        corners.insert(0, (start[0] - serif * math.cos(up), start[1] - serif * math.sin(up)))
    return corners, h


def radical(seed: int) -> Mark:
    """A radical sign of straight sides, 80-260 px tall: a start hook half the time (a short stroke up into the tick,
    0.05-0.15 of the height), a tick falling 40-80 degrees over 0.15-0.45 of the height, a long rise leaning 5-35
    degrees, a top bar 0.3-2.5 of the height within 5 degrees of level; its corners turned as a pen turns any corner;
    tilted up to 10 degrees."""
    rng = random.Random(f"radical:{seed}")
    corners, _ = _radical_corners(rng, True)
    return Mark("radical", _placed(rng, corners, 10), False)


def round_radical(seed: int) -> Mark:
    """A radical sign as `radical` drawn more loosely: the point at the bottom rounded over 0.2-0.8 of the tick, the
    top corner over up to 0.15 of the shorter side, the bar bowed up to 5 % of its length either way (or the rise up
    to 3 %), the start hook (where drawn) rounded too."""
    rng = random.Random(f"round-radical:{seed}")
    corners, _ = _radical_corners(rng, True)
    bar_bow = rng.uniform(-0.05, 0.05)
    rise_bow = rng.uniform(-0.03, 0.03)
    bottom, top_round, hook_round = rng.uniform(0.2, 0.8), rng.uniform(0.0, 0.15), rng.uniform(0.1, 0.5)
    route: list[Point] = [corners[0]]
    k = 0
    if len(corners) == 5:  # the start hook
        _round_corner(route, corners[1], corners[2], hook_round, 6)
        k = 1
    _round_corner(route, corners[k + 1], corners[k + 2], bottom, 12)
    rise_end = _toward(corners[k + 2], corners[k + 1], top_round * min(
        math.dist(corners[k + 1], corners[k + 2]), math.dist(corners[k + 2], corners[k + 3])) + 1e-6)
    route += _bowed(route[-1], rise_end, rise_bow, 30)
    bar_start = _toward(corners[k + 2], corners[k + 3], math.dist(rise_end, corners[k + 2]))
    route += _bezier(route[-1], _toward(rise_end, corners[k + 2], 0.55 * math.dist(rise_end, corners[k + 2])),
                     _toward(bar_start, corners[k + 2], 0.55 * math.dist(bar_start, corners[k + 2])), bar_start, 6)
    route += _bowed(bar_start, corners[k + 3], bar_bow, 30)
    return Mark("round-radical", _placed(rng, route, 10), True)


def barless_radical(seed: int) -> Mark:
    """A radical sign whose bar is left off (drawn as a separate stroke, or not at all): the start hook half the time,
    the tick and the rise of `radical`, the point rounded over up to 0.6 of the tick half the time."""
    rng = random.Random(f"barless-radical:{seed}")
    corners, _ = _radical_corners(rng, False)
    if rng.random() < 0.5:
        return Mark("barless-radical", _placed(rng, corners, 10), False)
    route: list[Point] = [corners[0]]
    if len(corners) == 4:
        _round_corner(route, corners[1], corners[2], rng.uniform(0.1, 0.5), 6)
    _round_corner(route, corners[-2], corners[-1], rng.uniform(0.1, 0.6), 12)
    route += _line(route[-1], corners[-1], 30)
    return Mark("barless-radical", _placed(rng, route, 10), True)


def _bow(rng: random.Random, h: float) -> list[Point]:
    """A parenthesis' bow (y up, from its top down, bulging to -x: a left parenthesis), 48 points: 0.06-0.3 of its
    height deep, a circle's arc a third of the time, else flatter in the middle (x = depth (1 - |t|^p), p 2-4),
    its deepest point up to a fifth of the height off its middle."""
    depth = rng.uniform(0.06, 0.3) * h
    shift = rng.uniform(-0.2, 0.2)
    circular, p = rng.random() < 1 / 3, rng.uniform(2.0, 4.0)
    r = (depth ** 2 + (h / 2) ** 2) / (2 * depth)
    pts = []
    for k in range(49):
        t = 1 - 2 * k / 48  # the top (t = 1) down to the bottom
        y = t * h / 2
        if circular:
            x = -(math.sqrt(max(r * r - y * y, 0.0)) - (r - depth))
        else:
            u = (t - shift) / (1 - shift) if t >= shift else (t - shift) / (1 + shift)
            x = -depth * (1 - abs(u) ** p)
        pts.append((x, y))
    return pts


def parenthesis(seed: int) -> Mark:
    """A parenthesis 100-320 px tall, one smooth bow (`_bow`); left or right, drawn from the top down (or up, one in
    five), tilted up to 12 degrees."""
    rng = random.Random(f"parenthesis:{seed}")
    pts = _bow(rng, rng.uniform(100, 320))
    return Mark("parenthesis", _finished(rng, pts), True)


def hooked_parenthesis(seed: int) -> Mark:
    """A parenthesis as `parenthesis` with an end (or both) turned off its bow over 0.04-0.12 of its height: hooked
    on in (curling on round the bow, 30-80 degrees further) or flicked out (turned back 20-50 degrees against it, an
    S begun)."""
    rng = random.Random(f"hooked-parenthesis:{seed}")
    h = rng.uniform(100, 320)
    pts = _bow(rng, h)
    ends = rng.choice(("top", "bottom", "both"))
    if ends in ("bottom", "both"):
        pts = _end_turned(rng, pts, h)
    if ends in ("top", "both"):
        pts = _end_turned(rng, pts[::-1], h)[::-1]
    return Mark("hooked-parenthesis", _finished(rng, pts), True)


def _end_turned(rng: random.Random, pts: list[Point], h: float) -> list[Point]:
    """``pts`` with their last end turned off the bow: on round it (a hook) or back against it (a flick)."""
    length = rng.uniform(0.04, 0.12) * h
    (x0, y0), (x1, y1) = pts[-4], pts[-1]
    heading = math.atan2(y1 - y0, x1 - x0)
    # the bow turns one way along the stroke (the sign of the cross product of its halves' chords); a hook turns on
    # the same way, a flick back the other
    (sx, sy), (mx, my) = pts[0], pts[len(pts) // 2]
    way = 1.0 if (mx - sx) * (y1 - my) - (my - sy) * (x1 - mx) > 0 else -1.0
    hooked = rng.random() < 0.5
    turn = math.radians(rng.uniform(30, 80) if hooked else -rng.uniform(20, 50)) * way
    out = list(pts)
    for k in range(1, 9):
        a = heading + turn * k / 8
        step = length / 8
        out.append((out[-1][0] + step * math.cos(a), out[-1][1] + step * math.sin(a)))
    return out


def flicked_parenthesis(seed: int) -> Mark:
    """A parenthesis as `parenthesis` whose end (or both) the pen flicks off straight: a straight piece 0.04-0.1 of
    its height turned at once 40-90 degrees off the bow's heading, on round the bow (in) or back against it (out)."""
    rng = random.Random(f"flicked-parenthesis:{seed}")
    h = rng.uniform(100, 320)
    pts = _bow(rng, h)
    ends = rng.choice(("top", "bottom", "both"))
    if ends in ("bottom", "both"):
        pts = _end_flicked(rng, pts, h)
    if ends in ("top", "both"):
        pts = _end_flicked(rng, pts[::-1], h)[::-1]
    return Mark("flicked-parenthesis", _finished(rng, pts), True)


def _end_flicked(rng: random.Random, pts: list[Point], h: float) -> list[Point]:
    """``pts`` with a straight piece at their last end, turned at once off the bow's heading, in or out."""
    length = rng.uniform(0.04, 0.1) * h
    (x0, y0), (x1, y1) = pts[-4], pts[-1]
    heading = math.atan2(y1 - y0, x1 - x0) + math.radians(rng.uniform(40, 90)) * rng.choice((-1.0, 1.0))
    end = (x1 + length * math.cos(heading), y1 + length * math.sin(heading))
    return pts + _line(pts[-1], end, 6)


def _finished(rng: random.Random, pts: list[Point]) -> tuple[Point, ...]:
    """A left parenthesis' points turned into a right one's half the time, drawn up one time in five, placed."""
    if rng.random() < 0.5:
        pts = [(-x, y) for x, y in pts]
    if rng.random() < 0.2:
        pts = pts[::-1]
    return _placed(rng, pts, 12)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "radical": radical, "round-radical": round_radical, "barless-radical": barless_radical,
    "parenthesis": parenthesis, "hooked-parenthesis": hooked_parenthesis, "flicked-parenthesis": flicked_parenthesis}
