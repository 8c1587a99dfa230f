"""Recognition's fast paths give the same numbers as the plain numpy they stand for, to the last bit, so a speed-up
changes no reading (issue 25, fifth pass; `benchmarks/compare_readings.py` checks whole sets): the even spacing, the
median, the path's length, resampling and turning, the jitter, and the ranker's early stop for a hurried check.

People's strokes are read in place from ``../shared/data/strokes/dollar1-dev.jsonl`` (`shared_data`).
"""

from __future__ import annotations

import math

import numpy as np
from test_people_strokes import people_rows

from physink_tui.scene.recognition import pen_noise, ranker
from physink_tui.scene.recognition import stroke_geometry as sg


def _strokes(seed: int, count: int) -> list[np.ndarray]:
    """Random walks of many lengths and scales, some on a whole-pixel grid with repeated points (as tablets give)."""
    rng = np.random.default_rng(seed)
    out = []
    for k in range(count):
        pts = np.cumsum(rng.normal(size=(int(rng.integers(1, 300)), 2)), axis=0) * rng.choice([1e-3, 1.0, 1e3])
        if k % 3 == 0:
            pts = np.round(pts)
        out.append(pts)
    return out


def _jitter_plain(pts: np.ndarray) -> float:
    """`pen_noise.jitter` as first written, with np.diff, np.column_stack and np.median."""
    if len(pts) < 6:
        return 0.0
    d2 = pts[:-2] - 2 * pts[1:-1] + pts[2:]
    t = pts[2:] - pts[:-2]
    norm = np.hypot(*t.T)
    ok = norm > 0
    if ok.sum() < 3:
        return 0.0
    normal = np.column_stack([-t[ok, 1], t[ok, 0]]) / norm[ok, None]
    bend = (d2[ok] * normal).sum(axis=1)
    return float(1.4826 * np.median(np.abs(np.diff(bend))) / math.sqrt(20))


def test_the_geometry_helpers_give_numpys_numbers_to_the_last_bit() -> None:
    rng = np.random.default_rng(7)
    for pts in _strokes(1, 1500):
        n = int(rng.integers(2, 400))
        total = float(rng.choice([rng.random() * 1e3, 1.0, 1e-310, 5e-324]))
        assert np.array_equal(sg.spaced(total, n), np.linspace(0.0, total, n))
        assert pen_noise.jitter(pts) == _jitter_plain(pts)
        values = rng.normal(size=int(rng.integers(1, 300)))
        assert sg.median(values) == float(np.median(values))
        if len(pts) < 2:
            continue
        seg = np.hypot(*np.diff(pts, axis=0).T)
        assert sg.path_length(pts) == float(np.sum(seg))
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        if cum[-1] > 0:
            at = np.linspace(0.0, cum[-1], n)
            assert np.array_equal(sg.resample(pts, n),
                                  np.column_stack([np.interp(at, cum, pts[:, 0]), np.interp(at, cum, pts[:, 1])]))
        heading = np.arctan2(*np.diff(pts, axis=0)[:, ::-1].T)
        assert np.array_equal(sg.turning(pts), (np.diff(heading) + np.pi) % (2 * np.pi) - np.pi)


def test_the_median_of_values_with_a_nan_is_nan_as_numpys() -> None:
    assert math.isnan(sg.median(np.array([1.0, math.nan, 2.0])))


def test_the_ranker_stops_early_exactly_for_the_checks_it_does_not_ask_about() -> None:
    """A polyline's features stop early (None) exactly when the full features make `ranker.checked_point` true, and a
    stroke prepared from what recognition measured (`ranker.Drawn`) gets the features of one prepared from scratch."""
    stopped = asked = 0
    for row in people_rows()[::4]:
        stroke = row["strokes"][0]
        points = [p[:2] for p in stroke]
        times = [p[2] / 1000 for p in stroke]
        unit = ranker._unit_work(points, times)
        full = ranker._features(unit, 1.0)
        assert full is not None
        early = ranker._features(unit, 1.0, polyline=True)
        if ranker.checked_point(full):
            assert early is None
            stopped += 1
        else:
            assert early is not None and np.array_equal(early, full)
            asked += 1
        pts = np.asarray(points, dtype=float)
        keep = np.ones(len(pts), dtype=bool)
        keep[1:] = np.any(np.diff(pts, axis=0) != 0.0, axis=1)
        raw = pts[keep]
        drawn = ranker.Drawn(raw, keep, raw.mean(axis=0), sg.bbox_diagonal(raw), pen_noise.jitter(raw))
        assert np.array_equal(ranker._features(ranker._unit_work(points, times, drawn), 1.0), full)
    assert stopped >= 50 and asked >= 200  # both ways exercised (84 and 276 of the 360 strokes)
