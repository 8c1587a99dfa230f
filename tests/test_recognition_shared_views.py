"""Issue 25 latency, session 25: what recognition now makes once and shares, or looks at first all at once, gives the
answers the plain computations give.

`stroke_views.StrokeViews` holds one stroke's resampled, smoothed and hook-cut copies for the checks after the rules;
`stroke_geometry.along` and `stroke_geometry.step_lengths` measure a path without numpy's per-call overhead;
`hooked_ticks._may_turn` picks the points `hooked_ticks._arm_corner` measures one by one; the learned ranker leaves the
timed features unmeasured where the model weighs them 0 (`ranker.reads_times`). Each is checked against the plain
computation written out here, and the recogniser with all of them undone must read every $1 stroke (people's,
`../shared/data/strokes/dollar1-dev.jsonl`, resampled to 200 points as `benchmarks/bench_side_by_side.py` times them)
exactly as with them.
"""

from __future__ import annotations

import dataclasses
import json
import math
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from shared_data import shared_path

from physink_tui.scene.recognition import hooked_ticks, ranker, stroke_views
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_recognition import resample


def _strokes(count: int, seed: int = 5) -> Iterator[np.ndarray]:
    """Open strokes at unit size: ticks with a short first arm turning by any angle (some exactly 45 degrees, on a
    lattice), brackets, braces, S-bends and random walks, with and without a pen's jitter."""
    rng = np.random.default_rng(seed)
    for k in range(count):
        sort = k % 5
        if sort == 0:  # a tick: a short arm, then a long one
            turn = math.radians(rng.choice([45.0, 90.0, float(rng.uniform(20.0, 170.0))]))
            arm = np.outer(np.linspace(1.0, 0.0, 13), [math.cos(turn), math.sin(turn)])
            pts = np.concatenate([arm, np.outer(np.linspace(0.0, 10.0, 116)[1:], [-1.0, 0.0])])
        elif sort == 1:  # a square bracket
            pts = np.concatenate([np.linspace([1.0, 0.0], [0.0, 0.0], 20), np.linspace([0.0, 0.0], [0.0, 4.0], 80)[1:],
                                  np.linspace([0.0, 4.0], [1.0, 4.0], 20)[1:]])
        elif sort == 2:  # a curly brace
            t = np.linspace(0.0, 1.0, 160)
            pts = np.column_stack([0.15 * np.sin(4 * math.pi * t) - 0.3 * np.exp(-((t - 0.5) / 0.03) ** 2), 4 * t])
        elif sort == 3:  # an S-bend
            t = np.linspace(0.0, 1.0, 120)
            pts = np.column_stack([t, 0.2 * np.sin(2 * math.pi * t)])
        else:  # a random walk
            pts = np.cumsum(rng.normal(size=(int(rng.integers(3, 300)), 2)), axis=0)
        if k % 3 == 1:
            pts = pts + rng.normal(0.0, 0.01, pts.shape)
        elif k % 3 == 2:
            pts = np.round(pts * 20) / 20  # a lattice: ties between equal steps and turns
        yield (pts - pts.mean(axis=0)) / max(float(np.abs(pts - pts.mean(axis=0)).max()), 1e-12)


def test_the_shared_views_are_the_plain_computations_made_once() -> None:
    """Each view of a `StrokeViews` is what the check used to make for itself, made the first time it is asked, then
    the same read-only array."""
    for unit in _strokes(120):
        views = stroke_views.StrokeViews(unit)
        for n in (64, 128, 160):
            plain = sg.smooth(sg.resample(unit, n))
            assert views.smoothed(n).tobytes() == plain.tobytes()
            assert np.array_equal(views.hooks_cut(n), sg.hooks_cut(unit, n))
            assert views.hooks_cut(n).tobytes() == sg.hooks_cut(unit, n).tobytes()
            assert views.cut_lobes(n, 0.01) == sf.lobes(sg.hooks_cut(unit, n), noise=0.01)
            assert views.smoothed(n) is views.smoothed(n) and views.hooks_cut(n) is views.hooks_cut(n)
            with pytest.raises(ValueError):
                views.smoothed(n)[0, 0] = 1.0
        asked: list[float] = []

        def check(answer: bool, asked: list[float] = asked) -> bool:
            asked.append(1.0)
            return answer

        assert views.once(("a check", 1.0), lambda: check(True)) is True
        assert views.once(("a check", 1.0), lambda: check(False)) is True  # found once: not asked again
        assert views.once(("a check", 2.0), lambda: check(False)) is False and asked == [1.0, 1.0]


