"""Decides what a recognised stroke means in its context (thesis 3.2.2) and returns the new scene.

The rules, in the thesis's order: a line through a body erases it; a small circle, ellipse, arc or
curve inside a body pins it (rotational joint) to what lies under it; an X inside a body welds it;
a helix with an end in a fixed body is a spring along its horizontal or vertical axis; polylines,
lines, boxes, polygons, circles and ellipses are rigid bodies; a curve outside bodies is a rope whose
ends hold on to the bodies they overlap. Pure: no physics engine, no I/O; every odd case comes back
with a message for the user rather than an exception.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import cast

import numpy as np
import shapely
import shapely.ops
from shapely.errors import EmptyPartError
from shapely.geometry import LineString, MultiPoint, Point

from physink_tui.scene.components import (
    BACKGROUND,
    MATERIALS,
    Body,
    Joint,
    Rope,
    Scene,
    Spring,
    material_class,
)
from physink_tui.scene.interpretation.body_shapes import body_geometry, body_size, outline_of
from physink_tui.scene.recognition.primitives import Circle, Ellipse, Geometry, Helix, Line, Recognition, XSymbol

JOINT_MAX_SIZE = 0.6
"""A circle or curve is a joint symbol only when smaller than this share of the body it is drawn in."""
INSIDE_SHARE = 0.9
"""Share of a stroke's points that must lie in a body for the stroke to be inside it."""
SPRING_K = 20.0


@dataclass(frozen=True, slots=True)
class Interpretation:
    """What a stroke did.

    Attributes:
        scene: the scene after the stroke.
        action: ``erase``, ``pivot``, ``weld``, ``spring``, ``body``, ``rope`` or ``none``.
        created: ids of the components made.
        removed: ids of the components removed.
        message: something the user should be told (a repair, an odd case), or None.
    """

    scene: Scene
    action: str
    created: tuple[str, ...] = ()
    removed: tuple[str, ...] = ()
    message: str | None = None


Near = Callable[[tuple[float, float, float, float]], Sequence[str]]
"""A spatial index of a scene's bodies: ids of the bodies whose bounds may meet ``(x0, y0, x1, y1)``, topmost first
(more may come back, never fewer). `physics.live.LiveWorld.bodies_in` is one; without one every body is tried."""


def _candidates(scene: Scene, bounds: tuple[float, float, float, float], near: Near | None) -> list[Body]:
    """The bodies that may meet ``bounds``, topmost (created last) first."""
    if near is None:
        return list(reversed(scene.bodies()))
    return [scene.body(i) for i in near(bounds)]


def bodies_at(scene: Scene, point: tuple[float, float], exclude: str | None = None,
              reach: float = 0.0, near: Near | None = None) -> list[Body]:
    """Bodies whose area contains the point (or lies within ``reach`` of it), topmost (created last) first."""
    p = Point(point)
    bounds = (point[0] - reach, point[1] - reach, point[0] + reach, point[1] + reach)
    return [b for b in _candidates(scene, bounds, near)
            if b.id != exclude and (body_geometry(b).covers(p) or (reach and body_geometry(b).distance(p) <= reach))]


def crossed_bodies(scene: Scene, line: Line, near: Near | None = None) -> list[Body]:
    """Bodies a straight line passes through (it meets their area), topmost first."""
    segment = LineString([line.start, line.end])
    minx, miny, maxx, maxy = segment.bounds
    return [b for b in _candidates(scene, (minx, miny, maxx, maxy), near) if body_geometry(b).intersects(segment)]


def under(scene: Scene, point: tuple[float, float], exclude: str, near: Near | None = None) -> str:
    """The body lying under ``point`` other than ``exclude``, or the background."""
    found = bodies_at(scene, point, exclude, near=near)
    return found[0].id if found else BACKGROUND


def _inside(scene: Scene, points: Sequence[tuple[float, float]], near: Near | None) -> Body | None:
    """The topmost body holding nearly all of the points; a thin body (a line, a polyline) holds a
    symbol drawn on it when the symbol's centre lies within the symbol's size of it."""
    if not points:
        return None
    cloud = cast(np.ndarray, shapely.points(np.asarray(points, dtype=float)))  # one shapely Point per row
    multi = _multipoint_of(cloud)
    centre, size = Point(_centre_of(multi)), _size_of(multi)
    minx, miny, maxx, maxy = multi.bounds
    for body in _candidates(scene, (minx - size, miny - size, maxx + size, maxy + size), near):
        area = body_geometry(body)
        bx0, by0, bx1, by1 = area.bounds
        if maxx < bx0 - size or minx > bx1 + size or maxy < by0 - size or miny > by1 + size:
            continue  # nowhere near: skip the point-by-point test
        if body.shape == "polyline" and area.distance(centre) <= size / 2:
            return body
        if np.count_nonzero(shapely.covers(area, cloud)) >= INSIDE_SHARE * len(points):
            return body
    return None


