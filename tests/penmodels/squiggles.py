"""Squiggles drawn smoothly (issue 25, session 27): an S whose two bends are round, and the zig-zag with rounded points
it must not take in; in canvas pixels, seeded, no noise (the pens draw them:
`penmodels.hurried`, the virtual pen).

- ``round-s``: two bends, each a circular arc turning 110-170 degrees (radius 0.18-0.35 of the mark's height), turning
  opposite ways, joined by a middle side that bows up to 4 % of its chord, with arms 0.1-0.5 of the middle side at the
  ends; 120-360 px across. Drawn slowly, each bend turns over more than the corner finder's straw, so no corner is
  found where a wave's bends are looked for, while the open-stroke rules, on their fewer points, find both and read an
  N (tutorboard seed260730's squiggles, `bench_waves`' s-curve by the careful pen);
and, read as a polyline (what it must not take in):

- ``round-peaked-zigzag``: 4-6 teeth whose points are rounded over 8-18 % of their sides and whose sides bow up to 6 %
  of their chords, each its own way (people's zig-zags with round peaks: pixelfac/user02 and user03, hat359/user5,
  whose sharpest point turns within 0.12-0.19 of its shorter side and whose sides bow 0.08-0.11 as `waves` measures),
  150-420 px long, 0.2-0.4 of that high.

- ``curly-line`` (session 33): a line with 3-5 curls drawn in it where the hand curled (a Quick, Draw! player's
  squiggle: tutorboard seed260730 #4, #41), each a loop the pen goes once round while moving on by 0.3-0.8 of its
  radius, radii uneven by up to a quarter, straight runs of 1.5-4 radii between them, each 0.3-1.7 of that, leads at
  the ends; 200-500 px across. Read as a curve: a line with curls is no spring (`beautify.UNEVEN_PITCH`); curls that
  happen to fall evenly are read as a helix, as a spring's loops;

- ``two-curls`` (session 34): a line with 2 curls drawn in it (tutorboard seed260730 #20, #32: an m whose dips
  curl, a line with a curl and a hump), drawn as ``curly-line``'s, the run between them 1-4 radii. Read as a curve: of
  two loops one pitch is seen, nothing to tell a spring by (`beautify.MIN_PITCHES`);

and, read as a helix (what it must not take in):

- ``coil``: a spring drawn as one coil, 3-6 loops of radius 0.5-1.0 of the pitch, pitch and radius uneven by up to a
  tenth, leads of up to a pitch at the ends; 150-450 px across.

Round humps joined at tight dips (an m drawn loosely, as some quickdraw squiggles are) were tried as a family and left
out: their dips turn within 0.16-0.17 of their sides, inside the people's round-peaked zig-zags (docs/BENCHMARKS.md).

Mirrored half the time, drawn the other way half the time, turned up to 12 degrees or (the S) any angle.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable

from penmodels.open_marks import Mark, _arc, _placed

Point = tuple[float, float]
EXPECTED = {"round-s": "curve", "round-peaked-zigzag": "polyline", "curly-line": "curve", "coil": "helix",
            "two-curls": "curve"}
"""The kind each family is read as: a squiggle is a curve (benchmarks/label_kinds.tsv), a zig-zag a polyline, a
spring a helix."""


def _line(a: Point, b: Point, n: int) -> list[Point]:
    """``n`` points after ``a`` along the segment to ``b``."""
    return [(a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n) for k in range(1, n + 1)]


def _bowed(a: Point, b: Point, bow: float, n: int) -> list[Point]:
    """``n`` points after ``a`` to ``b``, bowed sideways by ``bow`` of the chord at its middle (a parabola)."""
    chord = math.dist(a, b)
    normal = ((a[1] - b[1]) / chord, (b[0] - a[0]) / chord)
    return [(a[0] + (b[0] - a[0]) * u + 4 * bow * chord * u * (1 - u) * normal[0],
             a[1] + (b[1] - a[1]) * u + 4 * bow * chord * u * (1 - u) * normal[1])
            for u in (k / n for k in range(1, n + 1))]


def _turtle_arc(pos: Point, heading: float, radius: float, sweep: float, n: int) -> tuple[list[Point], float]:
    """A bend from ``pos`` heading ``heading`` (radians), turning ``sweep`` (positive: clockwise on screen, y down)
    along a circle of ``radius``: its ``n`` points after ``pos`` and the heading it leaves on."""
    side = 1.0 if sweep > 0 else -1.0
    centre = (pos[0] - side * radius * math.sin(heading), pos[1] + side * radius * math.cos(heading))
    start = math.atan2(pos[1] - centre[1], pos[0] - centre[0])
    return _arc(centre, radius, start, sweep, n), heading + sweep


def _ahead(pos: Point, heading: float, length: float) -> Point:
    return (pos[0] + length * math.cos(heading), pos[1] + length * math.sin(heading))


def round_s(seed: int) -> Mark:
    """An S of two round bends (module docstring)."""
    rng = random.Random(f"round-s:{seed}")
    middle = 1.0
    radius = rng.uniform(0.18, 0.35) * middle
    turns = (math.radians(rng.uniform(110, 170)), math.radians(rng.uniform(110, 170)))
    heading = rng.uniform(-0.3, 0.3)
    pos: Point = (0.0, 0.0)
    pts: list[Point] = [pos]
    arm = rng.uniform(0.1, 0.5) * middle
    pts += _line(pos, _ahead(pos, heading, arm), 8)
    pos = pts[-1]
    bend, heading = _turtle_arc(pos, heading, radius, turns[0], 20)
    pts += bend
    pos = pts[-1]
    end = _ahead(pos, heading, middle)
    pts += _bowed(pos, end, rng.uniform(-0.04, 0.04), 16)
    pos = pts[-1]
    bend, heading = _turtle_arc(pos, heading, radius * rng.uniform(0.8, 1.25), -turns[1], 20)
    pts += bend
    pos = pts[-1]
    pts += _line(pos, _ahead(pos, heading, rng.uniform(0.1, 0.5) * middle), 8)
    return Mark("round-s", _placed(rng, _scaled(rng, pts, 120, 360), rng.random() < 0.5), True)


def round_peaked_zigzag(seed: int) -> Mark:
    """A zig-zag whose points are rounded over 8-18 % of their sides, its sides bowed (module docstring)."""
    rng = random.Random(f"round-peaked-zigzag:{seed}")
    teeth = rng.randint(4, 6)
    length = 1.0
    height = rng.uniform(0.2, 0.4) * length
    corners = [((k / teeth) * length, height * (0.5 if k % 2 else -0.5)) for k in range(teeth + 1)]
    pts: list[Point] = [corners[0]]
    for i in range(1, teeth):
        a, b, c = corners[i - 1], corners[i], corners[i + 1]
        cut = rng.uniform(0.08, 0.18)
        into = (b[0] + (a[0] - b[0]) * cut, b[1] + (a[1] - b[1]) * cut)
        out = (b[0] + (c[0] - b[0]) * cut, b[1] + (c[1] - b[1]) * cut)
        pts += _bowed(pts[-1], into, rng.uniform(-0.06, 0.06), 10)
        for j in range(1, 7):  # a quadratic round the point, from ``into`` to ``out``
            u = j / 6
            pts.append(((1 - u) ** 2 * into[0] + 2 * u * (1 - u) * b[0] + u * u * out[0],
                        (1 - u) ** 2 * into[1] + 2 * u * (1 - u) * b[1] + u * u * out[1]))
    pts += _bowed(pts[-1], corners[-1], rng.uniform(-0.06, 0.06), 10)
    return Mark("round-peaked-zigzag", _placed(rng, _scaled(rng, pts, 150, 420), False), True)


def _scaled(rng: random.Random, pts: list[Point], least: float, most: float) -> list[Point]:
    """``pts`` scaled so that their bounding box's diagonal is ``least``-``most`` px, centred on the origin."""
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    scale = rng.uniform(least, most) / math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    return [((x - cx) * scale, (y - cy) * scale) for x, y in pts]


