"""Issue 25, session 36 (wt-bracket): the people's strokes that bound any rule reading a circle gone round past its
start and run on out of the loop (the `sign` set's Tablet PC circles, left read as curves: docs/BENCHMARKS.md,
"Circles run on past their start") stay what they are: the design group's pigtails with the shortest tails and dollar1
s04's question mark curled nearly round are curves.

People's strokes are read from ../shared/data and the caches `benchmarks/public_sets.py` and
`benchmarks/student_sets.py` write; without a cache that test skips, saying so.
"""

from __future__ import annotations

import json

import pytest
from shared_data import shared_path
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.recognize import recognize_stroke

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
    """dollar1 s04's medium question mark 10: its hook and curl turn 1.73 pi once the stem is cut, as far as a circle
    run on past its start, but leave the loop open by half its length."""
    rows = [json.loads(line) for line in shared_path("strokes", "dollar1-dev.jsonl").read_text().splitlines()]
    row = next(r for r in rows if r["file"] == "s04/medium/question_mark10.xml")
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind == "curve"
