"""Recognition's fast paths give the same numbers as the plain numpy they stand for, to the last bit, so a speed-up
changes no reading (issue 25, fifth pass; `benchmarks/compare_readings.py` checks whole sets): the even spacing, the
median, the path's length, resampling, smoothing and turning, the jitter, and the ranker's early stop for a hurried
check; and the rules' early stops give the answers of the full tests (issue 25, session 19): the staircase's corner
search, and the line test's hooks cut where no cut piece could be a line.

People's strokes are read in place from ``../shared/data/strokes/dollar1-dev.jsonl`` (`shared_data`).
"""

from __future__ import annotations

import math

import numpy as np
from test_people_strokes import people_rows

from physink_tui.scene.recognition import lines, open_shapes, pen_noise, ranker, stairs
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


def _smooth_plain(pts: np.ndarray, passes: int = 2) -> np.ndarray:
    """`stroke_geometry.smooth` as first written, each pass's points joined with np.concatenate."""
    out = pts.copy()
    for _ in range(passes):
        if len(out) < 3:
            break
        out = np.concatenate([out[:1], (out[:-2] + 2 * out[1:-1] + out[2:]) / 4, out[-1:]])
    return out


def test_the_geometry_helpers_give_numpys_numbers_to_the_last_bit() -> None:
    rng = np.random.default_rng(7)
    for pts in _strokes(1, 1500):
        n = int(rng.integers(2, 400))
        total = float(rng.choice([rng.random() * 1e3, 1.0, 1e-310, 5e-324]))
        assert np.array_equal(sg.spaced(total, n), np.linspace(0.0, total, n))
        assert pen_noise.jitter(pts) == _jitter_plain(pts)
        passes = int(rng.integers(0, 4))
        smoothed, plain = sg.smooth(pts, passes), _smooth_plain(pts, passes)
        assert smoothed.dtype == plain.dtype and np.array_equal(smoothed, plain)
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
        plain = (np.diff(heading) + np.pi) % (2 * np.pi) - np.pi
        back = plain == -np.pi  # an exact turn back takes the sign of the turns beside it (session 29): +-180 degrees
        th = sg.turning(pts)
        assert np.array_equal(th[~back], plain[~back]) and (np.abs(th[back]) == np.pi).all()


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


def _corners_plain(th: np.ndarray, n: int) -> list[int]:
    """`stairs._corners` as first written: every point in order of sharpness, until one too gentle to be a corner."""
    cum = np.concatenate([[0.0], np.cumsum(th)])
    idx = np.arange(1, n - 1)
    sharpness = np.abs(cum[np.minimum(idx + 1, n - 2)] - cum[np.maximum(idx - 1, 1) - 1])
    least = math.radians(stairs.MIN_TURN_DEG)
    free = np.ones(len(th), dtype=bool)
    taken: list[int] = []
    for k in np.argsort(-sharpness, kind="stable").tolist():
        c = k + 1
        if sharpness[k] < least / (2 * stairs.REACH + 1):
            break
        a, b = max(c - stairs.REACH, 1) - 1, min(c + stairs.REACH, n - 2)
        if free[c - 1] and abs(float(th[a:b][free[a:b]].sum())) >= least:
            taken.append(c)
            free[a:b] = False
    return [0, *sorted(taken), n - 1]


def _fine_turns(pts: np.ndarray, noise: float) -> tuple[np.ndarray, int]:
    """How a stroke turns on `stairs.corner_chain`'s fine resample (at unit size, ``noise`` in those units)."""
    unit = (pts - pts.mean(axis=0)) / sg.bbox_diagonal(pts)
    n = int(min(stairs.MAX_POINTS, max(stairs.MIN_POINTS, sg.path_length(unit) / (stairs.SPACING * noise))))
    work = sg.smooth(sg.resample(unit, n))
    return sg.turning(work), len(work)


def test_the_staircase_corner_search_finds_the_corners_the_full_search_finds() -> None:
    """`stairs._corners` looks only at points whose window turns far enough all told; it takes the corners the search
    over every point took, on people's strokes at the fine scale (three noises) and on random turning."""
    rng = np.random.default_rng(11)
    turns = []
    for row in people_rows()[::3]:
        pts = sg.drop_duplicates(np.asarray([p[:2] for p in row["strokes"][0]], dtype=float))
        turns += [_fine_turns(pts, noise) for noise in (0.002, 0.005, 0.01)]
    turns += [(rng.normal(0.0, rng.uniform(0.01, 0.6), n - 2), n) for n in rng.integers(64, 400, 300).tolist()]
    found = [stairs._corners(th, n) for th, n in turns]
    assert found == [_corners_plain(th, n) for th, n in turns]
    assert sum(len(c) >= stairs.MIN_CORNERS + 2 for c in found) >= 300  # chains of corners among them (668 of 1,740)


def test_a_hook_is_cut_for_the_line_test_only_where_a_piece_left_could_be_a_line(monkeypatch) -> None:
    """`lines.ends_may_span` is false only where no piece `lines.unhooked` would cut (whatever its corner test says)
    has its ends half its diagonal apart (`open_shapes._ends_span`, the line test's first question): people's strokes
    and random walks, at unit size, at several pens' noises."""
    monkeypatch.setattr(lines, "sharp_corner", lambda pts, noise: False)  # every piece, corner or not
    skipped = spanning = 0
    strokes = [np.asarray([p[:2] for p in row["strokes"][0]], dtype=float) for row in people_rows()[::2]]
    for pts in strokes + _strokes(3, 600):
        pts = sg.drop_duplicates(pts)
        if len(pts) < 3 or sg.bbox_diagonal(pts) == 0:
            continue
        unit = (pts - pts.mean(axis=0)) / float(np.abs(pts - pts.mean(axis=0)).max())
        for noise in (0.003, 0.01, 0.03):
            pieces = lines.unhooked(unit, noise)
            if not lines.ends_may_span(unit, noise, sg.bbox_diagonal(unit)):
                assert not any(open_shapes._ends_span(p) for p in pieces)
                skipped += bool(pieces)
            else:
                spanning += any(open_shapes._ends_span(p) for p in pieces)
    assert skipped >= 300 and spanning >= 300  # both ways exercised (736 and 2,093 of 3,738)
