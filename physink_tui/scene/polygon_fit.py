"""Best polygonal approximations of a stroke through its own points, for every number of sides; no decisions.

A k-segment polyline (open strokes) or k-gon (closed strokes) is chosen among candidate vertices (the points a
fine Douglas-Peucker pass keeps: every corner's apex is one of them, however short its sides) by dynamic
programming on the summed squared distance of the stroke's points to the chords between vertices. Vertices are
always points of the stroke itself, so nearly parallel sides never meet far away. Which k to believe is left to
`recognize`, which weighs each k's error against its complexity.

>>> import numpy as np
>>> square = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], dtype=float)
>>> dense = np.concatenate([np.linspace(a, b, 25, endpoint=False) for a, b in zip(square, square[1:])])
>>> fits = best_polygons(dense, closed=True, max_sides=6, tolerance=0.001)
>>> round(fits[4][0].rss, 9), len(fits[4][0].vertices)
(0.0, 4)
"""

from __future__ import annotations

import heapq
import itertools
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class PolygonFit:
    """The best chain of ``len(indices) - 1`` chords through the stroke's points.

    Attributes:
        indices: indices into the (rotated, for closed strokes) point array, first and last included; for a
            closed stroke the last index is the first point again, appended at the end.
        vertices: the points at those indices (for a closed stroke without the repeated last one).
        rss: sum over all points of the squared distance to their chord (stroke units squared).
        points: the point array the indices refer to.
    """

    indices: tuple[int, ...]
    vertices: np.ndarray
    rss: float
    points: np.ndarray


def candidate_vertices(pts: np.ndarray, tolerance: float, limit: int = 40) -> list[int]:
    """Indices a Douglas-Peucker pass at ``tolerance`` keeps (ends included), splitting the most deviating
    piece first and stopping at ``limit`` points."""
    n = len(pts)
    chosen = [0, n - 1]
    heap: list[tuple[float, int, int, int]] = []

    def push(a: int, b: int) -> None:
        if b - a < 2:
            return
        d = pts[b] - pts[a]
        rel = pts[a + 1:b] - pts[a]
        norm = float(np.hypot(*d))
        dist = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0]) / norm if norm > 0 else np.hypot(*rel.T)
        k = int(np.argmax(dist))
        if dist[k] > tolerance:
            heapq.heappush(heap, (-float(dist[k]), a + 1 + k, a, b))

    push(0, n - 1)
    while heap and len(chosen) < limit:
        _, k, a, b = heapq.heappop(heap)
        chosen.append(k)
        push(a, k)
        push(k, b)
    return sorted(chosen)


def chord_costs(pts: np.ndarray, cand: np.ndarray) -> np.ndarray:
    """``C[a, b]``: summed squared distance of ``pts[cand[a]..cand[b]]`` to the chord between its ends (inf for
    ``a >= b``); a chord of no length measures distances to its point."""
    x, y = pts[:, 0], pts[:, 1]
    zero = np.zeros(1)
    sx, sy = np.concatenate([zero, np.cumsum(x)]), np.concatenate([zero, np.cumsum(y)])
    sxx, syy = np.concatenate([zero, np.cumsum(x * x)]), np.concatenate([zero, np.cumsum(y * y)])
    sxy = np.concatenate([zero, np.cumsum(x * y)])
    i, j = np.meshgrid(cand, cand, indexing="ij")
    m = (j - i + 1).astype(float)
    lo, hi = i, j + 1
    with np.errstate(invalid="ignore"):
        m = np.where(j > i, m, 1.0)
        hi = np.where(j > i, hi, lo + 1)
    ax, ay = x[i], y[i]
    dx, dy = x[j] - ax, y[j] - ay
    px, py = sx[hi] - sx[lo], sy[hi] - sy[lo]
    pxx, pyy, pxy = sxx[hi] - sxx[lo], syy[hi] - syy[lo], sxy[hi] - sxy[lo]
    c = ax * dy - ay * dx
    norm2 = dx * dx + dy * dy
    cross2 = dy * dy * pxx + dx * dx * pyy - 2 * dx * dy * pxy - 2 * c * (dy * px - dx * py) + m * c * c
    point2 = pxx + pyy - 2 * (ax * px + ay * py) + m * (ax * ax + ay * ay)
    with np.errstate(divide="ignore", invalid="ignore"):
        cost = np.where(norm2 > 0, cross2 / np.where(norm2 > 0, norm2, 1.0), point2)
    cost = np.maximum(cost, 0.0)
    cost[j <= i] = np.inf
    return cost


def line_costs(pts: np.ndarray, cand: np.ndarray) -> np.ndarray:
    """``C[a, b]``: summed squared distance of ``pts[cand[a]..cand[b]]`` to their own best-fitting line (total
    least squares; inf for ``a >= b``), so where exactly a corner's apex point lies costs nothing."""
    x, y = pts[:, 0], pts[:, 1]
    zero = np.zeros(1)
    sx, sy = np.concatenate([zero, np.cumsum(x)]), np.concatenate([zero, np.cumsum(y)])
    sxx, syy = np.concatenate([zero, np.cumsum(x * x)]), np.concatenate([zero, np.cumsum(y * y)])
    sxy = np.concatenate([zero, np.cumsum(x * y)])
    i, j = np.meshgrid(cand, cand, indexing="ij")
    ok = j > i
    lo, hi = i, np.where(ok, j + 1, i + 1)
    m = (hi - lo).astype(float)
    px, py = sx[hi] - sx[lo], sy[hi] - sy[lo]
    cxx = sxx[hi] - sxx[lo] - px * px / m
    cyy = syy[hi] - syy[lo] - py * py / m
    cxy = sxy[hi] - sxy[lo] - px * py / m
    half = (cxx + cyy) / 2
    cost = np.maximum(half - np.sqrt(np.maximum(((cxx - cyy) / 2) ** 2 + cxy * cxy, 0.0)), 0.0)
    cost[~ok] = np.inf
    return cost


