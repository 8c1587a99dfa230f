"""Issue 25, session 33: a star's outline left open by a side is a polygon (`open_stars.star_left_open`, closed across
its gap, and not asked of the learned ranker, which takes it for a curve), while a zig-zag and a crown's rim left open,
whose turns alternate too, stay polylines; a line drawn out and back is a line, not the slit of an ellipse it closes
(`open_marks.out_and_back`). Pen models: `tests/penmodels/open_stars`, `benchmarks/bench_open_stars.py`.

Floors were measured on the held seeds (1000-1029), read once, at the end; each is this branch's figure. People's
strokes are read from the caches `benchmarks/public_sets.py` writes; without a cache that test skips, saying so.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from penmodels.open_stars import EXPECTED, FAMILIES
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.beautify import shape_points
from physink_tui.scene.recognition.primitives import Line
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_open_marks import HELD_SEEDS, PENS, read

HELD_FLOORS = {
    "star-left-open": {"careful": 38, "hurried": 40, "hurried-coarse": 40, "hurried-mouse": 28},
    "star-closed": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 58},
    "zigzag-row": {"careful": 56, "hurried": 58, "hurried-coarse": 56, "hurried-mouse": 50},
    "crown-left-open": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are read as
`EXPECTED`, measured on this branch; main 9b6f4da read 10, 16, 8, 8 (stars left open: curves and polylines), 58, 60,
58, 58 (closed stars), and the zig-zags and crowns as here. Left open: stars whose shallow dents the corner finders
miss (a hurried hand's 35-50 degree dents), most of them through the mouse, whose stair-steps add corners."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_a_star_left_open_is_a_polygon_and_a_zigzag_stays_open(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed, families=FAMILIES) for seed in HELD_SEEDS for timed in (True, False)]
    want = EXPECTED[family]
    assert sum(k in ((want,) if isinstance(want, str) else want) for k in got) >= HELD_FLOORS[family][pen], got


STAR = ("ArtemLevin/tutorboard@3b27669:tests/fixtures/smart-ink-corpus/external-v3/"
        "negative-holdout.seed-260730.json.gz#102")
"""A Quick, Draw! player's star (TutorBoard's seed260730): five points and four dents drawn, the pen lifting a side
short of its start; read as a curve at main 9b6f4da."""


def test_a_quick_draw_star_left_open_by_a_side_is_a_polygon() -> None:
    """Read as a polygon of nine corners or more (five points, the dents between)."""
    row = cached_rows("public-sets/quickdraw.jsonl").get(STAR)
    assert row is not None, f"{STAR} is not in quickdraw"
    points, times = _stroke(row)
    found = recognize_stroke(points, times)
    assert found.kind == "polygon" and found.geometry is not None
    assert len(shape_points(found.geometry)) >= 9


LINE = "borismus/exupery@5ab788c:docs/sketches/line.ndjson#5128369484070912"
"""A Quick, Draw! player's line drawn out and back (0.03 as wide as long); read as an ellipse at main 9b6f4da."""


@pytest.mark.parametrize("timed", [True, False], ids=["timed", "untimed"])
def test_a_line_drawn_out_and_back_is_a_line(timed: bool) -> None:
    """Read as a line spanning the stroke's length (within 2 %)."""
    row = cached_rows("public-sets/quickdraw.jsonl").get(LINE)
    assert row is not None, f"{LINE} is not in quickdraw"
    points, times = _stroke(row)
    found = recognize_stroke(points, times if timed else None)
    assert found.kind == "line" and isinstance(found.geometry, Line)
    xs = [p[0] for p in points]
    length = ((found.geometry.end[0] - found.geometry.start[0]) ** 2
              + (found.geometry.end[1] - found.geometry.start[1]) ** 2) ** 0.5
    assert abs(length - (max(xs) - min(xs))) <= 0.02 * (max(xs) - min(xs))
