"""A circle rounded off from a stroke's laps is asked alike from either end (issue 25, session 33): people's circles
that read one kind as drawn and another drawn from their other end read alike, and the count of hcira's circles and
arrows that read alike is held as a floor
(`benchmarks/bench_reversed.py` reads every design set; the tests skip without the cached sets).
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from test_open_marks import cached_rows

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_reversed import readings

HCIRA = "public-sets/hcira.jsonl"
ALIKE = [
    (HCIRA, "sinarest1608/HCIRA-HK@d91ccc6:Project1/usersamples/Subject3/circle10.xml", "circle"),
    (HCIRA, "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User02/circle04.xml", "circle"),
]
"""People's strokes a kind as drawn and another reversed at main 9b6f4da, alike since session 33: two circles whose
circle rounded off from the lap from the start reached past the stroke's bounds by a hair one way (an ellipse then;
`both_laps.circle_within_either_lap`)."""


@pytest.mark.parametrize("where,file,kind", ALIKE, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1]
                                                        for _, f, _ in ALIKE])
def test_a_persons_stroke_reads_alike_drawn_from_either_end(where: str, file: str, kind: str) -> None:
    row = cached_rows(where).get(file)
    assert row is not None, file
    assert readings(row) == (kind, kind)


HCIRA_ROUND_LABELS = ("circle", "arrow")
"""hcira's labels whose reversed readings differed at 9b6f4da by the causes above (1,219 strokes of one stroke)."""
HCIRA_ROUND_ALIKE = 1212
"""Of hcira's strokes of `HCIRA_ROUND_LABELS`, how many read the same kind reversed: 1,210 at main 9b6f4da, 1,212
since session 33 (the two circles of `ALIKE`); of the 7 left, 5 are circles holding a lift the device
missed (`pen_lifts`: read by the last attempt, which is another attempt reversed, meant to hang on the time order),
shriyansnidhish's with_stylus s06 arrow07 (`stroke_features.closure` takes a point more at the end than at the start:
0.419 one way, 0.434 the other, across `closed_loops.polygon_left_open`'s 0.42; as many points at both ends lost two
of `test_triangle_habits`' held start-short-overshoot triangles) and without_stylus s02 circle05, a circle whose ends
both run past each other (`loop_ends.cut_ends` cuts the end run past the start first, either way: asked alike, the
closer or the shorter cut, each lost a pen model's cornered polygon, `test_closed_shapes_kept`)."""


def test_hcira_circles_and_arrows_read_alike_drawn_either_way() -> None:
    rows = [r for r in cached_rows(HCIRA).values() if r["label"] in HCIRA_ROUND_LABELS and len(r["strokes"]) == 1]
    assert sum(len(set(readings(r))) == 1 for r in rows) >= HCIRA_ROUND_ALIKE
