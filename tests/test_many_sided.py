"""Issue 25, sessions 23 and 26: many-sided outlines drawn in a hurry keep their corners. An irregular octagon one or
two of whose shallow corners were swept round is read as the polygon drawn where its polygon explains nine tenths of the
round shape's error and two thirds of its corners are sharp (`round_or_cornered.mostly_sharp`), by the pen models
(`tests/penmodels/many_sided`, `benchmarks/bench_many_sided.py`) and on the Quick, Draw! players' octagons; people's
circles whose wobbly polygon explains as much stay round. A hexagon or octagon left open by one side, its corners
rounded, is a polygon where its turning is gathered at short bends between straight runs (`shape_corners`); circles left
open, lumpy or drawn as a few chords, stay round.

Floors were measured on the held seeds (1000-1029), read once, at the end; each is this branch's figure. People's
strokes are read from ../shared/data and the caches `benchmarks/public_sets.py` and `benchmarks/student_sets.py`
write; without a cache that test skips, saying so.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest
from penmodels.many_sided import EXPECTED, FAMILIES
from shapely.geometry import Polygon as ShapelyPolygon
from shared_data import shared_path
from test_open_marks import _stroke, cached_rows

from physink_tui.scene.recognition.beautify import shape_points
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_open_marks import HELD_SEEDS, PENS, read

HELD_FLOORS = {
    "irregular-hexagon": {"careful": 60, "hurried": 60, "hurried-coarse": 60, "hurried-mouse": 60},
    "swept-octagon": {"careful": 56, "hurried": 54, "hurried-coarse": 44, "hurried-mouse": 35},
    "left-open": {"careful": 46, "hurried": 56, "hurried-coarse": 52, "hurried-mouse": 46},
    "uneven-squiggle": {"careful": 32, "hurried": 38, "hurried-coarse": 36, "hurried-mouse": 34},
    "rounded-left-open": {"careful": 56, "hurried": 52, "hurried-coarse": 48, "hurried-mouse": 38},
    "round-left-open": {"careful": 60, "hurried": 60, "hurried-coarse": 58, "hurried-mouse": 60},
}
"""family -> pen -> of the 60 readings on the held seeds (30 marks, with and without times), how many are read as
`EXPECTED`, measured on this branch; main 6b543d7 read 60, 60, 60, 48 (hexagons), 48, 40, 32, 2 (octagons), 0, 0, 0,
0 (left open) and the squiggles as here. Left open: the octagons through a mouse (read round) and the squiggles read
as polylines (their tall humps turn within 0.1-0.2 of a side, as sharp as a zig-zag's teeth to `waves.MIN_ROUNDNESS`).
Session 26 (`shape_corners`, main 7111cdc -> this branch): left-open 8, 16, 16, 6 -> 46, 56, 52, 46; rounded-left-open
(new) 2, 2, 0, 2 -> 56, 52, 48, 38; round-left-open (new; lumpy circles left open, which must stay round) 60, 60, 58,
60 at both. Session 32 (wt-mouse, `round_or_cornered.paced_corners`: a loop in a mouse's bursts whose pen
slowed five times or more is its polygon): through the mouse, irregular-hexagon 48 -> 52, swept-octagon 6 -> 25 (timed
readings only; untimed ones are main's). Session 35 (wt-octagons, `rounded_polygons.SHALLOW_TURN`: a loop read round
may keep one shallow corner where over half its steps run straight): irregular-hexagon hurried-mouse 59 -> 60,
swept-octagon hurried-coarse 42 -> 44 and hurried-mouse 32 -> 35 (careful and hurried 56, 56 as before)."""


@pytest.mark.parametrize(("family", "pen"), [(f, p) for f in HELD_FLOORS for p in PENS])
def test_a_hurried_many_sided_outline_or_squiggle_reads_as_drawn(family: str, pen: str) -> None:
    got = [read(family, pen, seed, timed, families=FAMILIES) for seed in HELD_SEEDS for timed in (True, False)]
    want = EXPECTED[family]
    assert sum(k in ((want,) if isinstance(want, str) else want) for k in got) >= HELD_FLOORS[family][pen], got


OUTLINES = (
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5909800162426880",
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5455269007982592",
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5377113542623232",
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5901015196893184",
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#6140411519172608",
)
"""Quick, Draw! outlines misread at main 6b543d7: two octagons, closed and dense, a shallow corner or two swept round
(read as circles); three hexagons drawn round five of their sides and left open (read as a curve and polylines)."""


@pytest.mark.parametrize("file", OUTLINES, ids=[f.rsplit("/", 1)[-1] for f in OUTLINES])
def test_a_quick_draw_many_sided_outline_keeps_its_corners(file: str) -> None:
    """Read as a polygon of six sides or more whose outline overlaps the drawn one (closed across its gap) with
    IoU >= 0.90, as issue 25 asks of many-sided outlines."""
    row = cached_rows("public-sets/quickdraw.jsonl").get(file)
    assert row is not None, f"{file} is not in quickdraw"
    points, times = _stroke(row)
    found = recognize_stroke(points, times)
    assert found.kind == "polygon" and found.geometry is not None
    corners = shape_points(found.geometry)
    assert len(corners) >= 6
    drawn, read_as = ShapelyPolygon(points).buffer(0), ShapelyPolygon(corners).buffer(0)
    assert drawn.intersection(read_as).area / drawn.union(read_as).area >= 0.90


CIRCLES = (
    ("public-sets/hcira.jsonl", "jonathanzhang53/gesture-recognizer@8f30851:user_gestures/s04/circle6.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s03/circle03.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s03/circle06.xml"),
    ("public-sets/hcira.jsonl", "klarubbio/hcira_p1@e8eb332:xml/s03/circle07.xml"),
    ("public-sets/hcira.jsonl",
     "shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/MousePad/s05/circle08.xml"),
    ("student-sets/itt.jsonl",
     "ITT-26/assignment-06-gesture-recognition-marcel-moz@5404f89:02-recognizer-comparison/datasets/circle08.xml"),
    ("public-sets/ahmadosama.jsonl", "AhmadOsama4/Mouse-Gesture-Recognition-Using-HMM@4285ca6:TestData/Circle.xml#12"),
)
"""(cached set, file): the design sources' circles nearest to being read as polygons: a polygon of 8-10 sides leaves
under a tenth of the round shape's error and half or more of its vertices are sharp (at most 0.62 of them,
`round_or_cornered.MOSTLY_SHARP` asks 0.7)."""


@pytest.mark.parametrize(("name", "file"), CIRCLES, ids=[f.rsplit("@", 1)[-1] for _, f in CIRCLES])
def test_a_persons_wobbly_circle_stays_round(name: str, file: str) -> None:
    row = cached_rows(name).get(file)
    assert row is not None, f"{file} is not in {name}"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind in ("circle", "ellipse")


LEFT_OPEN_ROUNDED = {
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5724753627185152": 0.95,
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5210692967727104": 0.98,
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5564563560857600": 0.98,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5178504989638656": 0.97,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#6178885219647488": 0.97,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5032903316602880": 0.98,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#6654824772796416": 0.98,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5697908470972416": 0.89,
}
"""Quick, Draw! hexagons and octagons left open by one side, their corners rounded, misread at main 7111cdc (as curves,
polylines and circles: the corner finder missed the rounded corners); session 26 (`shape_corners`). Each with the
IoU its polygon keeps with the drawn outline closed across the gap, as measured on this branch (the last, an octagon
read with five vertices, its sides' rounded corners cut: 0.8998)."""


@pytest.mark.parametrize("file", list(LEFT_OPEN_ROUNDED), ids=[f.rsplit("#", 1)[-1] for f in LEFT_OPEN_ROUNDED])
@pytest.mark.parametrize("timed", [True, False], ids=["timed", "untimed"])
def test_a_many_sided_outline_left_open_with_rounded_corners_is_a_polygon(file: str, timed: bool) -> None:
    """Read, with its times or without, as a polygon of five sides or more whose outline overlaps the drawn one
    (closed across its gap) as closely as measured (`LEFT_OPEN_ROUNDED`)."""
    row = cached_rows("public-sets/quickdraw.jsonl").get(file)
    assert row is not None, f"{file} is not in quickdraw"
    points, times = _stroke(row)
    found = recognize_stroke(points, times if timed else None)
    assert found.kind == "polygon" and found.geometry is not None
    corners = shape_points(found.geometry)
    assert len(corners) >= 5
    drawn, read_as = ShapelyPolygon(points).buffer(0), ShapelyPolygon(corners).buffer(0)
    assert drawn.intersection(read_as).area / drawn.union(read_as).area >= LEFT_OPEN_ROUNDED[file]


FAST_CIRCLES = ("s04/fast/circle05.xml", "s04/medium/circle02.xml", "s04/medium/circle08.xml", "s04/slow/circle01.xml")
"""The $1 set's circles nearest `shape_corners.rounded_many_sided_left_open`: left open, drawn as a few chords, four
to eight short bends doing 0.64-0.75 of the turning on a convex outline the gap would close; but their steps run
straight only 0.29-0.37 of the way (`STRAIGHT_SHARE` asks 0.45) and their bends turn 0.75-0.82 of a regular polygon's
for their number."""


@pytest.mark.parametrize("file", FAST_CIRCLES)
def test_a_fast_circle_drawn_as_chords_and_left_open_stays_round(file: str) -> None:
    rows = (json.loads(line) for line in shared_path("strokes", "dollar1-dev.jsonl").read_text(encoding="utf-8")
            .splitlines() if line.strip())
    row = next((r for r in rows if r["file"] == file), None)
    assert row is not None, f"{file} is not in the $1 set"
    points, times = _stroke(row)
    assert recognize_stroke(points, times).kind in ("circle", "ellipse")
    assert recognize_stroke(points).kind in ("circle", "ellipse")


LEFT_OPEN_ON_A_SIDE = {
    "borismus/exupery@5ab788c:docs/sketches/hexagon.ndjson#5281337915211776": 0.89,
    "borismus/exupery@5ab788c:docs/sketches/octagon.ndjson#5101967531573248": 0.87,
}
"""Quick, Draw! hexagon and octagon left open part-way along a side (their ends 5 and 3 degrees the other way on the
ring of sides and gap: `shape_corners.ENDS_ON_A_SIDE_DEG`), two or three corners rounded over five steps
(`shape_corners.LEFT_OPEN_BEND_STEPS`): a curve and a polyline at main 85a9ce3; issue 25, session 34. Each with the
IoU its polygon keeps with the outline closed across the gap, as measured on this branch (the octagon, drawn nearly
as a quadrilateral with two corners cut round, is read with four vertices: 0.880; the hexagon with five: 0.890)."""


@pytest.mark.parametrize("file", list(LEFT_OPEN_ON_A_SIDE), ids=[f.rsplit("#", 1)[-1] for f in LEFT_OPEN_ON_A_SIDE])
@pytest.mark.parametrize("timed", [True, False], ids=["timed", "untimed"])
def test_a_many_sided_outline_left_open_along_a_side_is_a_polygon(file: str, timed: bool) -> None:
    """Read, with its times or without, as a polygon whose outline overlaps the drawn one (closed across its gap) as
    closely as measured (`LEFT_OPEN_ON_A_SIDE`)."""
    row = cached_rows("public-sets/quickdraw.jsonl").get(file)
    assert row is not None, f"{file} is not in quickdraw"
    points, times = _stroke(row)
    found = recognize_stroke(points, times if timed else None)
    assert found.kind == "polygon" and found.geometry is not None
    drawn, read_as = ShapelyPolygon(points).buffer(0), ShapelyPolygon(shape_points(found.geometry)).buffer(0)
    assert drawn.intersection(read_as).area / drawn.union(read_as).area >= LEFT_OPEN_ON_A_SIDE[file]
