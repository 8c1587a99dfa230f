"""Benchmark: closed shapes the design sets hardly hold (many-sided polygons, rhombi, parallelograms, trapezoids,
ovals, rounded rectangles) drawn by the project's two pen models, read cornered or round as a person means them.

Usage: .venv/bin/python benchmarks/bench_closed_shapes.py [--seeds A:B|tune|held] [--held-back] [--rules] [--json OUT]
       [--families A,B]

Each family (`ALL_FAMILIES`, made in `closed_shape_families`) draws a shape from its own seeded generator
(``random.Random(f"{family}:{seed}")``: sizes 40-400 px across, turned, stretched) and each pen draws it with the same
seed: the careful virtual pen (`physink_tui.input.virtual_pen`, windows-ink) and the hurried hand
(`tests/penmodels/hurried.py`), the latter also through a device sending an event every 15-30 ms
(`bench_device_stress.coarse`), and the slow, unsteady hand (`penmodels.hurried.SHAKY_SLOW`, session 20). Every stroke
is read twice, with its times and without. What a person expects (`EXPECTED`, the rule written down in
docs/BENCHMARKS.md "Closed shapes drawn by the pen models"):

- a convex pentagon, hexagon, heptagon or octagon, regular or not, its corners sharp or each rounded by 0.08-0.2 of
  its shorter side, is a polygon (a box when it is four-sided never happens);
- a triangle closed past its first corner, the tails crossing there, is a polygon;
- a star's outline of 5-7 points, its inner corners at 0.35-0.75 of its tips' radius, is a polygon;
- a rhombus (diamond), a parallelogram or a trapezoid is cornered: a box where squaring it stays within the stroke
  (`beautify.box_geometry`), else the four-sided polygon drawn;
- a rectangle with rounded corners (radius up to a quarter of its short side: straight sides longer than the arcs) is
  a box, as `tests/stroke_cases.py` "rectangle-rounded-corners" already says; so is a box a hurried hand swung round
  at one or two corners (radius 0.2-0.4 of the short side) or cut one corner of (a chamfer 0.15-0.35 of it);
- a circle is round (circle, or an ellipse within the round-off); an oval of aspect 1.3-3 is an ellipse; an egg (one
  end 10-25 % fatter) or a circle whose radius wanders by 4-8 % is round.

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
from closed_shape_families import (
    box_corners_off,
    circle,
    crossed_triangle,
    egg,
    irregular,
    lumpy_circle,
    oval,
    parallelogram,
    regular,
    rhombus,
    rounded_polygon,
    rounded_rectangle,
    star,
    trapezoid,
)
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
TUNING_SEEDS = range(0, 30)
HELD_BACK_SEEDS = range(1000, 1030)
ROUND = ("circle", "ellipse")
CORNERED = ("box", "polygon")


FAMILIES: dict[str, Callable[[random.Random], Shape]] = {
    "pentagon": regular(5), "hexagon": regular(6), "octagon": regular(8),
    "pentagon-irregular": irregular(5), "hexagon-irregular": irregular(6), "octagon-irregular": irregular(8),
    "rhombus": rhombus, "parallelogram": parallelogram, "trapezoid": trapezoid,
    "rounded-rectangle": rounded_rectangle, "triangle-crossed": crossed_triangle,
    "star-5": star(5), "star-6": star(6), "star-7": star(7),
    "box-corners-rounded": box_corners_off(rounded=True), "box-corner-cut": box_corners_off(rounded=False),
    "circle": circle, "oval-1.3-1.8": oval(1.3, 1.8), "oval-1.8-3": oval(1.8, 3.0),
}
"""The families up to session 19 (`bench_units` and tests/test_units read these alone)."""
LATER_FAMILIES: dict[str, Callable[[random.Random], Shape]] = {
    "heptagon": regular(7), "heptagon-irregular": irregular(7),
    "pentagon-rounded": rounded_polygon(5), "hexagon-rounded": rounded_polygon(6),
    "heptagon-rounded": rounded_polygon(7), "octagon-rounded": rounded_polygon(8),
    "egg": egg, "circle-lumpy": lumpy_circle,
}
"""Session 20's (issue 25, wt-polygons): heptagons, polygons with every corner rounded a little, eggs, lumpy circles."""
ALL_FAMILIES = {**FAMILIES, **LATER_FAMILIES}
EXPECTED: dict[str, tuple[str, ...]] = {
    **{f: ("polygon",) for f in ALL_FAMILIES
       if f.startswith(("pentagon", "hexagon", "heptagon", "octagon", "star", "triangle"))},
    "rhombus": CORNERED, "parallelogram": CORNERED, "trapezoid": CORNERED, "rounded-rectangle": ("box",),
    "box-corners-rounded": ("box",), "box-corner-cut": ("box",),
    "circle": ROUND, "oval-1.3-1.8": ("ellipse",), "oval-1.8-3": ("ellipse",), "egg": ROUND, "circle-lumpy": ROUND,
}
"""The kinds a person expects for each family (either kind of a pair counts as right)."""