def _loops(rng: random.Random, radii: list[float], advances: list[float], gaps: list[float],
           leads: tuple[float, float]) -> list[Point]:
    """A line along x with a loop drawn in it at each of ``radii`` (each the pen going once round, up and back, while
    moving on by its ``advances``: a prolate cycloid's arch), straight runs of ``gaps`` between them and ``leads`` at
    the ends, bowed a little each."""
    pts: list[Point] = [(0.0, 0.0)]
    pts += _bowed(pts[-1], (leads[0], 0.0), rng.uniform(-0.05, 0.05), 8) if leads[0] > 0 else []
    for k, (r, d) in enumerate(zip(radii, advances, strict=True)):
        x0 = pts[-1][0]
        pts += [(x0 + d * a / (2 * math.pi) + r * math.sin(a), r * math.cos(a) - r)
                for a in (2 * math.pi * j / 32 for j in range(1, 33))]
        if k < len(gaps) and gaps[k] > 0:
            pts += _bowed(pts[-1], (pts[-1][0] + gaps[k], 0.0), rng.uniform(-0.05, 0.05), 8)
    if leads[1] > 0:
        pts += _bowed(pts[-1], (pts[-1][0] + leads[1], 0.0), rng.uniform(-0.05, 0.05), 8)
    return pts


