"""Whether a body's outline can become collision shapes (area, convex pieces, distinct points), in pure geometry: no
pymunk object is made; `build` makes the shapes from what these return.

The same checks refuse a project whose outline the physics cannot use when it is read
(`physink_tui.formats.project.sanity`, through `outline_problem`) and a scene when its world is built.
"""

from __future__ import annotations

import shapely

from physink_tui.errors import SceneError
from physink_tui.scene.components import Body, Point


def outline_problem(spec: Body) -> str | None:
    """What keeps the physics from making ``spec``'s shapes, in words (None: nothing); the checks `body_shapes`
    makes, without building anything, so a project can be refused when it is read.

    >>> from physink_tui.scene.components import MATERIALS
    >>> outline_problem(Body("b1", "box", ((0, 0), (10, 0), (20, 0)), 0, (0, 0), 0, MATERIALS["box"]))
    'the outline encloses no area'
    """
    try:
        if spec.shape in ("box", "ellipse"):
            need_area(spec)
        elif spec.shape == "polygon":
            convex_pieces(spec)
        elif spec.shape == "polyline":
            distinct_points(spec)
    except _OutlineError as exc:
        return exc.reason
    return None


class _OutlineError(SceneError):
    """A `SceneError` that also keeps what is wrong without naming the body (`outline_problem`)."""

    def __init__(self, message: str, reason: str) -> None:
        super().__init__(message)
        self.reason = reason


def need_area(spec: Body) -> shapely.Polygon:
    """A box's, ellipse's or polygon's outline as a polygon of positive area; `SceneError` otherwise."""
    if len(spec.outline) < 3:
        raise _OutlineError(f"{spec.shape} {spec.id!r} has {len(spec.outline)} outline points; expected at least 3",
                            "fewer than 3 points")
    polygon = shapely.Polygon(spec.outline)
    if not polygon.area > 0:
        raise _OutlineError(f"{spec.shape} {spec.id!r} has an outline of zero area: {spec.outline!r}",
                            "the outline encloses no area")
    return polygon


def convex_pieces(spec: Body) -> list[tuple[Point, ...]]:
    """A closed outline as convex pieces: itself when convex, else its constrained Delaunay triangles.

    A self-intersecting outline is first repaired with ``shapely.make_valid`` (its enclosed areas are kept).

    >>> from physink_tui.scene.components import MATERIALS
    >>> ell = Body("b1", "polygon", ((0, 0), (20, 0), (20, 10), (10, 10), (10, 30), (0, 30)), 0, (0, 0), 0,
    ...            MATERIALS["freeform"])
    >>> len(convex_pieces(ell))
    4
    """
    polygon = need_area(spec)
    if polygon.is_valid and polygon.area >= polygon.convex_hull.area * (1 - 1e-9):
        return [tuple(spec.outline)]
    pieces = [g for g in shapely.get_parts(shapely.make_valid(polygon)) if isinstance(g, shapely.Polygon)]
    triangles = shapely.get_parts(shapely.constrained_delaunay_triangles(shapely.MultiPolygon(pieces)))
    floor = polygon.area * 1e-9
    out = [tuple((x, y) for x, y in t.exterior.coords[:3]) for t in triangles if t.area > floor]
    if not out:
        raise _OutlineError(f"polygon {spec.id!r} encloses no area once repaired: {spec.outline!r}",
                            "it crosses itself and encloses no area")
    return out


def distinct_points(spec: Body) -> list[Point]:
    """A polyline's points without repeats, at least 2; `SceneError` otherwise."""
    points = [p for i, p in enumerate(spec.outline) if i == 0 or p != spec.outline[i - 1]]
    if len(points) < 2:
        raise _OutlineError(f"polyline {spec.id!r} has {len(points)} distinct points; expected at least 2",
                            "fewer than 2 distinct points")
    return points