def shape(family: str, seed: int) -> Shape:
    made = ALL_FAMILIES[family](random.Random(f"{family}:{seed}"))
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
    "careful": careful, "hurried": hurried, "hurried-coarse": hurried_coarse}
"""The pens up to session 19 (`bench_units` reads these alone)."""
ALL_PENS = {**PENS, "slow": slow}


def read(family: str, pen: str, seed: int, timed: bool, learned: bool = True) -> tuple[str | None, float | None]:
    """The kind read and, for a cornered reading, the IoU of its outline with the outline meant."""
    s = shape(family, seed)
    drawn = ALL_PENS[pen](s, seed)
    got = recognize_stroke([p[:2] for p in drawn], [p[2] for p in drawn] if timed else None, learned=learned)
    if got.kind not in CORNERED or got.geometry is None:
        return got.kind, None
    a, b = ShapelyPolygon(shape_points(got.geometry)), ShapelyPolygon(outline_of(s))
    if not (a.is_valid and b.is_valid):
        return got.kind, 0.0
    return got.kind, a.intersection(b).area / a.union(b).area


def run(seeds: range, learned: bool) -> dict[tuple[str, str, bool], list[tuple[str | None, float | None]]]:
    out: dict[tuple[str, str, bool], list[tuple[str | None, float | None]]] = defaultdict(list)
    for family in ALL_FAMILIES:
        for pen in ALL_PENS:
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
    for pen in (*ALL_PENS, "all"):
        n = pooled[(pen, "n")]
        lines.append(f"- {pen}: class right {pooled[(pen, 'class')]}/{n}, kind right {pooled[(pen, 'exact')]}/{n}")
    return lines


def seed_range(text: str) -> range:
    """``--seeds``' value: ``A:B`` (seeds A to B-1), or the names the other pen benches take, ``tune`` and ``held``."""
    named = {"tune": TUNING_SEEDS, "held": HELD_BACK_SEEDS}
    if text in named:
        return named[text]
    try:
        a, b = map(int, text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: expected A:B (two whole numbers), tune or held") from None
    if b <= a:
        raise argparse.ArgumentTypeError(f"{text!r}: the range A:B must end after it starts")
    return range(a, b)


def add_seed_arguments(parser: argparse.ArgumentParser) -> None:
    """``--seeds A:B`` and ``--held-back``, the seeds a pen-model bench draws (`chosen_seeds`; `bench_boxes` and
    `bench_rounded_boxes` ask the same; `family_bench_parser` adds them)."""
    parser.add_argument("--seeds", type=seed_range,
                        help="A:B, a range of seeds, or tune (0:30, the default) or held (1000:1030)")
    parser.add_argument("--held-back", action="store_true", help="the held-back seeds 1000-1029")


def family_bench_parser(doc: str) -> argparse.ArgumentParser:
    """The arguments of a bench that reads pen-model families of one closed shape (`bench_boxes`, `bench_triangles`):
    the seeds (`add_seed_arguments`), ``--rules``, ``--families`` and ``--misread``; described by ``doc``'s first
    line."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    add_seed_arguments(parser)
    parser.add_argument("--rules", action="store_true", help="the rules' reading, without the learned ranker")
    parser.add_argument("--families", help="a comma-separated subset of the families (default: all)")
    parser.add_argument("--misread", action="store_true", help="list every misread stroke")
    return parser


def chosen_seeds(args: argparse.Namespace) -> tuple[range, str]:
    """The seeds asked for (`add_seed_arguments`) and their name: the held-back seeds, a range, or the tuning seeds."""
    if args.held_back:
        return HELD_BACK_SEEDS, "held-back seeds 1000-1029"
    if args.seeds == HELD_BACK_SEEDS:
        return HELD_BACK_SEEDS, "held-back seeds 1000-1029"
    if args.seeds:
        return args.seeds, f"seeds {args.seeds.start}-{args.seeds.stop - 1}"
    return TUNING_SEEDS, "tuning seeds 0-29"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_seed_arguments(parser)
    parser.add_argument("--rules", action="store_true", help="the rules' reading, without the learned ranker")
    parser.add_argument("--json", type=Path, help="write every reading here")
    parser.add_argument("--families", help="a comma-separated subset of the families (default: all)")
    args = parser.parse_args()
    if args.families:
        for name in set(ALL_FAMILIES) - set(args.families.split(",")):
            del ALL_FAMILIES[name]
    seeds, name = chosen_seeds(args)
    results = run(seeds, learned=not args.rules)
    print("\n".join(report(results, f"{name}, {'rules' if args.rules else 'shipped recogniser'}")))
    if args.json:
        args.json.write_text(json.dumps({f"{f}|{p}|{t}": v for (f, p, t), v in results.items()}, indent=0))


if __name__ == "__main__":
    main()
