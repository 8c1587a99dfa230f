"""Session 28's cheaper recognition checks answer exactly as the plain computations they replace (issue 25)."""

from __future__ import annotations

import heapq
import itertools
import math

import numpy as np

from physink_tui.scene.recognition import landing, polygon_checks, polygon_fit, ranker
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.beautify import shape_points, within
from physink_tui.scene.recognition.primitives import Arc, Box, Circle, Curve, Ellipse, Geometry, Line, Polygon, Polyline


def _plain_inside(g: Geometry, lo: np.ndarray, hi: np.ndarray) -> bool:
    """`ranking.inside` as it was: every shape point, as an array, against the box."""
    pts = np.asarray(shape_points(g), dtype=float)
    return bool(np.isfinite(pts).all() and (pts >= lo).all() and (pts <= hi).all())


def _geometries(rng: np.random.Generator) -> list[Geometry]:
    def pt() -> tuple[float, float]:
        return (float(rng.normal(0, 1)), float(rng.normal(0, 1)))

    out: list[Geometry] = []
    for _ in range(300):
        pieces = int(rng.integers(1, 7))
        out.append(Curve(tuple(pt() for _ in range(3 * pieces + 1))))
        out.append(Circle(pt(), float(abs(rng.normal(0, 1)))))
        out.append(Ellipse(pt(), float(abs(rng.normal(0, 1))), float(abs(rng.normal(0, 0.5))),
                           float(rng.uniform(-4, 4))))
        out.append(Polyline(tuple(pt() for _ in range(int(rng.integers(2, 8))))))
        out.append(Polygon(tuple(pt() for _ in range(int(rng.integers(3, 8))))))
        out.append(Box(pt(), float(abs(rng.normal(0, 1))), float(abs(rng.normal(0, 1))), float(rng.uniform(-4, 4))))
        out.append(Line(pt(), pt()))
        out.append(Arc(pt(), float(abs(rng.normal(0, 1))), float(rng.uniform(-4, 4)), float(rng.uniform(-7, 7))))
    out += [Curve(((0.0, 0.0), (math.nan, 0.0), (1.0, 1.0), (2.0, 0.0))),
            Curve(((0.0, 0.0), (math.inf, 0.0), (1.0, 1.0), (2.0, 0.0))),
            Circle((0.0, 0.0), math.inf), Circle((math.nan, 0.0), 1.0), Ellipse((0.0, 0.0), 1.0, math.nan, 0.3),
            Polyline(((0.0, 0.0), (math.nan, 1.0)))]
    return out


def test_within_answers_as_every_shape_point_against_the_box() -> None:
    """`beautify.within` (a curve's control points' hull, a round shape's extent, then the points) says what testing
    every one of `shape_points` as an array says: for boxes well clear of the shape, through it, and touching its
    extreme points exactly (where the hull's hair sends the test to the points)."""
    rng = np.random.default_rng(28)
    both = 0
    for g in _geometries(rng):
        with np.errstate(all="ignore"):
            pts = np.asarray(shape_points(g), dtype=float)
        finite = pts[np.isfinite(pts).all(axis=1)]
        tight = (finite.min(axis=0), finite.max(axis=0)) if len(finite) else None
        boxes = [(np.array([-9.0, -9.0]), np.array([9.0, 9.0])), (np.array([-1.0, -1.5]), np.array([1.2, 0.8])),
                 (rng.normal(-1, 1, 2), rng.normal(1, 1, 2))]
        if tight is not None:
            boxes += [tight, (tight[0] + 1e-12, tight[1]), (tight[0] - 1e-3, tight[1] + 1e-3)]
        for lo, hi in boxes:
            with np.errstate(all="ignore"):
                expected = _plain_inside(g, lo, hi)
            with np.errstate(all="ignore"):
                assert within(g, lo, hi) == expected, (g, lo, hi)
            both += expected
    assert both > 500  # many inside, many not


def _plain_douglas_peucker(pts: np.ndarray, tolerance: float, limit: int) -> list[int]:
    """`polygon_fit._douglas_peucker` as it was (rows of the point array)."""
    n = len(pts)
    chosen = [0, n - 1]
    heap: list[tuple[float, int, int, int]] = []

    def push(a: int, b: int) -> None:
        if b - a < 2:
            return
        rel = pts[a + 1:b + 1] - pts[a]
        d, rel = rel[-1], rel[:-1]
        norm = float(np.hypot(d[0], d[1]))
        dist = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0]) / norm if norm > 0 else np.hypot(rel[:, 0], rel[:, 1])
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


def test_douglas_peucker_by_columns_keeps_the_same_points() -> None:
    """Working a column at a time (`polygon_fit._douglas_peucker`) keeps the points, in the order, that working on rows
    kept: random walks, closed loops (whose chord is nil) and points on a line."""
    rng = np.random.default_rng(7)
    strokes = [np.cumsum(rng.normal(0, 1, (int(rng.integers(3, 120)), 2)), axis=0) for _ in range(300)]
    strokes += [np.concatenate([s, s[:1]]) for s in strokes[:100]]
    strokes += [np.column_stack([np.linspace(0, 1, 30), np.zeros(30)])]
    for pts in strokes:
        for tolerance in (0.0, 0.05, 0.5):
            assert polygon_fit._douglas_peucker(pts, tolerance, 10) == _plain_douglas_peucker(pts, tolerance, 10)


