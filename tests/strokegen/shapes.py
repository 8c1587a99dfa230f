"""The ideal shapes the stroke generators draw, at unit size and without noise; neither noise nor placement.

Vertex chains for open polylines and closed polygons, dense point lists for smooth curves, each with randomised
proportions from the ``random.Random`` passed in. `strokes` hands them to `noise`.

>>> turtle([1.0, 1.0], [90.0])
[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]
"""

from __future__ import annotations

import math
import random
from collections.abc import Sequence

Point = tuple[float, float]
TAU = 2 * math.pi


def turtle(lengths: Sequence[float], turns_deg: Sequence[float]) -> list[Point]:
    """Vertices of a chain: walk ``lengths[0]``, turn by ``turns_deg[0]``, walk ``lengths[1]``, ..."""
    x, y, heading = 0.0, 0.0, 0.0
    out = [(x, y)]
    for k, length in enumerate(lengths):
        if k:
            heading += math.radians(turns_deg[k - 1])
        x, y = x + length * math.cos(heading), y + length * math.sin(heading)
        out.append((x, y))
    return out


def sign(rng: random.Random) -> float:
    """+1 or -1, evenly."""
    return 1.0 if rng.random() < 0.5 else -1.0


def polyline_vertices(rng: random.Random, variant: str) -> list[Point]:
    """Vertices of an open chain of straight segments; ``variant`` is one of `POLYLINE_VARIANTS`."""
    s = sign(rng)
    u = rng.uniform
    if variant == "v":  # also a caret: the rotation is random
        return turtle([1.0, u(0.8, 1.2)], [s * u(80, 155)])
    if variant == "check":
        return turtle([u(0.3, 0.5), 1.0], [s * u(70, 120)])
    if variant == "l":
        return turtle([1.0, u(0.4, 1.0)], [s * u(75, 105)])
    if variant == "z":
        return turtle([u(0.6, 1.0), u(1.0, 1.4), u(0.6, 1.0)], [s * u(120, 150), -s * u(120, 150)])
    if variant == "zigzag":
        n = rng.randint(3, 5)
        return turtle([u(0.5, 1.0) for _ in range(n)], [s * (-1) ** k * u(100, 150) for k in range(n - 1)])
    if variant == "bracket":
        arm = u(0.2, 0.45)
        return turtle([arm, 1.0, arm * u(0.8, 1.2)], [s * u(80, 100), s * u(80, 100)])
    if variant == "arrow":  # tail, tip, one barb, back to the tip, the other barb (as in the $1 data)
        head, spread = u(0.2, 0.35), math.radians(u(25, 45))
        tip = (1.0, 0.0)
        barb1 = (1 - head * math.cos(spread), head * math.sin(spread))
        barb2 = (1 - head * math.cos(spread), -head * math.sin(spread))
        return [(0.0, 0.0), tip, barb1, tip, barb2]
    if variant == "cross":  # single-stroke x or delete mark: diagonal, side, diagonal
        j = [(u(-0.1, 0.1), u(-0.1, 0.1)) for _ in range(4)]
        corners = [(0, 0), (1, 1), (1, 0), (0, 1)] if rng.random() < 0.5 else [(0, 0), (1, 1), (0, 1), (1, 0)]
        return [(x + dx, y + dy) for (x, y), (dx, dy) in zip(corners, j, strict=True)]
    n = rng.randint(2, 5)
    return turtle([u(0.4, 1.0) for _ in range(n)], [sign(rng) * u(35, 150) for _ in range(n - 1)])


POLYLINE_VARIANTS = ("v", "check", "l", "z", "zigzag", "bracket", "arrow", "cross", "random")


