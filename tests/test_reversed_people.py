"""People's strokes read as the same kind drawn from their other end (issue 25, session 30): a person may start a
shape anywhere and go either way round, so a stroke's points and times reversed should read as drawn.

Counts of the design strokes that read alike both ways (`benchmarks/bench_reversed.py`, which reads every design
set), held as floors: the $1 people (``../shared/data``, `test_people_strokes.people_rows`; the tests skip without it)
and the cached hcira set's shapes that go round and its braces (`test_open_marks.cached_rows`: skips without the
cache). A floor rises with the figure, never falls. Then the same through a Session: a person's box and triangle drawn
backwards become the same body.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from test_open_marks import cached_rows
from test_people_strokes import drawn, people_rows, placed, sample, size_of

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_reversed import readings

DOLLAR1_ALIKE = 1438
"""Of the 1,440 strokes of the $1 people, how many read the same kind reversed: 1,436 at main 3b9e40f (three circles
a circle one way and an ellipse the other, both right; a question mark a curve as drawn, a polyline reversed, by the
learned ranker's corner roundness and bends, which leaned with direction); 1,438 since the ranker measures both alike
(the question mark a polyline both ways; two circles left: once round from where the pen landed)."""
HCIRA_LABELS = ("circle", "rectangle", "triangle", "star", "pigtail", "left_curly_brace", "right_curly_brace")
"""hcira's labels whose strokes go round or turn both ways: where its reversed readings differed at 3b9e40f."""
HCIRA_ALIKE = 4238
"""Of hcira's strokes of `HCIRA_LABELS`, how many read the same kind reversed (4,xxx of 4,270 at main 3b9e40f; the
rest mostly shriyansnidhish's strokes holding a lift the device missed, read by their last attempt, which is another
attempt reversed, and circles once round from where the pen landed)."""


def _alike(rows: list[dict]) -> int:
    return sum(len(set(readings(r))) == 1 for r in rows if len(r["strokes"]) == 1)


def test_the_dollar1_people_read_alike_drawn_either_way() -> None:
    assert _alike(people_rows()) >= DOLLAR1_ALIKE


def test_hcira_shapes_and_braces_read_alike_drawn_either_way() -> None:
    rows = [r for r in cached_rows("public-sets/hcira.jsonl").values() if r["label"] in HCIRA_LABELS]
    assert _alike(rows) >= HCIRA_ALIKE


BRACES = ["klarubbio/hcira_p1@e8eb332:xml/s06/left_curly_brace09.xml",
          "klarubbio/hcira_p1@e8eb332:xml/s07/pigtail05.xml",
          "pixelfac/hcira-project-23@80d4cc7:src/dataset/user04/left curly brace10.xml"]
"""hcira strokes a curve as drawn and a polyline reversed at 3b9e40f: the ranker's corner roundness and bends leaned
with direction (the brace09's polyline also had a zig-zag's teeth reversed only, so the ranker was not asked)."""


@pytest.mark.parametrize("file", BRACES, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1] for f in BRACES])
def test_a_persons_brace_and_pigtail_are_curves_drawn_either_way(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, file
    assert readings(row) == ("curve", "curve")
    points = [p[:2] for p in row["strokes"][0]]
    assert recognize_stroke(points[::-1]).kind == "curve"


@pytest.mark.parametrize("label", ["rectangle", "triangle"])
def test_a_persons_shape_drawn_backwards_becomes_the_same_body(label: str) -> None:
    """A Session given a person's stroke and the same stroke from its other end makes the same body (every 4th stroke
    of the label, `test_people_strokes.sample`): the full pipeline, pen events to the scene."""
    for i, row in sample(label)[::3]:
        points = placed(row, size_of(i))
        shapes = [[b.shape for b in drawn(p).scene.bodies()] for p in (points, points[::-1])]
        assert shapes[0] == shapes[1], f"{row['file']}: {shapes[0]} as drawn, {shapes[1]} reversed"
