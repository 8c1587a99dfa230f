"""Body outlines from beautified primitives, and bodies as shapely geometry for containment tests.

Pure geometry: no physics engine. A body's outline is kept relative to its position (its centroid
when made), unrotated; `body_geometry` places it on the canvas for "is this inside that" questions.
"""

from __future__ import annotations

import functools
import math

import shapely
from shapely.geometry import LineString, MultiPolygon, Point, Polygon
from shapely.geometry.base import BaseGeometry

from physink_tui.errors import SceneError
from physink_tui.scene.components import Body
from physink_tui.scene.recognition.primitives import Box, Circle, Ellipse, Geometry, Line, Polyline
from physink_tui.scene.recognition.primitives import Polygon as PolygonPrim

ELLIPSE_SIDES = 32
THIN = 0.004
"""Half-thickness of line and polyline bodies as a fraction of their length (they are thin strips)."""


XY = tuple[float, float]


def _centroid_relative(points: list[XY]) -> tuple[XY, tuple[XY, ...]]:
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    return (cx, cy), tuple((x - cx, y - cy) for x, y in points)


def outline_of(geometry: Geometry) -> tuple[str, XY, tuple[XY, ...], float, str | None]:
    """``(shape, position, outline, radius, note)`` of the body a primitive makes.

    ``note`` says what was repaired (a self-intersecting polygon), else None.
    """
    if isinstance(geometry, Circle):
        return "circle", geometry.center, (), geometry.radius, None
    if isinstance(geometry, Box):
        position, outline = _centroid_relative(list(geometry.corners))
        return "box", position, outline, 0.0, None
    if isinstance(geometry, Ellipse):
        c, s = math.cos(geometry.angle), math.sin(geometry.angle)
        pts = []
        for k in range(ELLIPSE_SIDES):
            a = 2 * math.pi * k / ELLIPSE_SIDES
            u, v = geometry.rx * math.cos(a), geometry.ry * math.sin(a)
            pts.append((geometry.center[0] + u * c - v * s, geometry.center[1] + u * s + v * c))
        position, outline = _centroid_relative(pts)
        return "ellipse", position, outline, 0.0, None
    if isinstance(geometry, PolygonPrim):
        polygon, note = valid_polygon(list(geometry.points))
        centre = polygon.centroid
        ring = list(shapely.geometry.polygon.orient(polygon, 1.0).exterior.coords)[:-1]
        return "polygon", (centre.x, centre.y), tuple((x - centre.x, y - centre.y) for x, y in ring), 0.0, note
    if isinstance(geometry, Polyline | Line):
        pts = list(geometry.points) if isinstance(geometry, Polyline) else [geometry.start, geometry.end]
        line = LineString(pts)
        centre = line.interpolate(0.5, normalized=True)
        return "polyline", (centre.x, centre.y), tuple((x - centre.x, y - centre.y) for x, y in pts), 0.0, None
    raise ValueError(f"{type(geometry).__name__} does not make a body")


def valid_polygon(points: list[tuple[float, float]]) -> tuple[Polygon, str | None]:
    """A simple polygon from possibly self-intersecting vertices: repaired with shapely (the largest
    piece is kept when it falls apart), with a note saying so.

    Raises:
        SceneError: points that all lie on one line (no polygon has them as its outline).
    """
    polygon = Polygon(points)
    if polygon.is_valid:
        return polygon, None
    repaired = shapely.make_valid(polygon)
    pieces = [g for g in getattr(repaired, "geoms", [repaired]) if isinstance(g, Polygon | MultiPolygon)]
    polys = [p for g in pieces for p in getattr(g, "geoms", [g])]
    if not polys:
        hull = polygon.convex_hull
        if not isinstance(hull, Polygon):
            raise SceneError(f"a polygon through {points!r} has no area (its points lie on one line)")
        return hull, "the shape crossed itself into nothing; its outline was used"
    largest = max(polys, key=lambda p: p.area)
    note = "the shape crossed itself; it was repaired" if len(polys) == 1 else (
        f"the shape crossed itself into {len(polys)} pieces; the largest was kept")
    return largest, note


@functools.lru_cache(maxsize=4096)
def body_geometry(body: Body) -> BaseGeometry:
    """The body's area on the canvas (lines and polylines as thin strips); cached per (immutable) body."""
    px, py = body.position
    c, s = math.cos(body.angle), math.sin(body.angle)
    placed = [(px + x * c - y * s, py + x * s + y * c) for x, y in body.outline]
    if body.shape == "circle":
        return Point(px, py).buffer(body.radius, quad_segs=16)
    if body.shape == "polyline":
        line = LineString(placed)
        return line.buffer(max(line.length * THIN, 1e-9), cap_style="flat")
    return Polygon(placed)


def body_size(body: Body) -> float:
    """A body's diameter-like size (the diagonal of its bounds)."""
    minx, miny, maxx, maxy = body_geometry(body).bounds
    return math.hypot(maxx - minx, maxy - miny)
