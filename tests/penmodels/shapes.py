"""What a person means to draw, in canvas pixels (boxes, ovals, paths, curves, coils, X marks); no motion, no noise."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

Point = tuple[float, float]
CANVAS = (1600.0, 1000.0)
"""The canvas the scenarios' tablet fractions map onto one to one (canvas units, y down)."""
X_LONGEST = 0.1
"""A stroke of an X is shorter than this share of the canvas diagonal (a wall it crosses is not)."""


@dataclass(frozen=True, slots=True)
class Outline:
    """A closed polygon (a box, a thick U container, any polygon): its corners in drawing order, not repeated."""

    vertices: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Oval:
    """A circle or ellipse: centre, semi-axes along x and y before rotation, rotation in radians."""

    center: Point
    rx: float
    ry: float
    angle: float = 0.0


@dataclass(frozen=True, slots=True)
class Path:
    """An open chain of straight segments (a line, a ramp, an open cup or basket)."""

    vertices: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Curve:
    """A smooth open curve through ``points`` (a rope)."""

    points: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Coil:
    """A spring drawn as loops: its axis from ``start`` to ``end``, ``loops`` turns of ``radius``."""

    start: Point
    end: Point
    loops: int
    radius: float


@dataclass(frozen=True, slots=True)
class XMark:
    """The two strokes of an X as meant: each a (start, end) pair, drawn in this order."""

    first: tuple[Point, Point]
    second: tuple[Point, Point]


Shape = Outline | Oval | Path | Curve | Coil | XMark


# -- constructors for single shapes -----------------------------------------------------------------------


def box(center: Point, width: float, height: float, angle: float = 0.0) -> Outline:
    """A ``width`` x ``height`` rectangle round ``center``, turned ``angle`` radians (clockwise on screen)."""
    c, s = math.cos(angle), math.sin(angle)
    hw, hh = width / 2, height / 2
    corners = ((-hw, -hh), (hw, -hh), (hw, hh), (-hw, hh))
    return Outline(tuple((center[0] + x * c - y * s, center[1] + x * s + y * c) for x, y in corners))


def u_container(center: Point, width: float, height: float, wall: float = 0.0, angle: float = 0.0) -> Outline | Path:
    """A cup open at the top, ``width`` x ``height`` round ``center``: with ``wall`` > 0 the closed outline of
    walls and floor that thick, else the open U of three strokes' worth of path drawn in one go."""
    hw, hh = width / 2, height / 2
    if wall > 0:
        local = ((-hw, -hh), (-hw + wall, -hh), (-hw + wall, hh - wall), (hw - wall, hh - wall), (hw - wall, -hh),
                 (hw, -hh), (hw, hh), (-hw, hh))
    else:
        local = ((-hw, -hh), (-hw, hh), (hw, hh), (hw, -hh))
    c, s = math.cos(angle), math.sin(angle)
    pts = tuple((center[0] + x * c - y * s, center[1] + x * s + y * c) for x, y in local)
    return Outline(pts) if wall > 0 else Path(pts)


def polygon(vertices: Sequence[Point]) -> Outline:
    return Outline(tuple((float(x), float(y)) for x, y in vertices))


def circle(center: Point, radius: float) -> Oval:
    return Oval(center, radius, radius)


# -- reading a scenario's strokes -------------------------------------------------------------------------


def to_canvas(points: Sequence[Point]) -> list[Point]:
    """Tablet fractions (the scenarios' units) to canvas pixels."""
    return [(x * CANVAS[0], y * CANVAS[1]) for x, y in points]


def _turning(pts: Sequence[Point]) -> float:
    total = 0.0
    for a, b, c in zip(pts, pts[1:], pts[2:], strict=False):
        h1 = math.atan2(b[1] - a[1], b[0] - a[0])
        h2 = math.atan2(c[1] - b[1], c[0] - b[0])
        total += (h2 - h1 + math.pi) % (2 * math.pi) - math.pi
    return total


def from_scenario_stroke(points: Sequence[Point]) -> Shape:
    """The shape a scenario's stroke (tablet fractions) describes, in canvas pixels, so the hurried pen draws the
    same machine its own way rather than retracing the virtual pen's path.

    A closed stroke of many points is an oval, a closed one of few points an outline; an open stroke of a
    few points is a path; a long open stroke that winds round is a coil, one that does not a curve.
    """
    pts = to_canvas(points)
    closed = len(pts) > 3 and math.dist(pts[0], pts[-1]) < 1e-6
    if closed and len(pts) > 12:
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return Oval(((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2), (max(xs) - min(xs)) / 2,
                    (max(ys) - min(ys)) / 2)
    if closed:
        return Outline(tuple(pts[:-1]))
    if len(pts) <= 6:
        return Path(tuple(pts))
    turns = abs(_turning(pts)) / (2 * math.pi)
    if turns < 1.5:
        return Curve(tuple(pts))
    # a coil: its points run round centres that advance along the axis; first point = start - radius * axis
    (x0, y0), (x1, y1) = pts[0], pts[-1]
    chord = math.dist(pts[0], pts[-1]) or 1.0
    ux, uy = (x1 - x0) / chord, (y1 - y0) / chord
    radius = max(abs((x - x0) * -uy + (y - y0) * ux) for x, y in pts)
    start, end = (x0 + radius * ux, y0 + radius * uy), (x1 + radius * ux, y1 + radius * uy)
    return Coil(start, end, round(turns), radius)


def segments_cross(a: tuple[Point, Point], b: tuple[Point, Point]) -> bool:
    """Whether two segments intersect."""
    (p, q), (r, s) = a, b

    def side(o: Point, u: Point, v: Point) -> float:
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])

    return side(p, q, r) * side(p, q, s) < 0 and side(r, s, p) * side(r, s, q) < 0


def group_scenario_strokes(strokes: Sequence[Sequence[Point]]) -> list[tuple[tuple[int, ...], Shape]]:
    """The shapes of a scenario's strokes in drawing order, each with the indices of the strokes it stands for:
    two consecutive short two-point strokes that cross are one `XMark`, every other stroke one shape."""
    out: list[tuple[tuple[int, ...], Shape]] = []
    i = 0
    while i < len(strokes):
        if i + 1 < len(strokes) and len(strokes[i]) == 2 and len(strokes[i + 1]) == 2:
            a, b = to_canvas(strokes[i]), to_canvas(strokes[i + 1])
            short = max(math.dist(*a), math.dist(*b)) < X_LONGEST * math.hypot(*CANVAS)
            if short and segments_cross((a[0], a[1]), (b[0], b[1])):
                out.append(((i, i + 1), XMark((a[0], a[1]), (b[0], b[1]))))
                i += 2
                continue
        out.append(((i,), from_scenario_stroke(strokes[i])))
        i += 1
    return out
