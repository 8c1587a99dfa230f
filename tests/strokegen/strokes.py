"""Seeded generators of hand-drawn strokes, one per recognised kind, for tests and benchmarks; recognises nothing.

Each generator builds the ideal shape of its kind at unit size (largest extent 1) with randomised proportions,
has `noise` draw it with a modelled hand and tablet (corners, hooks, closure gaps and overshoots, speed
profile, tremor, spikes, duplicates, pixel rounding), then scales it to ``size`` (10-2000 units, log-uniform,
unless given), mirrors it half the time, rotates it by ``angle`` and moves it to ``center``. A generated stroke is
labelled by construction; what counts as recognised is left to the tests and the benchmark. Pure: all randomness
comes from the ``random.Random`` passed in, and times are computed (seconds from the first sample), never read.

>>> import random
>>> stroke = box(random.Random(1), size=100.0)
>>> stroke[0][2], all(len(sample) == 3 for sample in stroke)
(0.0, True)
>>> [len(strokes) for strokes in (generate("circle", random.Random(2)), generate("x", random.Random(2)))]
[1, 2]
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from typing import NamedTuple

from strokegen.noise import (
    CORNERED_CLOSURE,
    ROUND_CLOSURE,
    PenPath,
    Point,
    Sample,
    add_hooks,
    closed_traversal,
    closure_delta,
    corner_path,
    digitise,
    draw,
    normalise,
    place,
)
from strokegen.shapes import (
    CURVE_VARIANTS,
    POLYGON_VARIANTS,
    POLYLINE_VARIANTS,
    curve_points,
    polygon_vertices,
    polyline_vertices,
    sign,
)

Stroke = list[Sample]
TAU = 2 * math.pi


class Pose(NamedTuple):
    """Where a unit-size shape goes: its largest extent in units, mirror (x -> -x), rotation (radians), centre."""

    size: float
    angle: float
    center: Point
    mirror: bool


def _pose(rng: random.Random, size: float | None, angle: float | None, center: Point | None) -> Pose:
    drawn = Pose(
        math.exp(rng.uniform(math.log(10.0), math.log(2000.0))),
        rng.uniform(0.0, TAU),
        (rng.uniform(0.0, 2000.0), rng.uniform(0.0, 2000.0)),
        rng.random() < 0.5,
    )
    return Pose(
        drawn.size if size is None else size,
        drawn.angle if angle is None else angle,
        drawn.center if center is None else center,
        drawn.mirror,
    )


def _finish(path: PenPath, rng: random.Random, pose: Pose, t0: float = 0.0) -> Stroke:
    """Hooks, the hand, the pose and the tablet; pixel rounding on 40 % of strokes of 150 units or more."""
    samples = draw(add_hooks(path, rng), rng)
    placed = place(samples, size=pose.size, angle=pose.angle, center=pose.center, mirror=pose.mirror, t0=t0)
    quantum = 1.0 if pose.size >= 150 and rng.random() < 0.4 else None
    return digitise(placed, rng, size=pose.size, quantum=quantum)


# ---------------------------------------------------------------------------------------------------------- open


def line(
    rng: random.Random, *, size: float | None = None, angle: float | None = None, center: Point | None = None
) -> Stroke:
    """A straight line, bowed by at most 1.5 % of its length."""
    pose = _pose(rng, size, angle, center)
    bow = rng.uniform(-0.015, 0.015)
    points = [(u / 20 - 0.5, 4 * bow * (u / 20) * (1 - u / 20)) for u in range(21)]
    return _finish(PenPath(tuple(points)), rng, pose)


def polyline(
    rng: random.Random,
    *,
    variant: str | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """An open chain of 2-5 straight segments: V/caret, check, L, Z, zigzag/W, bracket, arrow, x, or random."""
    pose = _pose(rng, size, angle, center)
    chosen = variant or rng.choice(POLYLINE_VARIANTS)
    for _ in range(50):
        vertices = normalise(polyline_vertices(rng, chosen))
        if math.dist(vertices[0], vertices[-1]) >= 0.3:  # plainly open, not a polygon left open
            break
    return _finish(corner_path(vertices, rng), rng, pose)


def arc(
    rng: random.Random,
    *,
    sweep_deg: float | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """Part of a circle sweeping 60-215 degrees either way, its radius wobbling by up to 1 %.

    Past about 225 degrees the recogniser reads a smooth round stroke as a circle left open, which is
    how people draw circles (a third of the $1 study's circles stop 60-120 degrees short), so arcs are
    generated below that.
    """
    pose = _pose(rng, size, angle, center)
    sweep = math.radians(sweep_deg if sweep_deg is not None else rng.uniform(60.0, 215.0)) * sign(rng)
    start, wobble, phase = rng.uniform(0, TAU), rng.uniform(0, 0.01), rng.uniform(0, TAU)
    n = 60
    points = [
        ((1 + wobble * math.sin(3 * a + phase)) * math.cos(a), (1 + wobble * math.sin(3 * a + phase)) * math.sin(a))
        for a in (start + sweep * k / n for k in range(n + 1))
    ]
    return _finish(PenPath(tuple(normalise(points))), rng, pose)


def curve(
    rng: random.Random,
    *,
    variant: str | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """A smooth open curve that is no circular arc: S, oval C, tilde, question mark, brace, or pigtail."""
    pose = _pose(rng, size, angle, center)
    points = normalise(curve_points(rng, variant or rng.choice(CURVE_VARIANTS)))
    return _finish(PenPath(tuple(points)), rng, pose)


def helix(
    rng: random.Random,
    *,
    loops: int | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """A spring drawn as one continuous coil: 3-10 loops advancing along an axis, loop size and pitch uneven."""
    pose = _pose(rng, size, angle, center)
    n = loops if loops is not None else rng.randint(3, 10)
    radius_over_pitch, squash = rng.uniform(0.35, 1.0), rng.uniform(0.5, 1.0)
    phase, vary, direction = rng.uniform(0, TAU), rng.uniform(0.0, 0.1), sign(rng)
    steps = 40 * n
    points = []
    for k in range(steps + 1):
        a = TAU * n * k / steps
        r = radius_over_pitch * (1 + vary * math.sin(a / n + phase))
        along = a / TAU + vary * math.sin(0.7 * a / n)
        points.append((along + squash * r * math.cos(a + phase), direction * r * math.sin(a + phase)))
    return _finish(PenPath(tuple(normalise(points))), rng, pose)


# -------------------------------------------------------------------------------------------------------- closed


def _closed(rng: random.Random, vertices: list[Point], pose: Pose, at_corner: float = 0.5) -> Stroke:
    """Draws the closed polygon ``vertices`` once round from a corner or mid-side, either way, gap or overshoot."""
    vertices = normalise(vertices if rng.random() < 0.5 else vertices[::-1])
    n = len(vertices)
    perimeter = sum(math.dist(vertices[k], vertices[(k + 1) % n]) for k in range(n))
    fraction = 0.0 if rng.random() < at_corner else rng.uniform(0.2, 0.8)
    chain = closed_traversal(vertices, rng.randrange(n), fraction, closure_delta(rng, perimeter, CORNERED_CLOSURE))
    return _finish(corner_path(chain, rng), rng, pose)


def box(
    rng: random.Random,
    *,
    aspect: float | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """A rectangle (height/width 0.3-3) at any rotation, its corners moved by up to 2 % of the size by the hand."""
    pose = _pose(rng, size, angle, center)
    h = aspect if aspect is not None else math.exp(rng.uniform(math.log(0.3), math.log(3.0)))
    corners = [(0.0, 0.0), (1.0, 0.0), (1.0, h), (0.0, h)]
    extent = max(1.0, h)
    vertices = [(x + rng.uniform(-0.02, 0.02) * extent, y + rng.uniform(-0.02, 0.02) * extent) for x, y in corners]
    return _closed(rng, vertices, pose)


def _oval(rng: random.Random, ratio: float, pose: Pose) -> Stroke:
    """Once round an oval of axis ratio ``ratio``, lumpy by up to 3 %, its radius drifting by up to 12 % (a spiral)."""
    start, direction = rng.uniform(0, TAU), sign(rng)
    lumps, phase, drift = rng.uniform(0, 0.03), rng.uniform(0, TAU), rng.uniform(-0.12, 0.12)
    mean_radius = 0.5 * (1 + ratio) / 2
    perimeter = TAU * mean_radius
    sweep = direction * (TAU + closure_delta(rng, perimeter, ROUND_CLOSURE) / mean_radius)
    n = 120
    points = []
    for k in range(n + 1):
        a = start + sweep * k / n
        r = 1 + lumps * math.sin(3 * a + phase) + drift * k / n
        points.append((0.5 * r * math.cos(a), 0.5 * ratio * r * math.sin(a)))
    return _finish(PenPath(tuple(normalise(points))), rng, pose)


def circle(
    rng: random.Random, *, size: float | None = None, angle: float | None = None, center: Point | None = None
) -> Stroke:
    """A circle as people draw one: slightly oval (axis ratio 0.85-1), with a gap or an overshoot."""
    pose = _pose(rng, size, angle, center)
    return _oval(rng, rng.uniform(0.85, 1.0), pose)


def ellipse(
    rng: random.Random,
    *,
    ratio: float | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """An ellipse of axis ratio 0.3-0.8 at any rotation, with a gap or an overshoot."""
    pose = _pose(rng, size, angle, center)
    return _oval(rng, ratio if ratio is not None else rng.uniform(0.3, 0.8), pose)


def polygon(
    rng: random.Random,
    *,
    variant: str | None = None,
    size: float | None = None,
    angle: float | None = None,
    center: Point | None = None,
) -> Stroke:
    """A closed freeform polygon: triangle, pentagon, non-rectangular quadrilateral, or a five-point star."""
    pose = _pose(rng, size, angle, center)
    return _closed(rng, polygon_vertices(rng, variant or rng.choice(POLYGON_VARIANTS)), pose, at_corner=0.6)


# ------------------------------------------------------------------------------------------------------- x symbol


def x(
    rng: random.Random, *, size: float | None = None, angle: float | None = None, center: Point | None = None
) -> list[Stroke]:
    """TWO strokes: short lines crossing near their middles at 70-110 degrees, the second drawn after a pause."""
    pose = _pose(rng, size, angle, center)
    crossing = math.radians(rng.uniform(70.0, 110.0))
    strokes, t0 = [], 0.0
    for k, heading in enumerate((0.0, crossing)):
        length = 1.0 if k == 0 else rng.uniform(0.8, 1.2)
        offset = rng.uniform(-0.15, 0.15) * length  # where the crossing falls, from this line's middle
        d = (math.cos(heading), math.sin(heading))
        ends = [(-d[0] * (length / 2 + offset), -d[1] * (length / 2 + offset))]
        ends.append((ends[0][0] + d[0] * length, ends[0][1] + d[1] * length))
        stroke = _finish(PenPath(tuple(ends if rng.random() < 0.5 else ends[::-1])), rng, pose, t0)
        strokes.append(stroke)
        t0 = stroke[-1][2] + rng.uniform(0.15, 0.6)
    return strokes


# -------------------------------------------------------------------------------------------------------- lookup

GENERATORS: dict[str, Callable[..., Stroke | list[Stroke]]] = {
    "line": line,
    "polyline": polyline,
    "box": box,
    "circle": circle,
    "ellipse": ellipse,
    "arc": arc,
    "curve": curve,
    "helix": helix,
    "polygon": polygon,
    "x": x,
}
"""One generator per kind of `primitives.KINDS`; ``x`` gives two strokes, the others one."""


def generate(kind: str, rng: random.Random) -> list[Stroke]:
    """The strokes of one random drawing of ``kind`` (two for ``"x"``, else one)."""
    if kind not in GENERATORS:
        raise ValueError(f"no generator for kind {kind!r}; expected one of {sorted(GENERATORS)}")
    made = GENERATORS[kind](rng)
    return made if kind == "x" else [made]  # type: ignore[list-item]
