"""Issue 25: a straight line as people draw it reads as a line (`recognition.lines`): a short line whose hook where the
pen landed or lifted is a large share of it, or whose slow tremor strays a few pixels, drawn by the pen models
(`benchmarks/bench_lines.py`: the careful virtual pen, the hurried hand, the slow shaky hand), becomes a line body
through a whole session (journal -> replay -> project), and an arc of 40-90 degrees drawn on purpose stays a rope (the
session's arc or curve), never a line body; on the benchmark's tuning seeds lines and arcs read so at least as often as
measured here."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import numpy as np
import pytest
from drawn_strokes import body_shapes
from penmodels.journal import header as hurried_header
from scenarios.thesis import DEVICE, MAPPING
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.formats.journal.entries import JournalEntry, JournalHeader, PenEntry
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition import lines

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_lines import HELD_SEEDS, TUNING_SEEDS, habits_of, hurried_reports, read, shape

LINES = [
    ("straight", "shaky", 11),  # 25 px, a slow tremor (a curve at main 0da4e5c)
    ("straight", "shaky", 15),  # 41 px, a slow tremor (a curve)
    ("hooked", "careful", 5),  # 19 px, a hook where the pen landed (a polyline)
    ("hooked", "careful", 10),  # 17 px, a hook where the pen landed (an arc)
    ("hooked", "hurried", 5),  # 19 px, a hook where the pen landed (a polyline)
    ("hooked", "hurried", 6),  # 30 px, a hook where the pen landed (a curve)
    ("hooked", "hurried", 10),  # 17 px, a hook where the pen landed (a curve)
    ("hooked", "shaky", 1),  # 37 px, a slow tremor and a hook where the pen lifted (a curve)
    ("hooked", "shaky", 10),  # 17 px, a slow tremor and a hook where the pen landed (a curve)
    ("bowed", "shaky", 22),  # 37 px, bowed 2 %, a slow tremor (a curve)
    ("bowed", "shaky", 29),  # 35 px, bowed 3.8 %, a slow tremor (a curve)
]
"""(family, pen, tuning seed) of `bench_lines`: lines the benchmark read otherwise at main 0da4e5c (in brackets)."""
ARCS = [
    ("arc", "careful", 7), ("arc", "careful", 12), ("arc", "careful", 21),  # 66, 89 and 65 degrees
    ("arc", "hurried", 10),  # 46 degrees with a hook where the pen landed: a swung line at main 0da4e5c
    ("arc", "hurried", 27),  # 45 degrees with a hook where the pen landed: a curve then and now
]
"""Arcs of 40-90 degrees drawn on purpose (`bench_lines.shape`'s arc family)."""


def _journal(family: str, pen: str, seed: int) -> tuple[JournalHeader, list[JournalEntry]]:
    """The ``family``'s stroke of ``seed`` drawn by ``pen`` as a journal; the pen leaves range and the session goes
    on 3 s after it lifts."""
    keys, _ = shape(family, seed)
    if pen == "careful":
        w, h = MAPPING.canvas_width, MAPPING.canvas_height
        capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record([Stroke(tuple((x / w, y / h)
                                                                                        for x, y in keys))])
        return header_for_capture(capture, MAPPING), capture_entries(capture)
    reports = hurried_reports(keys, seed, habits_of(pen, family))
    entries: list[JournalEntry] = [_pen_entry(r) for r in reports]
    entries.append(PenEntry(round(entries[-1].t + 3.0, 6), 0.95, 0.95, 0.0, False, False, False, False, False))
    return hurried_header(), entries


def _session(case: tuple[str, str, int], tmp_path) -> tuple[list[str], int, str]:
    """The bodies' shapes (a line's body is a polyline of two points: "line"), the number of ropes and the messages of
    the session ``case`` is drawn in."""
    folder = tmp_path / "-".join(map(str, case))
    folder.mkdir()
    project, told = replayed_project(*_journal(*case), folder)
    ropes = [c for c in project.scene.components.values() if type(c).__name__ == "Rope"]
    return body_shapes(project), len(ropes), told


@pytest.mark.parametrize("case", LINES, ids=[f"{f}-{p}-{s}" for f, p, s in LINES])
def test_a_line_as_people_draw_it_becomes_a_line_body(case, tmp_path) -> None:
    shapes, ropes, told = _session(case, tmp_path)
    assert shapes == ["line"] and ropes == 0, f"{case}: bodies {shapes}, {ropes} ropes\n{told}"


@pytest.mark.parametrize("case", ARCS, ids=[f"{f}-{p}-{s}" for f, p, s in ARCS])
def test_an_arc_drawn_on_purpose_is_no_line_body(case, tmp_path) -> None:
    shapes, ropes, told = _session(case, tmp_path)
    assert shapes == [] and ropes == 1, f"{case}: bodies {shapes}, {ropes} ropes\n{told}"


READ_FLOORS = {
    ("straight", "careful"): 60, ("straight", "hurried"): 60, ("straight", "hurried-coarse"): 60,
    ("straight", "shaky"): 44,
    ("hooked", "careful"): 60, ("hooked", "hurried"): 58, ("hooked", "hurried-coarse"): 54, ("hooked", "shaky"): 54,
    ("bowed", "careful"): 60, ("bowed", "hurried"): 60, ("bowed", "hurried-coarse"): 60, ("bowed", "shaky"): 48,
    ("short-hooked", "careful"): 56, ("short-hooked", "hurried"): 56, ("short-hooked", "hurried-coarse"): 54,
    ("short-hooked", "shaky"): 34,
}
"""(family, pen) -> how many of the 60 readings (30 tuning seeds, with and without times) are lines, measured on this
branch; main 0da4e5c: straight 60, 60, 60, 40; hooked 50, 50, 48, 48; bowed 60, 60, 60, 40; short-hooked (lines
25-90 px hooked at both ends, session 25) at main 2ff28bf 44, 42, 46, 34. Session 26 (wt-ends: `lines.unhooked` cuts
both ends where both are hooks) raised short-hooked from 44, 44, 46, 34 (main 7111cdc) and hooked careful from 58."""
ARC_AS_LINE_CEILING = {"careful": 0, "hurried": 2, "hurried-coarse": 2, "shaky": 0}
"""pen -> of the 38 readings of the 19 tuning arcs swept 40-90 degrees, how many may read as lines: measured on this
branch (main 0da4e5c: 0, 4, 6, 0; the hurried hand's small hook at an end made a circle miss the arc, which was then
taken for a swung line). The rest are arcs, or curves where the hand's hook or tremor breaks the arc test."""


@pytest.mark.parametrize(("family", "pen"), list(READ_FLOORS))
def test_lines_drawn_by_the_pen_models_read_as_lines(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed)[0] for seed in TUNING_SEEDS for timed in (True, False)]
    assert sum(k == "line" for k in got) >= READ_FLOORS[(family, pen)], got


