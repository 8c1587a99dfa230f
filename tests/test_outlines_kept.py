"""Issue 25: concave and many-sided outlines keep their corners. A T, an L, an arrow, a star, a trapezoid, a notched
block and a golf tee drawn by either pen model, journaled and replayed, become bodies that overlap the outline the
pen was asked to draw with IoU >= 0.90; a golf tee with a thin top keeps its wings (never a box the size of its
stem). Thin boxes and open containers keep their own guarantees (test_beautify_bounds, test_hurried_scenes)."""

from __future__ import annotations

import math
import random

import pytest
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.shapes import Outline
from scenarios.thesis import DEVICE, MAPPING
from shapely.geometry import Polygon
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.interpretation.body_shapes import body_geometry

Point = tuple[float, float]
CENTRE = (800.0, 500.0)
IOU_FLOOR = 0.90


def _star() -> list[Point]:
    return [((100 if k % 2 == 0 else 45) * math.cos(math.pi / 2 + k * math.pi / 5),
             -(100 if k % 2 == 0 else 45) * math.sin(math.pi / 2 + k * math.pi / 5)) for k in range(10)]


OUTLINES: dict[str, list[Point]] = {
    "T": [(-120, -80), (120, -80), (120, -30), (30, -30), (30, 110), (-30, 110), (-30, -30), (-120, -30)],
    "L": [(-100, -100), (-40, -100), (-40, 50), (100, 50), (100, 100), (-100, 100)],
    "arrow": [(-150, -30), (40, -30), (40, -80), (150, 0), (40, 80), (40, 30), (-150, 30)],
    "star": _star(),
    "trapezoid": [(-150, 60), (150, 60), (80, -60), (-80, -60)],
    "notch": [(-150, -60), (-30, -60), (-30, 0), (30, 0), (30, -60), (150, -60), (150, 60), (-150, 60)],
    "golf tee": [(-110, -90), (110, -90), (20, -30), (20, 120), (-20, 120), (-20, -30)],
}
"""What the pen is asked to draw, in canvas pixels round `CENTRE` (y down); about 200-300 pixels across."""
SCALES = (0.75, 1.0)
SEEDS = (1, 2, 3)


def placed(vertices: list[Point], scale: float, centre: Point = CENTRE) -> list[Point]:
    return [(centre[0] + x * scale, centre[1] + y * scale) for x, y in vertices]


def drawn(pen: str, vertices: list[Point], seed: int) -> tuple[JournalHeader, list[JournalEntry]]:
    """One closed stroke round ``vertices`` (canvas pixels) by the hurried hand or the virtual pen."""
    if pen == "hurried":
        reports = HurriedPen(random.Random(seed)).draw(Outline(tuple(vertices)), 0.3)[0]
        return hurried_header(), [_pen_entry(r) for r in reports]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    start = seed % len(vertices)  # the virtual pen starts at a corner, a different one per seed
    ring = vertices[start:] + vertices[:start + 1]
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record([Stroke(tuple((x / w, y / h) for x, y in ring))])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


def iou(a, b) -> float:
    return a.intersection(b).area / a.union(b).area


def sessions_drawing(outline, pen: str, tmp_path, scales=SCALES, seeds=SEEDS):
    """Each drawing of ``outline`` by ``pen`` at each scale and seed, through a whole session (journal -> replay ->
    project), as (case, the one body's shape, its IoU with the outline meant, the session's messages); a session
    making other than one body fails at once."""
    for scale in scales:
        for seed in seeds:
            meant = placed(outline, scale)
            folder = tmp_path / f"{scale}-{seed}"
            folder.mkdir()
            project, told = replayed_project(*drawn(pen, meant, seed), folder)
            bodies = project.scene.bodies()
            case = f"at {scale}x, {pen} pen seed {seed}"
            assert len(bodies) == 1, f"{case}: {[(b.id, b.shape) for b in bodies]}\n{told}"
            yield case, bodies[0].shape, iou(body_geometry(bodies[0]), Polygon(meant)), told


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize("name", OUTLINES)
def test_an_outline_keeps_its_corners_through_a_session(pen: str, name: str, tmp_path) -> None:
    for case, shape, overlap, told in sessions_drawing(OUTLINES[name], pen, tmp_path):
        assert overlap >= IOU_FLOOR, f"{name} {case}: a {shape} overlapping by IoU {overlap:.3f}\n{told}"


@pytest.mark.parametrize("pen", ("hurried", "virtual"))
@pytest.mark.parametrize(("width", "seed"), [(60.0, 1), (60.0, 2), (100.0, 1), (100.0, 3)])
def test_a_golf_tee_with_a_thin_top_keeps_its_wings(pen: str, width: float, seed: int, tmp_path) -> None:
    """A wide top a tenth of its width thick on a stem a fifth as wide and 1.5 times as long: the hand's wobble
    is as large as the top, so the overlap is not judged, but the body must span most of the top (the hand rounds
its sharp tips), not only the stem (a fifth of it)."""
    tee = [(-width / 2, 0.0), (width / 2, 0.0), (width / 10, width / 10), (width / 10, 1.6 * width),
           (-width / 10, 1.6 * width), (-width / 10, width / 10)]
    header, entries = drawn(pen, placed(tee, 1.0), seed)
    project, told = replayed_project(header, entries, tmp_path)
    bodies = project.scene.bodies()
    assert len(bodies) == 1, f"{[(b.id, b.shape) for b in bodies]}\n{told}"
    x0, _, x1, _ = body_geometry(bodies[0]).bounds
    assert bodies[0].shape == "polygon" and x1 - x0 >= 0.75 * width, (bodies[0].shape, x1 - x0, told)
