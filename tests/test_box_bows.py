"""Issue 25: rectangles one side of which a hurried hand bowed out or in, or swung round with its two corners
(`penmodels.box_bows`), read as boxes by both pen models at least as often as measured on the held-back seeds
1000-1029 (`benchmarks/bench_box_bows.py --held-back`), and the low pentagons, swallowtails and deeply cut boxes beside
them stay polygons at least as often as measured (houses and swallowtails on wt-roof, session 26:
`recognition.roofs`); a box with a side bowed by a fifth is a box body through a whole session
(journal -> replay -> project); a person's polygons square on one side that reach the rule stay polygons
(`recognition.bowed_sides`); people's squares whose side and its corners were swung round in one sweep are boxes
(session 34: `bowed_sides.MAX_BOW` 0.25 -> 0.3); a box swept round on one side that the ranker reads as a quad past a
box's tolerance is a box too, and a box body through a session (session 35: the rule asks four-sided polygons).

People's strokes are read from the public-set caches (`benchmarks/public_sets.py`; no licence: never committed) and
skip without them; only fourth-group (open design material) sources are named."""

from __future__ import annotations

import math
import random
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.box_bows import BOXES, FAMILIES, POLYGONS, drawn
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.shapes import Outline
from scenarios.thesis import DEVICE, MAPPING
from test_open_marks import _stroke, cached_rows
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition.bowed_sides import MAX_BOW, ROUND_FILL, bow_of
from physink_tui.scene.recognition.recognize import recognize_stroke

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_box_bows import meant, read
from bench_box_slips import PENS
from bench_closed_shapes import HELD_BACK_SEEDS

Point = tuple[float, float]

FLOORS: dict[str, tuple[int, int]] = {
    "bowed-out": (30, 30), "bowed-in": (28, 29), "bow-swung": (27, 26), "side-swept": (27, 27),
    "house": (23, 20), "house-in": (25, 21), "cut-deep": (28, 25),
}
"""family -> of the 30 held-back seeds, how many read as a box (the first three families) or as a polygon (the others)
drawn by the careful virtual pen and by the hurried hand (with their times), measured on wt-sides (session 25). At
main 2ff28bf: bowed-out 23/20, bowed-in 16/15, bow-swung 19/20; house 13/12, house-in 11/12, cut-deep 28/25 (main
reads most low roofs and swallowtails, 12-25 % of the side, as boxes already: `rounded_corners.box_as_drawn`). house and
house-in raised on wt-roof (session 26: `recognition.roofs` gives the pentagon back; main 7111cdc 13/12 and 11/11).
side-swept measured on wt-tutor (session 34; main 85a9ce3 27/25: the sweeps deeper than a quarter of their chord were
polygons)."""


def test_every_family_has_a_floor() -> None:
    assert set(FLOORS) == set(FAMILIES) and set(BOXES).isdisjoint(POLYGONS)


@pytest.mark.parametrize("family", list(FLOORS))
def test_bowed_boxes_read_as_boxes_and_roofs_as_polygons(family: str) -> None:
    for pen, floor in zip(("careful", "hurried"), FLOORS[family], strict=True):
        got = [read(family, pen, seed) for seed in HELD_BACK_SEEDS]
        assert sum(k == meant(family) for k in got) >= floor, (pen, got)


def _profile(shape: str, n: int = 41) -> np.ndarray:
    """A bow (or a roof) across a chord of 100 along x, 20 deep."""
    t = np.linspace(0.0, 1.0, n)
    depth = 20 * (np.sin(math.pi * t) if shape == "bow" else 1 - np.abs(2 * t - 1))
    return np.column_stack([100 * t, depth])


def test_a_round_bow_fills_its_strip_and_a_roof_half_of_it() -> None:
    """A sine's half wave fills 2/pi of the strip between its chord and its deepest point, a roof half; both reach a
    fifth of the chord, within `MAX_BOW`; the roof turns at its ridge (roundness near 0), the bow all along."""
    bow, roof = bow_of(_profile("bow"), 0.5), bow_of(_profile("roof"), 0.5)
    assert bow is not None and roof is not None
    assert bow[0] == pytest.approx(0.2) and roof[0] == pytest.approx(0.2) and bow[0] <= MAX_BOW
    assert bow[1] == pytest.approx(2 / math.pi, abs=0.01) and roof[1] == pytest.approx(0.5, abs=0.01)
    assert roof[1] < ROUND_FILL < bow[1]
    assert roof[2] < 0.2 < 0.6 < bow[2]


def test_a_line_turning_back_along_its_chord_or_crossing_it_is_no_bow() -> None:
    zigzag = np.column_stack([np.linspace(0, 100, 41), 15 * np.sin(np.linspace(0, 2 * math.pi, 41))])
    back = np.array([(0, 0), (60, 10), (90, 20), (40, 25), (70, 18), (100, 0)], dtype=float)
    assert bow_of(zigzag, 0.5) is None and bow_of(back, 0.5) is None


CENTRE = (800.0, 500.0)


def _bowed_box(out: float, scale: float) -> list[Point]:
    """A 300 x 180 box (canvas pixels round the centre, y down) whose right side bows ``out`` of its 180 px (a sine's
    half wave, into the box where negative), drawn from its top left corner."""
    right = [(150 + out * 180 * math.sin(math.pi * j / 12), -90 + 15 * j) for j in range(13)]
    return [(CENTRE[0] + x * scale, CENTRE[1] + y * scale) for x, y in [(-150, -90), *right, (-150, 90)]]


