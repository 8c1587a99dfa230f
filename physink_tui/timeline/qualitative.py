"""Qualitative geometry of events (thesis 3.3.1, figures 3-6 and 3-8): which sides of two bodies touch, whether a
body lands inside a concave container, and which regions (above, below, left, right) of other bodies a moving body
visits. Pure geometry on poses; when it is asked is the recorder's business.

A body is described once, at the start of a demonstration, by a `BodyOutline`: its convex hull in body coordinates
and whether it is a container. Everything else is computed at the pose the physics reports.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

from shapely.geometry import LineString, Polygon
from shapely.geometry import Point as ShapelyPoint
from shapely.geometry.base import BaseGeometry

from physink_tui.scene.components import Body
from physink_tui.scene.interpretation.body_shapes import body_geometry, body_size

Point = tuple[float, float]
Box = tuple[float, float, float, float]  # min x, min y, max x, max y (canvas units, y down)
Strips = tuple[float, float, float, float, float, float, float, float]
"""A body's `Box`, then where its regions end: the top of *above*, the bottom of *below*, the left end of *left*,
the right end of *right* (`strips`)."""

CONTAINER_HULL_RATIO = 2.0
"""A polyline or polygon whose convex hull is this many times its own area is a concave container (a cup, basket,
frying pan): what comes to rest in its hollow is *inside* it rather than on one of its sides."""
CONTAINER_MIN_DEPTH = 0.2
"""... and whose hull is at least this share of its size across both ways, so that a ramp drawn with a slight bend
is not a container."""
CIRCLE_VERTICES = 16


@dataclass(frozen=True, slots=True)
class BodyOutline:
    """A body as qualitative geometry sees it.

    Attributes:
        id: the body's component id.
        hull: its convex hull in body coordinates (relative to its position, unrotated), counter-clockwise.
        container: whether it is a concave container.
    """

    id: str
    hull: tuple[Point, ...]
    container: bool


def outline_of(body: Body) -> BodyOutline:
    """The `BodyOutline` of a scene body."""
    if body.shape == "circle":
        r = body.radius
        hull = tuple((r * math.cos(2 * math.pi * k / CIRCLE_VERTICES), r * math.sin(2 * math.pi * k / CIRCLE_VERTICES))
                     for k in range(CIRCLE_VERTICES))
        return BodyOutline(body.id, hull, False)
    geometry = body_geometry(body)
    placed_hull = geometry.convex_hull
    container = False
    if body.shape in ("polyline", "polygon") and isinstance(placed_hull, Polygon):
        rect = placed_hull.minimum_rotated_rectangle
        if isinstance(rect, Polygon):  # (a hull with no area has a line or a point for its rectangle)
            xs, ys = rect.exterior.coords.xy
            sides = [math.dist((xs[i], ys[i]), (xs[i + 1], ys[i + 1])) for i in range(2)]
            container = (placed_hull.area > CONTAINER_HULL_RATIO * geometry.area
                         and min(sides) > CONTAINER_MIN_DEPTH * body_size(body))
    points = body.outline if body.outline else ((0.0, 0.0),)
    local = Polygon(points).convex_hull if len(points) >= 3 else None
    if local is None or not isinstance(local, Polygon) or local.area == 0:
        hull = tuple(points)
    else:
        coords = list(local.exterior.coords)[:-1]
        hull = tuple((float(x), float(y)) for x, y in (coords if local.exterior.is_ccw else reversed(coords)))
    return BodyOutline(body.id, hull, container)


def placed(outline: BodyOutline, pose: tuple[float, ...]) -> list[Point]:
    """The hull's vertices on the canvas for a pose ``(x, y, angle, ...)``."""
    x, y, angle = pose[0], pose[1], pose[2]
    c, s = math.cos(angle), math.sin(angle)
    return [(x + px * c - py * s, y + px * s + py * c) for px, py in outline.hull]


def placed_bounds(outline: BodyOutline, pose: tuple[float, ...]) -> Box:
    """``bounds(placed(outline, pose))``, without building the points."""
    x, y, angle = pose[0], pose[1], pose[2]
    c, s = math.cos(angle), math.sin(angle)
    hull = outline.hull
    xs = [x + px * c - py * s for px, py in hull]
    ys = [y + px * s + py * c for px, py in hull]
    return (min(xs), min(ys), max(xs), max(ys))


def bounds(points: Iterable[Point]) -> Box:
    xs, ys = zip(*points, strict=True)
    return (min(xs), min(ys), max(xs), max(ys))


