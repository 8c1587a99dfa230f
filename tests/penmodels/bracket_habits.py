"""Square brackets as people we have not seen draw them (issue 25: held-back people read brackets ~10 % wrong): ends
the pen flicks into a hook, corners a mouse rounds over most of an arm, a spine the hand bows, short or unequal arms,
arms drawn askew, arms so long and leaning in that the bracket nearly closes, small brackets, one arm swept into the
spine; in canvas pixels, seeded; no motion, no noise (the pens draw them: `penmodels.hurried`, the virtual pen;
`benchmarks/bench_bracket_habits.py`)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, Point, _placed

EXPECTED = {"hooked-bracket": "polyline", "mouse-rounded-bracket": "polyline", "bowed-spine-bracket": "polyline",
            "short-arm-bracket": "polyline", "askew-bracket": "polyline", "closing-bracket": "polyline",
            "small-bracket": "polyline", "swept-arm-bracket": "polyline"}
"""The kind each family is read as (benchmarks/label_kinds.tsv: a square bracket is three straight sides, a
polyline, however its corners are turned)."""


def _side(a: Point, b: Point, bow: float, n: int) -> list[Point]:
    """``n`` points after ``a`` along the segment to ``b``, bowed sideways by ``bow`` (a share of its length, signed:
    positive to the left of the way it runs, y down) at its middle, a half sine."""
    length = math.dist(a, b) or 1.0
    nx, ny = (b[1] - a[1]) / length, -(b[0] - a[0]) / length
    out = []
    for k in range(1, n + 1):
        u = k / n
        off = bow * length * math.sin(math.pi * u)
        out.append((a[0] + u * (b[0] - a[0]) + off * nx, a[1] + u * (b[1] - a[1]) + off * ny))
    return out


def _toward(a: Point, b: Point, d: float) -> Point:
    """The point ``d`` from ``a`` towards ``b``."""
    length = math.dist(a, b) or 1.0
    return (a[0] + (b[0] - a[0]) * d / length, a[1] + (b[1] - a[1]) * d / length)


def _quad(a: Point, c: Point, b: Point, n: int) -> list[Point]:
    """A quadratic Bezier from ``a`` via control ``c`` to ``b``, ``n`` points after ``a``."""
    return [((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * c[0] + u * u * b[0],
             (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * c[1] + u * u * b[1]) for u in (k / n for k in range(1, n + 1))]


def _bracket(verts: list[Point], radii: tuple[float, float], bows: tuple[float, float, float]) -> list[Point]:
    """A bracket through ``verts`` (arm end, corner, corner, arm end): each corner rounded off over ``radii`` (pixels
    along each side from the corner, 0 sharp), each side bowed by ``bows`` (`_side`); dense, about a point each 4 px."""
    e0, c1, c2, e3 = verts
    r1, r2 = radii
    ends = [(e0, _toward(c1, e0, r1)), (_toward(c1, c2, r1), _toward(c2, c1, r2)), (_toward(c2, e3, r2), e3)]
    pts: list[Point] = [e0]
    for k, ((a, b), bow) in enumerate(zip(ends, bows, strict=True)):
        pts += _side(a, b, bow, max(4, int(math.dist(a, b) / 4)))
        if k < 2:
            corner, radius, nxt = (c1, r1, ends[1][0]) if k == 0 else (c2, r2, ends[2][0])
            if radius > 0:
                pts += _quad(pts[-1], corner, nxt, max(4, int(radius / 3)))
    return pts


def _flicked(pts: list[Point], length: float, turn_deg: float) -> list[Point]:
    """``pts`` with the pen flicked on from their last point: an arc of ``length`` pixels turning ``turn_deg`` (signed:
    positive clockwise on screen) from the last heading."""
    (x0, y0), (x1, y1) = pts[-4], pts[-1]
    heading = math.atan2(y1 - y0, x1 - x0)
    n = max(4, int(length / 2))
    out = list(pts)
    for _ in range(n):
        heading += math.radians(turn_deg) / n
        x, y = out[-1]
        out.append((x + length / n * math.cos(heading), y + length / n * math.sin(heading)))
    return out


def _frame(rng: random.Random, arms: tuple[float, float] = (0.2, 0.5)) -> tuple[float, float, float]:
    """A left bracket's spine height (120-320 px) and its arms' lengths (``arms``: a share of the height, the second
    arm 0.85-1.15 of the first)."""
    h = rng.uniform(120, 320)
    a = rng.uniform(*arms) * h
    return h, a, a * rng.uniform(0.85, 1.15)


def _verts(h: float, a1: float, a2: float, tilt1: float = 0.0, tilt2: float = 0.0) -> list[Point]:
    """A left bracket's vertices (y down, drawn from the top arm's end): arms ``a1`` and ``a2`` long, each turned
    ``tilt`` degrees off square towards the other arm (negative: away from it)."""
    t1, t2 = math.radians(tilt1), math.radians(tilt2)
    return [(a1 * math.cos(t1), -h / 2 + a1 * math.sin(t1)), (0.0, -h / 2), (0.0, h / 2),
            (a2 * math.cos(t2), h / 2 - a2 * math.sin(t2))]


def _corner_radii(rng: random.Random, a1: float, a2: float, most: float) -> tuple[float, float]:
    """Each corner rounded off over up to ``most`` of its arm, half the time (else sharp: the pens turn it)."""
    r1, r2 = (rng.uniform(0.05, most) * a if rng.random() < 0.5 else 0.0 for a in (a1, a2))
    return r1, r2


def hooked_bracket(seed: int) -> Mark:
    """A bracket whose pen flicks at its start, its end or both (each 70 % of the time, at least one): a hook of
    0.1-0.35 of the arm (at least 8 px, beyond a landing's 2-5 px) turning 60-170 degrees either way, a curl in or a
    flick out (itt marcel-moz's left bracket 09 curls its lower arm up); corners sharp or rounded a little."""
    rng = random.Random(f"hooked-bracket:{seed}")
    h, a1, a2 = _frame(rng)
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.25), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    start, end = rng.random() < 0.7, rng.random() < 0.7
    if not (start or end):
        start = rng.random() < 0.5
        end = not start
    for flick, arm in ((end, a2), (start, a1)):  # the end first, then the start (the points reversed)
        if flick:
            turn = rng.choice((-1.0, 1.0)) * rng.uniform(60, 170)
            pts = _flicked(pts, max(8.0, rng.uniform(0.1, 0.35) * arm), turn)
        pts = pts[::-1]
    return Mark("hooked-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def mouse_rounded_bracket(seed: int) -> Mark:
    """A bracket whose corners a hand in a hurry or a mouse rounds off over 0.45-0.85 of each arm (pixelfac/user01's
    and klarubbio/s06's rounded brackets), its spine bowed up to 4 % either way: a straight piece of each arm and of
    the spine is left; the arms 0.25-0.5 of the spine."""
    rng = random.Random(f"mouse-rounded-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    radii = (rng.uniform(0.45, 0.85) * a1, rng.uniform(0.45, 0.85) * a2)
    pts = _bracket(_verts(h, a1, a2), radii, (0.0, rng.uniform(-0.04, 0.04), 0.0))
    return Mark("mouse-rounded-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def bowed_spine_bracket(seed: int) -> Mark:
    """A bracket whose spine the hand swings into a bow of 4-10 % of its length, out (as a parenthesis bows) or in,
    its arms bowed up to 5 % each; corners sharp or rounded over up to 0.25 of the arm."""
    rng = random.Random(f"bowed-spine-bracket:{seed}")
    h, a1, a2 = _frame(rng)
    bows = (rng.uniform(-0.05, 0.05), rng.choice((-1.0, 1.0)) * rng.uniform(0.04, 0.10), rng.uniform(-0.05, 0.05))
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.25), bows)
    return Mark("bowed-spine-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def short_arm_bracket(seed: int) -> Mark:
    """A bracket with short arms: the longer 0.1-0.22 of the spine (at least 16 px), the shorter 0.45-1.0 of it (at
    least 12 px: beyond a landing hook's reach); corners sharp or rounded over up to 0.3 of the arm."""
    rng = random.Random(f"short-arm-bracket:{seed}")
    h = rng.uniform(120, 320)
    long_arm = max(16.0, rng.uniform(0.1, 0.22) * h)
    short = max(12.0, rng.uniform(0.45, 1.0) * long_arm)
    a1, a2 = (long_arm, short) if rng.random() < 0.5 else (short, long_arm)
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.3), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("short-arm-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def askew_bracket(seed: int) -> Mark:
    """A bracket drawn askew: each arm turned 10-35 degrees off square, in or out, on its own (the arms no longer
    parallel), arms 0.2-0.5 of the spine; corners sharp or rounded over up to 0.2 of the arm."""
    rng = random.Random(f"askew-bracket:{seed}")
    h, a1, a2 = _frame(rng)
    tilts = [rng.choice((-1.0, 1.0)) * rng.uniform(10, 35) for _ in range(2)]
    pts = _bracket(_verts(h, a1, a2, *tilts), _corner_radii(rng, a1, a2, 0.2), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("askew-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def closing_bracket(seed: int) -> Mark:
    """A bracket that nearly closes: arms 0.5-0.85 of the spine leaning in towards each other by 5-20 degrees, so
    its ends stand 0.3-0.9 of the spine apart; corners sharp or rounded over up to 0.35 of the arm (the open side is
    a gap no hand leaves closing a box)."""
    rng = random.Random(f"closing-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.5, 0.85))
    t1, t2 = rng.uniform(5, 20), rng.uniform(5, 20)
    while h - a1 * math.sin(math.radians(t1)) - a2 * math.sin(math.radians(t2)) < 0.3 * h:
        t1, t2 = 0.8 * t1, 0.8 * t2
    pts = _bracket(_verts(h, a1, a2, t1, t2), _corner_radii(rng, a1, a2, 0.35), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark("closing-bracket", _placed(rng, pts, rng.random() < 0.5), True)


def small_bracket(seed: int) -> Mark:
    """A small bracket, 40-90 px tall (a finger or a mouse on a small canvas, text-sized), arms 0.25-0.5 of the spine:
    the pen's hooks and tremor are a larger share of it; corners sharp or rounded over up to 0.3 of the arm."""
    return sized_bracket("small-bracket", seed, (40, 90), (0.25, 0.5))


def sized_bracket(name: str, seed: int, height: tuple[float, float], arm: tuple[float, float]) -> Mark:
    """A bracket ``height`` px tall, its arms ``arm`` of the spine (the two within 15 % of each other), its corners
    sharp or rounded over up to 0.3 of the arm, its spine bowed up to 2 %: the plain bracket at a chosen size."""
    rng = random.Random(f"{name}:{seed}")
    h = rng.uniform(*height)
    a1 = rng.uniform(*arm) * h
    a2 = a1 * rng.uniform(0.85, 1.15)
    pts = _bracket(_verts(h, a1, a2), _corner_radii(rng, a1, a2, 0.3), (0.0, rng.uniform(-0.02, 0.02), 0.0))
    return Mark(name, _placed(rng, pts, rng.random() < 0.5), True)


def swept_arm_bracket(seed: int) -> Mark:
    """A bracket with one corner sharp and the other swept: that arm drawn as one curve from its end into the spine
    (a quadratic through the corner, reaching 1-2 times the arm down the spine), no straight piece left of it, as a
    mouse or a hurried hand swings the first or the last arm in (`_placed` draws either first; pixelfac/user01's left
    bracket 3); arms 0.25-0.5 of the spine, the sharp corner's arm straight, the spine bowed up to 3 % either way."""
    rng = random.Random(f"swept-arm-bracket:{seed}")
    h, a1, a2 = _frame(rng, (0.25, 0.5))
    e0, c1, c2, e3 = _verts(h, a1, a2)
    reach = rng.uniform(1.0, 2.0) * a1
    swept_end = _toward(c1, c2, reach)
    pts: list[Point] = [e0, *_quad(e0, c1, swept_end, max(8, int((a1 + reach) / 4)))]
    pts += _side(swept_end, c2, rng.uniform(-0.03, 0.03), max(4, int(math.dist(swept_end, c2) / 4)))
    pts += _side(c2, e3, 0.0, max(4, int(a2 / 4)))
    return Mark("swept-arm-bracket", _placed(rng, pts, rng.random() < 0.5), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {
    "hooked-bracket": hooked_bracket, "mouse-rounded-bracket": mouse_rounded_bracket,
    "bowed-spine-bracket": bowed_spine_bracket, "short-arm-bracket": short_arm_bracket,
    "askew-bracket": askew_bracket, "closing-bracket": closing_bracket, "small-bracket": small_bracket,
    "swept-arm-bracket": swept_arm_bracket}
