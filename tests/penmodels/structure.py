"""A scene's structure in words (bodies, joints, ropes, springs, what is fixed) and how two differ; no drawing."""

from __future__ import annotations

import difflib
import math

from shapely.geometry import LineString

from physink_tui.scene.components import BACKGROUND, Body, Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation.body_shapes import body_geometry

CENTROID_SHARE = 0.05
"""How far (share of the canvas diagonal) a body's centroid may be from its counterpart's."""
EXTENT_SHARE = 0.30
"""How much (share) a body's area, or an open polyline's length, may differ from its counterpart's."""


def centroid(body: Body) -> tuple[float, float]:
    c = body_geometry(body).centroid
    return (c.x, c.y)


def extent(body: Body) -> float:
    """Area, or length for an open polyline (canvas units)."""
    if body.shape == "polyline":
        px, py = body.position
        c, s = math.cos(body.angle), math.sin(body.angle)
        return LineString([(px + x * c - y * s, py + x * s + y * c) for x, y in body.outline]).length
    return body_geometry(body).area


def reference_names(scene: Scene, names: list[str]) -> dict[str, str]:
    """Body id -> name, the n-th body drawn taking the n-th name (bodies past the names keep their ids)."""
    return {b.id: name for b, name in zip(scene.bodies(), names, strict=False)}


def match_names(reference: Scene, ref_names: dict[str, str], scene: Scene, diagonal: float) -> dict[str, str]:
    """Name ``scene``'s bodies after reference bodies, each name once: first a body with the same label (wherever
    it lies, so a misshapen body keeps its name), then the nearest of the same shape, then the nearest closed
    one for a closed one and open one for an open one (within `CENTROID_SHARE` of ``diagonal``); the others are
    called ``extra <shape> at (x, y)``."""
    pairs = sorted(((math.dist(centroid(b), centroid(r)), b.id, r.id), b, r)
                   for b in scene.bodies() for r in reference.bodies())
    rules = (lambda d, b, r: b.label is not None and b.label == r.label,
             lambda d, b, r: d <= CENTROID_SHARE * diagonal and b.shape == r.shape,
             lambda d, b, r: d <= CENTROID_SHARE * diagonal and (b.shape == "polyline") == (r.shape == "polyline"))
    out: dict[str, str] = {}
    taken: set[str] = set()
    for rule in rules:
        for (distance, _, _), b, r in pairs:
            if b.id not in out and r.id not in taken and rule(distance, b, r):
                out[b.id] = ref_names.get(r.id, r.id)
                taken.add(r.id)
    for b in scene.bodies():
        if b.id not in out:
            x, y = centroid(b)
            out[b.id] = f"extra {b.shape} at ({x:.0f}, {y:.0f})"
    return out


def summarize(scene: Scene, names: dict[str, str]) -> list[str]:
    """The scene's structure as sorted lines, bodies called by ``names`` (id -> name)."""

    def name(component_id: str | None) -> str:
        if component_id is None:
            return "(free end)"
        return component_id if component_id == BACKGROUND else names.get(component_id, component_id)

    lines = []
    for c in scene.components.values():
        if isinstance(c, Body):
            fixed = "fixed" if scene.is_fixed(c.id) else "movable"
            lines.append(f"body {name(c.id)}: {c.shape}, label {c.label!r}, {fixed}")
        elif isinstance(c, Joint):
            lines.append(f"joint {c.kind}: {name(c.a)} to {name(c.b)}")
        elif isinstance(c, Rope):
            lines.append(f"rope: {name(c.start_body)} to {name(c.end_body)}, label {c.label!r}")
        elif isinstance(c, Spring):
            lines.append(f"spring {c.axis}: {name(c.a)} to {name(c.b)}, label {c.label!r}")
    return sorted(lines)


def geometry_differences(reference: Scene, ref_names: dict[str, str], scene: Scene, names: dict[str, str],
                         diagonal: float) -> list[str]:
    """Bodies of the same name that are too far apart or too different in size."""
    by_name = {ref_names.get(b.id, b.id): b for b in reference.bodies()}
    out = []
    for body in scene.bodies():
        ref = by_name.get(names[body.id])
        if ref is None:
            continue
        moved = math.dist(centroid(body), centroid(ref))
        if moved > CENTROID_SHARE * diagonal:
            out.append(f"{names[body.id]}: centroid {moved:.0f} px from the reference's "
                       f"(limit {CENTROID_SHARE * diagonal:.0f})")
        a, b = extent(body), extent(ref)
        if body.shape == ref.shape and b > 0 and abs(a / b - 1.0) > EXTENT_SHARE:
            what = "length" if body.shape == "polyline" else "area"
            out.append(f"{names[body.id]}: {what} {a:.0f} against the reference's {b:.0f} "
                       f"(limit {EXTENT_SHARE:.0%})")
    return out


def structure_diff(reference: Scene, ref_names: dict[str, str], scene: Scene,
                   canvas: tuple[float, float] = (1600.0, 1000.0)) -> list[str]:
    """What differs between ``scene`` and ``reference``, as readable lines; empty when the structure is the same.

    Two drawings of one machine give the same structure when, with the bodies of one named after the bodies of
    the other (`match_names`): the same bodies with the same shapes and labels, fixed or movable alike, the
    same joints, ropes and springs between the same bodies, and each body about where and as big as its
    counterpart (centroid within `CENTROID_SHARE` of the canvas diagonal; area within `EXTENT_SHARE`, or
    length for open polylines, which are thin strips).

    Structure lines come as a diff (``-`` only in the reference, ``+`` only in ``scene``), then the geometry.
    """
    diagonal = math.hypot(*canvas)
    names = match_names(reference, ref_names, scene, diagonal)
    want, got = summarize(reference, ref_names), summarize(scene, names)
    diff = [line for line in difflib.ndiff(want, got) if line[:1] in "+-"]
    return diff + geometry_differences(reference, ref_names, scene, names, diagonal)
