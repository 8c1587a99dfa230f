"""Curly braces as different hands draw them (issue 25: right braces of people the project never saw): flattened,
lopsided, askew, hooked, two arcs meeting at a cusp, tall and thin, a wide chevron with rounded ends, straight runs,
lopsided with a bracket's square end and a straight short half, square-cornered with a small point; each built as a
left brace drawn from its top and then turned round and drawn from either end, seeded; no motion, no noise (the pens
draw them: `penmodels.hurried`, the virtual pen)."""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from dataclasses import dataclass

from penmodels.open_marks import Mark, angular_brace_corners

Point = tuple[float, float]
WAYS = ("left-down", "left-up", "right-down", "right-up")
"""How a brace is drawn: a left brace ``{`` or a right brace ``}``, from its top end down or from its bottom end up."""


@dataclass(frozen=True, slots=True)
class Half:
    """One half of a brace, drawn from its end to its point, as a turtle goes (y down: a positive sweep turns
    clockwise on screen): the end's curl (``curl_radius``, turning by ``curl_deg``, 90 for a plain curl), the arm
    (``arm`` long, bowed by an arc turning ``arm_deg`` over it), the bend out to the point (``approach`` long, turning
    ``point_deg`` towards the point) and the point's own roundness (``round_share`` of the half turn the point makes,
    taken off before the cusp)."""

    curl_radius: float
    curl_deg: float
    arm: float
    arm_deg: float
    approach: float
    point_deg: float
    round_share: float
    slant_deg: float = 0.0
    """The arm heads this many degrees off the brace's line, towards the point (a chevron's arms slant)."""


def _turtle(half: Half) -> list[Point]:
    """The half's points from its end to its point, the end's curl starting where it turns by ``curl_deg`` down onto
    the arm, heading down (+y) along the arm; the point where the half ends."""
    # a left brace's top curl turns counter-clockwise onto the arm
    heading = math.pi / 2 + math.radians(half.slant_deg + half.curl_deg)
    x, y = 0.0, 0.0
    pts: list[Point] = [(x, y)]

    def arc(length: float, sweep_deg: float, n: int) -> None:
        nonlocal heading, x, y
        sweep = math.radians(sweep_deg)
        for _ in range(n):
            heading += sweep / (2 * n)
            x += length / n * math.cos(heading)
            y += length / n * math.sin(heading)
            heading += sweep / (2 * n)
            pts.append((x, y))

    arc(half.curl_radius * math.radians(half.curl_deg), -half.curl_deg, 12)
    arc(half.arm, half.arm_deg, 16)
    arc(half.approach, half.point_deg, 8)
    if half.round_share > 0:
        arc(half.approach * half.round_share, -half.point_deg * half.round_share, 6)
    return pts


def _joined(top: Half, bottom: Half) -> list[Point]:
    """A left brace ``{`` drawn from its top end down: the top half to the point, then the bottom half (built as a
    top half, mirrored top to bottom) from the point on; its point at the origin."""
    a = _turtle(top)
    b = _turtle(bottom)
    ax, ay = a[-1]
    bx, by = b[-1]
    first = [(x - ax, y - ay) for x, y in a]
    second = [(x - bx, -(y - by)) for x, y in reversed(b[:-1])]
    return first + second


def _placed(rng: random.Random, pts: list[Point], way: str, askew_deg: float = 12.0) -> tuple[Point, ...]:
    """``pts`` (a left brace drawn down, round the origin) drawn ``way`` (`WAYS`), turned up to ``askew_deg`` either
    way and moved to a random place on the 1600 x 1000 canvas."""
    if way.startswith("right"):
        pts = [(-x, y) for x, y in pts]
    if way.endswith("up"):
        pts = pts[::-1]
    angle = math.radians(rng.uniform(-askew_deg, askew_deg))
    c, s = math.cos(angle), math.sin(angle)
    cx, cy = rng.uniform(500, 1100), rng.uniform(350, 650)
    return tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in pts)


def _half(rng: random.Random, h: float, curl_deg: tuple[float, float] = (80, 110),
          point_deg: tuple[float, float] = (40, 80), arm_deg: tuple[float, float] = (-8, 8),
          curl: tuple[float, float] = (0.15, 0.35), approach: tuple[float, float] = (0.15, 0.35),
          round_share: tuple[float, float] = (0.0, 0.6)) -> Half:
    """A half brace of ``h`` (its end to its point, along the arm) with its shape drawn from the ranges given (shares
    of ``h``, degrees)."""
    c, a = rng.uniform(*curl) * h, rng.uniform(*approach) * h
    return Half(c, rng.uniform(*curl_deg), max(h - c - a, 0.2 * h), rng.uniform(*arm_deg), a,
                rng.uniform(*point_deg), rng.uniform(*round_share))


