"""Best polygonal approximations of a stroke, for every number of sides; no decisions.

A k-segment polyline (open strokes) or k-gon (closed strokes) splits the stroke's points into k runs at candidate
vertices (`candidate_vertices`: every corner's apex, however short its sides); dynamic programming finds, for
each k, the split whose runs lie closest to their own best-fitting lines (summed squared distances, from prefix
sums). A vertex is where neighbouring runs' lines meet when that is near the join and inside the stroke's bounds,
else the join point itself, so nearly parallel sides never meet far away. Which k to believe is left to
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
import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True, slots=True)
class PolygonFit:
    """The best chain of ``len(indices) - 1`` runs of the stroke's points, each close to a line.

    Attributes:
        indices: where the runs join, as indices into ``points``, first and last included; for a closed stroke
            ``points`` is the loop from its chosen start with that start repeated at the end.
        rss: sum over all points of the squared distance to their run's own line (stroke units squared).
        points: the point array the indices refer to.
        closed: whether the chain is a closed outline (its last vertex joins its first).
        reach: how far outside the points' bounds a vertex may lie (see `corner_points`).
    """

    indices: tuple[int, ...]
    rss: float
    points: np.ndarray
    closed: bool
    reach: float
    sums: np.ndarray
    """`moments` of ``points``, shared by every fit of the same points."""
    memo: dict[str, np.ndarray] = field(default_factory=dict, compare=False, repr=False)
    """What has been measured of this fit (`vertices`, `polygon_checks.corner_roundness_closed`), each once: a fit's
    points and indices never change, so neither does anything measured of them (kept read-only)."""
    walks: dict[str, tuple[list[float], list[float]]] = field(default_factory=dict, compare=False, repr=False)
    """Walks along ``points`` (`stroke_features.walk`: the turning and the path before each point) that checks of the
    fits measure (`polygon_checks.corner_roundness_closed`), shared by every fit of the same points, as ``sums``."""
    extent: tuple[np.ndarray, np.ndarray] | None = field(default=None, compare=False, repr=False)
    """The least and the greatest x and y of ``points`` (`corner_points`' bounds), shared as ``sums``; None: measured
    by `corner_points`."""

    @property
    def vertices(self) -> np.ndarray:
        """The chain's vertices (`corner_points`), measured once (`memo`; read-only)."""
        found = self.memo.get("vertices")
        if found is None:
            found = corner_points(self.points, self.indices, closed=self.closed, reach=self.reach, sums=self.sums,
                                  extent=self.extent)
            found.flags.writeable = False
            self.memo["vertices"] = found
        return found


DP_POINTS = 100
DP_LIMIT = 10
"""The Douglas-Peucker pass for big corners looks at about this many of the stroke's points."""


def candidate_vertices(pts: np.ndarray, tolerance: float, limit: int = 28) -> list[int]:
    """Indices where a corner may be (ends included), at most about ``limit``: half of them from a
    Douglas-Peucker pass at ``tolerance`` (splitting the most deviating piece first: the shape's big corners),
    half the local peaks of how far a point stands out from the chord between its neighbours a few points either
    side (small features: a thin wall's end)."""
    n = len(pts)
    step = max(1, -(-n // DP_POINTS))  # the big corners are found on every step-th point
    coarse = _douglas_peucker(np.concatenate([pts[::step], pts[-1:]]), tolerance, DP_LIMIT)
    chosen = {min(i * step, n - 1) for i in coarse}
    i = np.arange(n)
    score = np.zeros(n)
    for w in (2, 4):
        a, b = pts[np.maximum(i - w, 0)], pts[np.minimum(i + w, n - 1)]
        chord = b - a
        norm = np.hypot(*chord.T)
        rel = pts - a
        off = np.abs(rel[:, 0] * chord[:, 1] - rel[:, 1] * chord[:, 0]) / np.where(norm > 0, norm, 1.0)
        score = np.maximum(score, np.where(norm > 0, off, 0.0))
    padded = np.concatenate([[-1.0], score, [-1.0]])
    peak = (score >= padded[:-2]) & (score >= padded[2:]) & (score > tolerance)
    found = np.flatnonzero(peak)
    chosen.update(found[np.argsort(-score[found], kind="stable")][: limit // 2].tolist())
    return sorted(chosen)


def _douglas_peucker(pts: np.ndarray, tolerance: float, limit: int) -> list[int]:
    """The points a Douglas-Peucker pass at ``tolerance`` keeps, the most deviating first, at most ``limit``."""
    n = len(pts)
    chosen = [0, n - 1]
    heap: list[tuple[float, int, int, int]] = []
    xs, ys = pts[:, 0].copy(), pts[:, 1].copy()  # each column once, contiguous
    x, y = xs.tolist(), ys.tolist()  # and as Python floats: the same numbers

    def push(a: int, b: int) -> None:
        if b - a < 2:
            return
        # the points between the chord's ends less its start, and the chord: ``pts[a + 1:b] - pts[a]`` and
        # ``pts[b] - pts[a]`` a column at a time, the same subtractions
        xa, ya = x[a], y[a]
        dx, dy = x[b] - xa, y[b] - ya
        norm = float(np.hypot(dx, dy))
        k, far = _farthest(x, y, a, b, dx, dy, norm) if b - a <= SHORT_RUN and norm > 0 else (-1, math.nan)
        if k < 0:  # a long run (or a NaN, or a chord of nothing): numpy's, the same arithmetic
            rx, ry = xs[a + 1:b] - xa, ys[a + 1:b] - ya
            dist = np.abs(rx * dy - ry * dx) / norm if norm > 0 else np.hypot(rx, ry)
            k = int(dist.argmax())
            far = float(dist[k])
        if far > tolerance:
            heapq.heappush(heap, (-far, a + 1 + k, a, b))

    push(0, n - 1)
    while heap and len(chosen) < limit:
        _, k, a, b = heapq.heappop(heap)
        chosen.append(k)
        push(a, k)
        push(k, b)
    return chosen


SHORT_RUN = 24
"""`_douglas_peucker` measures a run of up to this many points one point at a time in Python floats (numpy's per-call
cost is more than the arithmetic on so few)."""


def _farthest(x: list[float], y: list[float], a: int, b: int, dx: float, dy: float, norm: float) -> tuple[int, float]:
    """Which point strictly between ``a`` and ``b`` lies farthest from the chord (``dx``, ``dy``: from ``a`` to ``b``,
    ``norm`` its length, not 0), and how far: ``np.abs(rx * dy - ry * dx) / norm`` and its first greatest, a point at a
    time (each operation alone, rounded as numpy rounds it); (-1, nan) where a distance is NaN (numpy's argmax takes
    the first NaN: left to it)."""
    xa, ya = x[a], y[a]
    best, far = -1, -1.0
    for m in range(a + 1, b):
        d = abs((x[m] - xa) * dy - (y[m] - ya) * dx) / norm
        if d > far:
            best, far = m - a - 1, d
        elif d != d:
            return -1, math.nan
    return best, far


def line_costs(pts: np.ndarray, cand: np.ndarray, sums: np.ndarray | None = None) -> np.ndarray:
    """``C[a, b]``: summed squared distance of ``pts[cand[a]..cand[b]]`` to their own best-fitting line (total
    least squares; inf for ``a >= b``), so where exactly a corner's apex point lies costs nothing."""
    sx, sy, sxx, syy, sxy = sums if sums is not None else moments(pts)
    i, j = cand[:, None], cand[None, :]  # `np.meshgrid(cand, cand, indexing="ij")`, broadcast instead of copied
    ok = j > i
    lo, hi = i, np.where(ok, j + 1, i + 1)
    m = (hi - lo).astype(float)
    px, py = sx[hi] - sx[lo], sy[hi] - sy[lo]
    cxx = sxx[hi] - sxx[lo] - px * px / m
    cyy = syy[hi] - syy[lo] - py * py / m
    cxy = sxy[hi] - sxy[lo] - px * py / m
    half = (cxx + cyy) / 2
    cost: np.ndarray = np.maximum(half - np.sqrt(np.maximum(((cxx - cyy) / 2) ** 2 + cxy * cxy, 0.0)), 0.0)
    cost[~ok] = np.inf
    return cost


def _segmentations(cost: np.ndarray, max_segments: int) -> list[tuple[float, list[int]] | None]:
    """For k = 1..max_segments: the least total cost of a chain from the first candidate to the last in k
    chords, with the candidate positions it passes (None where no such chain exists)."""
    c = cost.shape[0]
    best = np.full(c, np.inf)
    best[0] = 0.0
    back: list[list[int]] = []
    out: list[tuple[float, list[int]] | None] = []
    columns = np.arange(c)
    for _ in range(max_segments):
        total = best[:, None] + cost  # total[a, b]: reach a in k-1 chords, then chord a -> b
        arg = total.argmin(axis=0)
        best = total[arg, columns]
        back.append(arg.tolist())
        if not math.isfinite(best[-1]):
            out.append(None)
            continue
        path = [c - 1]
        for step in reversed(back):
            path.append(step[path[-1]])
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
        start = int(np.hypot(*(pts - centre).T).argmax())
        fits: dict[int, list[PolygonFit]] = {}
        for attempt in range(2):
            loop = np.concatenate([pts[start:], pts[:start], pts[start:start + 1]])  # rolled to start there
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
    heading = np.arctan2(*(verts[1:] - verts[:-1])[:, ::-1].T)  # as np.diff, without its per-call overhead
    heading = np.concatenate([heading, heading[:1]])  # `np.append(heading, heading[0])`
    turns: np.ndarray = np.abs((heading[1:] - heading[:-1] + np.pi) % (2 * np.pi) - np.pi)
    return turns


def _chains(pts: np.ndarray, max_segments: int, tolerance: float, *, closed: bool) -> dict[int, PolygonFit]:
    cand = np.array(candidate_vertices(pts, tolerance))
    sums = moments(pts)
    cost = line_costs(pts, cand, sums)
    walks: dict[str, tuple[list[float], list[float]]] = {}  # shared by the fits, as ``sums``
    extent = (np.minimum.reduce(pts, axis=0), np.maximum.reduce(pts, axis=0))  # (`.min(axis=0)`'s own reduction)
    out: dict[int, PolygonFit] = {}
    for k, found in enumerate(_segmentations(cost, min(max_segments, len(cand) - 1)), start=1):
        if found is None:
            continue
        rss, path = found
        indices = tuple(int(cand[p]) for p in path)
        out[k] = PolygonFit(indices, rss, pts, closed, 4 * tolerance, sums, walks=walks, extent=extent)
    return out


def moments(pts: np.ndarray) -> np.ndarray:
    """Prefix sums of x, y, x^2, y^2 and xy (rows of one array, each from 0): any run's line in O(1)."""
    x, y = pts[:, 0], pts[:, 1]
    out = np.zeros((5, len(pts) + 1))
    for row, values in zip(out, (x, y, x * x, y * y, x * y), strict=True):
        np.add.accumulate(values, out=row[1:])
    return out


def run_lines(pts: np.ndarray, lo: np.ndarray, hi: np.ndarray, sums: np.ndarray | None = None,
              ) -> tuple[np.ndarray, np.ndarray]:
    """Centre and unit direction of the total-least-squares line through each ``pts[lo:hi]`` (closed form, from
    prefix sums, `moments` of ``pts`` when given: no per-run loop)."""
    table = sums if sums is not None else moments(pts)
    px, py, sxx, syy, sxy = table[:, hi] - table[:, lo]  # each run's sums of x, y, x^2, y^2 and xy, all five at once
    m = np.maximum(hi - lo, 1).astype(float)
    cxx = sxx - px * px / m
    cyy = syy - py * py / m
    cxy = sxy - px * py / m
    theta = 0.5 * np.arctan2(2 * cxy, cxx - cyy)
    centres, dirs = np.empty((len(m), 2)), np.empty((len(m), 2))  # as `np.column_stack` lays them out
    np.divide(px, m, out=centres[:, 0])
    np.divide(py, m, out=centres[:, 1])
    dirs[:, 0], dirs[:, 1] = np.cos(theta), np.sin(theta)  # computed into their own arrays, as before
    return centres, dirs


def corner_points(pts: np.ndarray, indices: tuple[int, ...], *, closed: bool, reach: float,
                  sums: np.ndarray | None = None, extent: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """The vertices of a chain of runs: where the lines fitted to neighbouring runs (their middle two thirds)
    meet, when that is near the point where the runs join (within a third of the shorter run, and within
    ``reach`` of the points' bounds, ``extent``: their least and greatest x and y where known); else that point itself
    (nearly parallel sides never meet far away). The ends of an open chain are its first and last points."""
    idx = np.asarray(indices)
    a, b = idx[:-1], idx[1:]
    size = b - a + 1
    trim = size // 6  # none under six points (as ``np.where(size >= 6, size // 6, 0)``: a run has two or more)
    centres, dirs = run_lines(pts, a + trim, b + 1 - trim, sums)
    d = pts[b] - pts[a]
    chords = np.hypot(d[:, 0], d[:, 1])  # (``np.hypot(*d.T)``, without unpacking the rows)
    runs = len(a)
    second = np.arange(runs) if closed else np.arange(1, runs)
    first = second - 1  # -1 wraps to the last run of a closed chain
    p1, d1, p2, d2 = centres[first], dirs[first], centres[second], dirs[second]
    at = pts[idx[second]]
    denom = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    safe = np.where(np.abs(denom) > 1e-9, denom, 1.0)
    t = ((p2 - p1)[:, 0] * d2[:, 1] - (p2 - p1)[:, 1] * d2[:, 0]) / safe
    meet = p1 + t[:, None] * d1
    least, most = (np.minimum.reduce(pts, axis=0), np.maximum.reduce(pts, axis=0)) if extent is None else extent
    lo, hi = least - reach, most + reach
    off = meet - at
    near = np.hypot(off[:, 0], off[:, 1]) <= np.minimum(chords[first], chords[second]) / 3
    inside = np.logical_and.reduce(meet >= lo, axis=1) & np.logical_and.reduce(meet <= hi, axis=1)  # (`.all(axis=1)`)
    ok = (np.abs(denom) > 1e-9) & near & inside
    inner: np.ndarray = np.where(ok[:, None], meet, at)
    if closed:
        return inner
    return np.concatenate([pts[idx[:1]], inner, pts[idx[-1:]]])
