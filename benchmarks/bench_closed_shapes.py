"""Benchmark: closed shapes the design sets hardly hold (many-sided polygons, rhombi, parallelograms, trapezoids,
ovals, rounded rectangles) drawn by the project's two pen models, read cornered or round as a person means them.

Usage: .venv/bin/python benchmarks/bench_closed_shapes.py [--seeds A:B] [--held-back] [--rules] [--json OUT]
       [--families A,B]

Each family (`FAMILIES`) draws a shape from its own seeded generator (``random.Random(f"{family}:{seed}")``: sizes
40-400 px across, turned, stretched) and each pen draws it with the same seed: the careful virtual pen
(`physink_tui.input.virtual_pen`, windows-ink) and the hurried hand (`tests/penmodels/hurried.py`), the latter also
through a device sending an event every 15-30 ms (`bench_device_stress.coarse`). Every stroke is read twice, with
its times and without. What a person expects (`EXPECTED`, the rule written down in
docs/BENCHMARKS.md "Closed shapes drawn by the pen models"):

- a convex pentagon, hexagon or octagon, regular or not, is a polygon (a box when it is four-sided never happens);
- a triangle closed past its first corner, the tails crossing there, is a polygon;
- a star's outline of 5-7 points, its inner corners at 0.35-0.75 of its tips' radius, is a polygon;
- a rhombus (diamond), a parallelogram or a trapezoid is cornered: a box where squaring it stays within the stroke
  (`beautify.box_geometry`), else the four-sided polygon drawn;
- a rectangle with rounded corners (radius up to a quarter of its short side: straight sides longer than the arcs) is
  a box, as `tests/stroke_cases.py` "rectangle-rounded-corners" already says; so is a box a hurried hand swung round
  at one or two corners (radius 0.2-0.4 of the short side) or cut one corner of (a chamfer 0.15-0.35 of it);
- a circle is round (circle, or an ellipse within the round-off); an oval of aspect 1.3-3 is an ellipse.

Scored as cornered-vs-round ("class right": the issue's mistake), and the exact kind beside it. Polygons and boxes read
from cornered shapes are also overlapped with the outline meant (IoU of the beautified outline, shapely).
Seeds 0-29 are the tuning range; seeds 1000-1029 (``--held-back``) are never looked at while tuning and reported
apart. Deterministic: no clock, no unseeded randomness.
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
from collections import Counter, defaultdict
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np
from bench_device_stress import coarse
from penmodels.hurried import SHAKY_SLOW, HurriedPen, touching
from penmodels.shapes import Curve as PenCurve
from penmodels.shapes import Outline, Oval, Shape
from penmodels.shapes import Path as PenPath
from shapely.geometry import Polygon as ShapelyPolygon

from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.beautify import shape_points
from physink_tui.scene.recognition.recognize import recognize_stroke

Point = tuple[float, float]
CANVAS = (1600.0, 1000.0)
CENTRE = (800.0, 500.0)
TUNING_SEEDS = range(0, 30)
HELD_BACK_SEEDS = range(1000, 1030)
ROUND = ("circle", "ellipse")
CORNERED = ("box", "polygon")


def _turned(points: list[Point], angle: float) -> tuple[Point, ...]:
    c, s = math.cos(angle), math.sin(angle)
    return tuple((CENTRE[0] + x * c - y * s, CENTRE[1] + x * s + y * c) for x, y in points)


def _fit_size(points: list[Point], size: float) -> list[Point]:
    """``points`` scaled so the larger side of their bounds is ``size`` px, centred on the origin."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    k = size / max(max(xs) - min(xs), max(ys) - min(ys))
    return [((x - cx) * k, (y - cy) * k) for x, y in points]


def _convex(points: list[Point]) -> bool:
    signs = set()
    n = len(points)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = points[i], points[(i + 1) % n], points[(i + 2) % n]
        signs.add((bx - ax) * (cy - by) - (by - ay) * (cx - bx) > 0)
    return len(signs) == 1


