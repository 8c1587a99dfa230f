"""Hand-made edge cases for the stroke recogniser: named strokes and the kind each must get; data only, no checks.

Straight-sided shapes are written out as their vertices (`_chain` only fills in points every few units, as a pen
would report them); round and spiral shapes come from the small formulas below, with every parameter written in
the case, so each case says exactly what it is. Nothing here is random. Coordinates are screen units, y down;
a point is ``(x, y)`` or ``(x, y, t)`` with ``t`` in seconds.

``expected_kind`` is a kind of `primitives.KINDS` (scene.recognition); None means the input cannot be recognised,
and the recogniser must say so (kind None and a reason) rather than raise; `NOT_X` means two strokes that are not
an X-symbol (any answer but "x").

Decided here: **two long perpendicular lines crossing at their middles are an X.** The thesis asks for "short"
strokes, but the recogniser sees no canvas (coordinates may be pixels or canvas fractions), so "short" cannot be
an absolute length; the tests the thesis lists (they cross, their midpoints are close, they are roughly
perpendicular) are scale-free, and whether a big X means a joint is for the interpretation step, which knows what
lies under it. Pairs that fail one of the three tests are `NOT_X` cases.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

Point = tuple[float, ...]
Stroke = tuple[Point, ...]
NOT_X = "not x"
NAN, INF = float("nan"), float("inf")


@dataclass(frozen=True, slots=True)
class Case:
    """One hand-made input and what the recogniser must make of it.

    Attributes:
        name: unique, used as the test id.
        strokes: one stroke, or two for the X-symbol cases; each point is (x, y) or (x, y, t seconds).
        expected_kind: a kind of `KINDS`; None: no kind and a non-empty reason; `NOT_X`: anything but "x".
        note: why the case is here, or what a reviewer should know about it.
    """

    name: str
    strokes: tuple[Stroke, ...]
    expected_kind: str | None
    note: str


def _chain(*vertices: tuple[float, float], step: float = 5.0) -> Stroke:
    """The polyline through ``vertices`` with a point at least every ``step`` units (vertices kept)."""
    out = [vertices[0]]
    for (x0, y0), (x1, y1) in itertools.pairwise(vertices):
        n = max(1, math.ceil(math.dist((x0, y0), (x1, y1)) / step))
        out += [(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n) for k in range(1, n + 1)]
    return tuple(out)


def _arc(
    cx: float, cy: float, r: float, start_deg: float, sweep_deg: float, n: int, ry: float | None = None, tilt: float = 0
) -> Stroke:
    """``n + 1`` points on an arc (or on an ellipse with semi-axes ``r`` and ``ry``, tilted ``tilt`` degrees)."""
    ry = r if ry is None else ry
    c, s = math.cos(math.radians(tilt)), math.sin(math.radians(tilt))
    out = []
    for k in range(n + 1):
        a = math.radians(start_deg + sweep_deg * k / n)
        x, y = r * math.cos(a), ry * math.sin(a)
        out.append((cx + x * c - y * s, cy + x * s + y * c))
    return tuple(out)


def _bowed(length: float, sagitta: float, n: int = 20) -> Stroke:
    """``n + 1`` points on the circular arc from (0, 0) to (``length``, 0) that bulges ``sagitta`` units (y down)."""
    radius = (length**2 / 4 + sagitta**2) / (2 * sagitta)
    half = math.asin(length / 2 / radius) if sagitta <= length / 2 else math.pi - math.asin(length / 2 / radius)
    cx, cy = length / 2, sagitta - radius
    start = math.pi / 2 + half
    return tuple(
        (cx + radius * math.cos(start - 2 * half * k / n), cy + radius * math.sin(start - 2 * half * k / n))
        for k in range(n + 1)
    )


def _spring(x0: float, y0: float, loops: int, pitch: float, radius: float, vertical: bool = False) -> Stroke:
    """A coil: the pen circles ``loops`` times while moving ``pitch`` along the axis per loop."""
    out = []
    for k in range(40 * loops + 1):
        a = 2 * math.pi * k / 40
        along, across = pitch * a / (2 * math.pi) + radius * math.cos(a), radius * math.sin(a)
        out.append((x0 + across, y0 + along) if vertical else (x0 + along, y0 + across))
    return tuple(out)


def _bezier(p0: Point, p1: Point, p2: Point, p3: Point, n: int = 20) -> Stroke:
    """``n + 1`` points on the cubic Bezier with control points ``p0`` .. ``p3``."""
    out = []
    for t in (k / n for k in range(n + 1)):
        weights = ((1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t * t * (1 - t), t**3)
        out.append(tuple(sum(w * p[i] for w, p in zip(weights, (p0, p1, p2, p3), strict=True)) for i in range(2)))
    return tuple(out)


def _timed(stroke: Stroke, rate_hz: float = 100.0, t0: float = 0.0) -> Stroke:
    return tuple((x, y, t0 + k / rate_hz) for k, (x, y) in enumerate(stroke))


def _huge_stroke() -> Stroke:
    """100,000 points once round a circle of radius 500 with a 0.5 % seven-lobed wobble."""
    n = 100_000
    radii_angles = ((500 * (1 + 0.005 * math.sin(7 * a)), a) for a in (2 * math.pi * k / (n - 1) for k in range(n)))
    return tuple((1000 + r * math.cos(a), 1000 + r * math.sin(a)) for r, a in radii_angles)


_SCRIBBLE = tuple((100 + 0.5 * (4 - abs(k % 8 - 4)), 100.0) for k in range(480))
_QUESTION_HOOK = _arc(100, 60, 30, 190, 230, 30)  # from the left, over the top, down the right side


CASES: tuple[Case, ...] = (
    # boxes
    Case("square-perfect", (_chain((0, 0), (100, 0), (100, 100), (0, 100), (0, 0)),), "box", "the ideal box"),
    Case("square-gap-15pc", (_chain((0, 0), (100, 0), (100, 100), (0, 100), (0, 15)),), "box",
         "stops 15 units (15 % of the side) short of its start"),
    Case("square-twice-round", (_chain((0, 0), (100, 0), (100, 100), (0, 100), (0, 0), (100, 0), (100, 100),
                                       (0, 100), (0, 0)),), "box", "overtraced: the pen goes round twice"),
    Case("rectangle-rounded-corners",
         (_chain((15, 0), (185, 0)) + _arc(185, 15, 15, -90, 90, 6) + _chain((200, 15), (200, 85))
          + _arc(185, 85, 15, 0, 90, 6) + _chain((185, 100), (15, 100)) + _arc(15, 85, 15, 90, 90, 6)
          + _chain((0, 85), (0, 15)) + _arc(15, 15, 15, 180, 90, 6),), "box",
         "200 x 100, corners rounded with radius 15 (15 % of the short side)"),
    Case("rectangle-thin-10-to-1", (_chain((0, 0), (300, 0), (300, 30), (0, 30), (0, 0)),), "box",
         "300 x 30: thin, but four right-angled corners"),
    Case("diamond", (_chain((50, 0), (100, 50), (50, 100), (0, 50), (50, 0)),), "box",
         "a square turned 45 degrees is still a box"),
    # round
    Case("circle-8-points", (_arc(50, 50, 50, 0, 360, 8),), "circle",
         "8 points round a circle and a 9th back on the first: sparse sampling, not an octagon"),
    Case("circle-overshoot-20pc", (_arc(50, 50, 50, 0, 432, 72),), "circle", "runs on 72 degrees past its start"),
    Case("circle-tiny-r3", (_arc(10, 10, 3, 0, 360, 24),), "circle", "radius 3 units: no absolute size limit"),
    Case("circle-huge-r5000", (_arc(0, 0, 5000, 30, 360, 90),), "circle", "radius 5000 units"),
    Case("ellipse-3-to-1-tilted-30", (_arc(200, 200, 150, 0, 360, 72, ry=50, tilt=30),), "ellipse",
         "axes 150 and 50, turned 30 degrees"),
    Case("huge-stroke-100k-points", (_huge_stroke(),), "circle",
         "issue 4's bad input: 100,000 points; a circle is a circle however finely sampled (must return promptly)"),
    # lines and arcs
    Case("line-hooked-both-ends", (_timed(_chain((6, 9), (0, 0), (200, 0), (195, -8), step=4)),), "line",
         "hooks of about 10 units (5 %) at both ends, with times"),
    Case("line-two-points", (((10, 10), (110, 60)),), "line", "the least a line can be"),
    Case("line-slightly-bowed", (_bowed(200, 4),), "line", "a 200-unit chord bowed by 4 units (2 %): a 9-degree arc"),
    Case("line-clearly-bowed-is-arc", (_bowed(150, 30),), "arc", "a 150-unit chord bowed by 30 units (20 %): 87 deg"),
    Case("semicircle", (_arc(100, 100, 80, 180, 180, 30),), "arc", "sweeps 180 degrees"),
    # polylines
    Case("v", (_chain((0, 0), (40, 100), (80, 0)),), "polyline", "two strokes of a V"),
    Case("l", (_chain((0, 0), (0, 100), (60, 100)),), "polyline", "a right angle"),
    Case("z", (_chain((0, 0), (100, 0), (0, 100), (100, 100)),), "polyline", "three segments, open"),
    Case("w", (_chain((0, 0), (25, 100), (50, 30), (75, 100), (100, 0)),), "polyline", "four segments"),
    Case("right-square-bracket", (_chain((0, 0), (30, 0), (30, 120), (0, 120)),), "polyline",
         "]: three sides of a rectangle, wide open"),
    # polygons
    Case("triangle", (_chain((0, 100), (60, 0), (120, 100), (0, 100)),), "polygon", "closed, three corners"),
    Case("star", (_chain(*[(50 + 50 * math.sin(math.radians(144 * k)), 50 - 50 * math.cos(math.radians(144 * k)))
                           for k in range(6)]),), "polygon", "five-point star drawn as one self-crossing stroke"),
    # curves
    Case("left-curly-brace", (_bezier((40, 0), (10, 0), (25, 45), (0, 50)) + _bezier((0, 50), (25, 55), (10, 100),
                                                                                       (40, 100))[1:],), "curve",
         "{ with a blunt point at its middle"),
    Case("s-curve", (_arc(50, 25, 25, 0, -270, 30) + _arc(50, 75, 25, 270, 270, 30)[1:],), "curve",
         "two arcs turning opposite ways"),
    Case("question-mark", (_QUESTION_HOOK + _chain(_QUESTION_HOOK[-1][:2], (100, 130), step=5)[1:],), "curve",
         "a hook then a straight tail down (the dot is another stroke)"),
    # springs
    Case("spring-5-loops", (_spring(0, 0, 5, 30, 25),), "helix", "five loops along x"),
    Case("spring-3-loops-vertical", (_spring(0, 0, 3, 40, 30, vertical=True),), "helix", "three loops down the page"),
    # X-symbol and near misses
    Case("x-two-strokes", (_timed(_chain((0, 0), (30, 30), step=3)), _timed(_chain((30, 0), (0, 30), step=3), t0=0.8)),
         "x", "two short perpendicular strokes crossing at their middles"),
    Case("x-long-lines", (_chain((0, 0), (1500, 1500), step=50), _chain((1500, 0), (0, 1500), step=50)), "x",
         "two 2100-unit perpendicular lines crossing at their middles: scale-free, so still an X (module docstring)"),
    Case("two-lines-not-crossing", (_chain((0, 0), (30, 0), step=3), _chain((0, 12), (30, 12), step=3)), NOT_X,
         "an equals sign: two short lines that never meet"),
    Case("two-lines-crossing-shallow", (_chain((0, 0), (40, 0), step=3), _chain((0, -7), (40, 7), step=3)), NOT_X,
         "they cross at their middles but only 20 degrees apart"),
    Case("two-lines-crossing-at-an-end", (_chain((0, 50), (100, 50), step=5), _chain((95, 0), (95, 100), step=5)),
         NOT_X, "perpendicular and crossing, but at the end of one: midpoints 45 % of a length apart"),
    # bad input (issue 4)
    Case("no-strokes", (), None, "recognize_strokes([]): nothing to recognise"),
    Case("empty-stroke", ((),), None, "a stroke with no points"),
    Case("one-point", (((5, 5),),), None, "a tap"),
    Case("two-identical-points", (((5, 5), (5, 5)),), None, "no extent at all"),
    Case("nan-coordinates", ((*_chain((0, 0), (50, 20))[:5], (NAN, 40), *_chain((60, 24), (100, 40))),), None,
         "one NaN x among good points"),
    Case("infinite-coordinates", (((0, 0), (10, 10), (INF, 20), (30, 30)),), None, "one infinite x"),
    Case("zero-area-scribble", (_SCRIBBLE,), None, "back and forth 60 times over the same 2 units: no shape"),
)
"""Every hand-made case; names are unique (a test checks)."""
