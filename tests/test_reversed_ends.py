"""A closed stroke's closure, the loop cut from its ends and a circle rounded off from its laps are asked alike from
either end (issue 25, session 33): people's circles, an arrow and a square that read one kind as drawn and another
drawn from their other end read alike, and counts of hcira's circles and arrows that read alike are held as a floor
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
from physink_tui.scene.recognition.loop_ends import cut_ends

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


def _cut(work: np.ndarray) -> np.ndarray:
    """`cut_ends` as `closed_loops.closed_loop` asks it: each end against the other end's half of the stroke."""
    n, half = len(work), max(2, len(work) // 2)
    gap = float(np.hypot(*(work[-1] - work[0])))
    d_tail = np.hypot(*(work[n - half:] - work[0]).T)
    d_head = np.hypot(*(work[:half] - work[-1]).T)
    return cut_ends(work, gap, d_tail, d_head)


@pytest.mark.parametrize("n", [64, 101, 121, 150])
def test_the_loop_cut_from_a_strokes_ends_is_the_same_drawn_from_either_end(n: int) -> None:
    """A stroke that both started before where it ends and ran on past its start is cut once round as the same stroke
    drawn from its other end is (`loop_ends.cut_ends`: the shorter of two loops, or one loop where its ends come
    closer): until session 33 the end run past the start was cut first either way (a person's circle read a circle one
    way, an ellipse the other)."""
    rng = np.random.default_rng(1000 + n)
    both = 0
    for _ in range(60):
        work = _wavy(rng, n)
        ahead, back = _cut(work), _cut(work[::-1])
        assert np.array_equal(ahead, back[::-1]), (len(ahead), len(back))
        both += len(ahead) < n - 2
    assert both > 0  # some of the paths were cut at all


HCIRA, QUICKDRAW = "public-sets/hcira.jsonl", "public-sets/quickdraw.jsonl"
ALIKE = [
    (HCIRA, "sinarest1608/HCIRA-HK@d91ccc6:Project1/usersamples/Subject3/circle10.xml", "circle"),
    (HCIRA, "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User02/circle04.xml", "circle"),
    (HCIRA, "shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/TouchScreen_without_stylus/s02/circle05.xml",
     "circle"),
    (HCIRA, "shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/TouchScreen_with_stylus/s06/arrow07.xml",
     "polyline"),
    (QUICKDRAW, "ArtemLevin/tutorboard@3b27669:tests/fixtures/smart-ink-corpus/external/"
                "quickdraw.seed-90210.json.gz#238", "box"),
]
"""People's strokes a kind as drawn and another reversed at main 9b6f4da, alike since session 33: two circles whose
circle rounded off from the lap from the start reached past the stroke's bounds by a hair one way (an ellipse then;
`both_laps.circle_within_either_lap`), a circle whose ends both overlap (`loop_ends.cut_ends` cut the end run past the
start first either way), an arrow closed by 0.419 one way and 0.434 the other (`stroke_features.closure`, across
`closed_loops.polygon_left_open`'s 0.42), and a Quick, Draw! square with a flag drawn on past its start (`cut_ends`:
the square once round one way, the whole stroke less its start the other, a figure eight; the shorter of two loops
now)."""


@pytest.mark.parametrize("where,file,kind", ALIKE, ids=[f.rsplit("/", 2)[-2] + "/" + f.rsplit("/", 1)[-1]
                                                        for _, f, _ in ALIKE])
def test_a_persons_stroke_reads_alike_drawn_from_either_end(where: str, file: str, kind: str) -> None:
    row = cached_rows(where).get(file)
    assert row is not None, file
    assert readings(row) == (kind, kind)


HCIRA_ROUND_LABELS = ("circle", "arrow")
"""hcira's labels whose reversed readings differed at 9b6f4da by the causes above (1,219 strokes of one stroke)."""
HCIRA_ROUND_ALIKE = 1214
"""Of hcira's strokes of `HCIRA_ROUND_LABELS`, how many read the same kind reversed: 1,210 at main 9b6f4da, 1,214
since session 33 (the three circles and the arrow of `ALIKE`); the 5 left are circles holding a lift the device missed
(`pen_lifts`: read by the last attempt, which is another attempt reversed, meant to hang on the time order)."""


def test_hcira_circles_and_arrows_read_alike_drawn_either_way() -> None:
    rows = [r for r in cached_rows(HCIRA).values() if r["label"] in HCIRA_ROUND_LABELS and len(r["strokes"]) == 1]
    assert sum(len(set(readings(r))) == 1 for r in rows) >= HCIRA_ROUND_ALIKE
