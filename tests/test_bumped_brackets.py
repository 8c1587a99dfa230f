"""Issue 25, session 28: square brackets whose spine dents, bulges or steps aside about halfway, the last arm flicked
back half the time, read as brackets; curly braces wobbled alike still braces. The rules read such a bracket as four
vertices and the learned ranker took the spine's turn back for a curve's bends (hcira pixelfac/user01's left bracket 5,
jonathanzhang53/s02's left bracket 1): `dented_spines.kept_bracket` keeps it from the ranker when its spine's middle
turns back against the corners (toward the opening) more than with them (a brace's point), between arms longer than a
brace's curls. The pen-model families (`tests/penmodels/bumped_brackets`, `benchmarks/bench_bumped_brackets.py`) are
read on the held seeds (1000-1029, read once, at the end), with and without times; each floor is the figure measured on
this branch. People's strokes are read from the public-set caches (design sources only); without them that test
skips."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.bumped_brackets import EXPECTED, FAMILIES
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import dented_spines
from physink_tui.scene.recognition.primitives import Polyline, Recognition
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_bracket_habits import drawn, reading
from bench_mouse_habits import PENS
from bench_open_marks import HELD_SEEDS

HELD_FLOORS = {
    "dented-spine-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60,
                             "hurried-fast": 60, "hurried-trackpad": 60, "hurried-slow-mouse": 60},
    "bumped-spine-bracket": {"careful": 40, "hurried": 40, "hurried-coarse": 44, "hurried-mouse": 44,
                             "hurried-fast": 42, "hurried-trackpad": 42, "hurried-slow-mouse": 42},
    "jogged-spine-bracket": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 58,
                             "hurried-fast": 60, "hurried-trackpad": 60, "hurried-slow-mouse": 56},
    "wobbly-brace": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 58,
                     "hurried-fast": 60, "hurried-trackpad": 60, "hurried-slow-mouse": 58},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are read as
`EXPECTED`, measured on this branch. Main 0ca43a2 read the bumped brackets 38, 40, 38, 44, 42, 38, 36 and the jogged
ones through the mouse 56, the other rows as here. Most bumped brackets still read as curves are read so by the rules
themselves (a bulge over a corner rounded over most of its arm: no four vertices to keep)."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_brackets_with_a_bump_halfway_read_as_brackets(family: str, pen: str) -> None:
    got = [reading(drawn(family, pen, seed, FAMILIES, PENS), timed) for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k == EXPECTED[family] for k in got) >= HELD_FLOORS[family][pen], got


def _dented(depth: float, flip: float = 1.0) -> list[tuple[float, float]]:
    """A left bracket 200 tall, arms 80 long, its spine two straight pieces meeting at its middle, that point ``depth``
    toward the opening (``flip`` -1: away from it, as a brace's point), 4 px apart."""
    top = [(80.0 - 4.0 * k, -100.0) for k in range(20)]
    spine = [(flip * depth * (1 - abs(y) / 100.0), float(y)) for y in range(-100, 101, 4)]
    bottom = [(4.0 * k, 100.0) for k in range(1, 21)]
    return top + spine + bottom


def _polyline(points: list[tuple[float, float]]) -> Recognition:
    return Recognition("polyline", 0.7, Polyline(((80.0, -100.0), points[20], points[-21], (80.0, 100.0))))


def test_a_spine_dented_toward_the_opening_is_kept_a_pointed_one_is_not() -> None:
    for flip, kept in ((1.0, True), (-1.0, False)):
        pts = _dented(12.0, flip)
        a = np.asarray(pts)
        origin, scale = a.mean(axis=0), float(np.abs(a - a.mean(axis=0)).max())
        unit = (a - origin) / scale
        found = _polyline(pts)
        assert dented_spines.kept_bracket(found, unit, 1.0 / scale, None, (origin, scale)) is kept
    assert recognize_stroke(_dented(12.0)).kind == "polyline"


def test_a_curl_as_short_as_a_braces_is_no_arm() -> None:
    pts = [(12.0 - 4.0 * k, -100.0) for k in range(3)] + [(12.0 * (1 - abs(y) / 100.0), float(y))
                                                          for y in range(-100, 101, 4)][1:]
    pts += [(4.0 * k, 100.0) for k in range(1, 4)]
    a = np.asarray(pts)
    origin, scale = a.mean(axis=0), float(np.abs(a - a.mean(axis=0)).max())
    found = Recognition("polyline", 0.7, Polyline(((12.0, -100.0), (4.0, -100.0), (0.0, 100.0), (12.0, 100.0))))
    assert not dented_spines.kept_bracket(found, (a - origin) / scale, 1.0 / scale, None, (origin, scale))


def _kept_with_arms(arm: float) -> bool:
    """Whether a left bracket 200 tall, its spine dented 12 toward the opening halfway, its arms ``arm`` long, is kept
    from the ranker."""
    n = int(arm / 4)
    pts = [(arm - 4.0 * k, -100.0) for k in range(n)] + [(12.0 * (1 - abs(y) / 100.0), float(y))
                                                          for y in range(-100, 101, 4)]
    pts += [(4.0 * k, 100.0) for k in range(1, n + 1)]
    a = np.asarray(pts)
    origin, scale = a.mean(axis=0), float(np.abs(a - a.mean(axis=0)).max())
    found = Recognition("polyline", 0.7, Polyline(((arm, -100.0), (0.0, -100.0), (0.0, 100.0), (arm, 100.0))))
    return dented_spines.kept_bracket(found, (a - origin) / scale, 1.0 / scale, None, (origin, scale))


def test_a_spine_no_longer_than_its_arms_is_a_braces_half() -> None:
    """Session 29 (wt-marks): a brace the rules cut at its point and at one curl makes one half its "spine" and the
    other an "arm" as long (`brace_habits`' wide chevron through the tiny mouse, held seed 1024, kept on main 821c642):
    a spine under `dented_spines.SPINE_OVER_ARM` times its longer arm is not kept; a bracket's spine 1.7 times its arms
    and more is."""
    assert _kept_with_arms(80.0) and _kept_with_arms(120.0)
    assert not _kept_with_arms(160.0) and not _kept_with_arms(200.0)


HCIRA = "public-sets/hcira.jsonl"
PEOPLE = {
    (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/left square bracket5.xml"): "polyline",
    (HCIRA, "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s02/left_square_bracket1.xml"): "polyline",
    (HCIRA, "hat359/HCIRA@69a6542:xml_collected_logs/user2/right_curly_brace03.xml"): "curve",
    (HCIRA, "hat359/HCIRA@69a6542:xml_collected_logs/user2/right_curly_brace09.xml"): "curve",
    (HCIRA, "shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/MousePad/s05/right_curly_brace10.xml"):
        "curve",
}
"""(cached set, file) -> the kind a reader names: the two brackets with a bump in the spine (curves on main 0ca43a2),
and the three right braces whose rules' polyline of four vertices the ranker rightly re-reads (a point turning with
the curls; a brace cut at its point, a half longer than the spine)."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.split("/")[-1] for _, f in PEOPLE])
def test_a_persons_bumped_bracket_reads_as_a_bracket_and_a_brace_as_a_brace(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]
