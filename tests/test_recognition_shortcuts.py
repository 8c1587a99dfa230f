"""Issue 25 latency: recognition's shortcuts (what is measured once and kept, and cheap bounds asked before costly
tests) give the answers the plain computations give.

`PolygonFit.memo` and `PolygonFit.walks` keep a fit's vertices and corner roundness; `lines.beyond_wobble` skips the
line test of `lines.unhooked`'s pieces where none can pass; `stroke_features.retraced` asks a bounding-box bound before
its quantile; `beautify.shape_points` draws a curve's pieces at once; `shape_fits` computes its means and design
matrices without numpy's per-call overhead. Each is checked against the plain computation written out here, on
strokes made to exercise it, and the recogniser with every shortcut undone must read every $1 stroke (people's,
`../shared/data/strokes/dollar1-dev.jsonl`, resampled to 200 points as `benchmarks/bench_side_by_side.py` times them)
exactly as with them.
"""

from __future__ import annotations

import itertools
import json
import math
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.scene.recognition import beautify, lines, open_shapes, polygon_checks, polygon_fit, shape_fits
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.primitives import Curve
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_recognition import resample


def _curvy_strokes(count: int, seed: int = 0) -> Iterator[np.ndarray]:
    """Open strokes of every sort the line test sees: arcs, pigtails, S-bends, zig-zags, hooked and bowed lines, with
    a pen's jitter, at several sizes."""
    rng = np.random.default_rng(seed)
    for k in range(count):
        n = int(rng.integers(20, 240))
        t = np.linspace(0.0, 1.0, n)
        sort = k % 6
        if sort == 0:  # an arc of any sweep
            a = t * rng.uniform(0.1, 5.5)
            pts = np.column_stack([np.cos(a), np.sin(a)])
        elif sort == 1:  # a pigtail: a line into a loop and out
            a = t * 2.6 * math.pi
            pts = np.column_stack([3 * t + 0.4 * np.sin(a), 0.4 * (1 - np.cos(a))])
        elif sort == 2:  # an S-bend
            pts = np.column_stack([t, 0.2 * np.sin(2 * math.pi * t)])
        elif sort == 3:  # a zig-zag
            pts = np.column_stack([t, 0.1 * (np.abs((t * 6) % 2 - 1))])
        elif sort == 4:  # a line with a hook where the pen landed
            pts = np.column_stack([t, np.zeros(n)])
            pts[: max(2, n // 12)] += [0.0, rng.uniform(0.005, 0.06)]
        else:  # a line bowed a little
            pts = np.column_stack([t, rng.uniform(0.001, 0.05) * np.sin(math.pi * t)])
        size = 10.0 ** rng.uniform(0.5, 3)
        yield pts * size + rng.normal(0.0, rng.uniform(0.2, 2.0), pts.shape)


def test_no_piece_of_a_stroke_beyond_the_wobble_passes_the_line_test() -> None:
    """Where `lines.beyond_wobble` says so, no piece `lines.unhooked` leaves passes the line test within the pen's
    wobble (`open_shapes._line` without bow, as `open_shapes.line` asks it where no line was found as drawn); and the
    bound does say so of most curvy strokes, or it would save nothing."""
    said = 0
    for raw in _curvy_strokes(600):
        noise = pen = 1.0
        if not lines.beyond_wobble(raw, noise, pen):
            continue
        said += 1
        for piece in lines.unhooked(raw, pen):
            assert open_shapes._line(piece, noise, sg.bbox_diagonal(piece), pen, bow=False)[0] is None
    assert said >= 150


def test_the_line_test_reads_alike_with_and_without_the_wobble_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    """`open_shapes.line` finds the same line (or none) whether or not it asks `lines.beyond_wobble` first."""
    strokes = list(_curvy_strokes(300, seed=1))
    fast = [open_shapes.line(raw, 1.0, sg.bbox_diagonal(raw), 1.0) for raw in strokes]
    monkeypatch.setattr(lines, "beyond_wobble", lambda raw, noise, pen: False)
    assert [open_shapes.line(raw, 1.0, sg.bbox_diagonal(raw), 1.0) for raw in strokes] == fast
    assert any(found is not None for found in fast) and any(found is None for found in fast)


def _plain_vertices(fit: polygon_fit.PolygonFit) -> np.ndarray:
    return polygon_fit.corner_points(fit.points, fit.indices, closed=fit.closed, reach=fit.reach, sums=fit.sums)


def _plain_roundness(fit: polygon_fit.PolygonFit) -> np.ndarray:
    """`polygon_checks.corner_roundness_closed` as it was before its memo: the whole walk for every fit."""
    ring = fit.points[:-1]
    m, idx = len(ring), [int(i) % len(ring) for i in fit.indices[:-1]]
    corners = [idx[-1], *(m + i for i in idx), 2 * m + idx[0]]
    return np.asarray(sf.corner_roundness(np.concatenate([ring, ring, ring]), corners))


def _loops(seed: int = 2) -> Iterator[np.ndarray]:
    rng = np.random.default_rng(seed)
    for sides in (3, 4, 5, 6, 8, 40):  # 40: a circle
        a = np.linspace(0.0, 2 * math.pi, sides + 1)
        corners = np.column_stack([np.cos(a), rng.uniform(0.5, 1.0) * np.sin(a)])
        loop = np.concatenate([np.linspace(p, q, 24, endpoint=False) for p, q in itertools.pairwise(corners)])
        yield loop + rng.normal(0.0, 0.004, loop.shape)


def test_a_fit_measured_once_measures_as_the_plain_computation() -> None:
    """A closed fit's vertices and corner roundness, kept after the first measure and read-only, are what measuring
    afresh gives, whichever fit of the same points was measured first (the walk round the loop is shared)."""
    for loop in _loops():
        fits = [f for found in polygon_fit.best_polygons(loop, closed=True, max_sides=8, tolerance=0.01).values()
                for f in found]
        assert len({id(f.walks) for f in fits}) <= 2  # one walk for each start the loop was tried from
        for fit in reversed(fits):  # the richest first: the walk is made by another fit than the one read below
            assert np.array_equal(polygon_checks.corner_roundness_closed(fit), _plain_roundness(fit))
        for fit in fits:
            assert np.array_equal(fit.vertices, _plain_vertices(fit))
            assert fit.vertices is fit.vertices and not fit.vertices.flags.writeable
            assert np.array_equal(polygon_checks.corner_roundness_closed(fit), _plain_roundness(fit))
            with pytest.raises(ValueError):
                polygon_checks.corner_roundness_closed(fit)[0] = 0.0


def _plain_retraced(work: np.ndarray, th: np.ndarray, diag: float) -> bool:
    end = int(np.searchsorted(np.abs(np.cumsum(th)), 2 * math.pi)) + 2
    first, rest = work[:end], work[end:]
    if len(rest) < 4 or len(first) < 4:
        return False
    d = np.hypot(rest[:, None, 0] - first[None, :, 0], rest[:, None, 1] - first[None, :, 1]).min(axis=1)
    return float(np.quantile(d, 0.9)) < 0.06 * diag


def test_retraced_answers_as_the_plain_quantile() -> None:
    """`stroke_features.retraced` with its bounding-box bound answers as the plain quantile does: shapes gone round
    twice over the same sides (retraced) and loops with tails or second rounds elsewhere (not)."""
    rng = np.random.default_rng(3)
    answers = []
    for k in range(400):
        n = int(rng.integers(40, 300))
        a = np.linspace(0.0, rng.uniform(2.2, 4.5) * math.pi, n)
        drift = rng.choice([0.0, 0.002, 0.05, 0.5]) * a
        work = np.column_stack([np.cos(a) + drift, rng.uniform(0.4, 1.0) * np.sin(a)])
        if k % 3 == 0:  # a tail drawn off the loop
            work = np.concatenate([work, work[-1] + np.outer(np.linspace(0, rng.uniform(0.1, 3), 30), [1.0, 0.3])])
        work = work + rng.normal(0.0, rng.uniform(0.0, 0.03), work.shape)
        th = sg.turning(work)
        diag = sg.bbox_diagonal(work)
        answers.append(sf.retraced(work, th, diag))
        assert answers[-1] == _plain_retraced(work, th, diag)
    assert any(answers) and not all(answers)


def _plain_curve_points(g: Curve, per_piece: int = 12) -> list[tuple[float, float]]:
    ctrl = np.asarray(g.control_points, dtype=float)
    ts = np.linspace(0.0, 1.0, per_piece + 1)[:, None]
    out = [(float(ctrl[0][0]), float(ctrl[0][1]))]
    for i in range(0, len(ctrl) - 3, 3):
        p0, p1, p2, p3 = ctrl[i:i + 4]
        pts = (1 - ts) ** 3 * p0 + 3 * ts * (1 - ts) ** 2 * p1 + 3 * ts * ts * (1 - ts) * p2 + ts ** 3 * p3
        out += [(float(x), float(y)) for x, y in pts[1:]]
    return out


def test_a_curves_points_are_drawn_as_piece_by_piece() -> None:
    rng = np.random.default_rng(4)
    for _ in range(300):
        ctrl = rng.normal(size=(3 * int(rng.integers(1, 10)) + 1, 2)) * 10.0 ** rng.uniform(-2, 3)
        curve = Curve(tuple((float(x), float(y)) for x, y in ctrl))
        assert beautify.shape_points(curve) == _plain_curve_points(curve)


def _plain_ellipse(pts: np.ndarray) -> shape_fits.EllipseFit | None:
    """`shape_fits.fit_ellipse` written with numpy's plain calls (np.mean, np.column_stack, numpy scalars)."""
    if len(pts) < 6:
        return None
    mean = pts.mean(axis=0)
    scale = float(np.abs(pts - mean).max()) or 1.0
    p = (pts - mean) / scale
    x, y = p[:, 0], p[:, 1]
    d1 = np.column_stack([x * x, x * y, y * y])
    d2 = np.column_stack([x, y, np.ones_like(x)])
    s1, s2, s3 = d1.T @ d1, d1.T @ d2, d2.T @ d2
    try:
        t = -np.linalg.solve(s3, s2.T)
        m = s1 + s2 @ t
        evecs = np.real(np.linalg.eig(np.array([m[2] / 2, -m[1], m[0] / 2]))[1])
    except np.linalg.LinAlgError:
        return None
    good = np.flatnonzero(4 * evecs[0] * evecs[2] - evecs[1] ** 2 > 0)
    if not len(good):
        return None
    a1 = evecs[:, good[0]]
    a1 = -a1 if a1[0] + a1[2] < 0 else a1
    a, b, c = a1
    dd, e, f = t @ a1
    den = b * b - 4 * a * c
    if den >= 0:
        return None
    cx, cy = (2 * c * dd - b * e) / den, (2 * a * e - b * dd) / den
    g = a * cx * cx + b * cx * cy + c * cy * cy - f
    root = math.sqrt((a - c) ** 2 + b * b)
    l1, l2 = (a + c + root) / 2, (a + c - root) / 2
    if l1 <= 0 or l2 <= 0 or g <= 0:
        return None
    angle = 0.5 * math.atan2(b, a - c) + math.pi / 2
    centre = np.array([cx, cy]) * scale + mean
    rx, ry = math.sqrt(g / l2) * scale, math.sqrt(g / l1) * scale
    cs, sn = math.cos(angle), math.sin(angle)
    rel = pts - centre
    r = np.sqrt(((rel[:, 0] * cs + rel[:, 1] * sn) / rx) ** 2 + ((-rel[:, 0] * sn + rel[:, 1] * cs) / ry) ** 2)
    return centre, rx, ry, angle, float(np.sqrt(np.mean((r - 1.0) ** 2)))


def test_an_ellipse_fit_is_the_plain_computations_to_the_bit() -> None:
    rng = np.random.default_rng(5)
    for _ in range(500):
        n = int(rng.integers(6, 300))
        a = np.sort(rng.uniform(0.0, rng.uniform(1.0, 7.0), n))
        pts = np.column_stack([np.cos(a), rng.uniform(0.1, 1.0) * np.sin(a)]) * 10.0 ** rng.uniform(-2, 3)
        pts = pts + rng.normal(0.0, 10.0 ** rng.uniform(-4, -1), pts.shape) + rng.normal(size=2)
        found, plain = shape_fits.fit_ellipse(pts), _plain_ellipse(pts)
        assert (found is None) == (plain is None)
        if found is not None and plain is not None:
            assert np.array_equal(found[0], plain[0]) and found[1:] == plain[1:]


def _dollar1_strokes() -> list[tuple[list[list[float]], list[float]]]:
    out = []
    for line in shared_path("strokes", "dollar1-dev.jsonl", module_level=False).read_text("utf-8").splitlines():
        row = json.loads(line)
        if len(row["strokes"]) == 1:
            p = np.asarray(row["strokes"][0], dtype=float)
            pts, times = resample(p[:, :2], p[:, 2] / 1000)
            out.append((pts.tolist(), times.tolist()))
    return out


def test_every_dollar1_stroke_reads_alike_without_the_shortcuts(monkeypatch: pytest.MonkeyPatch) -> None:
    """People's $1 strokes (1,440), as `benchmarks/bench_side_by_side.py` times them: the recogniser with every
    shortcut undone (the plain computations above, nothing kept on a fit) reads each exactly as with them."""
    strokes = _dollar1_strokes()
    fast = [recognize_stroke(points, times) for points, times in strokes]
    monkeypatch.setattr(lines, "beyond_wobble", lambda raw, noise, pen: False)
    monkeypatch.setattr(sf, "retraced", _plain_retraced)
    monkeypatch.setattr(beautify, "shape_points", lambda g, per_piece=12: (
        _plain_curve_points(g, per_piece) if isinstance(g, Curve) else _unpatched_shape_points(g, per_piece)))
    monkeypatch.setattr(polygon_checks, "corner_roundness_closed", _plain_roundness)
    monkeypatch.setattr(polygon_fit.PolygonFit, "vertices", property(_plain_vertices))
    for module in _users_of("fit_ellipse"):
        monkeypatch.setattr(module, "fit_ellipse", _plain_ellipse)
    for module in _users_of("shape_points"):
        monkeypatch.setattr(module, "shape_points", beautify.shape_points)
    for module in _users_of("corner_roundness_closed"):
        monkeypatch.setattr(module, "corner_roundness_closed", _plain_roundness)
    assert [recognize_stroke(points, times) for points, times in strokes] == fast


_unpatched_shape_points = beautify.shape_points


def _users_of(name: str) -> list[object]:
    """The recognition modules that imported ``name`` by itself (as ``from ... import name``)."""
    import importlib
    import pkgutil

    import physink_tui.scene.recognition as package

    modules = [importlib.import_module(f"{package.__name__}.{m.name}") for m in pkgutil.iter_modules(package.__path__)]
    return [m for m in modules if name in vars(m) and m.__name__.rsplit(".", 1)[-1] not in ("shape_fits", "beautify",
                                                                                             "polygon_checks")]
