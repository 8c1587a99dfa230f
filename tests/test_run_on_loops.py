"""A circle the pen landed on and ran on past its start as a tail reads as its loop (issue 25, session 41: the `sign`
set's ST5022 writers writer1010 and writer001, `run_on_loops`); a pigtail (the people's, the pen models' round-loop and
loop-first ones), a spiral and a 6 do not.

The people's strokes are read from the local cache (`~/.cache/physink/public-sets/`, as `test_open_marks.py` reads the
public sets) and skip without it, saying so.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from penmodels import pigtail_habits
from sign_rows import assert_body_through_a_session, assert_read_as, sign_id, sign_row
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import run_on_loops
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

RUN_ON = [
    "writer1010/sessionA/circle_left-1-13.json",  # crossing its start, a tail 10 % of the path
    "writer1010/sessionA/circle_left-1-14.json",  # landed with a small hook, passing within a pen's width of it
    "writer1010/sessionB/circle_left-1-21.json",  # landed with a lead-in, crossing it, a tail 15 %
    "writer1010/sessionC/circle_right-1-0.json",  # drawn the other way, passing its start a little outside
    "writer001/sessionC/circle_left-1-3.json",
]
"""ST5022 writers' circles read as curves at main 261f2a7."""


@pytest.mark.parametrize("file", RUN_ON, ids=[sign_id(f) for f in RUN_ON])
def test_a_writers_circle_run_on_past_its_start_is_an_ellipse(file: str) -> None:
    assert_read_as(sign_row(file), "ellipse")


def test_a_writers_run_on_circle_is_an_ellipse_body_through_a_session(tmp_path) -> None:
    """The person's stroke drawn 300 px across by the careful virtual pen through the thesis device, journal ->
    replay -> project: one round body."""
    assert_body_through_a_session(sign_row(RUN_ON[0]), "ellipse", tmp_path)


PIGTAILS = [
    "klarubbio/hcira_p1@e8eb332:xml/s02/pigtail04.xml",  # drawn loop first, the tail 1.75 half-lengths off the loop
    "klarubbio/hcira_p1@e8eb332:xml/s06/pigtail09.xml",  # a round loop holding 0.74 of the path, between two tails
    "klarubbio/hcira_p1@e8eb332:xml/s01 (pilot)/pigtail06.xml",  # a narrow loop holding 0.78 of it
]
"""The design sets' pigtails nearest a run-on circle: a curve each."""


