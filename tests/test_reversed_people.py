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

DOLLAR1_ALIKE = 1439
"""Of the 1,440 strokes of the $1 people, how many read the same kind reversed: 1,436 at main 3b9e40f (three circles
a circle one way and an ellipse the other, both right: once round from where the pen landed), 1,439 since a loop gone
round more than once is a circle or an ellipse as both its laps tell it (`both_laps`, session 32); left: a question
mark a curve as drawn, a polyline reversed (the learned ranker's corner roundness and bends lean with direction, and
measuring them alike without refitting the ranker lost two people's readings as drawn, docs/BENCHMARKS.md)."""
HCIRA_LABELS = ("rectangle", "triangle", "left_curly_brace", "right_curly_brace")
"""hcira's labels where its reversed readings differed at 3b9e40f in another kind than a circle's or an ellipse's
(both right for a circle; its stars and pigtails differ only by lifts the device missed), 610 strokes each."""
HCIRA_ALIKE = 2427
"""Of hcira's 2,440 strokes of `HCIRA_LABELS`, how many read the same kind reversed: 2,424 at main 3b9e40f, 2,426 since
the ranker's zig-zag teeth are asked of both vertex orders (`BRACES`), 2,427 since a polygon left open may bow its
first side as its last (`closed_loops.LAST_SIDE_BOW`, session 31: klarubbio s06 triangle03). Of the 13 left, 9 are
shriyansnidhish's boxes and triangles holding a lift the device missed (`pen_lifts`: read by the last attempt, which
is another attempt reversed, meant to hang on the time order); a box, a triangle and 2 braces read at a rule's
threshold one way (a box or a polygon, closed or open, a curve or a polyline)."""


def _alike(rows: list[dict]) -> int:
    return sum(len(set(readings(r))) == 1 for r in rows if len(r["strokes"]) == 1)


def test_the_dollar1_people_read_alike_drawn_either_way() -> None:
    assert _alike(people_rows()) >= DOLLAR1_ALIKE


def test_hcira_shapes_and_braces_read_alike_drawn_either_way() -> None:
    rows = [r for r in cached_rows("public-sets/hcira.jsonl").values() if r["label"] in HCIRA_LABELS]
    assert _alike(rows) >= HCIRA_ALIKE


BRACES = ["klarubbio/hcira_p1@e8eb332:xml/s06/left_curly_brace09.xml",
          "pixelfac/hcira-project-23@80d4cc7:src/dataset/user04/left curly brace10.xml"]
"""hcira braces a curve as drawn and a polyline reversed at 3b9e40f: reversed, the rules' polyline of each had a
zig-zag's teeth (`open_marks.sawtooth_vertices` compares a tooth's side with the one two before it, so one order
weighs the side leading into the teeth, the other the side leading out), and the ranker was not asked."""


@pytest.mark.parametrize("file", BRACES, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1] for f in BRACES])
def test_a_persons_brace_is_a_curve_drawn_either_way(file: str) -> None:
    row = cached_rows("public-sets/hcira.jsonl").get(file)
    assert row is not None, file
    assert readings(row) == ("curve", "curve")
    points = [p[:2] for p in row["strokes"][0]]
    assert recognize_stroke(points[::-1]).kind == "curve"


HCIRA, ITT_MORE = "public-sets/hcira.jsonl", "public-sets/itt-more.jsonl"
OVERDRAWN_CIRCLES = [(HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user03/circle5.xml"),
                     (HCIRA, "pixelfac/hcira-project-23@80d4cc7:src/dataset/user06/circle2.xml"),
                     (HCIRA, "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User05/circle07.xml"),
                     (ITT_MORE, "ITT23/assignment-06-gesture-recognition-sina-sch@8c0dbdb:dataset/circle09.xml")]
"""People's circles drawn on past their start, a circle one way and an ellipse the other until session 32: their lap
from the start and their lap to the end are 0.71-0.86 wide for their length, on either side of
`beautify.CIRCLE_RATIO`; both laps are asked alike now (`both_laps`)."""


@pytest.mark.parametrize("where,file", OVERDRAWN_CIRCLES, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1]
                                                              for _, f in OVERDRAWN_CIRCLES])
def test_a_persons_circle_drawn_on_past_its_start_reads_alike_either_way(where: str, file: str) -> None:
    row = cached_rows(where).get(file)
    assert row is not None, file
    ahead, back = readings(row)
    assert ahead == back and ahead in ("circle", "ellipse"), (ahead, back)


@pytest.mark.parametrize("label", ["rectangle", "triangle"])
def test_a_persons_shape_drawn_backwards_becomes_the_same_body(label: str) -> None:
    """A Session given a person's stroke and the same stroke from its other end makes the same body (every 4th stroke
    of the label, `test_people_strokes.sample`): the full pipeline, pen events to the scene."""
    for i, row in sample(label)[::3]:
        points = placed(row, size_of(i))
        shapes = [[b.shape for b in drawn(p).scene.bodies()] for p in (points, points[::-1])]
        assert shapes[0] == shapes[1], f"{row['file']}: {shapes[0]} as drawn, {shapes[1]} reversed"
