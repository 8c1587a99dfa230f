"""Issue 25, session 23: a curly brace drawn square-cornered (end arms turned at square corners onto a spine, a small
point halfway along it; `square_braces`) reads as a brace, a curve, by every pen and from either end, mirrored; a square
bracket, with or without a jog or a dent in its spine, stays a bracket. The pen-model family
(`tests/penmodels/brace_habits.square_cornered`, `benchmarks/bench_brace_habits.py`) is read on the held seeds
(1000-1029), looked at once, at the end; each floor is the figure measured then. People's strokes are read from the
public-set caches (design sources only); without them that test skips."""

from __future__ import annotations

import itertools
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.brace_habits import WAYS
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import square_braces
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_brace_habits import drawn

HELD = range(1000, 1030)

SQUARE_CORNERED_FLOORS = {"careful": 60, "hurried": 58, "hurried-fast": 44, "hurried-mouse": 43, "hurried-tiny": 45,
                          "hurried-accel": 55}
"""Of the square-cornered braces of the first 15 held seeds drawn four ways (60), how many each pen's read as curves
(with times): the held seeds' figures when `square_braces` was written; main 6b543d7 read 32, 42, 28, 33, 45 and 30
(the rest polylines, a few tiny ones lines; docs/BENCHMARKS.md, session 23)."""


@pytest.mark.parametrize("pen", list(SQUARE_CORNERED_FLOORS))
def test_a_square_cornered_brace_is_a_curve(pen: str) -> None:
    strokes = [drawn("square-cornered", way, pen, seed) for seed in HELD[:15] for way in WAYS]
    read = [recognize_stroke([p[:2] for p in s], [p[2] for p in s]).kind for s in strokes]
    assert sum(k == "curve" for k in read) >= SQUARE_CORNERED_FLOORS[pen], read


def _path(*corners: tuple[float, float], step: float = 2.0) -> np.ndarray:
    """Straight runs through ``corners`` (pixels), a point every ``step`` px or so."""
    runs = [np.linspace(a, b, max(2, int(np.hypot(b[0] - a[0], b[1] - a[1]) / step)), endpoint=False)
            for a, b in itertools.pairwise(np.asarray(corners, dtype=float))]
    return np.concatenate([*runs, np.asarray(corners[-1:], dtype=float)])


BRACE = ((340.0, 100.0), (300.0, 100.0), (300.0, 190.0), (288.0, 200.0), (300.0, 210.0), (300.0, 300.0),
         (340.0, 300.0))
"""A left brace 200 px tall, square-cornered, its point 12 px out (0.06 of it)."""


@pytest.mark.parametrize("turn", ["as drawn", "reversed", "mirrored", "mirrored and reversed", "lying down"])
def test_a_square_cornered_brace_with_a_small_point_is_one_however_drawn(turn: str) -> None:
    pts = _path(*BRACE)
    if "mirrored" in turn:
        pts = pts * np.array([-1.0, 1.0]) + np.array([700.0, 0.0])
    if "reversed" in turn:
        pts = pts[::-1]
    if turn == "lying down":
        pts = pts[:, ::-1].copy()
    assert square_braces.square_brace(pts, 1.0)
    assert recognize_stroke(pts.tolist()).kind == "curve"


@pytest.mark.parametrize(("name", "corners"), [
    ("bracket", ((340.0, 100.0), (300.0, 100.0), (300.0, 300.0), (340.0, 300.0))),
    ("bracket with a jog in its spine", ((340.0, 100.0), (300.0, 100.0), (300.0, 195.0), (292.0, 205.0),
                                         (292.0, 300.0), (332.0, 300.0))),
    ("bracket dented in towards its arms", ((340.0, 100.0), (300.0, 100.0), (300.0, 190.0), (312.0, 200.0),
                                            (300.0, 210.0), (300.0, 300.0), (340.0, 300.0))),
    ("bracket whose point is two pixels out", ((340.0, 100.0), (300.0, 100.0), (300.0, 196.0), (298.0, 200.0),
                                               (300.0, 204.0), (300.0, 300.0), (340.0, 300.0))),
    ("zig-zag", ((100.0, 100.0), (140.0, 160.0), (180.0, 100.0), (220.0, 160.0), (260.0, 100.0))),
    ("stair", ((100.0, 100.0), (200.0, 100.0), (200.0, 150.0), (300.0, 150.0))),
])
def test_a_bracket_a_zigzag_or_a_stair_is_no_square_cornered_brace(name: str, corners: tuple) -> None:
    assert not square_braces.square_brace(_path(*corners), 1.0), name
    if name.startswith("bracket"):
        assert recognize_stroke(_path(*corners).tolist()).kind == "polyline", name


PEOPLE = {("public-sets/hcira.jsonl",
           "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s01/right_curly_brace1.xml"): "curve"}
"""(cached set, file) -> the kind a reader names: a right brace drawn square-cornered with a point 5 px out on a
102 px spine, read as a polyline (a bracket) at main 6b543d7."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.rsplit("/", 1)[-1] for _, f in PEOPLE])
def test_a_persons_square_cornered_brace_is_a_curve(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times, learned=False).kind == PEOPLE[(name, file)]
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]