@pytest.mark.parametrize("file", PIGTAILS, ids=[f.rsplit("xml/", 1)[-1] for f in PIGTAILS])
def test_a_persons_pigtail_stays_a_curve(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, f"{file} is not in public-sets/hcira.jsonl"
    assert recognize_stroke(*_stroke(row)).kind == "curve"


def _judged(points: np.ndarray) -> np.ndarray:
    """``points`` at unit size, evenly resampled and smoothed as `recognize` judges a stroke (128 points)."""
    unit = (points - points.mean(axis=0)) / float(np.abs(points - points.mean(axis=0)).max())
    return sg.smooth(sg.resample(unit, 128))


def _run_on(loop: np.ndarray, diag_share: float = 0.003) -> np.ndarray | None:
    work = _judged(loop)
    diag = sg.bbox_diagonal(work)
    return run_on_loops.run_on_loop(work, diag, diag_share * diag)


@pytest.mark.parametrize("family", ["round-loop-pigtail", "loop-first-pigtail"])
def test_the_rule_reads_no_pen_model_pigtail_otherwise(family: str, monkeypatch) -> None:
    """Every tuning seed's round-loop pigtail (tails of 0.05-0.25 pi of the phase past a shallow crossing) and
    loop-first pigtail (a tail of 1.6-3 half-lengths) is read as it is without the rule. Not because the rule tells
    them apart: judged alone, the round-loop ones hold 0.76-0.84 of the path in their round loops, as the run-on circles
    do; where they hold 0.8 or more the closed-stroke rules read them first (round, as main did)."""
    marks = [pigtail_habits.FAMILIES[family](seed).points for seed in range(30)]
    with_rule = [recognize_stroke(list(points)).kind for points in marks]
    monkeypatch.setattr(run_on_loops, "run_on_loop", lambda *_: None)
    assert [recognize_stroke(list(points)).kind for points in marks] == with_rule


def _circle_run_on(tail_share: float, lead_share: float = 0.0, r: float = 100.0) -> np.ndarray:
    """A circle of radius ``r`` (points 2 px apart) from a lead ``lead_share`` of the path long, coming in along the
    rim's tangent, round once and on past its start along the tangent for ``tail_share`` of the path."""
    rim = 2 * math.pi * r
    tail = tail_share * rim / (1 - tail_share - lead_share)
    lead = lead_share * rim / (1 - tail_share - lead_share)
    phi = np.linspace(0.0, 2 * math.pi, int(rim / 2))
    circle = np.column_stack([r * np.sin(phi), r - r * np.cos(phi)])  # from (0, 0) heading +x, round anticlockwise
    ins = np.column_stack([np.arange(-lead, 0.0, 2.0), np.zeros(len(np.arange(-lead, 0.0, 2.0)))])
    outs = np.column_stack([np.arange(2.0, tail, 2.0), np.zeros(len(np.arange(2.0, tail, 2.0)))])
    return np.vstack([ins, circle, outs]) + 300.0


@pytest.mark.parametrize(("tail", "lead", "round_"), [
    (0.15, 0.0, True),  # landed on the rim, ran on past its start along the tangent for 15 % of the path
    (0.12, 0.05, True),  # a short lead-in too
    (0.3, 0.0, False),  # a tail of 30 %: a loop-first pigtail's
    (0.12, 0.12, False),  # both ends leave the loop: a pigtail's tails
])
def test_a_circle_run_on_along_its_tangent(tail: float, lead: float, round_: bool) -> None:
    pts = _circle_run_on(tail, lead)
    assert (_run_on(pts) is not None) == round_
    assert (recognize_stroke(pts.tolist()).kind in ("circle", "ellipse")) == round_


def _spiral(laps: float, inner: float = 30.0, outer: float = 120.0) -> np.ndarray:
    """An Archimedean spiral from radius ``inner`` out to ``outer`` over ``laps`` turns (points about 2 px apart)."""
    theta = np.linspace(0.0, 2 * math.pi * laps, int(math.pi * (inner + outer) * laps))
    r = inner + (outer - inner) * theta / theta[-1]
    return np.column_stack([r * np.cos(theta), r * np.sin(theta)]) + 300.0


@pytest.mark.parametrize("laps", [1.3, 2.0, 3.0])
def test_a_spiral_is_no_run_on_loop(laps: float, monkeypatch) -> None:
    """No lap of a spiral comes back to within `MEETS` of where it began with most of the path: the rule reads none of
    them otherwise (a lap and a third or two laps out from a third of the radius are read round as at main 261f2a7,
    by the closed-stroke rules; three laps are a curve)."""
    pts = _spiral(laps)
    assert _run_on(pts) is None
    read = recognize_stroke(pts.tolist()).kind
    monkeypatch.setattr(run_on_loops, "run_on_loop", lambda *_: None)
    assert recognize_stroke(pts.tolist()).kind == read
    assert laps < 3.0 or read == "curve"


def test_a_six_is_no_run_on_loop() -> None:
    """A 6: a straight stem down into a round loop (tangent to it), round 288 degrees and straight on into the stem,
    meeting it 72 degrees off its heading (`SAME_WAY_DEG`), where the pen lifts; the loop holds 0.84 of the path."""
    r = 60.0
    stem = np.column_stack([np.full(80, -r), np.linspace(2 * r, 0.0, 80)])  # heading -y onto the rim at (-r, 0)
    phi = np.linspace(math.pi, 2.6 * math.pi, 240)
    rim = np.column_stack([r * np.cos(phi), r * np.sin(phi)])
    close = np.linspace(rim[-1], [-r, 0.72 * r], 30)
    six = np.vstack([stem, rim[1:], close[1:]]) + 300.0
    measured = run_on_loops.measure(_judged(six), 0.003)
    assert measured is not None and measured.on_loop <= run_on_loops.ON_LOOP
    assert _run_on(six) is None