def regular(sides: int) -> Callable[[random.Random], Shape]:
    def make(rng: random.Random) -> Shape:
        phase = rng.uniform(0, 2 * math.pi)
        pts = [(math.cos(phase + 2 * math.pi * k / sides), math.sin(phase + 2 * math.pi * k / sides))
               for k in range(sides)]
        return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), 0.0))
    return make


def irregular(sides: int) -> Callable[[random.Random], Shape]:
    """A convex polygon: corners at jittered angles (up to 0.3 of a step) and radii (0.8-1.2), stretched 0.7-1."""
    def make(rng: random.Random) -> Shape:
        step = 2 * math.pi / sides
        while True:
            phase = rng.uniform(0, 2 * math.pi)
            stretch = rng.uniform(0.7, 1.0)
            pts = [(r * math.cos(a), stretch * r * math.sin(a))
                   for a, r in ((phase + step * (k + rng.uniform(-0.3, 0.3)), rng.uniform(0.8, 1.2))
                                for k in range(sides))]
            if _convex(pts):
                return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(0, math.pi)))
    return make


def rhombus(rng: random.Random) -> Shape:
    """A diamond standing on a point: diagonals 1 : 1-2 (either way up), turned up to 0.25 rad."""
    ratio = rng.uniform(1.0, 2.0)
    w, h = (1.0, ratio) if rng.random() < 0.5 else (ratio, 1.0)
    pts = [(0.0, -h), (w, 0.0), (0.0, h), (-w, 0.0)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.25, 0.25)))


def parallelogram(rng: random.Random) -> Shape:
    """Sides of aspect 1-2.5, the upright ones slanted 25-45 degrees (past a box's tolerance), turned."""
    w, h = rng.uniform(1.0, 2.5), 1.0
    shift = h * math.tan(math.radians(rng.uniform(25, 45))) * rng.choice((-1, 1))
    pts = [(0.0, 0.0), (w, 0.0), (w + shift, h), (shift, h)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def trapezoid(rng: random.Random) -> Shape:
    """A base 1-2 times as wide as tall, the top 0.35-0.75 of it, centred or slid a little."""
    base, h = rng.uniform(1.0, 2.0), 1.0
    top = rng.uniform(0.35, 0.75) * base
    off = (base - top) / 2 + rng.uniform(-0.15, 0.15) * base
    pts = [(0.0, h), (base, h), (off + top, 0.0), (off, 0.0)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def rounded_rectangle(rng: random.Random) -> Shape:
    """Aspect 1-2.5, corners rounded with a radius 0.1-0.25 of the short side (each corner an arc of 8 points)."""
    w, h = rng.uniform(1.0, 2.5), 1.0
    r = rng.uniform(0.1, 0.25) * h
    pts: list[Point] = []
    for cx, cy, a0 in ((w - r, r, -math.pi / 2), (w - r, h - r, 0.0), (r, h - r, math.pi / 2), (r, r, math.pi)):
        pts += [(cx + r * math.cos(a0 + math.pi / 2 * k / 8), cy + r * math.sin(a0 + math.pi / 2 * k / 8))
                for k in range(9)]
    return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))


def _corner_arc(corner: Point, before: Point, after: Point, cut: float, rounded: bool) -> list[Point]:
    """The corner at ``corner`` (sides from ``before`` and on to ``after``) taken off ``cut`` along each side: a bend
    of 9 points tangent to both sides where ``rounded``, else a straight chamfer (its two ends)."""
    def toward(p: Point, d: float) -> Point:
        n = math.hypot(p[0] - corner[0], p[1] - corner[1])
        return (corner[0] + (p[0] - corner[0]) * d / n, corner[1] + (p[1] - corner[1]) * d / n)
    a, b = toward(before, cut), toward(after, cut)
    if not rounded:
        return [a, b]
    # a bend tangent to both sides whatever the corner's angle: a quadratic Bezier with the corner as its control point
    return [((1 - t) ** 2 * a[0] + 2 * t * (1 - t) * corner[0] + t * t * b[0],
             (1 - t) ** 2 * a[1] + 2 * t * (1 - t) * corner[1] + t * t * b[1]) for t in (k / 8 for k in range(9))]


