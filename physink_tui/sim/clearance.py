"""Whether a ballistic flight is clear of the scene (issue 27): for aim points and flight times, how far a start
body thrown at the point stays from everything on the way; geometry only, no stepping.

A launch aimed at a point is one of a family: the same point reached in any flight time, from a near-straight shot
to a lob. Which of them pass between the other bodies is geometry, decided here before any rollout: the body's
centre is followed along the parabola (`SAMPLES` points) and its distance to every other body's outline
(`Obstacle`: segments, thickened for open polylines and round bodies) less its reach is the flight's clearance
(`clearance_grid`, every aim point by every flight time at once). The target counts until the body arrives (within
`ARRIVAL` reaches of the aim point) — a container aimed into, only where the body's centre is outside its hull. A
body the start body already touches where it starts is no obstacle (it leaves it).

Clear flights (clearance above `MARGIN`) come in connected regions of (aim point, flight time); the cell deepest
inside a region is the launch least sensitive to what the rollout does differently from the parabola
(`clear_regions`). Where none is clear, the flight that comes nearest (`nearly_clear`) is often clear in the physics
all the same: figure 3-22's shot under a platform's corner and over a basket's rim clears both by less than a unit.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from shapely.geometry import MultiPoint, Polygon

from physink_tui.scene.components import Body, Point, Scene
from physink_tui.scene.physics.build import POLYLINE_RADIUS
from physink_tui.scene.physics.world import GRAVITY

MARGIN = 2.0
"""Canvas units kept between the body and an obstacle on a clear flight."""
ARRIVAL = 1.5
"""The target counts as an obstacle until the body's centre is this many reaches from the aim point."""
CLEAR_FACTORS = tuple(float(f) for f in np.geomspace(0.04, 3.0, 49))
"""Flight times tried, as multiples of the slowest-launch flight time, short to long (log-spaced)."""
NEAR = 40.0
"""Canvas units beyond the body's reach within which distances are measured; clearances are capped at `FAR`."""
FAR = 40.0
RIDGE = 1.0
"""Canvas units below the best clearance within which `nearly_clear` takes a flight as near the best."""
GRAZE = 0.25
"""`nearly_clear` gives up when the best flight cuts into something by more than this share of the reach."""
SAMPLES = 96
"""Samples along one flight (a flight crosses the canvas, about 2,000 units: one every 20, under a ball's
radius)."""


@dataclass(frozen=True, slots=True)
class Obstacle:
    """A body as the flights see it: its outline's segments on the canvas and how thick they are."""

    id: str
    segments: np.ndarray
    """(n, 2, 2): segment ends, canvas units."""
    thickness: float


def obstacles(scene: Scene, start: str) -> tuple[Obstacle, ...]:
    """Every body but ``start``, placed (outline segments; a round body its centre, thick by its radius)."""
    out = []
    for body in scene.bodies():
        if body.id == start:
            continue
        if body.shape == "circle":
            p = np.array([body.position, body.position], dtype=float)
            out.append(Obstacle(body.id, p[None, :, :], body.radius))
            continue
        pts = _placed(body)
        pairs = list(itertools.pairwise(pts))
        if body.shape != "polyline" and len(pts) >= 3:
            pairs.append((pts[-1], pts[0]))
        if pairs:
            out.append(Obstacle(body.id, np.array(pairs, dtype=float),
                                POLYLINE_RADIUS if body.shape == "polyline" else 0.0))
    return tuple(out)


def _placed(body: Body) -> list[Point]:
    px, py = body.position
    c, s = math.cos(body.angle), math.sin(body.angle)
    return [(px + x * c - y * s, py + x * s + y * c) for x, y in body.outline]


def distances(points: np.ndarray, obstacle: Obstacle) -> np.ndarray:
    """Each point's distance to the obstacle's surface (negative inside its thickness)."""
    a, b = obstacle.segments[:, 0, :], obstacle.segments[:, 1, :]
    ab = b - a
    length2 = np.maximum((ab ** 2).sum(axis=1), 1e-12)
    ap = points[:, None, :] - a[None, :, :]
    u = np.clip((ap * ab[None, :, :]).sum(axis=2) / length2[None, :], 0.0, 1.0)
    nearest = a[None, :, :] + u[:, :, None] * ab[None, :, :]
    return np.asarray(np.sqrt(((points[:, None, :] - nearest) ** 2).sum(axis=2)).min(axis=1) - obstacle.thickness)


def flights(origin: Point, centres: np.ndarray, factors: Sequence[float], gravity: Point = GRAVITY) -> np.ndarray:
    """Samples of the centre's parabolas from ``origin`` to each of ``centres`` (m, 2) in each of ``factors`` times
    the slowest-launch flight time: (m, len(factors), `SAMPLES` + 1, 2), the last sample of each the centre."""
    o = np.asarray(origin, dtype=float)
    g = np.asarray(gravity, dtype=float)
    d = centres - o[None, :]
    slowest = np.sqrt(2 * np.hypot(d[:, 0], d[:, 1]) / max(float(np.hypot(*g)), 1e-9))
    t = np.maximum(slowest[:, None] * np.asarray(factors, dtype=float)[None, :], 1e-9)  # (m, f)
    v = d[:, None, :] / t[..., None] - g[None, None, :] * t[..., None] / 2
    s = t[..., None] * np.linspace(0.0, 1.0, SAMPLES + 1)[None, None, :]  # (m, f, n)
    return np.asarray(o + v[:, :, None, :] * s[..., None] + g * s[..., None] ** 2 / 2)


