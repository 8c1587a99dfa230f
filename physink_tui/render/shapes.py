"""Skia paths of what the renderer draws: bodies in their own coordinates, springs' zig-zags, weld X's, open
polylines; no colours, no canvas.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import skia

from physink_tui.scene.components import Body

Point = tuple[float, float]

SPRING_WIDTH = 14.0
"""Half the width of a spring's zig-zag, canvas units."""
SPRING_PITCH = 14.0
"""The rest length of one zig of a spring, canvas units."""


def body_path(body: Body) -> skia.Path:
    """The body's shape about its origin, unrotated (draw it translated to its pose and turned by its angle).

    A circle carries a radius line so that turning shows; an open polyline is an open path (stroke it thick).
    """
    path = skia.Path()
    if body.shape == "circle":
        path.addCircle(0.0, 0.0, body.radius)
        path.moveTo(0.0, 0.0)
        path.lineTo(body.radius, 0.0)
        return path
    if not body.outline:
        return path
    (x0, y0), *rest = body.outline
    path.moveTo(x0, y0)
    for x, y in rest:
        path.lineTo(x, y)
    if body.shape != "polyline":
        path.close()
    return path


def lowest(body: Body, angle: float) -> float:
    """How far below its origin the body reaches when turned to ``angle`` (canvas units, y down)."""
    if body.shape == "circle" or not body.outline:
        return body.radius
    s, c = math.sin(angle), math.cos(angle)
    return max(x * s + y * c for x, y in body.outline)


def polyline(points: Iterable[Point]) -> skia.Path:
    """An open path through ``points``."""
    path = skia.Path()
    first = True
    for x, y in points:
        if first:
            path.moveTo(x, y)
            first = False
        else:
            path.lineTo(x, y)
    return path


def zigzag(a: Point, b: Point, rest_length: float) -> skia.Path:
    """A spring from ``a`` to ``b``: short straight ends and a zig-zag whose zigs are counted from its rest length
    (a stretched spring spreads them)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    path = skia.Path()
    path.moveTo(*a)
    if length < 1e-6:
        return path
    ux, uy = dx / length, dy / length
    nx, ny = -uy, ux
    zigs = max(4, round(rest_length / SPRING_PITCH))
    lead = 0.1 * length
    step = (length - 2 * lead) / zigs
    path.lineTo(a[0] + ux * lead, a[1] + uy * lead)
    for i in range(zigs):
        along = lead + (i + 0.5) * step
        side = SPRING_WIDTH if i % 2 == 0 else -SPRING_WIDTH
        path.lineTo(a[0] + ux * along + nx * side, a[1] + uy * along + ny * side)
    path.lineTo(b[0] - ux * lead, b[1] - uy * lead)
    path.lineTo(*b)
    return path


def cross(centre: Point, half: float) -> skia.Path:
    """A weld's X of half-size ``half`` at ``centre``."""
    x, y = centre
    path = skia.Path()
    path.moveTo(x - half, y - half)
    path.lineTo(x + half, y + half)
    path.moveTo(x - half, y + half)
    path.lineTo(x + half, y - half)
    return path


def extend(path: skia.Path, points: Sequence[Point], start: int, stop: int) -> None:
    """Append ``points[start:stop]`` to ``path`` (the first point starts it when the path is empty)."""
    for i in range(start, stop):
        x, y = points[i]
        if i == 0:
            path.moveTo(x, y)
        else:
            path.lineTo(x, y)
