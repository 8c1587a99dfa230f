"""Hypothesis strategies for hand-drawn outlines (boxes, U containers, polygons, open polylines) and their strokes.

An `Outline` holds everything needed to redraw one stroke exactly (its repr pastes into ``@example``); `draw`
turns it into canvas points at about 2 px spacing with gaussian jitter from ``random.Random(seed)``.
"""

from __future__ import annotations

import itertools
import math
import random
from dataclasses import dataclass

from hypothesis import strategies as st

from strokegen.outlines import box_corners, draw_outline, u_corners

Point = tuple[float, float]
CENTRE = (800.0, 500.0)
"""Where the outline is drawn: the middle of a 1600 x 1000 canvas."""
SPACING = 2.0
CLOSED = ("rectangle", "u_container", "convex", "concave")


@dataclass(frozen=True)
class Outline:
    """One stroke to draw.

    Attributes:
        kind: ``rectangle``, ``u_container``, ``convex``, ``concave`` (closed) or ``polyline`` (open).
        vertices: the corners in pixels round the origin, unrotated (a U's eight, a polyline's chain).
        angle: rotation in radians.
        start: where the pen starts, as a share of the perimeter (closed outlines only).
        closing: pixels the pen goes past its start (negative: stops short; closed outlines only).
        jitter: standard deviation of the hand's jitter in pixels.
        seed: seeds the jitter.
    """

    kind: str
    vertices: tuple[Point, ...]
    angle: float = 0.0
    start: float = 0.0
    closing: float = 0.0
    jitter: float = 1.0
    seed: int = 0


def draw(o: Outline, reverse: bool = False) -> list[Point]:
    """The stroke's points on the canvas (drawn backwards when ``reverse``)."""
    rng = random.Random(o.seed)
    if o.kind in CLOSED:
        pts = [p[:2] for p in draw_outline(rng, list(o.vertices), jitter=o.jitter, angle=o.angle, start=o.start,
                                           spacing=SPACING, closing=o.closing)]
    else:
        pts = _draw_open(rng, o.vertices, o.angle, o.jitter)
    out = [(x + CENTRE[0], y + CENTRE[1]) for x, y in pts]
    return out[::-1] if reverse else out


def _draw_open(rng: random.Random, vertices: tuple[Point, ...], angle: float, jitter: float) -> list[Point]:
    c, s = math.cos(angle), math.sin(angle)
    pts = [(x * c - y * s, x * s + y * c) for x, y in vertices]
    out = []
    for (ax, ay), (bx, by) in itertools.pairwise(pts):
        n = max(1, round(math.dist((ax, ay), (bx, by)) / SPACING))
        out += [(ax + (bx - ax) * k / n, ay + (by - ay) * k / n) for k in range(n)]
    out.append(pts[-1])
    return [(x + rng.gauss(0, jitter), y + rng.gauss(0, jitter)) for x, y in out]


def _r(x: float, digits: int = 1) -> float:
    return round(x, digits)


def _pts(points: list[Point]) -> tuple[Point, ...]:
    return tuple((_r(x), _r(y)) for x, y in points)


@st.composite
def rectangles(draw_: st.DrawFn) -> tuple[Point, ...]:
    """Long side 60-600 px, aspect 1-40."""
    long, aspect = draw_(st.floats(60, 600)), draw_(st.floats(1, 40))
    return _pts(box_corners(long, long / aspect))


@st.composite
def u_containers(draw_: st.DrawFn) -> tuple[Point, ...]:
    """The thesis's basket: eight corners, open at the top, walls 3 px and up."""
    width, height = draw_(st.floats(60, 400)), draw_(st.floats(40, 300))
    wall = draw_(st.floats(3, max(3.0, min(40.0, width / 4, height / 3))))
    return _pts(u_corners(width, height, wall))


def _angles(draw_: st.DrawFn, n: int) -> list[float]:
    """``n`` increasing angles round the circle, no gap under 0.4 of the even one (no near-duplicate corners)."""
    even = 2 * math.pi / n
    offsets = [draw_(st.floats(-0.3 * even, 0.3 * even)) for _ in range(n)]
    return [k * even + d for k, d in enumerate(offsets)]


@st.composite
def convex_polygons(draw_: st.DrawFn) -> tuple[Point, ...]:
    """3-8 corners on an ellipse of radius 40-300 px (aspect up to 2)."""
    n, radius, squash = draw_(st.integers(3, 8)), draw_(st.floats(40, 300)), draw_(st.floats(0.5, 1.0))
    return _pts([(radius * math.cos(a), squash * radius * math.sin(a)) for a in _angles(draw_, n)])


def _concave(points: list[Point]) -> bool:
    turns = []
    for i in range(len(points)):
        (ax, ay), (bx, by), (cx, cy) = points[i - 2], points[i - 1], points[i]
        turns.append((bx - ax) * (cy - by) - (by - ay) * (cx - bx))
    return min(turns) < 0 < max(turns)


@st.composite
def concave_polygons(draw_: st.DrawFn) -> tuple[Point, ...]:
    """4-8 corners, star-shaped round the origin (so simple), at least one reflex corner."""
    n, radius = draw_(st.integers(4, 8)), draw_(st.floats(40, 300))
    angles = _angles(draw_, n)
    shares = [draw_(st.floats(0.3, 1.0)) for _ in range(n)]
    dent = draw_(st.integers(0, n - 1))
    shares[dent] = min(shares[dent], 0.35)  # one corner pushed well inside its neighbours' chord
    shares[dent - 1] = shares[(dent + 1) % n] = 1.0
    points = _pts([(radius * f * math.cos(a), radius * f * math.sin(a)) for a, f in zip(angles, shares, strict=True)])
    return points if _concave(list(points)) else draw_(st.nothing())


@st.composite
def polylines(draw_: st.DrawFn) -> tuple[Point, ...]:
    """2-6 segments of 40-300 px, turning 20-160 degrees either way at each corner."""
    n = draw_(st.integers(2, 6))
    heading, x, y = 0.0, 0.0, 0.0
    points = [(x, y)]
    for k in range(n):
        if k:
            heading += math.radians(draw_(st.floats(20, 160))) * draw_(st.sampled_from((-1, 1)))
        length = draw_(st.floats(40, 300))
        x, y = x + length * math.cos(heading), y + length * math.sin(heading)
        points.append((x, y))
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    return _pts([(px - cx, py - cy) for px, py in points])


SHAPES = {"rectangle": rectangles(), "u_container": u_containers(), "convex": convex_polygons(),
          "concave": concave_polygons(), "polyline": polylines()}


@st.composite
def outlines(draw_: st.DrawFn, kinds: tuple[str, ...] = tuple(SHAPES)) -> Outline:
    """An `Outline` of one of ``kinds``, at any rotation and start, 0-2 px jitter, a closing gap/overshoot of up
    to 6 px for closed ones."""
    kind = draw_(st.sampled_from(kinds))
    vertices = draw_(SHAPES[kind])
    closed = kind in CLOSED
    return Outline(kind, vertices, angle=_r(draw_(st.floats(0, 2 * math.pi)), 3),
                   start=_r(draw_(st.floats(0, 1)), 3) if closed else 0.0,
                   closing=_r(draw_(st.floats(-6, 6))) if closed else 0.0,
                   jitter=_r(draw_(st.floats(0, 2)), 2), seed=draw_(st.integers(0, 2**32 - 1)))
