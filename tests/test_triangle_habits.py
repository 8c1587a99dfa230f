"""Issue 25: triangles drawn with the habits of people we have not seen (`penmodels.triangle_habits`: a gap at the
close, a start along the first side, a tail or a crossing past the close, a start mid-side, the first side drawn twice
over, a start inside) read as polygons by both pen models at least as often as measured on the held-back seeds
1000-1029 (`benchmarks/bench_triangles.py --held-back`)."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.triangle_habits import FAMILIES
from test_open_marks import cached_rows

from physink_tui.scene.recognition import stroke_features as sf
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_closed_shapes import HELD_BACK_SEEDS
from bench_triangles import read

FLOORS: dict[str, tuple[int, int]] = {
    "plain": (30, 30), "gap-at-close": (22, 29), "start-short": (22, 30), "tail-past-close": (30, 30),
    "crossing-close": (30, 30), "start-mid-side": (30, 30), "first-side-redrawn": (30, 30), "start-inside": (30, 30),
    "both-ends-past": (30, 30), "start-short-run-past": (26, 30), "start-short-overshoot": (15, 23),
}
"""family -> of the 30 held-back seeds, how many read as a polygon drawn by the careful virtual pen and by the hurried
hand (with their times), measured on wt-corners (session 23); at main 6b543d7 gap-at-close 21 and 26, start-short 17
and 25 (a triangle left open at a corner sharper than 45 degrees had turned less than `closed_loops.LEFT_OPEN_TURN`
was), crossing-close 29 and 28, first-side-redrawn 26 and 27 (an ellipse through the sliver drawn out and back,
`closed_loops.encloses`). The careful pen's gaps short of 30 are read as polygons by the rules and as polylines by the
learned ranker (its shipped weights stay as they are). both-ends-past and start-short-run-past (session 27, wt-marks:
tutorboard seed90210's triangles #247 and #309) as measured on main 9f69154, no rule changed for them.
start-short-overshoot (session 28, wt-classes: #309 measured again, its last side 43 % past the corner) as measured
with `stroke_features.ran_through_first_corner` (main 0ca43a2: 12 and 19; the rest polylines, most of them polygons by
the rules re-read by the ranker, whose shipped weights stay as they are)."""


def test_every_family_has_a_floor() -> None:
    assert set(FLOORS) == set(FAMILIES)


@pytest.mark.parametrize("family", list(FLOORS))
def test_triangles_drawn_with_a_habit_read_as_polygons(family: str) -> None:
    for pen, floor in zip(("careful", "hurried"), FLOORS[family], strict=True):
        got = [read(family, pen, seed) for seed in HELD_BACK_SEEDS]
        assert sum(k == "polygon" for k in got) >= floor, (pen, got)


TRIANGLE309 = ("ArtemLevin/tutorboard@3b27669:tests/fixtures/smart-ink-corpus/external/"
               "quickdraw.seed-90210.json.gz#309")
"""tutorboard seed90210's triangle #309 (the fourth group, open design material; stored with the quickdraw set): the pen
lands 0.18 along the first side and the last side runs 43 % past the corner; a polyline on main 0ca43a2."""


def test_a_persons_triangle_overshot_at_the_close_is_a_polygon() -> None:
    row = cached_rows("public-sets/quickdraw.jsonl").get(TRIANGLE309)
    assert row is not None, f"{TRIANGLE309} is not in the quickdraw set"
    points = [p[:2] for p in row["strokes"][0]]
    assert recognize_stroke(points, learned=False).kind == "polygon"
    assert recognize_stroke(points).kind == "polygon"


def test_a_start_short_of_the_corner_the_last_side_ran_through() -> None:
    """The first side's line, drawn back from the start, meets the last side's in its second half: the pen ran
    through the first corner; a start 0.6 along the first side, or a last side that stops short of the corner, no."""
    square = np.array([[0.0, 0.2], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [-0.5, 0.0]])
    assert sf.ran_through_first_corner(square, [0, 1, 2, 3, 4])
    assert not sf.ran_through_first_corner(np.array([[0.0, 0.6], *square[1:]]), [0, 1, 2, 3, 4])
    assert not sf.ran_through_first_corner(np.array([*square[:-1], [0.3, 0.0]]), [0, 1, 2, 3, 4])
