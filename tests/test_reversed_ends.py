"""A stroke's closure and a circle rounded off from its laps are asked alike from either end (issue 25, session 33):
people's circles and an arrow that read one kind as drawn and another drawn from their other end read alike, and the
count of hcira's circles and arrows that read alike is held as a floor
(`benchmarks/bench_reversed.py` reads every design set; the tests skip without the cached sets).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from test_open_marks import cached_rows

from physink_tui.scene.recognition import stroke_features as sf

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_reversed import readings


def _wavy(rng: np.random.Generator, n: int) -> np.ndarray:
    """A path of ``n`` points round a wobbly loop, its ends run past each other by a random share of a turn."""
    turn = 2 * math.pi * (1.0 + rng.uniform(-0.15, 0.2))
    a = np.linspace(0.0, turn, n) + rng.uniform(0, 2 * math.pi)
    r = 1.0 + 0.1 * np.sin(3 * a + rng.uniform(0, 6)) + rng.normal(0, 0.01, n)
    return np.column_stack([r * np.cos(a) * rng.uniform(0.6, 1.4), r * np.sin(a)])


@pytest.mark.parametrize("n", [17, 33, 63, 64, 65, 99, 121, 150])
def test_closure_is_the_same_drawn_from_either_end(n: int) -> None:
    """Both ends' windows hold as many points (`stroke_features.closure`): until session 33 the last fifth held one
    more where a fifth of the count is not whole, and a stroke closed by 0.419 one way closed by 0.434 the other."""
    rng = np.random.default_rng(n)
    for _ in range(40):
        work = _wavy(rng, n)
        diag = float(np.hypot(*(work.max(axis=0) - work.min(axis=0))))
        assert sf.closure(work, diag) == pytest.approx(sf.closure(work[::-1], diag), abs=1e-12)


HCIRA = "public-sets/hcira.jsonl"
ALIKE = [
    (HCIRA, "sinarest1608/HCIRA-HK@d91ccc6:Project1/usersamples/Subject3/circle10.xml", "circle"),
    (HCIRA, "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User02/circle04.xml", "circle"),
    (HCIRA, "shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/TouchScreen_with_stylus/s06/arrow07.xml",
     "polyline"),
]
"""People's strokes a kind as drawn and another reversed at main 9b6f4da, alike since session 33: two circles whose
circle rounded off from the lap from the start reached past the stroke's bounds by a hair one way (an ellipse then;
`both_laps.circle_within_either_lap`), and an arrow closed by 0.419 one way and 0.434 the other
(`stroke_features.closure`, across `closed_loops.polygon_left_open`'s 0.42)."""


@pytest.mark.parametrize("where,file,kind", ALIKE, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1]
                                                        for _, f, _ in ALIKE])
def test_a_persons_stroke_reads_alike_drawn_from_either_end(where: str, file: str, kind: str) -> None:
    row = cached_rows(where).get(file)
    assert row is not None, file
    assert readings(row) == (kind, kind)


HCIRA_ROUND_LABELS = ("circle", "arrow")
"""hcira's labels whose reversed readings differed at 9b6f4da by the causes above (1,219 strokes of one stroke)."""
HCIRA_ROUND_ALIKE = 1213
"""Of hcira's strokes of `HCIRA_ROUND_LABELS`, how many read the same kind reversed: 1,210 at main 9b6f4da, 1,213
since session 33 (the two circles and the arrow of `ALIKE`); of the 6 left, 5 are circles holding a lift the device
missed (`pen_lifts`: read by the last attempt, which is another attempt reversed, meant to hang on the time order),
and shriyansnidhish's without_stylus s02 circle05 a circle whose ends both run past each other
(`loop_ends.cut_ends` cuts the end run past the start first, either way: asked alike, the closer or the shorter cut,
each lost a pen model's cornered polygon, `test_closed_shapes_kept`)."""


def test_hcira_circles_and_arrows_read_alike_drawn_either_way() -> None:
    rows = [r for r in cached_rows(HCIRA).values() if r["label"] in HCIRA_ROUND_LABELS and len(r["strokes"]) == 1]
    assert sum(len(set(readings(r))) == 1 for r in rows) >= HCIRA_ROUND_ALIKE