def classic(seed: int, way: str) -> Mark:
    """A brace 120-320 px tall as `penmodels.open_marks.brace` draws one: curls, nearly straight arms, a point."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    return Mark("classic", _placed(rng, _joined(_half(rng, h), _half(rng, h)), way), True)


def flat_point(seed: int, way: str) -> Mark:
    """A brace whose point is flattened: it turns out by 12-30 degrees only, rounded, over a long bend."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    top = _half(rng, h, point_deg=(12, 30), approach=(0.2, 0.4), round_share=(0.4, 0.9))
    bottom = _half(rng, h, point_deg=(12, 30), approach=(0.2, 0.4), round_share=(0.4, 0.9))
    return Mark("flat-point", _placed(rng, _joined(top, bottom), way), True)


def lopsided(seed: int, way: str) -> Mark:
    """A brace whose point is far from the middle (its halves 1 : 1.4-2.2), its curls and arms unlike (one arm bowed,
    one curl wider) and its arms not in line (up to 12 degrees apart)."""
    rng = random.Random(seed)
    h = rng.uniform(50, 130)
    long = h * rng.uniform(1.4, 2.2)
    halves = [_half(rng, h, curl=(0.1, 0.25)), _half(rng, long, curl=(0.2, 0.4), arm_deg=(-14, 14))]
    rng.shuffle(halves)
    return Mark("lopsided", _placed(rng, _joined(*halves), way), True)


def askew(seed: int, way: str) -> Mark:
    """A brace drawn askew: turned 15-40 degrees either way."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    pts = _joined(_half(rng, h), _half(rng, h))
    side = rng.choice((-1, 1))
    angle = side * math.radians(rng.uniform(15, 40))
    c, s = math.cos(angle), math.sin(angle)
    return Mark("askew", _placed(rng, [(x * c - y * s, x * s + y * c) for x, y in pts], way, 0.0), True)


def hooked(seed: int, way: str) -> Mark:
    """A brace whose ends curl on past the arm's line (each curl turns 140-250 degrees, tight)."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    top = _half(rng, h, curl_deg=(140, 250), curl=(0.08, 0.18))
    bottom = _half(rng, h, curl_deg=(140, 250), curl=(0.08, 0.18))
    return Mark("hooked", _placed(rng, _joined(top, bottom), way), True)