def _drawn(pen: str, vertices: list[Point], seed: int):
    """One closed stroke round ``vertices`` (canvas pixels) by the hurried hand or the virtual pen, as a journal."""
    if pen == "hurried":
        reports = HurriedPen(random.Random(seed)).draw(Outline(tuple(vertices)), 0.3)[0]
        return hurried_header(), [_pen_entry(r) for r in reports]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    ring = [*vertices, vertices[0]]
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record([Stroke(tuple((x / w, y / h) for x, y in ring))])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("out", (0.2, -0.2))
def test_a_box_with_a_side_bowed_by_a_fifth_is_a_box_through_a_session(pen: str, out: float, tmp_path) -> None:
    """At main 2ff28bf the hurried hand's boxes, bowed either way, and the virtual pen's bowed in are polygons (a low
    pentagon: the bow changes the box's area by an eighth, past what `rounded_corners.box_as_drawn` lets a box cover);
    the virtual pen's bowed out was a box already."""
    for scale in (0.75, 1.0):
        for seed in (1, 2):
            folder = tmp_path / f"{scale}-{seed}"
            folder.mkdir()
            project, told = replayed_project(*_drawn(pen, _bowed_box(out, scale), seed), folder)
            shapes = [b.shape for b in project.scene.bodies()]
            assert shapes == ["box"], f"bowed {out} at {scale}x, seed {seed}: {shapes}\n{told}"


SWEPT_QUADS: tuple[tuple[str, int], ...] = (
    ("careful", 10), ("hurried-mouse", 10), ("hurried-trackpad", 1), ("hurried-trackpad", 9),
    ("hurried-trackpad", 11), ("hurried-trackpad", 15),
)
"""(pen, tuning seed) of `penmodels.box_bows` side-swept boxes read as four-sided polygons at main 535bda1 (a quad past
a box's tolerance: the sweep pulls its fourth side askew), which `bowed_sides.box_with_a_bowed_side` did not ask
until session 35 (it asked five sides or more); its fits of five or six sides make the box with a bowed side."""


@pytest.mark.parametrize(("pen", "seed"), SWEPT_QUADS)
def test_a_box_swept_round_on_one_side_read_as_a_quad_is_a_box(pen: str, seed: int) -> None:
    points = PENS[pen](drawn("side-swept", seed), seed)
    assert recognize_stroke([p[:2] for p in points], [p[2] for p in points]).kind == "box"


def test_a_box_swept_round_on_one_side_read_as_a_quad_is_a_box_through_a_session(tmp_path) -> None:
    """The side-swept box of tuning seed 10 drawn by the hurried hand (seed 2) through a session: a four-sided polygon
    body at main 535bda1."""
    vertices = list(drawn("side-swept", 10).vertices)[:-1]
    project, told = replayed_project(*_drawn("hurried", vertices, 2), tmp_path)
    assert [b.shape for b in project.scene.bodies()] == ["box"], told


SWEPT: dict[str, str] = {
    "square.ndjson#4526069946253312": "BG: the sweep 0.26 of its chord; its other walls 11.7 degrees off square",
}
"""Quick, Draw! squares (fourth group: design material) whose left side, top and bottom are straight and whose right
side and both its corners were swung round in one sweep, deeper than the quarter of its chord `bowed_sides.MAX_BOW` was
until session 34 (a polygon at main 2ff28bf and 85a9ce3; a strict xfail from session 25, named for its left wall's 12.9
degrees off square: the rule now reads it from the fit whose walls are square within 11.7). Tutorboard seed90210 #232,
swept 0.38 of its chord, stays a polygon: as deep as a deep cut corner rounded by the hurried hand (`MAX_BOW`)."""


@pytest.mark.parametrize("name", list(SWEPT))
def test_a_persons_square_swung_round_on_one_side_is_a_box(name: str) -> None:
    rows = cached_rows("public-sets/quickdraw.jsonl")
    file = next((f for f in rows if f.endswith(name)), None)
    if file is None:
        pytest.skip(f"{name} is not in the cached quickdraw set")
    assert recognize_stroke(*_stroke(rows[file])).kind == "box", SWEPT[name]


REACHED: dict[str, str] = {
    "hexagon.ndjson#5401676863242240": "BR: its sixth side and its neighbours a roof's, filling 0.48 of its strip",
    "octagon.ndjson#4670462774738944": "BR: a corner cut on the bowed side, filling 0.54",
    "octagon.ndjson#5909800162426880": "MY: two corners cut beside it, turning within 0.32 of its half",
    "octagon.ndjson#5457314486157312": "FI: square on one side and round on the other, its walls' corners cut",
}
"""Quick, Draw! polygons (fourth group: design material) with three sides straight and square and a sweep round the
rest, which the rule reached with its thresholds opened (`ROUND_FILL`, `ROUND_BEND` at 0): what kept each a polygon."""


@pytest.mark.parametrize("name", list(REACHED))
def test_a_persons_polygon_square_on_one_side_stays_a_polygon(name: str) -> None:
    rows = cached_rows("public-sets/quickdraw.jsonl")
    file = next((f for f in rows if f.endswith(name)), None)
    if file is None:
        pytest.skip(f"{name} is not in the cached quickdraw set")
    assert recognize_stroke(*_stroke(rows[file])).kind == "polygon", REACHED[name]