def box_corners_off(rounded: bool) -> Callable[[random.Random], Shape]:
    """A box (aspect 1-2.5, its upright sides leaned up to 12 degrees, within a box's tolerance, as people's are) drawn
    by a hurried hand that swung round one or two of its corners (``rounded``: an arc of radius 0.2-0.4 of the short
    side) or cut one short (a chamfer 0.15-0.35 of the short side along each side). Issue 25: people's rectangles so
    drawn read as pentagons, hexagons or ellipses."""
    def make(rng: random.Random) -> Shape:
        w, h = rng.uniform(1.0, 2.5), 1.0
        lean = h * math.tan(math.radians(rng.uniform(-12.0, 12.0)))  # the upright sides leaned, as people's are
        square = [(0.0, 0.0), (w, 0.0), (w + lean, h), (lean, h)]
        off = rng.sample(range(4), rng.choice((1, 2)) if rounded else 1)
        pts: list[Point] = []
        for i, corner in enumerate(square):
            if i in off:
                share = rng.uniform(0.2, 0.4) if rounded else rng.uniform(0.15, 0.35)
                pts += _corner_arc(corner, square[i - 1], square[(i + 1) % 4], share * h, rounded)
            else:
                pts.append(corner)
        return Outline(_turned(_fit_size(pts, rng.uniform(40, 400)), rng.uniform(-0.4, 0.4)))
    return make


def star(points: int) -> Callable[[random.Random], Shape]:
    """A star's outline drawn round in one stroke, as the Quick, Draw! players drew theirs: ``points`` tips at radius
    0.85-1.15, the inner corners at 0.35-0.75 of it (each apart: a hurried hand makes some nearly flat), every corner
    up to 0.15 of a step off its place, stretched 0.75-1, turned."""
    def make(rng: random.Random) -> Shape:
        step = math.pi / points
        phase = rng.uniform(0, 2 * math.pi)
        stretch = rng.uniform(0.75, 1.0)
        pts = [(r * math.cos(a), stretch * r * math.sin(a))
               for a, r in ((phase + step * (k + rng.uniform(-0.15, 0.15)),
                             rng.uniform(0.85, 1.15) * (1.0 if k % 2 == 0 else rng.uniform(0.35, 0.75)))
                            for k in range(2 * points))]
        return Outline(_turned(_fit_size(pts, rng.uniform(60, 400)), rng.uniform(0, math.pi)))
    return make


def crossed_triangle(rng: random.Random) -> Shape:
    """A triangle closed in a hurry, as Quick, Draw! players drew some: the stroke lands a little before its first
    corner, on the line of its first side, goes round, and runs on past that corner along the last side's line, the
    two tails crossing there (each 0.05-0.2 of its longest side beyond it). Drawn as the open path it is (a
    `penmodels.shapes.Path`); the outline meant is the triangle (`outline_of`)."""
    while True:
        pts = [(math.cos(a), math.sin(a)) for a in (rng.uniform(0, 2 * math.pi) for _ in range(3))]
        (ax, ay), (bx, by), (cx, cy) = pts
        if abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) > 0.8:  # no sliver: twice its area on the unit circle
            break
    a, b, c = _fit_size(pts, rng.uniform(60, 400))
    size = max(math.dist(a, b), math.dist(b, c), math.dist(c, a))

    def beyond(p: Point, q: Point, share: float) -> Point:  # past p on the line from q through p
        d = math.dist(p, q)
        return (p[0] + (p[0] - q[0]) * share * size / d, p[1] + (p[1] - q[1]) * share * size / d)

    start, end = beyond(a, b, rng.uniform(0.05, 0.2)), beyond(a, c, rng.uniform(0.05, 0.2))
    return PenPath(_turned([start, b, c, end], rng.uniform(0, math.pi)))