def clearance_grid(origin: Point, centres: np.ndarray, reach: float, target: str,
                   scene_obstacles: Sequence[Obstacle], factors: Sequence[float] = CLEAR_FACTORS, *,
                   inside: bool = False) -> np.ndarray:
    """For each aim centre (rows) and flight factor (columns), how far (canvas units) the body's surface stays from
    everything on the way: the target counts until the body arrives (within `ARRIVAL` reaches of the aim), and when
    aiming ``inside`` a container only where the body's centre is outside its hull (a touch with the centre in the
    hull is a touch of its inside, `qualitative.contact_sides`); bodies it starts touching do not count. Negative
    when it touches something; capped at `FAR`."""
    start = np.asarray([origin], dtype=float)
    paths = flights(origin, centres, factors)
    m, f, n, _ = paths.shape
    points = paths.reshape(-1, 2)
    arriving = (np.hypot(paths[..., 0] - centres[:, None, None, 0], paths[..., 1] - centres[:, None, None, 1])
                < ARRIVAL * reach).reshape(-1)
    least = np.full(m * f * n, np.inf)
    for o in scene_obstacles:
        if float(distances(start, o)[0]) < reach + MARGIN:
            continue  # it starts touching it: it leaves it
        near = near_bounds(points, o, reach + MARGIN + NEAR)
        if inside and o.id == target:
            near &= ~in_hull(points, o.segments.reshape(-1, 2))
        if o.id == target:
            near &= ~arriving
        if near.any():
            least[near] = np.minimum(least[near], distances(points[near], o))
    return np.asarray(np.minimum(least.reshape(m, f, n).min(axis=2) - reach, FAR))


def near_bounds(points: np.ndarray, obstacle: Obstacle, within: float) -> np.ndarray:
    """Which points lie within ``within`` of the obstacle's bounds (the others are further from it than that)."""
    ends = obstacle.segments.reshape(-1, 2)
    pad = within + obstacle.thickness
    lo, hi = ends.min(axis=0) - pad, ends.max(axis=0) + pad
    inside = (points[:, 0] >= lo[0]) & (points[:, 0] <= hi[0]) & (points[:, 1] >= lo[1]) & (points[:, 1] <= hi[1])
    return np.asarray(inside)


def clear_regions(clear: np.ndarray, threshold: float = MARGIN) -> list[tuple[int, int]]:
    """Of a clearance grid (aim rows, factor columns): in each connected region of cells clear by more than
    ``threshold`` (4-neighbours), the cell deepest inside it (`depths`), then furthest from everything; the
    largest region first."""
    ok = clear > threshold
    depth = depths(ok)
    seen = np.zeros_like(ok)
    found: list[tuple[int, tuple[int, int]]] = []
    rows, cols = ok.shape
    for r0 in range(rows):
        for c0 in range(cols):
            if not ok[r0, c0] or seen[r0, c0]:
                continue
            stack, cells = [(r0, c0)], []
            seen[r0, c0] = True
            while stack:
                r, c = stack.pop()
                cells.append((r, c))
                for rr, cc in ((r + 1, c), (r - 1, c), (r, c + 1), (r, c - 1)):
                    if 0 <= rr < rows and 0 <= cc < cols and ok[rr, cc] and not seen[rr, cc]:
                        seen[rr, cc] = True
                        stack.append((rr, cc))
            best = max(cells, key=lambda rc: (int(depth[rc]), float(clear[rc]), -rc[0], -rc[1]))
            found.append((len(cells), best))
    found.sort(key=lambda x: (-x[0], x[1]))
    return [cell for _, cell in found]


def nearly_clear(clear: np.ndarray, reach: float) -> tuple[int, int] | None:
    """When no cell of a clearance grid is clear: the middle of the flights that come nearest to clear (within
    `RIDGE` of the best), if the best touches by less than `GRAZE` of the reach, else None. A rollout's contact
    is not the parabola's (a frame's lag, the body's spin): a flight that grazes a rim or a corner by a unit is
    often clear in the physics (the straight shot under a platform's corner into a basket)."""
    best = float(clear.max())
    if best > MARGIN or best < -GRAZE * reach:
        return None
    regions = clear_regions(clear, best - RIDGE)
    return regions[0] if regions else None


def depths(ok: np.ndarray) -> np.ndarray:
    """For each cell of a mask: how many cells a square round it can grow before it takes in one not set (or
    leaves the grid); -1 for the cells not set."""
    depth = np.where(ok, 0, -1)
    cur = ok.copy()
    k = 0
    while cur.any():
        grown = np.zeros((cur.shape[0] + 2, cur.shape[1] + 2), dtype=bool)
        grown[1:-1, 1:-1] = cur
        eroded = np.ones_like(cur)
        for dr in (0, 1, 2):
            for dc in (0, 1, 2):
                eroded &= grown[dr:dr + cur.shape[0], dc:dc + cur.shape[1]]
        k += 1
        depth[eroded] = k
        cur = eroded
    return depth


def in_hull(points: np.ndarray, outline: np.ndarray) -> np.ndarray:
    """Which points lie in the convex hull of ``outline``'s points."""
    hull = MultiPoint(outline).convex_hull
    if not isinstance(hull, Polygon):
        return np.zeros(len(points), dtype=bool)
    a = np.asarray(hull.exterior.coords)[:-1]
    b = np.roll(a, -1, axis=0)
    cross = ((b[None, :, 0] - a[None, :, 0]) * (points[:, None, 1] - a[None, :, 1])
             - (b[None, :, 1] - a[None, :, 1]) * (points[:, None, 0] - a[None, :, 0]))
    return np.asarray((cross >= 0).all(axis=1) | (cross <= 0).all(axis=1))
