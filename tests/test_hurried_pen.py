"""The hurried pen (tests/penmodels) draws as its docstring says: report rate, corners, starts, X timing, pressure."""

from __future__ import annotations

import itertools
import math
import random
import statistics

import pytest
from penmodels.hurried import HurriedPen, single_strokes
from penmodels.journal import hurried_drawing, write_hurried_journal
from penmodels.shapes import XMark, box, circle, polygon, u_container
from scenarios.thesis import egg_cracker

from physink_tui.formats.journal.reader import read_journal

SEEDS = range(6)
CORNERS = ((650.0, 440.0), (950.0, 440.0), (950.0, 560.0), (650.0, 560.0))


def _box_stroke(seed: int) -> list[tuple[float, float, float]]:
    (stroke,) = single_strokes(box((800.0, 500.0), 300.0, 120.0), seed=seed)
    return stroke


@pytest.mark.parametrize("seed", SEEDS)
def test_reports_come_at_about_200_hz_and_their_spacing_varies(seed: int) -> None:
    stroke = _box_stroke(seed)
    gaps = [b[2] - a[2] for a, b in itertools.pairwise(stroke)]
    assert min(gaps) > 0.004 and max(gaps) < 0.006
    assert statistics.median(gaps) == pytest.approx(0.005, abs=0.0002)
    spacing = [math.dist(a[:2], b[:2]) for a, b in itertools.pairwise(stroke)]
    assert max(spacing) > 3 * statistics.median(sorted(spacing)[: len(spacing) // 4])


@pytest.mark.parametrize("seed", SEEDS)
def test_the_pen_slows_into_corners_and_speeds_up_along_sides(seed: int) -> None:
    stroke = _box_stroke(seed)
    steps = [(a, math.dist(a[:2], b[:2])) for a, b in itertools.pairwise(stroke)]
    near = [d for p, d in steps if min(math.dist(p[:2], c) for c in CORNERS) < 8.0]
    mid = [d for p, d in steps if min(math.dist(p[:2], c) for c in CORNERS) > 60.0]
    assert statistics.mean(near) < 0.6 * statistics.mean(mid)


@pytest.mark.parametrize("seed", SEEDS)
def test_a_closed_shape_starts_mid_side_and_ends_near_its_start(seed: int) -> None:
    stroke = _box_stroke(seed)
    start, end = stroke[0][:2], stroke[-1][:2]
    assert min(math.dist(start, c) for c in CORNERS) > 20.0
    assert 0.5 < math.dist(start, end) < 60.0  # an overshoot or a gap, never exactly closed


@pytest.mark.parametrize("seed", SEEDS)
def test_the_strokes_of_an_x_cross_off_their_middles_a_moment_apart(seed: int) -> None:
    mark = XMark(((764.0, 464.0), (836.0, 536.0)), ((836.0, 464.0), (764.0, 536.0)))
    first, second = HurriedPen(random.Random(seed)).draw(mark, 1.0)
    lifted = max(r.t for r in first if r.tip)
    landed = min(r.t for r in second if r.tip)
    assert 0.3 <= landed - lifted <= 0.85
    middles = [statistics.fmean(r.x for r in s if r.tip) for s in (first, second)]
    assert any(abs(m - 800.0) > 3.0 for m in middles)


@pytest.mark.parametrize("seed", SEEDS)
def test_pressure_ramps_up_after_landing_and_down_before_lifting(seed: int) -> None:
    (reports,) = HurriedPen(random.Random(seed)).draw(circle((800.0, 500.0), 40.0), 0.0)
    touching = [r.p for r in reports if r.tip]
    middle = statistics.median(touching)
    assert touching[0] < 0.5 * middle and touching[-1] < 0.5 * middle
    assert not reports[-1].in_range and all(r.in_range for r in reports[:-1])


def test_the_same_seed_draws_the_same_strokes() -> None:
    shape = u_container((800.0, 500.0), 200.0, 150.0, wall=12.0, angle=0.2)
    assert single_strokes(shape, seed=7) == single_strokes(shape, seed=7)
    assert single_strokes(shape, seed=7) != single_strokes(shape, seed=8)


@pytest.mark.parametrize("shape", [box((800.0, 500.0), 200.0, 60.0, angle=0.4), circle((400.0, 300.0), 30.0),
                                   u_container((800.0, 500.0), 200.0, 150.0), polygon([(100, 100), (300, 120),
                                                                                       (200, 260)])])
def test_single_shapes_come_as_one_stroke_of_timed_points_on_the_shape(shape) -> None:
    (stroke,) = single_strokes(shape, seed=3)
    assert stroke[0][2] == 0.0 and all(b[2] > a[2] for a, b in itertools.pairwise(stroke))
    assert len(stroke) > 20


def test_a_hurried_drawing_is_a_journal_that_reads_back_unchanged(tmp_path) -> None:
    steps = egg_cracker().steps
    path = tmp_path / "egg_cracker_hurried.physink.jsonl"
    write_hurried_journal(steps, 1, path)
    journal = read_journal(path)
    assert not journal.warnings and journal.truncated is None
    assert list(journal.entries) == hurried_drawing(steps, 1)[0]
