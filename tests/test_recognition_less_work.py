"""Session 40's lighter recognition steps answer exactly as the plain computations they replace (issue 25)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from physink_tui.scene.recognition import polygon_fit, recognize
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.diameter_bounds import diameter_bound
from physink_tui.scene.recognition.small_loops import remove_small_loops


def _strokes(rng: np.random.Generator) -> list[np.ndarray]:
    """Stroke-like point arrays: walks, arcs, lines (exactly collinear and not), lattice points, far off the origin."""
    out = []
    for k in range(2000):
        n = int(rng.integers(2, 300))
        scale, off = 10.0 ** rng.uniform(-8, 8), 10.0 ** rng.uniform(-3, 9) * rng.normal(size=2)
        if k % 4 == 0:
            pts = np.cumsum(rng.normal(size=(n, 2)), axis=0)
        elif k % 4 == 1:
            t = np.linspace(0.0, rng.uniform(0.1, 7.0), n)
            pts = np.c_[np.cos(t), np.sin(t)]
        elif k % 4 == 2:
            pts = np.c_[np.linspace(0.0, 1.0, n), np.linspace(0.0, 1.0, n) * rng.uniform(-2, 2)]
        else:
            pts = np.round(rng.normal(size=(n, 2)) * 5)
        out.append(pts * scale + off)
    return out


def test_the_diameter_bound_is_never_under_the_diagonal() -> None:
    for pts in _strokes(np.random.default_rng(40)):
        assert sg.bbox_diagonal(pts) <= diameter_bound(pts)
    assert math.isnan(diameter_bound(np.array([[0.0, 0.0], [math.nan, 1.0]])))


def _plain_smooth(pts: np.ndarray, passes: int = 2) -> np.ndarray:
    if len(pts) < 3 or passes < 1:
        return pts.copy()
    out = pts.astype(np.result_type(pts.dtype, 0.25))
    for _ in range(passes):
        out[1:-1] = (out[:-2] + 2 * out[1:-1] + out[2:]) / 4
    return out


def test_smoothing_in_one_buffer_gives_the_same_bits() -> None:
    rng = np.random.default_rng(41)
    for k, pts in enumerate(_strokes(rng)[:600]):
        passes = k % 4
        with np.errstate(all="ignore"):
            assert sg.smooth(pts, passes).tobytes() == _plain_smooth(pts, passes).tobytes()
    ints = np.arange(20).reshape(10, 2)
    assert sg.smooth(ints).tobytes() == _plain_smooth(ints).tobytes()


def test_corner_points_with_the_shared_extent_are_the_same() -> None:
    rng = np.random.default_rng(42)
    for pts in _strokes(rng)[:400]:
        if len(pts) < 8:
            continue
        fits = polygon_fit.best_polygons(pts, closed=False, max_sides=6, tolerance=0.01 * sg.bbox_diagonal(pts))
        for fit in (f for found in fits.values() for f in found):
            plain = polygon_fit.corner_points(fit.points, fit.indices, closed=fit.closed, reach=fit.reach)
            assert fit.vertices.tobytes() == plain.tobytes()


@pytest.mark.parametrize("points, reason", [
    ([[0.0, 0.0], [1.0, math.nan]], "point 1 is"),
    ([[0.0, 0.0], [2e150, 1.0]], "too large"),
    ([[0.0, 0.0], [-2e150, 1.0]], "too large"),
    ([[1.0, 2.0], [1.0, 2.0]], "a single point"),
])
def test_clean_still_says_what_is_wrong(points: list[list[float]], reason: str) -> None:
    assert reason in str(recognize.recognize_stroke(points).reason)


def test_repeats_are_dropped_as_before() -> None:
    pts = [[0.0, 0.0], [0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [2.0, 1.0], [0.0, 0.0]]
    cleaned, keep, _, _ = recognize._clean(pts)
    assert keep is not None and keep.tolist() == [True, False, True, False, True, True, False, True]
    assert cleaned is not None and cleaned.tolist() == [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [2.0, 1.0], [0.0, 0.0]]


def _plain_small_loops(pts: np.ndarray, max_fraction: float = 0.08, max_size: float = 0.08) -> np.ndarray:
    """`small_loops.remove_small_loops` as it was: every pair of segments gathered, by gap then by start."""
    n = len(pts)
    if n < 8:
        return pts
    span = max(3, int(max_fraction * n))
    i = np.concatenate([np.arange(0, n - 1 - gap) for gap in range(2, span + 1)])
    j = np.concatenate([np.arange(gap, n - 1) for gap in range(2, span + 1)])
    step = pts[1:] - pts[:-1]
    p, r, q, s = pts[i], step[i], pts[j], step[j]
    denom = r[:, 0] * s[:, 1] - r[:, 1] * s[:, 0]
    qp = q - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t = (qp[:, 0] * s[:, 1] - qp[:, 1] * s[:, 0]) / denom
        u = (qp[:, 0] * r[:, 1] - qp[:, 1] * r[:, 0]) / denom
    hit = (denom != 0) & (t >= 0) & (t <= 1) & (u >= 0) & (u <= 1)
    if not hit.any():
        return pts
    diag = sg.bbox_diagonal(pts)
    keep = np.ones(n, dtype=bool)
    out = pts.copy()
    for k in np.flatnonzero(hit)[np.argsort(i[hit], kind="stable")]:
        a, b = int(i[k]), int(j[k])
        if keep[a] and keep[b] and sg.bbox_diagonal(pts[a + 1:b + 1]) <= max_size * diag:
            out[a + 1] = p[k] + t[k] * r[k]
            keep[a + 2:b + 1] = False
    return out[keep]


def test_small_loops_cut_as_testing_every_gathered_pair() -> None:
    rng = np.random.default_rng(43)
    for k, pts in enumerate(_strokes(rng)[:500]):
        if k % 5 == 0:  # a path crossing itself often
            pts = np.cumsum(rng.normal(size=(len(pts), 2)), axis=0)
        for share in (0.08, 0.2):
            with np.errstate(all="ignore"):
                assert remove_small_loops(pts, share).tobytes() == _plain_small_loops(pts, share).tobytes()
