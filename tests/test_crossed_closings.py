"""Issue 25: a triangle closed in a hurry, the pen landing before its first corner and running on past it so that the
two tails cross there, is a polygon even where its ends lifted farther apart than a closed stroke's gap
(`recognition.closed_loops.ends_cross`: the fourth group's Quick, Draw! triangles, opened in session 19, showed such
strokes read as polylines). Drawn by both pen models through a whole session (journal -> replay -> project), it
becomes one polygon body; a delete mark or an x drawn in one stroke, whose first and last strokes cross at their
middles, is no closed shape."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import numpy as np
import pytest
from penmodels.hurried import HurriedPen
from penmodels.journal import header as hurried_header
from penmodels.shapes import Path as PenPath
from scenarios.thesis import DEVICE, MAPPING
from xerase_drawings import _pen_entry, replayed_project

from physink_tui.formats.journal.entries import JournalEntry, JournalHeader
from physink_tui.input.journal_compose import capture_entries, header_for_capture
from physink_tui.input.virtual_pen import REFERENCE_DEVICES, Stroke, VirtualPen
from physink_tui.scene.recognition import closed_loops
from physink_tui.scene.recognition import stroke_geometry as sg

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from bench_closed_shapes import shape


def _journal(pen: str, path: PenPath, seed: int) -> tuple[JournalHeader, list[JournalEntry]]:
    if pen == "hurried":
        reports = HurriedPen(random.Random(seed)).draw(path, 0.3)[0]
        return hurried_header(), [_pen_entry(r) for r in reports]
    w, h = MAPPING.canvas_width, MAPPING.canvas_height
    capture = VirtualPen(REFERENCE_DEVICES[DEVICE], seed=seed).record(
        [Stroke(tuple((x / w, y / h) for x, y in path.vertices))])
    return header_for_capture(capture, MAPPING), capture_entries(capture)


@pytest.mark.parametrize(("pen", "seed"), [("hurried", 2233), ("hurried", 2244), ("virtual", 2063), ("virtual", 2089)])
def test_a_triangle_whose_tails_cross_becomes_a_polygon_body(pen: str, seed: int, tmp_path) -> None:
    """`bench_closed_shapes`' crossed triangles of seeds outside its tuning and held-back ranges that main a9aabd6
    read as polylines (found by reading seeds 2000-2399 with and without the rule)."""
    path = shape("triangle-crossed", seed)
    assert isinstance(path, PenPath)
    project, told = replayed_project(*_journal(pen, path, seed), tmp_path)
    bodies = project.scene.bodies()
    assert [b.shape for b in bodies] == ["polygon"], f"{pen} seed {seed}: {bodies}\n{told}"
    assert len(bodies[0].outline) == 3, f"{pen} seed {seed}: {bodies[0].outline}"


def _dense(corners: list[tuple[float, float]]) -> np.ndarray:
    pts = np.asarray(corners, dtype=float)
    return sg.resample(pts, 120)


@pytest.mark.parametrize("corners", (
    [(0.0, 0.0), (100.0, 100.0), (0.0, 100.0), (100.0, 0.0)],  # a delete mark's Z crossed at its middle
    [(0.0, 0.0), (100.0, 100.0), (100.0, 0.0), (0.0, 100.0)],  # an x drawn in one stroke
))
def test_marks_crossing_at_their_middles_are_not_closed_by_their_crossing(corners: list[tuple[float, float]]) -> None:
    work = _dense(corners)
    assert not closed_loops.ends_cross(work, sg.bbox_diagonal(work))


def test_tails_crossing_at_a_corner_close_the_stroke() -> None:
    work = _dense([(-30.0, 0.0), (200.0, 0.0), (100.0, -170.0), (-20.0, 34.0)])
    assert closed_loops.ends_cross(work, sg.bbox_diagonal(work))
