"""Issue 25, session 32 (wt-mouse): a loop in a busy mouse's bursts read as the polygon it was drawn as where the pen
slowed into its corners (`round_or_cornered.paced_corners`, `corner_pace.slowdowns`), and a whole note left open through
the mouse read round where its bursts are tangent to its ellipse (`pen_noise.round_in_bursts`). Pen-model seeds are
tuning seeds (0-29); the held figures are floors in the benches' own tests. Every reading asked of the pace test is a
timed one: without times, or with times that show no slowing, the test says nothing."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from physink_tui.scene.recognition import corner_pace
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
import bench_circle_gestures
import bench_open_marks
from bench_circle_habits import drawn as circle_habit
from bench_rounded_boxes import read as read_rounded
from penmodels.many_sided import FAMILIES as MANY_SIDED
from penmodels.run_on_closes import run_on

MOUSE = "hurried-mouse"


def _timed(path: np.ndarray, pace: np.ndarray, every: float = 0.008) -> tuple[np.ndarray, np.ndarray]:
    """Events every ``every`` seconds along ``path`` drawn at ``pace`` (px/s at each point of ``path``)."""
    steps = np.hypot(*np.diff(path, axis=0).T)
    clock = np.concatenate([[0.0], np.cumsum(steps / ((pace[1:] + pace[:-1]) / 2))])
    when = np.arange(0.0, clock[-1], every)
    return np.column_stack([np.interp(when, clock, path[:, k]) for k in (0, 1)]), when


def _hexagon() -> tuple[np.ndarray, np.ndarray]:
    """A hexagon 200 across on 600 points, and each point's distance along the path to the nearest corner (px)."""
    corners = [(100 * math.cos(a), 100 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 7)]
    path = np.concatenate([np.linspace(corners[k], corners[k + 1], 100, endpoint=False) for k in range(6)])
    to_corner = np.tile(np.minimum(np.arange(100), 100 - np.arange(100)), 6) * 1.0
    return path, to_corner


def test_a_hand_slowing_into_six_corners_slows_six_times_an_even_pace_not_once() -> None:
    """Drawn slowing into each corner (a quarter of its pace along the sides) the hexagon's pen slows five times or
    more (the first corner is the pen-down); drawn at an even pace, or round a circle at one, it never does."""
    path, to_corner = _hexagon()
    slowing = _timed(path, 300.0 + 900.0 * np.minimum(to_corner / 40.0, 1.0))
    falls = corner_pace.slowdowns(*slowing)
    assert falls is not None and falls >= corner_pace.CORNER_DIPS
    assert corner_pace.slowdowns(*_timed(path, np.full(len(path), 1200.0))) == 0
    circle = np.array([(100 * math.cos(a), 100 * math.sin(a)) for a in np.linspace(0, 2 * math.pi, 600)])
    assert corner_pace.slowdowns(*_timed(circle, np.full(len(circle), 1200.0))) == 0


def test_no_times_no_slowdowns() -> None:
    """Times that do not run forward, or span under three pace windows, say nothing."""
    path, _ = _hexagon()
    assert corner_pace.slowdowns(path[:50], np.linspace(0.0, 0.1, 50)) is None
    assert corner_pace.slowdowns(path[:50], np.linspace(1.0, 0.0, 50)) is None


@pytest.mark.parametrize(("family", "seed"), [
    ("swept-octagon", 0), ("swept-octagon", 1), ("swept-octagon", 9), ("swept-octagon", 20), ("swept-octagon", 26),
    ("irregular-hexagon", 1), ("irregular-hexagon", 25)])
def test_a_many_sided_outline_through_the_mouse_whose_pen_slowed_at_its_corners_is_a_polygon(family: str,
                                                                                         seed: int) -> None:
    """Circles or ellipses on main 5e031e5 (timed): the mouse's chords are too sparse to judge the corners by their
    shape (`polygon_checks.dense_enough`), but the pen slowed into five or more of them."""
    stroke = bench_open_marks.PENS[MOUSE](MANY_SIDED[family](seed), seed)
    assert recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke]).kind == "polygon"


@pytest.mark.parametrize("seed", [22, 25])
def test_a_hexagon_run_on_through_the_mouse_whose_pen_slowed_at_its_corners_is_a_polygon(seed: int) -> None:
    """Circles on main 5e031e5 (timed), as above."""
    stroke = bench_open_marks.PENS[MOUSE](run_on("hexagon-run-on", seed, None)[0], seed)
    assert recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke]).kind == "polygon"


def test_the_same_octagon_with_its_times_spread_evenly_shows_no_slowing() -> None:
    """The octagon's events (read a polygon with their own times, above) given times at one pace along their path (no
    slowing shown): no fall at all, so the loop is read as without this test."""
    stroke = np.array(bench_open_marks.PENS[MOUSE](MANY_SIDED["swept-octagon"](0), 0))
    along = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(stroke[:, :2], axis=0).T))])
    even = stroke[0, 2] + (stroke[-1, 2] - stroke[0, 2]) * along / along[-1]
    assert corner_pace.slowdowns(stroke[:, :2], even) == 0


@pytest.mark.parametrize(("family", "seed"), [
    ("flat-sided-circle", 19), ("lopsided-long-oval", 3), ("flat-oval", 5), ("wobbly-circle", 19)])
def test_round_shapes_through_the_mouse_stay_round(family: str, seed: int) -> None:
    """Session 31's geometric test turned the flat-sided circle seed 19 into a polygon; the pen's pace does not (an
    oval slows at its ends, a lopsided one three or four times at most: under `CORNER_DIPS`)."""
    stroke = circle_habit(family, MOUSE, seed)
    assert recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke]).kind in ("circle", "ellipse")


def test_the_wobbly_round_box_seed_19_through_the_mouse_stays_round() -> None:
    """The other shape session 31's geometric test turned into a polygon."""
    assert read_rounded("wobbly", MOUSE, 19) in ("circle", "ellipse")


@pytest.mark.parametrize(("family", "seed"), [("whole-note-open", 1), ("whole-note-open", 12),
                                              ("whole-note-open-hooked", 1)])
def test_a_whole_note_left_open_through_the_mouse_whose_bursts_are_tangent_to_it_is_round(family: str,
                                                                                         seed: int) -> None:
    """Polylines or a curve on main 5e031e5: the ends near (within `pen_noise.BURST_ENDS_NEAR`), the chords between
    the note's bursts turn alike out of one and into the next (`burst_tangents.EVEN_TANGENTS`), as on a closed note."""
    for mirror in (False, True):
        stroke = bench_circle_gestures.drawn(family, MOUSE, seed, mirror)
        assert all(bench_circle_gestures.reading(stroke, timed) in ("circle", "ellipse") for timed in (True, False))