def rounded_polygon(sides: int) -> Callable[[random.Random], Shape]:
    """An `irregular` polygon whose every corner a hand rounded a little: an arc tangent to both sides taking off
    0.08-0.2 of the shorter side at each (`_corner_arc`), straight runs between."""
    def make(rng: random.Random) -> Shape:
        corners = list(irregular(sides)(rng).vertices)  # type: ignore[union-attr]
        pts: list[Point] = []
        for i, corner in enumerate(corners):
            before, after = corners[i - 1], corners[(i + 1) % sides]
            shorter = min(math.dist(before, corner), math.dist(corner, after))
            pts += _corner_arc(corner, before, after, rng.uniform(0.08, 0.2) * shorter, True)
        return Outline(tuple(pts))
    return make


def egg(rng: random.Random) -> Shape:
    """An egg: an oval of aspect 1.2-2 whose one end is fatter than the other (the half-width grows by 10-25 % of
    itself from the narrow end to the wide one: ``y = b sin t (1 + k cos t)``), turned; drawn as a smooth closed
    curve (72 points, the start repeated)."""
    a = rng.uniform(20, 200)
    b = a / rng.uniform(1.2, 2.0)
    k = rng.uniform(0.1, 0.25)
    pts = [(a * math.cos(t), b * math.sin(t) * (1 + k * math.cos(t)))
           for t in (2 * math.pi * j / 72 for j in range(73))]
    start = rng.randrange(72)
    return PenCurve(_turned([*pts[start:72], *pts[:start + 1]], rng.uniform(0, 2 * math.pi)))


def lumpy_circle(rng: random.Random) -> Shape:
    """A circle drawn unevenly, as people's are: its radius wanders by the 2nd to 5th harmonics round it, each of
    amplitude up to 3 % (in all 4-8 % from the mean), so it bulges and flattens but turns one way all round; drawn as
    a smooth closed curve (72 points, the start repeated)."""
    r = rng.uniform(20, 200)
    waves = [(m, rng.uniform(0.0, 0.03), rng.uniform(0, 2 * math.pi)) for m in (2, 3, 4, 5)]
    spread = sum(amp for _, amp, _ in waves)
    want = rng.uniform(0.04, 0.08)
    waves = [(m, amp * want / spread, ph) for m, amp, ph in waves]
    pts = [(r * (1 + sum(amp * math.cos(m * t + ph) for m, amp, ph in waves)) * math.cos(t),
            r * (1 + sum(amp * math.cos(m * t + ph) for m, amp, ph in waves)) * math.sin(t))
           for t in (2 * math.pi * j / 72 for j in range(73))]
    return PenCurve(_turned(pts, rng.uniform(0, 2 * math.pi)))


def circle(rng: random.Random) -> Shape:
    return Oval(CENTRE, rng.uniform(20, 200), 0.0)


def oval(low: float, high: float) -> Callable[[random.Random], Shape]:
    def make(rng: random.Random) -> Shape:
        rx = rng.uniform(20, 200)
        return Oval(CENTRE, rx, rx / rng.uniform(low, high), rng.uniform(0, math.pi))
    return make


FAMILIES: dict[str, Callable[[random.Random], Shape]] = {
    "pentagon": regular(5), "hexagon": regular(6), "heptagon": regular(7), "octagon": regular(8),
    "pentagon-irregular": irregular(5), "hexagon-irregular": irregular(6), "heptagon-irregular": irregular(7),
    "octagon-irregular": irregular(8), "pentagon-rounded": rounded_polygon(5), "hexagon-rounded": rounded_polygon(6),
    "heptagon-rounded": rounded_polygon(7), "octagon-rounded": rounded_polygon(8),
    "rhombus": rhombus, "parallelogram": parallelogram, "trapezoid": trapezoid,
    "rounded-rectangle": rounded_rectangle, "triangle-crossed": crossed_triangle,
    "star-5": star(5), "star-6": star(6), "star-7": star(7),
    "box-corners-rounded": box_corners_off(rounded=True), "box-corner-cut": box_corners_off(rounded=False),
    "circle": circle, "oval-1.3-1.8": oval(1.3, 1.8), "oval-1.8-3": oval(1.8, 3.0), "egg": egg,
    "circle-lumpy": lumpy_circle,
}
EXPECTED: dict[str, tuple[str, ...]] = {
    **{f: ("polygon",) for f in FAMILIES
       if f.startswith(("pentagon", "hexagon", "heptagon", "octagon", "star", "triangle"))},
    "rhombus": CORNERED, "parallelogram": CORNERED, "trapezoid": CORNERED, "rounded-rectangle": ("box",),
    "box-corners-rounded": ("box",), "box-corner-cut": ("box",),
    "circle": ROUND, "oval-1.3-1.8": ("ellipse",), "oval-1.8-3": ("ellipse",), "egg": ROUND, "circle-lumpy": ROUND,
}
"""The kinds a person expects for each family (either kind of a pair counts as right)."""