def _segmentations(cost: np.ndarray, max_segments: int) -> list[tuple[float, list[int]] | None]:
    """For k = 1..max_segments: the least total cost of a chain from the first candidate to the last in k
    chords, with the candidate positions it passes (None where no such chain exists)."""
    c = cost.shape[0]
    best = np.full(c, np.inf)
    best[0] = 0.0
    back: list[np.ndarray] = []
    out: list[tuple[float, list[int]] | None] = []
    for _ in range(max_segments):
        total = best[:, None] + cost  # total[a, b]: reach a in k-1 chords, then chord a -> b
        arg = np.argmin(total, axis=0)
        best = total[arg, np.arange(c)]
        back.append(arg)
        if not np.isfinite(best[-1]):
            out.append(None)
            continue
        path = [c - 1]
        for step in reversed(back):
            path.append(int(step[path[-1]]))
        path.reverse()
        out.append((float(best[-1]), path))
    return out


def best_polygons(pts: np.ndarray, *, closed: bool, max_sides: int, tolerance: float,
                  ) -> dict[int, list[PolygonFit]]:
    """The best polylines (open) or polygons (closed) with each number of sides from 1 (open) or 3 (closed) up
    to ``max_sides``, keyed by that number, least error first (a closed loop is tried from two starts); vertices
    lie on or near points of ``pts`` (an (n, 2) array, n >= 3)."""
    if closed:
        # the loop must start at a vertex: start at the point farthest from the centre (a corner, if the shape
        # has any), then again at the sharpest corner that first pass found, and keep each k's better answer
        centre = pts.mean(axis=0)
        start = int(np.argmax(np.hypot(*(pts - centre).T)))
        fits: dict[int, list[PolygonFit]] = {}
        for attempt in range(2):
            loop = np.concatenate([np.roll(pts, -start, axis=0), pts[start:start + 1]])
            found = _chains(loop, max_sides, tolerance, closed=True)
            for k, fit in found.items():
                if k >= 3:
                    fits.setdefault(k, []).append(fit)
            if attempt == 0 and found:
                richest = found[max(found)]
                inner = richest.indices[1:-1]
                if not inner:
                    break
                turns = _turns(loop, richest.indices)
                start = (start + inner[int(np.argmax(turns[:-1]))]) % len(pts)
        return {k: sorted(v, key=lambda f: f.rss) for k, v in fits.items()}
    return {k: [fit] for k, fit in _chains(pts, max_sides, tolerance, closed=False).items()}


def _turns(pts: np.ndarray, indices: tuple[int, ...]) -> np.ndarray:
    """Turning (radians, absolute) at each inner index of a closed chain, and at its start last."""
    verts = pts[list(indices)]
    heading = np.arctan2(*np.diff(verts, axis=0)[:, ::-1].T)
    heading = np.append(heading, heading[0])
    return np.abs((np.diff(heading) + np.pi) % (2 * np.pi) - np.pi)


def _chains(pts: np.ndarray, max_segments: int, tolerance: float, *, closed: bool) -> dict[int, PolygonFit]:
    cand = np.array(candidate_vertices(pts, tolerance))
    cost = line_costs(pts, cand)
    out: dict[int, PolygonFit] = {}
    for k, found in enumerate(_segmentations(cost, min(max_segments, len(cand) - 1)), start=1):
        if found is None:
            continue
        rss, path = found
        indices = tuple(int(cand[p]) for p in path)
        out[k] = PolygonFit(indices, corner_points(pts, indices, closed=closed, reach=4 * tolerance), rss, pts)
    return out


def corner_points(pts: np.ndarray, indices: tuple[int, ...], *, closed: bool, reach: float) -> np.ndarray:
    """The vertices of a chain of runs: where the lines fitted to neighbouring runs meet, when that is near the
    point where the runs join (within a third of the shorter run, and within ``reach`` of the points' bounds);
    else that point itself (nearly parallel
    sides never meet far away). The ends of an open chain are its first and last points."""
    runs = list(itertools.pairwise(indices))
    lines = []
    for a, b in runs:
        run = pts[a:b + 1]
        k = len(run)
        core = run[k // 6: k - k // 6] if k >= 6 else run
        centre = core.mean(axis=0)
        _, _, vt = np.linalg.svd(core - centre, full_matrices=False)
        lines.append((centre, vt[0], float(np.hypot(*(run[-1] - run[0])))))
    joins = range(len(runs)) if closed else range(1, len(runs))
    lo, hi = pts.min(axis=0) - reach, pts.max(axis=0) + reach
    out = [] if closed else [pts[indices[0]]]
    for r in joins:
        (p1, d1, l1), (p2, d2, l2) = lines[r - 1], lines[r]
        at = pts[indices[r]]
        denom = d1[0] * d2[1] - d1[1] * d2[0]
        vertex = at
        if abs(denom) > 1e-9:
            t = ((p2 - p1)[0] * d2[1] - (p2 - p1)[1] * d2[0]) / denom
            meet = p1 + t * d1
            if (float(np.hypot(*(meet - at))) <= min(l1, l2) / 3 and (meet >= lo).all() and (meet <= hi).all()):
                vertex = meet
        out.append(vertex)
    if not closed:
        out.append(pts[indices[-1]])
    return np.array(out)
