"""Issue 25, session 27: a mark reads the same mirrored (a left bracket or brace made a right one), turned upside down
and drawn from its other end. Measures leaning one way: `square_braces`' point window and a turning lobe's zero steps
(`stroke_features.turn_lobes`), made symmetric; `corner_roundness`' midpoints and a zig-zag's run of teeth
(`open_marks.teeth_run`), left (strict xfails: the symmetric forms cost people's readings); each read some braces one
way and not the other. Pen-model strokes are tuning seeds
(0-29) where an asymmetry was found, and the held seeds (1000-1029) for the count; people's strokes are read from the
public-set caches (design sources only); without them that test skips."""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.brace_habits import FAMILIES
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import open_marks, square_braces
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_brace_habits import drawn

Drawn = list[tuple[float, float, float]]


def _mirrored(stroke: Drawn) -> Drawn:
    mid = (min(p[0] for p in stroke) + max(p[0] for p in stroke)) / 2
    return [(2 * mid - x, y, t) for x, y, t in stroke]


def _upside_down(stroke: Drawn) -> Drawn:
    mid = (min(p[1] for p in stroke) + max(p[1] for p in stroke)) / 2
    return [(x, 2 * mid - y, t) for x, y, t in stroke]


def _reversed(stroke: Drawn) -> Drawn:
    end = stroke[-1][2]
    return [(x, y, end - t) for x, y, t in reversed(stroke)]


WAYS = {"as drawn": lambda s: s, "mirrored": _mirrored, "upside down": _upside_down, "reversed": _reversed}


def _kind(stroke: Drawn, timed: bool = True) -> str | None:
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke] if timed else None).kind


def _wavy_path(seed: int, n: int = 90) -> np.ndarray:
    """A stroke with corners, bends and wobble, points equally spaced (as the checks resample it)."""
    rng = np.random.default_rng(seed)
    heading = np.cumsum(rng.normal(0.0, 0.35, n) + np.where(rng.random(n) < 0.06, rng.choice([-2.0, 2.0], n), 0.0))
    pts = np.cumsum(np.column_stack([np.cos(heading), np.sin(heading)]), axis=0)
    return sg.resample(pts, n)


@pytest.mark.parametrize("seed", range(8))
def test_a_square_brace_point_window_is_centred_on_its_point(seed: int) -> None:
    """Each point's turn within the point span is taken over a window centred on it: the same turns, point for point,
    whichever end the stroke was drawn from (an even window leaned one point toward the end)."""
    pts = _wavy_path(seed)
    length = sg.path_length(pts)
    np.testing.assert_allclose(square_braces._sharp(pts[::-1].copy(), length)[::-1], square_braces._sharp(pts, length),
                               atol=1e-9)


ROUNDNESS_LEANS = (
    "stroke_features.roundness_along takes the turning between the sides' midpoints over the first midpoint's point "
    "and not the last's, and a midpoint between two points falls on the earlier one. Holding both alike was tried in "
    "session 27 and withdrawn: the learned ranker was fitted on the leaning measure, and the rules' zig-zag and wave "
    "tests read three quickdraw/tutorboard squiggles as zig-zags and a zig-zag as a curve with it")


@pytest.mark.xfail(strict=True, reason=ROUNDNESS_LEANS)
@pytest.mark.parametrize("seed", range(2, 8))  # seeds 0 and 1 happen to measure alike either way
def test_a_corner_is_as_round_drawn_from_either_end(seed: int) -> None:
    pts = _wavy_path(seed)
    corners = sg.find_corners(pts, every_dip=True)
    last = len(pts) - 1
    forward = sf.corner_roundness(pts, corners)
    backward = sf.corner_roundness(pts[::-1].copy(), [last - c for c in reversed(corners)])
    np.testing.assert_allclose(backward[::-1], forward, rtol=1e-9, atol=1e-12)


UNEVEN_ZIGZAG = ((0.0, 0.0), (10.0, 45.0), (20.0, 0.0), (30.0, 20.0), (40.0, 0.0), (50.0, 20.0), (60.0, 0.0))
"""A zig-zag whose first tooth is drawn twice as deep as the rest: four even teeth counted from its end, and as many
from its start once the run starts again past the deep one (restarting at the tooth itself counted three)."""


@pytest.mark.xfail(strict=True, reason=(
    "open_marks.teeth_run and sawtooth_vertices restart a run of teeth at the tooth whose side is unlike the one two "
    "before: a deep tooth near one end cuts the count from that end only. Restarting two teeth back (the longest run) "
    "was tried in session 27 and withdrawn: it read hcira klarubbio/s06's zig-zag left braces 03 and 09 and three "
    "quickdraw squiggles as zig-zags"))
def test_a_zigzags_teeth_count_the_same_from_either_end() -> None:
    pts = np.asarray(UNEVEN_ZIGZAG)
    assert open_marks.sawtooth_vertices(UNEVEN_ZIGZAG)
    assert open_marks.sawtooth_vertices(tuple(map(tuple, pts[::-1])))
    path = sg.resample(pts, 160)
    th = sg.turning(path)
    corners = sg.find_corners(path, every_dip=True, th=th)
    assert len(corners) == len(UNEVEN_ZIGZAG)
    runs = [path[a:b + 1] for a, b in itertools.pairwise(corners)]
    straight = [True] * len(runs)
    rev = path[::-1].copy()
    rev_corners = [len(path) - 1 - c for c in reversed(corners)]
    forward = open_marks.teeth_run(path, th, corners, straight, sf.corner_roundness(path, corners, th=th))
    backward = open_marks.teeth_run(rev, sg.turning(rev), rev_corners, straight, sf.corner_roundness(rev, rev_corners))
    assert forward == backward == 4