def cusp_arcs(seed: int, way: str) -> Mark:
    """A brace of two arcs meeting at a sharp cusp: each half curls off its end and then bows all along into the
    point (its arm an arc turning 25-60 degrees towards the point), no straight arm."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    halves = [_half(rng, h, arm_deg=(25, 60), point_deg=(5, 20), approach=(0.02, 0.06), round_share=(0.0, 0.1))
              for _ in range(2)]
    return Mark("cusp-arcs", _placed(rng, _joined(*halves), way), True)


def tall_thin(seed: int, way: str) -> Mark:
    """A very tall, thin brace (200-400 px tall, 0.07-0.12 of that across): small curls (0.04-0.08 of the height)
    and a small point turning out 30-60 degrees."""
    rng = random.Random(seed)
    h = rng.uniform(100, 200)
    halves = [_half(rng, h, curl=(0.08, 0.16), point_deg=(30, 60), approach=(0.08, 0.16)) for _ in range(2)]
    return Mark("tall-thin", _placed(rng, _joined(*halves), way), True)


def wide_chevron(seed: int, way: str) -> Mark:
    """A brace that is a wide chevron with rounded ends: straight arms slanting 20-35 degrees to a point turning out a
    little more, each end a small curl onto its arm."""
    rng = random.Random(seed)
    h = rng.uniform(60, 160)
    halves = []
    for _ in range(2):
        slant = rng.uniform(20, 35)
        c = rng.uniform(0.1, 0.25) * h
        halves.append(Half(c, rng.uniform(60, 100), h - c, 0.0, rng.uniform(0.01, 0.04) * h, rng.uniform(10, 30),
                           0.0, slant))
    return Mark("wide-chevron", _placed(rng, _joined(*halves), way), True)


def straight_runs(seed: int, way: str) -> Mark:
    """A brace drawn as straight runs between corners (a mouse's): a run for each curl, each arm, out to the point and
    back (as `penmodels.open_marks.angular_brace`), the pen turning at each corner."""
    rng = random.Random(seed)
    return Mark("straight-runs", _placed(rng, angular_brace_corners(rng), way), False)


def _run(a: Point, b: Point, step: float = 3.0) -> list[Point]:
    """Points every ``step`` px or so from ``a`` (left out) to ``b`` along a straight run."""
    n = max(2, int(math.dist(a, b) / step))
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def _bend(a: Point, c: Point, b: Point, n: int = 10) -> list[Point]:
    """A quadratic from ``a`` (left out) by ``c`` to ``b``: a rounded corner."""
    return [((1 - u) ** 2 * a[0] + 2 * u * (1 - u) * c[0] + u * u * b[0],
             (1 - u) ** 2 * a[1] + 2 * u * (1 - u) * c[1] + u * u * b[1]) for u in (k / n for k in range(1, n + 1))]


def plain_short_half(seed: int, way: str) -> Mark:
    """A lopsided brace whose short half runs straight from the point to its end, slanting back with no curl, and
    whose long half turns onto its end arm at a square corner, as a bracket's (itt GixD42's and hcira
    pixelfac/user01's right braces): the long half 1.6-2.4 times the short (40-90 px), its end arm 0.3-0.6 of the
    short half, its spine bending out over its last 0.15-0.3 to a round point standing 0.2-0.45 of the short half
    past it; the short half's end 0.6-1.2 of the arm out, on the arm's side. The long half on top or at the bottom."""
    rng = random.Random(seed)
    short = rng.uniform(40, 90)
    long = short * rng.uniform(1.6, 2.4)
    arm = rng.uniform(0.3, 0.6) * short
    depth = rng.uniform(0.2, 0.45) * short
    bend = rng.uniform(0.15, 0.3) * long
    end = (rng.uniform(0.6, 1.2) * arm, short)
    corner, spine_end, point = (0.0, -long), (0.0, -bend), (-depth, 0.0)
    round_in = (point[0] + 0.25 * (spine_end[0] - point[0]), point[1] + 0.25 * (spine_end[1] - point[1]))
    round_out = (point[0] + 0.2 * (end[0] - point[0]), point[1] + 0.2 * (end[1] - point[1]))
    pts: list[Point] = [(arm, -long), *_run((arm, -long), corner), *_run(corner, spine_end)]
    pts += _bend(spine_end, (0.0, -0.4 * bend), round_in) + _bend(round_in, point, round_out) + _run(round_out, end)
    if rng.random() < 0.5:
        pts = [(x, -y) for x, y in pts][::-1]  # the long half at the bottom, still drawn from the top
    return Mark("plain-short-half", _placed(rng, pts, way), True)


def square_cornered(seed: int, way: str) -> Mark:
    """A brace drawn square-cornered, as a hand on a mouse or a trackpad that cannot swing a curl draws one (hcira
    jonathanzhang53/s01's right brace 1): each end arm (0.1-0.3 of the height) turned at a square corner (80-100
    degrees) onto a straight spine 120-320 px tall, and halfway along it a small point, 0.035-0.1 of the height out,
    reached over 0.02-0.08 of it either side; drawn as straight runs, the pen turning at each corner."""
    rng = random.Random(f"square-cornered:{seed}")
    h = rng.uniform(120, 320)
    arms = []
    for _ in range(2):
        length, tilt = rng.uniform(0.1, 0.3) * h, math.radians(rng.uniform(-10, 10))
        arms.append((length * math.cos(tilt), length * math.sin(tilt)))
    tip, approach = rng.uniform(0.035, 0.1) * h, rng.uniform(0.02, 0.08) * h
    (w1, t1), (w2, t2) = arms
    pts = [(w1, -h / 2 + t1), (0.0, -h / 2), (0.0, -approach), (-tip, 0.0), (0.0, approach), (0.0, h / 2),
           (w2, h / 2 - t2)]
    return Mark("square-cornered", _placed(rng, pts, way), False)


FAMILIES: dict[str, Callable[[int, str], Mark]] = {
    "classic": classic, "flat-point": flat_point, "lopsided": lopsided, "askew": askew, "hooked": hooked,
    "cusp-arcs": cusp_arcs, "tall-thin": tall_thin, "wide-chevron": wide_chevron, "straight-runs": straight_runs,
    "plain-short-half": plain_short_half, "square-cornered": square_cornered}
"""Every family; each is read as a curve (benchmarks/label_kinds.tsv: a curly brace is a curve)."""