def side_along(dx: float, dy: float) -> str:
    """The side of a body facing direction ``(dx, dy)`` (y down): ``top``, ``bottom``, ``left`` or ``right``.

    >>> side_along(0, -1), side_along(0.2, 1), side_along(-1, 0.5)
    ('top', 'bottom', 'left')
    """
    if abs(dy) >= abs(dx):
        return "top" if dy < 0 else "bottom"
    return "right" if dx > 0 else "left"


def contact_sides(a: BodyOutline, pose_a: tuple[float, ...], b: BodyOutline, pose_b: tuple[float, ...],
                  normal: Point) -> tuple[str, str]:
    """The side of ``a`` and of ``b`` in a contact whose normal points from ``a`` towards ``b``.

    The sides are the canvas's (the ball hits the *top* of a tilted paddle), read from the contact normal rather
    than from the contact point, so a long platform hit near its end is still hit on its top. A body whose centre
    is within the hollow of a container is *inside* it (the egg lands in the frying pan).
    """
    side_a, side_b = side_along(*normal), side_along(-normal[0], -normal[1])
    if a.container and contains(placed(a, pose_a), (pose_b[0], pose_b[1])):
        side_a = "inside"
    if b.container and contains(placed(b, pose_b), (pose_a[0], pose_a[1])):
        side_b = "inside"
    return side_a, side_b


def contains(hull: list[Point], point: Point) -> bool:
    """Whether ``point`` lies in the convex polygon ``hull`` (vertices in either winding)."""
    sign = 0
    n = len(hull)
    if n < 3:
        return False
    for i in range(n):
        (x0, y0), (x1, y1) = hull[i], hull[(i + 1) % n]
        cross = (x1 - x0) * (point[1] - y0) - (y1 - y0) * (point[0] - x0)
        if cross != 0:
            s = 1 if cross > 0 else -1
            if sign == 0:
                sign = s
            elif s != sign:
                return False
    return True


def regions_at(point: Point, box: Box, reach: float) -> tuple[str, ...]:
    """The regions of a body with bounds ``box`` that ``point`` is in (thesis figure 3-6), within ``reach``.

    *Above* is the strip over the body as wide as it is, up to ``reach`` away; *below*, *left* and *right* likewise.
    A point inside the bounds is in none of them.

    >>> box = (0, 0, 10, 2)
    >>> regions_at((5, -3), box, 50), regions_at((15, 1), box, 50), regions_at((15, 9), box, 50)
    (('above',), ('right',), ())
    """
    region = region_in(point, strips(box, reach))
    return (region,) if region is not None else ()


def strips(box: Box, reach: float) -> Strips:
    """A body's bounds ``box`` and where its regions end ``reach`` away from them (see `Strips`)."""
    minx, miny, maxx, maxy = box
    return (minx, miny, maxx, maxy, miny - reach, maxy + reach, minx - reach, maxx + reach)


def region_in(point: Point, body: Strips) -> str | None:
    """The region of a body with `strips` ``body`` that ``point`` is in, or None (`regions_at`).

    >>> region_in((5, -3), strips((0, 0, 10, 2), 50)), region_in((-5, 1), strips((0, 0, 10, 2), 50))
    ('above', 'left')
    """
    x, y = point
    minx, miny, maxx, maxy, top, bottom, left, right = body
    if minx <= x <= maxx:
        if top <= y < miny:
            return "above"
        if maxy < y <= bottom:
            return "below"
    elif miny <= y <= maxy:
        if left <= x < minx:
            return "left"
        if maxx < x <= right:
            return "right"
    return None


def separated(a: BodyOutline, pose_a: tuple[float, ...], b: BodyOutline, pose_b: tuple[float, ...],
              gap: float) -> bool:
    """Whether two bodies' hulls are more than ``gap`` apart."""
    return hull_gap(a, pose_a, b, pose_b, gap) > gap


def hull_gap(a: BodyOutline, pose_a: tuple[float, ...], b: BodyOutline, pose_b: tuple[float, ...],
             beyond: float = math.inf) -> float:
    """How far apart two bodies' hulls are (0 when they overlap); any value over ``beyond`` once it is known to
    be more (their bounds alone can tell)."""
    pa, pb = placed(a, pose_a), placed(b, pose_b)
    ba, bb = bounds(pa), bounds(pb)
    apart = max(ba[0] - bb[2], bb[0] - ba[2], ba[1] - bb[3], bb[1] - ba[3])
    if apart > beyond:
        return apart
    return float(_shape(pa).distance(_shape(pb)))


def _shape(points: list[Point]) -> BaseGeometry:
    if len(points) >= 3:
        polygon = Polygon(points)
        if polygon.area > 0:
            return polygon
    return LineString(points) if len(points) == 2 else ShapelyPoint(points[0])