def interpret(scene: Scene, recognition: Recognition,
              strokes: Sequence[Sequence[tuple[float, float]]], near: Near | None = None) -> Interpretation:
    """Apply one recognised stroke (or X pair) to the scene.

    Args:
        scene: the sketch so far.
        recognition: what the stroke was recognised as.
        strokes: the stroke's points (two strokes for an X), canvas units.
        near: a spatial index of ``scene``'s bodies (the same answers, sooner in a big sketch), or None.
    """
    kind, geometry = recognition.kind, recognition.geometry
    points = [(p[0], p[1]) for s in strokes for p in s]
    if kind is None or geometry is None:
        return Interpretation(scene, "none", message=f"stroke not used: {recognition.reason or 'not recognised'}")
    if kind == "line":
        assert isinstance(geometry, Line)
        erased = _erase(scene, geometry, near)
        if erased is not None:
            return erased
    if kind in ("circle", "ellipse", "curve", "arc"):
        host = _inside(scene, points, near)
        if host is not None and _size(points) < JOINT_MAX_SIZE * body_size(host):
            anchor = geometry.center if isinstance(geometry, Circle | Ellipse) else _centre(points)
            return _joint(scene, "pivot", host, anchor, near)
    if kind == "x":
        assert isinstance(geometry, XSymbol)
        held = _x_host(scene, geometry, near)
        if held is not None:
            return _joint(scene, "weld", *held, near)
        first = _add_body(scene, geometry.first)
        second = _add_body(first.scene, geometry.second)
        return Interpretation(second.scene, "body", created=first.created + second.created,
                              message="an X pins a body to what lies under it, but this one is outside every "
                                      "body; it became two line bodies")
    if kind == "helix":
        assert isinstance(geometry, Helix)
        return _spring(scene, geometry, points, near)
    if kind in ("curve", "arc"):
        return _rope(scene, points, near)
    return _add_body(scene, geometry)


def _x_host(scene: Scene, x: XSymbol, near: Near | None) -> tuple[Body, tuple[float, float]] | None:
    """The body an X welds and the weld's anchor: the topmost body holding the crossing; else, for an X drawn over
    a thin body (a platform a few pixels thick, a line) with its crossing just off it, the body nearest the crossing
    within half an arm, anchored at its point nearest the crossing."""
    hosts = bodies_at(scene, x.center, near=near)
    if hosts:
        return hosts[0], x.center
    reach = (math.dist(x.first.start, x.first.end) + math.dist(x.second.start, x.second.end)) / 4  # half an arm
    (cx, cy), centre = x.center, Point(x.center)
    found = [(body_geometry(b).distance(centre), rank, b)  # nearest first, then topmost
             for rank, b in enumerate(_candidates(scene, (cx - reach, cy - reach, cx + reach, cy + reach), near))]
    found = [n for n in found if n[0] <= reach]
    if not found:
        return None
    body = min(found, key=lambda n: n[:2])[2]
    anchor = shapely.ops.nearest_points(body_geometry(body), centre)[0]
    return body, (float(anchor.x), float(anchor.y))


def _multipoint(points: Sequence[tuple[float, float]]) -> MultiPoint:
    """The points as one shapely MultiPoint: the same geometry as ``MultiPoint(points)``, which makes a Python
    `Point` of each point first (0.25 ms for a 41-point stroke)."""
    return _multipoint_of(cast(np.ndarray, shapely.points(np.asarray(points, dtype=float))))


def _multipoint_of(cloud: np.ndarray) -> MultiPoint:
    """The MultiPoint of an array of shapely points, as ``MultiPoint(points)`` makes it (`shapely.multipoints` of
    the points, refusing an empty one)."""
    if shapely.is_empty(cloud).any():
        raise EmptyPartError("Can't create MultiPoint with empty component")
    return cast(MultiPoint, shapely.multipoints(cloud))


def _size(points: Sequence[tuple[float, float]]) -> float:
    return _size_of(_multipoint(points))


def _size_of(multi: MultiPoint) -> float:
    minx, miny, maxx, maxy = multi.bounds
    return math.hypot(maxx - minx, maxy - miny)


def _centre(points: Sequence[tuple[float, float]]) -> tuple[float, float]:
    return _centre_of(_multipoint(points))


