"""Issue 25: rectangles drawn with the habits of people we have not seen (`penmodels.box_habits`: tails past the close,
retraced, turned, a wall askew, corners swung round, a gap at the close, a start mid-wall, a bowed side, crossings at
the corners, thin, small, a side drawn twice over, a start inside, a kinked side) read as boxes by both pen models at
least as often as measured on the held-back seeds 1000-1029 (`benchmarks/bench_boxes.py --held-back`), and a box with
a side drawn twice over reads as one drawn either way round; a box with one wall askew and no two sides parallel is a
box through a whole session (journal -> replay -> project), as three people's rectangles are, while the quads it could
be taken for (a right trapezoid, whose base and top are parallel; a kite; a quad without a square wall) keep their
corners.

People's strokes are read from the public-set caches (`benchmarks/public_sets.py`; no licence: never committed) and
skip without them; only design sources are named."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from penmodels.box_habits import FAMILIES, drawn
from test_open_marks import _stroke, cached_rows
from test_outlines_kept import IOU_FLOOR, sessions_drawing

from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_boxes import PENS, read
from bench_closed_shapes import HELD_BACK_SEEDS, TUNING_SEEDS
from bench_closed_shapes import read as read_closed

Point = tuple[float, float]

FLOORS: dict[str, tuple[int, int]] = {
    "plain": (30, 30), "tail-past-close": (30, 30), "tail-hooked-in": (30, 30), "retraced": (30, 30),
    "turned": (30, 30), "wall-askew": (23, 22), "wall-askew-by-hand": (22, 24), "corner-swung": (30, 30),
    "two-corners-swung": (30, 30), "corners-rounded": (29, 27), "mouse-box": (30, 30), "gap-at-close": (30, 30),
    "start-mid-wall": (30, 30), "side-bowed": (30, 30), "corner-crossings": (30, 28), "thin": (30, 30),
    "small": (30, 30), "first-side-redrawn": (30, 30), "last-side-redrawn": (30, 30), "start-inside": (30, 30),
    "side-kinked": (30, 30),
}
"""family -> of the 30 held-back seeds, how many read as a box drawn by the careful virtual pen and by the hurried hand
(with their times), measured on wt-boxes (session 21; at main 98c6955 the same: the askew-wall rule gains on the tuning
seeds and on people's rectangles, not on these). Short of 30: a wall leaned 24-30 degrees with its base and top
parallel is a right trapezoid (the quad drawn, see `quads.askew_box`); a box with all four corners swung round by a
quarter or more of its shorter side read round until session 22 (14/11 at main 007872c; `rounded_boxes`, wt-rounded:
29/27), the rest reach no further towards their corners than people's squarish circles; two crossings at corners run
past by a tenth of a side become a polygon's corners. Session 23 (wt-corners) added the last four: at main 6b543d7 a box
with its first side drawn twice over read as a box 25 and 24 times (an ellipse or a polygon through the sliver the pen
drew out and back: `closed_loops.encloses`), its mirror at the close and the others 30 and 30."""


def test_every_family_has_a_floor() -> None:
    assert set(FLOORS) == set(FAMILIES)


@pytest.mark.parametrize("family", list(FLOORS))
def test_rectangles_drawn_with_a_habit_read_as_boxes(family: str) -> None:
    for pen, floor in zip(("careful", "hurried"), FLOORS[family], strict=True):
        got = [read(family, pen, seed) for seed in HELD_BACK_SEEDS]
        assert sum(k == "box" for k in got) >= floor, (pen, got)


ASKEW: dict[str, list[Point]] = {
    "wall askew 28 degrees": [(-169, -85), (131, -85), (206, 55), (-169, 115)],  # corners 90, 118, 71, 81
    "wall askew 26 degrees": [(-167, -84), (133, -84), (200, 52), (-167, 116)],  # corners 90, 116, 74, 80
}
"""A box whose left wall is square, its top square to it, its bottom 9-10 degrees off (so no two sides are parallel) and
its right wall leaned 26-28 degrees: as people's rectangles below are drawn. In canvas pixels round the centre."""
QUADS_KEPT: dict[str, list[Point]] = {
    "right trapezoid": [(-150, -100), (150, -100), (150, 100), (-35, 100)],  # a leg 30 degrees in, base, top parallel
    "kite": [(0, -120), (90, -30), (0, 130), (-90, -30)],  # corners 90, 106, 59, 106: no two square side by side
    "quad without a square wall": [(-185, -110), (115, -110), (157, 127), (-86, 93)],  # corners 64, 100, 72, 124
}
"""Quads the askew-wall rule must not take for boxes (each within 34 degrees of square at every corner, or nearly)."""


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("name", ASKEW)
def test_a_box_with_a_wall_askew_is_a_box_through_a_session(pen: str, name: str, tmp_path) -> None:
    for case, shape, _, told in sessions_drawing(ASKEW[name], pen, tmp_path, (0.75, 1.0), (1, 2)):
        assert shape == "box", f"{name} {case}: a {shape}\n{told}"


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("name", QUADS_KEPT)
def test_quads_of_their_own_keep_their_corners_through_a_session(pen: str, name: str, tmp_path) -> None:
    for case, shape, overlap, told in sessions_drawing(QUADS_KEPT[name], pen, tmp_path, (0.75, 1.0), (1, 2)):
        assert shape == "polygon" and overlap >= IOU_FLOOR, f"{name} {case}: a {shape}, IoU {overlap:.3f}\n{told}"


POLYGON_FLOORS: dict[tuple[str, str], int] = {
    ("pentagon-irregular", "careful"): 29, ("pentagon-irregular", "hurried"): 30, ("pentagon-irregular", "slow"): 30,
    ("pentagon-rounded", "careful"): 30, ("pentagon-rounded", "hurried"): 30, ("pentagon-rounded", "slow"): 30,
}
"""(family of `benchmarks/bench_closed_shapes.py`, pen) -> of its 30 tuning seeds, how many read as a polygon (with
times), as at main 98c6955 (the seed short of 30 is a box there too): a pentagon whose shallow corner no five-sided fit
passes is fitted with four sides, one bent in its middle, and is no box with a wall askew (`quads.STRAIGHT_WALLS`;
without it three of these read as boxes). On the held-back seeds they read as at main as well (docs/BENCHMARKS.md)."""


@pytest.mark.parametrize(("family", "pen"), list(POLYGON_FLOORS))
def test_pentagons_fitted_with_four_sides_stay_polygons(family: str, pen: str) -> None:
    got = [read_closed(family, pen, seed, timed=True)[0] for seed in TUNING_SEEDS]
    assert sum(k == "polygon" for k in got) >= POLYGON_FLOORS[(family, pen)], got


PEOPLE = [
    ("public-sets/hcira.jsonl", "jd4386/HCIRA-Project@ff559d7:Part 4/custom_xml_logs/User06/rectangle08.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s06/rectangle06.xml"),  # a mouse
    ("student-sets/itt.jsonl", "ITT-25/assignment-06-gesture-recognition-uniUbungsAccount@1b61d95:datasets/"
                               "own_recorded_gestures/rectangle06.xml"),
]
"""People's rectangles with a wall 27-29 degrees askew and no sides within 9 degrees of parallel: quads until
session 21."""


@pytest.mark.parametrize(("cache", "file"), PEOPLE, ids=[f.rsplit(":", 1)[-1] for _, f in PEOPLE])
def test_peoples_rectangles_with_a_wall_askew_are_boxes(cache: str, file: str) -> None:
    rows = cached_rows(cache)
    if file not in rows:
        pytest.skip(f"{file} not in the cached {cache}")
    points, times = _stroke(rows[file])
    assert recognize_stroke(points, times).kind == "box"


@pytest.mark.parametrize("pen", ("careful", "hurried"))
def test_a_box_with_a_side_drawn_twice_over_reads_the_same_either_way_round(pen: str) -> None:
    """A box whose first side the pen ran along, back to the corner and along again is the box drawn with its last side
    drawn twice over, the other way round: both read as boxes, drawn either way (session 23: drawn from the start it
    read as an ellipse or a polygon 6 times in 30 by the careful pen, from the close never)."""
    for family in ("first-side-redrawn", "last-side-redrawn"):
        for seed in TUNING_SEEDS:
            points = PENS[pen](drawn(family, seed), seed)
            end = points[-1][2]
            ways = {"as drawn": points, "backwards": [(x, y, end - t) for x, y, t in points[::-1]]}
            for way, pts in ways.items():
                kind = recognize_stroke([p[:2] for p in pts], [p[2] for p in pts]).kind
                assert kind == "box", (family, pen, seed, way, kind)
