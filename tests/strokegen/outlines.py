"""Hand-drawn outlines of thin boxes and U-shaped containers (the thesis's basket) for tests and benchmarks.

Each is drawn as one stroke through the shape's corners with a seeded hand: a start anywhere along the outline
(at a corner or mid-side), slightly rounded corners, pixel jitter of the given size (in the stroke's units,
pixels), and a small closing overshoot or gap. Pure: all randomness comes from the ``random.Random`` passed in.

>>> import random
>>> stroke = thin_box(random.Random(1), 200.0, 10.0)
>>> len(stroke) > 50, all(len(p) == 3 for p in stroke)
(True, True)
"""

from __future__ import annotations

import math
import random

Point = tuple[float, float]


def box_corners(width: float, height: float) -> list[Point]:
    return [(-width / 2, -height / 2), (width / 2, -height / 2), (width / 2, height / 2), (-width / 2, height / 2)]


def u_corners(width: float, height: float, wall: float) -> list[Point]:
    """The eight corners of a U container open at the top (y down), walls and floor ``wall`` thick."""
    w, h = width / 2, height / 2
    return [(-w, -h), (-w + wall, -h), (-w + wall, h - wall), (w - wall, h - wall), (w - wall, -h), (w, -h),
            (w, h), (-w, h)]


def draw_outline(rng: random.Random, corners: list[Point], *, jitter: float = 1.0, angle: float | None = None,
                 start: float | None = None, spacing: float = 2.0, closing: float | None = None,
                 rounding: float = 0.3) -> list[tuple[float, float, float]]:
    """One closed stroke through ``corners`` (rotated by ``angle``), starting ``start`` of the way round the
    perimeter (random when None), every ``spacing`` units, corners rounded by up to ``rounding`` units of
    path on either side (never more than a fifth of the shorter side), jittered by ``jitter``, and ended
    ``closing`` units past the start (negative: short of it; random within +-3 spacing when None)."""
    angle = rng.uniform(0, 2 * math.pi) if angle is None else angle
    c, s = math.cos(angle), math.sin(angle)
    pts = [(x * c - y * s, x * s + y * c) for x, y in corners]
    sides = [(pts[i], pts[(i + 1) % len(pts)]) for i in range(len(pts))]
    lengths = [math.dist(a, b) for a, b in sides]
    perimeter = sum(lengths)
    start = rng.random() if start is None else start
    closing = rng.uniform(-3 * spacing, 3 * spacing) if closing is None else closing
    total = perimeter + closing
    n = max(8, int(total / spacing))
    out = []
    for k in range(n + 1):
        d = (start * perimeter + total * k / n) % perimeter
        i = 0
        while d > lengths[i] and i < len(lengths) - 1:  # rounding may leave d a hair past the last side
            d -= lengths[i]
            i += 1
        (ax, ay), (bx, by) = sides[i]
        f = d / lengths[i] if lengths[i] else 0.0
        x, y = ax + (bx - ax) * f, ay + (by - ay) * f
        # round the corner: pull points near a corner towards the chord that cuts it
        r = min(rounding, 0.2 * min(lengths[i], lengths[i - 1]), 0.2 * min(lengths[i], lengths[(i + 1) % len(sides)]))
        if r > 0:
            if d < r:
                px, py = pts[i]
                qx, qy = sides[i - 1][0]
                back = (r - d) / r
                lx = lengths[i - 1] or 1.0
                x += (qx - px) / lx * r * back * 0.5 * (1 - back)
                y += (qy - py) / lx * r * back * 0.5 * (1 - back)
        out.append((x + rng.gauss(0, jitter), y + rng.gauss(0, jitter), k / n * total / 400.0))
    return out


def thin_box(rng: random.Random, length: float, thickness: float, **kw: float) -> list[tuple[float, float, float]]:
    return draw_outline(rng, box_corners(length, thickness), **kw)


def u_container(rng: random.Random, width: float, height: float, wall: float,
                **kw: float) -> list[tuple[float, float, float]]:
    return draw_outline(rng, u_corners(width, height, wall), **kw)
