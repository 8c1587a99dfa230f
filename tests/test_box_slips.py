"""Issue 25: rectangles drawn with the slips of `penmodels.box_slips` (a wide gap at the close, begun mid-wall and left
open, corners rounded and left open, a spur at a corner, a lead-in, two laps apart, a deep bow, a cut corner) read as
boxes by both pen models at least as often as measured on the held-back seeds 1000-1029
(`benchmarks/bench_box_slips.py --held-back`); a box whose last side stops half way is a box body through a whole
session (journal -> replay -> project); a person's box gone round twice, the second lap beside the first, is a box;
and the open marks the left-open rule could take for boxes keep their readings (a bracket with its landing hook turned
in, a scribble whose first loop comes back).

People's strokes are read from the public-set caches (`benchmarks/public_sets.py`; no licence: never committed) and
skip without them; only design and fourth-group (open design material) sources are named."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import pytest
from penmodels.box_slips import FAMILIES, drawn
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.shapes import Path as PenPath
from scenarios.thesis import DEVICE, MAPPING
from test_open_marks import _stroke, cached_rows
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_box_slips import PENS, read
from bench_closed_shapes import HELD_BACK_SEEDS, TUNING_SEEDS

Point = tuple[float, float]

FLOORS: dict[str, tuple[int, int]] = {
    "gap-wide": (30, 29), "mid-wall-open": (30, 30), "rounded-left-open": (28, 28), "corner-spur": (30, 30),
    "lead-in": (30, 30), "laps-apart": (30, 30), "side-bowed-deep": (30, 29), "corner-cut": (30, 29),
}
"""family -> of the 30 held-back seeds, how many read as a box drawn by the careful virtual pen and by the hurried hand
(with their times), measured on wt-rects (session 24). At main 40b8114: gap-wide 19/19, mid-wall-open 23/23,
rounded-left-open 26/26, laps-apart 25/22 (`open_boxes.box_left_open`, `closed_loops.TWICE_ROUND`); side-bowed-deep
27/24 until session 25 (wt-sides: `bowed_sides`); the others as here. Short of 30: two corners rounded with the box
left open bow the side between them past `open_shapes.STRAIGHT`."""


def test_every_family_has_a_floor() -> None:
    assert set(FLOORS) == set(FAMILIES)


@pytest.mark.parametrize("family", list(FLOORS))
def test_rectangles_drawn_with_a_slip_read_as_boxes(family: str) -> None:
    for pen, floor in zip(("careful", "hurried"), FLOORS[family], strict=True):
        got = [read(family, pen, seed) for seed in HELD_BACK_SEEDS]
        assert sum(k == "box" for k in got) >= floor, (pen, got)


LEFT_OPEN: dict[str, list[Point]] = {
    "last side half drawn": [(-150, -90), (150, -90), (150, 90), (-150, 90), (-150, 0)],
    "begun mid-wall, lifted at the corner": [(20, -90), (150, -90), (150, 90), (-150, 90), (-150, -90)],
}
"""Boxes left open (canvas pixels round the centre, y down): 300 x 180, the pen lifting half way up the last side, or
landing on the top side 170 px from its corner and lifting at that corner."""
CENTRE = (800.0, 500.0)


def _drawn_open(pen: str, chain: list[Point], seed: int):
    """One open stroke along ``chain`` (canvas pixels) by the hurried hand or the virtual pen, as a journal."""
    if pen == "hurried":
        reports = HurriedPen(random.Random(seed)).draw(PenPath(tuple(chain)), 0.3)[0]
        return hurried_header(), [_pen_entry(r) for r in reports]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record([Stroke(tuple((x / w, y / h) for x, y in chain))])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("name", LEFT_OPEN)
def test_a_box_left_open_by_part_of_a_side_is_a_box_through_a_session(pen: str, name: str, tmp_path) -> None:
    """Polylines at main 40b8114: the half side drawn is a tenth of the path, cut as a hook (`remove_hooks`), and the
    box begun mid-wall has its ends 0.49 of its size apart, past the 0.42 a polygon of any sides may be left open by
    (`closed_loops.polygon_left_open`)."""
    for scale in (0.75, 1.0):
        for seed in (1, 2):
            chain = [(CENTRE[0] + x * scale, CENTRE[1] + y * scale) for x, y in LEFT_OPEN[name]]
            folder = tmp_path / f"{scale}-{seed}"
            folder.mkdir()
            project, told = replayed_project(*_drawn_open(pen, chain, seed), folder)
            shapes = [b.shape for b in project.scene.bodies()]
            assert shapes == ["box"], f"{name} at {scale}x, seed {seed}: {shapes}\n{told}"


@pytest.mark.parametrize(("pen", "floor"), [("careful", 30), ("hurried", 29)])
def test_a_box_left_open_reads_the_same_drawn_either_way_round(pen: str, floor: int) -> None:
    """Drawn backwards, a box whose last side stops short is one begun mid-wall and lifted at a corner: every one of
    the 30 tuning seeds reads the same both ways, and as a box at least ``floor`` times (both ways; at main 40b8114, 6
    and 9 times: the rest polylines both ways)."""
    kinds = []
    for seed in TUNING_SEEDS:
        points = PENS[pen](drawn("gap-wide", seed), seed)
        end = points[-1][2]
        ways = (points, [(x, y, end - t) for x, y, t in points[::-1]])
        kinds.append(tuple(recognize_stroke([p[:2] for p in pts], [p[2] for p in pts]).kind for pts in ways))
    assert all(a == b for a, b in kinds), kinds
    assert sum(a == "box" for a, _ in kinds) >= floor, kinds


@pytest.mark.parametrize("pen", ("careful", "hurried"))
@pytest.mark.parametrize("hook", (0.08, 0.15))
def test_a_bracket_with_its_landing_hook_turned_in_stays_a_bracket(pen: str, hook: float) -> None:
    """A square bracket (arms a third of its 240 px spine) whose pen turned in at the lift by a tenth of the spine or
    less, square to the arm: three corners turning one way, as a box left open has, but the last side is no side."""
    arm, spine = 80.0, 240.0
    chain = [(CENTRE[0] + arm, CENTRE[1] - spine / 2), (CENTRE[0], CENTRE[1] - spine / 2),
             (CENTRE[0], CENTRE[1] + spine / 2), (CENTRE[0] + arm, CENTRE[1] + spine / 2),
             (CENTRE[0] + arm, CENTRE[1] + spine / 2 - hook * spine)]
    for seed in TUNING_SEEDS[:10]:
        points = PENS[pen](PenPath(tuple(chain)), seed)
        kind = recognize_stroke([p[:2] for p in points], [p[2] for p in points]).kind
        assert kind == "polyline", (pen, seed, kind)


def test_a_persons_box_gone_round_twice_laps_apart_is_a_box() -> None:
    """hcira shriyansnidhish s02 rectangle01 (a touch screen): the second lap a seventh of the box's size out; a
    polygon at main 40b8114."""
    rows = cached_rows("public-sets/hcira.jsonl")
    file = ("shriyansnidhish/Dollar-one-recognizer@35d6736:Part-2/Dataset/TouchScreen_without_stylus/s02/"
            "rectangle01.xml")
    if file not in rows:
        pytest.skip(f"{file} not in the cached hcira set")
    assert recognize_stroke(*_stroke(rows[file])).kind == "box"


def test_a_scribble_whose_first_loop_comes_back_is_no_lap() -> None:
    """A Quick, Draw! squiggle (fourth group: design material) of loops wandering across the page, the first of which
    comes back to its start: read as a curve, as its label says; the two-laps rule made it an ellipse until its second
    lap had to lie beside the first (`closed_loops._beside`)."""
    rows = cached_rows("public-sets/quickdraw.jsonl")
    file = next((f for f in rows if f.endswith("squiggle.ndjson#5804658608046080")), None)
    if file is None:
        pytest.skip("the squiggle is not in the cached quickdraw set")
    assert recognize_stroke(*_stroke(rows[file])).kind == "curve"


def test_a_square_spiral_is_no_box_gone_round_twice() -> None:
    """A tutorboard sample labelled "negative" (fourth group: design material): a spiral drawn square, two and a quarter
    laps inward, each beside the last. A curve at main 40b8114; the two-laps rule read it as a box until it stopped at
    `closed_loops.SPIRAL_TURN`."""
    rows = cached_rows("public-sets/tutorboard.jsonl")
    file = next((f for f in rows if f.endswith("captured-chromium-v1/corpus.json.gz#168")), None)
    if file is None:
        pytest.skip("the square spiral is not in the cached tutorboard set")
    assert recognize_stroke(*_stroke(rows[file])).kind != "box"
