"""Curly braces drawn with different hands' habits (issue 25, session 21; `tests/penmodels/brace_habits`): a left and a
right brace, drawn from either end, read alike; a tall, thin brace is a curve, not a line (`thin_braces`), by both pen
models and on people's strokes; a line is still a line.

Floors were measured on the held seeds (1000-1029, `benchmarks/bench_brace_habits.py`), never looked at while the
rule was designed. People's strokes are read from the caches `benchmarks/public_sets.py` and
`benchmarks/student_sets.py` write; without them those tests skip, saying so.
"""

from __future__ import annotations

import itertools
import json
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.brace_habits import FAMILIES, WAYS
from test_open_marks import CACHE

from physink_tui.scene.recognition import lopsided_braces
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_brace_habits import drawn

HELD = range(1000, 1030)


def _read(family: str, way: str, pen: str, seed: int) -> str | None:
    stroke = drawn(family, way, pen, seed)
    return recognize_stroke([p[:2] for p in stroke], [p[2] for p in stroke]).kind


@pytest.mark.parametrize("family", list(FAMILIES))
def test_a_brace_reads_the_same_mirrored_and_drawn_from_either_end(family: str) -> None:
    """The careful pen draws the same brace four ways (`brace_habits.WAYS`): a left brace mirrored is a right one, and
    a brace drawn from its bottom is the same mark; the recogniser reads all four alike."""
    for seed in HELD[:4]:
        readings = {way: _read(family, way, "careful", seed) for way in WAYS}
        assert len(set(readings.values())) == 1, (family, seed, readings)


TALL_THIN_FLOORS = {"careful": 56, "hurried": 53}
"""Of the tall, thin braces of the first 15 held seeds drawn four ways (60), how many each pen's read as curves: the
held seeds' figures when `thin_braces` was written (main 98c6955, before it: careful 0, hurried 22; the rest lines)."""


@pytest.mark.parametrize("pen", list(TALL_THIN_FLOORS))
def test_a_tall_thin_brace_is_a_curve_not_a_line(pen: str) -> None:
    read = [_read("tall-thin", way, pen, seed) for seed in HELD[:15] for way in WAYS]
    assert sum(k == "curve" for k in read) >= TALL_THIN_FLOORS[pen], read


PEOPLE = {
    ("public-sets/itt-more.jsonl",
     "ITT-24/assignment-6-gesture-recognition-EmmaSophieReichert@32d2840:dataset/my-dataset/right_curly_brace01.xml"):
    "curve",
    ("public-sets/hcira.jsonl", "hat359/HCIRA@69a6542:xml_collected_logs/user3/right_curly_brace03.xml"): "curve",
}
"""(cached set, file) -> the kind a reader names: thin right braces the line test took for lines (main 98c6955)."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.rsplit("/", 1)[-1] for _, f in PEOPLE])
def test_a_persons_tall_thin_brace_is_a_curve(name: str, file: str) -> None:
    path = CACHE / name
    if not path.is_file():
        pytest.skip(f"{path} not found: the public sets are not committed; `python benchmarks/public_sets.py` "
                    "writes them there")
    key = json.dumps(file)[1:-1]  # only the line naming the file is parsed (the whole set takes seconds)
    rows = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if key in line]
    row = next((r for r in rows if r["file"] == file), None)
    assert row is not None, f"{file} is not in {name}"
    stroke = row["strokes"][0]
    times = [p[2] / 1000 for p in stroke] if all(len(p) > 2 and p[2] is not None for p in stroke) else None
    points = [p[:2] for p in stroke]
    assert recognize_stroke(points, times, learned=False).kind != "line"  # the rules' line test no longer takes it
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]


def test_a_line_with_a_kink_or_hooks_is_still_a_line() -> None:
    """No point between curls: a long line bent a few degrees at its middle (an obtuse chevron: its arms run on to
    its ends), and one with a short hook at each end curling the same way, stay lines."""
    kinked = [(100.0 + 4 * k, 500.0 + (k if k < 50 else 100 - k) * 0.25) for k in range(101)]
    assert recognize_stroke(kinked).kind == "line"
    hooks = ([(96.0 + 2 * k, 480.0 + 4 * k) for k in range(5)] + [(108.0 + 4 * k, 500.0) for k in range(100)]
             + [(508.0 + 2 * k, 500.0 - 4 * k) for k in range(1, 5)])
    assert recognize_stroke(hooks).kind == "line"


PLAIN_SHORT_HALF_FLOORS = {"careful": 45, "hurried": 58, "hurried-mouse": 54, "hurried-fast": 56}
"""Of the lopsided braces with a straight short half (`brace_habits.plain_short_half`) of the first 15 held seeds drawn
four ways (60), how many each pen's read as curves: the held seeds' figures when `lopsided_braces` was written (on
all 30 held seeds, with and without times, main 007872c read 2, 104, 100 and 102 of 240 as curves, this branch 210,
232, 186 and 224: docs/BENCHMARKS.md, session 22)."""


@pytest.mark.parametrize("pen", list(PLAIN_SHORT_HALF_FLOORS))
def test_a_lopsided_brace_with_a_straight_short_half_is_a_curve(pen: str) -> None:
    read = [_read("plain-short-half", way, pen, seed) for seed in HELD[:15] for way in WAYS]
    assert sum(k == "curve" for k in read) >= PLAIN_SHORT_HALF_FLOORS[pen], read


def _unit_path(*corners: tuple[float, float]) -> np.ndarray:
    """Straight runs through ``corners``, on 128 points equally spaced (as `lopsided_braces` judges a stroke)."""
    pts = np.concatenate([np.linspace(a, b, 40, endpoint=False) for a, b in itertools.pairwise(corners)]
                         + [np.asarray(corners[-1:], dtype=float)])
    return sg.resample(pts, 128)


@pytest.mark.parametrize(("name", "corners"), [
    ("check", ((0.0, 0.0), (0.25, 0.3), (1.0, -0.6))),
    ("bracket with a long lower arm", ((0.3, 0.0), (0.0, 0.0), (0.0, 1.0), (0.55, 1.0))),
    ("zig-zag of two teeth", ((0.0, 0.0), (0.2, 0.3), (0.45, 0.05), (0.7, 0.3), (0.9, 0.0))),
])
def test_a_check_a_bracket_or_a_zigzag_is_no_lopsided_brace(name: str, corners: tuple) -> None:
    assert not lopsided_braces.laid_out(_unit_path(*corners)), name


def test_a_lopsided_brace_drawn_as_straight_runs_is_laid_out_as_one() -> None:
    """An end arm, a square corner, a long spine, a point standing past it, a straight slant back: either way."""
    brace = _unit_path((0.3, 0.0), (0.0, 0.0), (0.0, 0.7), (-0.15, 0.85), (0.25, 1.2))
    assert lopsided_braces.laid_out(brace) and lopsided_braces.laid_out(brace[::-1])
