"""Issue 25: square brackets are polylines and curly braces curves, however a hand rounds or straightens them. A
bracket whose two corners are rounded off (`recognition.round_brackets`) and a brace drawn as straight runs between
cusps, as a mouse draws one (`recognition.angular_braces`), drawn by both pen models (the careful virtual pen and the
hurried hand of `tests/penmodels`, also through a coarse device and a mouse), read as the kind people's labels say,
through a whole session (journal -> replay -> project) and on `benchmarks/bench_open_marks.py`'s tuning seeds (0-29);
braces, question marks, pigtails and sharp brackets stay as they were read. People's strokes the two rules read right
are named (public-set caches, design sources only; they skip without the caches)."""

from __future__ import annotations

import itertools
import math
import random
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.open_marks import EXPECTED, FAMILIES, Mark
from penmodels.shapes import Curve
from penmodels.shapes import Path as PenPath
from scenarios.thesis import DEVICE, MAPPING
from test_open_marks import _stroke, cached_rows
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.components import Rope
from physink_tui.scene.recognition import angular_braces, round_brackets
from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_open_marks import TUNING_SEEDS, read

FLOORS = {
    ("rounded-bracket", "careful"): 60, ("rounded-bracket", "hurried"): 60,
    ("rounded-bracket", "hurried-coarse"): 60, ("rounded-bracket", "hurried-mouse"): 60,
    ("angular-brace", "careful"): 56, ("angular-brace", "hurried"): 54,
    ("angular-brace", "hurried-coarse"): 58, ("angular-brace", "hurried-mouse"): 54,
    ("bracket", "careful"): 60, ("bracket", "hurried"): 60, ("bracket", "hurried-coarse"): 60,
    ("bracket", "hurried-mouse"): 60,
    ("brace", "careful"): 60, ("brace", "hurried"): 60, ("brace", "hurried-coarse"): 60, ("brace", "hurried-mouse"): 60,
    ("question", "careful"): 60, ("question", "hurried"): 60, ("question", "hurried-coarse"): 60,
    ("question", "hurried-mouse"): 54,
    ("pigtail", "careful"): 60, ("pigtail", "hurried"): 60, ("pigtail", "hurried-coarse"): 60,
    ("pigtail", "hurried-mouse"): 60,
}
"""(family, pen) -> how many of the 60 readings (30 tuning seeds, with and without times) are the family's kind
(`penmodels.open_marks.EXPECTED`), measured on this branch. Main 0da4e5c read rounded brackets 52, 46, 44 and 44 (the
rest curves) and angular braces 28, 40, 44 and 44 (the rest polylines); the other families as here. The careful pen's
angular braces rose from 54 to 56 when a brace was also laid out against its arms' own line
(`angular_braces._arms_layout`). The rounded
brackets the hurried hand drew that were still read as curves (52 and 54) had a landing or lifting hook just before a
rounded corner, which the stroke's hook cut keeps: judged without it (`round_brackets._hook`, session 21) all 60 read
as brackets; the angular braces still read as polylines have curls longer than their arms; the question marks drawn
with a mouse and read as polylines have a hook a few pixels across on a straight stem (a 7)."""


@pytest.mark.parametrize(("family", "pen"), list(FLOORS))
def test_open_marks_drawn_by_the_pen_models_read_as_their_kind(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed) for seed in TUNING_SEEDS for timed in (True, False)]
    assert sum(k == EXPECTED[family] for k in got) >= FLOORS[(family, pen)], got


def _journal(pen: str, mark: Mark, seed: int) -> tuple[JournalHeader, list[JournalEntry]]:
    """One stroke along ``mark`` by the hurried hand or the careful virtual pen, as a session's journal."""
    if pen == "hurried":
        shape = Curve(mark.points) if mark.smooth else PenPath(mark.points)
        return hurried_header(), [_pen_entry(r) for r in HurriedPen(random.Random(seed)).draw(shape, 0.3)[0]]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record(
        [Stroke(tuple((x / w, y / h) for x, y in mark.points))])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


SESSION_SEEDS = range(8)
SESSION_FLOORS = {("rounded-bracket", "hurried"): 7, ("rounded-bracket", "virtual"): 8,
                  ("angular-brace", "hurried"): 8, ("angular-brace", "virtual"): 7}
"""(family, pen) -> of the marks of seeds 0-7, how many a session makes what the family's kind makes (a polyline body
for a bracket, a rope for a brace), measured on this branch; main 0da4e5c made 6, 6, 5 and 2."""


def _made(project) -> str:
    """What a session made of one stroke: ``polyline`` (one polyline body), ``curve`` (one rope), else a list."""
    bodies = project.scene.bodies()
    ropes = [c for c in project.scene.components.values() if isinstance(c, Rope)]
    if len(bodies) == 1 and not ropes:
        return bodies[0].shape
    if len(ropes) == 1 and not bodies:
        return "curve"
    return repr([(b.id, b.shape) for b in bodies] + [r.id for r in ropes])


@pytest.mark.parametrize(("family", "pen"), list(SESSION_FLOORS))
def test_a_bracket_or_a_brace_becomes_its_kind_through_a_session(family: str, pen: str, tmp_path) -> None:
    made = []
    for seed in SESSION_SEEDS:
        folder = tmp_path / str(seed)
        folder.mkdir()
        project, _ = replayed_project(*_journal(pen, FAMILIES[family](seed), seed), folder)
        made.append(_made(project))
    assert sum(m == EXPECTED[family] for m in made) >= SESSION_FLOORS[(family, pen)], made