def test_a_path_is_measured_as_by_the_plain_numpy_calls() -> None:
    """`stroke_geometry.along` and `step_lengths` give the plain ``np.diff`` / ``np.cumsum`` numbers to the bit, from a
    single point up."""
    rng = np.random.default_rng(7)
    for n in [1, 2, 3, *rng.integers(4, 700, 60).tolist()]:
        pts = rng.normal(size=(n, 2)) * 10.0 ** rng.uniform(-6, 6)
        steps = np.hypot(*np.diff(pts, axis=0).T)
        assert sg.step_lengths(pts).tobytes() == steps.tobytes()
        assert sg.along(pts).tobytes() == np.concatenate([[0.0], np.cumsum(steps)]).tobytes()
        assert sg.path_length(pts) == (float(steps.sum()) if n >= 2 else 0.0)


def test_a_ticks_arm_corner_is_found_as_measuring_every_point(monkeypatch: pytest.MonkeyPatch) -> None:
    """Measuring only the points the first look keeps (`hooked_ticks._may_turn`) finds the corner measuring every
    point finds, or none alike, on ticks turning by any angle (45 degrees, the least a corner turns, among them),
    brackets, braces and random walks, either way round."""
    cases = [(ordered, within, noise) for unit in _strokes(400)
             for pts in [sg.smooth(sg.resample(unit, hooked_ticks.POINTS))] for ordered in (pts, pts[::-1])
             for within, noise in ((12, 0.0), (12, 0.01), (5, 0.05))]
    found = [hooked_ticks._arm_corner(*case) for case in cases]
    monkeypatch.setattr(hooked_ticks, "_may_turn", lambda pts, within: range(1, within + 1))
    assert found == [hooked_ticks._arm_corner(*case) for case in cases]
    assert any(c is None for c in found) and any(c is not None for c in found)


def test_the_timed_features_are_left_out_only_where_no_weight_reads_them() -> None:
    """The shipped model weighs neither timed feature (`ranker.TIMED_FEATURES`), so `rerank` does not measure them; a
    model weighing one, for any kind, has them measured."""
    model = ranker.shipped_model()
    assert not ranker.reads_times(model)
    width = len(ranker.FEATURES) + 1
    for k in range(len(ranker.KINDS)):
        for name in ranker.TIMED_FEATURES:
            theta = model.theta.copy()
            theta[k * width + ranker.FEATURES.index(name)] = 0.25
            assert ranker.reads_times(dataclasses.replace(model, theta=theta))


def _dollar1_strokes() -> list[tuple[list[list[float]], list[float]]]:
    out = []
    for line in shared_path("strokes", "dollar1-dev.jsonl", module_level=False).read_text("utf-8").splitlines():
        row = json.loads(line)
        if len(row["strokes"]) == 1:
            points = np.asarray(row["strokes"][0], dtype=float)
            pts, times = resample(points[:, :2], points[:, 2] / 1000)
            out.append((pts.tolist(), times.tolist()))
    return out


def test_every_dollar1_stroke_reads_alike_with_nothing_shared(monkeypatch: pytest.MonkeyPatch) -> None:
    """People's $1 strokes, with times: the recogniser making every view afresh for each check, measuring every point
    for a tick's corner and the timed features for the ranker, reads each exactly as it does sharing them."""
    strokes = _dollar1_strokes()
    shared = [recognize_stroke(points, times) for points, times in strokes]
    monkeypatch.setattr(stroke_views.StrokeViews, "_once", lambda self, key, make: make())
    monkeypatch.setattr(hooked_ticks, "_may_turn", lambda pts, within: list(range(1, within + 1)))
    monkeypatch.setattr(ranker, "reads_times", lambda model: True)
    plain = [recognize_stroke(points, times) for points, times in strokes]
    assert len(strokes) > 1000
    assert plain == shared