def _bezier(p0: Point, p1: Point, p2: Point, p3: Point, n: int = 30) -> list[Point]:
    out = []
    for k in range(n + 1):
        t = k / n
        a, b, c, d = (1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t * t * (1 - t), t**3
        out.append((a * p0[0] + b * p1[0] + c * p2[0] + d * p3[0], a * p0[1] + b * p1[1] + c * p2[1] + d * p3[1]))
    return out


def curve_points(rng: random.Random, variant: str) -> list[Point]:
    """Dense points of a smooth open curve that is no circular arc; ``variant`` is one of `CURVE_VARIANTS`."""
    u = rng.uniform
    if variant == "s":  # two arcs turning opposite ways
        r1, r2 = 0.5, u(0.4, 0.6)
        first = [(r1 * math.cos(a), r1 + r1 * math.sin(a)) for a in _angles(270 - u(180, 250), 270)]
        second = [(r2 * math.cos(a), -r2 + r2 * math.sin(a)) for a in _angles(90, 90 - u(180, 250))]
        return first + second[1:]
    if variant == "c":  # half an oval round its pointed end: a circle misses it by 10-16 % of the size
        ratio, sweep = u(0.4, 0.6), math.radians(u(170, 220))
        return [(math.cos(t), ratio * math.sin(t)) for t in (sweep * (k / 60 - 0.5) for k in range(61))]
    if variant == "tilde":
        periods, amplitude = u(0.8, 1.3), u(0.12, 0.25)
        return [(k / 60, amplitude * math.sin(TAU * periods * k / 60)) for k in range(61)]
    if variant == "question":  # a hook over the top, then a tail down
        r, end = 0.3, u(-80, -40)
        hook = [(r * math.cos(a), r * math.sin(a)) for a in _angles(u(150, 190), end)]
        end = math.radians(end)
        p, tangent = hook[-1], (math.sin(end), -math.cos(end))
        tail = _bezier(p, (p[0] + 0.15 * tangent[0], p[1] + 0.15 * tangent[1]), (0.0, -0.45), (u(-0.05, 0.05), -0.75))
        return hook + tail[1:]
    if variant == "brace":  # { : two S-bends meeting at a blunt point
        w, tip = u(0.15, 0.3), u(0.05, 0.12)
        top = _bezier((w, 0.0), (0.0, 0.0), (w * 0.6, 0.45), (-tip, 0.5))
        bottom = _bezier((-tip, 0.5), (w * 0.6, 0.55), (0.0, 1.0), (w, 1.0))
        return top + bottom[1:]
    # pigtail: a prolate cycloid with one small loop
    b, reach = u(1.6, 2.4), u(2.4, 3.2)
    return [(t - b * math.sin(t), -b * math.cos(t)) for t in (-reach + 2 * reach * k / 80 for k in range(81))]


def _angles(start_deg: float, end_deg: float, n: int = 40) -> list[float]:
    """``n + 1`` angles in radians from ``start_deg`` to ``end_deg`` degrees."""
    start, end = math.radians(start_deg), math.radians(end_deg)
    return [start + (end - start) * k / n for k in range(n + 1)]


CURVE_VARIANTS = ("s", "c", "tilde", "question", "brace", "pigtail")


def polygon_vertices(rng: random.Random, variant: str) -> list[Point]:
    """Vertices of a closed polygon (last joins first) that is no rectangle; ``variant`` in `POLYGON_VARIANTS`."""
    u = rng.uniform
    if variant == "triangle":  # every angle 30 degrees or more
        a = math.radians(u(30, 110))
        b = math.radians(u(30, min(120.0, 150 - math.degrees(a))))
        c_side = math.sin(b) / math.sin(a + b)  # side from vertex A, opposite angle B (law of sines, AB = 1)
        return [(0.0, 0.0), (1.0, 0.0), (c_side * math.cos(a), c_side * math.sin(a))]
    if variant == "pentagon":
        return _on_circle([TAU * k / 5 + math.radians(u(-8, 8)) for k in range(5)], [u(0.9, 1.1) for _ in range(5)])
    if variant == "star":  # {5/2}, one self-crossing stroke
        return _on_circle(
            [TAU * 2 * k / 5 + math.radians(u(-5, 5)) for k in range(5)], [u(0.92, 1.08) for _ in range(5)]
        )
    for _ in range(100):  # a quadrilateral with an angle at least 25 degrees from square
        kind = rng.choice(("trapezoid", "parallelogram", "kite", "irregular"))
        if kind == "trapezoid":
            top, height, offset = u(0.3, 0.7), u(0.4, 0.9), u(-0.2, 0.5)
            quad = [(0.0, 0.0), (1.0, 0.0), (offset + top, height), (offset, height)]
        elif kind == "parallelogram":
            side, skew = u(0.4, 1.0), math.radians(u(25, 50))
            dx, dy = side * math.sin(skew), side * math.cos(skew)
            quad = [(0.0, 0.0), (1.0, 0.0), (1.0 + dx, dy), (dx, dy)]
        elif kind == "kite":
            quad = [(0.0, -u(0.2, 0.5)), (u(0.3, 0.6), 0.0), (0.0, u(0.6, 1.0)), (-u(0.3, 0.6), 0.0)]
        else:
            quad = [(math.cos(a), math.sin(a)) for a in sorted(u(0, TAU) for _ in range(4))]
        if _convex_and_not_square(quad):
            return quad
    return [(0.0, 0.0), (1.0, 0.0), (0.7, 0.6), (0.2, 0.6)]


def _on_circle(angles: Sequence[float], radii: Sequence[float]) -> list[Point]:
    return [(r * math.cos(a), r * math.sin(a)) for a, r in zip(angles, radii, strict=True)]


def _convex_and_not_square(quad: list[Point]) -> bool:
    """Convex, every angle 30 degrees or more, one at least 25 from square, no side under a quarter of another."""
    angles, sides = [], []
    for k in range(4):
        p, q, r = quad[k - 1], quad[k], quad[(k + 1) % 4]
        a, b = (p[0] - q[0], p[1] - q[1]), (r[0] - q[0], r[1] - q[1])
        angles.append(math.degrees(abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))))
        sides.append(math.dist(q, r))
    return (
        abs(sum(angles) - 360) < 1
        and min(angles) >= 30
        and max(abs(a - 90) for a in angles) >= 25
        and (min(sides) >= 0.25 * max(sides))
    )


POLYGON_VARIANTS = ("triangle", "pentagon", "quad", "star")