def shape(family: str, seed: int) -> Shape:
    made = FAMILIES[family](random.Random(f"{family}:{seed}"))
    if isinstance(made, Oval) and made.ry == 0.0:  # a circle
        return Oval(made.center, made.rx, made.rx)
    return made


def outline_of(s: Shape, n: int = 72) -> list[Point]:
    """The outline meant, as a ring of points (an oval sampled at ``n`` points)."""
    if isinstance(s, Outline):
        return list(s.vertices)
    if isinstance(s, PenCurve):  # a smooth closed curve (an egg, a lumpy circle): its points, the start once
        return list(s.points[:-1])
    if isinstance(s, PenPath):  # a triangle whose tails cross at its first corner (`crossed_triangle`)
        (sx, sy), b, c, (ex, ey) = s.vertices
        dx1, dy1, dx2, dy2 = b[0] - sx, b[1] - sy, ex - c[0], ey - c[1]
        t = ((c[0] - sx) * dy2 - (c[1] - sy) * dx2) / (dx1 * dy2 - dy1 * dx2)
        return [(sx + t * dx1, sy + t * dy1), b, c]
    assert isinstance(s, Oval)
    c, si = math.cos(s.angle), math.sin(s.angle)
    return [(s.center[0] + s.rx * math.cos(t) * c - s.ry * math.sin(t) * si,
             s.center[1] + s.rx * math.cos(t) * si + s.ry * math.sin(t) * c)
            for t in (2 * math.pi * k / n for k in range(n))]