def test_a_turning_lobe_is_not_broken_by_a_step_straight_on() -> None:
    """A run turning right is one lobe however many steps along it go straight on (exactly 0, or about 1e-15 degrees
    mirrored): the same lobes as the run turning left, its mirror image."""
    right = np.radians([10.0, 0.0, 10.0, 0.0, 0.0, 10.0, 10.0, -1e-15, 10.0, -40.0])
    assert sf.turn_lobes(right) == pytest.approx([50.0, -40.0])
    assert sf.turn_lobes(-right) == pytest.approx([-50.0, 40.0])


MOUSE_BRACES = [("askew", 4), ("classic", 13)]
"""Braces by the hurried hand through a mouse (`bench_brace_habits`, tuning seeds) that read as curves as drawn and as
polylines mirrored, turned or reversed on 9f69154: a straight step of the coarse turning counted as turning left."""


@pytest.mark.parametrize(("family", "seed"), MOUSE_BRACES)
def test_a_mouse_brace_reads_as_a_brace_however_it_is_turned(family: str, seed: int) -> None:
    stroke = drawn(family, "left-down", "hurried-mouse", seed)
    assert {way: _kind(make(stroke)) for way, make in WAYS.items()} == dict.fromkeys(WAYS, "curve")


PEOPLE = [
    "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s01/right_curly_brace1.xml",
    "pixelfac/hcira-project-23@80d4cc7:src/dataset/user04/left curly brace10.xml",
]
"""hcira braces that read as curves as drawn and as polylines reversed on 9f69154: a square-cornered brace whose
point window leaned one point toward the end (fixed), a wavy brace held a strict xfail as the corners' roundness
leaning (`ROUNDNESS_LEANS`) until session 30 found the rules' polyline of it a zig-zag's teeth reversed only (the
ranker was not asked that way, `ranker.zigzag_teeth`, now asked of both vertex orders: fixed)."""


@pytest.mark.parametrize("file", PEOPLE, ids=["right_curly_brace1", "left curly brace10"])
def test_a_persons_brace_reads_as_a_brace_from_either_end(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, file
    points, times = _stroke(row)
    timed = times is not None  # hcira's strokes carry no times
    stroke = [(x, y, t) for (x, y), t in zip(points, times if timed else [0.0] * len(points), strict=True)]
    assert {way: _kind(make(stroke), timed) for way, make in WAYS.items()} == dict.fromkeys(WAYS, "curve")


HELD = range(1000, 1030)
MOUSE_ASYMMETRY_MOST = 1
"""Of the braces of every `brace_habits` family by the hurried hand through a mouse on the first 10 held seeds (110
marks), how many read differently mirrored, turned upside down or reversed than as drawn (1 on 9f69154 and after
session 27: tall-thin 1008, a curve as drawn and a polyline reversed, by the learned ranker, whose corner roundness
leans, `ROUNDNESS_LEANS`; the rules read it a curve both ways). A ceiling, lowered as more is made symmetric, never
raised."""


def test_mouse_braces_read_alike_mirrored_turned_and_reversed() -> None:
    changed = []
    for family in FAMILIES:
        for seed in HELD[:10]:
            stroke = drawn(family, "left-down", "hurried-mouse", seed)
            kinds = {way: _kind(make(stroke)) for way, make in WAYS.items()}
            if len(set(kinds.values())) > 1:
                changed.append((family, seed, kinds))
    assert len(changed) <= MOUSE_ASYMMETRY_MOST, changed


def test_a_turn_straight_back_turns_opposite_ways_mirrored_and_reversed() -> None:
    """`stroke_geometry.turning` wraps an exact turn back to -180 degrees whichever way round it comes: it takes the
    sign of the turns beside it (session 29), so a stroke mirrored or drawn from its other end turns by the opposite
    angles, the turn back too; a stroke that turns nowhere else keeps -180."""
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.5], [1.0, 0.0], [0.0, 1.0], [-1.0, 1.5]])
    th = sg.turning(pts)
    assert abs(th[1]) == np.pi
    np.testing.assert_allclose(sg.turning(pts * [-1.0, 1.0]), -th, atol=1e-12)
    np.testing.assert_allclose(sg.turning(pts[::-1].copy())[::-1], -th, atol=1e-12)
    assert list(sg.turning(np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]]))) == [-np.pi]


def test_a_tiny_mouse_brace_reads_alike_mirrored_and_upside_down() -> None:
    """brace_habits square-cornered through the tiny mouse, tuning seed 9: a curve as drawn, a polyline mirrored, upside
    down and reversed on 821c642, its pixel retrace at the point turning -180 degrees every way (the ranker's net turn
    1.0 as drawn, 0.0 mirrored); a curve all four ways with the turn back turning as the stroke does."""
    stroke = drawn("square-cornered", "left-down", "hurried-tiny", 9)
    assert {way: _kind(make(stroke)) for way, make in WAYS.items()} == dict.fromkeys(WAYS, "curve")