def _centre_of(multi: MultiPoint) -> tuple[float, float]:
    c = multi.centroid
    return (c.x, c.y)


def _erase(scene: Scene, line: Line, near: Near | None) -> Interpretation | None:
    """A line whose midpoint is in a body and whose ends are outside it erases that body."""
    mid = ((line.start[0] + line.end[0]) / 2, (line.start[1] + line.end[1]) / 2)
    for body in bodies_at(scene, mid, near=near):
        area = body_geometry(body)
        if not area.covers(Point(line.start)) and not area.covers(Point(line.end)):
            gone = (body.id, *scene.attached_to(body.id))
            return Interpretation(scene.remove(*gone), "erase", removed=gone)
    return None


def _joint(scene: Scene, kind: str, host: Body, anchor: tuple[float, float], near: Near | None) -> Interpretation:
    jid, scene2 = scene.new_id("j")
    other = under(scene, anchor, host.id, near)
    joint = Joint(jid, kind, host.id, other, (float(anchor[0]), float(anchor[1])))
    return Interpretation(scene2.add(joint), kind, created=(jid,))


def _add_body(scene: Scene, geometry: Geometry) -> Interpretation:
    shape, position, outline, radius, note = outline_of(geometry)
    bid, scene2 = scene.new_id("b")
    body = Body(bid, shape, outline, radius, position, 0.0, MATERIALS[material_class(shape)])
    scene2 = scene2.add(body)
    scene2, attached = _attach_rope_ends(scene2, body)
    message = note
    if attached:
        message = (message + "; " if message else "") + f"rope ends attached to it: {', '.join(attached)}"
    return Interpretation(scene2, "body", created=(bid,), message=message)


def _attach_rope_ends(scene: Scene, body: Body) -> tuple[Scene, list[str]]:
    """Free rope ends lying in a new body hold on to it (thesis 3.2.3)."""
    area = body_geometry(body)
    attached = []
    for c in list(scene.components.values()):
        if not isinstance(c, Rope):
            continue
        start = body.id if c.start_body is None and area.covers(Point(c.points[0])) else c.start_body
        end = body.id if c.end_body is None and area.covers(Point(c.points[-1])) else c.end_body
        if (start, end) != (c.start_body, c.end_body):
            scene = scene.update(replace(c, start_body=start, end_body=end))
            attached.append(c.id)
    return scene, attached


def _rope(scene: Scene, points: Sequence[tuple[float, float]], near: Near | None) -> Interpretation:
    rid, scene2 = scene.new_id("r")
    start = bodies_at(scene, points[0], near=near)
    end = bodies_at(scene, points[-1], near=near)
    rope = Rope(rid, tuple((float(x), float(y)) for x, y in points),
                start[0].id if start else None, end[0].id if end else None)
    return Interpretation(scene2.add(rope), "rope", created=(rid,))


def _spring(scene: Scene, helix: Helix, points: Sequence[tuple[float, float]], near: Near | None) -> Interpretation:
    """A helix with an end in (or its end loop touching) a fixed body is a spring along its dominant axis."""
    first, last = points[0], points[-1]
    reach = helix.radius  # a coil's end loop touching a body holds on to it, as drawn by a hurried hand
    at_first, at_last = (bodies_at(scene, first, reach=reach, near=near),
                         bodies_at(scene, last, reach=reach, near=near))
    fixed_first = next((b for b in at_first if scene.is_fixed(b.id)), None)
    fixed_last = next((b for b in at_last if scene.is_fixed(b.id)), None)
    if fixed_first is not None:
        fixed = fixed_first
    elif fixed_last is not None:  # make the first end the fixed one
        first, last, at_last, fixed = last, first, at_first, fixed_last
    else:
        result = _rope(scene, points, near)
        return replace(result, message="a spring needs one end in a fixed body (weld one with an X first); "
                                       "this helix was kept as a rope")
    other = next((b for b in at_last if b.id != fixed.id), None)
    dx, dy = last[0] - first[0], last[1] - first[1]
    axis = "horizontal" if abs(dx) >= abs(dy) else "vertical"
    rest = abs(dx) if axis == "horizontal" else abs(dy)
    sid, scene2 = scene.new_id("s")
    spring = Spring(sid, fixed.id, other.id if other else BACKGROUND, (float(first[0]), float(first[1])),
                    (float(last[0]), float(last[1])), axis, rest, SPRING_K)
    message = None if other else "the spring's free end touches no body; it is held by the background there"
    return Interpretation(scene2.add(spring), "spring", created=(sid,), message=message)