def test_a_short_hooked_line_through_a_coarse_device_stays_a_line() -> None:
    """A 46 px line hooked at both ends, drawn by the hurried hand through a coarse device (held seed 1010): the circle
    misses what the hooks left of its bow by under `open_marks.SWUNG_WOBBLE` (session 24 read it a polyline, 40b8114 a
    line); a line misses it as closely and an end curls as a hook does, so it is a line
    (`open_marks.hooked_straight`)."""
    assert [read("hooked", "hurried-coarse", 1010, timed)[0] for timed in (True, False)] == ["line", "line"]


SHORT_HOOKED_HELD_FLOORS = {"careful": 58, "hurried": 44, "hurried-coarse": 40, "shaky": 22}
"""pen -> how many of the 60 readings of `bench_lines`' short-hooked family (lines 25-90 px hooked at both ends; held
seeds 1000-1029, with and without times) are lines, measured once on this branch (main 7111cdc: 44, 38, 38, 22; both
ends' hooks cut at once where both are hooks, `lines.unhooked`, session 26). The rest are polylines (a hook standing
square off one side as a bracket's arm does, or through a coarse device) and, by the slow shaky hand, curves (its
tremor strays farther than the pen's stated noise allows, as its straight lines' do)."""


@pytest.mark.parametrize("pen", list(SHORT_HOOKED_HELD_FLOORS))
def test_short_lines_hooked_at_both_ends_read_as_lines_on_the_held_seeds(pen: str) -> None:
    got = [read("short-hooked", pen, seed, timed)[0] for seed in HELD_SEEDS for timed in (True, False)]
    assert sum(k == "line" for k in got) >= SHORT_HOOKED_HELD_FLOORS[pen], got


def test_a_short_line_hooked_at_both_ends_by_the_hurried_hand_becomes_a_line_body(tmp_path) -> None:
    """`bench_lines`' short-hooked tuning seed 22 by the hurried hand (34.5 px; main 2ff28bf: a curve): a line body
    through a whole session, as a reader sees it."""
    shapes, ropes, told = _session(("short-hooked", "hurried", 22), tmp_path)
    assert shapes == ["line"] and ropes == 0, f"bodies {shapes}, {ropes} ropes\n{told}"


@pytest.mark.parametrize("pen", list(ARC_AS_LINE_CEILING))
def test_arcs_of_40_degrees_and_more_are_no_lines(pen: str) -> None:
    seeds = [s for s in TUNING_SEEDS if _sweep(s) >= 40.0]
    got = [read("arc", pen, seed, timed)[0] for seed in seeds for timed in (True, False)]
    assert sum(k == "line" for k in got) <= ARC_AS_LINE_CEILING[pen], got


def _sweep(seed: int) -> float:
    """The arc family's sweep of ``seed``, degrees (`bench_lines.shape` draws the turn, the centre, the chord, then
    it)."""
    rng = random.Random(f"lines:arc:{seed}")
    for _ in range(3):
        rng.uniform(0.0, 1.0)
    rng.uniform(40.0, 500.0)
    return rng.uniform(20.0, 90.0)


def test_the_pens_wobble_reaches_farther_than_its_spread_and_a_circle_tells_a_bow() -> None:
    assert 2.7 < lines.wobble_reach(48) < lines.wobble_reach(160) < 3.3
    arc = np.column_stack([np.sin(np.linspace(-0.35, 0.35, 60)), np.cos(np.linspace(-0.35, 0.35, 60))]) * 60
    assert lines.circular_bow(arc)
    wobble = np.column_stack([np.linspace(0, 40, 60), 1.5 * np.sin(np.linspace(0, 3 * np.pi, 60))])
    assert not lines.circular_bow(wobble)