def careful(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    """The virtual pen round the outline, starting at a corner (or a point of an oval) that the seed picks."""
    if isinstance(s, PenPath):
        ring = list(s.vertices)
    elif isinstance(s, PenCurve):
        ring = list(s.points)
    else:
        ring = outline_of(s)
        start = seed % len(ring)
        ring = ring[start:] + ring[:start + 1]
    w, h = CANVAS
    samples = VirtualPen(REFERENCE_DEVICES["windows-ink"], seed=seed).samples(
        [Stroke(tuple((x / w, y / h) for x, y in ring))])
    return [(p.state.x * w, p.state.y * h, p.t) for p in samples if p.phase == "touch"]


def hurried(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    return touching(HurriedPen(random.Random(seed)).draw(s, 0.0)[0])


def slow(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    """The slow, unsteady hand (`penmodels.hurried.SHAKY_SLOW`: 180-300 px/s along a side, a 4-7 Hz tremor)."""
    return touching(HurriedPen(random.Random(seed), habits=SHAKY_SLOW).draw(s, 0.0)[0])


def hurried_coarse(s: Shape, seed: int) -> list[tuple[float, float, float]]:
    """The hurried hand on a device that sends an event every 15-30 ms (`bench_device_stress.coarse`): a stroke
    drawn in half a second comes as 15-35 points, each corner between two of them."""
    drawn = np.array(hurried(s, seed))
    pts, when = coarse((drawn[:, :2], drawn[:, 2]), np.random.default_rng(seed))
    assert when is not None
    return [(float(x), float(y), float(t)) for (x, y), t in zip(pts, when, strict=True)]


PENS: dict[str, Callable[[Shape, int], list[tuple[float, float, float]]]] = {
    "careful": careful, "hurried": hurried, "hurried-coarse": hurried_coarse, "slow": slow}


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> tuple[str | None, float | None]:
    """The kind read and, for a cornered reading, the IoU of its outline with the outline meant."""
    s = shape(family, seed)
    drawn = PENS[pen](s, seed)
    got = recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn] if timed else None, learned=learned)
    if got.kind not in CORNERED or got.geometry is None:
        return got.kind, None
    a, b = ShapelyPolygon(shape_points(got.geometry)), ShapelyPolygon(outline_of(s))
    if not (a.is_valid and b.is_valid):
        return got.kind, 0.0
    return got.kind, a.intersection(b).area / a.union(b).area


def run(seeds: range, learned: bool) -> dict[tuple[str, str, bool], list[tuple[str | None, float | None]]]:
    out: dict[tuple[str, str, bool], list[tuple[str | None, float | None]]] = defaultdict(list)
    for family in FAMILIES:
        for pen in PENS:
            for timed in (True, False):
                out[(family, pen, timed)] = [read(family, pen, seed, timed, learned) for seed in seeds]
    return out


def class_right(family: str, kind: str | None) -> bool:
    want = EXPECTED[family]
    return kind in (ROUND if want[0] in ROUND else CORNERED)


def report(results: dict[tuple[str, str, bool], list[tuple[str | None, float | None]]], title: str) -> list[str]:
    lines = [f"#### {title}", "",
             "| family | pen | times | class right | kind right | readings | IoU min / median |",
             "|---|---|---|---:|---:|---|---|"]
    pooled: Counter[tuple[str, str]] = Counter()
    for (family, pen, timed), got in results.items():
        n = len(got)
        cls = sum(class_right(family, k) for k, _ in got)
        exact = sum(k in EXPECTED[family] for k, _ in got)
        kinds = ", ".join(f"{k} {c}" for k, c in Counter(k for k, _ in got).most_common())
        ious = sorted(i for _, i in got if i is not None)
        iou = f"{ious[0]:.3f} / {ious[len(ious) // 2]:.3f}" if ious and EXPECTED[family][0] not in ROUND else ""
        lines.append(f"| {family} | {pen} | {'yes' if timed else 'no'} | {cls}/{n} | {exact}/{n} | {kinds} | {iou} |")
        for key in ((pen, "class"), ("all", "class")):
            pooled[key] += cls
        for key in ((pen, "exact"), ("all", "exact")):
            pooled[key] += exact
        pooled[(pen, "n")] += n
        pooled[("all", "n")] += n
    lines.append("")
    for pen in (*PENS, "all"):
        n = pooled[(pen, "n")]
        lines.append(f"- {pen}: class right {pooled[(pen, 'class')]}/{n}, kind right {pooled[(pen, 'exact')]}/{n}")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", help="A:B, a range of seeds (default: the tuning range 0:30)")
    parser.add_argument("--held-back", action="store_true", help="the held-back seeds 1000-1029")
    parser.add_argument("--rules", action="store_true", help="the rules' reading, without the learned ranker")
    parser.add_argument("--json", type=Path, help="write every reading here")
    parser.add_argument("--families", help="a comma-separated subset of the families (default: all)")
    args = parser.parse_args()
    if args.families:
        for name in set(FAMILIES) - set(args.families.split(",")):
            del FAMILIES[name]
    if args.held_back:
        seeds, name = HELD_BACK_SEEDS, "held-back seeds 1000-1029"
    elif args.seeds:
        a, b = map(int, args.seeds.split(":"))
        seeds, name = range(a, b), f"seeds {a}-{b - 1}"
    else:
        seeds, name = TUNING_SEEDS, "tuning seeds 0-29"
    results = run(seeds, learned=not args.rules)
    print("\n".join(report(results, f"{name}, {'rules' if args.rules else 'shipped recogniser'}")))
    if args.json:
        args.json.write_text(json.dumps({f"{f}|{p}|{t}": v for (f, p, t), v in results.items()}, indent=0))


if __name__ == "__main__":
    main()
