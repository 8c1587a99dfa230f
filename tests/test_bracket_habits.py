"""Issue 25, session 21: square brackets drawn with the habits of people we have not seen (the held-back HCIRA people
read brackets 89-90 %) read as brackets, the same mirrored or drawn the other way. A bracket whose pen hooks or flicks
at an end, or whose corners are rounded over most of its arms, is judged without the hook (`round_brackets._hook`:
the stroke's own hook cut keeps a hook followed at once by a rounded corner) and is no ellipse left open
(`open_shapes.classify_open`); of straight runs as long, those sharing most of their segments are one spine, whichever
end the stroke was drawn from, and runs apart are none (a brace's halves). The pen-model families
(`tests/penmodels/bracket_habits`, `benchmarks/bench_bracket_habits.py`) are read on the held seeds (1000-1029, read
once, at the end), with and without times; each floor is the figure measured on this branch. One-stroke x's whose
diagonals cross near an end (`tests/penmodels/x_habits`) read as polylines as before, but a few not drawn the other
way: a strict xfail naming the cause. People's strokes are read from the public-set caches (design sources only);
without them that test skips."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels import x_habits
from penmodels.bracket_habits import EXPECTED, FAMILIES
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import round_brackets
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_bracket_habits import PENS, drawn, mirrored, reading, reversed_stroke
from bench_open_marks import HELD_SEEDS

HELD_FLOORS = {
    "hooked-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 60},
    "mouse-rounded-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 58,
                              "hurried-fast": 60},
    "bowed-spine-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60,
                            "hurried-fast": 60},
    "short-arm-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 56, "hurried-fast": 60},
    "askew-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 60},
    "closing-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 58},
    "small-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60, "hurried-fast": 60},
    "swept-arm-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60,
                          "hurried-fast": 60},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are polylines,
measured on this branch; main 98c6955 read hooked brackets through the fast device 54, brackets rounded over most of
their arms 60, 44, 44, 46 and 40, small brackets 60, 60, 58, 56 and 56 (the rest curves, a few ellipses or arcs), the
other rows the same. The short-armed brackets the mouse leaves read as lines have arms of 4-5 % of the path, within a
landing hook's reach (`stroke_geometry.ARM_SHARE`). Session 22 (wt-mouse: `round_brackets.SPLAYED_TURN`) raised
brackets rounded over most of their arms through the coarse and fast devices from 54 and 58 to 58 and 60, askew
brackets through the fast device from 58 to 60; the swept-arm family (session 22, wt-students) reads 60 by every pen at
main 007872c too. Session 24 (wt-brackets: `round_brackets.HALF_TURN` to 245 degrees, `ROUND_ARM_FLAT`) raised the
rounded brackets through the coarse device 58 -> 60, short-armed ones through the mouse 54 -> 56, small ones through
the mouse and the fast device 58 -> 60."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_brackets_drawn_with_unseen_habits_read_as_brackets(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed), timed) for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k == EXPECTED[family] for k in got) >= HELD_FLOORS[family][pen], got


@pytest.mark.parametrize("family", list(FAMILIES))
def test_a_bracket_reads_the_same_mirrored_and_drawn_the_other_way(family: str) -> None:
    """Main 98c6955 read 18 of the held seeds' rounded brackets otherwise drawn the other way (a spine chosen among
    straight runs as long by which came first)."""
    changed = []
    for seed in HELD_SEEDS:
        stroke = drawn(family, "hurried", seed)
        kind = reading(stroke, False)
        for name, variant in (("mirrored", mirrored(stroke)), ("reversed", reversed_stroke(stroke))):
            if reading(variant, False) != kind:
                changed.append((seed, name))
    assert not changed


def _hooked_rounded_bracket(hook_deg: float) -> np.ndarray:
    """A bracket 200 tall, arms 60 long, both corners rounded off over 30 of them (a quarter circle each), with a
    hook of 8 turned ``hook_deg`` off the arm at each end (y down, unit size as `recognize` judges it)."""
    r = 30.0
    pts = [(60.0 - k * (60.0 - r) / 4, -100.0) for k in range(5)]
    pts += [(r - r * math.sin(a), -100.0 + r - r * math.cos(a)) for a in np.linspace(0, math.pi / 2, 16)[1:]]
    pts += [(0.0, -100.0 + r + k * (200.0 - 2 * r) / 20) for k in range(1, 21)]
    pts += [(r - r * math.cos(a), 100.0 - r + r * math.sin(a)) for a in np.linspace(0, math.pi / 2, 16)[1:]]
    pts += [(r + k * (60.0 - r) / 4, 100.0) for k in range(1, 5)]
    turn = math.radians(hook_deg)
    start = [(60.0 + 8.0 * math.cos(turn) * k / 3, -100.0 - 8.0 * math.sin(turn) * k / 3) for k in (3, 2, 1)]
    end = [(60.0 + 8.0 * math.cos(turn) * k / 3, 100.0 + 8.0 * math.sin(turn) * k / 3) for k in (1, 2, 3)]
    return np.asarray(start + pts + end) / 200.0


def _judged(pts: np.ndarray) -> tuple[np.ndarray, list[float]]:
    work = sg.resample(pts, 128)
    return work, sf.lobes(work)


@pytest.mark.parametrize("hook_deg", [-120.0, 120.0])
def test_a_rounded_bracket_with_a_hook_at_each_end_is_a_bracket(hook_deg: float) -> None:
    work, lobes = _judged(_hooked_rounded_bracket(hook_deg))
    found = round_brackets.rounded_bracket(work, lobes)
    assert found is not None
    corners = np.asarray(found[1:3]) * 200.0
    assert np.allclose(corners, [(0.0, -100.0), (0.0, 100.0)], atol=8.0), corners


HCIRA = "public-sets/hcira.jsonl"
PEOPLE = {
    (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/right square bracket6.xml"): "polyline",
    (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/left square bracket3.xml"): "polyline",
    (HCIRA, "klarubbio/hcira_p1@e8eb332:xml/s02/left_square_bracket08.xml"): "polyline",
    ("public-sets/itt-more.jsonl", "ITT23/assignment-06-gesture-recognition-sina-sch@8c0dbdb:dataset/"
                                   "right_curly_brace05.xml"): "curve",
    (HCIRA, "hat359/HCIRA@69a6542:xml_collected_logs/user6/left_curly_brace04.xml"): "curve",
    (HCIRA, "hat359/HCIRA@69a6542:xml_collected_logs/user3/right_curly_brace02.xml"): "curve",
}
"""(cached set, file) -> the kind a reader names: a right bracket with both corners rounded and a hook where the pen
lifted (misread as a curve at main 98c6955), two rounded brackets whose arms bend gently into their corners (a skip
of the bend's first segments must not be taken for a hook), and three braces whose halves either side of a small point
are straight runs as long (read as brackets by this session's first tries)."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.split("/")[-1] for _, f in PEOPLE])
def test_a_persons_bracket_or_brace_reads_as_what_it_is(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]


X_HELD_FLOORS = {"careful": 58, "hurried": 56, "hurried-coarse": 56, "hurried-mouse": 56, "hurried-fast": 58}
"""pen -> of the 60 readings of `x_habits.offset_x` on the held seeds, how many are polylines (as main 98c6955)."""


@pytest.mark.parametrize("pen", list(PENS))
def test_an_x_whose_diagonals_cross_near_an_end_reads_as_an_x(pen: str) -> None:
    got = [reading(drawn("offset-x", pen, seed, x_habits.FAMILIES), timed) for seed in HELD_SEEDS
           for timed in (True, False)]
    assert sum(k == "polyline" for k in got) >= X_HELD_FLOORS[pen], got


@pytest.mark.xfail(strict=True, reason=(
    "closed_loops.polygon_left_open asks stroke_features.heading_home whether the first side or the last heads home, "
    "not the same of each: an x whose diagonals cross near its end, its first tail left long, passes as a triangle "
    "'drawn past its start, back from it'; drawn from the other end it does not. Asking it both ways, or asking the "
    "last side to run along the first, cost two or three design polygons left open (session 21); session 22 measured "
    "both symmetric forms: 'past the start' asked of the first side and the last alike loses hcira jonathanzhang53/s06 "
    "triangle5 and klarubbio/s01 star09 as drawn (and a fourth-group star), of either loses sinarest1608/Subject3 "
    "delete_mark10 and 4 of 300 offset-x tuning readings"))
def test_an_x_whose_diagonals_cross_near_an_end_reads_the_same_drawn_the_other_way() -> None:
    changed = [seed for seed in HELD_SEEDS
               for stroke in [drawn("offset-x", "hurried", seed, x_habits.FAMILIES)]
               if reading(reversed_stroke(stroke), False) != reading(stroke, False)]
    assert not changed
