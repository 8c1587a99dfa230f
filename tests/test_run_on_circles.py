"""Issue 25, session 36 (wt-bracket): a circle drawn with a Tablet PC pen that goes round past its start and runs on out
of the loop by a short tail (or lands outside it) is read by its loop (`recognition.round_cores.run_on_core`); people's
pigtails and question marks, whose tails are longer or whose curl does not close, stay curves.

People's strokes are read from ../shared/data and the caches `benchmarks/public_sets.py` and
`benchmarks/student_sets.py` write; without a cache that test skips, saying so.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from shared_data import shared_path
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition import round_cores
from physink_tui.scene.recognition import stroke_geometry as sg
from physink_tui.scene.recognition.recognize import recognize_stroke

ROUND = ("circle", "ellipse")
SIGN = "nmagrofuoco/Gester@cd24525:datasets/2D/SIGN/"
RUN_ON = (
    "writer001/sessionC/circle_left-1-3.json",
    "writer1010/sessionA/circle_left-1-13.json",
    "writer1010/sessionA/circle_right-1-14.json",
    "writer1010/sessionB/circle_left-1-21.json",
    "writer1010/sessionC/circle_right-1-0.json",
)
"""`sign` circles of the ST5022 writers read as curves at main 02d2055: round past the start and out by a tail of
0.03-0.12 of the path (one landing outside the loop, crossing it)."""


@pytest.mark.parametrize("file", RUN_ON)
def test_a_persons_circle_run_on_past_its_start_reads_round(file: str) -> None:
    row = cached_rows("public-sets/sign.jsonl").get(SIGN + file)
    assert row is not None, f"{file} is not in sign.jsonl"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind in ROUND


CURVES = (
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s01 (pilot)/pigtail01.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/pigtail09.xml"),
    ("student-sets/itt.jsonl", "ITT-26/assignment-06-gesture-recognition-lvht1203@925708d:datasets/logs_custom/"
                               "pigtail/pigtail06.xml"),
)
"""(cached set, file): the design group's pigtails with the shortest tails where the rest turns 1.6 pi and fits an
ellipse (0.20-0.22 of the path): curves."""


@pytest.mark.parametrize(("name", "file"), CURVES, ids=[f.rsplit("/", 1)[-1] for _, f in CURVES])
def test_a_persons_pigtail_with_short_tails_stays_a_curve(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == "curve"


def test_a_question_mark_curled_nearly_round_stays_a_curve() -> None:
    """dollar1 s04's medium question mark 10: its hook and curl turn 1.73 pi once the stem is cut, but leave the loop
    open by half its length (`round_cores.RUN_ON_GAP`)."""
    rows = [json.loads(line) for line in shared_path("strokes", "dollar1-dev.jsonl").read_text().splitlines()]
    row = next(r for r in rows if r["file"] == "s04/medium/question_mark10.xml")
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == "curve"


def _fits(ellipse: tuple) -> bool:
    return ellipse[4] < 0.05


def _arc(sweep_deg: float, start_deg: float = 0.0, n: int = 160) -> np.ndarray:
    a = np.radians(np.linspace(start_deg, start_deg + sweep_deg, n))
    return np.column_stack([np.cos(a), np.sin(a)])


def _run_off(loop: np.ndarray, length: float) -> np.ndarray:
    """``loop`` run on along its last heading by ``length``."""
    heading = loop[-1] - loop[-2]
    heading = heading / np.hypot(*heading)
    return np.vstack([loop, loop[-1] + np.linspace(0.0, length, 20)[1:, None] * heading])


def test_a_loop_run_on_out_by_a_short_tail_has_its_loop() -> None:
    work = sg.resample(_run_off(_arc(370.0), 0.6), 128)  # the tail about 0.08 of the path
    core = round_cores.run_on_core(work, _fits)
    assert core is not None
    centre, rx, ry, _, _ = core
    assert np.allclose(centre, (0.0, 0.0), atol=0.05) and abs(rx - 1.0) < 0.05 and abs(ry - 1.0) < 0.05


def test_a_loop_with_a_pigtails_long_tail_has_none() -> None:
    work = sg.resample(_run_off(_arc(370.0), 2.5), 128)  # the tail about 0.28 of the path
    assert round_cores.run_on_core(work, _fits) is None


def test_a_curl_that_does_not_close_has_none() -> None:
    """Round 300 degrees and off by a short tail: the curl turns too little and leaves its loop open."""
    work = sg.resample(_run_off(_arc(300.0), 0.6), 128)
    assert round_cores.run_on_core(work, _fits) is None