def _rounded_bracket(radius: float) -> np.ndarray:
    """A bracket 200 tall with arms 80 long, both corners rounded off with ``radius`` (a quarter circle each)."""
    pts = [(80.0 - k * (80.0 - radius) / 10, -100.0) for k in range(11)]
    pts += [(radius - radius * math.sin(a), -100.0 + radius - radius * math.cos(a))
            for a in np.linspace(0, math.pi / 2, 12)[1:]]
    pts += [(0.0, -100.0 + radius + k * (200.0 - 2 * radius) / 20) for k in range(1, 21)]
    pts += [(radius - radius * math.cos(a), 100.0 - radius + radius * math.sin(a))
            for a in np.linspace(0, math.pi / 2, 12)[1:]]
    pts += [(radius + k * (80.0 - radius) / 10, 100.0) for k in range(1, 11)]
    return np.asarray(pts) / 200.0


def _judged(pts: np.ndarray) -> tuple[np.ndarray, list[float]]:
    from physink_tui.scene.recognition import stroke_geometry as sg
    work = sg.resample(pts, 128)
    return work, sf.lobes(work)


def test_a_bracket_with_both_corners_rounded_has_its_corners_where_its_sides_meet() -> None:
    found = round_brackets.rounded_bracket(*_judged(_rounded_bracket(40.0)))
    assert found is not None
    corners = np.asarray(found[1:3]) * 200.0
    assert np.allclose(corners, [(0.0, -100.0), (0.0, 100.0)], atol=6.0), corners


def test_a_parenthesis_a_u_and_a_question_mark_are_no_rounded_bracket() -> None:
    half = np.linspace(-math.pi / 2, math.pi / 2, 100)
    paren = np.column_stack([-np.cos(half), np.sin(half)])  # a semicircle
    u = np.vstack([[(-1.0, -1.0 + k / 10) for k in range(10)],
                   np.column_stack([-np.cos(half + math.pi / 2), np.sin(half + math.pi / 2)]),
                   [(1.0, -k / 10) for k in range(1, 11)]])  # straight sides, one round bottom
    hook = np.linspace(math.pi, math.pi + math.radians(250), 60)
    question = np.vstack([np.column_stack([np.cos(hook), np.sin(hook)]),
                          [(math.cos(hook[-1]), math.sin(hook[-1]) + k / 8) for k in range(1, 17)]])
    for pts in (paren, u, question):
        assert round_brackets.rounded_bracket(*_judged(pts)) is None


def _polyline(vertices: list[tuple[float, float]]) -> np.ndarray:
    dense = [np.linspace(a, b, 20, endpoint=False) for a, b in itertools.pairwise(vertices)]
    return np.vstack([*dense, [vertices[-1]]]) / 200.0


BRACE = [(40.0, -100.0), (0.0, -80.0), (0.0, -15.0), (-45.0, 0.0), (0.0, 15.0), (0.0, 80.0), (40.0, 100.0)]
"""A left brace drawn as straight runs (y down): a curl, an arm, out to the point and back, an arm, a curl."""


def test_a_brace_of_straight_runs_is_a_brace_and_a_v_a_bracket_and_a_zigzag_are_not() -> None:
    assert angular_braces.angular_brace(*_judged(_polyline(BRACE)))
    hooked_v = [(10.0, -95.0), (0.0, -100.0), (-60.0, 0.0), (0.0, 100.0), (10.0, 95.0)]
    bracket = [(40.0, -100.0), (0.0, -100.0), (0.0, 100.0), (40.0, 100.0)]
    zigzag = [(0.0, -100.0), (-40.0, -50.0), (0.0, 0.0), (-40.0, 50.0), (0.0, 100.0)]
    for vertices in (hooked_v, bracket, zigzag):
        assert not angular_braces.angular_brace(*_judged(_polyline(vertices))), vertices


def test_a_brace_of_straight_runs_reads_as_a_curve_turned_any_way() -> None:
    for angle in range(0, 360, 30):
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        pts = _polyline(BRACE) * 200.0 @ np.array([[c, s], [-s, c]]) + (800.0, 500.0)
        for learned in (False, True):
            assert recognize_stroke(pts.tolist(), learned=learned).kind == "curve", (angle, learned)


HCIRA = "public-sets/hcira.jsonl"
PEOPLE = {
    (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/left square bracket3.xml"): "polyline",
    (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user01/right square bracket4.xml"): "polyline",
    (HCIRA, "klarubbio/hcira_p1@e8eb332:xml/s02/left_square_bracket08.xml"): "polyline",
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-marcel-moz@5404f89:02-recognizer-comparison/"
                               "datasets/left_curly_brace08.xml"): "curve",
}
"""(cached set, file) -> the kind a reader names: brackets with both corners rounded off (hcira: pixelfac's user01,
klarubbio's s02) and a brace drawn as straight runs (itt: marcel-moz's left brace 08), each misread by the recogniser
at main 0da4e5c."""


@pytest.mark.parametrize(("name", "file"), list(PEOPLE), ids=[f.split("/")[-1] for _, f in PEOPLE])
def test_a_persons_rounded_bracket_or_straight_run_brace_is_read_as_what_it_is(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times, learned=False).kind == PEOPLE[(name, file)]
    assert recognize_stroke(points, times).kind == PEOPLE[(name, file)]