def _plain_dwell(pts: np.ndarray, radius: float) -> int:
    """`landing._dwell` as it was: every point measured first."""
    away = np.hypot(*(pts - pts[0]).T) > radius
    if not away.any():
        return 0
    out = int(np.argmax(away))
    if out < landing.DWELL_POINTS:
        return 0
    extent = float(np.hypot(*(pts[:out] - pts[0]).T).max())
    path = float(np.hypot(*np.diff(pts[:out], axis=0).T).sum())
    if path < landing.DWELL_PATH_CENTRED * extent:
        return 0
    centre = float(np.hypot(*(pts[:out] - pts[0]).mean(axis=0)))
    if path < landing.DWELL_PATH * extent and centre > landing.DWELL_CENTRE * extent:
        return 0
    spread = np.linalg.eigvalsh(np.cov((pts[:out] - pts[:out].mean(axis=0)).T))
    return out if spread[0] >= landing.DWELL_BREADTH**2 * spread[1] else 0


def test_a_dwell_is_found_as_measuring_every_point() -> None:
    """`landing._dwell`'s first look at the first few points answers as measuring every point does: landings on a
    blob, straight departures, tiny blobs and random walks."""
    rng = np.random.default_rng(3)
    line = np.column_stack([np.linspace(0, 100, 20), np.zeros(20)])
    cases = [np.vstack([rng.normal(0, 1.5, (8, 2)) * scale, line]) for scale in (1.0, 0.01, 3.0) for _ in range(30)]
    cases += [line, *(np.cumsum(rng.normal(0, 1, (40, 2)), axis=0) for _ in range(200))]
    found = 0
    for pts in cases:
        for radius in (0.5, 2.0, 6.0, 50.0):
            assert landing._dwell(pts, radius) == _plain_dwell(pts, radius)
            found += _plain_dwell(pts, radius) > 0
    assert found > 10


def test_the_rankers_mean_is_numpys() -> None:
    """`ranker._mean` is ``float(np.mean(values))`` to the bit (numpy's pairwise sum beyond eight values)."""
    rng = np.random.default_rng(11)
    for n in range(1, 40):
        values = rng.normal(0, 1, n).tolist()
        assert ranker._mean(values) == float(np.mean(values))
        flags = (rng.random(n) < 0.5).tolist()
        assert sum(flags) / len(flags) == float(np.mean(flags))


def _plain_retraced(work: np.ndarray, th: np.ndarray, diag: float) -> bool:
    """`stroke_features.retraced` as it was: the quantile worked out wherever the box does not decide."""
    end = int(np.searchsorted(np.abs(np.add.accumulate(th)), 2 * math.pi)) + 2
    first, rest = work[:end], work[end:]
    if len(rest) < 4 or len(first) < 4:
        return False
    d = np.hypot(rest[:, None, 0] - first[None, :, 0], rest[:, None, 1] - first[None, :, 1]).min(axis=1)
    return float(np.quantile(d, 0.9)) < 0.06 * diag


def test_a_retraced_loop_is_told_as_by_the_quantile() -> None:
    """`stroke_features.retraced` (the quantile's two order statistics first) answers as the quantile does: loops
    drawn twice over with the pen's wobble, stars turning twice round, and spirals, at limits either side."""
    rng = np.random.default_rng(5)
    cases = []
    for _ in range(150):
        a = np.linspace(0, 2 * math.pi * rng.uniform(1.2, 2.5), int(rng.integers(60, 300)))
        wobble = rng.normal(0, rng.choice([0.001, 0.02, 0.1]), (len(a), 2))
        grow = 1 + rng.uniform(0, 0.3) * a / a[-1]
        cases.append(np.column_stack([np.cos(a) * grow, np.sin(a) * grow]) + wobble)
    star = np.array([[math.cos(k * 4 * math.pi / 5), math.sin(k * 4 * math.pi / 5)] for k in range(11)])
    cases.append(np.concatenate([np.linspace(p, q, 20, endpoint=False) for p, q in itertools.pairwise(star)]))
    told = set()
    for work in cases:
        th = sg.turning(work)
        for diag in (0.1, 0.5, 1.0, 2.0, 2.8, 5.0):
            assert sf.retraced(work, th, diag) == _plain_retraced(work, th, diag)
            told.add(_plain_retraced(work, th, diag))
    assert told == {True, False}


def _plain_crossings(vertices: np.ndarray) -> int:
    """`polygon_checks.crossings` as it was (its pairs of sides made afresh each time)."""
    a = np.asarray(vertices, dtype=float)
    b = np.roll(a, -1, axis=0)
    m = len(a)
    i, j = np.triu_indices(m, 2)
    keep = ~((i == 0) & (j == m - 1))
    i, j = i[keep], j[keep]

    def side(p: np.ndarray, q: np.ndarray, r: np.ndarray) -> np.ndarray:
        u, w = q - p, r - p
        turn: np.ndarray = np.sign(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        return turn

    apart_j = side(a[i], b[i], a[j]) * side(a[i], b[i], b[j]) < 0
    apart_i = side(a[j], b[j], a[i]) * side(a[j], b[j], b[i]) < 0
    return int(np.count_nonzero(apart_i & apart_j))


def test_crossings_with_pairs_made_once_count_as_before() -> None:
    """`polygon_checks.crossings` (its pairs of sides made once for each number of sides) counts as before: stars,
    random outlines of 3-12 vertices, twice over each (the pairs read again)."""
    rng = np.random.default_rng(9)
    star = np.array([[math.cos(k * 4 * math.pi / 5), math.sin(k * 4 * math.pi / 5)] for k in range(5)])
    outlines = [star, *(rng.normal(0, 1, (int(rng.integers(3, 13)), 2)) for _ in range(400))]
    counts = set()
    for _ in range(2):
        for v in outlines:
            assert polygon_checks.crossings(v) == _plain_crossings(v)
            assert polygon_checks.crossings([tuple(p) for p in v.tolist()]) == _plain_crossings(v)
            counts.add(_plain_crossings(v))
    assert 0 in counts and 5 in counts