def curly_line(seed: int) -> Mark:
    """A line with 3-5 curls drawn in it where the hand curled (module docstring)."""
    rng = random.Random(f"curly-line:{seed}")
    n = rng.randint(3, 5)
    radius = 1.0
    radii = [radius * rng.uniform(0.75, 1.25) for _ in range(n)]
    advances = [r * rng.uniform(0.3, 0.8) for r in radii]
    gap = radius * rng.uniform(1.5, 4.0)
    gaps = [gap * rng.uniform(0.3, 1.7) for _ in range(n - 1)]
    leads = (gap * rng.uniform(0.3, 1.5), gap * rng.uniform(0.3, 1.5))
    return Mark("curly-line", _placed(rng, _scaled(rng, _loops(rng, radii, advances, gaps, leads), 200, 500), False),
                True)


def two_curls(seed: int) -> Mark:
    """A line with 2 curls drawn in it (module docstring)."""
    rng = random.Random(f"two-curls:{seed}")
    radii = [rng.uniform(0.75, 1.25) for _ in range(2)]
    advances = [r * rng.uniform(0.3, 0.8) for r in radii]
    gap = rng.uniform(1.0, 4.0)
    leads = (gap * rng.uniform(0.3, 1.5), gap * rng.uniform(0.3, 1.5))
    return Mark("two-curls", _placed(rng, _scaled(rng, _loops(rng, radii, advances, [gap], leads), 150, 450), False),
                True)


def coil(seed: int) -> Mark:
    """A spring drawn as one coil: 3-6 loops following each other evenly (module docstring)."""
    rng = random.Random(f"coil:{seed}")
    n = rng.randint(3, 6)
    pitch = 1.0
    radius = pitch * rng.uniform(0.5, 1.0)
    radii = [radius * rng.uniform(0.9, 1.1) for _ in range(n)]
    advances = [pitch * rng.uniform(0.9, 1.1) for _ in range(n)]
    leads = (pitch * rng.uniform(0.0, 1.0), pitch * rng.uniform(0.0, 1.0))
    return Mark("coil", _placed(rng, _scaled(rng, _loops(rng, radii, advances, [0.0] * (n - 1), leads), 150, 450),
                                False), True)


FAMILIES: dict[str, Callable[[int], Mark]] = {"round-s": round_s, "round-peaked-zigzag": round_peaked_zigzag,
                                              "curly-line": curly_line, "coil": coil, "two-curls": two_curls}
