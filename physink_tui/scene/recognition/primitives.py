"""Recognised primitives and their beautified geometry, as frozen values; no recognition, no I/O.

Coordinates are in the units of the input strokes (canvas fractions or pixels alike), y down.
Angles are radians, counter-clockwise as seen on screen is negative (y grows downwards), measured
with ``math.atan2(dy, dx)`` in those coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass

Point = tuple[float, float]

KINDS = ("line", "polyline", "box", "circle", "ellipse", "arc", "curve", "helix", "polygon", "x")
"""Every kind a recognition can name (DESIGN.md, `physink recognize`)."""


@dataclass(frozen=True, slots=True)
class Line:
    start: Point
    end: Point


@dataclass(frozen=True, slots=True)
class Polyline:
    """An open chain of straight segments; ``points`` has at least three vertices."""

    points: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Polygon:
    """A closed chain of straight segments (last vertex joins the first); at least three vertices."""

    points: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Box:
    """A rectangle at any rotation: centre, side lengths, and the angle of the ``width`` side."""

    center: Point
    width: float
    height: float
    angle: float

    @property
    def corners(self) -> tuple[Point, Point, Point, Point]:
        import math

        c, s = math.cos(self.angle), math.sin(self.angle)
        hw, hh = self.width / 2, self.height / 2
        cx, cy = self.center
        def corner(dx: float, dy: float) -> Point:
            return (cx + dx * c - dy * s, cy + dx * s + dy * c)

        return corner(-hw, -hh), corner(hw, -hh), corner(hw, hh), corner(-hw, hh)


@dataclass(frozen=True, slots=True)
class Circle:
    center: Point
    radius: float


@dataclass(frozen=True, slots=True)
class Ellipse:
    """Semi-axes ``rx`` >= ``ry``; ``angle`` is the direction of the ``rx`` axis."""

    center: Point
    rx: float
    ry: float
    angle: float


@dataclass(frozen=True, slots=True)
class Arc:
    """Part of a circle from ``start_angle`` sweeping ``sweep`` radians (sign gives the direction)."""

    center: Point
    radius: float
    start_angle: float
    sweep: float


@dataclass(frozen=True, slots=True)
class Curve:
    """A smooth open curve as cubic Bézier segments: ``3 * n + 1`` control points for ``n`` segments."""

    control_points: tuple[Point, ...]


@dataclass(frozen=True, slots=True)
class Helix:
    """A spring drawn as loops from ``start`` to ``end`` (its axis), loop radius and number of turns."""

    start: Point
    end: Point
    radius: float
    turns: float


@dataclass(frozen=True, slots=True)
class XSymbol:
    """Two short crossing strokes: where they cross, and the two beautified lines."""

    center: Point
    first: Line
    second: Line


Geometry = Line | Polyline | Polygon | Box | Circle | Ellipse | Arc | Curve | Helix | XSymbol


@dataclass(frozen=True, slots=True)
class Recognition:
    """What a stroke (or a pair of strokes, for the X) was recognised as.

    Attributes:
        kind: one of `KINDS`, or None when the input cannot be recognised (see ``reason``).
        confidence: 0..1, how well the best primitive fits.
        geometry: the beautified primitive, or None with ``kind``.
        alternatives: other kinds that fit, best first, with their confidences.
        reason: why nothing was recognised (e.g. "too short to recognise"), else None.
        note: what the user should know of how the stroke was read (only part of it read), else None.
    """

    kind: str | None
    confidence: float
    geometry: Geometry | None
    alternatives: tuple[tuple[str, float], ...] = ()
    reason: str | None = None
    note: str | None = None
